//! `runout sweep`, `runout calibrate` and `runout sensitivity`: studies of many runs on the
//! user's own cases, by the study engine ([`runout_study`]), below a folder of the user's
//! (`--out`, default the current folder): `runs/<case>/<fidelity>/`,
//! `runs/calibrate/<study>/` and `results/`.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use runout_case::Fidelity;
use runout_study::sweep::{matrix, parse_shard, SweepOptions};

use crate::parse_fidelity;

/// The program's name in the messages that say how to continue.
const PROGRAM: &str = "runout";

/// `runout sweep`.
#[derive(clap::Args, Debug, Clone)]
pub struct SweepArgs {
    /// a case file, a sweep file or a folder of them (every `.ron` below it; a sweep's
    /// `base.ron` is a template, not a run)
    pub path: PathBuf,
    /// smoke, coarse, wall (the paper's cells in y, x coarsened) or paper
    #[arg(long, default_value = "coarse", value_parser = parse_fidelity)]
    pub fidelity: Fidelity,
    /// parallel runs, each on a share of the cores (default: the number of cores)
    #[arg(long)]
    pub jobs: Option<usize>,
    /// run only shard i of n (1-based), e.g. `--shard 2/4`, for a cluster job array
    #[arg(long)]
    pub shard: Option<String>,
    /// run only the cases whose name contains this
    #[arg(long, value_name = "PATTERN")]
    pub only: Option<String>,
    /// the folder that gets `runs/` and `results/summary.csv`
    #[arg(long, value_name = "DIR", default_value = ".")]
    pub out: PathBuf,
    /// described or measured gate speeds (CSV `gate,x,speed`) for the summary's
    /// `mse_vs_described` column
    #[arg(long, value_name = "CSV")]
    pub gates: Option<PathBuf>,
    /// list the cases and run nothing
    #[arg(long)]
    pub list: bool,
}

/// Expands PATH and runs its cases below `--out`: finished runs are skipped, a killed
/// sweep continues from its checkpoints, the rows are merged into results/summary.csv.
pub fn sweep(args: &SweepArgs) -> Result<()> {
    let cases = matrix(&args.path)?;
    if cases.runs.is_empty() && cases.analytic.is_empty() {
        anyhow::bail!("{}: no case or sweep file", args.path.display());
    }
    let opts = SweepOptions {
        fidelity: args.fidelity,
        only: args.only.clone(),
        jobs: args
            .jobs
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get())),
        shard: args.shard.as_deref().map(parse_shard).transpose()?,
        list: args.list,
        gates: args.gates.clone(),
        program: PROGRAM,
    };
    create_dir(&args.out)?;
    runout_study::sweep::sweep(&args.out, &cases, &opts)
}

/// `runout calibrate` (docs/reference/calibrate.md).
#[derive(clap::Args, Debug, Clone)]
pub struct CalibrateArgs {
    /// the case or sweep file
    pub case_file: PathBuf,
    /// PATH=LO:HI[:START][:log] (one or two): a field path such as
    /// `boundaries.south.solids.specularity`, or a bare field name such as `specularity`
    /// for every field of that name
    #[arg(long = "param", required = true)]
    pub params: Vec<String>,
    /// the measurements CSV (header gate,speed_m_s | t,x | y,<profile column>)
    #[arg(long)]
    pub measurements: PathBuf,
    /// the case of a sweep file
    #[arg(long)]
    pub case: Option<String>,
    /// smoke, coarse, wall or paper
    #[arg(long, default_value = "coarse", value_parser = parse_fidelity)]
    pub fidelity: Fidelity,
    /// landscape scan points per parameter (N, or N × N in 2-D)
    #[arg(long, default_value_t = 5)]
    pub scan: usize,
    /// at most this many refinement runs (Brent or Nelder–Mead)
    #[arg(long, default_value_t = 6)]
    pub refine: usize,
    /// parallel runs in the scan
    #[arg(long, default_value_t = 1)]
    pub jobs: usize,
    /// the measurement error σ of every point, in the measurement's unit (overrides the
    /// file's `sigma` column or `# sigma:` line)
    #[arg(long)]
    pub sigma: Option<f64>,
    /// Brent's and the range edges' absolute tolerance, as a fraction of the bounds (or log
    /// bounds)
    #[arg(long, default_value_t = 0.002)]
    pub xtol: f64,
    /// Nelder–Mead (2-D) stops when the standard deviation of its simplex's χ² is below this
    #[arg(long, default_value_t = 0.05)]
    pub ftol: f64,
    /// at most this many runs per side pinning the edges of the range Δχ² ≤ 1, then as many
    /// rounds of runs across the smooth response's range (1-D)
    #[arg(long, default_value_t = 2)]
    pub profile: usize,
    /// stations of the profile of χ² along the loosely constrained parameter (2-D; 0: none),
    /// up to 7 runs each: the range then follows a curved valley to its ends
    #[arg(long, default_value_t = 5)]
    pub valley: usize,
    /// study name: the folder under runs/calibrate/ (default: the case name)
    #[arg(long)]
    pub name: Option<String>,
    /// the folder that gets `runs/calibrate/<study>/`
    #[arg(long, value_name = "DIR", default_value = ".")]
    pub out: PathBuf,
    /// check the input and print the plan; run nothing
    #[arg(long)]
    pub dry_run: bool,
}

