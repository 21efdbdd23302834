//! `runout`: the command-line program of the runout two-fluid solver.
//!
//! - `runout check <files or dirs...>`: validate case, sweep and analytic files and list the
//!   cases they expand to;
//! - `runout run <file>`: run a case (single-phase gas cases today; the two-fluid model is
//!   issue 7) and write VTK fields, CSV monitors and a JSON summary;
//! - `runout mesh <file>`: print the grid summary of a case (or of each case of a sweep);
//! - `runout closures --eps-s … --theta …`: every closure value at one state, as JSON;
//! - `runout wall --model … --eps-s … --theta … --slip …`: a wall model's Robin coefficients
//!   and diagnostics (h_w^u, φ, COL, FRI), as JSON;
//! - `runout sweep <path>`, `runout calibrate <case> --param … --measurements …`, `runout
//!   sensitivity <path>`: studies of many runs on the user's own cases ([`cmd_study`]).

mod cmd_closures;
mod cmd_grid_error;
mod cmd_pore_pressure;
mod cmd_study;
mod cmd_wall;
mod material;

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use indicatif::{ProgressBar, ProgressStyle};
use runout_case::{case_files, load, Fidelity, Loaded};
use runout_output::{RunStatus, RunSummary};
use runout_run::{signals, RunOptions};
use tracing::info;

