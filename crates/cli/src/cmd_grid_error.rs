//! `runout grid-error CASE`: the grid error of where a case's flow stops (issue 57 item 3).
//! The case is run on `--levels` grids, each twice as coarse as the one before in both
//! directions from the finest (the case's own grid coarsened `--finest` times), into
//! `--out/<case>-x<factor>/`; a level whose folder already holds a completed run is read,
//! not run again. From the three finest levels' deposits the runout L∞, the maximum
//! thickness H∞ and the deposit's centre get their observed order, Richardson value and
//! Roache's GCI ([`runout_post::grid_error`]), printed and written to
//! `--out/<case>-grid-error.json`.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

use anyhow::{bail, Context, Result};
use runout_case::{load, Case, Fidelity, Loaded};
use runout_output::RunStatus;
use runout_post::deposit::{read_deposit, DEFAULT_REST_FRACTION};
use runout_post::grid_error::{deposit_errors, Level};

/// `runout grid-error`.
#[derive(clap::Args, Debug, Clone)]
pub struct GridErrorArgs {
    /// a case file (one case)
    pub file: PathBuf,
    /// how many grids, 3 or more, each twice as coarse as the one before
    #[arg(long, default_value_t = 3)]
    pub levels: usize,
    /// the finest grid: the case's own coarsened this many times (1: the case as written)
    #[arg(long, default_value_t = 1)]
    pub finest: u32,
    /// every level's end time instead of the case's [s]
    #[arg(long)]
    pub end_time: Option<f64>,
    /// the folder of the levels' run folders
    #[arg(long, value_name = "DIR", default_value = "runs/grid-error")]
    pub out: PathBuf,
    /// parallel runs, each on a share of the cores (default: the number of cores)
    #[arg(long)]
    pub jobs: Option<usize>,
}

/// The levels' cases: the case coarsened by `finest` · 2^l in x and y, l = 0 (finest) up.
fn level_cases(case: &Case, args: &GridErrorArgs) -> Result<Vec<(u32, Case)>> {
    if args.levels < 3 {
        bail!("--levels {}: a grid error needs 3 or more", args.levels);
    }
    if args.finest == 0 {
        bail!("--finest 0: allowed 1 or more");
    }
    (0..args.levels)
        .map(|l| {
            let factor = args.finest * 2u32.pow(l as u32);
            let mut c = case.clone();
            c.name = format!("{}-x{factor}", case.name);
            c.domain.x = case.domain.x.coarsened(factor);
            c.domain.y = case.domain.y.coarsened(factor);
            if let Some(end) = args.end_time {
                c.run.end_time = end;
            }
            runout_case::validate_case(&c).map_err(|errors| {
                let fields: Vec<String> = errors.iter().map(|e| e.to_string()).collect();
                anyhow::anyhow!("level coarsened {factor}×: {}", fields.join("; "))
            })?;
            Ok((factor, c))
        })
        .collect()
}

/// Whether `dir` holds a completed run.
fn completed(dir: &Path) -> bool {
    matches!(
        runout_post::folder::read_summary(dir),
        Some(Ok(s)) if s.status == RunStatus::Completed
    )
}

/// Runs the levels, reads their deposits and prints the grid error.
pub fn grid_error(args: &GridErrorArgs) -> Result<()> {
    let case = match load(&args.file).map_err(|e| anyhow::anyhow!("{e}"))? {
        Loaded::Cases(cases) if cases.len() == 1 => cases[0].case.clone(),
        Loaded::Cases(cases) => bail!(
            "{}: {} cases; grid-error takes a file of one case",
            args.file.display(),
            cases.len()
        ),
        Loaded::Analytic(_) => bail!("{}: an analytic family has no grid", args.file.display()),
    };
    let levels = level_cases(&case, args)?;
    let jobs = args
        .jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let failures = Mutex::new(Vec::new());
    runout_study::jobs::run_queue(
        levels.iter(),
        jobs,
        || true,
        |(factor, c)| {
            let dir = args.out.join(&c.name);
            if completed(&dir) {
                println!("{}: completed run found in {}", c.name, dir.display());
                return;
            }
            let grid = c.grid().map(|g| format!("{} × {}", g.nx(), g.ny()));
            println!(
                "{} ({}, coarsened {factor}×): running into {}",
                c.name,
                grid.unwrap_or_default(),
                dir.display()
            );
            if let Err(e) = runout_run::run_case(c, Fidelity::Paper, &dir, |_| {}) {
                failures
                    .lock()
                    .expect("no poisoned lock")
                    .push(format!("{}: {e}", c.name));
            }
        },
    )?;
    let failures = failures.into_inner().expect("no poisoned lock");
    if !failures.is_empty() {
        bail!("runs failed: {}", failures.join("; "));
    }
    let mut ladder = Vec::new();
    for (factor, c) in &levels {
        let dir = args.out.join(&c.name);
        let resolved = c.at_fidelity(Fidelity::Paper);
        let (deposit, _) = read_deposit(&dir, &resolved, DEFAULT_REST_FRACTION)
            .map_err(|e| anyhow::anyhow!("{}: {e}", dir.display()))?;
        println!(
            "  coarsened {factor}×: {} at t = {:.3} s; L∞ {:.4} m, H∞ {:.4} m ({} cells), centre {:.4} m{}",
            if deposit.at_rest { "at rest" } else { "NOT at rest" },
            deposit.time,
            deposit.runout_grain,
            deposit.max_thickness,
            deposit.max_thickness_cells,
            deposit.centre_x,
            deposit.thin.map_or(String::new(), |t| format!(
                "; {}",
                t.message(deposit.max_thickness_cells)
            ))
        );
        ladder.push(Level {
            spacing: f64::from(*factor),
            deposit,
        });
    }
    let errors = deposit_errors(&ladder, &case.numerics.convection).map_err(anyhow::Error::msg)?;
    println!("grid error of {} from its three finest levels:", case.name);
    for e in &errors {
        println!("  {}", e.line());
    }
    let json = serde_json::json!({
        "case": case.name,
        "spacings": ladder.iter().map(|l| l.spacing).collect::<Vec<_>>(),
        "at_rest": ladder.iter().map(|l| l.deposit.at_rest).collect::<Vec<_>>(),
        "quantities": errors.iter().map(|e| {
            let c = &e.convergence;
            serde_json::json!({
                "name": e.name,
                "unit": e.unit,
                "values": e.values,
                "observed_order": c.observed_order,
                "asymptotic": c.asymptotic,
                "order_used": c.gci_order,
                "safety_factor": c.safety_factor,
                "richardson": c.extrapolated,
                "gci_fine": c.gci_fine_absolute,
                "gci_fine_relative": c.gci_fine,
            })
        }).collect::<Vec<_>>(),
    });
    let path = args.out.join(format!("{}-grid-error.json", case.name));
    std::fs::create_dir_all(&args.out).with_context(|| args.out.display().to_string())?;
    std::fs::write(&path, serde_json::to_string_pretty(&json)?)
        .with_context(|| path.display().to_string())?;
    println!("wrote {}", path.display());
    Ok(())
}
