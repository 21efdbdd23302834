//! The time loop's view of a solver (single phase or two-fluid): one step, the fields and
//! monitors it writes, and its state for checkpoints.

use runout_case::{Case, Gravity, ImpactCriterion};
use runout_mesh::Grid;
use runout_output::{CellField, OutputError, PvdSeries};

use crate::build::{bent_floor, gravity_vector};
use crate::RunError;
use runout_solver::bent_floor::BentFloor;
use runout_solver::single_phase::SinglePhase;
use runout_solver::state::{SolverState, StateError};
use runout_solver::two_fluid::TwoFluid;

/// What one time step of a case solver reports to the time loop.
pub(super) struct StepReport {
    pub(super) converged: bool,
    pub(super) iterations: usize,
    pub(super) residual: f64,
    /// the residual breakdown (and locations where known), for a diagnosis
    pub(super) detail: String,
}

/// The time loop's view of a solver: single phase or two-fluid.
pub(super) trait CaseSolver {
    fn step(&mut self, dt: f64, run: &runout_case::RunControl) -> Result<StepReport, RunError>;
    /// Puts back the fields of the start of the step after a step that failed with an error.
    fn restore(&mut self);
    /// Gravity schedules act here, before the step from `time`; true when gravity changed.
    fn before_step(&mut self, _time: f64) -> bool {
        false
    }
    /// The time of the next scheduled change after `time` (a timed gravity tilt, a gate's
    /// opening), which the time loop lands a step on as on the end time; `None` when
    /// nothing is scheduled by time.
    fn next_event(&self, _time: f64) -> Option<f64> {
        None
    }
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
    /// Whether the release has yet to happen at `time` [s]: a tilt on impact still pending, a
    /// gate yet to open, a gas inlet yet to open or close. Solids held before it are not at
    /// rest (`run.stop_at_rest`).
    fn release_pending(&self, _time: f64) -> bool {
        false
    }
    /// The front interpolated within its cell, for the front tracker; `None` without solids.
    fn interpolated_front(&self, _threshold: f64) -> Option<f64> {
        None
    }
    /// Wall time per part of the iteration, if the solver keeps it.
    fn time_profile(&self) -> Vec<(String, f64)> {
        Vec::new()
    }
    /// Linear-solver iterations per equation, if the solver counts them.
    fn linear_iterations(&self) -> Vec<(String, u64)> {
        Vec::new()
    }
    /// h_w^u of the floor's velocity node nearest to `x` (the wall probe of paper Fig. 9),
    /// `None` where the floor has no state-dependent wall model.
    fn floor_h_u(&self, _x: f64) -> Option<f64> {
        None
    }
    /// The state the next step reads, for a checkpoint.
    fn save_state(&self) -> SolverState;
    /// Puts back a state of [`CaseSolver::save_state`].
    fn load_state(&mut self, state: &SolverState) -> Result<(), StateError>;
}

pub(super) struct SinglePhaseCase {
    pub(super) solver: SinglePhase,
    pub(super) velocity: Vec<f64>,
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

    fn save_state(&self) -> SolverState {
        self.solver.save_state()
    }

    fn restore(&mut self) {
        self.solver.restore_step();
    }

    fn load_state(&mut self, state: &SolverState) -> Result<(), StateError> {
        self.solver.load_state(state)
    }
}

/// The state entry saying whether a tilt-on-impact schedule has not tilted yet.
const TILT_PENDING: &str = "tilt_pending";

/// What fires a tilt-on-impact schedule, resolved from its [`ImpactCriterion`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum ImpactTrigger {
    /// a floor cell of any phase with εs at or above this
    FloorEpsS(f64),
    /// the step starting at or after this time [s]
    Time(f64),
    /// the solids' centre of mass at or below this height [m]
    CentroidBelow(f64),
}

/// A tilt-on-impact schedule that has not tilted yet.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct PendingTilt {
    /// |g| [m s⁻²]
    pub(super) magnitude: f64,
    /// slope after the tilt [deg]
    pub(super) slope: f64,
    pub(super) trigger: ImpactTrigger,
    /// the bent floor that acts with the tilted gravity (docs/model.md §9), if any
    pub(super) floor: Option<BentFloor>,
}

impl PendingTilt {
    /// The schedule of a case, `None` for constant gravity. The thresholds and times are
    /// computed from the case (its initial regions), so a checkpoint needs only whether
    /// the tilt is still pending.
    pub(super) fn of(case: &Case) -> Option<PendingTilt> {
        let Gravity::TiltOnImpact {
            magnitude,
            slope,
            contact_eps_s,
            ref criterion,
            ..
        } = case.gravity
        else {
            return None;
        };
        let trigger = match *criterion {
            ImpactCriterion::FloorCell => ImpactTrigger::FloorEpsS(contact_eps_s),
            ImpactCriterion::DenseContact { fraction } => {
                ImpactTrigger::FloorEpsS(fraction * release_eps_s(case))
            }
            ImpactCriterion::CentroidDrop => {
                ImpactTrigger::CentroidBelow(release_centroid_y(case) - case.release_height())
            }
            // sqrt(2 h / g) or the given time (runout_case's clock.rs)
            ImpactCriterion::FreeFall | ImpactCriterion::At { .. } => {
                ImpactTrigger::Time(case.scheduled_tilt_time()?)
            }
        };
        Some(PendingTilt {
            magnitude,
            slope,
            trigger,
            // an invalid bend is refused when the solver is built (`two_fluid_solver`)
            floor: bent_floor(case).ok().flatten(),
        })
    }
}

