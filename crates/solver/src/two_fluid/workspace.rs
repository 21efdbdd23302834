//! Work storage, allocated once and rewritten by every outer iteration: the matrices of
//! the equations, the corrections' coefficients (d_g of docs/model.md §4.6, e_s of §4.7, P',
//! ε'), the mass imbalances, the face data of the convection scheme (§4.2), the dilute faces
//! (§2.7) and the θ-row classes (§4.8) per solids phase; the linear solvers (§4.13); and the
//! flags of the outer iteration.

use runout_linsolve::{LinearSolver, Pattern, Stencil5};

use crate::momentum::MassFluxes;
use crate::transport::FaceData;

/// The work storage of the solver (module doc).
pub(crate) struct Workspace {
    /// d_g of the u and v nodes (docs/model.md §4.6)
    pub d_u: Vec<f64>,
    pub d_v: Vec<f64>,
    /// P' of the last gas pressure correction
    pub p_corr: Vec<f64>,
    /// gas mass imbalance per cell before the pressure correction
    pub imbalance: Vec<f64>,
    /// face data of the gas u and v equations' convection and of the cell equations'
    /// (docs/model.md §4.2)
    pub u_faces: FaceData,
    pub v_faces: FaceData,
    pub c_faces: FaceData,
    /// the gas's scalar-cell mass fluxes of the momentum assembly (shared by u and v)
    pub gas_fluxes: MassFluxes,
    /// the gas u, v and P' equations
    pub a_ug: Stencil5,
    pub a_vg: Stencil5,
    pub a_p: Stencil5,
    /// work storage per solids phase
    pub solids: Vec<PhaseWork>,
    /// the linear solvers
    pub solvers: Solvers,
    /// the flags of the outer iteration
    pub flags: IterationFlags,
}

/// The linear solvers of the equations (docs/model.md §4.13).
pub(crate) struct Solvers {
    /// momentum u and v (every phase)
    pub u: Box<dyn LinearSolver>,
    pub v: Box<dyn LinearSolver>,
    /// gas pressure correction
    pub p: Box<dyn LinearSolver>,
    /// solids volume-fraction correction
    pub eps: Box<dyn LinearSolver>,
    /// MFIX's own ε' solver (BiCGSTAB with line relaxation, `LEQ_IT` 20, docs/model.md §4.13),
    /// used where the multigrid-preconditioned solve breaks down
    pub eps_fallback: Box<dyn LinearSolver>,
    /// granular energy
    pub theta: Box<dyn LinearSolver>,
}

/// The flags of the outer iteration.
#[derive(Clone, Copy, Debug)]
pub(crate) struct IterationFlags {
    /// P' is pinned at cell 0 (no side is open)
    pub pressure_pinned: bool,
    /// the multigrid preconditioners of the P' and ε' solves are built on the first outer
    /// iteration of a step and kept for the others ([`LinearSolver::refresh`])
    pub rebuild_preconditioners: bool,
    /// the closures were evaluated at the current iterate (the start of a step) and need
    /// not be evaluated again by the next outer iteration
    pub closures_fresh: bool,
    /// the next θ solve is the step's first: it classifies every cell afresh
    pub theta_class_fresh: bool,
}

/// Work storage of one solids phase (module doc).
#[derive(Clone, Debug)]
pub(crate) struct PhaseWork {
    /// face data of the phase's u and v equations' convection (its own, so that the
    /// phases' momentum equations are assembled in parallel)
    pub u_faces: FaceData,
    pub v_faces: FaceData,
    /// the phase's scalar-cell mass fluxes of the momentum assembly (shared by u and v)
    pub fluxes: MassFluxes,
    /// dilute u and v faces of the current momentum assembly (docs/model.md §2.7)
    pub dilute_u: Vec<bool>,
    pub dilute_v: Vec<bool>,
    /// e_s of the u and v nodes (docs/model.md §4.7)
    pub e_u: Vec<f64>,
    pub e_v: Vec<f64>,
    /// ε' of the last volume-fraction correction
    pub eps_prime: Vec<f64>,
    /// solids mass imbalance per cell before the correction
    pub imbalance: Vec<f64>,
    /// the u, v, ε' and θ equations
    pub a_u: Stencil5,
    pub a_v: Stencil5,
    pub a_eps: Stencil5,
    pub a_theta: Stencil5,
    /// the class of each cell's θ row at the last outer iteration (true: dense, a θ
    /// equation; false: dilute, the mean of its dense neighbours; docs/model.md §4.8), and how
    /// often it changed within the step ([`super::TwoFluidSettings::freeze_cycling_dilute_class`])
    pub theta_dense: Vec<bool>,
    pub theta_class_changes: Vec<u8>,
    /// the negation of `theta_dense`: the rows the θ assembly skips
    pub theta_dilute: Vec<bool>,
    /// per cell, the θ residual's |Σ a_nb θ_nb + b − a_P θ_P| and |a_P θ_P| (zero on
    /// dilute rows), summed in cell order (docs/model.md §4.11)
    pub theta_terms: Vec<(f64, f64)>,
}

impl PhaseWork {
    /// Work storage on an nx × ny grid with the u, v and cell patterns of its equations.
    pub fn new((nx, ny): (usize, usize), pu: &Pattern, pv: &Pattern, pc: &Pattern) -> Self {
        let n = nx * ny;
        PhaseWork {
            u_faces: FaceData::zeros(nx + 1, ny),
            v_faces: FaceData::zeros(nx, ny + 1),
            fluxes: MassFluxes::default(),
            dilute_u: vec![false; (nx + 1) * ny],
            dilute_v: vec![false; nx * (ny + 1)],
            e_u: vec![0.0; (nx + 1) * ny],
            e_v: vec![0.0; nx * (ny + 1)],
            eps_prime: vec![0.0; n],
            imbalance: vec![0.0; n],
            a_u: Stencil5::new(pu.clone()),
            a_v: Stencil5::new(pv.clone()),
            a_eps: Stencil5::new(pc.clone()),
            a_theta: Stencil5::new(pc.clone()),
            theta_dense: vec![false; n],
            theta_class_changes: vec![0; n],
            theta_dilute: vec![true; n],
            theta_terms: vec![(0.0, 0.0); n],
        }
    }
}
