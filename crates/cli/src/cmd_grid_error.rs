//! `runout grid-error CASE`: the grid error of where a case's flow stops (issue 57 item 3).
//! The case (or, of a sweep file, the one `--only` names) is run on `--levels` grids, each
//! twice as coarse as the one before from the finest (the case's own grid coarsened
//! `--finest` times), into `--out/<case>-x<factor>/`: in both directions, or with
//! `--refine y` in y alone, x then coarsened `--coarsen-x` times on every level
//! (`--out/<case>-x<cx>y<factor>/`), which measures the error of the cells across a thin
//! deposit apart from the along-flow spacing's. A level whose folder already holds a
//! completed run is read, not run again. From the three finest levels' deposits the runout
//! L∞, the maximum thickness H∞ and the deposit's centre get their observed order,
//! Richardson value and Roache's GCI ([`runout_post::grid_error`]), printed and written to
//! `--out/<case>-grid-error.json` (`-grid-error-y.json` with `--refine y`).

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
    /// the case of this name, of a sweep file's cases
    #[arg(long, value_name = "NAME")]
    pub only: Option<String>,
    /// the directions refined from level to level: both, or y alone (across the flow)
    #[arg(long, value_enum, default_value_t = Refine::Xy)]
    pub refine: Refine,
    /// with `--refine y`: x coarsened this many times on every level [default: `--finest`]
    #[arg(long, value_name = "N")]
    pub coarsen_x: Option<u32>,
}

/// The directions a grid-error ladder refines.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Refine {
    /// x and y, each level twice as fine in both
    Xy,
    /// y alone, x the same on every level
    Y,
}

impl Refine {
    /// How a level's grid differs from the case's, for messages.
    fn coarsened(self) -> &'static str {
        match self {
            Refine::Xy => "coarsened",
            Refine::Y => "y coarsened",
        }
    }
}

/// The levels' cases: the case coarsened by `finest` · 2^l in y, and in x too or by
/// `coarsen_x` on every level (`--refine`), l = 0 (finest) up.
fn level_cases(case: &Case, args: &GridErrorArgs) -> Result<Vec<(u32, Case)>> {
    if args.levels < 3 {
        bail!("--levels {}: a grid error needs 3 or more", args.levels);
    }
    if args.finest == 0 {
        bail!("--finest 0: allowed 1 or more");
    }
    let coarsen_x = match (args.refine, args.coarsen_x) {
        (Refine::Xy, Some(n)) => bail!("--coarsen-x {n}: only with --refine y"),
        (_, Some(0)) => bail!("--coarsen-x 0: allowed 1 or more"),
        (Refine::Y, n) => Some(n.unwrap_or(args.finest)),
        (Refine::Xy, None) => None,
    };
    (0..args.levels)
        .map(|l| {
            let factor = args.finest * 2u32.pow(l as u32);
            let mut c = case.clone();
            c.name = match coarsen_x {
                None => format!("{}-x{factor}", case.name),
                Some(cx) => format!("{}-x{cx}y{factor}", case.name),
            };
            c.domain.x = case.domain.x.coarsened(coarsen_x.unwrap_or(factor));
            c.domain.y = case.domain.y.coarsened(factor);
            if let Some(end) = args.end_time {
                c.run.end_time = end;
            }
            runout_case::validate_case(&c).map_err(|errors| {
                let fields: Vec<String> = errors.iter().map(|e| e.to_string()).collect();
                anyhow::anyhow!("level {}: {}", c.name, fields.join("; "))
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
        Loaded::Cases(cases) => match &args.only {
            Some(name) => match cases.iter().find(|c| &c.case.name == name) {
                Some(c) => c.case.clone(),
                None => bail!(
                    "{}: --only {name}: no such case (it has: {})",
                    args.file.display(),
                    cases
                        .iter()
                        .map(|c| c.case.name.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            },
            None if cases.len() == 1 => cases[0].case.clone(),
            None => bail!(
                "{}: {} cases; name one with --only",
                args.file.display(),
                cases.len()
            ),
        },
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
                "{} ({}, {} {factor}×): running into {}",
                c.name,
                grid.unwrap_or_default(),
                args.refine.coarsened(),
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
            "  {} {factor}×: {} at t = {:.3} s; L∞ {:.4} m, H∞ {:.4} m ({} cells), centre {:.4} m{}",
            args.refine.coarsened(),
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
        "refine": match args.refine { Refine::Xy => "xy", Refine::Y => "y" },
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
    let path = match args.refine {
        Refine::Xy => args.out.join(format!("{}-grid-error.json", case.name)),
        Refine::Y => args.out.join(format!("{}-grid-error-y.json", case.name)),
    };
    std::fs::create_dir_all(&args.out).with_context(|| args.out.display().to_string())?;
    std::fs::write(&path, serde_json::to_string_pretty(&json)?)
        .with_context(|| path.display().to_string())?;
    println!("wrote {}", path.display());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(clap::Parser)]
    struct Cli {
        #[command(flatten)]
        args: GridErrorArgs,
    }

    fn args(words: &[&str]) -> GridErrorArgs {
        Cli::parse_from(std::iter::once("grid-error").chain(words.iter().copied())).args
    }

    fn column() -> Case {
        let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/collapse/CM-a1.ron");
        match load(&file).unwrap() {
            Loaded::Cases(cases) => cases[0].case.clone(),
            Loaded::Analytic(_) => unreachable!("a case file"),
        }
    }

    fn cells(c: &Case) -> (usize, usize) {
        let g = c.grid().unwrap();
        (g.nx(), g.ny())
    }

    #[test]
    fn a_ladder_in_y_keeps_x_and_halves_y() {
        let case = column();
        let (nx, ny) = cells(&case);
        let levels = level_cases(
            &case,
            &args(&["c.ron", "--refine", "y", "--coarsen-x", "2"]),
        )
        .unwrap();
        let got: Vec<(u32, String, (usize, usize))> = levels
            .iter()
            .map(|(f, c)| (*f, c.name.clone(), cells(c)))
            .collect();
        let name = |f: u32| format!("{}-x2y{f}", case.name);
        assert_eq!(
            got,
            vec![
                (1, name(1), (nx / 2, ny)),
                (2, name(2), (nx / 2, ny / 2)),
                (4, name(4), (nx / 2, ny / 4)),
            ]
        );
        // both directions, as before
        let xy = level_cases(&case, &args(&["c.ron", "--finest", "2"])).unwrap();
        assert_eq!(xy[1].1.name, format!("{}-x4", case.name));
        assert_eq!(cells(&xy[1].1), (nx / 4, ny / 4));
    }

    #[test]
    fn coarsen_x_goes_with_a_ladder_in_y_only() {
        let case = column();
        let err = level_cases(&case, &args(&["c.ron", "--coarsen-x", "2"])).unwrap_err();
        assert!(err.to_string().contains("only with --refine y"), "{err}");
        let err = level_cases(
            &case,
            &args(&["c.ron", "--refine", "y", "--coarsen-x", "0"]),
        )
        .unwrap_err();
        assert!(err.to_string().contains("allowed 1 or more"), "{err}");
    }
}
