//! The two-fluid model: gas plus M solids phases (docs/model.md §1, §4.9), first version.
//!
//! One outer iteration follows MFIX's DO_ITERATION (docs/model.md §4.9):
//! 1. closures per cell and phase at the current iterate (runout-closures `evaluate`):
//!    μ_s, λ_s, P_s (kinetic + frictional, summed), κ_s, K_cp, F_gs and the θ sources;
//! 2. momentum predictor of every phase ([`crate::momentum`]) with the current P_g and P_s,
//!    the drag removed by partial elimination ([`crate::pea`]), Patankar relaxation;
//! 3. solids volume-fraction correction of each phase ([`crate::volume_fraction`]);
//!    εg = 1 − Σεs;
//! 4. gas pressure correction from gas continuity with d_g of the partial elimination
//!    (docs/model.md §4.6); the solids velocities are not corrected with P'_g;
//! 5. granular energy of each phase ([`crate::energy`]), θ ≥ 10⁻¹² m²/s² (with Schaeffer
//!    friction a fixed row θ = 10⁻¹² m²/s² where εg < εg*, docs/model.md §1.3);
//! 6. residuals (docs/model.md §4.11).
//!
//! Also: the explicit stress terms of docs/model.md §4.4 once per step ([`crate::stress`]);
//! per-face Johnson–Jackson, revisited-JJ and Jenkins closures with MFIX's near-wall state
//! (§3.5–3.8, [`TwoFluid::update_walls`]); the wall face velocities in the strain rates of
//! wall cells (§4.4); the continuity face values of the convection scheme (§4.2); the
//! DIL_EP_S treatment of dilute faces and cells (§2.7, §4.8).
//!
//! Schaeffer friction (docs/model.md §2.4.1): the plastic pressure P* = A (εg* − εg)^10 is kept
//! per cell apart from P_s ([`SolidsFields::p_star`]) and enters only the solids momentum, as
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

use rayon::prelude::*;

use runout_closures::friction::p_star;
use runout_closures::{evaluate, CellState, ClosureParams, FrictionModel};
use runout_linsolve::{
    build, LinSolveError, LinearSolver, LinearSolverKind, MultigridParams, Pattern, Stencil5,
};
use runout_mesh::{Grid, Side, Sides};
use runout_walls::state::{corner_theta, face_theta};
use runout_walls::{MomentumWallState, RobinFace, SolidsWallModel, ThetaWallState, WallStrain};

use crate::energy::{assemble_theta, EnergyInputs};
use crate::kinematics::{strain_rates, Strain, WallVelocities};
use crate::momentum::{
    assemble_u, assemble_v, fixed_row, neighbour_sum, Context, PhaseFields, WallFaces,
};
use crate::pea::eliminate_node;
use crate::single_phase::{Fluid, SideBc};
use crate::transport::{face_value, FaceData, Scheme};
use crate::volume_fraction::{
    apply_correction, assemble_correction, mass_imbalance, CorrectionInputs,
};

/// Smallest normaliser of the gas continuity residual, as a fraction of the gas mass a mean
/// cell holds per time step (ρ_g V/Δt): with the 1e-3 tolerance a step converges at the
/// latest when the mean gas imbalance is 1e-8 of that.
const GAS_RESIDUAL_FLOOR: f64 = 1e-5;

/// Relative tolerance of the gas pressure-correction solve (see [`TwoFluid::new`]).
const PRESSURE_RTOL: f64 = 1e-2;

/// Fewest cells per parallel task of the per-cell closures (rayon's fork/join costs a few
/// microseconds, the closures of one cell about 0.1–0.2 µs).
const PAR_MIN_CELLS: usize = 4096;

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
    /// tangential-velocity closure on each side
    pub walls: Sides<SideBc>,
    /// θ closure on each wall side (`None` on an outlet)
    pub theta_walls: Sides<Option<RobinFace>>,
    /// state-dependent wall models (Johnson–Jackson, revisited JJ, Jenkins) per side; where
    /// given they replace `walls` and `theta_walls` with per-face closures each outer
    /// iteration (docs/model.md §3.5, §3.6, §3.8)
    pub wall_models: Sides<Option<SolidsWallModel>>,
}

/// Iteration settings (MFIX defaults, docs/model.md §4.10).
#[derive(Clone, Debug)]
pub struct TwoFluidSettings {
    /// convection scheme of the momentum and θ equations
    pub scheme: Scheme,
    /// momentum relaxation (`UR_FAC(3..4)`)
    pub relax_velocity: f64,
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
    /// docs/performance.md). Changes the path of the outer iterations, not the converged
    /// step.
    pub relax_wall_closures: f64,
    /// Apply `relax_wall_closures` only at a wall node whose slip coefficient h (of the
    /// Robin closure g ∂u/∂n + h u = c) turned back between outer iterations by more than
    /// half its previous change ([`turns_back`]); such a node stays relaxed until the time
    /// step ends. The period-2 cycle is damped where it occurs, and a floor whose iteration
    /// converges by itself keeps MFIX's iteration. Not in MFIX (docs/performance.md,
    /// session 6).
    pub relax_wall_closures_oscillating_only: bool,
    /// Freeze the class of a cell's θ row (dilute: εs ≤ DIL_EP_S, docs/model.md §4.8) to
    /// dilute for the rest of the step once it has changed twice within the step
    /// ([`next_dilute_class`]). MFIX reclassifies every outer iteration; a cell whose εs
    /// straddles DIL_EP_S can then flip class every iteration: dense, its θ row heats it
    /// and its dilute neighbours (whose rows take the mean of their dense neighbours), its
    /// solids pressure pushes εs below DIL_EP_S; dilute, εs returns. Neither class is then
    /// self-consistent and the step stalls (the coarse flume at t = 0.55 s, cell (55, 10):
    /// εs 1.00078e-4 ↔ 0.99672e-4 for 30 iterations). Not in MFIX; where the class settles
    /// within a step, the converged step is MFIX's (docs/performance.md, session 7).
    pub freeze_cycling_dilute_class: bool,
    /// A fully developed column: periodic in x with a single column of cells (nx = 1), as
    /// MFIX's `CYCLIC_X` on one cell. Every ∂/∂x vanishes: the x-face fluxes of a cell cancel,
    /// u has one unknown per row (node 0, with the whole cell as its control volume; node nx
    /// is its copy) and no x pressure gradient. The west and east sides must be free-slip
    /// walls (they then add nothing to v or θ). Used by the steady chute check (issue 7,
    /// docs/chute1d.md).
    pub periodic_x: bool,
    /// End each converged step with exact discrete solids continuity
    /// ([`TwoFluid::conservative_finish`]; not MFIX): the solids mass then changes only by
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
}

impl Default for TwoFluidSettings {
    fn default() -> Self {
        TwoFluidSettings {
            scheme: Scheme::Upwind,
            relax_velocity: 0.5,
            relax_pressure: 0.8,
            relax_eps: 0.5,
            relax_theta: 0.5,
            relax_wall_closures: 1.0,
            relax_wall_closures_oscillating_only: false,
            freeze_cycling_dilute_class: false,
            periodic_x: false,
            exact_solids_continuity: false,
            detect_stall: true,
        }
    }
}

/// The closure values one cell contributes to the solver (docs/model.md §2), all zero where
/// εs = 0.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CellClosures {
    /// P_s = P_kin + P_fric [Pa]
    pub p_s: f64,
    /// Schaeffer plastic pressure P* [Pa], 0 with other friction models (docs/model.md §2.4.1)
    pub p_star: f64,
    /// μ_s = μ_kin + μ_fric [Pa s]
    pub mu: f64,
    /// λ_s = λ_kin + λ_fric [Pa s]
    pub lambda: f64,
    /// κ_s [kg m⁻¹ s⁻¹]
    pub kappa: f64,
    /// K_cp = dP_s/dεs [Pa]
    pub k_cp: f64,
    /// F_gs [kg m⁻³ s⁻¹]
    pub f_gs: f64,
    /// P_kin/θ [kg m⁻³]
    pub p_kin_over_theta: f64,
    /// μ_kin [Pa s]
    pub mu_kin: f64,
    /// λ_kin [Pa s]
    pub lambda_kin: f64,
    /// γ/θ, collisional dissipation over θ [kg m⁻³ s⁻¹]
    pub gamma_over_theta: f64,
    /// J_slip, drag production of θ [kg m⁻¹ s⁻³]
    pub j_slip: f64,
}

impl CellClosures {
    /// The values of one cell from runout-closures' `evaluate` (θ ≥ θ_small expected).
    pub fn evaluate(state: &CellState, params: &ClosureParams) -> Self {
        let c = evaluate(state, params);
        CellClosures {
            p_s: c.stress.p_s,
            p_star: c.stress.p_star,
            mu: c.stress.mu_s,
            lambda: c.stress.lambda_s,
            kappa: c.kinetic.kappa_kin,
            k_cp: c.k_cp,
            f_gs: c.f_gs,
            p_kin_over_theta: c.kinetic.p_kin / state.theta,
            mu_kin: c.kinetic.mu_kin,
            lambda_kin: c.kinetic.lambda_kin,
            gamma_over_theta: c.kinetic.dissipation / state.theta,
            j_slip: c.j_slip,
        }
    }
}

/// Fields and closure values of one solids phase.
#[derive(Clone, Debug)]
pub struct SolidsFields {
    /// volume fraction εs per cell
    pub eps: Vec<f64>,
    /// u on x-faces
    pub u: Vec<f64>,
    /// v on y-faces
    pub v: Vec<f64>,
    /// granular temperature θ per cell [m² s⁻²]
    pub theta: Vec<f64>,
    eps_old: Vec<f64>,
    u_old: Vec<f64>,
    v_old: Vec<f64>,
    theta_old: Vec<f64>,
    rho_eps: Vec<f64>,
    rho_eps_old: Vec<f64>,
    /// solids pressure P_s = P_kin + P_fric per cell [Pa]
    pub p_s: Vec<f64>,
    /// Schaeffer plastic pressure P* per cell [Pa] (docs/model.md §2.4.1), all 0 with other
    /// friction models; in the solids momentum only, as −∇P* (§4.4)
    pub p_star: Vec<f64>,
    mu: Vec<f64>,
    lambda: Vec<f64>,
    kappa: Vec<f64>,
    k_cp: Vec<f64>,
    f_gs: Vec<f64>,
    p_kin_over_theta: Vec<f64>,
    mu_kin: Vec<f64>,
    lambda_kin: Vec<f64>,
    gamma_over_theta: Vec<f64>,
    j_slip: Vec<f64>,
    strain: Vec<Strain>,
    /// dilute u and v faces of the current momentum assembly (docs/model.md §2.7)
    dilute_u: Vec<bool>,
    dilute_v: Vec<bool>,
    /// closure values per cell (the parallel evaluation's output)
    cells: Vec<CellClosures>,
    /// tangential velocity on the wall faces of the south/north rows (per column) and the
    /// west/east columns (per row), from the wall closures (docs/model.md §3.2): what MFIX's
    /// ghost cells put into the strain rates of the wall cells (§4.4)
    wall_face_velocity: Sides<Vec<f64>>,
    /// explicit stress sources of the u and v equations, once per step (docs/model.md §4.4)
    tau_u: Vec<f64>,
    tau_v: Vec<f64>,
    tr_d: Vec<f64>,
    tr_d2: Vec<f64>,
    e_u: Vec<f64>,
    e_v: Vec<f64>,
    eps_prime: Vec<f64>,
    imbalance: Vec<f64>,
    a_u: Stencil5,
    a_v: Stencil5,
    a_eps: Stencil5,
    a_theta: Stencil5,
    /// per-node momentum closures of the state-dependent walls
    wall_velocity: WallFaces,
    /// per node of each side, the cycle watch of its momentum closure (for
    /// [`TwoFluidSettings::relax_wall_closures_oscillating_only`]; empty until used)
    wall_velocity_cycle: Sides<Vec<ClosureCycle>>,
    /// per-cell θ closures of the state-dependent walls
    wall_theta: WallFaces,
    /// the class of each cell's θ row at the last outer iteration (true: dense, a θ
    /// equation; false: dilute, the mean of its dense neighbours; docs/model.md §4.8), and how
    /// often it changed within the step ([`TwoFluidSettings::freeze_cycling_dilute_class`])
    theta_dense: Vec<bool>,
    theta_class_changes: Vec<u8>,
    /// h_w^u of the last floor evaluation per u-node (the wall probe of paper Fig. 9)
    pub floor_h_u: Vec<f64>,
}

