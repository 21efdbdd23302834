//! Running a case file: the time loop with MFIX's adaptive time step (model-spec §4.12),
//! output of fields and monitors, and the run summary.
//!
//! Today this drives the single-phase core; a case with solids phases is refused with a
//! clear message until the two-fluid model (issue 7) exists.

use std::path::{Path, PathBuf};
use std::time::Instant;

use runout_case::{
    Boundary, Case, Convection, Fidelity, FrictionModel, GasWall, Gravity, InitialPressure,
    KineticTheory, OutletPressure, SolidsWall,
};
use runout_mesh::{Grid, Sides};
use runout_output::{CellField, CsvSeries, DtStats, OutputError, PvdSeries, RunStatus, RunSummary};
use runout_walls::{RobinFace, SolidsWallModel};

use runout_closures::{ClosureParams, FrictionParams, Gas, Particles};

use crate::single_phase::{Fluid, Settings, SideBc, SinglePhase, SolverError};
use crate::transport::Scheme;
use crate::two_fluid::{SolidsSpec, TwoFluid, TwoFluidSettings};

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

/// The adaptive time-step controller of MFIX (model-spec §4.12): after every block of
/// `steps_per_change` converged steps (MFIX `STEPS_MIN` = 5) it compares the outer iterations per simulated second with the previous block and
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
    steps_per_change: usize,
    failure_factor: f64,
    cost_old: f64,
}

impl DtController {
    /// Starts at `initial`, bounded by [min, max], changing by `factor` (MFIX `DT_FAC`) after
    /// every `steps_per_change` converged steps (MFIX `STEPS_MIN` = 5; at least 1). A failed
    /// step multiplies Δt by `factor` (MFIX) or by [`DtController::with_failure_factor`]'s.
    pub fn new(initial: f64, min: f64, max: f64, factor: f64, steps_per_change: usize) -> Self {
        DtController {
            failure_factor: factor,
            dt: initial,
            min,
            max,
            factor,
            direction: -1.0,
            iterations: 0,
            steps: 0,
            steps_per_change: steps_per_change.max(1),
            cost_old: 0.0,
        }
    }

