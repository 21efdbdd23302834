//! `cargo xtask report release [--fidelity F]`: the station against the release the paper
//! does not report (issue 19 items 3–4, docs/studies/impact.md §4).
//!
//! Reads the runs of the sweeps of `study: "release"` (cases/sensitivity/release-*.ron, run
//! by `cargo xtask sweep --study release`) and writes `docs/reports/release.md`, one table
//! per fidelity that has runs: for each release block, its released mass, the tilt time of
//! its criterion, the time its front reaches the station, the front and the station's max
//! u_s, floor εs and air cushion at the profile time; and
//! `docs/reports/release/front_<fidelity>.svg`, the fronts x(t). The criterion reads the
//! Jenkins rows: max u_s at the station at the paper's t = 1.25 s against the middle of the
//! paper's 8.18–8.67 m/s.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use runout_case::{Fidelity, SourcedCase};

use super::plots::{draw, Mark, Panel, Series};
use super::reading::flow_at_station;
use runout_post::case_data::CaseData;
use runout_post::metrics::PROFILE_TIME;
use runout_post::table::Table;

/// The study's name in its sweep files.
pub const STUDY: &str = "release";
/// Output page, relative to the docs directory.
const PAGE: &str = "reports/release.md";
/// The paper's range of max u_s at the station for the Jenkins floors [m/s] (§3.1, Fig. 10).
pub const JENKINS_MAX_U_S: (f64, f64) = (8.18, 8.67);

/// One release run of the study.
pub struct ReleaseRow {
    /// case name
    pub case: String,
    /// the sweep's name (one per floor)
    pub sweep: String,
    /// block: x range, y range [m]
    pub block: ((f64, f64), (f64, f64)),
    /// released solids mass per metre of width [kg/m]
    pub mass: f64,
    /// tilt time of a time criterion (`FreeFall`, `At`) [s]; `None` for a field criterion
    pub tilt: Option<f64>,
    /// time the front reaches the station [s], or why not
    pub arrival: Result<f64, String>,
    /// the paper's t = 1.25 s in the run's clock [s]
    pub station_time: f64,
    /// front x at the station time [m], or why not
    pub front: Result<f64, String>,
    /// max u_s at the station at the profile time [m/s], or why not
    pub max_u_s: Result<f64, String>,
    /// floor-cell εs at the station at the profile time, or why not
    pub floor_eps_s: Result<f64, String>,
    /// air cushion at the station at the profile time, or why not
    pub cushion: Result<bool, String>,
    /// its thickness (0 without a cushion) [m], or why not
    pub cushion_thickness: Result<f64, String>,
    /// flow thickness at the station at the profile time [m], or why not
    pub flow_thickness: Result<f64, String>,
    /// the run's fidelity, if it has a run
    pub fidelity: Option<Fidelity>,
}

/// The first time `front` reaches `x`, linearly interpolated between samples.
pub fn arrival_time(front: &[(f64, f64)], x: f64) -> Option<f64> {
    let k = front.iter().position(|&(_, f)| f >= x)?;
    if k == 0 {
        return Some(front[0].0);
    }
    let ((t0, x0), (t1, x1)) = (front[k - 1], front[k]);
    Some(t0 + (t1 - t0) * (x - x0) / (x1 - x0))
}

/// The front at `t`: interpolated between the samples around it, or the last sample if it
/// is at most `LAST_SAMPLE_GAP` before `t` (a run ends between two bulk samples).
pub fn front_at(front: &[(f64, f64)], t: f64) -> Option<f64> {
    if let Some(k) = front.iter().position(|&(s, _)| s >= t) {
        if k == 0 {
            return (front[0].0 - t <= 1e-12).then_some(front[0].1);
        }
        let ((t0, x0), (t1, x1)) = (front[k - 1], front[k]);
        return Some(x0 + (x1 - x0) * (t - t0) / (t1 - t0));
    }
    front
        .last()
        .filter(|&&(s, _)| t - s <= LAST_SAMPLE_GAP)
        .map(|&(_, x)| x)
}

/// How long before a time the last bulk sample may be and still stand for it [s] (the
/// shipped bulk interval is 0.01 s).
const LAST_SAMPLE_GAP: f64 = 0.0101;

fn no_sample(front: &[(f64, f64)], t: f64) -> String {
    let end = front.last().map_or(0.0, |s| s.0);
    format!("the bulk samples end at t = {end:.3} s, before t = {t:.4} s")
}