impl SolidsFields {
    /// The gas–solids drag coefficient F_gs per cell of the last closure evaluation
    /// [kg m⁻³ s⁻¹].
    pub fn drag(&self) -> &[f64] {
        &self.f_gs
    }
}

/// Normalised residuals of one outer iteration (docs/model.md §4.11).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TwoFluidResiduals {
    /// momentum of all phases and components, MFIX's normalisation, summed
    pub momentum: f64,
    /// mean |gas mass imbalance| before the pressure correction [kg s⁻¹ per m depth]
    pub gas_mass: f64,
    /// mean |solids mass imbalance| before the ε correction, summed over phases
    pub solids_mass: f64,
    /// θ equations, Σ|residual| / Σ|a_P θ_P|, summed over phases
    pub theta: f64,
}

/// Wall time spent in each part of the outer iteration since the solver was built \[s\]
/// (issue 9: where the time goes). Timers are `Instant`s around whole loops, a few tens of
/// nanoseconds per call.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Profile {
    /// closures per cell (KT, friction, drag), strain rates, wall face velocities
    pub closures: f64,
    /// state-dependent wall closures (JJ, revisited JJ, Jenkins)
    pub walls: f64,
    /// explicit stress sources (once per step)
    pub stress: f64,
    /// momentum assembly of every phase and the partial elimination
    pub momentum_assembly: f64,
    /// momentum linear solves
    pub momentum_solve: f64,
    /// ε-correction assembly and update
    pub eps_assembly: f64,
    /// ε-correction linear solves
    pub eps_solve: f64,
    /// gas pressure-correction assembly and update
    pub pressure_assembly: f64,
    /// gas pressure-correction linear solves
    pub pressure_solve: f64,
    /// granular-energy assembly
    pub theta_assembly: f64,
    /// granular-energy linear solves
    pub theta_solve: f64,
    /// linear-solver iterations of each equation's solves
    pub iterations: LinearIterations,
}

/// Linear-solver iterations summed over every solve since the solver was built, per
/// equation (issue 22: where the cost per cell grows with the grid).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LinearIterations {
    /// momentum (every phase, u and v)
    pub momentum: u64,
    /// solids volume-fraction corrections
    pub eps: u64,
    /// gas pressure corrections
    pub pressure: u64,
    /// granular energy
    pub theta: u64,
}

impl LinearIterations {
    /// The counts by equation name.
    pub fn parts(&self) -> [(&'static str, u64); 4] {
        [
            ("momentum", self.momentum),
            ("eps", self.eps),
            ("pressure", self.pressure),
            ("theta", self.theta),
        ]
    }
}

impl Profile {
    /// The parts by name, in the order of the outer iteration.
    pub fn parts(&self) -> [(&'static str, f64); 11] {
        [
            ("closures", self.closures),
            ("walls", self.walls),
            ("stress", self.stress),
            ("momentum_assembly", self.momentum_assembly),
            ("momentum_solve", self.momentum_solve),
            ("eps_assembly", self.eps_assembly),
            ("eps_solve", self.eps_solve),
            ("pressure_assembly", self.pressure_assembly),
            ("pressure_solve", self.pressure_solve),
            ("theta_assembly", self.theta_assembly),
            ("theta_solve", self.theta_solve),
        ]
    }

    /// Sum of all parts \[s\].
    pub fn total(&self) -> f64 {
        self.closures
            + self.walls
            + self.stress
            + self.momentum_assembly
            + self.momentum_solve
            + self.eps_assembly
            + self.eps_solve
            + self.pressure_assembly
            + self.pressure_solve
            + self.theta_assembly
            + self.theta_solve
    }
}

/// Seconds since `t`.
fn since(t: Instant) -> f64 {
    t.elapsed().as_secs_f64()
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
    /// A periodic-x column with more than one cell across or with an outlet on its x sides.
    #[error("periodic x needs one column of cells (nx = 1, got {0}) and walls on the west and east sides")]
    PeriodicColumn(usize),
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
    grid: Grid,
    gas: Fluid,
    gas_walls: Sides<SideBc>,
    /// gas velocity into the domain through each wall side [m s⁻¹] (a distributor: gas
    /// enters with εg = 1, solids see the wall; MFIX's mass inlet with BC_EP_G = 1), 0 on
    /// impermeable walls
    gas_inflow: Sides<f64>,
    solids_specs: Vec<SolidsSpec>,
    gravity: (f64, f64),
    settings: TwoFluidSettings,
    /// gas volume fraction εg per cell
    pub eps_g: Vec<f64>,
    /// gas pressure per cell [Pa]
    pub p_g: Vec<f64>,
    /// gas u on x-faces
    pub u_g: Vec<f64>,
    /// gas v on y-faces
    pub v_g: Vec<f64>,
    /// solids phases
    pub solids: Vec<SolidsFields>,
    eps_g_old: Vec<f64>,
    u_g_old: Vec<f64>,
    v_g_old: Vec<f64>,
    rho_eps_g: Vec<f64>,
    rho_eps_g_old: Vec<f64>,
    mu_g: Vec<f64>,
    d_u: Vec<f64>,
    d_v: Vec<f64>,
    p_corr: Vec<f64>,
    imbalance: Vec<f64>,
    u_faces: FaceData,
    v_faces: FaceData,
    c_faces: FaceData,
    a_ug: Stencil5,
    a_vg: Stencil5,
    a_p: Stencil5,
    solver_u: Box<dyn LinearSolver>,
    solver_v: Box<dyn LinearSolver>,
    solver_p: Box<dyn LinearSolver>,
    solver_eps: Box<dyn LinearSolver>,
    /// MFIX's own ε' solver (BiCGSTAB with line relaxation, `LEQ_IT` 20, docs/model.md §4.13),
    /// used where the multigrid-preconditioned solve breaks down
    solver_eps_fallback: Box<dyn LinearSolver>,
    solver_theta: Box<dyn LinearSolver>,
    pressure_pinned: bool,
    /// the multigrid preconditioners of the P' and ε' solves are built on the first outer
    /// iteration of a step and kept for the others ([`LinearSolver::refresh`])
    rebuild_preconditioners: bool,
    /// the closures were evaluated at the current iterate (the start of a step) and need
    /// not be evaluated again by the next outer iteration
    closures_fresh: bool,
    /// the next θ solve is the step's first: it classifies every cell afresh
    theta_class_fresh: bool,
    /// where the time went
    profile: Profile,
    /// where the residuals of the last outer iteration were largest
    worst: Worst,
}

/// Locations of the largest residuals of the last outer iteration (for diagnoses).
#[derive(Clone, Copy, Debug, Default)]
struct Worst {
    /// |residual|, phase (0 gas, m solids m), component (0 u, 1 v), node i, j
    momentum: (f64, usize, usize, usize, usize),
    /// |residual|, cell
    theta: (f64, usize),
}

fn lin(equation: &str) -> impl Fn(LinSolveError) -> TwoFluidError + '_ {
    move |source| TwoFluidError::Linear {
        equation: equation.to_string(),
        source,
    }
}

impl TwoFluid {
    /// Sets up the solver: gas at rest, εs = 0, θ = θ_small, zero pressure; the caller fills
    /// the initial fields.
    pub fn new(
        grid: Grid,
        gas: Fluid,
        gas_walls: Sides<SideBc>,
        solids_specs: Vec<SolidsSpec>,
        gravity: (f64, f64),
        settings: TwoFluidSettings,
    ) -> Result<Self, TwoFluidError> {
        if solids_specs.len() > MAX_SOLIDS_PHASES {
            return Err(TwoFluidError::TooManyPhases(solids_specs.len()));
        }
        let (nx, ny) = (grid.nx(), grid.ny());
        let n = nx * ny;
        let outlet = |b: &SideBc| !matches!(b, SideBc::Wall(_));
        let periodic = settings.periodic_x;
        if periodic && (nx != 1 || outlet(&gas_walls.west) || outlet(&gas_walls.east)) {
            return Err(TwoFluidError::PeriodicColumn(nx));
        }
        let mut pu = Pattern::new(nx + 1, ny).map_err(lin("u pattern"))?;
        let mut pv = Pattern::new(nx, ny + 1).map_err(lin("v pattern"))?;
        for j in 0..ny {
            // periodic column: node 0 is the row's unknown, node nx its copy
            if !outlet(&gas_walls.west) && !periodic {
                pu.fix(0, j).map_err(lin("u pattern"))?;
            }
            if !outlet(&gas_walls.east) {
                pu.fix(nx, j).map_err(lin("u pattern"))?;
            }
        }
        for i in 0..nx {
            if !outlet(&gas_walls.south) {
                pv.fix(i, 0).map_err(lin("v pattern"))?;
            }
            if !outlet(&gas_walls.north) {
                pv.fix(i, ny).map_err(lin("v pattern"))?;
            }
        }
        let mut pp = Pattern::new(nx, ny).map_err(lin("p' pattern"))?;
        let pressure_pinned = !gas_walls.iter().any(|(_, b)| outlet(b));
        if pressure_pinned {
            pp.fix(0, 0).map_err(lin("p' pattern"))?;
        }
        let pc = Pattern::new(nx, ny).map_err(lin("cell pattern"))?;
        // Momentum and θ are solved tighter than MFIX's LEQ_TOL = 1e-4 (docs/model.md §4.13):
        // with 1e-4 the normalised residuals of the outer iteration stall near 1e-4, the
        // size of the linear solves' own error, and θ's tolerance (1e-4) is never met.
        let transport = LinearSolverKind::transport_default(1e-8, 100);
        let mut solver_u = build(&transport);
        let mut solver_v = build(&transport);
        // The gas pressure correction is solved to 1e-2: its error is removed by the next outer
        // iteration like any other, and on family M (coarse) the results agree with a 1e-4
        // solve to 6 digits at the same outer-iteration count while the solve costs half
        // (docs/performance.md). MFIX's own pressure solves stop near 1e-1 (20 line-relaxed
        // BiCGSTAB iterations, docs/model.md §4.13).
        let mut solver_p = build(&LinearSolverKind::MultigridCg(MultigridParams {
            rtol: PRESSURE_RTOL,
            max_iter: 20,
            ..MultigridParams::default()
        }));
        let mut solver_eps = build(&LinearSolverKind::volume_fraction_default());
        let mut solver_eps_fallback = build(&LinearSolverKind::transport_default(1e-4, 20));
        let mut solver_theta = build(&transport);
        solver_u.set_pattern(&pu).map_err(lin("u"))?;
        solver_v.set_pattern(&pv).map_err(lin("v"))?;
        solver_p.set_pattern(&pp).map_err(lin("p'"))?;
        solver_eps.set_pattern(&pc).map_err(lin("eps'"))?;
        solver_eps_fallback
            .set_pattern(&pc)
            .map_err(lin("eps' (fallback)"))?;
        solver_theta.set_pattern(&pc).map_err(lin("theta"))?;
        let solids = solids_specs
            .iter()
            .map(|_| SolidsFields {
                eps: vec![0.0; n],
                u: vec![0.0; (nx + 1) * ny],
                v: vec![0.0; nx * (ny + 1)],
                theta: vec![THETA_SMALL; n],
                eps_old: vec![0.0; n],
                u_old: vec![0.0; (nx + 1) * ny],
                v_old: vec![0.0; nx * (ny + 1)],
                theta_old: vec![THETA_SMALL; n],
                rho_eps: vec![0.0; n],
                rho_eps_old: vec![0.0; n],
                p_s: vec![0.0; n],
                p_star: vec![0.0; n],
                mu: vec![0.0; n],
                lambda: vec![0.0; n],
                kappa: vec![0.0; n],
                k_cp: vec![0.0; n],
                f_gs: vec![0.0; n],
                p_kin_over_theta: vec![0.0; n],
                mu_kin: vec![0.0; n],
                lambda_kin: vec![0.0; n],
                gamma_over_theta: vec![0.0; n],
                j_slip: vec![0.0; n],
                strain: vec![Strain::default(); n],
                cells: vec![CellClosures::default(); n],
                dilute_u: vec![false; (nx + 1) * ny],
                dilute_v: vec![false; nx * (ny + 1)],
                wall_face_velocity: Sides {
                    west: vec![0.0; ny],
                    east: vec![0.0; ny],
                    south: vec![0.0; nx],
                    north: vec![0.0; nx],
                },
                tau_u: vec![0.0; (nx + 1) * ny],
                tau_v: vec![0.0; nx * (ny + 1)],
                tr_d: vec![0.0; n],
                tr_d2: vec![0.0; n],
                e_u: vec![0.0; (nx + 1) * ny],
                e_v: vec![0.0; nx * (ny + 1)],
                eps_prime: vec![0.0; n],
                imbalance: vec![0.0; n],
                a_u: Stencil5::new(pu.clone()),
                a_v: Stencil5::new(pv.clone()),
                a_eps: Stencil5::new(pc.clone()),
                a_theta: Stencil5::new(pc.clone()),
                wall_velocity: WallFaces::default(),
                wall_velocity_cycle: Sides::all(Vec::new()),
                wall_theta: WallFaces::default(),
                theta_dense: vec![false; n],
                theta_class_changes: vec![0; n],
                floor_h_u: vec![0.0; nx + 1],
            })
            .collect();
        Ok(TwoFluid {
            eps_g: vec![1.0; n],
            p_g: vec![0.0; n],
            u_g: vec![0.0; (nx + 1) * ny],
            v_g: vec![0.0; nx * (ny + 1)],
            solids,
            eps_g_old: vec![1.0; n],
            u_g_old: vec![0.0; (nx + 1) * ny],
            v_g_old: vec![0.0; nx * (ny + 1)],
            rho_eps_g: vec![gas.density; n],
            rho_eps_g_old: vec![gas.density; n],
            mu_g: vec![gas.viscosity; n],
            d_u: vec![0.0; (nx + 1) * ny],
            d_v: vec![0.0; nx * (ny + 1)],
            p_corr: vec![0.0; n],
            imbalance: vec![0.0; n],
            u_faces: FaceData::zeros(nx + 1, ny),
            v_faces: FaceData::zeros(nx, ny + 1),
            c_faces: FaceData::zeros(nx, ny),
            a_ug: Stencil5::new(pu),
            a_vg: Stencil5::new(pv),
            a_p: Stencil5::new(pp),
            solver_u,
            solver_v,
            solver_p,
            solver_eps,
            solver_eps_fallback,
            solver_theta,
            pressure_pinned,
            rebuild_preconditioners: true,
            closures_fresh: false,
            theta_class_fresh: true,
            profile: Profile::default(),
            worst: Worst::default(),
            grid,
            gas,
            gas_walls,
            gas_inflow: Sides {
                west: 0.0,
                east: 0.0,
                south: 0.0,
                north: 0.0,
            },
            solids_specs,
            gravity,
            settings,
        })
    }

