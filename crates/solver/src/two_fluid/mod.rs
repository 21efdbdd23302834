//! The two-fluid model: gas plus M solids phases (docs/model.md §1, §4.9), first version.
//!
//! One outer iteration ([`TwoFluid::outer_iteration`]) follows MFIX's DO_ITERATION
//! (docs/model.md §4.9), one stage per module:
//! 1. [`closures`]: closures per cell and phase at the current iterate (runout-closures
//!    `evaluate`): μ_s, λ_s, P_s (kinetic + frictional, summed), κ_s, K_cp, F_gs and the θ
//!    sources; then the per-face wall closures of the state-dependent walls from the
//!    near-wall state ([`walls`], docs/model.md §3.5–3.8);
//! 2. [`momentum_pea`]: momentum predictor of every phase ([`crate::momentum`]) with the
//!    current P_g and P_s, the drag removed by partial elimination ([`crate::pea`]),
//!    Patankar relaxation;
//! 3. [`eps_correction`]: solids volume-fraction correction of each phase
//!    ([`crate::volume_fraction`]); εg = 1 − Σεs;
//! 4. [`pressure`]: gas pressure correction from gas continuity with d_g of the partial
//!    elimination (docs/model.md §4.6); the solids velocities are not corrected with P'_g;
//! 5. [`granular_energy`]: granular energy of each phase ([`crate::energy`]),
//!    θ ≥ 10⁻¹² m²/s² (with Schaeffer friction a fixed row θ = 10⁻¹² m²/s² where εg < εg*,
//!    docs/model.md §1.3);
//! 6. [`residuals`]: residuals (docs/model.md §4.11), and a step's convergence
//!    ([`TwoFluid::step`]).
//!
//! Also: the explicit stress terms of docs/model.md §4.4 once per step ([`crate::stress`]);
//! the wall face velocities in the strain rates of wall cells (§4.4, [`walls`]); the
//! continuity face values of the convection scheme (§4.2); the DIL_EP_S treatment of dilute
//! faces and cells (§2.7, §4.8, [`dilute`]); u and v written once through a staggered
//! component view ([`crate::staggered`]); time and residual locations in [`diagnostics`].
//!
//! What the solver holds: what it was built with ([`model`]: grid, gas, solids phases and
//! their walls, gravity, settings, scene), the fields ([`state`], keeping εg = 1 − Σεs), the
//! closure values per cell and phase as a struct of arrays ([`coefficients`]), the wall
//! closures between outer iterations ([`wall_closures`]), the per-phase work storage
//! ([`workspace`]) and the timers and counters ([`diagnostics`]). Each stage is a function
//! over explicit borrows of these (`&Model`, `&mut State`, ...), so its signature says what
//! it reads and what it changes.
//!
//! Schaeffer friction (docs/model.md §2.4.1): the plastic pressure P* = A (εg* − εg)^10 is kept
//! per cell apart from P_s ([`TwoFluid::p_star`]) and enters only the solids momentum, as
//! its own gradient −∇P* (§4.4); K_cp = dP*/dεs (§2.5); P* is recomputed from the corrected εs
//! (§4.9 step 5); θ is forced to θ_small where εg < εg* (§1.3; as MFIX, by a fixed row of the
//! θ equation, not relaxed). With the Princeton model P* is never computed (≡ 0) and the
//! momentum has no P* term.
//!
//! Not yet: dry (gas-free) cases, the gas's own explicit stress terms (μ_g ∇(∇·u_g),
//! negligible for air), Schaeffer with more than one solids phase (MFIX's P* from the
//! mixture εg and its εs/Σε_cp weights).

use std::time::Instant;

mod checkpoint;
mod closures;
mod coefficients;
mod diagnostics;
mod dilute;
mod eps_correction;
mod forcing;
mod granular_energy;
mod model;
mod momentum_pea;
mod pressure;
mod relaxation;
mod residuals;
mod scene;
mod setup;
mod sidewalls;
mod state;
mod wall_closures;
mod wall_load;
mod walls;
mod workspace;