/// The row of one release case from its run under `runs`.
pub fn release_row(runs: &Path, c: &SourcedCase, requested: Option<Fidelity>) -> ReleaseRow {
    let case = &c.case;
    let block = case
        .initial
        .regions
        .first()
        .map_or(((0.0, 0.0), (0.0, 0.0)), |r| (r.x, r.y));
    let mass = case
        .initial
        .regions
        .iter()
        .map(|r| {
            let area = (r.x.1 - r.x.0) * (r.y.1 - r.y.0);
            let solids: f64 = r
                .solids
                .iter()
                .zip(&case.solids)
                .map(|(b, s)| b.eps_s * s.density)
                .sum();
            area * solids
        })
        .sum();
    let station = case.monitors.profiles.first().map_or(f64::NAN, |p| p.x);
    let data = CaseData::load(runs, &case.name, requested);
    // the case's own, so that a case without a run has it too
    let station_time = runout_post::metrics::station_time(Some(&case.clone().with_start_clock()));
    let front_series = data
        .bulk
        .as_ref()
        .map_err(Clone::clone)
        .and_then(|b: &Table| b.pairs("t", "front_x"));
    let front = front_series
        .clone()
        .and_then(|f| front_at(&f, station_time).ok_or_else(|| no_sample(&f, station_time)));
    let arrival = front_series.and_then(|f| {
        arrival_time(&f, station).ok_or_else(|| {
            let end = f.last().map_or(0.0, |s| s.0);
            format!("not by t = {end:.2} s")
        })
    });
    // the reason a profile is missing is said once, in the max u_s column
    let flow = flow_at_station(&data);
    let brief = |_| "—".to_string();
    ReleaseRow {
        case: case.name.clone(),
        sweep: case.name.split('_').next().unwrap_or_default().to_string(),
        block,
        mass,
        tilt: case.scheduled_tilt_time(),
        arrival,
        station_time,
        front,
        max_u_s: flow
            .clone()
            .and_then(|m| m.max_u_s.ok_or_else(|| "no profile".into())),
        floor_eps_s: flow
            .clone()
            .map_err(brief)
            .and_then(|m| m.floor_eps_s.ok_or_else(|| "no profile".into())),
        cushion: flow
            .clone()
            .map_err(brief)
            .and_then(|m| m.air_cushion.ok_or_else(|| "no profile".into())),
        cushion_thickness: flow
            .clone()
            .map_err(brief)
            .and_then(|m| match m.air_cushion {
                Some(true) => m.cushion_thickness.ok_or_else(|| "no profile".into()),
                Some(false) => Ok(0.0),
                None => Err("no profile".into()),
            }),
        flow_thickness: flow
            .map_err(brief)
            .and_then(|m| m.flow_thickness.ok_or_else(|| "no profile".into())),
        fidelity: data.fidelity(),
    }
}

fn number(r: &Result<f64, String>, digits: usize) -> String {
    match r {
        Ok(v) => format!("{v:.digits$}"),
        Err(why) => missing(why),
    }
}

/// A missing value: "—", with its reason unless the reason is "—".
fn missing(why: &str) -> String {
    if why == "—" {
        why.into()
    } else {
        format!("— ({why})")
    }
}

/// The markdown table of `rows`.
pub fn table(rows: &[ReleaseRow]) -> String {
    let mut md = String::from(
        "| case | block x [m] | block y [m] | mass [kg/m] | tilt [s] | front at x = 11 m [s] | \
         profile t [s] | front at profile t [m] | max u_s [m/s] | floor εs | air cushion | \
         fidelity |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        let ((x0, x1), (y0, y1)) = r.block;
        let cushion = match &r.cushion {
            Ok(true) => "yes".to_string(),
            Ok(false) => "no".to_string(),
            Err(why) => missing(why),
        };
        let _ = writeln!(
            md,
            "| `{}` | {x0:.2}–{x1:.2} | {y0:.2}–{y1:.2} | {:.1} | {} | {} | {:.4} | {} | {} | {} | {cushion} | {} |",
            r.case,
            r.mass,
            r.tilt.map_or("field".into(), |t| format!("{t:.4}")),
            number(&r.arrival, 3),
            r.station_time,
            number(&r.front, 2),
            number(&r.max_u_s, 2),
            number(&r.floor_eps_s, 3),
            r.fidelity.map_or("—".into(), |f| f.to_string()),
        );
    }
    md
}