/// The height of the centre of mass of all solids phases [m] (0 without solids).
fn solids_centroid_y(tf: &TwoFluid) -> f64 {
    let g = tf.grid();
    let nx = g.nx();
    let yc = g.y.centres();
    let (mut num, mut den) = (0.0, 0.0);
    for m in 0..tf.n_solids() {
        let rho = tf.solids_density(m);
        for (k, &e) in tf.solids(m).eps().iter().enumerate() {
            let (i, j) = (k % nx, k / nx);
            let m = rho * e * g.cell_volume(i, j);
            num += m * yc[j];
            den += m;
        }
    }
    if den > 0.0 {
        num / den
    } else {
        0.0
    }
}

/// The height of the centre of mass of the case's initial regions as written [m] (later
/// regions overwrite earlier ones where they overlap; the regions of the shipped cases do
/// not overlap, and this ignores overlaps).
fn release_centroid_y(case: &Case) -> f64 {
    let (mut num, mut den) = (0.0, 0.0);
    for b in &case.initial.regions {
        let density: f64 = b
            .solids
            .iter()
            .zip(&case.solids)
            .map(|(s, phase)| s.eps_s * phase.density)
            .sum();
        let m = density * (b.x.1 - b.x.0) * (b.y.1 - b.y.0);
        num += m * 0.5 * (b.y.0 + b.y.1);
        den += m;
    }
    if den > 0.0 {
        num / den
    } else {
        0.0
    }
}

/// The largest εs (summed over phases) of the case's initial regions.
fn release_eps_s(case: &Case) -> f64 {
    case.initial
        .regions
        .iter()
        .map(|b| b.solids.iter().map(|s| s.eps_s).sum::<f64>())
        .fold(0.0, f64::max)
}

/// Whether `time` has reached the scheduled time `t`, to within the rounding of a time
/// summed from steps (1e-12 relative): the step the loop lands on `t` may end an ulp short.
pub(super) fn at_or_after(time: f64, t: f64) -> bool {
    time >= t - 1e-12 * t.abs().max(1.0)
}

