//! `cargo xtask report [results] [--fidelity F]`: the sweep's runs beside the paper (issue 8).
//!
//! Writes `docs/results.md` and, in `docs/results/`, SVG figures of the quantities and axes
//! of paper Figs. 4, 5, 7, 8, 9, 12, 13 and 14 (Fig. 1 is `cargo xtask report analytic`,
//! linked), a table of every number the paper reports beside runout's, the flume's gate
//! speeds with their mean square error against the described speeds, the family-M
//! cross-check against MFIX, and the elasticities of the one-factor families of family S
//! (issue 23, [`crate::sensitivity`]) as a table and a heat map.
//!
//! Each case is read from `runs/<case>/<fidelity>/` (written by `cargo xtask sweep` or
//! `runout run`): by default the best fidelity with a finished run (paper, then coarse, then
//! smoke), with `--fidelity` only that one. What a case lacks (no run, a run that ended
//! before the paper's time, a monitor file the run does not have) is said in the figure's
//! caption and in the tables; it is never an error.

pub mod data;
mod fields;
mod findings;
mod paper;
pub(crate) mod plots;
pub mod release;
mod sensitivity;

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use runout_case::Fidelity;
use runout_output::RunStatus;

use crate::metrics::{mse_vs_described, PROFILE_TIME};
use data::{CaseData, Cases, Profile};
use paper::{
    reading, ProfileFigure, CUSHION_LIMIT_H_U, FIELD_FIGURES, FLUME, FLUME_SIDEWALLS, MFIX_CASE,
    MFIX_SLIDE, PAPER_NUMBERS, PROBE_CURVES, PROFILE_FIGURES,
};
use plots::{Mark, Panel, Series};

/// Output file, relative to the docs directory.
const RESULTS_FILE: &str = "results.md";
/// Figure directory, relative to the docs directory.
const FIGURE_DIR: &str = "results";

/// Where the report reads and writes.
pub struct ReportPaths {
    /// run folders: `<runs>/<case>/<fidelity>/`
    pub runs: PathBuf,
    /// case directory (the matrix and `flume/gates.csv`)
    pub cases: PathBuf,
    /// docs directory: `results.md` and `results/*.svg` go here
    pub docs: PathBuf,
}

/// Which cases a figure drew at which fidelity, and which it lacks and why.
#[derive(Default)]
struct Coverage {
    /// fidelity → cases drawn
    drawn: BTreeMap<String, Vec<String>>,
    /// reason → cases missing
    missing: BTreeMap<String, Vec<String>>,
}

impl Coverage {
    fn add_drawn(&mut self, case: &str, fidelity: Option<Fidelity>) {
        let f = fidelity.map_or("?".into(), |f| f.to_string());
        let list = self.drawn.entry(f).or_default();
        if !list.iter().any(|c| c == case) {
            list.push(case.into());
        }
    }

    fn add_missing(&mut self, case: &str, why: &str) {
        let list = self.missing.entry(why.into()).or_default();
        if !list.iter().any(|c| c == case) {
            list.push(case.into());
        }
    }

    fn is_empty(&self) -> bool {
        self.drawn.is_empty()
    }