#[derive(Parser, Debug)]
#[command(
    name = "runout",
    version,
    about = "Two-fluid model solver for dense gas–granular flows"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Validate case, sweep and analytic files (or every .ron file under a directory) and
    /// list the cases they expand to, with their grid sizes at every fidelity.
    Check {
        /// files or directories
        #[arg(required = true)]
        paths: Vec<PathBuf>,
        /// also say what each case computes (the solver's stages, closures, wall closures
        /// per side, friction terms, monitors) and what it costs (cells, unknowns, memory),
        /// from the solver built as `runout run` builds it
        #[arg(long)]
        explain: bool,
        /// the fidelity `--explain` builds the solver at
        #[arg(long, default_value = "paper", value_parser = parse_fidelity)]
        fidelity: Fidelity,
    },
    /// Print the grid summary of a case: cell counts, min/max widths, largest adjacent
    /// width ratio and largest aspect ratio.
    Mesh {
        /// a case or sweep file
        file: PathBuf,
        /// smoke, coarse, wall (the paper's cells in y, x coarsened) or paper
        #[arg(long, default_value = "paper", value_parser = parse_fidelity)]
        fidelity: Fidelity,
    },
    /// Run a case (or every case of a sweep) and write fields (VTK), monitors (CSV) and a
    /// run summary (JSON) into `runs/<case>/<fidelity>/` or `--out`.
    Run {
        /// a case or sweep file
        file: PathBuf,
        /// smoke, coarse, wall (the paper's cells in y, x coarsened) or paper
        #[arg(long, default_value = "paper", value_parser = parse_fidelity)]
        fidelity: Fidelity,
        /// output folder (default runs/<case>/<fidelity>)
        #[arg(long)]
        out: Option<PathBuf>,
        /// no progress bar
        #[arg(long)]
        quiet: bool,
        /// stop at this simulated time [s] instead of the fidelity's end time, in the case's
        /// clock (from the tilt with `clock: Impact`, docs/studies/impact.md §4)
        #[arg(long, value_parser = parse_end_time)]
        end_time: Option<f64>,
        /// run only the case of this name (of a sweep file's cases)
        #[arg(long, value_name = "NAME")]
        only: Option<String>,
        /// continue the run in DIR (default: the output folder) from its newest checkpoint
        #[arg(long, value_name = "DIR", num_args = 0..=1)]
        restart: Option<Option<PathBuf>>,
        /// replace an earlier run in the output folder (its files only) instead of refusing
        #[arg(long, conflicts_with = "restart")]
        overwrite: bool,
        /// run even if the estimated memory exceeds what the machine has available
        #[arg(long)]
        ignore_memory: bool,
        /// also write a checkpoint after every this many minutes of wall time
        #[arg(long, value_name = "MINUTES", value_parser = parse_minutes)]
        checkpoint_every: Option<f64>,
    },
    /// Print every closure value (kinetic theory, friction, drag, K_cp, granular-energy
    /// sources) at one state as JSON.
    Closures(cmd_closures::ClosuresArgs),
    /// Print how long gas pressure lasts in the pores of a bed at rest as JSON: the drag
    /// law's Darcy mobility and U_mf, the gas's and the bed's storage, the pore-pressure
    /// diffusivity and the basal excess's half-life at each height (docs/guide/gas.md).
    PorePressure(cmd_pore_pressure::PorePressureArgs),
    /// Print a run folder's metrics as JSON: its summary, the station time, the front and
    /// mean u_s there, and the station profile's metrics (air cushion, cushion and flow
    /// thickness, floor εs, max u_s), h_w^u at the floor probe, the gate speeds
    /// (definitions: runout-post's metrics module) and the deposit: whether and when the
    /// solids came to rest (εs-weighted mean u_s ≤ v_rest = 1 % of √(g H∞) and a still
    /// front from then on), the distal edges at εs ≥ 0.01 and ≥ 0.3, L∞ from the release's
    /// east edge and H∞, the largest thickness at εs ≥ 0.3, with the cells across it; a
    /// warning on stderr where the dense deposit is nowhere `--min-cells` cells thick, a
    /// note on its thin edge (docs/reference/deposit.md).
    Post {
        /// a run folder (runs/<case>/<fidelity>, or a `.partial` one of a run still going)
        run_dir: PathBuf,
        /// described or measured gate speeds (CSV: gate,x,speed with gates L1..L7) for the
        /// gate-speed MSE, e.g. cases/flume/gates.csv
        #[arg(long, value_name = "CSV")]
        gates: Option<PathBuf>,
        /// write the deposit profile along x to this CSV
        /// (x,thickness_dense,thickness_dilute,solids_height; m; cells_dense)
        #[arg(long, value_name = "CSV")]
        deposit_profile: Option<PathBuf>,
        /// v_rest as a fraction of √(g H∞)
        #[arg(long, default_value_t = runout_post::deposit::DEFAULT_REST_FRACTION)]
        rest_fraction: f64,
        /// warn where the dense deposit is nowhere this many cells thick
        #[arg(long, default_value_t = runout_post::deposit::DEFAULT_MIN_CELLS, value_parser = clap::value_parser!(usize))]
        min_cells: usize,
        /// write who carries the flow's weight at its base (the gas's excess pressure, the
        /// solids pressure) column by column at every field file to this CSV
        /// (t,x,load,gas_share,solids_share), and the whole flow's shares to the JSON's
        /// `basal_load` (docs/reference/deposit.md, "The basal load")
        #[arg(long, value_name = "CSV")]
        basal_load: Option<PathBuf>,
    },
    /// Print a wall model's Robin coefficients for velocity and granular temperature, with
    /// the diagnostics the paper plots (h_w^u, φ, COL, FRI, slip), as JSON.
    Wall(cmd_wall::WallArgs),
    /// Run every case of a case file, a sweep file or a folder of them, in parallel, into
    /// `DIR/runs/<case>/<fidelity>/` (`--out DIR`, default the current folder): finished runs
    /// are skipped and an interrupted one continues from its checkpoint, so a killed sweep
    /// resumes; the rows are merged into `DIR/results/summary.csv` (shards of a cluster array
    /// may write at once).
    Sweep(cmd_study::SweepArgs),
    /// Fit one or two numeric fields of a case to measurements (front speeds at gates, front
    /// positions or a profile): a scan of the misfit landscape, then Brent (1-D) or
    /// Nelder–Mead (2-D); every evaluation is a run in `DIR/runs/calibrate/<study>/`, reused
    /// when the command is run again.
    Calibrate(cmd_study::CalibrateArgs),
    /// Elasticities ∂ln y/∂ln p of every numeric column of `DIR/results/summary.csv` and of
    /// the front and mean u_s at each run's end over every one-factor family of the sweeps
    /// under PATH; writes `DIR/results/elasticities.csv`.
    Sensitivity(cmd_study::SensitivityArgs),
    /// The grid error of where a case's flow stops: the case run on three or more grids,
    /// each twice as coarse as the one before, into `--out/<case>-x<factor>/` (completed
    /// levels are reused); for the deposit's runout L∞, maximum thickness H∞ and centre,
    /// the observed order, the Richardson value and Roache's GCI of the finest grid
    /// (docs/reference/deposit.md).
    GridError(cmd_grid_error::GridErrorArgs),
}

