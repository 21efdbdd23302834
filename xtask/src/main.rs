//! Developer tasks of runout, run as `cargo xtask <task>`.
//!
//! - `sweep`: the paper's case matrix (every sweep and stand-alone case under `cases/`),
//!   expanded, validated and run in parallel into `runs/`, its rows merged into
//!   `results/summary.csv` (the study engine, [`runout_study`]);
//!   cases that need the two-fluid model (issue 7) are reported as unsupported.
//! - `bench linsolve`: the linear-solver timing table of docs/studies/performance.md;
//! - `bench two-fluid`: the two-fluid solver's cost table (issue 22).
//! - `verify <name> [--report]`: the checks of runout-verification's registry at full size
//!   ([`verify`]): one check (cavity, poiseuille, taylor-green, chute, incline, haff, cooling,
//!   settling, fluidized-bed, s-jj-phi) or a group (single-phase, two-fluid, all);
//!   `verify <study> [options]`: a study of the registry, given the command line's options
//!   ([`runout_verification::study`]): `collapse [--friction F] [--fidelity F] [--aspect
//!   LIST] [--sidewalls W_L0,MU_W] [--reuse]`, the granular column collapse (issues 7, 43);
//!   `mfix-slope [--fidelity F] [--threads LIST] [--skip-variants]`, family M against MFIX
//!   (issue 9); `cavity-re1000`, the Re = 1000 cavity investigation;
//! - `report analytic`: family A, the closed-form profiles of paper Fig. 1, as SVG and CSV
//!   in docs/reports/analytic/;
//! - `report [results] [--fidelity F]`: the runs of the sweep beside the paper, in
//!   docs/reports/results.md with SVG figures in docs/reports/results/, and the elasticities of family S's
//!   one-factor families ([`runout_study::sensitivity`]) as a table, a heat map and a CSV;
//! - `ledger add RUN_DIR...`: records run folders made elsewhere in the metrics ledger
//!   docs/reports/results/ledger/<fidelity>.csv, which the report judges the findings from where a
//!   case has no run folder ([`runout_paper::ledger`]);
//! - `error-time`: the discretisation error of the paper's station and probe numbers (with
//!   Roache's GCI), the station profiles, gate speeds and bulk histories against CPU time
//!   over a ladder of grids ([`runout_paper::error_time`]), in docs/reports/error-time.md;
//! - `calibrate`: fits one or two numeric fields of a case to measurements (front speeds at
//!   gates, front positions or a profile) by minimising the RMS misfit: a landscape scan,
//!   then Brent (1-D) or Nelder–Mead (2-D) from argmin ([`calibrate`], docs/reference/calibrate.md);
//! - `stability`: the stiff and extreme cases of cases/stability/ (issue 7), one at a time,
//!   with the table of docs/reports/stability.md ([`runout_paper::stability`]); fails if a
//!   run writes NaN.

mod analytic;
mod bench_two_fluid;
mod case_reference;
mod chute;
mod verify;

/// The seed paper's reproduction: its matrix, sweep, report and ledger.
use runout_paper::{error_time, foot, ledger, release, stability};
/// The study engine: sweeps, calibration and sensitivity (`runout sweep` and friends).
use runout_study::{calibrate, sweep};

use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{bail, Context, Result};
use clap::{Parser, Subcommand};
use runout_case::Fidelity;
use runout_verification::{find_study, Args as StudyArgs, Context as StudyContext};

#[derive(Parser)]
#[command(name = "cargo xtask", about = "runout developer tasks")]
struct Cli {
    #[command(subcommand)]
    task: Task,
}