pub use closures::CellClosures;
pub use diagnostics::{Counters, LinearIterations, Profile};
pub use relaxation::RelaxationBase;
pub use residuals::TwoFluidResiduals;
pub use scene::{PhaseScene, Scene, WallClosure};
pub use sidewalls::{SidewallCell, SidewallTerms, Sidewalls};
pub use state::{GasOld, GasState, PhaseMut, PhaseOld, PhaseState, State};

use runout_closures::ClosureParams;
use runout_linsolve::{LinSolveError, LinearSolver, Stencil5};
use runout_mesh::{Grid, Side, Sides};
use runout_walls::{RobinFace, SolidsWallModel};

use crate::single_phase::SideBc;
use crate::transport::Scheme;
use coefficients::PhaseCoefficients;
use diagnostics::{since, Diagnostics};
use model::Model;
use residuals::Convergence;
use wall_closures::PhaseWallClosures;
use wall_load::BodyForce;
use walls::{GasNearWalls, WallRelaxation};
use workspace::{IterationFlags, PhaseWork, Solvers, Workspace};

/// Smallest normaliser of the gas continuity residual, as a fraction of the gas mass a mean
/// cell holds per time step (ρ_g V/Δt): with the 1e-3 tolerance a step converges at the
/// latest when the mean gas imbalance is 1e-8 of that.
const GAS_RESIDUAL_FLOOR: f64 = 1e-5;

/// Relative tolerance of the gas pressure-correction solve (see [`TwoFluid::new`]).
const PRESSURE_RTOL: f64 = 1e-2;

/// Cells of the pressure multigrid's coarsest level at most (band LU): on the pressure-like
/// model problem an outer iteration costs 14 % less than with 1024 on 200 × 50 cells and
/// 2–6 % less on 400 × 100, 800 × 200 and 1000 × 90, at the same iteration counts
/// (`cargo run --release -p runout-linsolve --example mg_threads`, docs/studies/performance.md,
/// "The y lines split in two"). The ε' preconditioner keeps the default 1024: its solves took
/// longer with 4096.
const PRESSURE_COARSEST_CELLS: usize = 4096;

/// Cells per parallel task of the per-cell closures (rayon's fork/join costs about a
/// microsecond, the closures of one cell with solids 0.1–0.2 µs, of one without nothing):
/// small, so that the rows with solids spread over the threads.
const PAR_MIN_CELLS: usize = 2048;

/// θ floor after each solve (docs/model.md §1.3, MFIX `adjust_theta.f`).
const THETA_SMALL: f64 = runout_closures::guards::THETA_SMALL;

/// Dilute threshold of solids faces and cells (MFIX `DIL_EP_S`, docs/model.md §2.7).
const DIL_EP_S: f64 = runout_closures::guards::DIL_EP_S;

/// One solids phase as the solver needs it.
#[derive(Clone, Debug)]
pub struct SolidsSpec {
    /// closure parameters (particles, gas, friction, radial distribution, drag)
    pub params: ClosureParams,
    /// maximum packing εs,max (selective relaxation of the ε correction)
    pub eps_max: f64,
    /// The solids condition on each side (docs/model.md §3): the wall model, `None` where the
    /// side is an outlet (the solids then see the gas's outlet: zero gradient, the gas
    /// outlet's pressure). A side must be a wall for the solids exactly where it is one for
    /// the gas ([`TwoFluid::new`]).
    pub walls: Sides<Option<SolidsWallModel>>,
}

impl SolidsSpec {
    /// The wall model on `side`, `None` on an outlet.
    pub fn wall(&self, side: Side) -> Option<&SolidsWallModel> {
        self.walls.get(side).as_ref()
    }

    /// The state-dependent wall model on `side` (Johnson–Jackson, revisited JJ, Jenkins),
    /// whose closures are evaluated per face each outer iteration (docs/model.md §3.5–3.8);
    /// `None` on an outlet and on a wall with fixed faces.
    pub fn per_face_model(&self, side: Side) -> Option<&SolidsWallModel> {
        self.wall(side)
            .filter(|model| model.fixed_faces().is_none())
    }

