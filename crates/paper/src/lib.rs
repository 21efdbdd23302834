//! The seed paper's reproduction, built on runout's public libraries (study, post, run, case,
//! output): the paper's case matrix and its sweep ([`matrix`]), and the report of its runs
//! beside the paper (`cargo xtask report [results] [--fidelity F]`, issue 8) with its
//! findings, error bars, explanations, figures and the metrics ledger ([`ledger`]); beside it
//! the release study ([`release`]), the slide onto a flat run-out ([`foot`]) and the
//! discretisation error against run time over a ladder of grids ([`error_time`], `cargo
//! xtask error-time`), and the stiff and extreme cases of the stability suite ([`stability`],
//! `cargo xtask stability`). A research group builds its own study on runout the same way.
//!
//! The report ([`report`]) writes `docs/reports/results.md` and, in `docs/reports/results/`,
//! SVG figures of the quantities and axes of paper Figs. 4, 5, 7, 8, 9, 12, 13 and 14 (Fig. 1
//! is `cargo xtask report analytic`, linked), a table of every number the paper reports
//! beside runout's, the flume's gate speeds with their mean square error against the
//! described speeds, the family-M cross-check against MFIX, and the elasticities of the
//! one-factor families of family S (issue 23, [`runout_study::sensitivity`]) as a table and a
//! heat map.
//!
//! Each case is read from `runs/<case>/<fidelity>/` (written by `cargo xtask sweep` or
//! `runout run`): by default the best fidelity with a finished run (paper, then coarse, then
//! smoke), with `--fidelity` only that one. What a case lacks (no run, a run that ended
//! before the paper's time, a monitor file the run does not have) is said in the figure's
//! caption and in the tables; it is never an error.

#![deny(missing_docs)]

mod coverage;
mod curves;
pub mod date;
mod error_bars;
pub mod error_time;
mod explain;
mod fields;
mod figure_sets;
mod findings;
pub mod foot;
pub mod ledger;
pub mod matrix;
pub mod paper;
/// The SVG panels, drawn by the study engine's plots.
use runout_study::plots;
pub mod reading;
mod record;
pub mod records;
pub mod release;
mod row;
mod sensitivity;
mod side_by_side;
pub mod solver_stamp;
pub mod stability;
mod tables;
mod trends;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use runout_case::Fidelity;
use runout_post::case_data::Cases;
use runout_post::gates::{read_described_gates, speeds_of, DescribedGate};

use error_bars::Ladders;
use explain::Releases;
use figure_sets::{FIELD_FIGURES, PROFILE_FIGURES};
use ledger::Ledger;
use record::Source;
use records::{Records, Store};
use tables::cell;

/// Output file, relative to the reports directory (docs/reports/).
const RESULTS_FILE: &str = "results.md";
/// Figure directory, relative to the reports directory.
const FIGURE_DIR: &str = "results";

/// Where the report reads and writes.
pub struct ReportPaths {
    /// run folders: `<runs>/<case>/<fidelity>/`
    pub runs: PathBuf,
    /// case directory (the matrix and `flume/gates.csv`)
    pub cases: PathBuf,
    /// reports directory (docs/reports/): `results.md` and `results/*.svg` go here; the
    /// ledger, the error ladder, the release study and mfix-slope.md are read from it
    pub reports: PathBuf,
}

// ---------------------------------------------------------------------------------------
// The report
// ---------------------------------------------------------------------------------------