/// `runout post`: the metrics of one run folder as pretty JSON on stdout.
fn post(
    run_dir: &std::path::Path,
    gates: Option<&std::path::Path>,
    (deposit_profile, basal_load): (Option<&std::path::Path>, Option<&std::path::Path>),
    (rest_fraction, min_cells): (f64, usize),
) -> ExitCode {
    if !(rest_fraction > 0.0 && rest_fraction < 1.0) {
        eprintln!("runout post: --rest-fraction {rest_fraction}: allowed (0, 1)");
        return ExitCode::FAILURE;
    }
    if min_cells == 0 {
        eprintln!("runout post: --min-cells 0: allowed 1 or more");
        return ExitCode::FAILURE;
    }
    let described = match gates {
        Some(csv) => {
            let d = runout_post::metrics::described_speeds(csv);
            if d.is_empty() {
                eprintln!(
                    "runout post: {}: no gate speeds (expected a CSV `gate,x,speed` with rows \
                     such as `L2,2.6,4.0`)",
                    csv.display()
                );
                return ExitCode::FAILURE;
            }
            d
        }
        None => Vec::new(),
    };
    let mut metrics = match runout_post::run::run_metrics(run_dir, &described) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("runout post: {e}");
            return ExitCode::FAILURE;
        }
    };
    let custom = rest_fraction != runout_post::deposit::DEFAULT_REST_FRACTION
        || min_cells != runout_post::deposit::DEFAULT_MIN_CELLS;
    if custom || deposit_profile.is_some() {
        let read = runout_post::folder::read_resolved_unvalidated(run_dir)
            .and_then(|case| runout_post::deposit::read_deposit(run_dir, &case, rest_fraction));
        let (mut deposit, profile) = match read {
            Ok(d) => d,
            Err(e) => {
                eprintln!("runout post: deposit: {e}");
                return ExitCode::FAILURE;
            }
        };
        if let Some(csv) = deposit_profile {
            let text = runout_post::deposit::profile_csv(&profile);
            if let Err(e) = std::fs::write(csv, text) {
                eprintln!("runout post: writing {}: {e}", csv.display());
                return ExitCode::FAILURE;
            }
        }
        deposit.thin = runout_post::deposit::thin_deposit(&profile, min_cells);
        metrics.deposit = Ok(deposit);
    }
    if let Some(csv) = basal_load {
        match flow_basal_load(run_dir, csv) {
            Ok(flow) => metrics.basal_load = Some(flow),
            Err(e) => {
                eprintln!("runout post: basal load: {e}");
                return ExitCode::FAILURE;
            }
        }
    }
    if let Ok(d) = &metrics.deposit {
        if let Some(thin) = &d.thin {
            eprintln!("runout post: {}", thin.message(d.max_thickness_cells));
        }
    }
    match serde_json::to_string_pretty(&metrics) {
        Ok(json) => {
            // a closed pipe (`| head`) is not an error of the command
            let _ = writeln!(std::io::stdout(), "{json}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("runout post: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Writes the run's basal load column by column to `csv` and returns the whole flow's
/// shares at each field file that holds a flow (runout_post::basal_load).
fn flow_basal_load(
    run_dir: &std::path::Path,
    csv: &std::path::Path,
) -> Result<Vec<runout_post::basal_load::FlowLoad>, String> {
    use runout_post::basal_load::{columns_csv, flow_load, read_basal_load};
    let case = runout_post::folder::read_resolved_unvalidated(run_dir)?;
    let snapshots = read_basal_load(run_dir, &case)?;
    std::fs::write(csv, columns_csv(&snapshots))
        .map_err(|e| format!("writing {}: {e}", csv.display()))?;
    Ok(snapshots
        .iter()
        .filter_map(|(time, columns)| flow_load(*time, columns))
        .collect())
}

fn parse_fidelity(s: &str) -> Result<Fidelity, String> {
    s.parse()
}

fn parse_minutes(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(m) if m.is_finite() && m > 0.0 && m <= 1e6 => Ok(m),
        _ => Err(format!("`{s}`: a number of minutes in (0, 1e6]")),
    }
}

fn parse_end_time(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(t) if t.is_finite() && t > 0.0 => Ok(t),
        _ => Err(format!("{s}: allowed (0, inf) seconds")),
    }
}

/// `runout check`: validates the files and lists their cases with sizes; with `explain`,
/// also what each case computes and costs at that fidelity.
fn check(paths: &[PathBuf], explain: Option<Fidelity>) -> ExitCode {
    let mut failed = 0;
    let mut total = 0;
    for file in case_files(paths) {
        match load(&file) {
            Ok(Loaded::Cases(cases)) => {
                println!(
                    "{}: ok, {} case{}",
                    file.display(),
                    cases.len(),
                    if cases.len() == 1 { "" } else { "s" }
                );
                let available = runout_case::available_memory_bytes();
                for sc in &cases {
                    total += 1;
                    let sizes: Vec<String> = [
                        Fidelity::Smoke,
                        Fidelity::Coarse,
                        Fidelity::Wall,
                        Fidelity::Paper,
                    ]
                    .into_iter()
                    .map(|f| fidelity_size(&sc.case, f, available))
                    .collect();
                    println!("  {}  [{}]", sc.case.name, sizes.join("; "));
                    if let Some(fidelity) = explain {
                        match runout_run::explain::explain(&sc.case, fidelity) {
                            Ok(text) => println!("{text}"),
                            Err(e) => {
                                failed += 1;
                                eprintln!("{}: {e}", file.display());
                            }
                        }
                    }
                }
            }
            Ok(Loaded::Analytic(a)) => {
                println!(
                    "{}: ok, analytic family `{}` (closed-form profiles, no flow solve)",
                    file.display(),
                    a.name
                );
            }
            Err(e) => {
                failed += 1;
                eprintln!("{e}");
            }
        }
    }
    info!(files_failed = failed, cases = total, "check finished");
    if failed > 0 {
        eprintln!("{failed} file(s) rejected");
        ExitCode::FAILURE
    } else {
        println!("{total} case(s) valid");
        ExitCode::SUCCESS
    }
}

/// A case's grid, unknowns and estimated memory at one fidelity, for `check`, with a
/// warning when the estimate exceeds the memory available on this machine.
fn fidelity_size(case: &runout_case::Case, f: Fidelity, available: Option<u64>) -> String {
    let c = case.at_fidelity(f);
    match runout_case::case_size(&c) {
        Ok(s) => {
            let over = match available {
                Some(a) if s.memory_bytes > a => format!(
                    ", more than the {} available here",
                    runout_case::format_bytes(a)
                ),
                _ => String::new(),
            };
            format!(
                "{f} {}x{} = {} cells, {} unknowns, ~{}{over}, to {} s",
                s.nx,
                s.ny,
                s.cells,
                s.unknowns,
                runout_case::format_bytes(s.memory_bytes),
                // 0.1 ms: the end time of a case timed from the impact carries the tilt time
                (c.run.end_time * 1e4).round() / 1e4
            )
        }
        Err(e) => format!("{f} grid error: {e}"),
    }
}

/// The cases of a case or sweep file; `None` (after printing why) for an invalid file or
/// an analytic family, which has no grid and no flow to run.
fn flow_cases(file: &Path) -> Option<Vec<runout_case::SourcedCase>> {
    match load(file) {
        Ok(Loaded::Cases(c)) => Some(c),
        Ok(Loaded::Analytic(a)) => {
            eprintln!(
                "{}: `{}` is an analytic family (closed-form profiles, no grid): use `cargo xtask \
                 report analytic`",
                file.display(),
                a.name
            );
            None
        }
        Err(e) => {
            eprintln!("{e}");
            None
        }
    }
}

fn mesh(file: &Path, fidelity: Fidelity) -> ExitCode {
    let Some(cases) = flow_cases(file) else {
        return ExitCode::FAILURE;
    };
    let mut printed: Vec<runout_mesh::GridSummary> = Vec::new();
    for sc in cases {
        let case = sc.case.at_fidelity(fidelity);
        match case.grid() {
            Ok(grid) => {
                let s = grid.summary();
                if printed.contains(&s) {
                    println!("{} ({fidelity}): same grid as above", case.name);
                } else {
                    println!("{} ({fidelity}):\n{s}", case.name);
                    printed.push(s);
                }
                if let Ok(Some(floor)) = case.bent_floor() {
                    print!("{}", floor.describe(grid.x.start(), grid.x.end()));
                }
            }
            Err(e) => {
                eprintln!("{}: case `{}`: grid error: {e}", file.display(), case.name);
                return ExitCode::FAILURE;
            }
        }
    }
    ExitCode::SUCCESS
}

/// What `runout run` runs and where.
struct Target<'a> {
    /// the one case of a sweep file to run
    only: Option<&'a str>,
    fidelity: Fidelity,
    /// the output folder (default runs/<case>/<fidelity>)
    out: Option<&'a Path>,
    /// the end time instead of the fidelity's
    end_time: Option<f64>,
    /// run even where the memory estimate exceeds the available memory
    ignore_memory: bool,
}

