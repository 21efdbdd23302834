//! The sensitivity section of results.md (issue 23, item 3): the elasticity of each output
//! of the report over each one-factor family of family S, as a table, a heat map
//! (`sensitivity.svg`) and a CSV of every pair (`elasticities.csv`). The computation is
//! [`runout_study::sensitivity`]; this module finds the families in the matrix and reads the
//! outputs of their runs.

use std::collections::BTreeSet;
use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};

use super::coverage::remove_stale;
use super::plots::{self, HeatCell, Heatmap};
use super::record::RunRecord;
use super::records::Records;
use super::{cell, FIGURE_DIR};
use runout_post::metrics::PROFILE_TIME;
use runout_study::families::Family;
use runout_study::sensitivity::{local, summary, Elasticity, Method, Summary};
use runout_study::sweep::{csv_field, Matrix};

/// The case directory of family S (the sensitivity study) below `cases/`.
pub const SENSITIVITY_DIR: &str = "sensitivity";
/// The heat map, in the figure directory.
const HEATMAP_FILE: &str = "sensitivity.svg";
/// Every pair's elasticity, in the figure directory.
const CSV_FILE: &str = "elasticities.csv";

/// The one-factor families of the sweeps of family S (`cases/sensitivity/`) in the matrix,
/// in the matrix's order. The flume's φ pair (F-JJ) is left out: its outputs are gate
/// speeds, not the station quantities.
pub fn families(matrix: &Matrix, cases_dir: &Path) -> Result<Vec<Family>> {
    runout_study::families::families(matrix, &cases_dir.join(SENSITIVITY_DIR))
}

/// An output of the report whose elasticity is computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Output {
    /// largest u_s of the station profile [m/s]
    MaxUs,
    /// front x (bulk.csv) minus the release's front edge [m]
    FrontTravel,
    /// εs-weighted mean u_s over the domain (bulk.csv) [m/s]
    MeanUs,
    /// εs of the floor cell at the station [-]
    FloorEpsS,
    /// air-cushion thickness at the station [m]
    CushionThickness,
    /// flow thickness at the station [m]
    FlowThickness,
    /// h_w^u at the floor probe [1/m]
    ProbeHu,
}

/// The outputs, in the table's order.
pub const OUTPUTS: [Output; 7] = [
    Output::MaxUs,
    Output::FrontTravel,
    Output::MeanUs,
    Output::FloorEpsS,
    Output::CushionThickness,
    Output::FlowThickness,
    Output::ProbeHu,
];

/// The largest x of the release blocks of `case` in the matrix (the blocks are the same at
/// every fidelity).
fn release_front(matrix: &Matrix, case: &str) -> Result<f64, String> {
    let run = matrix
        .runs
        .iter()
        .find(|r| r.case.name == case)
        .ok_or_else(|| "not in the case matrix".to_string())?;
    run.case
        .initial
        .regions
        .iter()
        .map(|b| b.x.1)
        .reduce(f64::max)
        .ok_or_else(|| "the case has no release block".into())
}

/// Whether the record's probe reading (the last sample at or before the station time) is
/// its last sample at or before `t`: at the station time, or at or past its end.
fn probe_holds_at(r: &RunRecord, t: f64) -> bool {
    (t - r.station_time).abs() <= 1e-9 * t.max(1.0) || t >= r.end_time * (1.0 - 1e-9)
}