    /// The grid.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// Stores the current fields as the old time level and refreshes the bulk densities.
    pub fn begin_step(&mut self) {
        self.rebuild_preconditioners = true;
        self.theta_class_fresh = true;
        self.sync_volume_fractions();
        self.eps_g_old.copy_from_slice(&self.eps_g);
        self.u_g_old.copy_from_slice(&self.u_g);
        self.v_g_old.copy_from_slice(&self.v_g);
        self.rho_eps_g_old.copy_from_slice(&self.rho_eps_g);
        for s in &mut self.solids {
            s.eps_old.copy_from_slice(&s.eps);
            s.u_old.copy_from_slice(&s.u);
            s.v_old.copy_from_slice(&s.v);
            s.theta_old.copy_from_slice(&s.theta);
            s.rho_eps_old.copy_from_slice(&s.rho_eps);
            for side in Side::ALL {
                for node in s.wall_velocity_cycle.get_mut(side) {
                    node.cycling = false;
                }
            }
        }
    }

    /// Restores the fields of the start of the step.
    pub fn restore_step(&mut self) {
        self.eps_g.copy_from_slice(&self.eps_g_old);
        self.u_g.copy_from_slice(&self.u_g_old);
        self.v_g.copy_from_slice(&self.v_g_old);
        for s in &mut self.solids {
            s.eps.copy_from_slice(&s.eps_old);
            s.u.copy_from_slice(&s.u_old);
            s.v.copy_from_slice(&s.v_old);
            s.theta.copy_from_slice(&s.theta_old);
        }
        self.sync_volume_fractions();
    }

    /// εg = 1 − Σεs and the bulk densities of every phase.
    pub fn sync_volume_fractions(&mut self) {
        let n = self.eps_g.len();
        for k in 0..n {
            self.eps_g[k] = 1.0 - self.solids.iter().map(|s| s.eps[k]).sum::<f64>();
            self.rho_eps_g[k] = self.gas.density * self.eps_g[k];
        }
        for (s, spec) in self.solids.iter_mut().zip(&self.solids_specs) {
            for k in 0..n {
                s.rho_eps[k] = spec.params.particles.density * s.eps[k];
            }
        }
    }

    /// Material density ρ_s of phase m [kg m⁻³].
    pub fn solids_density(&self, m: usize) -> f64 {
        self.solids_specs[m].params.particles.density
    }

    /// Total solids mass per unit depth of phase m [kg m⁻¹].
    pub fn solids_mass(&self, m: usize) -> f64 {
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        let rho = self.solids_specs[m].params.particles.density;
        (0..ny)
            .flat_map(|j| (0..nx).map(move |i| (i, j)))
            .map(|(i, j)| rho * self.solids[m].eps[i + nx * j] * self.grid.cell_volume(i, j))
            .sum()
    }

    /// Step 1: closures per cell and phase at the current iterate.
    fn update_closures(&mut self) {
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        for (s, spec) in self.solids.iter_mut().zip(&self.solids_specs) {
            let on_wall = wall_face_velocities(&self.grid, spec, s);
            let walls = WallVelocities {
                south: on_wall.south.then_some(&s.wall_face_velocity.south[..]),
                north: on_wall.north.then_some(&s.wall_face_velocity.north[..]),
                west: on_wall.west.then_some(&s.wall_face_velocity.west[..]),
                east: on_wall.east.then_some(&s.wall_face_velocity.east[..]),
            };
            strain_rates(&self.grid, &s.u, &s.v, &walls, &mut s.strain);
            // per cell, rows in parallel (rayon), into the closure records; then scattered
            // into the field arrays the assemblies read
            let (u_g, v_g) = (&self.u_g, &self.v_g);
            let (u, v, eps, theta, strain) = (&s.u, &s.v, &s.eps, &s.theta, &s.strain);
            let params = &spec.params;
            // tasks of at least PAR_MIN_CELLS cells: a small grid runs as one task
            let rows_per_task = PAR_MIN_CELLS.div_ceil(nx);
            s.cells
                .par_chunks_mut(nx)
                .with_min_len(rows_per_task)
                .enumerate()
                .for_each(|(j, row)| {
                    for (i, out) in row.iter_mut().enumerate() {
                        let k = i + nx * j;
                        if eps[k] == 0.0 {
                            // no solids: every closure value the solver reads is zero
                            // (runout-closures gives exactly that at εs = 0; checked by
                            // the test `closures_vanish_without_solids`)
                            *out = CellClosures::default();
                            continue;
                        }
                        // |u_g − u_s| from cell-centred averages of the face velocities (§2.6)
                        let du = 0.5
                            * ((u_g[i + (nx + 1) * j] - u[i + (nx + 1) * j])
                                + (u_g[i + 1 + (nx + 1) * j] - u[i + 1 + (nx + 1) * j]));
                        let dv = 0.5 * ((v_g[k] - v[k]) + (v_g[k + nx] - v[k + nx]));
                        let st = strain[k];
                        *out = CellClosures::evaluate(
                            &CellState {
                                eps_s: eps[k],
                                theta: theta[k].max(THETA_SMALL),
                                slip: (du * du + dv * dv).sqrt(),
                                tr_d: st.tr_d,
                                s_ddot_s: st.s_ddot_s,
                            },
                            params,
                        );
                    }
                });
            for k in 0..nx * ny {
                let c = s.cells[k];
                s.p_s[k] = c.p_s;
                s.p_star[k] = c.p_star; // P* from the current εs (docs/model.md §2.4.1)
                s.mu[k] = c.mu;
                s.lambda[k] = c.lambda;
                s.kappa[k] = c.kappa;
                s.k_cp[k] = c.k_cp;
                s.f_gs[k] = c.f_gs;
                s.p_kin_over_theta[k] = c.p_kin_over_theta;
                s.mu_kin[k] = c.mu_kin;
                s.lambda_kin[k] = c.lambda_kin;
                s.gamma_over_theta[k] = c.gamma_over_theta;
                s.j_slip[k] = c.j_slip;
                s.tr_d[k] = s.strain[k].tr_d;
                s.tr_d2[k] = s.strain[k].tr_d2;
            }
        }
    }