/// Refuses a case whose estimated memory exceeds what the machine has available (before
/// anything is allocated), unless `ignore`.
fn memory_fits(file: &Path, case: &runout_case::Case, ignore: bool) -> bool {
    let need = runout_case::estimated_memory_bytes(case);
    match runout_case::available_memory_bytes() {
        Some(available) if need > available && !ignore => {
            eprintln!(
                "{}: case `{}` needs about {} of memory, and {} is available: refused before \
                 allocating (a coarser fidelity, or --ignore-memory to try anyway)",
                file.display(),
                case.name,
                runout_case::format_bytes(need),
                runout_case::format_bytes(available)
            );
            false
        }
        _ => true,
    }
}

fn run(file: &Path, target: &Target, quiet: bool, options: &RunOptions) -> ExitCode {
    let Target {
        only,
        fidelity,
        out,
        end_time,
        ignore_memory,
    } = *target;
    let Some(mut cases) = flow_cases(file) else {
        return ExitCode::FAILURE;
    };
    let several = cases.len() > 1;
    if let Some(name) = only {
        cases.retain(|c| c.case.name == name);
        if cases.is_empty() {
            eprintln!(
                "{}: --only {name}: no case of that name (`runout check {}` lists them)",
                file.display(),
                file.display()
            );
            return ExitCode::FAILURE;
        }
    }
    if let Some(t) = end_time {
        for sc in &mut cases {
            sc.case.run.end_time = t;
            sc.case.fidelity.smoke.end_time = t;
            sc.case.fidelity.coarse.end_time = t;
            if let Some(wall) = &mut sc.case.fidelity.wall {
                wall.end_time = t;
            }
            // the intervals and Δt bounds are validated against the end time (profile
            // times after it are kept: they never fire)
            let mut checked = sc.case.clone();
            for p in &mut checked.monitors.profiles {
                p.times.retain(|&time| time <= t);
            }
            checked.monitors.profiles.retain(|p| !p.times.is_empty());
            if let Err(errors) = runout_case::validate_case(&checked) {
                for e in errors {
                    eprintln!("{}: with --end-time {t}: {e}", file.display());
                }
                return ExitCode::FAILURE;
            }
        }
    }
    let mut status = ExitCode::SUCCESS;
    for sc in &cases {
        let dir = match out {
            Some(o) if cases.len() == 1 => o.to_path_buf(),
            Some(o) => o.join(&sc.case.name),
            None => match runout_case::run_dir(Path::new("."), &sc.case.name, fidelity) {
                Ok(dir) => dir,
                Err(e) => {
                    eprintln!("{}: {e}", file.display());
                    return ExitCode::FAILURE;
                }
            },
        };
        if !memory_fits(file, &sc.case.at_fidelity(fidelity), ignore_memory) {
            status = ExitCode::FAILURE;
            continue;
        }
        let bar = if quiet {
            ProgressBar::hidden()
        } else {
            ProgressBar::new(1000)
        };
        bar.set_style(
            ProgressStyle::with_template("{prefix} [{bar:30}] {msg} (eta {eta})")
                .expect("a valid template")
                .progress_chars("=> "),
        );
        bar.set_prefix(sc.case.name.clone());
        let result = runout_run::run_case_with(&sc.case, fidelity, &dir, options, |p| {
            bar.set_position((1000.0 * p.time / p.end_time) as u64);
            bar.set_message(format!(
                "t = {:.4} s, dt = {:.2e} s, {} it, {} steps",
                p.time, p.dt, p.iterations, p.steps
            ));
        });
        bar.finish_and_clear();
        match result {
            Ok(summary) => match report(file, target, &dir, &summary, several) {
                Reported::Completed => {}
                Reported::Failed => status = ExitCode::FAILURE,
                Reported::Interrupted => return ExitCode::from(signals::EXIT_INTERRUPTED as u8),
            },
            Err(e) => {
                eprintln!("{}: {e}", file.display());
                status = ExitCode::FAILURE;
            }
        }
    }
    status
}

