//! Running a case file: the time loop with MFIX's adaptive time step (model-spec §4.12),
//! output of fields and monitors, and the run summary.
//!
//! Today this drives the single-phase core; a case with solids phases is refused with a
//! clear message until the two-fluid model (issue 7) exists.

use std::path::{Path, PathBuf};
use std::time::Instant;

use runout_case::{
    Boundary, Case, Convection, Fidelity, GasWall, Gravity, InitialPressure, OutletPressure,
};
use runout_mesh::{Grid, Sides};
use runout_output::{CellField, CsvSeries, DtStats, OutputError, PvdSeries, RunStatus, RunSummary};
use runout_walls::RobinFace;

use crate::single_phase::{Fluid, Settings, SideBc, SinglePhase, SolverError};
use crate::transport::Scheme;

/// Why a case cannot run or stopped.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The case needs physics this solver does not have yet.
    #[error("case `{case}`: {reason}")]
    Unsupported {
        /// case name
        case: String,
        /// what is missing
        reason: String,
    },
    /// The grid could not be built.
    #[error("case `{case}`: grid: {source}")]
    Mesh {
        /// case name
        case: String,
        /// the mesh error
        source: runout_mesh::MeshError,
    },
    /// The solver failed outright (not a retryable non-convergence).
    #[error("case `{case}`: {source}")]
    Solver {
        /// case name
        case: String,
        /// the solver error
        source: SolverError,
    },
    /// Writing output failed.
    #[error("case `{case}`: output: {source}")]
    Output {
        /// case name
        case: String,
        /// the output error
        source: OutputError,
    },
}

/// Progress of a running case, for progress bars.
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    /// simulated time [s]
    pub time: f64,
    /// end time [s]
    pub end_time: f64,
    /// current Δt [s]
    pub dt: f64,
    /// outer iterations of the last step
    pub iterations: usize,
    /// accepted steps so far
    pub steps: u64,
}

/// The adaptive time-step controller of MFIX (model-spec §4.12): after every 5 converged
/// steps it compares the outer iterations per simulated second with the previous block and
/// keeps or reverses the direction of change; a failed step shrinks Δt and resets.
#[derive(Clone, Debug)]
pub struct DtController {
    dt: f64,
    min: f64,
    max: f64,
    factor: f64,
    direction: f64,
    iterations: usize,
    steps: usize,
    cost_old: f64,
}

/// Converged steps per adaptation (MFIX `STEPS_MIN`).
const STEPS_PER_ADAPTATION: usize = 5;

impl DtController {
    /// Starts at `initial`, bounded by [min, max], changing by `factor` (MFIX `DT_FAC`).
    pub fn new(initial: f64, min: f64, max: f64, factor: f64) -> Self {
        DtController {
            dt: initial,
            min,
            max,
            factor,
            direction: -1.0,
            iterations: 0,
            steps: 0,
            cost_old: 0.0,
        }
    }