    /// The (momentum, θ) faces of the wall on `side`: the fixed faces of a state-independent
    /// model (docs/model.md §3.2–3.3), zero-gradient placeholders under a per-face model
    /// (its per-face closures replace them once evaluated); `None` on an outlet.
    fn side_faces(&self, side: Side) -> Option<(RobinFace, RobinFace)> {
        self.wall(side).map(|model| {
            model
                .fixed_faces()
                .unwrap_or((RobinFace::ZERO_GRADIENT, RobinFace::ZERO_GRADIENT))
        })
    }

    /// The side's face of the tangential solids velocity ([`SolidsSpec::side_faces`]),
    /// `None` on an outlet.
    pub(crate) fn momentum_face(&self, side: Side) -> Option<RobinFace> {
        self.side_faces(side).map(|(momentum, _)| momentum)
    }

    /// The condition of the solids momentum on each side: the wall's momentum face
    /// ([`SolidsSpec::momentum_face`]), the gas's condition `gas_walls` on an outlet.
    pub(crate) fn momentum_bcs(&self, gas_walls: &Sides<SideBc>) -> Sides<SideBc> {
        Sides::from_fn(|side| match self.momentum_face(side) {
            Some(face) => SideBc::Wall(face),
            None => *gas_walls.get(side),
        })
    }

    /// The θ face of each side ([`SolidsSpec::side_faces`]), `None` on an outlet.
    pub(crate) fn theta_faces(&self) -> Sides<Option<RobinFace>> {
        Sides::from_fn(|side| self.side_faces(side).map(|(_, theta)| theta))
    }
}

/// Iteration settings (MFIX defaults, docs/model.md §4.10).
#[derive(Clone, Debug)]
pub struct TwoFluidSettings {
    /// convection scheme of the momentum and θ equations
    pub scheme: Scheme,
    /// momentum relaxation (`UR_FAC(3..4)`)
    pub relax_velocity: f64,
    /// what the solids momentum rows are relaxed in proportion to ([`RelaxationBase`]:
    /// MFIX's whole centre coefficient, or the row's own part, docs/model.md §4.10); `None`:
    /// each phase's friction model answers
    /// ([`runout_closures::FrictionModel::relaxes_momentum_by_own_part`])
    pub solids_relaxation_base: Option<RelaxationBase>,
    /// gas-pressure relaxation (`UR_FAC(1)`)
    pub relax_pressure: f64,
    /// selective ε-correction relaxation (`UR_FAC(2)`)
    pub relax_eps: f64,
    /// θ relaxation (`UR_FAC(8)`)
    pub relax_theta: f64,
    /// Relaxation of the solids momentum wall closures (the Robin coefficients g, h, c of
    /// each wall node) of the state-dependent walls between outer iterations: new =
    /// ω·computed + (1 − ω)·previous. Default 1, MFIX's iteration. With ω = 1 the lagged
    /// closures of a high-friction wall (Johnson–Jackson φ = 1) make the floor's slip and
    /// strain cycle with period 2 between outer iterations, so steps stall; ω = 0.5 removes
    /// that but slows other floors (the Jenkins flume takes twice the steps;
    /// docs/history/performance-log.md, "Relaxed wall closures"). Changes the path of the outer
    /// iterations, not the converged step.
    pub relax_wall_closures: f64,
    /// Apply `relax_wall_closures` only at a wall node whose slip coefficient h (of the
    /// Robin closure g ∂u/∂n + h u = c) turned back between outer iterations by more than
    /// half its previous change ([`dilute::turns_back`]); such a node stays relaxed until the time
    /// step ends. The period-2 cycle is damped where it occurs, and a floor whose iteration
    /// converges by itself keeps MFIX's iteration. Not in MFIX (docs/history/performance-log.md,
    /// "Relaxing the wall closures only where they cycle").
    pub relax_wall_closures_oscillating_only: bool,
    /// Freeze the class of a cell's θ row (dilute: εs ≤ DIL_EP_S, docs/model.md §4.8) to
    /// dilute for the rest of the step once it has changed twice within the step
    /// ([`dilute::next_dilute_class`]). MFIX reclassifies every outer iteration; a cell whose εs
    /// straddles DIL_EP_S can then flip class every iteration: dense, its θ row heats it
    /// and its dilute neighbours (whose rows take the mean of their dense neighbours), its
    /// solids pressure pushes εs below DIL_EP_S; dilute, εs returns. Neither class is then
    /// self-consistent and the step stalls (the coarse flume at t = 0.55 s, cell (55, 10):
    /// εs 1.00078e-4 ↔ 0.99672e-4 for 30 iterations). Not in MFIX; where the class settles
    /// within a step, the converged step is MFIX's (docs/history/performance-log.md,
    /// "Cells that cycle across DIL_EP_S").
    pub freeze_cycling_dilute_class: bool,
    /// End each converged step with exact discrete solids continuity
    /// ([`eps_correction::conservative_finish`]; not MFIX): the solids mass then changes only by
    /// the boundary flux, where MFIX lets the step tolerance's remainder accumulate where
    /// solids compact (1e-7 of the solids over family M). Off by default: on the paper's
    /// slide (S-PS base, coarse) the finish's changes in the dilute cells above the flow
    /// cost 43 rejected steps and 57 % more steps; restricted to cells with εs > DIL_EP_S it
    /// no longer conserves (the dilute cells carry part of the remainder).
    pub exact_solids_continuity: bool,
    /// MFIX's `DETECT_STALL` (default true, docs/model.md §4.11): at every 5th outer iteration
    /// after the 10th, a hydrodynamic residual sum (momentum and continuity) that is not
    /// below its value 5 iterations before ends the step as failed, so it is retried with a
    /// smaller Δt instead of iterating to `max_iterations`.
    pub detect_stall: bool,
    /// The momentum residual normalised per class of node (default) or pooled over every
    /// node as MFIX ([`residuals::ClassedResidual`], docs/model.md §4.11).
    pub pooled_momentum_residual: bool,
    /// The momentum equations' form: MFIX's continuity-subtracted (default) or conservative
    /// ([`crate::momentum::MomentumForm`], docs/model.md §4.3).
    pub momentum_form: crate::momentum::MomentumForm,
}