    /// "Fidelity: …. Missing (…): …." for the caption.
    fn caption(&self) -> String {
        let list = |cases: &[String]| {
            cases
                .iter()
                .map(|c| format!("`{c}`"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let mut s = String::new();
        if !self.drawn.is_empty() {
            let parts: Vec<String> = self
                .drawn
                .iter()
                .map(|(f, cases)| format!("**{f}** ({})", list(cases)))
                .collect();
            let _ = write!(s, " Fidelity: {}.", parts.join("; "));
        }
        for (why, cases) in &self.missing {
            let _ = write!(s, " **Missing** ({why}): {}.", list(cases));
        }
        s
    }
}

/// Legend label with the run's fidelity.
fn legend(label: &str, fidelity: Option<Fidelity>) -> String {
    fidelity.map_or(label.into(), |f| format!("{label} ({f})"))
}

/// First pass over a figure's curves: which cases have data.
fn coverage<'a>(
    cases: &Cases,
    curves: impl IntoIterator<Item = &'a str>,
    has: impl Fn(&CaseData) -> Result<(), String>,
) -> Coverage {
    let mut c = Coverage::default();
    for case in curves {
        let d = cases.get(case);
        match has(&d) {
            Ok(()) => c.add_drawn(case, d.fidelity()),
            Err(why) => c.add_missing(case, &why),
        }
    }
    c
}

/// Removes a stale figure (from an earlier report) that has no data now.
fn remove_stale(path: &Path) -> Result<()> {
    if path.exists() {
        std::fs::remove_file(path).with_context(|| format!("removing {}", path.display()))?;
    }
    Ok(())
}

/// One section of results.md for a figure: image (if drawn) and caption.
fn figure_section(md: &mut String, title: &str, file: Option<&str>, caption: &str) {
    let _ = writeln!(md, "### {title}\n");
    if let Some(f) = file {
        let _ = writeln!(md, "![{title}]({FIGURE_DIR}/{f})\n");
    } else {
        let _ = writeln!(md, "*No figure: no case of it has data.*\n");
    }
    let _ = writeln!(md, "{caption}\n");
}

/// Fraction of a profile's peak εs that still counts as solids when sizing the plot.
const VISIBLE_FRACTION: f64 = 0.01;

/// The height of the highest cell centre whose εs is at least [`VISIBLE_FRACTION`] of the
/// profile's peak; `None` without solids.
fn solids_top(p: &Profile) -> Option<f64> {
    let peak = p.eps_s.iter().copied().fold(0.0, f64::max);
    (peak > 0.0)
        .then(|| {
            p.y.iter()
                .zip(&p.eps_s)
                .filter(|(_, &e)| e >= VISIBLE_FRACTION * peak)
                .map(|(&y, _)| y)
                .fold(f64::NEG_INFINITY, f64::max)
        })
        .filter(|y| y.is_finite())
}

fn draw_profile_figure(
    md: &mut String,
    fig: &ProfileFigure,
    cases: &Cases,
    out: &Path,
) -> Result<()> {
    let cov = coverage(
        cases,
        fig.rows.iter().flat_map(|r| r.curves.iter().map(|c| c.0)),
        |d| d.profile.as_ref().map(|_| ()).map_err(Clone::clone),
    );
    let path = out.join(fig.file);
    let title = format!(
        "Fig. {} — station profiles at t = {PROFILE_TIME} s",
        fig.number
    );
    let caption = format!(
        "Paper Fig. {}: {}. Profiles at the station x = 11 m (5.5 m downstream of the release) at \
         t = {PROFILE_TIME} s against the distance from the floor (profile_x11_t1.25.csv of each \
         run).{}",
        fig.number,
        fig.what,
        cov.caption()
    );
    if cov.is_empty() {
        remove_stale(&path)?;
        figure_section(md, &title, None, &caption);
        return Ok(());
    }
    let mut panels = Vec::new();
    for (r, row) in fig.rows.iter().enumerate() {
        // the vertical range: 1.3 × the highest solids of the row (εs ≥ 1 % of the profile's
        // peak), the whole profile if none
        let profiles: Vec<(String, Profile, Option<Fidelity>)> = row
            .curves
            .iter()
            .filter_map(|(case, label)| {
                let d = cases.get(case);
                let p = d.profile.as_ref().ok()?.clone();
                Some((label.to_string(), p, d.fidelity()))
            })
            .collect();
        let top = profiles
            .iter()
            .filter_map(|(_, p, _)| solids_top(p))
            .fold(0.0_f64, f64::max);
        let y_max = (top > 0.0).then_some(1.3 * top);
        for (v, var) in fig.vars.iter().enumerate() {
            let letter = (b'a' + (r * fig.vars.len() + v) as u8) as char;
            panels.push(Panel {
                title: format!("({letter}) {}", row.title),
                x_label: var.axis().into(),
                y_label: "distance from the floor [m]".into(),
                series: profiles
                    .iter()
                    .enumerate()
                    .map(|(k, (label, p, f))| Series {
                        label: legend(label, *f),
                        points: var
                            .values(p)
                            .iter()
                            .copied()
                            .zip(p.y.iter().copied())
                            .filter(|&(_, y)| y_max.is_none_or(|m| y <= m))
                            .collect(),
                        colour: k,
                        mark: Mark::LineAndDots,
                    })
                    .collect(),
                vertical: Vec::new(),
                horizontal: Vec::new(),
                y_from_zero: true,
            });
        }
    }
    plots::draw(&path, &panels, fig.vars.len())?;
    figure_section(md, &title, Some(fig.file), &caption);
    Ok(())
}

fn draw_probe_figure(md: &mut String, cases: &Cases, out: &Path) -> Result<()> {
    let file = "fig9.svg";
    let cov = coverage(cases, PROBE_CURVES.iter().map(|c| c.0), |d| {
        d.probe.as_ref().map(|_| ()).map_err(Clone::clone)
    });
    let title = "Fig. 9 — h_w^u at the floor probe against time";
    let caption = format!(
        "Paper Fig. 9: h_w^u of the floor face at x = 11 m against time, d = 0.5 mm, for the \
         state-dependent floor conditions (JJ = Johnson–Jackson); dashed: the paper's limit of \
         air-cushion formation, h_w^u = {CUSHION_LIMIT_H_U} m⁻¹ (wall_probe_south_x11.csv of each \
         run).{}",
        cov.caption()
    );
    let path = out.join(file);
    if cov.is_empty() {
        remove_stale(&path)?;
        figure_section(md, title, None, &caption);
        return Ok(());
    }
    let series = PROBE_CURVES
        .iter()
        .enumerate()
        .filter_map(|(k, (case, label))| {
            let d = cases.get(case);
            Some(Series {
                label: legend(label, d.fidelity()),
                points: d.probe.as_ref().ok()?.clone(),
                colour: k,
                mark: Mark::Line,
            })
        })
        .collect();
    let panel = Panel {
        title: "h_w^u at x = 11 m, d = 0.5 mm".into(),
        x_label: "t [s]".into(),
        y_label: "h_w^u [1/m]".into(),
        series,
        vertical: Vec::new(),
        horizontal: vec![(CUSHION_LIMIT_H_U, "air-cushion limit 70 1/m".into())],
        y_from_zero: true,
    };
    plots::draw(&path, &[panel], 1)?;
    figure_section(md, title, Some(file), &caption);
    Ok(())
}

/// The flume's gates of cases/flume/gates.csv: (gate number, distance from the inlet [m],
/// described speed [m/s]).
fn flume_gates(gates_csv: &Path) -> Vec<(usize, f64, Option<f64>)> {
    let Ok(text) = std::fs::read_to_string(gates_csv) else {
        return Vec::new();
    };
    text.lines()
        .filter(|l| !l.trim_start().starts_with('#'))
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split(',').map(str::trim).collect();
            let gate = f.first()?.trim_start_matches('L').parse().ok()?;
            let distance = f.get(1)?.parse().ok()?;
            Some((gate, distance, f.get(2).and_then(|s| s.parse().ok())))
        })
        .collect()
}