#[derive(Subcommand)]
enum Task {
    /// Expand, validate and run the paper's case matrix (cases/) in parallel; finished runs
    /// are skipped (a killed sweep resumes); its rows are merged into results/summary.csv (the
    /// rows of other cases and fidelities are kept; shards may write at once, under a lock).
    Sweep {
        /// smoke, coarse (default), wall or paper
        #[arg(long, default_value = "coarse")]
        fidelity: String,
        /// run only the cases whose name contains this
        #[arg(long)]
        only: Option<String>,
        /// parallel runs (default: the number of cores)
        #[arg(long)]
        jobs: Option<usize>,
        /// run only shard i of n (1-based), e.g. `--shard 2/4`, for cluster job arrays
        #[arg(long)]
        shard: Option<String>,
        /// list the matrix and run nothing
        #[arg(long)]
        list: bool,
        /// case directory
        #[arg(long, default_value = "cases")]
        cases: PathBuf,
        /// run the sweeps of this study (`Sweep(study: "...")`, e.g. `release`) instead of the
        /// paper's matrix
        #[arg(long)]
        study: Option<String>,
    },
    /// Fit one or two numeric fields of a case to measurements (docs/reference/calibrate.md): a scan
    /// of the misfit landscape in parallel, then Brent (1-D) or Nelder–Mead (2-D); every
    /// evaluation is a run in runs/calibrate/<study>/, reused when the same case repeats (a
    /// killed study resumes when the command is run again).
    Calibrate {
        /// the case or sweep file
        case_file: PathBuf,
        /// PATH=LO:HI[:START][:log] (one or two): a field path such as
        /// `boundaries.south.solids.specularity`, or a bare field name such as
        /// `specularity` for every field of that name
        #[arg(long = "param", required = true)]
        params: Vec<String>,
        /// the measurements CSV (header gate,speed_m_s | t,x | y,<profile column>)
        #[arg(long)]
        measurements: PathBuf,
        /// the case of a sweep file
        #[arg(long)]
        case: Option<String>,
        /// smoke, coarse (default), wall or paper
        #[arg(long, default_value = "coarse")]
        fidelity: String,
        /// landscape scan points per parameter (N, or N × N in 2-D)
        #[arg(long, default_value_t = 5)]
        scan: usize,
        /// at most this many refinement runs (Brent or Nelder–Mead)
        #[arg(long, default_value_t = 6)]
        refine: usize,
        /// parallel runs in the scan
        #[arg(long, default_value_t = 1)]
        jobs: usize,
        /// the measurement error σ of every point, in the measurement's unit (overrides the
        /// file's `sigma` column or `# sigma:` line)
        #[arg(long)]
        sigma: Option<f64>,
        /// Brent's and the range edges' absolute tolerance, as a fraction of the bounds (or
        /// log bounds)
        #[arg(long, default_value_t = 0.002)]
        xtol: f64,
        /// Nelder–Mead (2-D) stops when the standard deviation of its simplex's χ² is below this
        #[arg(long, default_value_t = 0.05)]
        ftol: f64,
        /// at most this many runs per side pinning the edges of the range Δχ² ≤ 1, then as many
        /// rounds of runs across the smooth response's range (1-D)
        #[arg(long, default_value_t = 2)]
        profile: usize,
        /// stations of the profile of χ² along the loosely constrained parameter (2-D; 0: none),
        /// up to 7 runs each: the range then follows a curved valley to its ends
        #[arg(long, default_value_t = 5)]
        valley: usize,
        /// study name: the folder under runs/calibrate/ (default: the case name)
        #[arg(long)]
        name: Option<String>,
        /// check the input and print the plan; run nothing
        #[arg(long)]
        dry_run: bool,
    },
    /// Write synthetic measurements from a finished run (docs/reference/calibrate.md, "Synthetic
    /// truths"): its interpolated front at given times, its gate speeds or a profile column,
    /// with a stated σ
    /// and optionally Gaussian noise of that σ; a calibration against them has a known truth.
    SyntheticMeasurements {
        /// the run folder (runs/<case>/<fidelity>/)
        run_dir: PathBuf,
        /// the front x at these times [s], comma-separated (else --gates or --profile)
        #[arg(long, value_delimiter = ',', required_unless_present_any = ["gates", "profile"])]
        times: Vec<f64>,
        /// the front speed at every gate the run crossed
        #[arg(long, conflicts_with_all = ["times", "profile"])]
        gates: bool,
        /// a column of this profile file of the run (profile_x<x>_t<t>.csv) against y
        #[arg(long, conflicts_with = "times", requires = "column")]
        profile: Option<String>,
        /// the profile's column (eps_s, u_s, theta, u_g, v_g)
        #[arg(long)]
        column: Option<String>,
        /// the profile's rows with εs at least this (the flow, not the empty cells above it)
        #[arg(long, default_value_t = 1e-3)]
        min_eps_s: f64,
        /// the measurement error σ of every point (written as `# sigma:`)
        #[arg(long)]
        sigma: f64,
        /// add Gaussian noise of σ, from this seed
        #[arg(long)]
        noise: Option<u64>,
        /// the file to write
        #[arg(long)]
        out: PathBuf,
    },
    /// Run the stiff and extreme cases of cases/stability/ (issue 7) and write their table to
    /// docs/reports/stability.md and docs/reports/stability/summary.csv; fails if a run writes a NaN or an
    /// infinity, or panics (a stop with a diagnosis is acceptable).
    Stability {
        /// smoke, coarse (default: the table) or paper
        #[arg(long, default_value = "coarse")]
        fidelity: String,
        /// run only the cases whose name contains this
        #[arg(long)]
        only: Option<String>,
        /// parallel runs (default 1: wall times stay comparable)
        #[arg(long, default_value_t = 1)]
        jobs: usize,
    },
    /// Discretisation error of the paper's station and probe numbers, the station profiles,
    /// gate speeds and bulk histories against CPU time (issues 8, 45): each case on a ladder
    /// of grids, one run at a time, with the observed order, Richardson and Roache's GCI;
    /// writes docs/reports/error-time.md, docs/reports/error-time/error_time.csv and SVG figures.
    ErrorTime {
        /// comma-separated levels: tiny (pipeline check), smoke, coarse, half (the paper grid
        /// coarsened 2×), paper, finer
        #[arg(long, default_value = error_time::DEFAULT_LEVELS)]
        levels: String,
        /// comma-separated case names of the matrix
        #[arg(long, default_value = error_time::DEFAULT_CASES)]
        cases: String,
        /// comma-separated convection schemes: upwind, superbee (default: each case's own)
        #[arg(long, default_value = "")]
        schemes: String,
        /// reuse finished runs of unchanged cases instead of rerunning them
        #[arg(long)]
        reuse: bool,
        /// run nothing: reuse finished runs and report levels without one as not run (the
        /// reuse compares the case, not the solver version that ran it)
        #[arg(long)]
        no_run: bool,
        /// stop every run at this time [s] and compare the profiles there (default: the
        /// case's end time and profile time)
        #[arg(long)]
        end_time: Option<f64>,
    },
    /// Verification: the checks of runout-verification at full size (cavity, poiseuille,
    /// taylor-green, chute, incline, haff, cooling, settling, fluidized-bed, s-jj-phi; groups
    /// single-phase, two-fluid, all), the Re = 1000 cavity study (cavity-re1000), the
    /// granular column collapse (collapse) and family M against MFIX (mfix-slope).
    Verify {
        /// a check, a group (single-phase, two-fluid, all), cavity-re1000, collapse or
        /// mfix-slope
        name: String,
        /// also write error against run time (CSV/SVG/Markdown) into docs/reports/verification/
        #[arg(long)]
        report: bool,
        #[command(flatten)]
        options: VerifyOptions,
    },
    /// Figures and tables: `cargo xtask report [results]` (the runs beside the paper, into
    /// docs/reports/results.md and docs/reports/results/), `cargo xtask report analytic` (paper Fig. 1 into
    /// docs/reports/analytic/), `release` (docs/reports/release.md) or `foot` (the slide onto a flat
    /// run-out, docs/reports/foot.md).
    Report {
        /// what to report: results (default), analytic or release (the release study,
        /// docs/reports/release.md)
        #[arg(default_value = "results")]
        what: String,
        /// read only runs of this fidelity (smoke, coarse, wall or paper); default: the best
        /// finished run of each case
        #[arg(long)]
        fidelity: Option<String>,
    },
    /// The metrics ledger docs/reports/results/ledger/<fidelity>.csv (one row of every scalar the
    /// findings read per run; `cargo xtask report` also writes the rows of the run folders it
    /// reads): `cargo xtask ledger add RUN_DIR...` records runs made elsewhere (a cluster,
    /// the error-time ladder, another machine).
    Ledger {
        #[command(subcommand)]
        action: LedgerAction,
    },
    /// Benchmarks: `cargo xtask bench linsolve [-- --max-cells N]`, `cargo xtask bench
    /// two-fluid [--smoke] [--write] [--window T] [--refine 1,2,4] [--skip-paper]`.
    Bench {
        /// what to benchmark (linsolve, two-fluid)
        what: String,
        /// the benchmark's own options
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        args: Vec<String>,
    },
    /// Writes docs/guide/case-reference.md from the case schema's reference table; `--check`
    /// fails when the checked-in page differs (CI).
    CaseReference {
        /// compare instead of writing
        #[arg(long)]
        check: bool,
    },
}

