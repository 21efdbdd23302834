//! `cargo xtask error-time`: the discretisation error of the paper's station and probe
//! numbers, the station profiles, the gate speeds and the bulk histories against CPU time
//! (issues 8 and 45), with the observed order, Richardson extrapolation and Roache's GCI.
//!
//! Each case (default S-JJ-phi φ = 0.1 and S-JEN-d d = 0.5 mm) runs on a ladder of grids, one
//! run at a time, with its own convection scheme (or those of `--schemes`), into
//! `runs/error-time/<case>/<level>-<scheme>/`:
//! - `tiny`: the smoke grid coarsened 2× more (a pipeline check, not a fidelity preset);
//! - `smoke`, `coarse`: the grids of the case's fidelity presets;
//! - `half`: the paper grid coarsened 2×; `paper`: the case's own grid; `finer`: the paper
//!   grid refined 2× (`runout_mesh::Segment::refined`). For family S, coarse, half, paper
//!   and finer (250 × 23, 500 × 45, 1000 × 90, 2000 × 180) are a uniform ladder, 2× per
//!   step.
//!
//! Every level runs to the case's own end time (the presets' shorter smoke end time would
//! stop before the profile time and the gates), so only the grid changes between levels;
//! `--end-time T` stops every level at T instead and compares the profiles there.
//!
//! Errors, for each case and scheme:
//! - **the paper's station and probe numbers** (air-cushion thickness, flow thickness, εs and
//!   θ of the floor cell, max u_s at the station at the profile time, h_w^u at the floor
//!   probe), read by the report's own functions (`station`): |q − q_ref| in their unit,
//!   and from the three finest levels the trend, observed order, Richardson extrapolation
//!   and Roache's GCI (`gci`); a cushion present at one level and not the next is said to
//!   be a ladder that does not converge;
//! - **station profiles** (εs, u_s, θ at the x and last time of the case's first profile
//!   monitor): every run's profile is interpolated linearly onto the cell-centre heights of
//!   the reference run (extended linearly over the half cell at either end) and compared on
//!   the flow band, the heights where any run of the ladder has εs ≥ 0.01 (cases.md front
//!   threshold); L1 = Σ w |q − q_ref| / Σ w with w the reference cell heights, and the
//!   largest |q − q_ref|, both divided by the range (max − min) of q_ref over the band;
//! - **gate speeds** (front monitor): RMS and largest |v − v_ref| in m/s over the gates every
//!   run of the ladder reached;
//! - **front position and mean solids speed against time** (bulk monitor, `bulk.csv`): every
//!   run's history is interpolated linearly onto the reference run's sample times; RMS and
//!   largest difference in m and m/s over the times every run covers (for the front, the
//!   times at which every run has one). Unlike the station profile these exist at every level
//!   whether or not the front reaches the station; the bulk front is whole-cell (the east face
//!   of the last floor cell with εs ≥ the bulk threshold), so it moves in steps of Δx.
//!
//! The reference is the finest level with the quantity. With three levels or more the three
//! finest also give the observed order p, from the norms of the differences of successive
//! levels D₃₂ and D₂₁ (h = √(cells of the paper grid / cells), D₃₂/D₂₁ = (h₃ᵖ − h₂ᵖ)/(h₂ᵖ − h₁ᵖ)),
//! and the Richardson extrapolation q* = q₁ + (q₁ − q₂) h₁ᵖ/(h₂ᵖ − h₁ᵖ) (pointwise), against
//! which every level's error is given as well. The order is called asymptotic when it lies
//! in [0.5, 1.5] × the scheme's nominal order range (upwind: 1; Superbee: 1 at extrema and
//! fronts, 2 where smooth); otherwise, or when the differences do not shrink, the page says
//! so and the Richardson numbers are to be read as indicative only.
//!
//! Every level runs with the case file's numerics (outer iteration, time-step controller),
//! as the sweep's runs do, so the paper level is the sweep's paper run. Each run's CPU time
//! and threads are kept beside it (`cost`).
//!
//! Output: `docs/reports/error-time.md` (date, command, the hand-kept notes of
//! `docs/reports/error-time/notes.md`, levels not run and why, tables),
//! `docs/reports/error-time/error_time.csv` and one log–log SVG of error against CPU time per case
//! and quantity in `docs/reports/error-time/`.
//!
//! The parts, one a file: `ladder` (the levels and schemes), `quantity` (what is
//! compared), `run` (running or reusing one level), `cost` (its CPU time), `read` and
//! `station` (reading its files), `measures` (interpolation, norms, shared samples),
//! `errors` and `station_errors` (the errors against the reference and the Richardson
//! extrapolation), `richardson` (the observed order), `gci` (Roache's GCI),
//! `csv_file`, `page`, `station_page` and `plot` (the outputs); this file holds the
//! options and the study's stages.