fn draw_flume_figure(
    md: &mut String,
    cases: &Cases,
    gates: &[(usize, f64, Option<f64>)],
    out: &Path,
) -> Result<()> {
    let file = "fig12.svg";
    let cov = coverage(cases, FLUME.iter().map(|c| c.0), |d| {
        d.gates.as_ref().map_err(Clone::clone).and_then(|g| {
            if g.is_empty() {
                Err(d.no_gate_reached())
            } else {
                Ok(())
            }
        })
    });
    let front_cov = coverage(cases, FLUME.iter().map(|c| c.0), |d| {
        d.front.as_ref().map(|_| ()).map_err(Clone::clone)
    });
    let title = "Fig. 12 — flume front speed at the gates";
    let caption = format!(
        "Paper Fig. 12: front speed as the front crosses each laser gate, against the gate's \
         distance from the channel inlet (gates.csv of each run); black squares: the speeds the \
         paper *describes* for the experiment (cases/flume/gates.csv: no measured values are in \
         the paper's text); dotted: the gates L1–L7. Panel (b), not in the paper: the front \
         position against time (front.csv: where the floor row's εs falls through 0.01, \
         interpolated between cell centres), from which the gate speeds are taken by central \
         differences.{} Panel (b):{}",
        cov.caption(),
        front_cov.caption()
    );
    let path = out.join(file);
    if cov.is_empty() && front_cov.is_empty() {
        remove_stale(&path)?;
        figure_section(md, title, None, &caption);
        return Ok(());
    }
    let distance = |g: usize| gates.iter().find(|r| r.0 == g).map(|r| r.1);
    let mut speed_series: Vec<Series> = FLUME
        .iter()
        .enumerate()
        .filter_map(|(k, (case, label, _))| {
            let d = cases.get(case);
            let g = d.gates.as_ref().ok()?;
            Some(Series {
                label: legend(label, d.fidelity()),
                points: g
                    .iter()
                    .filter_map(|g| Some((distance(g.gate)?, g.speed)))
                    .collect(),
                colour: k,
                mark: Mark::LineAndDots,
            })
        })
        .filter(|s| !s.points.is_empty())
        .collect();
    speed_series.push(Series {
        label: "described (paper text)".into(),
        points: gates.iter().filter_map(|g| Some((g.1, g.2?))).collect(),
        colour: plots::BLACK_INDEX,
        mark: Mark::Squares,
    });
    let vertical: Vec<(f64, String)> = gates.iter().map(|g| (g.1, format!("L{}", g.0))).collect();
    let front_series = FLUME
        .iter()
        .enumerate()
        .filter_map(|(k, (case, label, _))| {
            let d = cases.get(case);
            let origin = d.gate_origin.unwrap_or(0.0);
            Some(Series {
                label: legend(label, d.fidelity()),
                points: d
                    .front
                    .as_ref()
                    .ok()?
                    .iter()
                    // a front at the domain's start (x = 0) means no solids on the floor yet
                    .filter(|&&(_, x)| x > 0.0)
                    .map(|&(t, x)| (t, x - origin))
                    .collect(),
                colour: k,
                mark: Mark::Line,
            })
        })
        .collect();
    let panels = [
        Panel {
            title: "(a) front speed at the gates".into(),
            x_label: "distance from the channel inlet [m]".into(),
            y_label: "front speed [m/s]".into(),
            series: speed_series,
            vertical: vertical.clone(),
            horizontal: Vec::new(),
            y_from_zero: true,
        },
        Panel {
            title: "(b) front position".into(),
            x_label: "t [s]".into(),
            y_label: "front, distance from the channel inlet [m]".into(),
            series: front_series,
            vertical: Vec::new(),
            horizontal: vertical,
            y_from_zero: false,
        },
    ];
    plots::draw(&path, &panels, 2)?;
    figure_section(md, title, Some(file), &caption);
    Ok(())
}

