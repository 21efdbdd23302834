//! Work storage of one solids phase, allocated once and rewritten by every outer iteration:
//! the matrices of its equations, the corrections' coefficients (e_s of docs/model.md §4.7,
//! ε'), its mass imbalance, the dilute faces (§2.7) and the θ-row classes (§4.8).

use runout_linsolve::{Pattern, Stencil5};

/// Work storage of one solids phase (module doc).
#[derive(Clone, Debug)]
pub(crate) struct PhaseWork {
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
}

impl PhaseWork {
    /// Work storage on an nx × ny grid with the u, v and cell patterns of its equations.
    pub fn new((nx, ny): (usize, usize), pu: &Pattern, pv: &Pattern, pc: &Pattern) -> Self {
        let n = nx * ny;
        PhaseWork {
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
        }
    }
}