    /// Per-face closures of the state-dependent walls from the current iterate (lagged one
    /// outer iteration, docs/model.md §3.5 last line), with the near-wall state gathered as MFIX
    /// does (docs/model.md §3.5, §3.6; `calc_grbdry.f`, `calc_s_ddot_s.f`, `bc_theta.f`). The
    /// ghost values MFIX stores are those the previous closures imply ([`RobinFace::ghost`]):
    /// - momentum, at each tangential-velocity node of the wall: εs interpolated between the
    ///   two fluid cells; θ the mean of the ghost- and fluid-row means over those cells
    ///   ([`corner_theta`]); the slip from the face value (mean of ghost and fluid); the
    ///   strain rate at the wall location, with the normal derivative of the tangential
    ///   velocity (U_F − U_G)/Δ, the normal derivative of the normal velocity from its value
    ///   at the fluid cell centre and zero on the wall, and the derivative along the wall
    ///   from the ghost/fluid-mean velocities at the two cell centres;
    /// - θ, at each wall cell: the fluid cell's εs; θ the mean of ghost and fluid
    ///   ([`face_theta`]); the slip from the ghost/fluid-mean tangential velocity at the cell
    ///   centre.
    ///
    /// Gas–solids slips use the gas's own wall face values.
    pub(crate) fn update_walls(&mut self) {
        let grid = &self.grid;
        let (nx, ny) = (grid.nx(), grid.ny());
        let (dx, dy) = (grid.x.widths(), grid.y.widths());
        let (dxc, dyc) = (grid.x.face_spacing(), grid.y.face_spacing());
        let wall_relax = self.settings.relax_wall_closures;
        let oscillating_only = self.settings.relax_wall_closures_oscillating_only;
        for (s, spec) in self.solids.iter_mut().zip(&self.solids_specs) {
            for side in [Side::West, Side::East, Side::South, Side::North] {
                let Some(model) = spec.wall_models.get(side) else {
                    continue;
                };
                let u_w = model.wall_velocity();
                // along a south/north wall the tangential component is u (nodes 0..=nx,
                // cells k−1 and k of the wall row); along west/east it is v
                let horizontal = matches!(side, Side::South | Side::North);
                // +1 where the wall is on the low side of the fluid (south, west)
                let sign = if matches!(side, Side::South | Side::West) {
                    1.0
                } else {
                    -1.0
                };
                let (row, n_cells) = match side {
                    Side::South => (0, nx),
                    Side::North => (ny - 1, nx),
                    Side::West => (0, ny),
                    Side::East => (nx - 1, ny),
                };
                let cell = |along: usize| {
                    if horizontal {
                        along + nx * row
                    } else {
                        row + nx * along
                    }
                };
                let delta = if horizontal { dy[row] } else { dx[row] };
                let along_spacing = if horizontal { dxc } else { dyc };
                // tangential velocity of phase field `f` at node k of the fluid row
                let tangential = |f_u: &[f64], f_v: &[f64], k: usize| {
                    if horizontal {
                        f_u[k + (nx + 1) * row]
                    } else {
                        f_v[row + nx * k]
                    }
                };
                // normal velocity at the fluid cell centre (zero on the wall face)
                let normal_centre = |c: usize| {
                    let (i, j) = (c % nx, c / nx);
                    if horizontal {
                        0.5 * (s.v[i + nx * j] + s.v[i + nx * (j + 1)])
                    } else {
                        0.5 * (s.u[i + (nx + 1) * j] + s.u[i + 1 + (nx + 1) * j])
                    }
                };
                let gas_face = match self.gas_walls.get(side) {
                    SideBc::Wall(face) => Some(*face),
                    _ => None,
                };
                let gas_face_value = |vel: f64| gas_face.map_or(vel, |f| f.face_value(vel, delta));
                let face_velocity = match side {
                    Side::West => &s.wall_face_velocity.west,
                    Side::East => &s.wall_face_velocity.east,
                    Side::South => &s.wall_face_velocity.south,
                    Side::North => &s.wall_face_velocity.north,
                };
                let (velocity_slot, theta_slot) = match side {
                    Side::West => (&mut s.wall_velocity.west, &mut s.wall_theta.west),
                    Side::East => (&mut s.wall_velocity.east, &mut s.wall_theta.east),
                    Side::South => (&mut s.wall_velocity.south, &mut s.wall_theta.south),
                    Side::North => (&mut s.wall_velocity.north, &mut s.wall_theta.north),
                };
                // last iteration's closures (allocated on first use only); a first
                // evaluation starts from zero gradient (ghost = fluid)
                let mut faces = velocity_slot
                    .take()
                    .unwrap_or_else(|| vec![RobinFace::ZERO_GRADIENT; n_cells + 1]);
                let mut theta_faces = theta_slot
                    .take()
                    .unwrap_or_else(|| vec![RobinFace::ZERO_GRADIENT; n_cells]);
                let mut cycle = std::mem::take(s.wall_velocity_cycle.get_mut(side));
                if oscillating_only && wall_relax < 1.0 {
                    cycle.resize(n_cells + 1, ClosureCycle::default());
                }
                let ghost_theta = |c_along: usize| {
                    let c = cell(c_along);
                    theta_faces[c_along].ghost(s.theta[c], delta)
                };
                for k in 0..=n_cells {
                    // the cells beside node k (one at a corner)
                    let lo = k.checked_sub(1);
                    let hi = (k < n_cells).then_some(k);
                    let (c_lo, c_hi) = (lo.or(hi).unwrap(), hi.or(lo).unwrap());
                    let weight = match (lo, hi) {
                        (Some(a), Some(_)) => {
                            if horizontal {
                                grid.x.interpolation_weight(a)
                            } else {
                                grid.y.interpolation_weight(a)
                            }
                        }
                        _ => 0.5,
                    };
                    let interp =
                        |f: &[f64]| weight * f[cell(c_lo)] + (1.0 - weight) * f[cell(c_hi)];
                    let vel = tangential(&s.u, &s.v, k);
                    let closure = faces[k];
                    let ghost = closure.ghost(vel, delta);
                    let face_vel = closure.face_value(vel, delta);
                    // strain rate at the wall location (CALC_S_DDOT_S)
                    let d_tangent_normal = sign * (vel - ghost) / delta;
                    let d_normal =
                        sign * 0.5 * (normal_centre(cell(c_lo)) + normal_centre(cell(c_hi)))
                            / delta;
                    let d_along = match (lo, hi) {
                        (Some(a), Some(b)) => {
                            (face_velocity[b] - face_velocity[a]) / along_spacing[k]
                        }
                        _ => 0.0,
                    };
                    // (along, normal) play the roles of (x, y) of a floor on every side
                    let strain = WallStrain::planar_floor(d_along, d_tangent_normal, 0.0, d_normal);
                    let theta_rows = corner_theta(
                        0.5 * (ghost_theta(c_lo) + ghost_theta(c_hi)),
                        0.5 * (s.theta[cell(c_lo)] + s.theta[cell(c_hi)]),
                    );
                    let gas_vel = gas_face_value(tangential(&self.u_g, &self.v_g, k));
                    let state = MomentumWallState {
                        // MFIX's IJK2 for U(i) is the cell west of the face (cell i)
                        eps_s_fluid: s.eps[cell(c_lo)],
                        eps_s: interp(&s.eps),
                        theta: theta_rows,
                        slip: (face_vel - u_w).abs(),
                        gas_slip: (gas_vel - face_vel).abs(),
                        tr_d: strain.tr_d,
                        s_ddot_s: strain.s_ddot_s,
                        s_nn: strain.s_nn,
                    };
                    let wall = model.momentum(&state, &spec.params);
                    if side == Side::South {
                        s.floor_h_u[k] = wall.diagnostics.h_u;
                    }
                    faces[k] = if oscillating_only && wall_relax < 1.0 {
                        let node = &mut cycle[k];
                        node.cycling |= turns_back(wall.face.h - closure.h, node.last_change);
                        let w = if node.cycling { wall_relax } else { 1.0 };
                        let applied = relax_face(wall.face, closure, w);
                        node.last_change = applied.h - closure.h;
                        applied
                    } else {
                        relax_face(wall.face, closure, wall_relax)
                    };
                }
                *s.wall_velocity_cycle.get_mut(side) = cycle;
                for along in 0..n_cells {
                    let c = cell(along);
                    let (i, j) = (c % nx, c / nx);
                    let gas_centre = if horizontal {
                        0.5 * (gas_face_value(self.u_g[i + (nx + 1) * j])
                            + gas_face_value(self.u_g[i + 1 + (nx + 1) * j]))
                    } else {
                        0.5 * (gas_face_value(self.v_g[c]) + gas_face_value(self.v_g[c + nx]))
                    };
                    let state = ThetaWallState {
                        eps_s: s.eps[c],
                        theta: face_theta(theta_faces[along].ghost(s.theta[c], delta), s.theta[c]),
                        slip: (face_velocity[along] - u_w).abs(),
                        gas_slip: (gas_centre - face_velocity[along]).abs(),
                    };
                    // this cell's θ ghost was read by its two nodes above and just now
                    theta_faces[along] = model.granular_temperature(&state, &spec.params).face;
                }
                match side {
                    Side::West => {
                        (s.wall_velocity.west, s.wall_theta.west) = (Some(faces), Some(theta_faces))
                    }
                    Side::East => {
                        (s.wall_velocity.east, s.wall_theta.east) = (Some(faces), Some(theta_faces))
                    }
                    Side::South => {
                        (s.wall_velocity.south, s.wall_theta.south) =
                            (Some(faces), Some(theta_faces))
                    }
                    Side::North => {
                        (s.wall_velocity.north, s.wall_theta.north) =
                            (Some(faces), Some(theta_faces))
                    }
                }
            }
        }
    }

    /// One outer iteration with time step `dt`.
    pub fn outer_iteration(&mut self, dt: f64) -> Result<TwoFluidResiduals, TwoFluidError> {
        if !std::mem::take(&mut self.closures_fresh) {
            let t = Instant::now();
            self.update_closures();
            self.profile.closures += since(t);
        }
        let t = Instant::now();
        self.update_walls();
        self.profile.walls += since(t);
        let t = Instant::now();
        let momentum = self.momentum(dt)?;
        self.profile.momentum_assembly += since(t);
        let t = Instant::now();
        let solids_mass = self.volume_fraction_correction(dt)?;
        self.profile.eps_assembly += since(t);
        let t = Instant::now();
        let gas_mass = self.pressure_correction(dt)?;
        self.profile.pressure_assembly += since(t);
        let t = Instant::now();
        let theta = self.granular_energy(dt)?;
        self.profile.theta_assembly += since(t);
        Ok(TwoFluidResiduals {
            momentum,
            gas_mass,
            solids_mass,
            theta,
        })
    }