// ---------------------------------------------------------------------------------------
// Tables
// ---------------------------------------------------------------------------------------

/// A markdown table cell: `|` escaped.
fn cell(s: &str) -> String {
    s.replace('|', "\\|")
}

fn runs_table(md: &mut String, names: &[String], cases: &Cases) {
    md.push_str(
        "| case | fidelity | status | simulated [s] | cells | steps (rejected) | wall [s] |\n\
         |---|---|---|---|---|---|---|\n",
    );
    for name in names {
        let d = cases.get(name);
        match &d.run {
            Ok(r) => {
                let s = &r.summary;
                let status = match &s.status {
                    RunStatus::Diverged { .. } => "diverged".to_string(),
                    other => format!("{other:?}"),
                };
                let _ = writeln!(
                    md,
                    "| `{name}` | {} | {status} | {:.2} | {} × {} | {} ({}) | {:.1} |",
                    r.fidelity,
                    s.simulated_time,
                    s.cells.0,
                    s.cells.1,
                    s.steps,
                    s.rejected_steps,
                    s.wall_time
                );
            }
            Err(why) => {
                let _ = writeln!(md, "| `{name}` | — | {} | | | | |", cell(why));
            }
        }
    }
    md.push('\n');
}

fn paper_table(md: &mut String, cases: &Cases, described: &[(usize, f64)]) {
    md.push_str(
        "| paper Fig. | quantity | case | paper (MFIX) | runout | fidelity |\n\
         |---|---|---|---|---|---|\n",
    );
    for row in PAPER_NUMBERS {
        let d = cases.get(row.case);
        let value = match reading(row.quantity, &d, cases, described) {
            Ok(v) => v,
            Err(why) => format!("— ({why})"),
        };
        let fidelity = d.fidelity().map_or("—".into(), |f| f.to_string());
        let _ = writeln!(
            md,
            "| {} | {} | `{}` | {} | {} | {} |",
            row.figure,
            cell(&row.quantity.label()),
            row.case,
            cell(row.paper),
            cell(&value),
            fidelity
        );
    }
    md.push('\n');
}