impl Default for TwoFluidSettings {
    fn default() -> Self {
        TwoFluidSettings {
            scheme: Scheme::Upwind,
            relax_velocity: 0.5,
            solids_relaxation_base: None,
            relax_pressure: 0.8,
            relax_eps: 0.5,
            relax_theta: 0.5,
            relax_wall_closures: 1.0,
            relax_wall_closures_oscillating_only: false,
            freeze_cycling_dilute_class: false,
            exact_solids_continuity: false,
            detect_stall: true,
            pooled_momentum_residual: false,
            momentum_form: crate::momentum::MomentumForm::ContinuitySubtracted,
        }
    }
}

/// Largest number of solids phases (the per-node partial-elimination work arrays are fixed
/// size, so the momentum loop allocates nothing).
pub const MAX_SOLIDS_PHASES: usize = 7;

/// Errors of the two-fluid solver.
#[derive(Debug, thiserror::Error)]
pub enum TwoFluidError {
    /// More solids phases than [`MAX_SOLIDS_PHASES`].
    #[error("{0} solids phases: at most {MAX_SOLIDS_PHASES} are supported")]
    TooManyPhases(usize),
    /// Gas inflow asked for on a side that is not a wall.
    #[error("gas inflow on the {0} side, which is an outlet")]
    InflowOnOutlet(String),
    /// A field of flags or values of the wrong size.
    #[error("{0}")]
    Shape(String),
    /// A solids phase whose side is a wall where the gas's is an outlet, or an outlet where
    /// the gas's is a wall ([`SolidsSpec::walls`]).
    #[error(
        "solids phase {phase}: the {side} side is {solids} for the solids but {gas} for the \
         gas; a side is a wall or an outlet for every phase"
    )]
    SolidsSideMismatch {
        /// the phase, counted from 1
        phase: usize,
        /// the side's name
        side: &'static str,
        /// "a wall" or "an outlet"
        solids: &'static str,
        /// "a wall" or "an outlet"
        gas: &'static str,
    },
    /// A periodic-x grid ([`runout_mesh::Grid::periodic_x`]) with more than one cell across
    /// or with an outlet on its x sides. Periodic x is a fully developed column, MFIX's
    /// `CYCLIC_X` on one cell: every ∂/∂x vanishes, the x-face fluxes of a cell cancel, u has
    /// one unknown per row (node 0, with the whole cell as its control volume; node nx is its
    /// copy) and no x pressure gradient. The west and east sides must be free-slip walls
    /// (they then add nothing to v or θ). Used by the steady chute check (issue 7,
    /// docs/studies/chute1d.md).
    #[error("periodic x needs one column of cells (nx = 1, got {0}) and walls on the west and east sides")]
    PeriodicColumn(usize),
    /// A periodic y axis (only x may be periodic, [`runout_mesh::Grid::periodic_x`]).
    #[error("the y axis cannot be periodic: only a column periodic in x is supported")]
    PeriodicY,
    /// A linear solve failed.
    #[error("{equation}: {source}")]
    Linear {
        /// which equation
        equation: String,
        /// the solver error
        source: LinSolveError,
    },
}