/// A two-fluid case: the solver, the gravity schedule and output scratch.
pub(super) struct TwoFluidCase {
    pub(super) solver: TwoFluid,
    /// a tilt-on-impact schedule not yet tilted
    pub(super) tilt: Option<PendingTilt>,
    /// the case's gates on the grid
    pub(super) gates: crate::gates::GateSchedule,
    /// the case's gas inlets on the grid
    pub(super) inlets: crate::gas_inlets::InletSchedule,
    /// when this process tilted gravity (logged; not in checkpoints)
    pub(super) tilted_at: Option<f64>,
    pub(super) scratch: Vec<f64>,
    pub(super) scratch2: Vec<f64>,
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

impl TwoFluidCase {
    /// Whether the impact has happened by the start of the step from `time` (paper Fig. 3,
    /// docs/studies/impact.md).
    fn impacted(&self, trigger: ImpactTrigger, time: f64) -> bool {
        match trigger {
            ImpactTrigger::FloorEpsS(eps) => {
                let nx = self.solver.grid().nx();
                self.solver
                    .state()
                    .phases()
                    .iter()
                    .any(|s| s.eps()[..nx].iter().any(|&e| e >= eps))
            }
            ImpactTrigger::Time(t) => at_or_after(time, t),
            ImpactTrigger::CentroidBelow(y) => solids_centroid_y(&self.solver) <= y,
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

    fn before_step(&mut self, time: f64) -> bool {
        if let Some(faces) = self.gates.faces_if_changed(time) {
            self.solver
                .set_gate_faces(faces)
                .expect("the schedule's faces fit its own grid");
        }
        if let Some(faces) = self.inlets.faces_if_changed(time) {
            self.solver
                .set_gas_inflow_faces(faces)
                .expect("validated inlets on wall sides of the schedule's own grid");
        }
        let Some(tilt) = self.tilt.clone() else {
            return false;
        };
        if !self.impacted(tilt.trigger, time) {
            return false;
        }
        self.solver
            .set_gravity(gravity_vector(tilt.magnitude, tilt.slope));
        self.solver.set_bent_floor(tilt.floor);
        self.tilt = None;
        self.tilted_at = Some(time);
        tracing::info!(
            time,
            slope = tilt.slope,
            trigger = ?tilt.trigger,
            "gravity tilted on impact at t = {time} s"
        );
        true
    }

    fn next_event(&self, time: f64) -> Option<f64> {
        let tilt = self.tilt.as_ref().and_then(|t| match t.trigger {
            ImpactTrigger::Time(t) => Some(t),
            ImpactTrigger::FloorEpsS(_) | ImpactTrigger::CentroidBelow(_) => None,
        });
        let gate = self.gates.next_opening(time);
        let inlet = self.inlets.next_change(time);
        [tilt, gate, inlet]
            .into_iter()
            .flatten()
            .min_by(f64::total_cmp)
    }

    fn write_fields(&mut self, series: &mut PvdSeries, time: f64) -> Result<(), OutputError> {
        let grid = self.solver.grid().clone();
        let s = self.solver.solids(0);
        Self::centre(
            &grid,
            self.solver.u_g(),
            self.solver.v_g(),
            &mut self.scratch,
        );
        Self::centre(&grid, &s.u, &s.v, &mut self.scratch2);
        series.push(
            &grid,
            time,
            &[
                CellField::scalar("eps_s", s.eps()),
                CellField::vector("u_s", &self.scratch2),
                CellField::scalar("theta", &s.theta),
                CellField::scalar("p_s", self.solver.p_s(0)),
                CellField::vector("u_g", &self.scratch),
                CellField::scalar("p_g", self.solver.p_g()),
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
        let s = self.solver.solids(0);
        let k = i + nx * j;
        let u = 0.5 * (s.u[i + (nx + 1) * j] + s.u[i + 1 + (nx + 1) * j]);
        vec![y, s.eps()[k], u, s.theta[k]]
    }

    fn grid(&self) -> &Grid {
        self.solver.grid()
    }

    fn mass_imbalance_ratio(&self) -> f64 {
        0.0
    }

    fn restore(&mut self) {
        self.solver.restore_step();
    }

    fn save_state(&self) -> SolverState {
        let mut state = self.solver.save_state();
        // gravity is in the solver's state; whether the impact is still to come is here
        state.put_counts(TILT_PENDING, [self.tilt.is_some() as u8]);
        state
    }

    fn load_state(&mut self, state: &SolverState) -> Result<(), StateError> {
        self.solver.load_state(state)?;
        if state.take_counts(TILT_PENDING, 1)?[0] == 0 {
            // tilted before the checkpoint: the bent floor acts too
            if let Some(tilt) = self.tilt.take() {
                self.solver.set_bent_floor(tilt.floor);
            }
        }
        Ok(())
    }

    fn solids_mass(&self) -> f64 {
        (0..self.solver.n_solids())
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
    fn linear_iterations(&self) -> Vec<(String, u64)> {
        self.solver
            .profile()
            .iterations
            .parts()
            .iter()
            .map(|(name, n)| (name.to_string(), *n))
            .collect()
    }

    fn max_eps_s(&self) -> f64 {
        self.solver
            .state()
            .phases()
            .iter()
            .flat_map(|s| s.eps().iter())
            .fold(0.0, |a: f64, &e| a.max(e))
    }

    fn floor_h_u(&self, x: f64) -> Option<f64> {
        let faces = self.solver.grid().x.faces();
        let k = (0..faces.len())
            .min_by(|&a, &b| (faces[a] - x).abs().total_cmp(&(faces[b] - x).abs()))?;
        self.solver
            .has_floor_model(0)
            .then(|| self.solver.floor_h_u(0)[k])
    }

    /// The front for the gate speeds: where εs of the floor row falls through `threshold`
    /// beyond its last cell i at or above it, interpolated linearly between the centres of
    /// cells i and i + 1 (the east face at the last cell). Unlike the whole-cell front of
    /// the bulk monitor it moves continuously, so speeds from it are not quantised in steps
    /// of Δx per sampling interval.
    fn interpolated_front(&self, threshold: f64) -> Option<f64> {
        let g = self.solver.grid();
        let nx = g.nx();
        let (xc, eps) = (g.x.centres(), self.solver.solids(0).eps());
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

    fn release_pending(&self, time: f64) -> bool {
        self.tilt.is_some()
            || self.gates.next_opening(time).is_some()
            || self.inlets.next_change(time).is_some()
    }

    fn bulk(&self, threshold: f64) -> Option<(f64, f64)> {
        let g = self.solver.grid();
        let (nx, ny) = (g.nx(), g.ny());
        let s = self.solver.solids(0);
        // front: the largest x whose floor cell has εs ≥ threshold (cases.md family F)
        let front = (0..nx)
            .rev()
            .find(|&i| s.eps()[i] >= threshold)
            .map_or(g.x.start(), |i| g.x.faces()[i + 1]);
        let (mut num, mut den) = (0.0, 0.0);
        for j in 0..ny {
            for i in 0..nx {
                let k = i + nx * j;
                let w = s.eps()[k] * g.cell_volume(i, j);
                num += w * 0.5 * (s.u[i + (nx + 1) * j] + s.u[i + 1 + (nx + 1) * j]);
                den += w;
            }
        }
        Some((front, if den > 0.0 { num / den } else { 0.0 }))
    }
}