fn flume_table(
    md: &mut String,
    cases: &Cases,
    gates: &[(usize, f64, Option<f64>)],
    described: &[(usize, f64)],
) {
    let numbers: Vec<usize> = gates.iter().map(|g| g.0).collect();
    let _ = writeln!(
        md,
        "| case | fidelity | {} | MSE vs described [m²/s²] | paper's MFIX MSE vs measured [m²/s²] |",
        numbers.iter().map(|g| format!("L{g}")).collect::<Vec<_>>().join(" | ")
    );
    let _ = writeln!(md, "|---|---|{}---|---|", "---|".repeat(numbers.len()));
    let _ = writeln!(
        md,
        "| described (cases/flume/gates.csv) | — | {} | — | — |",
        gates
            .iter()
            .map(|g| g.2.map_or(String::new(), |s| format!("{s:.1}")))
            .collect::<Vec<_>>()
            .join(" | ")
    );
    for (case, _, paper_mse) in FLUME.iter().chain(FLUME_SIDEWALLS) {
        let d = cases.get(case);
        let (fidelity, speeds, mse) = match d.gate_pairs() {
            Ok(pairs) => {
                let speeds = numbers
                    .iter()
                    .map(|g| {
                        pairs
                            .iter()
                            .find(|p| p.0 == *g)
                            .map_or("—".into(), |p| format!("{:.2}", p.1))
                    })
                    .collect::<Vec<_>>()
                    .join(" | ");
                let mse = mse_vs_described(&pairs, described).map_or_else(
                    || format!("— ({})", d.no_gate_reached()),
                    |(e, k)| format!("{e:.2} ({k} gates)"),
                );
                (
                    d.fidelity().map_or("—".into(), |f| f.to_string()),
                    speeds,
                    mse,
                )
            }
            Err(why) => (
                "—".into(),
                vec!["—"; numbers.len()].join(" | "),
                format!("— ({why})"),
            ),
        };
        let _ = writeln!(
            md,
            "| `{case}` | {fidelity} | {speeds} | {} | {} |",
            cell(&mse),
            cell(paper_mse)
        );
    }
    md.push('\n');
}

fn mfix_table(md: &mut String, cases: &Cases) {
    let d = cases.get(MFIX_CASE);
    let fidelity = d.fidelity().map_or("—".into(), |f| f.to_string());
    md.push_str(
        "| t [s] | MFIX front x [m] | runout front x [m] | MFIX mean u_s [m/s] | runout mean u_s [m/s] | fidelity |\n\
         |---|---|---|---|---|---|\n",
    );
    for &(t, front, mean) in MFIX_SLIDE {
        let (ours_front, ours_mean, f) = match d.bulk_at(t) {
            Ok((x, u)) => (format!("{x:.2}"), format!("{u:.2}"), fidelity.clone()),
            Err(why) => (format!("— ({why})"), "—".into(), "—".into()),
        };
        let _ = writeln!(
            md,
            "| {t} | {front:.2} | {} | {mean:.2} | {ours_mean} | {f} |",
            cell(&ours_front)
        );
    }
    md.push('\n');
}

// ---------------------------------------------------------------------------------------
// The report
// ---------------------------------------------------------------------------------------