    /// The controller with `failure_factor` instead of `factor` after a failed step.
    pub fn with_failure_factor(mut self, failure_factor: f64) -> Self {
        self.failure_factor = failure_factor;
        self
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
        if self.steps < self.steps_per_change {
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
        self.dt *= self.failure_factor.min(0.999_999);
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

/// The gas condition of a boundary: the wall's closure of the tangential velocity, or the
/// outlet's (hydrostatic) pressure.
fn outlet_bc(b: &Boundary, gas: &runout_case::Gas) -> SideBc {
    match b {
        Boundary::Wall { gas: wall, .. } => SideBc::Wall(wall_closure(wall)),
        Boundary::PressureOutlet {
            pressure: OutletPressure::Uniform(p),
        } => SideBc::Outlet(*p),
        Boundary::PressureOutlet {
            pressure: OutletPressure::Hydrostatic(p0),
        } => SideBc::HydrostaticOutlet {
            p0: *p0,
            density: gas.density,
        },
    }
}

/// The gas conditions of the four sides of a case.
fn gas_sides(case: &Case, gas: &runout_case::Gas) -> Sides<SideBc> {
    let b = &case.boundaries;
    Sides {
        west: outlet_bc(&b.west, gas),
        east: outlet_bc(&b.east, gas),
        south: outlet_bc(&b.south, gas),
        north: outlet_bc(&b.north, gas),
    }
}

/// Initial gas pressure of cell centre (x, y): hydrostatic from the top-left corner,
/// p = p_ref + ρ_g g·(r − r_top-left), or the case's uniform value.
fn initial_gas_pressure(
    case: &Case,
    gas: &runout_case::Gas,
    gravity: (f64, f64),
    grid: &Grid,
    x: f64,
    y: f64,
) -> f64 {
    match case.initial.gas_pressure {
        InitialPressure::Hydrostatic => {
            gas.reference_pressure
                + gas.density * (gravity.0 * (x - grid.x.start()) + gravity.1 * (y - grid.y.end()))
        }
        InitialPressure::Uniform(p) => p,
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
    let b = &case.boundaries;
    let bcs = gas_sides(case, gas);
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
    for j in 0..g.ny() {
        for i in 0..g.nx() {
            let (x, y) = g.cell_centre(i, j);
            s.p[g.cell_index(i, j)] = initial_gas_pressure(case, gas, gravity, &g, x, y);
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

/// What one time step of a case solver reports to the time loop.
struct StepReport {
    converged: bool,
    iterations: usize,
    residual: f64,
    /// the residual breakdown (and locations where known), for a diagnosis
    detail: String,
}

/// The time loop's view of a solver: single phase or two-fluid.
trait CaseSolver {
    fn step(&mut self, dt: f64, run: &runout_case::RunControl) -> Result<StepReport, RunError>;
    /// Gravity schedules act here, before each step.
    fn before_step(&mut self) {}
    fn write_fields(&mut self, series: &mut PvdSeries, time: f64) -> Result<(), OutputError>;
    fn profile_header(&self) -> &'static [&'static str];
    fn profile(&self, x: f64, y: f64) -> Vec<f64>;
    fn grid(&self) -> &Grid;
    /// Net continuity imbalance relative to the flow through the domain (0 if no flow).
    fn mass_imbalance_ratio(&self) -> f64;
    /// Total solids mass per unit depth [kg m⁻¹] (0 for a single phase).
    fn solids_mass(&self) -> f64 {
        0.0
    }
    /// Largest solids volume fraction of any phase in any cell (0 for a single phase).
    fn max_eps_s(&self) -> f64 {
        0.0
    }
    /// (front x, εs-weighted mean solids u) for the bulk monitor, `None` without solids.
    fn bulk(&self, _threshold: f64) -> Option<(f64, f64)> {
        None
    }
    /// The front interpolated within its cell, for the front tracker; `None` without solids.
    fn interpolated_front(&self, _threshold: f64) -> Option<f64> {
        None
    }
    /// Wall time per part of the iteration, if the solver keeps it.
    fn time_profile(&self) -> Vec<(String, f64)> {
        Vec::new()
    }
    /// h_w^u of the floor's velocity node nearest to `x` (the wall probe of paper Fig. 9),
    /// `None` where the floor has no state-dependent wall model.
    fn floor_h_u(&self, _x: f64) -> Option<f64> {
        None
    }
}

struct SinglePhaseCase {
    solver: SinglePhase,
    velocity: Vec<f64>,
}

impl CaseSolver for SinglePhaseCase {
    fn step(&mut self, dt: f64, run: &runout_case::RunControl) -> Result<StepReport, RunError> {
        let t = &run.tolerances;
        let out = self
            .solver
            .step(dt, t.residual, t.diverge, t.max_iterations as usize)
            .map_err(|source| RunError::Solver {
                case: String::new(),
                source,
            })?;
        let places: Vec<String> = self
            .solver
            .locate_residual(&out.last)
            .iter()
            .map(|(eq, r, x, y)| format!("{eq} {r:.3e} (largest at x = {x:.4} m, y = {y:.4} m)"))
            .collect();
        let history: Vec<String> = out
            .history
            .iter()
            .filter(|h| !h.is_nan())
            .map(|h| format!("{h:.3e}"))
            .collect();
        Ok(StepReport {
            converged: out.converged,
            iterations: out.iterations,
            residual: out.residual,
            detail: format!(
                "{}; residual history {}",
                places.join(", "),
                history.join(" ")
            ),
        })
    }

    fn write_fields(&mut self, series: &mut PvdSeries, time: f64) -> Result<(), OutputError> {
        self.solver.centre_velocities(&mut self.velocity);
        series.push(
            self.solver.grid(),
            time,
            &[
                CellField::vector("u_g", &self.velocity),
                CellField::scalar("p_g", &self.solver.p),
            ],
        )?;
        Ok(())
    }

    fn profile_header(&self) -> &'static [&'static str] {
        &["y", "u_g", "v_g"]
    }

    fn profile(&self, x: f64, y: f64) -> Vec<f64> {
        vec![y, self.solver.u_at(x, y), self.solver.v_at(x, y)]
    }

    fn grid(&self) -> &Grid {
        self.solver.grid()
    }

    fn mass_imbalance_ratio(&self) -> f64 {
        let g = self.solver.grid();
        let flow: f64 =
            self.solver.u.iter().map(|u| u.abs()).sum::<f64>() * g.y.length() / g.ny() as f64;
        if flow > 0.0 {
            self.solver.mass_imbalance() / flow
        } else {
            0.0
        }
    }
}

/// A two-fluid case: the solver, the gravity schedule and output scratch.
struct TwoFluidCase {
    solver: TwoFluid,
    /// (magnitude, slope in degrees, contact εs) of a tilt-on-impact schedule not yet tilted
    tilt: Option<(f64, f64, f64)>,
    scratch: Vec<f64>,
    scratch2: Vec<f64>,
}

impl TwoFluidCase {
    /// Cell-centred (u, v) of face fields, interleaved.
    fn centre(grid: &Grid, u: &[f64], v: &[f64], out: &mut [f64]) {
        let (nx, ny) = (grid.nx(), grid.ny());
        for j in 0..ny {
            for i in 0..nx {
                let k = i + nx * j;
                out[2 * k] = 0.5 * (u[i + (nx + 1) * j] + u[i + 1 + (nx + 1) * j]);
                out[2 * k + 1] = 0.5 * (v[k] + v[k + nx]);
            }
        }
    }
}

impl CaseSolver for TwoFluidCase {
    fn step(&mut self, dt: f64, run: &runout_case::RunControl) -> Result<StepReport, RunError> {
        let t = &run.tolerances;
        let out = self
            .solver
            .step(
                dt,
                t.residual,
                t.theta_residual,
                t.diverge,
                t.max_iterations as usize,
            )
            .map_err(|e| RunError::Unsupported {
                case: String::new(),
                reason: format!("two-fluid step failed: {e}"),
            })?;
        let r = out.last;
        Ok(StepReport {
            converged: out.converged,
            iterations: out.iterations,
            residual: out.residual,
            // only a failed step's detail is read (its diagnosis)
            detail: if out.converged {
                String::new()
            } else {
                format!(
                    "momentum {:.3e}, gas continuity {:.3e}, solids continuity {:.3e}, granular energy {:.3e}; {}{}",
                    r.momentum,
                    r.gas_mass,
                    r.solids_mass,
                    r.theta,
                    self.solver.residual_locations(),
                    out.failure.map_or(String::new(), |f| format!("; the last try stopped on: {f}"))
                )
            },
        })
    }

    fn before_step(&mut self) {
        if let Some((magnitude, slope, contact)) = self.tilt {
            let nx = self.solver.grid().nx();
            // impact: solids first reach a floor cell (cases.md, paper Fig. 3)
            if self
                .solver
                .solids
                .iter()
                .any(|s| s.eps[..nx].iter().any(|&e| e >= contact))
            {
                self.solver.set_gravity(gravity_vector(magnitude, slope));
                self.tilt = None;
            }
        }
    }

    fn write_fields(&mut self, series: &mut PvdSeries, time: f64) -> Result<(), OutputError> {
        let grid = self.solver.grid().clone();
        let s = &self.solver.solids[0];
        Self::centre(&grid, &self.solver.u_g, &self.solver.v_g, &mut self.scratch);
        Self::centre(&grid, &s.u, &s.v, &mut self.scratch2);
        series.push(
            &grid,
            time,
            &[
                CellField::scalar("eps_s", &s.eps),
                CellField::vector("u_s", &self.scratch2),
                CellField::scalar("theta", &s.theta),
                CellField::scalar("p_s", &s.p_s),
                CellField::vector("u_g", &self.scratch),
                CellField::scalar("p_g", &self.solver.p_g),
            ],
        )?;
        Ok(())
    }

    fn profile_header(&self) -> &'static [&'static str] {
        &["y", "eps_s", "u_s", "theta"]
    }

    fn profile(&self, x: f64, y: f64) -> Vec<f64> {
        let g = self.solver.grid();
        let nx = g.nx();
        let (i, j) = g.locate(x, y).unwrap_or((0, 0));
        let s = &self.solver.solids[0];
        let k = i + nx * j;
        let u = 0.5 * (s.u[i + (nx + 1) * j] + s.u[i + 1 + (nx + 1) * j]);
        vec![y, s.eps[k], u, s.theta[k]]
    }

    fn grid(&self) -> &Grid {
        self.solver.grid()
    }

    fn mass_imbalance_ratio(&self) -> f64 {
        0.0
    }

    fn solids_mass(&self) -> f64 {
        (0..self.solver.solids.len())
            .map(|m| self.solver.solids_mass(m))
            .sum()
    }

    fn time_profile(&self) -> Vec<(String, f64)> {
        self.solver
            .profile()
            .parts()
            .iter()
            .map(|(name, t)| (name.to_string(), *t))
            .collect()
    }
    fn max_eps_s(&self) -> f64 {
        self.solver
            .solids
            .iter()
            .flat_map(|s| s.eps.iter())
            .fold(0.0, |a: f64, &e| a.max(e))
    }

    fn floor_h_u(&self, x: f64) -> Option<f64> {
        let faces = self.solver.grid().x.faces();
        let k = (0..faces.len())
            .min_by(|&a, &b| (faces[a] - x).abs().total_cmp(&(faces[b] - x).abs()))?;
        self.solver
            .has_floor_model(0)
            .then(|| self.solver.solids[0].floor_h_u[k])
    }

    /// The front for the gate speeds: where εs of the floor row falls through `threshold`
    /// beyond its last cell i at or above it, interpolated linearly between the centres of
    /// cells i and i + 1 (the east face at the last cell). Unlike the whole-cell front of
    /// the bulk monitor it moves continuously, so speeds from it are not quantised in steps
    /// of Δx per sampling interval.
    fn interpolated_front(&self, threshold: f64) -> Option<f64> {
        let g = self.solver.grid();
        let nx = g.nx();
        let (xc, eps) = (g.x.centres(), &self.solver.solids[0].eps);
        let front = (0..nx)
            .rev()
            .find(|&i| eps[i] >= threshold)
            .map_or(g.x.start(), |i| {
                if i + 1 == nx {
                    g.x.faces()[nx]
                } else {
                    let (e0, e1) = (eps[i], eps[i + 1]);
                    xc[i] + (e0 - threshold) / (e0 - e1) * (xc[i + 1] - xc[i])
                }
            });
        Some(front)
    }

    fn bulk(&self, threshold: f64) -> Option<(f64, f64)> {
        let g = self.solver.grid();
        let (nx, ny) = (g.nx(), g.ny());
        let s = &self.solver.solids[0];
        // front: the largest x whose floor cell has εs ≥ threshold (cases.md family F)
        let front = (0..nx)
            .rev()
            .find(|&i| s.eps[i] >= threshold)
            .map_or(g.x.start(), |i| g.x.faces()[i + 1]);
        let (mut num, mut den) = (0.0, 0.0);
        for j in 0..ny {
            for i in 0..nx {
                let k = i + nx * j;
                let w = s.eps[k] * g.cell_volume(i, j);
                num += w * 0.5 * (s.u[i + (nx + 1) * j] + s.u[i + 1 + (nx + 1) * j]);
                den += w;
            }
        }
        Some((front, if den > 0.0 { num / den } else { 0.0 }))
    }
}

/// Builds the two-fluid solver of a case with solids, or says what it still lacks.
pub fn two_fluid_solver(case: &Case) -> Result<TwoFluid, RunError> {
    let unsupported = |reason: String| RunError::Unsupported {
        case: case.name.clone(),
        reason,
    };
    let gas = case.gas.as_ref().ok_or_else(|| {
        unsupported("a dry case (no gas) is not supported by the two-fluid solver yet".into())
    })?;
    if !matches!(case.models.kinetic_theory, KineticTheory::Lun1984 { .. }) {
        return Err(unsupported(
            "only the Lun 1984 kinetic theory with the θ PDE is implemented".into(),
        ));
    }
    // one phase only: MFIX's P* of several phases uses the mixture εg and εs/Σε_cp weights
    // (model-spec §2.4.1, §4.4), not implemented
    if case.models.friction == FrictionModel::Schaeffer && case.solids.len() > 1 {
        return Err(unsupported(
            "Schaeffer friction with more than one solids phase is not implemented".into(),
        ));
    }
    let grid = case.grid().map_err(|source| RunError::Mesh {
        case: case.name.clone(),
        source,
    })?;
    let b = &case.boundaries;
    let gas_walls = gas_sides(case, gas);
    // (tangential closure, θ closure, state-dependent model) of each side for the solids
    type SolidsSide = (SideBc, Option<RobinFace>, Option<SolidsWallModel>);
    let solids_side = |b: &Boundary| -> Result<SolidsSide, RunError> {
        let model_err = |e: runout_walls::WallError| unsupported(format!("wall model: {e}"));
        // placeholders that the per-face closures of a state-dependent model replace
        let by_model = |m: SolidsWallModel| {
            (
                SideBc::Wall(RobinFace::ZERO_GRADIENT),
                Some(RobinFace::ZERO_GRADIENT),
                Some(m),
            )
        };
        Ok(match b {
            Boundary::PressureOutlet { .. } => (outlet_bc(b, gas), None, None),
            Boundary::Wall { solids, .. } => match solids {
                SolidsWall::NoSlip => (
                    SideBc::Wall(RobinFace::dirichlet(0.0)),
                    Some(RobinFace::ZERO_GRADIENT),
                    None,
                ),
                SolidsWall::FreeSlip => (
                    SideBc::Wall(RobinFace::ZERO_GRADIENT),
                    Some(RobinFace::ZERO_GRADIENT),
                    None,
                ),
                SolidsWall::PartialSlip {
                    h_u,
                    u_w,
                    h_theta,
                    theta_w,
                    c,
                } => (
                    SideBc::Wall(RobinFace::partial_slip(*h_u, *u_w)),
                    Some(RobinFace::user_theta(*h_theta, *theta_w, *c)),
                    None,
                ),
                SolidsWall::JohnsonJackson {
                    specularity,
                    wall_restitution,
                    wall_friction_angle,
                    u_w,
                } => by_model(
                    SolidsWallModel::johnson_jackson(
                        *specularity,
                        *wall_restitution,
                        *wall_friction_angle,
                        *u_w,
                    )
                    .map_err(model_err)?,
                ),
                SolidsWall::RevisitedJohnsonJackson {
                    wall_restitution,
                    wall_friction_angle,
                    phi0,
                    u_w,
                } => by_model(
                    SolidsWallModel::revisited_johnson_jackson(
                        *wall_restitution,
                        *wall_friction_angle,
                        *phi0,
                        *u_w,
                    )
                    .map_err(model_err)?,
                ),
                SolidsWall::Jenkins {
                    wall_restitution,
                    wall_friction_angle,
                    u_w,
                } => by_model(
                    SolidsWallModel::jenkins(*wall_restitution, *wall_friction_angle, *u_w)
                        .map_err(model_err)?,
                ),
            },
        })
    };
    let (w, e, s_, n) = (
        solids_side(&b.west)?,
        solids_side(&b.east)?,
        solids_side(&b.south)?,
        solids_side(&b.north)?,
    );
    let specs: Vec<SolidsSpec> = case
        .solids
        .iter()
        .map(|m| SolidsSpec {
            params: ClosureParams {
                particles: Particles {
                    diameter: m.diameter,
                    density: m.density,
                    restitution: m.restitution,
                },
                gas: Gas {
                    density: gas.density,
                    viscosity: gas.viscosity,
                },
                friction: FrictionParams::new(
                    m.max_packing,
                    m.friction_min_packing,
                    m.internal_friction_angle,
                ),
                radial: case.models.radial_distribution,
                friction_model: case.models.friction,
                drag: case.models.drag,
            },
            eps_max: m.max_packing,
            walls: Sides {
                west: w.0,
                east: e.0,
                south: s_.0,
                north: n.0,
            },
            theta_walls: Sides {
                west: w.1,
                east: e.1,
                south: s_.1,
                north: n.1,
            },
            wall_models: Sides {
                west: w.2,
                east: e.2,
                south: s_.2,
                north: n.2,
            },
        })
        .collect();
    let gravity = match case.gravity {
        Gravity::Constant { magnitude, slope } => gravity_vector(magnitude, slope),
        Gravity::TiltOnImpact { magnitude, .. } => gravity_vector(magnitude, 0.0),
    };
    let r = &case.numerics.relaxation;
    let settings = TwoFluidSettings {
        scheme: match case.numerics.convection {
            Convection::Upwind => Scheme::Upwind,
            Convection::Superbee => Scheme::Superbee,
        },
        relax_velocity: r.velocity,
        relax_pressure: r.pressure,
        relax_eps: r.eps_s,
        relax_theta: r.theta,
        relax_wall_closures: r.wall_closures,
        relax_wall_closures_oscillating_only: r.wall_closures_at
            == runout_case::WallRelaxationScope::Oscillating,
        freeze_cycling_dilute_class: case.numerics.dilute_cells
            == runout_case::DiluteCellClass::FrozenWhenCycling,
        periodic_x: false,
        exact_solids_continuity: case.numerics.exact_solids_mass,
        detect_stall: case.run.tolerances.detect_stall,
    };
    let fluid = Fluid {
        density: gas.density,
        viscosity: gas.viscosity,
    };
    let mut tf = TwoFluid::new(grid.clone(), fluid, gas_walls, specs, gravity, settings)
        .map_err(|e| unsupported(format!("setting up the two-fluid solver: {e}")))?;
    // initial state: gas, background θ, then the blocks in order
    let (nx, ny) = (grid.nx(), grid.ny());
    let (u0, v0) = case.initial.gas_velocity;
    tf.u_g.iter_mut().for_each(|u| *u = u0);
    tf.v_g.iter_mut().for_each(|v| *v = v0);
    for s in tf.solids.iter_mut() {
        s.theta
            .iter_mut()
            .for_each(|t| *t = case.initial.theta.max(runout_closures::guards::THETA_SMALL));
    }
    for j in 0..ny {
        for i in 0..nx {
            let (x, y) = grid.cell_centre(i, j);
            let k = i + nx * j;
            tf.p_g[k] = initial_gas_pressure(case, gas, gravity, &grid, x, y);
            for block in &case.initial.regions {
                if x >= block.x.0 && x <= block.x.1 && y >= block.y.0 && y <= block.y.1 {
                    for (s, bs) in tf.solids.iter_mut().zip(&block.solids) {
                        s.eps[k] = bs.eps_s;
                        s.theta[k] = bs.theta.max(runout_closures::guards::THETA_SMALL);
                        for f in [i + (nx + 1) * j, i + 1 + (nx + 1) * j] {
                            s.u[f] = bs.velocity.0;
                        }
                        for f in [k, k + nx] {
                            s.v[f] = bs.velocity.1;
                        }
                    }
                }
            }
        }
    }
    // walls: zero normal velocity of every phase
    for (side, is_wall) in [
        (0usize, matches!(b.west, Boundary::Wall { .. })),
        (nx, matches!(b.east, Boundary::Wall { .. })),
    ] {
        if is_wall {
            for j in 0..ny {
                tf.u_g[side + (nx + 1) * j] = 0.0;
                tf.solids
                    .iter_mut()
                    .for_each(|s| s.u[side + (nx + 1) * j] = 0.0);
            }
        }
    }
    for (side, is_wall) in [
        (0usize, matches!(b.south, Boundary::Wall { .. })),
        (ny, matches!(b.north, Boundary::Wall { .. })),
    ] {
        if is_wall {
            for i in 0..nx {
                tf.v_g[i + nx * side] = 0.0;
                tf.solids.iter_mut().for_each(|s| s.v[i + nx * side] = 0.0);
            }
        }
    }
    tf.sync_volume_fractions();
    Ok(tf)
}

/// Runs `case` at `fidelity`, writing into `out_dir`: `fields.pvd` + `.vtr` files at every
/// output interval, `profile_x<x>_t<t>.csv` for each profile monitor, `bulk.csv` for a bulk
/// monitor (solids mass, front, mean u_s), `resolved.ron` (the case as run) and
/// `summary.json`. A step that does not converge is retried with a smaller Δt; below Δt_min
/// the run stops with a diagnosis in the summary and keeps what it wrote.
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
    let mut solver: Box<dyn CaseSolver> = if case.solids.is_empty() {
        let s = single_phase_solver(&case)?;
        let n = s.grid().cell_count();
        Box::new(SinglePhaseCase {
            solver: s,
            velocity: vec![0.0; 2 * n],
        })
    } else {
        let tf = two_fluid_solver(&case)?;
        let n = tf.grid().cell_count();
        let tilt = match case.gravity {
            Gravity::TiltOnImpact {
                magnitude,
                slope,
                contact_eps_s,
            } => Some((magnitude, slope, contact_eps_s)),
            Gravity::Constant { .. } => None,
        };
        Box::new(TwoFluidCase {
            solver: tf,
            tilt,
            scratch: vec![0.0; 2 * n],
            scratch2: vec![0.0; 2 * n],
        })
    };
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
    let grid: Grid = solver.grid().clone();
    let mut series = PvdSeries::new(out_dir.join("fields.pvd"));
    solver.write_fields(&mut series, 0.0).map_err(out_err)?;
    let mass0 = solver.solids_mass();
    let mut bulk = match &case.monitors.bulk {
        Some(b) if !case.solids.is_empty() => Some((
            CsvSeries::create(
                &out_dir.join("bulk.csv"),
                &["t", "solids_mass", "front_x", "mean_u_s"],
            )
            .map_err(out_err)?,
            b.interval,
            b.front_threshold,
            0.0,
        )),
        _ => None,
    };
    // wall probes (floor only in this version) and the front tracker
    let mut probes = Vec::new();
    for p in &case.monitors.wall_probes {
        if p.side == runout_mesh::Side::South && !case.solids.is_empty() {
            let path = out_dir.join(format!("wall_probe_south_x{}.csv", p.at));
            probes.push((
                CsvSeries::create(&path, &["t", "h_w_u"]).map_err(out_err)?,
                p.at,
                p.interval,
                0.0,
            ));
        }
    }
    let mut front = match &case.monitors.front {
        Some(f) if !case.solids.is_empty() => Some((
            CsvSeries::create(&out_dir.join("front.csv"), &["t", "front_x"]).map_err(out_err)?,
            f.clone(),
            0.0,
            Vec::<(f64, f64)>::new(),
        )),
        _ => None,
    };
    let run = &case.run;
    let mut dt = DtController::new(
        run.dt.initial,
        run.dt.min,
        run.dt.max,
        run.dt.factor,
        run.dt.steps_per_change,
    )
    .with_failure_factor(run.dt.failure_factor.unwrap_or(run.dt.factor));
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
        max_eps_s: solver.max_eps_s(),
        status: RunStatus::Running,
        profile: Vec::new(),
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
    let max_it = run.tolerances.max_iterations as usize;
    while time < end * (1.0 - 1e-12) {
        let step_dt = dt.dt().min(end - time);
        let shortened = step_dt < dt.dt();
        solver.before_step();
        let outcome = solver.step(step_dt, run).map_err(|e| match e {
            RunError::Solver { source, .. } => RunError::Solver {
                case: case.name.clone(),
                source,
            },
            RunError::Unsupported { reason, .. } => RunError::Unsupported {
                case: case.name.clone(),
                reason,
            },
            other => other,
        })?;
        tracing::debug!(
            time,
            dt = step_dt,
            iterations = outcome.iterations,
            converged = outcome.converged,
            residual = outcome.residual,
            detail = outcome.detail.as_str(),
            "step"
        );
        if !outcome.converged {
            summary.rejected_steps += 1;
            if !dt.failed() {
                summary.status = RunStatus::Diverged {
                    diagnosis: format!(
                        "the step from t = {time:.6e} s did not converge and dt fell below dt_min = {:.1e} s; \
                         last try: dt = {step_dt:.3e} s, {} outer iterations, residual sum {:.3e}: {}",
                        run.dt.min, outcome.iterations, outcome.residual, outcome.detail
                    ),
                };
                break;
            }
            continue;
        }
        time += step_dt;
        summary.steps += 1;
        summary.outer_iterations += outcome.iterations as u64;
        if !shortened {
            summary.dt.min = summary.dt.min.min(step_dt);
        }
        summary.dt.max = summary.dt.max.max(step_dt);
        summary.dt.mean += step_dt;
        summary.max_mass_imbalance = summary
            .max_mass_imbalance
            .max(solver.mass_imbalance_ratio());
        summary.max_eps_s = summary.max_eps_s.max(solver.max_eps_s());
        dt.converged(step_dt, outcome.iterations, outcome.iterations >= max_it);
        if time >= next_output * (1.0 - 1e-9) || time >= end * (1.0 - 1e-12) {
            solver.write_fields(&mut series, time).map_err(out_err)?;
            while next_output <= time * (1.0 + 1e-9) {
                next_output += run.output_interval;
            }
        }
        if let Some((csv, interval, threshold, next)) = bulk.as_mut() {
            if time >= *next * (1.0 - 1e-9) {
                if let Some((front, mean_u)) = solver.bulk(*threshold) {
                    csv.push(&[time, solver.solids_mass(), front, mean_u])
                        .map_err(out_err)?;
                }
                while *next <= time * (1.0 + 1e-9) {
                    *next += *interval;
                }
            }
        }
        for (csv, at, interval, next) in probes.iter_mut() {
            if time >= *next * (1.0 - 1e-9) {
                if let Some(h) = solver.floor_h_u(*at) {
                    csv.push(&[time, h]).map_err(out_err)?;
                }
                while *next <= time * (1.0 + 1e-9) {
                    *next += *interval;
                }
            }
        }
        if let Some((csv, tracker, next, series)) = front.as_mut() {
            if time >= *next * (1.0 - 1e-9) {
                if let Some(x) = solver.interpolated_front(tracker.threshold) {
                    csv.push(&[time, x]).map_err(out_err)?;
                    series.push((time, x));
                }
                while *next <= time * (1.0 + 1e-9) {
                    *next += tracker.interval;
                }
            }
        }
        for (x, times, next) in profiles.iter_mut() {
            while *next < times.len() && time >= times[*next] * (1.0 - 1e-9) {
                let path = out_dir.join(format!("profile_x{x}_t{}.csv", times[*next]));
                let mut csv = CsvSeries::create(&path, solver.profile_header()).map_err(out_err)?;
                for &y in grid.y.centres() {
                    csv.push(&solver.profile(*x, y)).map_err(out_err)?;
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
    if let Some((_, tracker, _, series)) = &front {
        write_gate_speeds(&out_dir.join("gates.csv"), tracker, series).map_err(out_err)?;
    }
    if summary.steps > 0 {
        summary.dt.mean /= summary.steps as f64;
    }
    if !summary.dt.min.is_finite() {
        // no accepted step, or only one shortened to the end time
        summary.dt.min = summary.dt.max;
    }
    if mass0 > 0.0 {
        summary.solids_mass_change = solver.solids_mass() / mass0 - 1.0;
    }
    summary.simulated_time = time;
    summary.wall_time = started.elapsed().as_secs_f64();
    summary.profile = solver.time_profile();
    if summary.status == RunStatus::Running {
        summary.status = RunStatus::Completed;
    }
    summary
        .write_json(&out_dir.join("summary.json"))
        .map_err(out_err)?;
    Ok(summary)
}

/// Front speed at each gate (cases.md family F): at the first sample whose front has passed
/// the gate, the slope of the front position over the two samples on either side (a
/// central difference over up to four sampling intervals). Gates the front never reached
/// get no speed.
fn write_gate_speeds(
    path: &Path,
    tracker: &runout_case::FrontTracker,
    series: &[(f64, f64)],
) -> Result<(), OutputError> {
    let mut csv = CsvSeries::create(path, &["gate", "x", "t_cross", "speed"])?;
    for (g, distance) in tracker.gates.iter().enumerate() {
        let x_gate = tracker.gate_origin + distance;
        let Some(k) = series.iter().position(|&(_, x)| x >= x_gate) else {
            continue;
        };
        let (lo, hi) = (k.saturating_sub(2), (k + 2).min(series.len() - 1));
        let speed = if series[hi].0 > series[lo].0 {
            (series[hi].1 - series[lo].1) / (series[hi].0 - series[lo].0)
        } else {
            f64::NAN
        };
        if speed.is_finite() {
            csv.push(&[(g + 1) as f64, x_gate, series[k].0, speed])?;
        }
    }
    Ok(())
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
        let mut c = DtController::new(1e-3, 1e-6, 1e-2, 0.9, 5);
        // first block of 5: cost > 0 = old → direction flips from − to +: Δt grows
        for _ in 0..5 {
            c.converged(1e-3, 10, false);
        }
        assert!((c.dt() - 1e-3 / 0.9).abs() < 1e-15);
        // a failure shrinks Δt and resets the direction
        assert!(c.failed());
        assert!((c.dt() - 1e-3).abs() < 1e-15);
        let mut c = DtController::new(2e-6, 1e-6, 1e-2, 0.5, 5);
        assert!(c.failed());
        assert!(!c.failed(), "below dt_min the run must stop");
    }

    #[test]
    fn dt_controller_changes_after_every_block_of_steps_per_change() {
        // one step per change: Δt grows at every converged step while the iterations per
        // simulated second fall (same iterations at a larger Δt)
        let mut c = DtController::new(1e-4, 1e-6, 1e-3, 0.9, 1);
        for n in 1..=10 {
            c.converged(c.dt(), 8, false);
            assert!((c.dt() - 1e-4 / 0.9_f64.powi(n)).abs() < 1e-15, "step {n}");
        }
        // a step that costs more per simulated second turns the direction: Δt shrinks
        let before = c.dt();
        c.converged(before, 40, false);
        assert!((c.dt() - before * 0.9).abs() < 1e-15);
        // at the cap it stays
        let mut c = DtController::new(1e-3, 1e-6, 1e-3, 0.9, 1);
        c.converged(1e-3, 8, false);
        assert_eq!(c.dt(), 1e-3);
        // a failure factor of its own
        let mut c = DtController::new(1e-3, 1e-6, 1e-3, 0.9, 5).with_failure_factor(0.5);
        assert!(c.failed());
        assert!((c.dt() - 5e-4).abs() < 1e-15);
    }
}
