//! Solids stress assembly (docs/model.md §2.3; MFIX `calc_mu_s.f` CALC_DEFAULT_MUS).
//!
//! Additive, not a switch (paper Eq. 5 shows a switch at εg*; MFIX with a granular-energy
//! PDE sums the parts, docs/model.md §3.10.1): μ_s = μ_kin + μ_fric, λ_s = λ_kin + λ_fric,
//! P_s = P_kin + P_fric. The Schaeffer P* is kept apart: it enters the solids momentum as its
//! own gradient −∇P*.

use crate::friction::FrictionalStress;
use crate::kinetic::KineticStress;
use serde::Serialize;

/// Total solids stress coefficients of one cell (docs/model.md §2.3), MFIX convention
/// τ_s = −P_s I + 2 μ_s D + λ_s (tr D) I.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct SolidsStress {
    /// P_s = P_kin + P_fric \[Pa\]
    pub p_s: f64,
    /// μ_s = μ_kin + μ_fric (Princeton or Schaeffer) [Pa s]
    pub mu_s: f64,
    /// λ_s = λ_kin + λ_fric [Pa s]
    pub lambda_s: f64,
    /// plastic pressure P* \[Pa\] (Schaeffer only; a separate −∇P* term)
    pub p_star: f64,
}

/// Sum the kinetic and frictional parts (docs/model.md §2.3): P_s = P_kin + P_fric,
/// μ_s = μ_kin + μ_fric, λ_s = λ_kin + λ_fric; P* passed through.
#[inline]
pub fn assemble(kinetic: &KineticStress, friction: &FrictionalStress) -> SolidsStress {
    SolidsStress {
        p_s: kinetic.p_kin + friction.p_fric,
        mu_s: kinetic.mu_kin + friction.mu_fric,
        lambda_s: kinetic.lambda_kin + friction.lambda_fric,
        p_star: friction.p_star,
    }
}