    /// Step 2: momentum predictor of every phase with partial elimination of the drag.
    fn momentum(&mut self, dt: f64) -> Result<f64, TwoFluidError> {
        self.worst.momentum = (0.0, 0, 0, 0, 0);
        let grid = &self.grid;
        let (nx, ny) = (grid.nx(), grid.ny());
        let (dx, dy) = (grid.x.widths(), grid.y.widths());
        let scheme = self.settings.scheme;
        let gravity = self.gravity;
        let ctx_gas = Context {
            grid,
            bcs: &self.gas_walls,
            gravity,
            dt,
            scheme,
            gas_pressure: &self.p_g,
            wall_faces: None,
            periodic_x: self.settings.periodic_x,
        };
        let gas_fields = PhaseFields {
            bulk_density: &self.rho_eps_g,
            bulk_density_old: &self.rho_eps_g_old,
            volume_fraction: &self.eps_g,
            viscosity: &self.mu_g,
            solids_pressure: None,
            plastic_pressure: None,
            // the gas's own cross terms are left out: with uniform μ_g they reduce to
            // μ_g ∇(∇·u_g), negligible here (μ_g = 1.8e-5 Pa s)
            explicit_source: None,
            skip: None,
        };
        assemble_u(
            &ctx_gas,
            &gas_fields,
            &self.u_g,
            &self.v_g,
            &self.u_g_old,
            &mut self.u_faces,
            &mut self.a_ug,
        );
        assemble_v(
            &ctx_gas,
            &gas_fields,
            &self.u_g,
            &self.v_g,
            &self.v_g_old,
            &mut self.v_faces,
            &mut self.a_vg,
        );
        for (s, spec) in self.solids.iter_mut().zip(&self.solids_specs) {
            // dilute faces (interpolated εs ≤ DIL_EP_S, docs/model.md §2.7): their rows are
            // replaced below, so the assembly skips them (most of a slide's domain)
            dilute_faces(
                grid,
                &s.eps,
                self.a_ug.pattern().fixed_mask(),
                0,
                &mut s.dilute_u,
            );
            dilute_faces(
                grid,
                &s.eps,
                self.a_vg.pattern().fixed_mask(),
                1,
                &mut s.dilute_v,
            );
            let ctx = Context {
                grid,
                bcs: &spec.walls,
                gravity,
                dt,
                scheme,
                gas_pressure: &self.p_g,
                wall_faces: Some(&s.wall_velocity),
                periodic_x: self.settings.periodic_x,
            };
            let fields = PhaseFields {
                bulk_density: &s.rho_eps,
                bulk_density_old: &s.rho_eps_old,
                volume_fraction: &s.eps,
                viscosity: &s.mu,
                solids_pressure: Some(&s.p_s),
                // −∇P* only with Schaeffer (docs/model.md §4.4); none with Princeton, where MFIX
                // never computes P* (§2.4.2)
                plastic_pressure: (spec.params.friction_model == FrictionModel::Schaeffer)
                    .then_some(&s.p_star[..]),
                explicit_source: Some(&s.tau_u),
                skip: Some(&s.dilute_u),
            };
            assemble_u(
                &ctx,
                &fields,
                &s.u,
                &s.v,
                &s.u_old,
                &mut self.u_faces,
                &mut s.a_u,
            );
            assemble_v(
                &ctx,
                &PhaseFields {
                    explicit_source: Some(&s.tau_v),
                    skip: Some(&s.dilute_v),
                    ..fields
                },
                &s.u,
                &s.v,
                &s.v_old,
                &mut self.v_faces,
                &mut s.a_v,
            );
        }
        let relax = self.settings.relax_velocity;
        let periodic = self.settings.periodic_x;
        let m = self.solids.len();
        let mut residual = 0.0;
        // u: nodes at x-faces; drag averaged to the face by volume (VF_GS_X)
        for dir in 0..2 {
            let (mx, my) = if dir == 0 { (nx + 1, ny) } else { (nx, ny + 1) };
            let (mut num, mut den) = (0.0, 0.0);
            for j in 0..my {
                for i in 0..mx {
                    let k = i + mx * j;
                    let gas_a = if dir == 0 { &self.a_ug } else { &self.a_vg };
                    if gas_a.pattern().fixed_mask()[k] {
                        continue;
                    }
                    // the cells beside the node and their half volumes
                    let (c0, c1, h0, h1) = if dir == 0 {
                        // a periodic column's node 0 lies between cell nx − 1 and cell 0
                        let west = if periodic && i == 0 {
                            Some(nx - 1)
                        } else {
                            i.checked_sub(1)
                        };
                        let w = west.map(|c| (c + nx * j, 0.5 * dx[c] * dy[j]));
                        let e = (i < nx).then(|| (i + nx * j, 0.5 * dx[i] * dy[j]));
                        (
                            w.map(|x| x.0),
                            e.map(|x| x.0),
                            w.map_or(0.0, |x| x.1),
                            e.map_or(0.0, |x| x.1),
                        )
                    } else {
                        let s_ = j.checked_sub(1).map(|r| (i + nx * r, 0.5 * dx[i] * dy[r]));
                        let n_ = (j < ny).then(|| (i + nx * j, 0.5 * dx[i] * dy[j]));
                        (
                            s_.map(|x| x.0),
                            n_.map(|x| x.0),
                            s_.map_or(0.0, |x| x.1),
                            n_.map_or(0.0, |x| x.1),
                        )
                    };
                    let mut a_in = [0.0; MAX_SOLIDS_PHASES + 1];
                    let mut r_in = [0.0; MAX_SOLIDS_PHASES + 1];
                    let mut phi = [0.0; MAX_SOLIDS_PHASES + 1];
                    let mut drag = [0.0; MAX_SOLIDS_PHASES];
                    let gas_phi: &[f64] = if dir == 0 { &self.u_g } else { &self.v_g };
                    a_in[0] = gas_a.a_p[k];
                    r_in[0] = neighbour_sum(gas_a, gas_phi, k);
                    phi[0] = gas_phi[k];
                    let mut dilute = [false; MAX_SOLIDS_PHASES];
                    for (p, s) in self.solids.iter().enumerate() {
                        let (a, field) = if dir == 0 {
                            (&s.a_u, &s.u)
                        } else {
                            (&s.a_v, &s.v)
                        };
                        // a face whose interpolated εs ≤ DIL_EP_S carries no solids momentum
                        // (MFIX `source_u_s.f`, docs/model.md §2.7): its velocity is set below
                        dilute[p] = if dir == 0 {
                            s.dilute_u[k]
                        } else {
                            s.dilute_v[k]
                        };
                        a_in[p + 1] = if dilute[p] { 1.0 } else { a.a_p[k] };
                        r_in[p + 1] = if dilute[p] {
                            field[k]
                        } else {
                            neighbour_sum(a, field, k)
                        };
                        phi[p + 1] = field[k];
                        drag[p] = if dilute[p] {
                            0.0
                        } else {
                            c0.map_or(0.0, |c| s.f_gs[c] * h0) + c1.map_or(0.0, |c| s.f_gs[c] * h1)
                        };
                    }
                    // momentum residuals of the coupled node (before relaxation, §4.11):
                    // only where the phase moves, |(U, V)| > 1e-15 with U, V the two face
                    // velocities MFIX stores at one index (the east and north faces of the
                    // cell west of a u-node, south of a v-node)
                    for p in 0..=m {
                        if p > 0 && dilute[p - 1] {
                            continue;
                        }
                        let (pu, pv): (&[f64], &[f64]) = if p == 0 {
                            (&self.u_g, &self.v_g)
                        } else {
                            (&self.solids[p - 1].u, &self.solids[p - 1].v)
                        };
                        let other = match (dir, c0) {
                            (0, Some(c)) => pv[c + nx],
                            (1, Some(c)) => pu[c + c / nx + 1],
                            _ => 0.0,
                        };
                        let speed = (phi[p] * phi[p] + other * other).sqrt();
                        if speed <= 1e-15 {
                            continue;
                        }
                        let coupling = if p == 0 {
                            (0..m).map(|q| drag[q] * (phi[q + 1] - phi[0])).sum::<f64>()
                        } else {
                            drag[p - 1] * (phi[0] - phi[p])
                        };
                        let res = (r_in[p] + coupling - a_in[p] * phi[p]).abs();
                        num += res;
                        den += a_in[p].abs() * speed;
                        if res > self.worst.momentum.0 {
                            self.worst.momentum = (res, p, dir, i, j);
                        }
                    }
                    let (mut a_out, mut r_out) =
                        ([0.0; MAX_SOLIDS_PHASES + 1], [0.0; MAX_SOLIDS_PHASES + 1]);
                    eliminate_node(
                        &a_in[..=m],
                        &r_in[..=m],
                        &phi[..=m],
                        &drag[..m],
                        &mut a_out[..=m],
                        &mut r_out[..=m],
                    );
                    // area of the node's face for d and e
                    let area = if dir == 0 { dy[j] } else { dx[i] };
                    // relaxed centre coefficients, d_g (docs/model.md §4.6), e_s (§4.7)
                    let gas_ap = a_out[0] / relax;
                    let eps_face_g = face_mean(&self.eps_g, c0, c1);
                    let mut numerator = eps_face_g;
                    let mut denominator = a_in[0] / relax;
                    for (p, s) in self.solids.iter_mut().enumerate() {
                        let a_s = a_in[p + 1] / relax;
                        let f = drag[p];
                        let eps_face_s = face_mean(&s.eps, c0, c1);
                        numerator += eps_face_s * f / (a_s + f);
                        denominator += f * a_s / (a_s + f);
                        let (a, field, e) = if dir == 0 {
                            (&mut s.a_u, &s.u, &mut s.e_u)
                        } else {
                            (&mut s.a_v, &s.v, &mut s.e_v)
                        };
                        if dilute[p] {
                            dilute_row(a, k, field[k], c0.or(c1), &s.eps, (mx, my), nx);
                            e[k] = 0.0;
                            continue;
                        }
                        e[k] = area / a_s;
                        let ap = a_out[p + 1] / relax;
                        a.b[k] += (r_out[p + 1] - r_in[p + 1]) + (1.0 - relax) * ap * field[k];
                        a.a_p[k] = ap;
                    }
                    let (gas_a, gas_phi, d) = if dir == 0 {
                        (&mut self.a_ug, &self.u_g, &mut self.d_u)
                    } else {
                        (&mut self.a_vg, &self.v_g, &mut self.d_v)
                    };
                    gas_a.b[k] += (r_out[0] - r_in[0]) + (1.0 - relax) * gas_ap * gas_phi[k];
                    gas_a.a_p[k] = gas_ap;
                    d[k] = area * numerator / denominator;
                    if periodic && dir == 0 {
                        // a periodic column has no x gradient of P'_g or of K_cp ε'
                        d[k] = 0.0;
                        self.solids.iter_mut().for_each(|s| s.e_u[k] = 0.0);
                    }
                }
            }
            residual += if den > 0.0 { num / den } else { num };
            // fixed nodes: walls, zero velocity (the gas's inflow through a distributor),
            // no d or e
            let inflow = self.gas_inflow.clone();
            let gas_fixed = |k: usize| gas_fixed_velocity(&inflow, (nx, ny), dir, k);
            let gas_a = if dir == 0 {
                &mut self.a_ug
            } else {
                &mut self.a_vg
            };
            let d = if dir == 0 {
                &mut self.d_u
            } else {
                &mut self.d_v
            };
            for k in 0..d.len() {
                if gas_a.pattern().fixed_mask()[k] {
                    fixed_row(gas_a, k, gas_fixed(k));
                    d[k] = 0.0;
                    for s in self.solids.iter_mut() {
                        let (a, e) = if dir == 0 {
                            (&mut s.a_u, &mut s.e_u)
                        } else {
                            (&mut s.a_v, &mut s.e_v)
                        };
                        fixed_row(a, k, 0.0);
                        e[k] = 0.0;
                    }
                }
            }
        }
        let t = Instant::now();
        let mut iterations = 0;
        iterations += self
            .solver_u
            .setup_and_solve(&self.a_ug, &mut self.u_g)
            .map_err(lin("gas u momentum"))?
            .iterations;
        iterations += self
            .solver_v
            .setup_and_solve(&self.a_vg, &mut self.v_g)
            .map_err(lin("gas v momentum"))?
            .iterations;
        for s in self.solids.iter_mut() {
            iterations += self
                .solver_u
                .setup_and_solve(&s.a_u, &mut s.u)
                .map_err(lin("solids u momentum"))?
                .iterations;
            iterations += self
                .solver_v
                .setup_and_solve(&s.a_v, &mut s.v)
                .map_err(lin("solids v momentum"))?
                .iterations;
        }
        self.profile.iterations.momentum += iterations as u64;
        if periodic {
            // node nx of a periodic column is node 0 (fixed in the solves)
            let mx = nx + 1;
            for u in std::iter::once(&mut self.u_g).chain(self.solids.iter_mut().map(|s| &mut s.u))
            {
                (0..ny).for_each(|j| u[nx + mx * j] = u[mx * j]);
            }
        }
        // solves are reported apart from the assembly that encloses them
        let solve = since(t);
        self.profile.momentum_solve += solve;
        self.profile.momentum_assembly -= solve;
        Ok(residual)
    }