impl Output {
    /// Column name of the table.
    pub fn label(self) -> &'static str {
        match self {
            Output::MaxUs => "max u_s",
            Output::FrontTravel => "front travel",
            Output::MeanUs => "mean u_s",
            Output::FloorEpsS => "floor εs",
            Output::CushionThickness => "cushion thickness",
            Output::FlowThickness => "flow thickness",
            Output::ProbeHu => "h_w^u at the probe",
        }
    }

    /// Column name of the heat map (short, ASCII).
    fn short(self) -> &'static str {
        match self {
            Output::MaxUs => "max u_s",
            Output::FrontTravel => "front travel",
            Output::MeanUs => "mean u_s",
            Output::FloorEpsS => "floor eps_s",
            Output::CushionThickness => "cushion",
            Output::FlowThickness => "flow thick.",
            Output::ProbeHu => "h_w^u probe",
        }
    }

    /// The output of the record `r` of `case`; the time series at `t`.
    pub fn read(self, r: &RunRecord, t: f64, matrix: &Matrix) -> Result<f64, String> {
        let unknown = || "not defined for this profile".to_string();
        match self {
            Output::MaxUs => r.flow()?.max_u_s.ok_or_else(unknown),
            Output::FloorEpsS => Ok(r.flow()?.floor_eps_s),
            Output::FlowThickness => r.flow()?.flow_thickness.ok_or_else(unknown),
            Output::CushionThickness => {
                let m = r.flow()?;
                match m.air_cushion {
                    Some(true) => m.cushion_thickness.ok_or_else(unknown),
                    _ => Err("no air cushion (thickness 0)".into()),
                }
            }
            Output::FrontTravel => {
                let (x, _) = bulk_at(r, t)?;
                let edge = release_front(matrix, &r.case)?;
                if x <= edge {
                    return Err(format!(
                        "the front has not passed the release's front edge (x = {edge} m) by \
                         t = {t:.2} s"
                    ));
                }
                Ok(x - edge)
            }
            Output::MeanUs => Ok(bulk_at(r, t)?.1),
            Output::ProbeHu => {
                if let Some(why) = r.ended_before(t) {
                    return Err(why);
                }
                if !probe_holds_at(r, t) {
                    return Err(format!("no probe reading at t = {t} s recorded"));
                }
                let (_, h) = r.probe.clone()?;
                if h == 0.0 {
                    return Err(format!(
                        "h_w^u = 0 at the floor probe at t = {t:.2} s (no solids at the probe yet)"
                    ));
                }
                Ok(h)
            }
        }
    }
}

/// (front x, mean u_s) of a record at `t`: why not if the run ended before `t`.
fn bulk_at(r: &RunRecord, t: f64) -> Result<(f64, f64), String> {
    if let Some(why) = r.ended_before(t) {
        return Err(why);
    }
    r.bulk_at_station_or_end(t)
}

/// The station time of a family's runs: the paper's t = 1.25 s in their clock (1.25 s after
/// the impact for family S, docs/studies/impact.md §4), the same for every run of a family.
fn family_station_time(family: &Family, records: &Records) -> f64 {
    family
        .points
        .iter()
        .find_map(|(_, c)| records.get(c).ok().map(|r| r.station_time))
        .unwrap_or(PROFILE_TIME)
}

/// A family's time of the time-series outputs: its station time, or the last time its runs
/// reach if they all end before (smoke runs).
fn family_time(family: &Family, records: &Records) -> f64 {
    let station = family_station_time(family, records);
    family
        .points
        .iter()
        .filter_map(|(_, c)| records.get(c).ok().map(|r| r.end_time))
        .reduce(f64::max)
        .map_or(station, |t| t.min(station))
}

/// An elasticity for a table cell or the heat map: 2 decimals, or 2 digits if small; `*`
/// marks an arc elasticity.
fn format_elasticity(e: &Elasticity) -> String {
    let v = e.value;
    let number = if v == 0.0 {
        "0".to_string()
    } else if v.abs() >= 0.01 {
        format!("{v:.2}")
    } else {
        format!("{v:.1e}")
    };
    match e.method {
        Method::LogLog => number,
        Method::Arc => format!("{number}*"),
    }
}

/// A parameter value as written in the sweep files.
fn value(p: f64) -> String {
    format!("{p}")
}

/// The computed section: the per-(family, output) summaries and their notes.
struct Computed {
    families: Vec<Family>,
    /// `summaries[family][output]`
    summaries: Vec<Vec<Summary>>,
    /// time-series time per family
    times: Vec<f64>,
    /// CSV of every pair and summary
    csv: String,
}