/// Writes results.md and its figures; returns the markdown.
pub fn write_report(paths: &ReportPaths, requested: Option<Fidelity>) -> Result<String> {
    let matrix = crate::matrix::paper_matrix(&paths.cases)?;
    let names: Vec<String> = matrix.runs.iter().map(|r| r.case.name.clone()).collect();
    let store = Store::load(&paths.runs, &names);
    let mut ledger = Ledger::read(&paths.reports)?;
    for (_, cases) in &store.at {
        ledger.put_store(&names, cases);
    }
    ledger.write()?;
    let records = Records::choose(&names, &store, &ledger, requested);
    let mut cases = Cases::load(&paths.runs, names.iter().map(String::as_str), requested);
    for case in records.with_source(Source::Ledger) {
        if let Ok(r) = records.get(case) {
            let why = format!(
                "no run folder here: its numbers are the {} ledger row's",
                r.fidelity
            );
            cases.explain_missing(case, &why);
        }
    }
    let gates = read_described_gates(&paths.cases.join("flume").join("gates.csv"));
    let described = speeds_of(&gates);
    let out = paths.reports.join(FIGURE_DIR);
    std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;

    let mut md = String::new();
    preamble(&mut md, &names, &records, requested);
    let ladders = Ladders::read(&paths.reports)?;
    side_by_side::section(&mut md, &names, &store, &ledger, &described, &ladders);
    let releases = Releases::read(&paths.reports)?;
    findings::section(&mut md, &records, &described, &ladders, &releases);
    figures(&mut md, &cases, &gates, &paths.reports, &out)?;
    tables::paper_section(&mut md, &records, &described);
    tables::flume_section(&mut md, &records, &gates, &described);
    tables::mfix_section(&mut md, &records);
    tables::floors_section(&mut md, &paths.reports);
    sensitivity::section(&mut md, &matrix, &paths.cases, &records, &out)?;
    md.push_str("## Runs used\n\n");
    tables::runs_table(&mut md, &names, &records);

    runout_output::write_atomic(&paths.reports.join(RESULTS_FILE), md.as_bytes())
        .context("writing results.md")?;
    Ok(md)
}

/// The title, where the numbers come from (fidelities, run folders or ledger, metric
/// definitions, family S's clock), and the smoke-fidelity warning where smoke runs are used.
fn preamble(md: &mut String, names: &[String], records: &Records, requested: Option<Fidelity>) {
    let used = records.fidelities();
    let count = |f: Fidelity| used.iter().filter(|&&u| u == f).count();
    let from_ledger = records.with_source(Source::Ledger).len();
    let _ = writeln!(
        md,
        "# Results: runout beside the paper\n\n\
         Generated by `cargo xtask report{}` from the run folders `runs/<case>/<fidelity>/` \
         (written by `cargo xtask sweep`) and, for a case without one, its row of the metrics \
         ledger docs/reports/results/ledger/<fidelity>.csv (rows of earlier runs, kept in git; \
         `cargo xtask ledger add RUN_DIR` records a run made elsewhere); do not edit by hand. \
         Fidelity: {}. Of the {} cases of the matrix, {} have a run: {} at paper, {} at wall, \
         {} at coarse, {} at smoke fidelity; {} of them from the ledger (named in the runs \
         table at the end). The figures are drawn from run folders only: a case whose numbers \
         come from the ledger is named in each caption as having no run folder here.\n",
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
        from_ledger,
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
         runout's are computed from the monitor files as defined in crates/post/src/metrics.rs (air \
         cushion: floor εs below 0.8 × the profile's peak; flow thickness: top of the highest \
         cell with εs ≥ 0.01; max u_s over cells with εs ≥ 0.01).\n\n",
    );
    md.push_str(
        "Family S's release, impact and clock are assumptions chosen by one criterion stated \
         before this comparison (docs/studies/impact.md §4; `cargo xtask report release`): the block \
         of cases.md filled by covered fraction, gravity tilted at the free fall of its bottom \
         (0.2856 s), and the paper's \"t = 1.25 s\" counted from that tilt, so family S's \
         profiles and probe readings are at t = 1.5356 s of the run.\n\n",
    );
}

/// The figures in the paper's order: 1 (linked), 4, 5, 6, 7, 8, 9, 10, 12, 13, 14.
fn figures(
    md: &mut String,
    cases: &Cases,
    gates: &[DescribedGate],
    reports: &Path,
    out: &Path,
) -> Result<()> {
    md.push_str("## Figures\n\n");
    md.push_str(
        "### Fig. 1 — analytical wall profiles\n\n\
         Paper Fig. 1 (closed forms of Eqs. 12–13, family A) is written by `cargo xtask report \
         analytic`: ![Fig. 1](analytic/fig1.svg)\n\n",
    );
    if !reports.join("analytic").join("fig1.svg").exists() {
        md.push_str(
            "*Missing: docs/reports/analytic/fig1.svg; run `cargo xtask report analytic`.*\n\n",
        );
    }
    // in the paper's order: 4, 5, 6, 7, 8, 9, 10, 12, 13, 14
    for fig in &PROFILE_FIGURES[..2] {
        curves::draw_profile_figure(md, fig, cases, out)?;
    }
    fields::draw_figure(md, &FIELD_FIGURES[0], cases, out)?;
    for fig in &PROFILE_FIGURES[2..4] {
        curves::draw_profile_figure(md, fig, cases, out)?;
    }
    curves::draw_probe_figure(md, cases, out)?;
    fields::draw_figure(md, &FIELD_FIGURES[1], cases, out)?;
    curves::draw_flume_figure(md, cases, gates, out)?;
    for fig in &PROFILE_FIGURES[4..] {
        curves::draw_profile_figure(md, fig, cases, out)?;
    }
    Ok(())
}