/// The two-fluid solver with its work storage (allocated once).
pub struct TwoFluid {
    /// grid, gas, walls, phases, gravity, settings, scene and side walls
    model: Model,
    /// the fields of the gas and every solids phase
    state: State,
    /// closure values, strain rates and explicit sources per solids phase, per cell
    coefficients: Vec<PhaseCoefficients>,
    /// the wall closures per solids phase
    wall_closures: Vec<PhaseWallClosures>,
    /// work arrays, stencils, linear solvers and iteration flags
    workspace: Workspace,
    /// profile timers, counters and the worst residual locations
    diagnostics: Diagnostics,
}

fn lin(equation: &str) -> impl Fn(LinSolveError) -> TwoFluidError + '_ {
    move |source| TwoFluidError::Linear {
        equation: equation.to_string(),
        source,
    }
}

impl TwoFluid {
    /// The grid.
    pub fn grid(&self) -> &Grid {
        &self.model.grid
    }

    /// Sets the side walls of a quasi-2-D channel (docs/model.md §8); `None`: a plane flow.
    pub fn set_sidewalls(&mut self, sidewalls: Option<Sidewalls>) {
        self.model.sidewalls = sidewalls;
        self.model.scene = self.derive_scene();
    }

    /// What this solver computes ([`Scene`]).
    pub fn scene(&self) -> &Scene {
        &self.model.scene
    }

    /// How often each optional piece of the outer iteration ran ([`Counters`]).
    pub fn counters(&self) -> Counters {
        self.diagnostics.counters.clone()
    }

    /// The scene of the current phases, settings and side walls.
    fn derive_scene(&self) -> Scene {
        Scene::of(
            &self.model.grid,
            &self.model.solids_specs,
            &self.model.settings,
            self.model.sidewalls.as_ref().map(|w| w.width),
        )
    }

    /// Stores the current fields as the old time level.
    pub fn begin_step(&mut self) {
        self.workspace.flags.rebuild_preconditioners = true;
        self.workspace.flags.theta_class_fresh = true;
        self.state.begin_step();
        for w in &mut self.wall_closures {
            for side in Side::ALL {
                for node in w.wall_velocity_cycle.get_mut(side) {
                    node.cycling = false;
                }
            }
        }
    }

    /// Restores the fields of the start of the step.
    pub fn restore_step(&mut self) {
        self.state.restore_step();
    }

    /// The fields of the gas and every solids phase.
    pub fn state(&self) -> &State {
        &self.state
    }

    /// The fields, to set an initial state (εs through [`State::set_solids_fraction`] and
    /// [`State::update_solids`], which keep εg = 1 − Σεs).
    pub fn state_mut(&mut self) -> &mut State {
        &mut self.state
    }

    /// εg per cell.
    pub fn eps_g(&self) -> &[f64] {
        self.state.gas().eps()
    }

    /// Gas pressure per cell [Pa].
    pub fn p_g(&self) -> &[f64] {
        &self.state.gas().p
    }

    /// Gas u on the x-faces [m s⁻¹].
    pub fn u_g(&self) -> &[f64] {
        &self.state.gas().u
    }

    /// Gas v on the y-faces [m s⁻¹].
    pub fn v_g(&self) -> &[f64] {
        &self.state.gas().v
    }