/// The station numbers of the release rows, one CSV per fidelity beside the page
/// (`reports/release/release_<fidelity>.csv`; an empty field where the row has no value),
/// read by the results report's explanation of the findings (`explain.rs`).
pub const CSV_COLUMNS: [&str; 7] = [
    "case",
    "sweep",
    "max_u_s",
    "floor_eps_s",
    "air_cushion",
    "cushion_thickness",
    "flow_thickness",
];

/// The CSV of `rows` (header [`CSV_COLUMNS`]).
pub fn csv_text(rows: &[ReleaseRow]) -> String {
    let mut text = CSV_COLUMNS.join(",");
    text.push('\n');
    let v = |r: &Result<f64, String>| r.as_ref().map_or(String::new(), |v| format!("{v:e}"));
    for r in rows {
        let cushion = r
            .cushion
            .as_ref()
            .map_or(String::new(), |&b| u8::from(b).to_string());
        let _ = writeln!(
            text,
            "{},{},{},{},{cushion},{},{}",
            r.case,
            r.sweep,
            v(&r.max_u_s),
            v(&r.floor_eps_s),
            v(&r.cushion_thickness),
            v(&r.flow_thickness)
        );
    }
    text
}

/// Writes the page and its figures (one table and one figure per fidelity that has runs, or
/// the requested one); returns the page.
pub fn write(root: &Path, requested: Option<Fidelity>) -> Result<String> {
    let matrix = runout_study::sweep::study_matrix(&root.join("cases"), STUDY)?;
    let runs = root.join("runs");
    let docs = root.join("docs");
    let (lo, hi) = JENKINS_MAX_U_S;
    let flag = requested.map_or(String::new(), |f| format!(" --fidelity {f}"));
    let mut md = format!(
        "# The station against the unreported release (generated)\n\n\
         Generated by `cargo xtask report release{flag}` from the runs of \
         `cargo xtask sweep --study release --fidelity F` (cases/sensitivity/release-*.ron); \
         what the rows mean and the criterion chosen from them: docs/studies/impact.md §4.\n\n\
         Each sweep moves one factor of base.ron's block (0.5 × 0.2 m at εs = 0.6, front edge \
         at 5.5 m, bottom at 0.40 m) at a time; `-t0` sweeps count the times from the tilt. \
         Criterion (docs/studies/impact.md §4): the Jenkins d = 0.5 mm flow's max u_s at the station \
         at the paper's t = {PROFILE_TIME} s nearest {:.3} m/s, the middle of the paper's \
         {lo}–{hi} m/s.\n",
        0.5 * (lo + hi)
    );
    let fidelities = requested.map_or(
        vec![Fidelity::Coarse, Fidelity::Wall, Fidelity::Paper],
        |f| vec![f],
    );
    for fidelity in fidelities {
        let rows: Vec<ReleaseRow> = matrix
            .runs
            .iter()
            .map(|c| release_row(&runs, c, Some(fidelity)))
            .filter(|r| requested.is_some() || r.fidelity.is_some())
            .collect();
        if rows.is_empty() {
            continue;
        }
        let figure = format!("reports/release/front_{fidelity}.svg");
        let path = docs.join(&figure);
        std::fs::create_dir_all(path.parent().expect("a folder"))?;
        let mut sweeps: Vec<&str> = rows.iter().map(|r| r.sweep.as_str()).collect();
        sweeps.dedup();
        let panels: Vec<Panel> = sweeps
            .iter()
            .map(|&sweep| front_panel(&runs, &matrix.runs, sweep, Some(fidelity)))
            .collect();
        draw(&path, &panels, panels.len().max(1))?;
        let csv = docs.join(format!("reports/release/release_{fidelity}.csv"));
        std::fs::write(&csv, csv_text(&rows)).with_context(|| format!("{}", csv.display()))?;
        let _ = write!(md, "\n## {fidelity} fidelity\n\n{}", table(&rows));
        let _ = write!(
            md,
            "\n![Front x(t) of every release at {fidelity} fidelity]({})\n\n*The front (the \
             furthest cell with εs ≥ the bulk monitor's threshold) against time; dashed: the \
             station.*\n",
            figure.trim_start_matches("reports/")
        );
    }
    let page = docs.join(PAGE);
    std::fs::write(&page, &md).with_context(|| format!("writing {}", page.display()))?;
    Ok(md)
}

