//! One collapse run: run (or with `--reuse` read) a column into `runs/<case>/<fidelity>/`
//! and measure it (front metrics, the dense deposit's runout, the deposit's and the dilute
//! fringe's θ).

use std::path::Path;

use anyhow::{Context, Result};
use runout_case::{Case, Fidelity};
use runout_output::{RunStatus, RunSummary};
use runout_solver::run_case;

use super::column::Column;
use super::fields::{floor_front, last_fields, median};
use super::front::{front_metrics, read_bulk, FrontMetrics};
use crate::sweep::finished_run;

/// εs threshold of the dense-deposit front read from the last field file [-] (the bulk
/// monitor's front uses the case's threshold, 0.01).
const DENSE_FRONT_EPS_S: f64 = 0.3;

/// One collapse run and what it says.
pub(super) struct Outcome {
    pub(super) name: String,
    pub(super) column: Column,
    /// a of the column as the grid holds it: initial solids mass / (ρs εs0 L0²)
    pub(super) a_gridded: f64,
    pub(super) cells: (usize, usize),
    pub(super) front: FrontMetrics,
    /// runout of the dense deposit (floor εs ≥ 0.3) in the last field file
    pub(super) dense_runout: f64,
    /// median θ of the cells with εs ≥ εs,min at the end [m² s⁻²]
    pub(super) deposit_theta: f64,
    /// largest θ of the dilute fringe (10⁻⁴ ≤ εs < 10⁻²) at the end [m² s⁻²]
    pub(super) fringe_theta: f64,
    /// particle diameter [m]
    pub(super) diameter: f64,
    pub(super) end_time: f64,
    pub(super) summary: RunSummary,
}

impl Outcome {
    pub(super) fn completed(&self) -> bool {
        self.summary.status == RunStatus::Completed
    }
}

/// Runs `case` at `fidelity` into runs/<case>/<fidelity>/ (written as `.partial`, renamed
/// when done), or with `reuse` takes the finished run of the same resolved case, and
/// measures it.
pub(super) fn run_one(
    root: &Path,
    case: &Case,
    fidelity: Fidelity,
    reuse: bool,
) -> Result<Outcome> {
    let column = Column::of(case)?;
    let resolved = case.at_fidelity(fidelity);
    let grid = resolved.grid()?;
    let runs = root.join("runs").join(&case.name);
    let done = runs.join(fidelity.name());
    let partial = runs.join(format!("{}.partial", fidelity.name()));
    let previous = if reuse {
        finished_run(&done, &resolved)
    } else {
        None
    };
    let summary = if let Some(summary) = previous {
        println!(
            "{}: reusing the finished run in {}",
            case.name,
            done.display()
        );
        summary
    } else {
        let _ = std::fs::remove_dir_all(&partial);
        println!(
            "{}: a = {}, {} × {} cells, to t = {} s ...",
            case.name,
            column.aspect(),
            grid.nx(),
            grid.ny(),
            resolved.run.end_time
        );
        let summary = run_case(case, fidelity, &partial, |p| {
            if p.steps % 250 == 0 {
                eprintln!(
                    "  t = {:.3} s, dt = {:.1e} s, {} it",
                    p.time, p.dt, p.iterations
                );
            }
        })
        .with_context(|| format!("running {}", case.name))?;
        let _ = std::fs::remove_dir_all(&done);
        std::fs::rename(&partial, &done)
            .with_context(|| format!("renaming {} to {}", partial.display(), done.display()))?;
        summary
    };
    let rows = read_bulk(&done.join("bulk.csv"))?;
    let front = front_metrics(&rows, &column, grid.x.end());
    let (eps, theta) = last_fields(&done)?;
    let solids = case
        .solids
        .first()
        .context("a collapse case has one solids phase")?;
    let eps0 = case.initial.regions[0].solids[0].eps_s;
    let a_gridded = rows[0].mass / (solids.density * eps0 * column.l0 * column.l0);
    let deposit_theta = median(
        eps.iter()
            .zip(&theta)
            .filter(|(&e, _)| e >= solids.friction_min_packing)
            .map(|(_, &t)| t)
            .collect(),
    );
    let fringe_theta = eps
        .iter()
        .zip(&theta)
        .filter(|(&e, _)| (1e-4..1e-2).contains(&e))
        .map(|(_, &t)| t)
        .fold(0.0, f64::max);
    Ok(Outcome {
        name: case.name.clone(),
        column,
        a_gridded,
        cells: (grid.nx(), grid.ny()),
        front,
        dense_runout: column.runout(floor_front(&eps, grid.x.faces(), DENSE_FRONT_EPS_S)),
        deposit_theta,
        fringe_theta,
        diameter: solids.diameter,
        end_time: resolved.run.end_time,
        summary,
    })
}