mod cost;
mod csv_file;
mod errors;
mod gci;
mod ladder;
mod measures;
mod page;
mod plot;
mod quantity;
mod read;
mod richardson;
mod run;
mod station;
mod station_errors;
mod station_page;

use std::path::Path;

use anyhow::{bail, Context, Result};
use runout_case::{Case, Convection};

use self::errors::{quantity_errors, QuantityErrors};
use self::gci::ScalarConvergence;
use self::ladder::{ending_at, scheme_name};
pub use self::ladder::{parse_scheme, Level};
use self::quantity::{quantities, LevelData, Quantity};
use self::run::{run_level, Run};
use self::station_errors::station_gci;
use crate::date::today;
use runout_study::sweep::matrix;

/// The cases of the error-against-time study: family S on the Johnson–Jackson φ = 0.1 floor
/// and on the Jenkins floor with d = 0.5 mm (issue 45).
pub const DEFAULT_CASES: &str = "S-JJ-phi_phi=0.1,S-JEN-d_d=0.0005";
/// The uniform ladder of family S: every level 2× the cells of the previous in x and y.
pub const DEFAULT_LEVELS: &str = "coarse,half,paper,finer";
/// What `--no-run` reports for a level without a finished run.
const NOT_RUN: &str = "not run (--no-run)";
/// Run folders, relative to the workspace root.
const RUNS_DIR: &str = "runs/error-time";
/// The page, relative to the workspace root.
const PAGE: &str = "docs/reports/error-time.md";
/// CSV and figures, relative to the workspace root.
const OUTPUT_DIR: &str = "docs/reports/error-time";
/// The notes kept by hand (which commit ran which level, caveats), in [`OUTPUT_DIR`]: the
/// page puts them under its header.
const NOTES: &str = "notes.md";

/// Options of the study.
pub struct Options {
    /// levels to run, any subset
    pub levels: Vec<Level>,
    /// case names (expanded sweep names, e.g. `S-JJ-phi_phi=0.1`)
    pub cases: Vec<String>,
    /// convection schemes; empty: each case's own (`numerics.convection` of its file)
    pub schemes: Vec<Convection>,
    /// read finished runs of an unchanged case instead of rerunning them
    pub reuse: bool,
    /// run nothing: reuse finished runs and report the levels without one as not run
    pub no_run: bool,
    /// stop every run at this time and compare the profiles there (default: the case's end
    /// time and profile time)
    pub end_time: Option<f64>,
}

impl Options {
    /// The command line that reproduces these options.
    pub fn command(&self) -> String {
        let join = |v: Vec<&str>| v.join(",");
        let schemes = if self.schemes.is_empty() {
            String::new()
        } else {
            format!(
                " --schemes {}",
                join(self.schemes.iter().map(scheme_name).collect())
            )
        };
        format!(
            "cargo xtask error-time --levels {} --cases {}{schemes}{}{}",
            join(self.levels.iter().map(|l| l.name()).collect()),
            join(self.cases.iter().map(String::as_str).collect()),
            self.end_time
                .map_or(String::new(), |t| format!(" --end-time {t}")),
            if self.no_run {
                " --no-run"
            } else if self.reuse {
                " --reuse"
            } else {
                ""
            }
        )
    }
}

/// The ladder of one case and scheme, with the errors of every quantity the case has.
struct Ladder {
    case: String,
    scheme: Convection,
    runs: Vec<Run>,
    errors: Vec<(Quantity, QuantityErrors)>,
    /// Roache's GCI of each station number with three levels or more
    gci: Vec<(Quantity, ScalarConvergence)>,
}

