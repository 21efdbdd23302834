//! Solids stress assembly (docs/model.md §2.3; MFIX `calc_mu_s.f` CALC_DEFAULT_MUS).
//!
//! Additive, not a switch (paper Eq. 5 shows a switch at εg*; MFIX with a granular-energy
//! PDE sums the parts, docs/model.md §3.10.1): μ_s = μ_kin + μ_fric, λ_s = λ_kin + λ_fric,
//! P_s = P_kin + P_fric. The Schaeffer P* is kept apart: it enters the solids momentum as its
//! own gradient −∇P*. The μ(I) law joins the viscosities as the larger of the two instead
//! ([`KineticJoin::LargerOf`], docs/model.md §2.4.4): its coefficient is the whole dense
//! shear stress, kinetic part included.

use crate::friction::FrictionalStress;
use crate::kinetic::KineticStress;
use serde::Serialize;

/// Total solids stress coefficients of one cell (docs/model.md §2.3), MFIX convention
/// τ_s = −P_s I + 2 μ_s D + λ_s (tr D) I.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct SolidsStress {
    /// P_s = P_kin + P_fric \[Pa\]
    pub p_s: f64,
    /// μ_s = μ_kin + μ_fric (Princeton or Schaeffer; the larger-of join for μ(I)) [Pa s]
    pub mu_s: f64,
    /// λ_s = λ_kin + λ_fric (weighted as μ_s for μ(I)) [Pa s]
    pub lambda_s: f64,
    /// plastic pressure P* \[Pa\] (Schaeffer only; a separate −∇P* term)
    pub p_star: f64,
}

/// Exponent n of the larger-of join (μ_kin^n + μ_fric^n)^(1/n): where one viscosity is four
/// times the other the join exceeds the larger by 0.1 %, where they are equal by 19 %.
pub const LARGER_OF_EXPONENT: i32 = 4;

/// How the kinetic-theory viscosities join the frictional ones (docs/model.md §2.3, §2.4.4).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub enum KineticJoin {
    /// μ_s = μ_kin + μ_fric, λ_s = λ_kin + λ_fric (MFIX; Princeton, Schaeffer)
    #[default]
    Sum,
    /// μ_s = μ_fric + w μ_kin, λ_s = λ_fric + w λ_kin with the weight of
    /// [`larger_of_weight`], so that μ_s = (μ_kin⁴ + μ_fric⁴)^(1/4): the larger viscosity
    /// where one dominates (μ(I))
    LargerOf,
}

impl KineticJoin {
    /// The weight w ∈ [0, 1] of the kinetic viscosities in μ_s = μ_fric + w μ_kin.
    #[inline]
    pub fn weight(self, mu_kin: f64, mu_fric: f64) -> f64 {
        match self {
            Self::Sum => 1.0,
            Self::LargerOf => larger_of_weight(mu_kin, mu_fric),
        }
    }

    /// The joined shear viscosity μ_s = μ_fric + w μ_kin [Pa s].
    #[inline]
    pub fn viscosity(self, mu_kin: f64, mu_fric: f64) -> f64 {
        self.weight(mu_kin, mu_fric) * mu_kin + mu_fric
    }
}

/// w = ((μ_k⁴ + μ_f⁴)^(1/4) − μ_f)/μ_k ∈ [0, 1], so that μ_f + w μ_k = (μ_k⁴ + μ_f⁴)^(1/4)
/// (μ_k, μ_f ≥ 0 [Pa s]). Written with the ratio of the smaller to the larger viscosity,
/// q ≤ 1, to keep it exact where one is negligible: w = ((1 + q⁴)^(1/4) − 1)/q for
/// μ_k ≤ μ_f (q = μ_k/μ_f, w → q³/4), w = (1 + q⁴)^(1/4) − q for μ_k > μ_f (q = μ_f/μ_k).
/// w = 1 where μ_f = 0 (the kinetic theory alone) and 0 where μ_k = 0.
#[inline]
pub fn larger_of_weight(mu_kin: f64, mu_fric: f64) -> f64 {
    let root =
        |q: f64| (q.powi(LARGER_OF_EXPONENT).ln_1p() / f64::from(LARGER_OF_EXPONENT)).exp_m1();
    if mu_kin <= 0.0 {
        0.0
    } else if mu_kin <= mu_fric {
        let q = mu_kin / mu_fric;
        root(q) / q
    } else {
        let q = mu_fric / mu_kin;
        1.0 + root(q) - q
    }
}

/// How a phase's cell viscosities are averaged to the corners of the staggered momentum
/// cells (docs/model.md §4.1): the friction model answers ([`crate::FrictionModel::corner_viscosity_mean`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub enum FaceMean {
    /// distance-weighted harmonic mean (MFIX's AVG_H; the gas, Princeton, Schaeffer)
    #[default]
    Harmonic,
    /// distance-weighted arithmetic mean (μ(I)): the Coulomb strength μ P of the pressure a
    /// corner carries where P falls towards a free surface, which the harmonic mean of
    /// μ P/γ̇ underestimates (docs/model.md §2.4.4)
    Arithmetic,
}

/// Join the kinetic and frictional parts (docs/model.md §2.3): P_s = P_kin + P_fric,
/// μ_s = w μ_kin + μ_fric, λ_s = w λ_kin + λ_fric, w from the frictional model's
/// [`KineticJoin`] (1 for MFIX's sum); P* passed through.
#[inline]
pub fn assemble(kinetic: &KineticStress, friction: &FrictionalStress) -> SolidsStress {
    let w = friction
        .kinetic_join
        .weight(kinetic.mu_kin, friction.mu_fric);
    SolidsStress {
        p_s: kinetic.p_kin + friction.p_fric,
        mu_s: w * kinetic.mu_kin + friction.mu_fric,
        lambda_s: w * kinetic.lambda_kin + friction.lambda_fric,
        p_star: friction.p_star,
    }
}