/// How a run ended, for the exit status.
enum Reported {
    Completed,
    Failed,
    Interrupted,
}

/// Prints a finished run's summary line and, for a run that did not complete, why (and,
/// for an interrupted one, the command that continues it; `--only` where the file holds
/// several cases).
fn report(
    file: &Path,
    target: &Target,
    dir: &Path,
    summary: &RunSummary,
    several: bool,
) -> Reported {
    println!(
        "{}: {:?} at t = {} s, {} steps ({} rejected), {} outer iterations, {:.2} s wall; output in {}",
        summary.case,
        summary.status,
        summary.simulated_time,
        summary.steps,
        summary.rejected_steps,
        summary.outer_iterations,
        summary.wall_time,
        dir.display()
    );
    match &summary.status {
        RunStatus::Completed => Reported::Completed,
        RunStatus::Interrupted => {
            let end = target
                .end_time
                .map_or(String::new(), |t| format!(" --end-time {t}"));
            let only = if several {
                format!(" --only {}", summary.case)
            } else {
                String::new()
            };
            println!(
                "{}: interrupted at t = {} s with a checkpoint; continue with:\n  \
                 runout run {}{only} --fidelity {}{end} --restart {}",
                summary.case,
                summary.simulated_time,
                file.display(),
                target.fidelity,
                dir.display()
            );
            Reported::Interrupted
        }
        RunStatus::Diverged { diagnosis } => {
            eprintln!("{}: diverged: {diagnosis}", summary.case);
            Reported::Failed
        }
        RunStatus::Failed { reason } => {
            eprintln!("{}: failed: {reason}", summary.case);
            Reported::Failed
        }
        RunStatus::Running => Reported::Failed,
    }
}