fn compute(families: Vec<Family>, records: &Records, matrix: &Matrix) -> Computed {
    let mut csv = String::from(
        "family,parameter,output,kind,p_low,p_high,at,method,elasticity,points_used,reason\n",
    );
    let mut summaries = Vec::new();
    let mut times = Vec::new();
    for f in &families {
        let t = family_time(f, records);
        times.push(t);
        let mut row = Vec::new();
        for o in OUTPUTS {
            let points: Vec<(f64, Result<f64, String>)> = f
                .points
                .iter()
                .map(|(p, case)| (*p, records.get(case).and_then(|r| o.read(r, t, matrix))))
                .collect();
            let method = |m: Method| match m {
                Method::LogLog => "log-log",
                Method::Arc => "arc",
            };
            for l in local(&points) {
                let (m, e, used, why) = match &l.elasticity {
                    Ok(e) => (method(e.method), format!("{}", e.value), 2, String::new()),
                    Err(why) => ("", String::new(), 0, why.clone()),
                };
                let _ = writeln!(
                    csv,
                    "{},{},{},pair,{},{},{},{m},{e},{used},{}",
                    csv_field(&f.label()),
                    csv_field(f.symbol),
                    csv_field(o.label()),
                    l.p.0,
                    l.p.1,
                    l.at,
                    csv_field(&why)
                );
            }
            let s = summary(&points);
            let (lo, hi) = s.range.map_or((String::new(), String::new()), |(a, b)| {
                (a.to_string(), b.to_string())
            });
            let (m, e, why) = match &s.elasticity {
                Ok(e) => (method(e.method), format!("{}", e.value), String::new()),
                Err(why) => ("", String::new(), why.clone()),
            };
            let _ = writeln!(
                csv,
                "{},{},{},summary,{lo},{hi},,{m},{e},{},{}",
                csv_field(&f.label()),
                csv_field(f.symbol),
                csv_field(o.label()),
                s.used,
                csv_field(&why)
            );
            row.push(s);
        }
        summaries.push(row);
    }
    Computed {
        families,
        summaries,
        times,
        csv,
    }
}

/// Writes the sensitivity section of results.md and its figure and CSV into `out`.
pub fn section(
    md: &mut String,
    matrix: &Matrix,
    cases_dir: &Path,
    records: &Records,
    out: &Path,
) -> Result<()> {
    md.push_str("## Sensitivity: elasticities of the one-factor families (issue 23)\n\n");
    let c = compute(families(matrix, cases_dir)?, records, matrix);
    let svg = out.join(HEATMAP_FILE);
    let csv = out.join(CSV_FILE);
    if c.families.is_empty() {
        remove_stale(&svg)?;
        remove_stale(&csv)?;
        md.push_str("*No one-factor family in cases/sensitivity/.*\n\n");
        return Ok(());
    }
    method(md);
    let heat_cells = table(md, &c, records);
    heat_map(&c, heat_cells, &svg)?;
    runout_output::write_atomic(&csv, c.csv.as_bytes())
        .with_context(|| format!("writing {}", csv.display()))?;
    let _ = writeln!(
        md,
        "![Elasticities]({FIGURE_DIR}/{HEATMAP_FILE})\n\n\
         Heat map of the table: rows are the families, columns the outputs, colour the \
         summary elasticity on a scale symmetric about 0 (red: the output grows with the \
         parameter, blue: it falls); \\* marks an arc elasticity; grey cells have no value.\n"
    );
    Ok(())
}