/// Writes results.md and its figures; returns the markdown.
pub fn write_report(paths: &ReportPaths, requested: Option<Fidelity>) -> Result<String> {
    let matrix = crate::sweep::paper_matrix(&paths.cases)?;
    let names: Vec<String> = matrix.runs.iter().map(|r| r.case.name.clone()).collect();
    let cases = Cases::load(&paths.runs, names.iter().map(String::as_str), requested);
    let gates_csv = paths.cases.join("flume").join("gates.csv");
    let gates = flume_gates(&gates_csv);
    let described: Vec<(usize, f64)> = gates.iter().filter_map(|g| Some((g.0, g.2?))).collect();
    let out = paths.docs.join(FIGURE_DIR);
    std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;

    let used: Vec<Fidelity> = names
        .iter()
        .filter_map(|n| cases.get(n).fidelity())
        .collect();
    let count = |f: Fidelity| used.iter().filter(|&&u| u == f).count();
    let mut md = String::new();
    let _ = writeln!(
        md,
        "# Results: runout beside the paper\n\n\
         Generated by `cargo xtask report{}` from the run folders `runs/<case>/<fidelity>/` \
         (written by `cargo xtask sweep`); do not edit by hand. Fidelity: {}. Of the {} cases of \
         the matrix, {} have a run here: {} at paper, {} at wall, {} at coarse, {} at smoke \
         fidelity.\n",
        requested.map_or(String::new(), |f| format!(" --fidelity {f}")),
        requested.map_or(
            "the best finished run of each case (paper, then wall, then coarse, then smoke), named \
             in every \
             caption and table"
                .to_string(),
            |f| format!("{f} only")
        ),
        names.len(),
        used.len(),
        count(Fidelity::Paper),
        count(Fidelity::Wall),
        count(Fidelity::Coarse),
        count(Fidelity::Smoke),
    );
    if count(Fidelity::Smoke) > 0 {
        md.push_str(
            "> **Smoke fidelity is a CI-level check, not a reproduction.** Smoke runs use grids \
             5–10× coarser than the paper's and stop at t = 0.4 s (0.1 s for the MFIX slide, \
             0.4 s after the tilt for family S), before the paper's profile time of 1.25 s and \
             before the flume's front reaches a \
             gate: they show that the case matrix runs and that the report reads every \
             monitor, and their numbers are not comparable with the paper's. Numbers worth \
             comparing need `cargo xtask sweep --fidelity coarse` or `--fidelity paper`.\n\n",
        );
    }
    md.push_str(
        "The paper's numbers are MFIX's (shared/docs/cases.md \"What the paper reports\"); \
         runout's are computed from the monitor files as defined in xtask/src/metrics.rs (air \
         cushion: floor εs below 0.8 × the profile's peak; flow thickness: top of the highest \
         cell with εs ≥ 0.01; max u_s over cells with εs ≥ 0.01).\n\n",
    );
    md.push_str(
        "Family S's release, impact and clock are assumptions chosen by one criterion stated \
         before this comparison (docs/impact.md §4; `cargo xtask report release`): the block \
         of cases.md filled by covered fraction, gravity tilted at the free fall of its bottom \
         (0.2856 s), and the paper's \"t = 1.25 s\" counted from that tilt, so family S's \
         profiles and probe readings are at t = 1.5356 s of the run.\n\n",
    );

    findings::section(&mut md, &cases, &described);

    md.push_str("## Figures\n\n");
    md.push_str(
        "### Fig. 1 — analytical wall profiles\n\n\
         Paper Fig. 1 (closed forms of Eqs. 12–13, family A) is written by `cargo xtask report \
         analytic`: ![Fig. 1](analytic/fig1.svg)\n\n",
    );
    if !paths.docs.join("analytic").join("fig1.svg").exists() {
        md.push_str("*Missing: docs/analytic/fig1.svg; run `cargo xtask report analytic`.*\n\n");
    }
    // in the paper's order: 4, 5, 6, 7, 8, 9, 10, 12, 13, 14
    for fig in &PROFILE_FIGURES[..2] {
        draw_profile_figure(&mut md, fig, &cases, &out)?;
    }
    fields::draw_figure(&mut md, &FIELD_FIGURES[0], &cases, &out)?;
    for fig in &PROFILE_FIGURES[2..4] {
        draw_profile_figure(&mut md, fig, &cases, &out)?;
    }
    draw_probe_figure(&mut md, &cases, &out)?;
    fields::draw_figure(&mut md, &FIELD_FIGURES[1], &cases, &out)?;
    draw_flume_figure(&mut md, &cases, &gates, &out)?;
    for fig in &PROFILE_FIGURES[4..] {
        draw_profile_figure(&mut md, fig, &cases, &out)?;
    }

    md.push_str(
        "## Every number the paper reports, beside runout's\n\n\
         Profile quantities at the station x = 11 m, t = 1.25 s; \"—\" says why runout has no \
         value.\n\n",
    );
    paper_table(&mut md, &cases, &described);

    md.push_str(
        "## Flume: front speed at the gates (paper §4, Fig. 12)\n\n\
         Speeds [m/s] from each run's gates.csv. The MSE is runout's against the speeds the \
         paper *describes* (cases/flume/gates.csv: ~4.0 m/s at L2–L6 and the last peak of \
         5.4 m/s at L7; L1 lies in the initial rise and has none), over the gates both have; \
         the paper's MSEs are MFIX's against the *measured* speeds, which are not in its text, \
         so the two columns are not the same error. The `FSW-` rows are the same cases with \
         the channel's side walls (0.30 m apart, the floor's solids condition, gas no-slip; \
         docs/model.md §8), which the paper's 2-D runs and the `F-` rows leave out.\n\n",
    );
    flume_table(&mut md, &cases, &gates, &described);

    md.push_str(
        "## Family M: the slide run in MFIX (cross-check, not a paper number)\n\n\
         Front x and εs-weighted mean u_s from runout's bulk.csv against MFIX 21.3.2 on the same \
         case (shared/docs/cases.md family M).\n\n",
    );
    mfix_table(&mut md, &cases);
    floors_section(&mut md, &paths.docs);

    sensitivity::section(&mut md, &matrix, &paths.cases, &cases, &out)?;

    md.push_str("## Runs used\n\n");
    runs_table(&mut md, &names, &cases);

    runout_output::write_atomic(&paths.docs.join(RESULTS_FILE), md.as_bytes())
        .context("writing results.md")?;
    Ok(md)
}