/// Fits the parameters to the measurements: a landscape scan, then Brent (1-D) or
/// Nelder–Mead (2-D); every evaluation is a run, reused when the command is run again.
pub fn calibrate(args: &CalibrateArgs) -> Result<()> {
    create_dir(&args.out)?;
    runout_study::calibrate::run(
        &args.out,
        &runout_study::calibrate::Options {
            case_file: args.case_file.clone(),
            case: args.case.clone(),
            params: args.params.clone(),
            measurements: args.measurements.clone(),
            fidelity: args.fidelity,
            scan: args.scan,
            refine: args.refine,
            jobs: args.jobs,
            sigma: args.sigma,
            xtol: args.xtol,
            ftol: args.ftol,
            profile: args.profile,
            valley: args.valley,
            name: args.name.clone(),
            dry_run: args.dry_run,
            program: PROGRAM,
        },
    )
}

/// `runout sensitivity`.
#[derive(clap::Args, Debug, Clone)]
pub struct SensitivityArgs {
    /// the sweep file, or a folder of them, that the sweep ran (its one-factor families)
    pub path: PathBuf,
    /// the rows of this fidelity
    #[arg(long, default_value = "coarse", value_parser = parse_fidelity)]
    pub fidelity: Fidelity,
    /// the folder of the sweep: reads `results/summary.csv` and the runs' `bulk.csv`,
    /// writes `results/elasticities.csv`
    #[arg(long, value_name = "DIR", default_value = ".")]
    pub out: PathBuf,
}

/// Prints the elasticity of every numeric column of the summary (and of the front and mean
/// u_s at each run's end) over every one-factor
/// family of the sweeps under PATH, and writes every pair with its points to
/// results/elasticities.csv.
pub fn sensitivity(args: &SensitivityArgs) -> Result<()> {
    use runout_study::elasticities::{add_bulk_outputs, compute, csv, read_rows, table};
    let cases = matrix(&args.path)?;
    let results = args.out.join("results");
    let mut rows = read_rows(&results.join("summary.csv"), args.fidelity)?;
    add_bulk_outputs(&mut rows, &args.out.join("runs"), args.fidelity);
    let all = compute(&cases, &args.path, &rows)?;
    if all.is_empty() {
        anyhow::bail!(
            "{}: no sweep varies a numeric parameter over two values or more",
            args.path.display()
        );
    }
    println!(
        "elasticities ∂ln y/∂ln p at fidelity `{}` ({} famil{}; the least-squares slope over a \
         family's points, `(arc)` where p ≤ 0, — without a value: see the note in the CSV)\n",
        args.fidelity,
        all.len(),
        if all.len() == 1 { "y" } else { "ies" }
    );
    println!("{}", table(&rows.columns, &all));
    let file = results.join("elasticities.csv");
    std::fs::write(&file, csv(&rows.columns, &all))
        .with_context(|| format!("writing {}", file.display()))?;
    println!("every pair with its points and notes: {}", file.display());
    Ok(())
}

/// Creates the output folder (and its parents) if needed.
fn create_dir(dir: &Path) -> Result<()> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))
}