fn main() -> ExitCode {
    tracing_subscriber::fmt()
        .with_env_filter(
            tracing_subscriber::EnvFilter::try_from_env("RUNOUT_LOG")
                .unwrap_or_else(|_| "warn".into()),
        )
        .with_writer(std::io::stderr)
        .init();
    let cli = Cli::parse();
    match cli.command {
        Command::Check {
            paths,
            explain,
            fidelity,
        } => check(&paths, explain.then_some(fidelity)),
        Command::Mesh { file, fidelity } => mesh(&file, fidelity),
        Command::Run {
            file,
            fidelity,
            out,
            quiet,
            end_time,
            only,
            restart,
            overwrite,
            ignore_memory,
            checkpoint_every,
        } => {
            let (out, restart) = match restart {
                Some(Some(dir)) => (Some(dir), true),
                Some(None) => (out, true),
                None => (out, false),
            };
            let options = RunOptions {
                restart,
                replace: overwrite,
                checkpoint_every: checkpoint_every
                    .map(|m| std::time::Duration::from_secs_f64(60.0 * m)),
                stop: Some(signals::stop_on_signals(
                    "runout",
                    "stopping after this step with a checkpoint",
                )),
            };
            let target = Target {
                only: only.as_deref(),
                fidelity,
                out: out.as_deref(),
                end_time,
                ignore_memory,
            };
            run(&file, &target, quiet, &options)
        }
        Command::Closures(args) => match cmd_closures::run(&args) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("runout closures: {e:#}");
                ExitCode::FAILURE
            }
        },
        Command::PorePressure(args) => exit_code("pore-pressure", cmd_pore_pressure::run(&args)),
        Command::Post {
            run_dir,
            gates,
            deposit_profile,
            rest_fraction,
            min_cells,
            basal_load,
        } => post(
            &run_dir,
            gates.as_deref(),
            (deposit_profile.as_deref(), basal_load.as_deref()),
            (rest_fraction, min_cells),
        ),
        Command::Wall(args) => match cmd_wall::run(&args) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("runout wall: {e:#}");
                ExitCode::FAILURE
            }
        },
        Command::Sweep(args) => exit_code("sweep", cmd_study::sweep(&args)),
        Command::Calibrate(args) => exit_code("calibrate", cmd_study::calibrate(&args)),
        Command::Sensitivity(args) => exit_code("sensitivity", cmd_study::sensitivity(&args)),
        Command::GridError(args) => exit_code("grid-error", cmd_grid_error::grid_error(&args)),
    }
}

/// Success, or the error printed after the command's name and failure.
fn exit_code(command: &str, result: anyhow::Result<()>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("runout {command}: {e:#}");
            ExitCode::FAILURE
        }
    }
}