    /// Step 3: ε correction of each solids phase; returns the mean |imbalance| summed.
    fn volume_fraction_correction(&mut self, dt: f64) -> Result<f64, TwoFluidError> {
        let n = self.eps_g.len() as f64;
        let mut total = 0.0;
        for (s, spec) in self.solids.iter_mut().zip(&self.solids_specs) {
            let inputs = CorrectionInputs {
                density: spec.params.particles.density,
                eps: &s.eps,
                eps_old: &s.eps_old,
                u: &s.u,
                v: &s.v,
                e_u: &s.e_u,
                e_v: &s.e_v,
                k_cp: &s.k_cp,
                dt,
                scheme: self.settings.scheme,
                periodic_x: self.settings.periodic_x,
            };
            assemble_correction(&self.grid, &inputs, &mut s.imbalance, &mut s.a_eps);
            total += s.imbalance.iter().map(|x| x.abs()).sum::<f64>() / n;
            s.eps_prime.iter_mut().for_each(|x| *x = 0.0);
            let t = Instant::now();
            let mut iterations = 0;
            let solved = solve_keeping_preconditioner(
                self.solver_eps.as_mut(),
                &s.a_eps,
                &mut s.eps_prime,
                // ε' is rebuilt every iteration: its K_cp terms change too much within a
                // step (kept, the solves took 17 % longer on family M)
                true,
            )
            .map(|n| iterations += n);
            if let Err(LinSolveError::Breakdown { .. }) = solved {
                // the multigrid-preconditioned BiCGSTAB broke down (seen at its first
                // iteration on the paper grid of the sensitivity slide, during the fall):
                // solve with MFIX's own ε' method (§4.13) instead of failing the step
                tracing::debug!("eps' solve: multigrid breakdown, line-relaxed BiCGSTAB instead");
                s.eps_prime.iter_mut().for_each(|x| *x = 0.0);
                solve_keeping_preconditioner(
                    self.solver_eps_fallback.as_mut(),
                    &s.a_eps,
                    &mut s.eps_prime,
                    true,
                )
                .map(|n| iterations += n)
            } else {
                solved
            }
            .map_err(lin("solids volume fraction"))?;
            self.profile.iterations.eps += iterations as u64;
            let solve = since(t);
            self.profile.eps_solve += solve;
            self.profile.eps_assembly -= solve;
            apply_correction(
                &self.grid,
                &mut s.eps_prime,
                &mut s.eps,
                spec.eps_max,
                self.settings.relax_eps,
                &mut s.u,
                &mut s.v,
                &s.e_u,
                &s.e_v,
                &s.k_cp,
            );
            // (Schaeffer only) P* from the corrected εs (docs/model.md §4.9 step 5)
            if spec.params.friction_model == FrictionModel::Schaeffer {
                for (p, &e) in s.p_star.iter_mut().zip(&s.eps) {
                    *p = p_star(e, &spec.params.friction);
                }
            }
        }
        self.sync_volume_fractions();
        Ok(total)
    }

    /// Step 4: gas pressure correction from gas continuity (docs/model.md §4.6).
    fn pressure_correction(&mut self, dt: f64) -> Result<f64, TwoFluidError> {
        let grid = &self.grid;
        let (nx, ny) = (grid.nx(), grid.ny());
        let (dx, dy) = (grid.x.widths(), grid.y.widths());
        let rho = self.gas.density;
        let eps = &self.eps_g;
        let scheme = self.settings.scheme;
        // face εg (MFIX `DISCRETIZE(1)`, docs/model.md §4.2): upwind or Superbee between the
        // cells lo and hi, `stride` apart; the inside cell's on the domain boundary
        let face = |vel: f64, lo: Option<usize>, hi: Option<usize>, stride: usize| -> f64 {
            match (lo, hi) {
                (Some(l), Some(h)) => face_value(
                    scheme,
                    eps,
                    l.checked_sub(stride)
                        .filter(|&x| same_line(x, l, stride, nx)),
                    l,
                    h,
                    Some(h + stride).filter(|&x| x < eps.len() && same_line(h, x, stride, nx)),
                    vel,
                ),
                (Some(c), None) | (None, Some(c)) => eps[c],
                (None, None) => 0.0,
            }
        };
        let a = &mut self.a_p;
        let mut total = 0.0;
        for j in 0..ny {
            for i in 0..nx {
                let k = i + nx * j;
                let (kw, ke) = (i + (nx + 1) * j, i + 1 + (nx + 1) * j);
                let (ks, kn) = (i + nx * j, i + nx * (j + 1));
                let west = (i > 0).then(|| k - 1);
                let east = (i + 1 < nx).then_some(k + 1);
                let south = (j > 0).then(|| k - nx);
                let north = (j + 1 < ny).then_some(k + nx);
                // gas entering through a distributor is pure gas (MFIX BC_EP_G = 1)
                let inlet = |at_side: bool, inflow: f64, value: f64| {
                    if at_side && inflow != 0.0 {
                        1.0
                    } else {
                        value
                    }
                };
                let f = &self.gas_inflow;
                let ew = inlet(i == 0, f.west, face(self.u_g[kw], west, Some(k), 1));
                let ee = inlet(i + 1 == nx, f.east, face(self.u_g[ke], Some(k), east, 1));
                let es = inlet(j == 0, f.south, face(self.v_g[ks], south, Some(k), nx));
                let en = inlet(j + 1 == ny, f.north, face(self.v_g[kn], Some(k), north, nx));
                let volume = dx[i] * dy[j];
                let b = rho
                    * (-(eps[k] - self.eps_g_old[k]) * volume / dt + ew * self.u_g[kw] * dy[j]
                        - ee * self.u_g[ke] * dy[j]
                        + es * self.v_g[ks] * dx[i]
                        - en * self.v_g[kn] * dx[i]);
                self.imbalance[k] = b;
                total += b.abs();
                if self.pressure_pinned && k == 0 {
                    fixed_row(a, k, 0.0);
                    continue;
                }
                let ce = rho * ee * self.d_u[ke] * dy[j];
                let cw = rho * ew * self.d_u[kw] * dy[j];
                let cn = rho * en * self.d_v[kn] * dx[i];
                let cs = rho * es * self.d_v[ks] * dx[i];
                a.a_e[k] = if east.is_some() { ce } else { 0.0 };
                a.a_w[k] = if west.is_some() { cw } else { 0.0 };
                a.a_n[k] = if north.is_some() { cn } else { 0.0 };
                a.a_s[k] = if south.is_some() { cs } else { 0.0 };
                a.a_p[k] = ce + cw + cn + cs;
                a.b[k] = b;
            }
        }
        self.p_corr.iter_mut().for_each(|x| *x = 0.0);
        let t = Instant::now();
        self.profile.iterations.pressure += solve_keeping_preconditioner(
            self.solver_p.as_mut(),
            &self.a_p,
            &mut self.p_corr,
            self.rebuild_preconditioners,
        )
        .map_err(lin("gas pressure correction"))?
            as u64;
        // both multigrid hierarchies of this step are built (ε' is solved first)
        self.rebuild_preconditioners = false;
        let solve = since(t);
        self.profile.pressure_solve += solve;
        self.profile.pressure_assembly -= solve;
        let pc = &self.p_corr;
        for j in 0..ny {
            for i in 0..=nx {
                let k = i + (nx + 1) * j;
                if self.d_u[k] != 0.0 {
                    let p_w = if i == 0 { 0.0 } else { pc[i - 1 + nx * j] };
                    let p_e = if i == nx { 0.0 } else { pc[i + nx * j] };
                    self.u_g[k] += self.d_u[k] * (p_w - p_e);
                }
            }
        }
        for j in 0..=ny {
            for i in 0..nx {
                let k = i + nx * j;
                if self.d_v[k] != 0.0 {
                    let p_s = if j == 0 { 0.0 } else { pc[i + nx * (j - 1)] };
                    let p_n = if j == ny { 0.0 } else { pc[i + nx * j] };
                    self.v_g[k] += self.d_v[k] * (p_s - p_n);
                }
            }
        }
        let w = self.settings.relax_pressure;
        self.p_g.iter_mut().zip(pc).for_each(|(p, c)| *p += w * c);
        Ok(total / (nx * ny) as f64)
    }

    /// Step 5: granular energy of each solids phase (docs/model.md §4.8).
    fn granular_energy(&mut self, dt: f64) -> Result<f64, TwoFluidError> {
        let mut worst_theta = (0.0, 0);
        let relax = self.settings.relax_theta;
        let nx = self.grid.nx();
        let mut residual = 0.0;
        for (s, spec) in self.solids.iter_mut().zip(&self.solids_specs) {
            let inputs = EnergyInputs {
                bulk_density: &s.rho_eps,
                bulk_density_old: &s.rho_eps_old,
                conductivity: &s.kappa,
                p_kin_over_theta: &s.p_kin_over_theta,
                mu_kin: &s.mu_kin,
                lambda_kin: &s.lambda_kin,
                dissipation_over_theta: &s.gamma_over_theta,
                drag: &s.f_gs,
                slip_production: &s.j_slip,
                tr_d: &s.tr_d,
                tr_d2: &s.tr_d2,
            };
            assemble_theta(
                &self.grid,
                &inputs,
                &spec.theta_walls,
                Some(&s.wall_theta),
                &s.u,
                &s.v,
                &s.theta_old,
                dt,
                self.settings.scheme,
                &s.theta,
                &mut self.c_faces,
                &mut s.a_theta,
            );
            // the class of each θ row: MFIX's εs > DIL_EP_S, unless frozen (a cycling cell)
            let freeze = self.settings.freeze_cycling_dilute_class && !self.theta_class_fresh;
            for k in 0..s.theta.len() {
                let dense_now = s.eps[k] > DIL_EP_S;
                if freeze {
                    next_dilute_class(
                        dense_now,
                        &mut s.theta_dense[k],
                        &mut s.theta_class_changes[k],
                    );
                } else {
                    s.theta_dense[k] = dense_now;
                    s.theta_class_changes[k] = 0;
                }
            }
            let a = &mut s.a_theta;
            let (mut num, mut den) = (0.0, 0.0);
            // Schaeffer: θ = θ_small where εg < εg* (docs/model.md §1.3), as a fixed row before
            // the residual and not relaxed (MFIX `solve_granular_energy.f`, `under_relax.f`)
            let eps_g_star = (spec.params.friction_model == FrictionModel::Schaeffer)
                .then_some(1.0 - spec.params.friction.eps_s_max);
            for k in 0..s.theta.len() {
                if !s.theta_dense[k] {
                    // the mean θ of the neighbours with εs > DIL_EP_S, or kept if none
                    // (docs/model.md §4.8, MFIX `source_phi.f`)
                    dilute_cell_row(a, k, s.theta[k], &s.theta_dense, nx);
                    continue;
                }
                let forced = eps_g_star.is_some_and(|star| self.eps_g[k] < star);
                if forced {
                    fixed_row(a, k, THETA_SMALL); // docs/model.md §1.3 (Schaeffer)
                }
                let nb = neighbour_sum(a, &s.theta, k) - a.a_p[k] * s.theta[k];
                num += nb.abs();
                if nb.abs() > worst_theta.0 {
                    worst_theta = (nb.abs(), k);
                }
                den += (a.a_p[k] * s.theta[k]).abs();
                if forced {
                    continue; // fixed rows are not relaxed (MFIX `under_relax.f`, §1.3)
                }
                let ap = a.a_p[k] / relax;
                a.b[k] += (1.0 - relax) * ap * s.theta[k];
                a.a_p[k] = ap;
            }
            residual += if den > 0.0 { num / den } else { num };
            let t = Instant::now();
            self.profile.iterations.theta += self
                .solver_theta
                .setup_and_solve(&s.a_theta, &mut s.theta)
                .map_err(lin("granular energy"))?
                .iterations as u64;
            let solve = since(t);
            self.profile.theta_solve += solve;
            self.profile.theta_assembly -= solve;
            s.theta.iter_mut().for_each(|t| *t = t.max(THETA_SMALL));
        }
        self.theta_class_fresh = false;
        self.worst.theta = worst_theta;
        Ok(residual)
    }