/// The options of `cargo xtask verify`'s studies (runout-verification's `Study`), passed
/// on as the command line gave them.
#[derive(clap::Args)]
struct VerifyOptions {
    /// fidelity of the runs (collapse: smoke or coarse, default coarse; mu-i also paper, L0/20; mfix-slope:
    /// default paper, MFIX's 200 × 50 grid)
    #[arg(long)]
    fidelity: Option<String>,
    /// reuse finished runs of unchanged cases (collapse only)
    #[arg(long)]
    reuse: bool,
    /// collapse: the friction law, princeton (the paper's material, the four shipped
    /// columns), mu-i (glass beads, cases/collapse/CM-a1.ron as template) or both (each
    /// μ(I) column and the same column with Princeton beside it)
    #[arg(long, default_value = "princeton")]
    friction: String,
    /// collapse: comma-separated aspect ratios a = H0/L0 whose columns are built from the
    /// friction's template (default with mu-i and both: 0.5,1,3,6)
    #[arg(long, value_delimiter = ',')]
    aspect: Option<Vec<String>>,
    /// collapse: every column between two Coulomb side walls (docs/model.md §3.11, §8):
    /// `W_L0,MU_W`, the channel width in L0 and the grain–wall friction μ_w; the page
    /// goes to runs/collapse-report/<fidelity>-W<W_L0>L0-mu<MU_W>/
    #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
    sidewalls: Option<Vec<String>>,
    /// mfix-slope: comma-separated rayon thread counts to time the JJ case with
    #[arg(long, default_value = "1")]
    threads: String,
    /// mfix-slope: only the JJ case, not the other three floors
    #[arg(long)]
    skip_variants: bool,
}