/// The floor-variant comparison of family M (issue 9, item 4) as `cargo xtask verify
/// mfix-slope` wrote it into docs/mfix-slope.md, with a sentence ranking the floors by slip;
/// a note if that file or section does not exist yet.
fn floors_section(md: &mut String, docs: &Path) {
    const HEADING: &str = "## The four floors at t = 0.3 s";
    md.push_str("### Family M: the four floors at t = 0.3 s (issue 9)\n\n");
    let text = std::fs::read_to_string(docs.join("mfix-slope.md")).unwrap_or_default();
    let Some(start) = text.find(HEADING) else {
        md.push_str(
            "**Missing**: docs/mfix-slope.md has no floor comparison yet; run `cargo xtask \
             verify mfix-slope`.\n\n",
        );
        return;
    };
    let body = &text[start + HEADING.len()..];
    let body = body.split_once("\n(").map_or(body, |(b, _)| b);
    let end = body
        .find("\n## ")
        .or_else(|| body.find("\n**Result"))
        .unwrap_or(body.len());
    let section = body[..end].trim_start_matches(|c: char| c != '\n').trim();
    md.push_str(section);
    md.push_str(
        "\n\nFrom docs/mfix-slope.md (written by `cargo xtask verify mfix-slope`, MFIX's grid).",
    );
    // rank by the wall-row mean solids velocity (table column 3) and give θ (column 5)
    let mut rows: Vec<(String, f64, f64)> = section
        .lines()
        .filter(|l| l.starts_with("| M-"))
        .filter_map(|l| {
            let c: Vec<&str> = l.split('|').map(str::trim).collect();
            Some((
                c.get(1)?.to_string(),
                c.get(3)?.parse().ok()?,
                c.get(5)?.parse().ok()?,
            ))
        })
        .collect();
    if rows.len() > 1 {
        rows.sort_by(|a, b| a.1.total_cmp(&b.1));
        let order: Vec<String> = rows
            .iter()
            .map(|(name, u, theta)| format!("{name} ({u:.2} m/s, θ {theta:.1e} m²/s²)"))
            .collect();
        md.push_str(&format!(
            " Ranked by wall slip (wall-row mean u_s), least to most: {}.",
            order.join(" < ")
        ));
    }
    md.push_str("\n\n");
}