    /// Where the residuals of the last outer iteration were largest: momentum (phase,
    /// component, node), gas and solids continuity (cell) and granular energy (cell), with
    /// grid indices and coordinates, for the diagnosis of a step that fails.
    pub fn residual_locations(&self) -> String {
        let g = &self.grid;
        let nx = g.nx();
        let cell = |k: usize| {
            let (i, j) = (k % nx, k / nx);
            let (x, y) = g.cell_centre(i, j);
            format!("cell ({i}, {j}) at x = {x:.4} m, y = {y:.4} m")
        };
        let largest = |v: &[f64]| {
            v.iter().enumerate().fold(
                (0.0_f64, 0),
                |m, (k, r)| if r.abs() > m.0 { (r.abs(), k) } else { m },
            )
        };
        let mut out = Vec::new();
        let (r, p, dir, i, j) = self.worst.momentum;
        if r > 0.0 {
            let phase = if p == 0 {
                "gas".to_string()
            } else {
                format!("solids {p}")
            };
            let (comp, (x, y)) = if dir == 0 {
                ("u", g.u_face_position(i, j))
            } else {
                ("v", g.v_face_position(i, j))
            };
            out.push(format!(
                "momentum: largest residual {r:.3e} in {phase} {comp} at node ({i}, {j}), x = {x:.4} m, y = {y:.4} m"
            ));
        }
        let (r, k) = largest(&self.imbalance);
        if r > 0.0 {
            out.push(format!(
                "gas continuity: largest imbalance {r:.3e} kg/s per m in {}",
                cell(k)
            ));
        }
        for (m, s) in self.solids.iter().enumerate() {
            let (r, k) = largest(&s.imbalance);
            if r > 0.0 {
                out.push(format!(
                    "solids {} continuity: largest imbalance {r:.3e} kg/s per m in {}",
                    m + 1,
                    cell(k)
                ));
            }
        }
        let (r, k) = self.worst.theta;
        if r > 0.0 {
            out.push(format!(
                "granular energy: largest residual {r:.3e} in {}",
                cell(k)
            ));
        }
        out.join("; ")
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
        let mean_volume = self.grid.x.length() * self.grid.y.length() / self.eps_g.len() as f64;
        let t = Instant::now();
        self.update_closures();
        self.profile.closures += since(t);
        let t = Instant::now();
        self.update_stress_sources();
        self.profile.stress += since(t);
        self.closures_fresh = true;
        let (mut gas0, mut solids0) = (None, None);
        // the hydrodynamic sum at the last multiple of 5 iterations (MFIX SUM5_RESID)
        let mut sum5 = f64::INFINITY;
        let mut out = TwoFluidStep {
            iterations: 0,
            converged: false,
            residual: f64::INFINITY,
            last: TwoFluidResiduals::default(),
            failure: None,
        };
        for it in 0..max_iterations {
            out.iterations = it + 1;
            let r = match self.outer_iteration(dt) {
                Ok(r) => r,
                Err(e) => {
                    out.failure = Some(e.to_string());
                    break;
                }
            };
            // the gas residual's normaliser is its first iteration's value (MFIX's default),
            // but not below GAS_RESIDUAL_FLOOR of the gas a mean cell holds per step: a
            // step that starts nearly converged otherwise has to reduce round-off-level
            // imbalances (1e-9 of that content, flipping between two values in a dilute
            // cell) by another 1e3 and never does (S-JJ-phi coarse, docs/status.md)
            let gas_floor = GAS_RESIDUAL_FLOOR * self.gas.density * mean_volume / dt;
            let g = *gas0.get_or_insert(if r.gas_mass > f64::MIN_POSITIVE {
                r.gas_mass.max(gas_floor)
            } else {
                1.0
            });
            let s = *solids0.get_or_insert(if r.solids_mass > f64::MIN_POSITIVE {
                r.solids_mass
            } else {
                1.0
            });
            out.residual = r.momentum + r.gas_mass / g + r.solids_mass / s;
            out.last = r;
            tracing::trace!(
                iteration = it + 1,
                momentum = r.momentum,
                gas = r.gas_mass / g,
                solids = r.solids_mass / s,
                theta = r.theta,
                "outer iteration"
            );
            let finite = self
                .p_g
                .iter()
                .chain(&self.u_g)
                .chain(&self.v_g)
                .all(|x| x.is_finite())
                && self.solids.iter().all(|p| {
                    p.eps
                        .iter()
                        .chain(&p.u)
                        .chain(&p.v)
                        .chain(&p.theta)
                        .all(|x| x.is_finite())
                });
            if !finite {
                out.residual = f64::INFINITY;
                break;
            }
            // stall detection before the convergence test, as MFIX's check_convergence.f
            // (docs/model.md §4.11): the step is then retried with a smaller Δt (§4.12)
            let nit = it + 1;
            if self.settings.detect_stall && nit % 5 == 0 {
                if nit > 10 && sum5 <= out.residual {
                    out.failure = Some(format!(
                        "stalled: the momentum and continuity residual sum {:.3e} at outer \
                         iteration {nit} was not below its value {sum5:.3e} 5 iterations before \
                         (granular energy residual {:.3e})",
                        out.residual, r.theta
                    ));
                    break;
                }
                sum5 = out.residual;
            }
            if it >= 1 && out.residual <= tol && r.theta <= tol_theta {
                out.converged = true;
                if self.settings.exact_solids_continuity {
                    self.conservative_finish(dt);
                }
                return Ok(out);
            }
            if it >= 1 && out.residual >= diverge {
                break;
            }
        }
        self.restore_step();
        Ok(out)
    }

    /// Ends a converged step with exact discrete solids continuity (if
    /// [`TwoFluidSettings::exact_solids_continuity`]): each cell's εs becomes
    /// εs⁰ − Δt/V Σ (εs,face u·n A) with the step's final face fluxes, i.e. the imbalance
    /// the outer iteration left within its tolerance is removed where it sits. Without it
    /// that remainder accumulates where solids compact, because the selective relaxation of
    /// positive ε' beyond εs,max (docs/model.md §4.7) leaves every step's imbalance with the
    /// same sign (3e-7 of the solids over family M, 2e-5 over ST-schaeffer, 1e-7 over a
    /// coarse column collapse). The change is of the size of the step tolerance (MFIX keeps
    /// the remainder). Internal fluxes cancel in
    /// pairs, so the solids mass changes by exactly the boundary flux, up to the mass of any
    /// cell that would go below zero (clipped, reported by tracing).
    fn conservative_finish(&mut self, dt: f64) {
        for (s, spec) in self.solids.iter_mut().zip(&self.solids_specs) {
            let density = spec.params.particles.density;
            let inputs = CorrectionInputs {
                density,
                eps: &s.eps,
                eps_old: &s.eps_old,
                u: &s.u,
                v: &s.v,
                e_u: &s.e_u,
                e_v: &s.e_v,
                k_cp: &s.k_cp,
                dt,
                scheme: self.settings.scheme,
                periodic_x: self.settings.periodic_x,
            };
            mass_imbalance(&self.grid, &inputs, &mut s.imbalance);
            let nx = self.grid.nx();
            let (mut largest, mut clipped) = (0.0_f64, 0.0);
            for (k, (e, r)) in s.eps.iter_mut().zip(&s.imbalance).enumerate() {
                let volume = self.grid.cell_volume(k % nx, k / nx);
                let change = -r * dt / (density * volume);
                largest = largest.max(change.abs());
                *e += change;
                if *e < 0.0 {
                    clipped -= *e * volume;
                    *e = 0.0;
                }
            }
            tracing::trace!(
                largest,
                clipped,
                "conservative finish of the solids continuity"
            );
        }
        self.sync_volume_fractions();
    }

    /// The explicit stress sources of every solids phase from the current velocities and
    /// closures (docs/model.md §4.4: once per step, at its start).
    fn update_stress_sources(&mut self) {
        let fixed_u = self.a_ug.pattern().fixed_mask();
        let fixed_v = self.a_vg.pattern().fixed_mask();
        for s in &mut self.solids {
            crate::stress::explicit_stress(
                &self.grid,
                &s.u,
                &s.v,
                &s.mu,
                &s.lambda,
                &s.tr_d,
                fixed_u,
                fixed_v,
                &mut s.tau_u,
                &mut s.tau_v,
            );
        }
    }

    /// Wall time per part of the outer iteration so far.
    pub fn profile(&self) -> Profile {
        self.profile
    }

    /// Gas enters through the wall sides given, at this velocity normal to the side into
    /// the domain [m s⁻¹] (a distributor plate or porous wall: the gas's normal velocity on
    /// the side's faces is fixed at it and its face εg is 1, as MFIX's mass inlet with
    /// BC_EP_G = 1; the solids still see the wall). Outlet sides must get 0.
    pub fn set_gas_inflow(&mut self, inflow: Sides<f64>) -> Result<(), TwoFluidError> {
        for (side, &v) in inflow.iter() {
            if v != 0.0 && !matches!(self.gas_walls.get(side), SideBc::Wall(_)) {
                return Err(TwoFluidError::InflowOnOutlet(format!("{side:?}")));
            }
        }
        self.gas_inflow = inflow;
        Ok(())
    }

    /// Sets gravity (a schedule may tilt it during a run).
    pub fn set_gravity(&mut self, gravity: (f64, f64)) {
        self.gravity = gravity;
    }

    /// Whether solids phase `m` has a state-dependent model (JJ, revisited JJ, Jenkins) on
    /// the floor, i.e. whether `floor_h_u` is meaningful.
    pub fn has_floor_model(&self, m: usize) -> bool {
        self.solids_specs[m].wall_models.south.is_some()
    }