/// How the elasticities are computed, the outputs and the limits.
fn method(md: &mut String) {
    let _ = writeln!(
        md,
        "**How it is computed** (crates/study/src/sensitivity.rs). A one-factor family is the runs of \
         one sweep of cases/{SENSITIVITY_DIR}/ that differ in one parameter p only (φ, d, h_w^u, \
         h_w^θ, c_w or the slope; a sweep's other varied parameter is held, and named in \
         brackets). For each output y the elasticity E = ∂ln y/∂ln p (the % change of y per % \
         change of p) is taken by differences over the swept points: for neighbours \
         pᵢ < pᵢ₊₁, (ln yᵢ₊₁ − ln yᵢ)/(ln pᵢ₊₁ − ln pᵢ), at the geometric mid-point √(pᵢpᵢ₊₁) \
         (every pair is in [{FIGURE_DIR}/{CSV_FILE}]({FIGURE_DIR}/{CSV_FILE})). The table and \
         the heat map give one number per family and output: the least-squares slope of ln y \
         against ln p over the family's points (for two points, the pair's value; exact for a \
         power law y = a·p^b). Where p = 0 (the 0° slope) ln p does not exist: the pair's arc \
         elasticity (Δy/ȳ)/(Δp/p̄) at the arithmetic mid-point is given instead, marked \\*; on \
         a pair (0, p) it is half the relative change Δy/ȳ, within ±1, and not comparable in \
         size with the others. A point without a usable output (no run, a run that ended \
         before the time read, no flow at the station, no cushion, y ≤ 0) is left out; a \
         number over fewer points than the family has gives the range it covers, and a cell \
         without two usable points is \"—\" with the reason in the notes below the table.\n\n\
         **Outputs.** max u_s, floor εs, cushion thickness and flow thickness: the station \
         profile at x = 11 m at the station time, as in the tables above (a cushion \
         thickness of 0, no cushion, has no elasticity). Front travel: the front x of bulk.csv \
         (where the floor row's εs falls through 0.01) minus the release block's front edge \
         (x = 5.5 m), a distance from a natural origin, so its elasticity does not depend on \
         where the domain starts. Mean u_s: the εs-weighted mean over the domain (bulk.csv). \
         Front travel, mean u_s and h_w^u at the floor probe are read at the station time (the \
         paper's t = {PROFILE_TIME} s: for family S 1.25 s after the impact, the run's \
         t = 1.536 s, docs/studies/impact.md §4), or, where the family's runs all end before it, at \
         their end (column \"read at\"); the profile exists only at the station time.\n\n\
         **Limits.** One-at-a-time: each family moves one parameter with the others at that \
         sweep's base, so interactions are not seen, and the base differs between families \
         (d is swept at Johnson–Jackson φ = 0.1, at Jenkins and at partial slip). Local and on \
         the swept points only: secants between points that are far apart (φ and d by factors \
         of 2–10), so a threshold response such as a cushion appearing is summarised by one \
         number that hides it, and nothing is said between or beyond the points. The numbers \
         carry the runs' discretisation error (docs/reports/error-time.md), which at coarse fidelity \
         is of the size of some differences here; the bulk front moves in whole cells (0.2 m \
         at smoke, 0.08 m at coarse fidelity), so front travel changes in steps and a 0 can \
         mean a change below one cell. At smoke and coarse fidelity the station \
         quantities are often missing because the flow has not reached the station (smoke \
         runs stop at 0.4 s), and the time-series outputs are then read at the runs' end, a \
         different state from the paper's t = 1.25 s.\n"
    );
}

/// The number (from 1) of the note `why`, added if new.
fn note_number(notes: &mut Vec<String>, why: &str) -> usize {
    match notes.iter().position(|n| n == why) {
        Some(k) => k + 1,
        None => {
            notes.push(why.to_string());
            notes.len()
        }
    }
}

/// The table of summary elasticities, one row per family, and the notes on its "—" cells;
/// returns the heat map's cells.
fn table(md: &mut String, c: &Computed, records: &Records) -> Vec<Vec<HeatCell>> {
    let mut notes: Vec<String> = Vec::new();
    let _ = writeln!(
        md,
        "| family | parameter | fidelity | read at | {} |",
        OUTPUTS.map(|o| o.label()).join(" | ")
    );
    let _ = writeln!(md, "|---|---|---|---|{}", "---|".repeat(OUTPUTS.len()));
    let heat_cells = (0..c.families.len())
        .map(|k| table_row(md, c, k, records, &mut notes))
        .collect();
    md.push('\n');
    if !notes.is_empty() {
        md.push_str("Why a cell is \"—\":\n\n");
        for (k, n) in notes.iter().enumerate() {
            let _ = writeln!(md, "{}. {}", k + 1, n);
        }
        md.push('\n');
    }
    heat_cells
}