/// `cargo xtask report [results]`: the report of the runs under `root`.
pub fn report(root: &Path, requested: Option<Fidelity>) -> Result<()> {
    let paths = ReportPaths {
        runs: root.join("runs"),
        cases: root.join("cases"),
        docs: root.join("docs"),
    };
    let md = write_report(&paths, requested)?;
    let missing = md.matches("**Missing**").count();
    println!(
        "wrote docs/{RESULTS_FILE} and docs/{FIGURE_DIR}/*.svg ({} figure(s) drawn, {missing} \
         missing-data note(s) in captions)",
        md.matches(&format!("]({FIGURE_DIR}/")).count()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::data::fixture::*;
    use super::*;

    fn paths(tmp: &TempDir) -> ReportPaths {
        ReportPaths {
            runs: tmp.0.join("runs"),
            cases: Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases"),
            docs: tmp.0.join("docs"),
        }
    }

    #[test]
    fn the_report_draws_what_exists_and_names_what_is_missing() {
        let tmp = TempDir::new("end-to-end");
        let p = paths(&tmp);
        write_run(
            &p.runs,
            "S-JJ-phi_phi=1",
            "coarse",
            1.25,
            &[("profile_x11_t1.25.csv", CUSHION_PROFILE)],
        );
        write_run(&p.runs, "S-JJ-phi_phi=1", "smoke", 0.4, &[]);
        write_run(&p.runs, "S-JJ-phi_phi=0.1", "smoke", 0.4, &[]);
        write_run(
            &p.runs,
            "F-JJ_phi=0.1",
            "coarse",
            2.5,
            &[
                (
                    "gates.csv",
                    "gate,x,t_cross,speed\n2,2.6,0.7,4.5\n3,3.05,0.8,3.5\n",
                ),
                ("front.csv", "t,front_x\n0.1,0\n0.7,2.6\n0.8,3.05\n"),
            ],
        );
        // a figure left by an earlier report whose data are gone now
        let figures = p.docs.join(FIGURE_DIR);
        std::fs::create_dir_all(&figures).unwrap();
        std::fs::write(figures.join("fig5.svg"), "stale").unwrap();

        let md = write_report(&p, None).unwrap();
        assert_eq!(
            std::fs::read_to_string(p.docs.join(RESULTS_FILE)).unwrap(),
            md
        );
        let fig4 = std::fs::read_to_string(figures.join("fig4.svg")).unwrap();
        assert!(
            fig4.contains("<polyline"),
            "Fig. 4 has the coarse run's lines"
        );
        assert!(md.contains("![Fig. 4"));
        assert!(md.contains("Fidelity: **coarse** (`S-JJ-phi_phi=1`)."));
        assert!(md.contains(
            "**Missing** (the smoke run ends at t = 0.40 s, before t = 1.25 s): `S-JJ-phi_phi=0.1`."
        ));
        assert!(md.contains("**Missing** (not run): `S-JJ-phi_phi=0.01`"));
        assert!(
            !figures.join("fig5.svg").exists(),
            "the stale Fig. 5 is removed"
        );
        assert!(md.contains("### Fig. 5 — station profiles at t = 1.25 s\n\n*No figure"));
        assert!(figures.join("fig12.svg").exists());
        assert!(
            md.contains("CI-level check, not a reproduction"),
            "a smoke run is used"
        );
        // the paper's numbers beside runout's, with the fidelity
        assert!(
            md.contains("| 4a | εs of the floor cell | `S-JJ-phi_phi=1` | 0.03 | 0.050 | coarse |")
        );
        // the flume's MSE against the described speeds beside the paper's
        assert!(md.contains(
            "| `F-JJ_phi=0.1` | coarse | — | 4.50 | 3.50 | — | — | — | — | 0.25 (2 gates) | 0.36 |"
        ));

        // only smoke: the coarse runs are not used, and Fig. 4 goes
        let md = write_report(&p, Some(Fidelity::Smoke)).unwrap();
        assert!(!figures.join("fig4.svg").exists());
        assert!(md.contains("Generated by `cargo xtask report --fidelity smoke`"));
        assert!(md.contains("**Missing** (not run at smoke fidelity): `S-JJ-phi_phi=0.01`"));
        assert!(md.contains("| `F-JJ_phi=0.1` | — | not run at smoke fidelity |"));
    }
}