impl VerifyOptions {
    /// The options by name, as a study reads them.
    fn study_args(self) -> StudyArgs {
        StudyArgs::new()
            .with("fidelity", self.fidelity)
            .flag("reuse", self.reuse)
            .with("friction", Some(self.friction))
            .with("aspect", self.aspect.map(|a| a.join(",")))
            .with("sidewalls", self.sidewalls.map(|w| w.join(",")))
            .with("threads", Some(self.threads))
            .flag("skip-variants", self.skip_variants)
    }
}

#[derive(Subcommand)]
enum LedgerAction {
    /// Record finished run folders (each with a summary.json) in the ledger, replacing
    /// their cases' rows at their fidelity; smoke runs are refused.
    Add {
        /// run folders, e.g. runs/S-JJ-phi_phi=0.1/paper
        #[arg(required = true)]
        run_dirs: Vec<PathBuf>,
        /// the case's name in the matrix, if the summary's differs (one folder only)
        #[arg(long)]
        case: Option<String>,
        /// record under this fidelity instead of the summary's (coarse, wall or paper)
        #[arg(long)]
        fidelity: Option<String>,
        /// `git describe` of the build that made the runs, for folders that do not record
        /// it (else "unknown")
        #[arg(long)]
        solver: Option<String>,
    },
}