    /// Solids phase `m`.
    pub fn solids(&self, m: usize) -> &PhaseState {
        self.state.solids(m)
    }

    /// The number of solids phases.
    pub fn n_solids(&self) -> usize {
        self.state.n_solids()
    }

    /// Solids pressure P_s = P_kin + P_fric of phase `m` per cell [Pa].
    pub fn p_s(&self, m: usize) -> &[f64] {
        &self.coefficients[m].p_s
    }

    /// Schaeffer plastic pressure P* of phase `m` per cell [Pa] (docs/model.md §2.4.1), all 0
    /// with other friction models.
    pub fn p_star(&self, m: usize) -> &[f64] {
        &self.coefficients[m].p_star
    }

    /// The gas–solids drag coefficient F_gs of phase `m` per cell of the last closure
    /// evaluation [kg m⁻³ s⁻¹].
    pub fn drag(&self, m: usize) -> &[f64] {
        &self.coefficients[m].f_gs
    }

    /// h_w^u of phase `m` at the last floor evaluation per u-node (the wall probe of paper
    /// Fig. 9; see [`TwoFluid::has_floor_model`]).
    pub fn floor_h_u(&self, m: usize) -> &[f64] {
        &self.wall_closures[m].floor_h_u
    }

    /// The normal load N_w of a Coulomb floor per u-node of phase m at the last wall
    /// evaluation [Pa] (docs/model.md §3.11); 0 on other floors.
    pub fn floor_normal_load(&self, m: usize) -> &[f64] {
        &self.wall_closures[m].floor_normal_load
    }

    /// The side walls' normal load beyond the pressure per cell of phase m [Pa]: −λ_s tr D
    /// where they are Coulomb walls (docs/model.md §3.11), else 0.
    pub fn sidewall_extra_normal_load(&self, m: usize) -> Vec<f64> {
        self.coefficients[m]
            .sidewall
            .iter()
            .map(|t| t.extra_normal_load)
            .collect()
    }

    /// Material density ρ_s of phase m [kg m⁻³].
    pub fn solids_density(&self, m: usize) -> f64 {
        self.model.solids_specs[m].params.particles.density
    }

    /// Total solids mass per unit depth of phase m [kg m⁻¹].
    pub fn solids_mass(&self, m: usize) -> f64 {
        let (nx, ny) = (self.model.grid.nx(), self.model.grid.ny());
        let rho = self.model.solids_specs[m].params.particles.density;
        (0..ny)
            .flat_map(|j| (0..nx).map(move |i| (i, j)))
            .map(|(i, j)| {
                rho * self.solids(m).eps()[i + nx * j] * self.model.grid.cell_volume(i, j)
            })
            .sum()
    }

    /// One outer iteration with time step `dt` (docs/model.md §4.9, the module doc's steps):
    /// each stage a function over explicit borrows of the model, the state, the closures,
    /// the workspace and the diagnostics.
    pub fn outer_iteration(&mut self, dt: f64) -> Result<TwoFluidResiduals, TwoFluidError> {
        let TwoFluid {
            model,
            state,
            coefficients,
            wall_closures,
            workspace: work,
            diagnostics,
        } = self;
        let specs = &model.solids_specs;
        // 1. closures at the current iterate (already fresh at a step's first iteration),
        //    then the closures of the state-dependent walls and of the side walls
        if !std::mem::take(&mut work.flags.closures_fresh) {
            let t = Instant::now();
            diagnostics.counters.cell_closures +=
                closures::update_closures(&model.grid, state, wall_closures, coefficients, specs);
            diagnostics.profile.closures += since(t);
        }
        let t = Instant::now();
        if model.scene.has_per_face_walls() {
            update_walls(model, state, (wall_closures, coefficients), diagnostics);
        }
        if let Some(sidewalls) = &model.sidewalls {
            sidewalls::update_sidewalls(&model.grid, sidewalls, state, coefficients, specs);
        }
        diagnostics.profile.walls += since(t);
        // 2. momentum of every phase, drag by partial elimination
        let t = Instant::now();
        let momentum = momentum_pea::momentum(
            model,
            state,
            coefficients,
            wall_closures,
            work,
            diagnostics,
            dt,
        )?;
        diagnostics.profile.momentum_assembly += since(t);
        // 3. solids volume-fraction correction, εg = 1 − Σεs
        let t = Instant::now();
        let solids_mass = eps_correction::volume_fraction_correction(
            model,
            state,
            coefficients,
            work,
            diagnostics,
            dt,
        )?;
        diagnostics.profile.eps_assembly += since(t);
        // 4. gas pressure correction
        let t = Instant::now();
        let gas_mass = pressure::pressure_correction(model, state, work, diagnostics, dt)?;
        diagnostics.profile.pressure_assembly += since(t);
        // 5. granular energy
        let t = Instant::now();
        let theta = granular_energy::granular_energy(
            model,
            state,
            coefficients,
            wall_closures,
            work,
            diagnostics,
            dt,
        )?;
        diagnostics.profile.theta_assembly += since(t);
        // 6. residuals (each stage returned its own)
        Ok(TwoFluidResiduals {
            momentum,
            gas_mass,
            solids_mass,
            theta,
        })
    }