    /// Gravity (g_x, g_y) [m s⁻²].
    pub fn gravity(&self) -> (f64, f64) {
        self.gravity
    }
}

/// The gas normal velocity (in +x or +y) that fixed gas node k of component `dir` (0: u,
/// 1: v) holds: the inflow of its side, 0 on impermeable walls.
fn gas_fixed_velocity(inflow: &Sides<f64>, (nx, ny): (usize, usize), dir: usize, k: usize) -> f64 {
    if dir == 0 {
        match k % (nx + 1) {
            0 => inflow.west,
            i if i == nx => -inflow.east,
            _ => 0.0,
        }
    } else {
        match k / nx {
            0 => inflow.south,
            j if j == ny => -inflow.north,
            _ => 0.0,
        }
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

/// Fills `s.wall_face_velocity` with the tangential solids velocity on each wall face (the
/// face value of the wall closure, docs/model.md §3.2: per-node closures of a state-dependent
/// wall, else the side's fixed closure), averaged from the two velocity nodes of each
/// boundary cell to its centre (MFIX AVG_X_E). Returns which sides are walls.
fn wall_face_velocities(grid: &Grid, spec: &SolidsSpec, s: &mut SolidsFields) -> Sides<bool> {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let mut on_wall = Sides {
        west: false,
        east: false,
        south: false,
        north: false,
    };
    for side in [Side::West, Side::East, Side::South, Side::North] {
        let per_node = match side {
            Side::West => s.wall_velocity.west.as_ref(),
            Side::East => s.wall_velocity.east.as_ref(),
            Side::South => s.wall_velocity.south.as_ref(),
            Side::North => s.wall_velocity.north.as_ref(),
        };
        let fixed = match spec.walls.get(side) {
            SideBc::Wall(face) => Some(*face),
            _ => None,
        };
        if per_node.is_none() && fixed.is_none() {
            continue;
        }
        let closure = |k: usize| per_node.map_or_else(|| fixed.unwrap(), |f| f[k]);
        let (out, n_cells) = match side {
            Side::West => (&mut s.wall_face_velocity.west, ny),
            Side::East => (&mut s.wall_face_velocity.east, ny),
            Side::South => (&mut s.wall_face_velocity.south, nx),
            Side::North => (&mut s.wall_face_velocity.north, nx),
        };
        for c in 0..n_cells {
            let face = |node: usize| match side {
                Side::South => closure(node).face_value(s.u[node], dy[0]),
                Side::North => {
                    closure(node).face_value(s.u[node + (nx + 1) * (ny - 1)], dy[ny - 1])
                }
                Side::West => closure(node).face_value(s.v[nx * node], dx[0]),
                Side::East => closure(node).face_value(s.v[nx - 1 + nx * node], dx[nx - 1]),
            };
            out[c] = 0.5 * (face(c) + face(c + 1));
        }
        match side {
            Side::West => on_wall.west = true,
            Side::East => on_wall.east = true,
            Side::South => on_wall.south = true,
            Side::North => on_wall.north = true,
        }
    }
    on_wall
}

/// Marks the dilute velocity nodes of a solids phase, component `dir` (0: u on x-faces,
/// 1: v on y-faces): εs interpolated to the face (AVG_X / AVG_Y; the one cell's value on a
/// boundary face) ≤ DIL_EP_S (docs/model.md §2.7, MFIX `source_u_s.f`). Fixed (wall) nodes are
/// not dilute: their rows are fixed anyway.
fn dilute_faces(grid: &Grid, eps: &[f64], fixed: &[bool], dir: usize, out: &mut [bool]) {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (mx, my) = if dir == 0 { (nx + 1, ny) } else { (nx, ny + 1) };
    for j in 0..my {
        for i in 0..mx {
            let k = i + mx * j;
            let (lo, hi, w) = if dir == 0 {
                (
                    i.checked_sub(1).map(|c| c + nx * j),
                    (i < nx).then(|| i + nx * j),
                    if i > 0 && i < nx {
                        grid.x.interpolation_weight(i - 1)
                    } else {
                        0.5
                    },
                )
            } else {
                (
                    j.checked_sub(1).map(|r| i + nx * r),
                    (j < ny).then(|| i + nx * j),
                    if j > 0 && j < ny {
                        grid.y.interpolation_weight(j - 1)
                    } else {
                        0.5
                    },
                )
            };
            let eps_face = match (lo, hi) {
                (Some(a), Some(b)) => w * eps[a] + (1.0 - w) * eps[b],
                (Some(c), None) | (None, Some(c)) => eps[c],
                (None, None) => 0.0,
            };
            out[k] = !fixed[k] && eps_face <= DIL_EP_S;
        }
    }
}

/// The row of a dilute solids velocity node k (docs/model.md §2.7, MFIX `source_u_s.f`): the
/// mean of its neighbour nodes whose test cell — the neighbour of the node's low-side cell
/// `cell` in that direction (MFIX's IJK) — holds εs > DIL_EP_S, and of its own current
/// value; with no such neighbour the node keeps `current`. Neighbours on fixed (wall) nodes do not count. `(mx, my)` is
/// the node block, `nx` the cells per row.
fn dilute_row(
    a: &mut Stencil5,
    k: usize,
    current: f64,
    cell: Option<usize>,
    eps: &[f64],
    (mx, my): (usize, usize),
    nx: usize,
) {
    let ny = eps.len() / nx;
    let (i, j) = (k % mx, k / mx);
    fixed_row(a, k, current);
    let Some(c) = cell else {
        return;
    };
    let (ci, cj) = (c % nx, c / nx);
    let dense = |ti: Option<usize>, tj: Option<usize>| match (ti, tj) {
        (Some(ti), Some(tj)) if ti < nx && tj < ny => eps[ti + nx * tj] > DIL_EP_S,
        _ => false,
    };
    // (neighbour node exists, its test cell is dense)
    let west = i > 0 && dense(ci.checked_sub(1), Some(cj));
    let east = i + 1 < mx && dense(Some(ci + 1), Some(cj));
    let south = j > 0 && dense(Some(ci), cj.checked_sub(1));
    let north = j + 1 < my && dense(Some(ci), Some(cj + 1));
    let fixed = a.pattern().fixed_mask();
    let (west, east, south, north) = (
        west && !fixed[k - 1],
        east && !fixed[k + 1],
        south && !fixed[k - mx],
        north && !fixed[k + mx],
    );
    // the node's own current value counts once as well: two dilute nodes that would only
    // average each other otherwise form a singular pair (MFIX's plain mean has no self term)
    mean_row(a, k, [west, east, south, north], Some(current));
}

/// Makes row k the plain mean of the neighbours flagged (west, east, south, north), plus
/// the node's `own` value once if given; leaves the row as it is if no neighbour is flagged.
fn mean_row(a: &mut Stencil5, k: usize, [west, east, south, north]: [bool; 4], own: Option<f64>) {
    let count = [west, east, south, north].iter().filter(|&&x| x).count();
    if count == 0 {
        return;
    }
    let one = |flag: bool| if flag { 1.0 } else { 0.0 };
    a.a_w[k] = one(west);
    a.a_e[k] = one(east);
    a.a_s[k] = one(south);
    a.a_n[k] = one(north);
    a.a_p[k] = count as f64 + one(own.is_some());
    a.b[k] = own.unwrap_or(0.0);
}

/// The cycle watch of one wall node's momentum closure
/// ([`TwoFluidSettings::relax_wall_closures_oscillating_only`]).
#[derive(Clone, Copy, Debug, Default)]
struct ClosureCycle {
    /// the change of the closure's h applied at the last outer iteration
    last_change: f64,
    /// whether it has cycled in this time step (it then stays relaxed until the step ends)
    cycling: bool,
}

/// A wall node's closure is cycling when its change turns back at more than this fraction of
/// the previous change (an alternating iteration that contracts faster converges unaided).
const CYCLE_CONTRACTION: f64 = 0.5;

/// Whether a closure coefficient's `change` at this outer iteration turns back from the
/// previous iteration's `last` without contracting below [`CYCLE_CONTRACTION`] of it: the
/// mark of a period-2 cycle.
fn turns_back(change: f64, last: f64) -> bool {
    change * last < 0.0 && change.abs() > CYCLE_CONTRACTION * last.abs()
}

/// Under-relaxed wall closure: ω·`new` + (1 − ω)·`old` in each coefficient
/// ([`TwoFluidSettings::relax_wall_closures`]).
fn relax_face(new: RobinFace, old: RobinFace, w: f64) -> RobinFace {
    if w >= 1.0 {
        return new;
    }
    RobinFace {
        g: w * new.g + (1.0 - w) * old.g,
        h: w * new.h + (1.0 - w) * old.h,
        c: w * new.c + (1.0 - w) * old.c,
    }
}

/// How often a cell's θ-row class may change within a step before it is frozen dilute
/// ([`TwoFluidSettings::freeze_cycling_dilute_class`]): the second change is a change back.
const DILUTE_CLASS_CHANGES: u8 = 2;

/// The θ-row class of a cell at this outer iteration, given its class by the current εs
/// (`dense_now`), its class at the last iteration (`dense`, updated) and its class changes
/// within the step (`changes`, updated): it follows εs until it has changed
/// [`DILUTE_CLASS_CHANGES`] times (dense → dilute → dense, or dilute → dense → dilute: a
/// cycle), then stays dilute.
fn next_dilute_class(dense_now: bool, dense: &mut bool, changes: &mut u8) {
    if *changes < DILUTE_CLASS_CHANGES && dense_now != *dense {
        *dense = dense_now;
        *changes += 1;
        if *changes == DILUTE_CLASS_CHANGES {
            // frozen dilute: the cell is at the threshold, and a dense θ row there keeps
            // its face velocities and εs cycling (coarse flume to 0.55 s, rejected steps:
            // MFIX's iteration 53, frozen in the class it returned to 42, frozen dilute 25)
            *dense = false;
        }
    }
}

/// The θ row of a dilute cell k: the plain mean of its neighbour cells of the dense class
/// (εs > DIL_EP_S), or `current` if there are none (docs/model.md §4.8).
fn dilute_cell_row(a: &mut Stencil5, k: usize, current: f64, dense_class: &[bool], nx: usize) {
    let n = dense_class.len();
    let (i, j) = (k % nx, k / nx);
    fixed_row(a, k, current);
    let dense = |c: usize| dense_class[c];
    let west = i > 0 && dense(k - 1);
    let east = i + 1 < nx && dense(k + 1);
    let south = j > 0 && dense(k - nx);
    let north = k + nx < n && dense(k + nx);
    mean_row(a, k, [west, east, south, north], None);
}

/// Whether cells `a` < `b`, `stride` apart, lie on one grid line (x lines: stride 1 within
/// a row of `nx`; y lines: stride `nx`, always).
fn same_line(a: usize, b: usize, stride: usize, nx: usize) -> bool {
    stride != 1 || a / nx == b / nx
}

/// Mean of a cell field over the (one or two) cells beside a face.
fn face_mean(field: &[f64], c0: Option<usize>, c1: Option<usize>) -> f64 {
    match (c0, c1) {
        (Some(a), Some(b)) => 0.5 * (field[a] + field[b]),
        (Some(c), None) | (None, Some(c)) => field[c],
        (None, None) => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The classes a cell's θ row takes over a step's outer iterations, given its class by
    /// εs at each (the first iteration classifies afresh, as the solver does).
    fn classes(by_eps: &[bool]) -> Vec<bool> {
        let (mut dense, mut changes) = (by_eps[0], 0);
        let mut out = vec![dense];
        for &now in &by_eps[1..] {
            next_dilute_class(now, &mut dense, &mut changes);
            out.push(dense);
        }
        out
    }

    #[test]
    fn a_cycling_dilute_class_is_frozen_after_changing_back() {
        // the flume's cell (55, 10): dense, dilute, dense, ... is frozen dilute at the 3rd
        assert_eq!(
            classes(&[true, false, true, false, true, false]),
            [true, false, false, false, false, false]
        );
        assert_eq!(
            classes(&[false, true, false, true, true]),
            [false, true, false, false, false]
        );
        // a cell that becomes dense once follows εs, as MFIX's iteration
        assert_eq!(
            classes(&[false, false, true, true, true]),
            [false, false, true, true, true]
        );
        assert_eq!(classes(&[true, false, false]), [true, false, false]);
    }

    #[test]
    fn a_cycle_is_a_change_that_turns_back_without_contracting() {
        // period 2: h alternates between two values
        assert!(turns_back(-1.0, 1.0));
        assert!(turns_back(0.6, -1.0));
        // an alternating iteration contracting by more than half converges unaided
        assert!(!turns_back(-0.4, 1.0));
        // monotone, the first iteration, and no change
        assert!(!turns_back(0.9, 1.0));
        assert!(!turns_back(1.0, 0.0));
        assert!(!turns_back(0.0, 1.0));
        // the relaxation itself: ω = 0.5 averages the coefficients
        let (a, b) = (
            RobinFace::partial_slip(4.0, 0.0),
            RobinFace::partial_slip(2.0, 0.0),
        );
        let r = relax_face(a, b, 0.5);
        assert_eq!((r.g, r.h, r.c), (1.0, 3.0, 0.0));
        assert_eq!(relax_face(a, b, 1.0), a);
    }
}