/// The folder that holds `runs/`, `results/` and `docs/`: `$XTASK_ROOT` if set (the tests
/// sweep into a temporary folder so), else the workspace root (xtask lives one level below
/// it).
fn root() -> PathBuf {
    if let Some(dir) = std::env::var_os("XTASK_ROOT").filter(|d| !d.is_empty()) {
        return PathBuf::from(dir);
    }
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

fn main() -> Result<()> {
    match Cli::parse().task {
        Task::Sweep {
            fidelity,
            only,
            jobs,
            shard,
            list,
            cases,
            study,
        } => sweep_task(fidelity, only, jobs, shard, list, cases, study),
        Task::Calibrate {
            case_file,
            params,
            measurements,
            case,
            fidelity,
            scan,
            refine,
            jobs,
            sigma,
            xtol,
            ftol,
            profile,
            valley,
            name,
            dry_run,
        } => calibrate::run(
            &root(),
            &calibrate::Options {
                case_file,
                case,
                params,
                measurements,
                fidelity: parse_fidelity(&fidelity)?,
                scan,
                refine,
                jobs,
                sigma,
                xtol,
                ftol,
                profile,
                valley,
                name,
                dry_run,
                program: "cargo xtask",
            },
        ),
        Task::SyntheticMeasurements {
            run_dir,
            times,
            gates,
            profile,
            column,
            min_eps_s,
            sigma,
            noise,
            out,
        } => {
            use calibrate::synthetic::{measurements_from_run, Measured};
            let what = match (gates, profile) {
                (true, _) => Measured::GateSpeeds,
                (false, Some(file)) => Measured::Profile {
                    file,
                    column: column.unwrap_or_default(),
                    min_eps_s,
                },
                (false, None) => Measured::Front(times),
            };
            let text = measurements_from_run(&run_dir, &what, sigma, noise)?;
            std::fs::write(&out, &text).with_context(|| format!("writing {}", out.display()))?;
            print!("{text}");
            Ok(())
        }
        Task::Stability {
            fidelity,
            only,
            jobs,
        } => stability::stability(
            &root(),
            &stability::StabilityOptions {
                fidelity: parse_fidelity(&fidelity)?,
                only,
                jobs,
            },
        ),
        Task::ErrorTime {
            levels,
            cases,
            schemes,
            reuse,
            no_run,
            end_time,
        } => error_time_task(&levels, &cases, &schemes, reuse, no_run, end_time),
        Task::Verify {
            name,
            report,
            options,
        } => verify_task(&name, report, &options.study_args()),
        Task::Report { what, fidelity } => report_task(&what, fidelity.as_deref()),
        Task::Ledger { action } => ledger_task(action),
        Task::Bench { what, args } => bench_task(&what, &args),
        Task::CaseReference { check } => case_reference::run(&root(), check),
    }
}

/// A fidelity preset from its name (smoke, coarse, wall or paper).
fn parse_fidelity(name: &str) -> Result<Fidelity> {
    name.parse().map_err(anyhow::Error::msg)
}

/// Runs `cargo` (the one that runs xtask, if known) with `args` in the workspace root; an
/// error naming `what` if it fails.
fn cargo(args: &[&str], what: &str) -> Result<()> {
    let status = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
        .current_dir(root())
        .args(args)
        .status()?;
    if !status.success() {
        bail!("{what} failed: {status}");
    }
    Ok(())
}

/// `cargo xtask sweep`.
fn sweep_task(
    fidelity: String,
    only: Option<String>,
    jobs: Option<usize>,
    shard: Option<String>,
    list: bool,
    cases: PathBuf,
    study: Option<String>,
) -> Result<()> {
    let opts = sweep::SweepOptions {
        fidelity: parse_fidelity(&fidelity)?,
        only,
        jobs: jobs.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get())),
        shard: shard.as_deref().map(sweep::parse_shard).transpose()?,
        list,
        gates: None,
        program: "cargo xtask",
    };
    let dir = if cases.is_absolute() {
        cases
    } else {
        root().join(cases)
    };
    runout_paper::matrix::sweep(&root(), &dir, study.as_deref(), opts)
}