/// The row of family `k`; returns its heat map cells.
fn table_row(
    md: &mut String,
    c: &Computed,
    k: usize,
    records: &Records,
    notes: &mut Vec<String>,
) -> Vec<HeatCell> {
    let f = &c.families[k];
    let fidelities: BTreeSet<String> = f
        .points
        .iter()
        .filter_map(|(_, case)| records.get(case).ok().map(|r| r.fidelity.to_string()))
        .collect();
    let fidelity = if fidelities.is_empty() {
        "—".to_string()
    } else {
        fidelities.into_iter().collect::<Vec<_>>().join(" + ")
    };
    let t = c.times[k];
    let station = family_station_time(f, records);
    let read_at = if t < station {
        format!("t = {t:.2} s (profile: {station:.3} s)")
    } else {
        format!("t = {station:.3} s")
    };
    let values: Vec<String> = f.points.iter().map(|(p, _)| value(*p)).collect();
    let mut row_cells = Vec::new();
    let mut text = Vec::new();
    for s in &c.summaries[k] {
        match &s.elasticity {
            Ok(e) => {
                let mut t = format_elasticity(e);
                row_cells.push(HeatCell {
                    value: Some(e.value),
                    label: t.clone(),
                });
                if s.used < s.of {
                    if let Some((lo, hi)) = s.range {
                        let _ = write!(
                            t,
                            " ({} of {} points: {}–{})",
                            s.used,
                            s.of,
                            value(lo),
                            value(hi)
                        );
                    }
                }
                text.push(t);
            }
            Err(why) => {
                row_cells.push(HeatCell {
                    value: None,
                    label: "—".into(),
                });
                text.push(format!("— [{}]", note_number(notes, why)));
            }
        }
    }
    let fixed = if f.fixed.is_empty() {
        String::new()
    } else {
        format!(" ({})", f.fixed.join(", "))
    };
    let _ = writeln!(
        md,
        "| `{}`{} | {} [{}] ∈ {{{}}} | {fidelity} | {read_at} | {} |",
        f.sweep,
        cell(&fixed),
        f.symbol,
        f.unit,
        values.join(", "),
        text.iter().map(|t| cell(t)).collect::<Vec<_>>().join(" | ")
    );
    row_cells
}