    /// The closures per cell and phase and the explicit stress sources at the start of a
    /// step (docs/model.md §4.4: the stresses once per step).
    fn begin_step_closures(&mut self) {
        let t = Instant::now();
        self.diagnostics.counters.cell_closures += closures::update_closures(
            &self.model.grid,
            &self.state,
            &mut self.wall_closures,
            &mut self.coefficients,
            &self.model.solids_specs,
        );
        self.diagnostics.profile.closures += since(t);
        let t = Instant::now();
        momentum_pea::update_stress_sources(
            &self.model.grid,
            &self.state,
            &mut self.coefficients,
            &self.workspace,
        );
        self.diagnostics.profile.stress += since(t);
        self.workspace.flags.closures_fresh = true;
    }
}

/// Step 1, walls: the per-face closures of the state-dependent walls from the current
/// iterate ([`walls::update_walls`]), counted per side.
fn update_walls(
    model: &Model,
    state: &State,
    (wall_closures, coefficients): (&mut [PhaseWallClosures], &[PhaseCoefficients]),
    diagnostics: &mut Diagnostics,
) {
    let gas = GasNearWalls {
        walls: &model.gas_walls,
        u: &state.gas().u,
        v: &state.gas().v,
        p: &state.gas().p,
    };
    let body = BodyForce {
        gravity: model.gravity,
        bent_floor: model.bent_floor.as_ref(),
    };
    let relax = WallRelaxation {
        weight: model.settings.relax_wall_closures,
        oscillating_only: model.settings.relax_wall_closures_oscillating_only,
    };
    let faces = walls::update_walls(
        &model.grid,
        gas,
        &body,
        relax,
        state,
        (wall_closures, coefficients),
        &model.solids_specs,
    );
    for side in Side::ALL {
        *diagnostics.counters.wall_closure_faces.get_mut(side) += faces.get(side);
    }
}

/// Outcome of [`TwoFluid::step`].
#[derive(Clone, Debug, PartialEq)]
pub struct TwoFluidStep {
    /// outer iterations used
    pub iterations: usize,
    /// whether the step converged (if not, the fields were restored)
    pub converged: bool,
    /// the residual sum of the last iteration (momentum + normalised continuity)
    pub residual: f64,
    /// the residuals of the last iteration
    pub last: TwoFluidResiduals,
    /// a linear solver failure or a stall that ended the step (the step was undone and may
    /// be retried with a smaller Δt)
    pub failure: Option<String>,
}