/// `cargo xtask error-time`: the comma-separated lists parsed into the study's options.
fn error_time_task(
    levels: &str,
    cases: &str,
    schemes: &str,
    reuse: bool,
    no_run: bool,
    end_time: Option<f64>,
) -> Result<()> {
    let list = |s: &str| -> Vec<String> {
        s.split(',')
            .map(|v| v.trim().to_string())
            .filter(|v| !v.is_empty())
            .collect()
    };
    let opts = error_time::Options {
        levels: list(levels)
            .iter()
            .map(|l| l.parse())
            .collect::<Result<_, _>>()
            .map_err(anyhow::Error::msg)?,
        cases: list(cases),
        schemes: list(schemes)
            .iter()
            .map(|s| error_time::parse_scheme(s))
            .collect::<Result<_, _>>()
            .map_err(anyhow::Error::msg)?,
        reuse,
        no_run,
        end_time,
    };
    error_time::error_time(&root(), &opts)
}

/// `cargo xtask verify <name>`: a study of runout-verification's registry with its options
/// (collapse, mfix-slope), or its checks at full size (one, or a group: single-phase,
/// two-fluid, all).
fn verify_task(name: &str, report: bool, args: &StudyArgs) -> Result<()> {
    match find_study(name) {
        Some(study) => study.run(args, &StudyContext::at(&root())),
        None => verify::verify(name, report, &root()),
    }
}

/// `cargo xtask report [results|analytic|release]`.
fn report_task(what: &str, fidelity: Option<&str>) -> Result<()> {
    let fidelity = fidelity.map(parse_fidelity).transpose()?;
    match what {
        "analytic" => analytic::report(&root()),
        "results" => runout_paper::report(&root(), fidelity),
        "release" => release::report(&root(), fidelity),
        "foot" => foot::report(&root(), fidelity),
        other => bail!("unknown report `{other}` (known: results, analytic, release, foot)"),
    }
}

/// `cargo xtask ledger add RUN_DIR... [--case C] [--fidelity F] [--solver S]`.
fn ledger_task(action: LedgerAction) -> Result<()> {
    let LedgerAction::Add {
        run_dirs,
        case,
        fidelity,
        solver,
    } = action;
    let opts = ledger::AddOptions {
        case,
        fidelity: fidelity.as_deref().map(parse_fidelity).transpose()?,
        solver,
    };
    ledger::add(
        &root().join("docs/reports"),
        &root().join("cases"),
        &run_dirs,
        &opts,
    )
}

/// `cargo xtask bench <what> [args]`.
fn bench_task(what: &str, args: &[String]) -> Result<()> {
    match what {
        "linsolve" => {
            let mut all = vec![
                "run",
                "--release",
                "-p",
                "runout-linsolve",
                "--example",
                "linsolve_table",
                "--",
            ];
            all.extend(args.iter().map(String::as_str));
            cargo(&all, "linsolve benchmark")
        }
        "two-fluid" => bench_two_fluid::run(&root(), args),
        other => bail!("unknown benchmark `{other}` (known: linsolve, two-fluid)"),
    }
}