/// The fronts of one sweep's runs.
fn front_panel(
    runs: &Path,
    cases: &[SourcedCase],
    sweep: &str,
    requested: Option<Fidelity>,
) -> Panel {
    let series = cases
        .iter()
        .filter(|c| c.case.name.split('_').next() == Some(sweep))
        .enumerate()
        .filter_map(|(k, c)| {
            let data = CaseData::load(runs, &c.case.name, requested);
            let points = data.bulk.ok()?.pairs("t", "front_x").ok()?;
            Some(Series {
                label: c
                    .case
                    .name
                    .split_once('=')
                    .map_or("", |(_, l)| l)
                    .to_string(),
                points,
                colour: k,
                mark: Mark::Line,
            })
        })
        .collect();
    let station = cases
        .first()
        .and_then(|c| c.case.monitors.profiles.first())
        .map_or(11.0, |p| p.x);
    Panel {
        title: format!("{sweep}: front x(t)"),
        x_label: "t [s]".into(),
        y_label: "front x [m]".into(),
        series,
        vertical: vec![(PROFILE_TIME, format!("t = {PROFILE_TIME} s"))],
        horizontal: vec![(station, "station".into())],
        y_from_zero: false,
    }
}

/// `cargo xtask report release`.
pub fn report(root: &Path, requested: Option<Fidelity>) -> Result<()> {
    let md = write(root, requested)?;
    println!(
        "wrote docs/{PAGE} ({} release row(s)) and its figures in docs/reports/release/",
        md.lines().filter(|l| l.starts_with("| `")).count()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_front_is_interpolated_and_the_last_sample_stands_for_the_end() {
        let front = [(1.0, 10.0), (1.01, 10.1), (1.02, 10.3)];
        assert!((front_at(&front, 1.005).unwrap() - 10.05).abs() < 1e-12);
        assert_eq!(front_at(&front, 1.025), Some(10.3));
        assert_eq!(front_at(&front, 1.05), None);
        assert_eq!(front_at(&front, 0.9), None);
    }

    #[test]
    fn the_arrival_is_interpolated_between_samples() {
        let front = [(0.0, 5.5), (1.0, 10.0), (1.1, 12.0)];
        assert!((arrival_time(&front, 11.0).unwrap() - 1.05).abs() < 1e-12);
        assert_eq!(arrival_time(&front, 5.0), Some(0.0));
        assert_eq!(arrival_time(&front, 13.0), None);
    }

    #[test]
    fn every_release_case_has_a_row_that_says_why_it_is_missing() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let matrix = runout_study::sweep::study_matrix(&root.join("cases"), STUDY).unwrap();
        assert_eq!(matrix.runs.len(), 36);
        let empty = std::env::temp_dir().join(format!("runout-release-{}", std::process::id()));
        let named = |name: &str| {
            let c = matrix.runs.iter().find(|c| c.case.name == name).unwrap();
            release_row(&empty, c, None)
        };
        // a clock from the impact: the profile is 1.25 s after the tilt
        let t0 = named("R-JJ-t0_release=L0.5-H0.2-F5.5-B0.2");
        assert!((t0.station_time - 1.25 - (0.4 / 9.80665_f64).sqrt()).abs() < 1e-12);
        let row = named("R-JEN_release=L0.5-H0.2-F5.5-B0.4");
        assert!((row.mass - 120.0).abs() < 1e-9, "{}", row.mass);
        // FreeFall from 0.40 m: sqrt(0.8 / 9.80665)
        assert!((row.tilt.unwrap() - 0.285_617_396_245_806_9).abs() < 1e-12);
        assert_eq!(row.arrival.as_ref().unwrap_err(), "not run");
        let csv = csv_text(std::slice::from_ref(&row));
        assert_eq!(
            csv.lines().nth(1),
            Some("R-JEN_release=L0.5-H0.2-F5.5-B0.4,R-JEN,,,,,")
        );
        let md = table(&[row]);
        assert!(md.contains("| `R-JEN_release=L0.5-H0.2-F5.5-B0.4` | 5.00–5.50 | 0.40–0.60 | 120.0 | 0.2856 | — (not run) | 1.2500 |"), "{md}");
    }
}