/// Draws the heat map of the table into `svg`.
fn heat_map(c: &Computed, heat_cells: Vec<Vec<HeatCell>>, svg: &Path) -> Result<()> {
    let map = Heatmap {
        title: "Elasticity d ln y / d ln p of each output over each one-factor family".into(),
        rows: c.families.iter().map(Family::label).collect(),
        columns: OUTPUTS.iter().map(|o| o.short().to_string()).collect(),
        cells: heat_cells,
        note:
            "* arc elasticity (the family has p = 0); grey: no value (see docs/reports/results.md)"
                .into(),
    };
    plots::draw_heatmap(svg, &map)
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_post::fixture::*;

    fn cases_dir() -> std::path::PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases")
    }

    #[test]
    fn the_families_of_family_s_are_found_and_name_cases_of_the_matrix() {
        let matrix = crate::matrix::paper_matrix(&cases_dir()).unwrap();
        let fams = families(&matrix, &cases_dir()).unwrap();
        let labels: Vec<String> = fams.iter().map(Family::label).collect();
        for expected in [
            "S-JJ-phi: φ",
            "S-JJ-d: d",
            "S-JEN-d: d",
            "S-PS-d: d",
            "S-PS-hu: h_w^u",
            "S-PS-cw: c_w (slope = 40)",
            "S-PS-cw: c_w (slope = 0)",
            "S-PS-cw: slope (c_w = 0.1)",
            "S-PS-cw: slope (c_w = 10)",
            "S-PS-htheta: h_w^θ (slope = 0)",
            "S-PS-htheta: slope (h_w^θ = 100)",
        ] {
            assert!(
                labels.contains(&expected.to_string()),
                "{expected}: {labels:?}"
            );
        }
        // S-RJJ varies nothing; the flume is not family S
        assert!(!labels
            .iter()
            .any(|l| l.starts_with("S-RJJ") || l.starts_with('F')));
        assert_eq!(fams.len(), 15, "{labels:?}");
        let names: BTreeSet<&str> = matrix.runs.iter().map(|r| r.case.name.as_str()).collect();
        for f in &fams {
            for (_, case) in &f.points {
                assert!(names.contains(case.as_str()), "{case}");
            }
        }
        let cw = fams
            .iter()
            .find(|f| f.label() == "S-PS-cw: slope (c_w = 1)")
            .unwrap();
        assert_eq!(
            cw.points,
            [
                (40.0, "S-PS-cw_cw=1_slope=40".to_string()),
                (0.0, "S-PS-cw_cw=1_slope=0".to_string())
            ]
        );
    }

    /// A profile whose max u_s is `u` with a 0.015 m thick flow and no cushion.
    fn profile(u: f64) -> String {
        format!(
            "y,eps_s,u_s,theta\n0.0025,0.6,{},0.1\n0.0075,0.55,{u},0.2\n0.0125,0.3,{},0.3\n\
             0.0175,0.0,0.0,0.0\n",
            0.5 * u,
            0.8 * u
        )
    }

    /// End to end: made-up runs of S-PS-hu whose max u_s is 8·h_u^(−1/4) and whose mean
    /// u_s is linear in h_u; the table gives −0.25 for the first, and the reasons of the
    /// missing outputs.
    #[test]
    fn the_section_recovers_a_made_up_power_law_and_names_what_is_missing() {
        let tmp = TempDir::new("sensitivity");
        let runs = tmp.0.join("runs");
        let matrix = crate::matrix::paper_matrix(&cases_dir()).unwrap();
        let base = matrix
            .runs
            .iter()
            .find(|r| r.case.name == "S-PS-hu_hu=1")
            .unwrap();
        let resolved =
            ron::ser::to_string_pretty(&base.case, ron::ser::PrettyConfig::default()).unwrap();
        for hu in [1.0, 10.0, 40.0, 70.0, 100.0] {
            let case = format!("S-PS-hu_hu={hu}");
            let u = 8.0 * f64::powf(hu, -0.25);
            // front 1 m + hu/100 m past the release edge at 5.5 m
            let bulk = format!(
                "t,solids_mass,front_x,mean_u_s\n1.25,1,{},{}\n",
                6.5 + hu / 100.0,
                2.0 + 0.01 * hu
            );
            write_run(
                &runs,
                &case,
                "coarse",
                1.25,
                &[
                    ("profile_x11_t1.25.csv", &profile(u)),
                    ("bulk.csv", &bulk),
                    ("resolved.ron", &resolved),
                ],
            );
        }
        let names: Vec<&str> = matrix.runs.iter().map(|r| r.case.name.as_str()).collect();
        let cases = super::super::records::from_runs(&runs, &names, None);
        let out = tmp.0.join("docs").join(FIGURE_DIR);
        std::fs::create_dir_all(&out).unwrap();
        let mut md = String::new();
        section(&mut md, &matrix, &cases_dir(), &cases, &out).unwrap();
        let row = md
            .lines()
            .find(|l| l.starts_with("| `S-PS-hu` |"))
            .unwrap_or_else(|| panic!("{md}"));
        let c: Vec<&str> = row.split(" | ").collect();
        assert_eq!(c[1], "h_w^u [1/m] ∈ {1, 10, 40, 70, 100}");
        assert_eq!(c[2], "coarse");
        assert_eq!(c[3], "t = 1.250 s");
        assert_eq!(c[4], "-0.25", "max u_s: {row}");
        // front travel 1 + hu/100: the least-squares log-log slope, positive and below 1
        let travel: f64 = c[5].parse().unwrap();
        assert!(0.0 < travel && travel < 1.0, "{row}");
        let mean: f64 = c[6].parse().unwrap();
        assert!(
            0.0 < mean && mean < 1.0 / 3.0,
            "linear, below its end elasticity: {row}"
        );
        assert_eq!(c[7], "0", "floor εs is the same at every point");
        assert!(c[8].starts_with("— ["), "no cushion: {row}");
        assert!(md.contains("no air cushion (thickness 0)"));
        assert_eq!(c[9], "0", "flow thickness");
        // a family without runs says why
        assert!(md.contains("not run"));
        // the heat map has a cell and a label per family and output
        let svg = std::fs::read_to_string(out.join(HEATMAP_FILE)).unwrap();
        assert!(
            svg.contains("S-PS-hu: h_w^u") && svg.contains("\n-0.25\n"),
            "{svg}"
        );
        assert!(svg.matches("<rect").count() >= 15 * OUTPUTS.len());
        let csv = std::fs::read_to_string(out.join(CSV_FILE)).unwrap();
        assert_eq!(
            csv.lines()
                .filter(|l| l.starts_with("S-PS-hu: h_w^u,h_w^u,max u_s,pair"))
                .count(),
            4
        );
        // no family: the figure goes
        let mut md = String::new();
        let empty = Matrix {
            runs: Vec::new(),
            analytic: Vec::new(),
        };
        section(&mut md, &empty, &cases_dir(), &cases, &out).unwrap();
        assert!(!out.join(HEATMAP_FILE).exists());
    }
}
