//! One collapse run: run (or with `--reuse` read) a column into `runs/<case>/<fidelity>/`
//! through the run store (`runout_run::store`)
//! and measure it (front metrics, the dense deposit's runout, the deposit's and the dilute
//! fringe's θ).

use std::path::Path;

use anyhow::{Context, Result};
use runout_case::{Case, Fidelity};
use runout_output::{RunStatus, RunSummary};
use runout_run::store::{self, finished_run, Request, Reuse, Stored};

use super::column::{is_mu_i, Column};
use super::fields::{last_fields, median};
use super::front::{front_metrics, read_bulk, FrontMetrics};
use runout_post::deposit::{
    distal_edge, grain_edge, profile, DepositColumn, DENSE_EPS_S, GRAIN_EDGE_DIAMETERS,
};

/// One collapse run and what it says.
pub(super) struct Outcome {
    pub(super) name: String,
    /// the friction law is μ(I) (the check's thresholds judge only these columns)
    pub(super) mu_i: bool,
    pub(super) column: Column,
    /// a of the column as the grid holds it: initial solids mass / (ρs εs0 L0²)
    pub(super) a_gridded: f64,
    pub(super) cells: (usize, usize),
    pub(super) front: FrontMetrics,
    /// runout of the dense deposit (floor εs ≥ 0.3) in the last field file
    pub(super) dense_runout: f64,
    /// runout to the grain edge (solids height Σ εs Δy ≥ d, `runout_post::deposit`) in the
    /// last field file: the check's runout
    pub(super) grain_runout: f64,
    /// H∞/L0: the largest dense (εs ≥ 0.3) thickness of the last field file over L0
    pub(super) height: f64,
    /// the deposit profile of the last field file (`runout_post::deposit::profile`)
    pub(super) deposit: Vec<DepositColumn>,
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
    let done = root.join("runs").join(&case.name).join(fidelity.name());
    let request = Request {
        reuse: if reuse { Reuse::SameCase } else { Reuse::Never },
        checkpoint_every: Some(store::CHECKPOINT_EVERY),
        ..Request::default()
    };
    if !reuse || finished_run(&done, &resolved).is_none() {
        println!(
            "{}: a = {}, {} × {} cells, to t = {} s ...",
            case.name,
            column.aspect(),
            grid.nx(),
            grid.ny(),
            resolved.run.end_time
        );
    }
    let stored = store::obtain(&done, case, fidelity, &request, |p| {
        if p.steps % 250 == 0 {
            eprintln!(
                "  t = {:.3} s, dt = {:.1e} s, {} it",
                p.time, p.dt, p.iterations
            );
        }
    })
    .with_context(|| format!("running {}", case.name))?;
    if let Stored::Reused(_) = stored {
        println!(
            "{}: reusing the finished run in {}",
            case.name,
            done.display()
        );
    }
    measure(case, fidelity, &done, stored.summary().clone())
}

/// The finished run of `case` at `fidelity` in runs/<case>/<fidelity>/, measured, if the
/// store holds one of the same resolved case (nothing is run).
pub(super) fn finished(root: &Path, case: &Case, fidelity: Fidelity) -> Result<Option<Outcome>> {
    let done = root.join("runs").join(&case.name).join(fidelity.name());
    match finished_run(&done, &case.at_fidelity(fidelity)) {
        Some(summary) => measure(case, fidelity, &done, summary).map(Some),
        None => Ok(None),
    }
}

/// Measures the finished run of `case` at `fidelity` in `done`.
fn measure(case: &Case, fidelity: Fidelity, done: &Path, summary: RunSummary) -> Result<Outcome> {
    let column = Column::of(case)?;
    let resolved = case.at_fidelity(fidelity);
    let grid = resolved.grid()?;
    let rows = read_bulk(&done.join("bulk.csv"))?;
    let front = front_metrics(&rows, &column, grid.x.end());
    let (eps, theta) = last_fields(done)?;
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
    let deposit = profile(&eps, grid.x.faces(), grid.y.faces());
    let grain_runout = column.runout(grain_edge(
        &deposit,
        grid.x.faces(),
        GRAIN_EDGE_DIAMETERS * solids.diameter,
    ));
    let height = deposit
        .iter()
        .map(|c| c.thickness_dense)
        .fold(0.0, f64::max)
        / column.l0;
    Ok(Outcome {
        name: case.name.clone(),
        mu_i: is_mu_i(case),
        grain_runout,
        height,
        deposit,
        column,
        a_gridded,
        cells: (grid.nx(), grid.ny()),
        front,
        dense_runout: column.runout(distal_edge(&eps[..grid.nx()], grid.x.faces(), DENSE_EPS_S)),
        deposit_theta,
        fringe_theta,
        diameter: solids.diameter,
        end_time: resolved.run.end_time,
        summary,
    })
}