    /// The Δt to try next [s].
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Records a converged step of `dt` that took `iterations` outer iterations (`hit_cap`:
    /// the iteration limit was reached).
    pub fn converged(&mut self, dt: f64, iterations: usize, hit_cap: bool) {
        if self.factor >= 1.0 {
            return;
        }
        self.iterations += iterations;
        self.steps += 1;
        if self.steps < STEPS_PER_ADAPTATION {
            return;
        }
        let cost = self.iterations as f64 / (self.steps as f64 * dt);
        if cost > self.cost_old {
            self.direction = -self.direction;
        }
        if self.direction > 0.0 {
            if !hit_cap {
                self.dt = (self.dt / self.factor).min(self.max);
            }
        } else {
            self.dt *= self.factor;
        }
        self.iterations = 0;
        self.steps = 0;
        self.cost_old = cost;
    }

    /// Records a failed step; returns `false` if Δt fell below the minimum (the run stops).
    pub fn failed(&mut self) -> bool {
        self.direction = -1.0;
        self.iterations = 0;
        self.steps = 0;
        self.cost_old = 0.0;
        self.dt *= self.factor.min(0.999_999);
        self.dt >= self.min
    }
}

fn wall_closure(gas: &GasWall) -> RobinFace {
    match *gas {
        GasWall::NoSlip => RobinFace::dirichlet(0.0),
        GasWall::FreeSlip => RobinFace::ZERO_GRADIENT,
        GasWall::Moving { u_w } => RobinFace::dirichlet(u_w),
        GasWall::PartialSlip { h_u, u_w } => RobinFace::partial_slip(h_u, u_w),
    }
}

/// Gravity vector of a slope α: g = (g sin α, −g cos α) (architecture.md conventions).
fn gravity_vector(magnitude: f64, slope_deg: f64) -> (f64, f64) {
    let a = slope_deg.to_radians();
    (magnitude * a.sin(), -magnitude * a.cos())
}

/// Builds the single-phase solver of a gas-only case, or says why it cannot.
pub fn single_phase_solver(case: &Case) -> Result<SinglePhase, RunError> {
    let unsupported = |reason: &str| RunError::Unsupported {
        case: case.name.clone(),
        reason: reason.into(),
    };
    if !case.solids.is_empty() {
        return Err(unsupported(
            "has solids phases: the two-fluid model is not implemented yet (issue 7); only \
             single-phase gas cases run today",
        ));
    }
    let gas = case
        .gas
        .as_ref()
        .ok_or_else(|| unsupported("has neither gas nor solids"))?;
    let gravity = match case.gravity {
        Gravity::Constant { magnitude, slope } => gravity_vector(magnitude, slope),
        Gravity::TiltOnImpact { .. } => {
            return Err(unsupported(
                "tilts gravity on solids impact, which needs a solids phase",
            ));
        }
    };
    let grid = case.grid().map_err(|source| RunError::Mesh {
        case: case.name.clone(),
        source,
    })?;
    let side = |b: &Boundary| match b {
        Boundary::Wall { gas, .. } => SideBc::Wall(wall_closure(gas)),
        Boundary::PressureOutlet {
            pressure: OutletPressure::Uniform(p),
        } => SideBc::Outlet(*p),
        Boundary::PressureOutlet {
            pressure: OutletPressure::Hydrostatic(p0),
        } => SideBc::HydrostaticOutlet {
            p0: *p0,
            density: gas.density,
        },
    };
    let b = &case.boundaries;
    let bcs = Sides {
        west: side(&b.west),
        east: side(&b.east),
        south: side(&b.south),
        north: side(&b.north),
    };
    let r = &case.numerics.relaxation;
    let settings = Settings {
        scheme: match case.numerics.convection {
            Convection::Upwind => Scheme::Upwind,
            Convection::Superbee => Scheme::Superbee,
        },
        relax_velocity: r.velocity,
        relax_pressure: r.pressure,
        ..Settings::default()
    };
    let fluid = Fluid {
        density: gas.density,
        viscosity: gas.viscosity,
    };
    let mut s = SinglePhase::new(grid, fluid, bcs, gravity, settings).map_err(|source| {
        RunError::Solver {
            case: case.name.clone(),
            source,
        }
    })?;
    // Initial state: uniform gas velocity; hydrostatic or uniform pressure.
    let (u0, v0) = case.initial.gas_velocity;
    s.u.iter_mut().for_each(|u| *u = u0);
    s.v.iter_mut().for_each(|v| *v = v0);
    let g = s.grid().clone();
    let (x0, y1) = (g.x.start(), g.y.end());
    for j in 0..g.ny() {
        for i in 0..g.nx() {
            let (x, y) = g.cell_centre(i, j);
            s.p[g.cell_index(i, j)] = match case.initial.gas_pressure {
                // p = p_ref + ρ g·(r − r_top-left), the column under the top-left corner
                InitialPressure::Hydrostatic => {
                    gas.reference_pressure
                        + gas.density * (gravity.0 * (x - x0) + gravity.1 * (y - y1))
                }
                InitialPressure::Uniform(p) => p,
            };
        }
    }
    // Walls: zero normal velocity on the wall faces.
    let (nx, ny) = (g.nx(), g.ny());
    for j in 0..ny {
        for (i, side) in [(0, &b.west), (nx, &b.east)] {
            if matches!(side, Boundary::Wall { .. }) {
                s.u[i + (nx + 1) * j] = 0.0;
            }
        }
    }
    for i in 0..nx {
        for (j, side) in [(0, &b.south), (ny, &b.north)] {
            if matches!(side, Boundary::Wall { .. }) {
                s.v[i + nx * j] = 0.0;
            }
        }
    }
    Ok(s)
}

/// Writes the current fields as one time level of the series.
fn write_fields(
    series: &mut PvdSeries,
    s: &SinglePhase,
    time: f64,
    velocity: &mut [f64],
) -> Result<(), OutputError> {
    s.centre_velocities(velocity);
    series.push(
        s.grid(),
        time,
        &[
            CellField::vector("u_g", velocity),
            CellField::scalar("p_g", &s.p),
        ],
    )?;
    Ok(())
}

/// Runs `case` at `fidelity`, writing into `out_dir`: `fields.pvd` + `.vtr` files at every
/// output interval, `profile_x<x>_t<t>.csv` for each profile monitor, `resolved.ron` (the
/// case as run) and `summary.json`. A step that does not converge is retried with a smaller
/// Δt; below Δt_min the run stops with a diagnosis in the summary and keeps what it wrote.
pub fn run_case(
    case: &Case,
    fidelity: Fidelity,
    out_dir: &Path,
    mut progress: impl FnMut(&Progress),
) -> Result<RunSummary, RunError> {
    let case = case.at_fidelity(fidelity);
    let name = case.name.clone();
    let out_err = |source| RunError::Output {
        case: name.clone(),
        source,
    };
    let mut s = single_phase_solver(&case)?;
    std::fs::create_dir_all(out_dir).map_err(|e| {
        out_err(OutputError::Io {
            path: out_dir.to_path_buf(),
            source: e,
        })
    })?;
    let resolved = ron::ser::to_string_pretty(&case, ron::ser::PrettyConfig::default())
        .expect("a case serialises");
    runout_output::write_atomic(&out_dir.join("resolved.ron"), resolved.as_bytes())
        .map_err(out_err)?;

    let started = Instant::now();
    let grid: Grid = s.grid().clone();
    let mut velocity = vec![0.0; 2 * grid.cell_count()];
    let mut series = PvdSeries::new(out_dir.join("fields.pvd"));
    write_fields(&mut series, &s, 0.0, &mut velocity).map_err(out_err)?;
    let run = &case.run;
    let mut dt = DtController::new(run.dt.initial, run.dt.min, run.dt.max, run.dt.factor);
    let mut summary = RunSummary {
        case: case.name.clone(),
        fidelity: fidelity.to_string(),
        cells: (grid.nx(), grid.ny()),
        simulated_time: 0.0,
        wall_time: 0.0,
        steps: 0,
        rejected_steps: 0,
        outer_iterations: 0,
        dt: DtStats {
            min: f64::INFINITY,
            max: 0.0,
            mean: 0.0,
        },
        solids_mass_change: 0.0,
        max_mass_imbalance: 0.0,
        status: RunStatus::Running,
    };
    let mut profiles: Vec<(f64, Vec<f64>, usize)> = case
        .monitors
        .profiles
        .iter()
        .map(|p| (p.x, p.times.clone(), 0))
        .collect();
    let mut next_output = run.output_interval;
    let mut time = 0.0;
    let end = run.end_time;
    let tol = run.tolerances.residual;
    let max_it = run.tolerances.max_iterations as usize;
    while time < end * (1.0 - 1e-12) {
        let step_dt = dt.dt().min(end - time);
        let outcome = s
            .step(step_dt, tol, run.tolerances.diverge, max_it)
            .map_err(|source| RunError::Solver {
                case: case.name.clone(),
                source,
            })?;
        if !outcome.converged {
            summary.rejected_steps += 1;
            if !dt.failed() {
                let places: Vec<String> = s
                    .locate_residual(&outcome.last)
                    .iter()
                    .map(|(eq, r, x, y)| {
                        format!("{eq} {r:.3e} (largest at x = {x:.4} m, y = {y:.4} m)")
                    })
                    .collect();
                let history: Vec<String> = outcome
                    .history
                    .iter()
                    .filter(|h| !h.is_nan())
                    .map(|h| format!("{h:.3e}"))
                    .collect();
                summary.status = RunStatus::Diverged {
                    diagnosis: format!(
                        "the step from t = {time:.6e} s did not converge and dt fell below dt_min = {:.1e} s; \
                         last try: dt = {step_dt:.3e} s, {} outer iterations, residual sum {:.3e}: {}; \
                         residual history {}",
                        run.dt.min,
                        outcome.iterations,
                        outcome.residual,
                        places.join(", "),
                        history.join(" ")
                    ),
                };
                break;
            }
            continue;
        }
        time += step_dt;
        summary.steps += 1;
        summary.outer_iterations += outcome.iterations as u64;
        summary.dt.min = summary.dt.min.min(step_dt);
        summary.dt.max = summary.dt.max.max(step_dt);
        summary.dt.mean += step_dt;
        let flow: f64 =
            s.u.iter().map(|u| u.abs()).sum::<f64>() * grid.y.length() / grid.ny() as f64;
        if flow > 0.0 {
            summary.max_mass_imbalance = summary.max_mass_imbalance.max(s.mass_imbalance() / flow);
        }
        dt.converged(step_dt, outcome.iterations, outcome.iterations >= max_it);
        if time >= next_output * (1.0 - 1e-9) || time >= end * (1.0 - 1e-12) {
            write_fields(&mut series, &s, time, &mut velocity).map_err(out_err)?;
            while next_output <= time * (1.0 + 1e-9) {
                next_output += run.output_interval;
            }
        }
        for (x, times, next) in profiles.iter_mut() {
            while *next < times.len() && time >= times[*next] * (1.0 - 1e-9) {
                let path = out_dir.join(format!("profile_x{x}_t{}.csv", times[*next]));
                let mut csv = CsvSeries::create(&path, &["y", "u_g", "v_g"]).map_err(out_err)?;
                for &y in grid.y.centres() {
                    csv.push(&[y, s.u_at(*x, y), s.v_at(*x, y)])
                        .map_err(out_err)?;
                }
                *next += 1;
            }
        }
        progress(&Progress {
            time,
            end_time: end,
            dt: dt.dt(),
            iterations: outcome.iterations,
            steps: summary.steps,
        });
    }
    if summary.steps > 0 {
        summary.dt.mean /= summary.steps as f64;
    } else {
        summary.dt.min = 0.0;
    }
    summary.simulated_time = time;
    summary.wall_time = started.elapsed().as_secs_f64();
    if summary.status == RunStatus::Running {
        summary.status = RunStatus::Completed;
    }
    summary
        .write_json(&out_dir.join("summary.json"))
        .map_err(out_err)?;
    Ok(summary)
}

/// The default output folder of a case: `runs/<case>/<fidelity>`.
pub fn default_out_dir(root: &Path, case: &str, fidelity: Fidelity) -> PathBuf {
    root.join("runs").join(case).join(fidelity.name())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dt_controller_follows_mfix_rules() {
        let mut c = DtController::new(1e-3, 1e-6, 1e-2, 0.9);
        // first block of 5: cost > 0 = old → direction flips from − to +: Δt grows
        for _ in 0..5 {
            c.converged(1e-3, 10, false);
        }
        assert!((c.dt() - 1e-3 / 0.9).abs() < 1e-15);
        // a failure shrinks Δt and resets the direction
        assert!(c.failed());
        assert!((c.dt() - 1e-3).abs() < 1e-15);
        let mut c = DtController::new(2e-6, 1e-6, 1e-2, 0.5);
        assert!(c.failed());
        assert!(!c.failed(), "below dt_min the run must stop");
    }
}