/// `cargo xtask report [results]`: the report of the runs under `root`.
pub fn report(root: &Path, requested: Option<Fidelity>) -> Result<()> {
    let paths = ReportPaths {
        runs: root.join("runs"),
        cases: root.join("cases"),
        reports: root.join("docs/reports"),
    };
    let md = write_report(&paths, requested)?;
    let missing = md.matches("**Missing**").count();
    println!(
        "wrote docs/reports/{RESULTS_FILE} and docs/reports/{FIGURE_DIR}/*.svg ({} figure(s) drawn, {missing} \
         missing-data note(s) in captions)",
        md.matches(&format!("]({FIGURE_DIR}/")).count()
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_post::fixture::*;

    fn paths(tmp: &TempDir) -> ReportPaths {
        ReportPaths {
            runs: tmp.0.join("runs"),
            cases: Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases"),
            reports: tmp.0.join("docs/reports"),
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
        let figures = p.reports.join(FIGURE_DIR);
        std::fs::create_dir_all(&figures).unwrap();
        std::fs::write(figures.join("fig5.svg"), "stale").unwrap();

        let md = write_report(&p, None).unwrap();
        assert_eq!(
            std::fs::read_to_string(p.reports.join(RESULTS_FILE)).unwrap(),
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
        assert!(md.contains("| `F-JJ_phi=0.1` | — | — | not run at smoke fidelity |"));
    }

    #[test]
    fn the_ledger_keeps_the_numbers_of_runs_whose_folders_are_gone() {
        let tmp = TempDir::new("ledger-report");
        let p = paths(&tmp);
        let profile = "profile_x11_t1.25.csv";
        write_run(
            &p.runs,
            "S-JJ-phi_phi=1",
            "coarse",
            1.25,
            &[(profile, CUSHION_PROFILE)],
        );
        write_run(&p.runs, "S-JJ-phi_phi=1", "smoke", 0.4, &[]);
        let md = write_report(&p, None).unwrap();
        let ledger = p.reports.join(ledger::LEDGER_DIR);
        let coarse = std::fs::read_to_string(ledger.join("coarse.csv")).unwrap();
        assert_eq!(coarse.lines().count(), 2, "one row: {coarse}");
        assert!(
            !ledger.join("smoke.csv").exists(),
            "smoke runs are not recorded"
        );
        // the side-by-side table: coarse is incomplete, wall quotes its last count
        assert!(md.contains("## The findings at each fidelity"));
        assert!(md.contains("| coarse | — (partial: "), "{md}");
        assert!(md.contains("| wall | — (no finding has its runs) | 0 of 42 (0) | 0 of 30 |"));
        assert!(md.contains("**40 of 64**"));
        assert!(md.contains("`cargo xtask sweep --fidelity paper --only S-`"));

        // the folders are lost (a new machine): the numbers come from the ledger, the
        // figures say why they lack the case, and the smoke report leaves the ledger alone
        std::fs::remove_dir_all(&p.runs).unwrap();
        let md = write_report(&p, Some(Fidelity::Smoke)).unwrap();
        assert_eq!(
            std::fs::read_to_string(ledger.join("coarse.csv")).unwrap(),
            coarse
        );
        assert!(md.contains("| coarse | — (partial: "));
        let md = write_report(&p, None).unwrap();
        assert_eq!(
            std::fs::read_to_string(ledger.join("coarse.csv")).unwrap(),
            coarse
        );
        assert!(
            md.contains("| 4a | εs of the floor cell | `S-JJ-phi_phi=1` | 0.03 | 0.050 | coarse |"),
            "{md}"
        );
        assert!(md.contains("| `S-JJ-phi_phi=1` | coarse | ledger ("));
        assert!(md.contains(
            "**Missing** (no run folder here: its numbers are the coarse ledger row's): \
             `S-JJ-phi_phi=1`"
        ));
    }
}