impl TwoFluid {
    /// One implicit-Euler step of size `dt` (docs/model.md §4.9, §4.11): outer iterations until
    /// the momentum residuals plus the gas and solids continuity residuals (each relative to
    /// its first iteration) sum to at most `tol` and the θ residual is at most `tol_theta`,
    /// after at least two iterations. A step that does not converge within `max_iterations`,
    /// or whose sum exceeds `diverge`, or that produces a non-finite value, is undone.
    pub fn step(
        &mut self,
        dt: f64,
        tol: f64,
        tol_theta: f64,
        diverge: f64,
        max_iterations: usize,
    ) -> Result<TwoFluidStep, TwoFluidError> {
        self.begin_step();
        let mean_volume =
            self.model.grid.x.length() * self.model.grid.y.length() / self.eps_g().len() as f64;
        self.begin_step_closures();
        let mut convergence = Convergence::new();
        let mut out = TwoFluidStep {
            iterations: 0,
            converged: false,
            residual: f64::INFINITY,
            last: TwoFluidResiduals::default(),
            failure: None,
        };
        for it in 0..max_iterations {
            let nit = it + 1;
            out.iterations = nit;
            let r = match self.outer_iteration(dt) {
                Ok(r) => r,
                Err(e) => {
                    out.failure = Some(e.to_string());
                    break;
                }
            };
            // the gas residual's normaliser is at least GAS_RESIDUAL_FLOOR of the gas a mean
            // cell holds per step ([`Convergence::sum`], S-JJ-phi coarse, docs/history/status-log.md)
            let gas_floor = GAS_RESIDUAL_FLOOR * self.model.gas.density * mean_volume / dt;
            let (sum, g, s) = convergence.sum(&r, gas_floor);
            out.residual = sum;
            out.last = r;
            tracing::trace!(
                iteration = nit,
                momentum = r.momentum,
                gas = r.gas_mass / g,
                solids = r.solids_mass / s,
                theta = r.theta,
                "outer iteration"
            );
            // where each iteration's largest residuals sit (why a step needs many iterations)
            if tracing::enabled!(tracing::Level::TRACE) {
                tracing::trace!(locations = %self.residual_locations(), "largest residuals");
            }
            if !self.state.all_finite() {
                out.residual = f64::INFINITY;
                break;
            }
            // stall detection before the convergence test, as MFIX's check_convergence.f
            // (docs/model.md §4.11): the step is then retried with a smaller Δt (§4.12)
            if self.model.settings.detect_stall {
                if let Some(sum5) = convergence.stalled(nit, sum) {
                    out.failure = Some(format!(
                        "stalled: the momentum and continuity residual sum {sum:.3e} at outer \
                         iteration {nit} was not below its value {sum5:.3e} 5 iterations before \
                         (granular energy residual {:.3e})",
                        r.theta
                    ));
                    break;
                }
            }
            if it >= 1 && sum <= tol && r.theta <= tol_theta {
                out.converged = true;
                if self.model.settings.exact_solids_continuity {
                    eps_correction::conservative_finish(
                        &self.model,
                        &mut self.state,
                        &self.coefficients,
                        &mut self.workspace,
                        dt,
                    );
                }
                return Ok(out);
            }
            if it >= 1 && sum >= diverge {
                break;
            }
        }
        self.restore_step();
        Ok(out)
    }

    /// Wall time per part of the outer iteration so far.
    pub fn profile(&self) -> Profile {
        self.diagnostics.profile
    }

    /// Whether solids phase `m` has a state-dependent model (JJ, revisited JJ, Jenkins) on
    /// the floor, i.e. whether `floor_h_u` is meaningful.
    pub fn has_floor_model(&self, m: usize) -> bool {
        self.model.solids_specs[m]
            .per_face_model(Side::South)
            .is_some()
    }
}

/// Solves `a x = b` from x = 0 with the preconditioner of the step's first outer iteration
/// (`rebuild` on that one): the P' and ε' matrices change little within a step, and the
/// multigrid set-up costs as much as a few iterations. A solve that misses its tolerance
/// with the kept preconditioner is repeated with a fresh one. Returns the iterations of
/// the solves.
fn solve_keeping_preconditioner(
    solver: &mut dyn LinearSolver,
    a: &Stencil5,
    x: &mut [f64],
    rebuild: bool,
) -> Result<usize, LinSolveError> {
    if rebuild {
        return Ok(solver.setup_and_solve(a, x)?.iterations);
    }
    solver.refresh(a)?;
    let kept = solver.solve(a, x)?;
    if kept.converged {
        return Ok(kept.iterations);
    }
    x.iter_mut().for_each(|v| *v = 0.0);
    Ok(kept.iterations + solver.setup_and_solve(a, x)?.iterations)
}