/// Runs the study and writes its page, CSV and figures.
pub fn error_time(root: &Path, opts: &Options) -> Result<()> {
    if opts.levels.is_empty() || opts.cases.is_empty() {
        bail!("--levels and --cases need at least one entry each");
    }
    let mut levels = opts.levels.clone();
    levels.sort();
    levels.dedup();
    let cases = select_cases(root, opts)?;
    let command = opts.command();
    println!("{command}");
    println!(
        "levels {}, one run at a time on {} rayon thread(s)",
        levels
            .iter()
            .map(|l| l.name())
            .collect::<Vec<_>>()
            .join(", "),
        rayon::current_num_threads()
    );
    let ladders = run_ladders(root, &cases, &levels, opts)?;
    write_outputs(root, &command, &levels, &cases, &ladders)?;
    let failed = ladders
        .iter()
        .flat_map(|l| &l.runs)
        .filter(|r| {
            r.summary
                .as_ref()
                .is_err_and(|why| !why.starts_with(NOT_RUN))
        })
        .count();
    if failed > 0 {
        bail!("{failed} run(s) failed (see {PAGE})");
    }
    Ok(())
}

/// The cases named in `opts`, from the matrix under cases/ (stopped at `--end-time` if
/// given); an unknown name is an error that lists the cases of its family.
fn select_cases(root: &Path, opts: &Options) -> Result<Vec<Case>> {
    let all = matrix(&root.join("cases"))?.runs;
    let mut cases = Vec::new();
    for name in &opts.cases {
        let Some(c) = all.iter().find(|r| &r.case.name == name) else {
            let near: Vec<&str> = all
                .iter()
                .map(|r| r.case.name.as_str())
                .filter(|n| n.split('_').next() == name.split('_').next())
                .collect();
            bail!(
                "no case `{name}` in cases/ (same family: {})",
                near.join(", ")
            );
        };
        cases.push(match opts.end_time {
            Some(t) => ending_at(&c.case, t),
            None => c.case.clone(),
        });
    }
    Ok(cases)
}

/// Runs (or reads) every level of every case with every scheme, one run at a time, and
/// computes the errors of each ladder.
fn run_ladders(
    root: &Path,
    cases: &[Case],
    levels: &[Level],
    opts: &Options,
) -> Result<Vec<Ladder>> {
    let mut ladders = Vec::new();
    for case in cases {
        let paper_cells = case.grid()?.cell_count();
        let own = [case.numerics.convection.clone()];
        let schemes = if opts.schemes.is_empty() {
            &own[..]
        } else {
            &opts.schemes[..]
        };
        for scheme in schemes {
            let runs = levels
                .iter()
                .map(|&level| run_level(root, case, scheme, level, paper_cells, opts))
                .collect::<Result<Vec<Run>>>()?;
            let data: Vec<LevelData> = runs.iter().map(|r| r.data.clone()).collect();
            let errors = quantities(case)
                .into_iter()
                .map(|q| (q, quantity_errors(q, &data)))
                .collect();
            let gci = quantities(case)
                .into_iter()
                .filter_map(|q| Some((q, station_gci(q, &data, scheme)?)))
                .collect();
            ladders.push(Ladder {
                case: case.name.clone(),
                scheme: scheme.clone(),
                runs,
                errors,
                gci,
            });
        }
    }
    Ok(ladders)
}

/// Writes the CSV, the figures and the page.
fn write_outputs(
    root: &Path,
    command: &str,
    levels: &[Level],
    cases: &[Case],
    ladders: &[Ladder],
) -> Result<()> {
    let out = root.join(OUTPUT_DIR);
    std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
    csv_file::write_csv(&out.join("error_time.csv"), ladders)?;
    let mut figures = Vec::new();
    for case in cases {
        for q in quantities(case) {
            let file = format!("{}_{}.svg", plot::file_stem(&case.name), q.name());
            if plot::draw(&out.join(&file), &case.name, q, ladders)? {
                figures.push((case.name.clone(), q, file));
            }
        }
    }
    let notes = std::fs::read_to_string(out.join(NOTES)).ok();
    let page = page::markdown(
        command,
        &today(),
        levels,
        cases,
        ladders,
        &figures,
        notes.as_deref(),
    )?;
    runout_output::write_atomic(&root.join(PAGE), page.as_bytes())
        .with_context(|| format!("writing {PAGE}"))?;
    println!(
        "wrote {PAGE}, {OUTPUT_DIR}/error_time.csv and {} figure(s)",
        figures.len()
    );
    Ok(())
}

/// A finite value formatted with `fmt`, or nothing.
fn opt(v: Option<f64>, fmt: impl Fn(f64) -> String) -> String {
    v.filter(|x| x.is_finite()).map_or(String::new(), fmt)
}
