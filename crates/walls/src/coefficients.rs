//! The individual terms of the Johnson–Jackson and Jenkins wall conditions as MFIX computes
//! them (docs/model.md §3.5, §3.6, §3.8; paper Table 2, Eqs. 14, 18–20). Pure functions of a
//! few scalars; the models in [`crate::model`] assemble them.
//!
//! Where the paper's printed forms differ, these follow MFIX (docs/model.md §3.10): Table 2's
//! "(1 − εs*)" is εs,max = 1 − εg*; the JJ θ coefficient carries εs g0 (missing in Table 2);
//! FRI is a stress, not divided by the slip speed.

use runout_closures::kinetic::SolidsState;
use std::f64::consts::PI;

/// JJ collisional coefficient COL = φ √(3θ) π ρs εs g0 / (6 εs,max) [kg m⁻² s⁻¹ = Pa s/m]
/// (paper Table 2 with (1 − εs*) read as εs,max; docs/model.md §3.5 step 2; MFIX
/// CALC_GRBDRY_COLLISIONAL). The second term of paper Eq. 14 divided by |u_sl|, with JJ's
/// εs,max[1 − (εs/εs,max)^{1/3}] replaced by εs,max/g0. Linear in φ.
#[inline]
pub fn collisional_johnson_jackson(specularity: f64, s: &SolidsState, eps_s_max: f64) -> f64 {
    specularity * (3.0 * s.theta).sqrt() * PI * s.rho_s * s.eps_s * s.g0 / (6.0 * eps_s_max)
}

/// Jenkins collisional coefficient COL = tan δ_w P_kin/|u_sl| [Pa s/m], 0 at zero slip
/// (paper Table 2; docs/model.md §3.8; MFIX CALC_GRBDRY_COLLISIONAL with `JENKINS`).
#[inline]
pub fn collisional_jenkins(tan_wall_friction: f64, p_kin: f64, slip: f64) -> f64 {
    if slip == 0.0 {
        0.0
    } else {
        tan_wall_friction * p_kin / slip
    }
}

/// Frictional (Coulomb) term FRI = tan δ_w max(0, P_f − 2 μ_f S_nn) \[Pa\] (paper Eq. 14
/// third term with the frictional stress; docs/model.md §3.5 step 3; MFIX
/// CALC_GRBDRY_FRICTIONAL). The frictional normal stress on the wall P_f − 2 μ_f S_nn is
/// bounded below by 0 — a wall is pressed on, never pulled, as the Coulomb wall's N_w
/// (§3.11) — where MFIX takes it as it comes: with μ(I) below εs,min, where P_f = P_c = 0
/// while μ_f = μ(I) P_kin/γ̇_r is not, a layer stretched normal to the wall (S_nn > 0) made
/// it negative, h_w^u < 0, and the wall pushed the flow (issue 58). Not divided by |u_sl|:
/// MFIX adds it to COL as coded (docs/model.md §3.5 step 4, §3.10.5).
#[inline]
pub fn frictional(tan_wall_friction: f64, p_fric: f64, mu_fric: f64, s_nn: f64) -> f64 {
    tan_wall_friction * (p_fric - 2.0 * mu_fric * s_nn).max(0.0)
}

/// JJ granular-energy wall dissipation coefficient
/// h_θ = (π√3/(4 εs,max)) (1 − e_w²) ρs εs g0 √θ [kg m⁻² s⁻¹], so that h_θ θ is the
/// dissipation D of paper Eq. 19 in MFIX's form (docs/model.md §3.6; MFIX `bc_theta.f`
/// THETA_HW_CW; paper Table 2 lacks the εs g0 factor).
#[inline]
pub fn h_theta_johnson_jackson(wall_restitution: f64, s: &SolidsState, eps_s_max: f64) -> f64 {
    PI * 3.0_f64.sqrt() / (4.0 * eps_s_max)
        * (1.0 - wall_restitution * wall_restitution)
        * s.rho_s
        * s.eps_s
        * s.g0
        * s.theta.sqrt()
}

/// JJ slip generation c_θ = (π√3/(6 εs,max)) φ ρs εs g0 √θ |u_sl|² [kg s⁻³]
/// (u_sl·S_c^b of paper Eq. 18; docs/model.md §3.6; MFIX THETA_HW_CW).
#[inline]
pub fn c_theta_johnson_jackson(
    specularity: f64,
    s: &SolidsState,
    slip: f64,
    eps_s_max: f64,
) -> f64 {
    PI * 3.0_f64.sqrt() / (6.0 * eps_s_max)
        * specularity
        * s.rho_s
        * s.eps_s
        * s.g0
        * s.theta.sqrt()
        * slip
        * slip
}

/// Jenkins wall dissipation h_θ = (3/8) √(3θ) (1 − e_w) P_kin/θ [kg m⁻² s⁻¹]
/// (paper Eq. 20 second term, Table 2; docs/model.md §3.8). θ > 0.
#[inline]
pub fn h_theta_jenkins(wall_restitution: f64, theta: f64, p_kin: f64) -> f64 {
    // P_kin/θ first: P_kin ∝ θ, so the product √θ · P_kin would underflow for tiny θ
    3.0 / 8.0 * (p_kin / theta) * (3.0 * theta).sqrt() * (1.0 - wall_restitution)
}

/// Jenkins slip generation c_θ = (21/16) tan²δ_w (1 + e_w) √(3θ) P_kin [kg s⁻³]
/// (paper Eq. 20 first term, Table 2; docs/model.md §3.8).
#[inline]
pub fn c_theta_jenkins(
    tan_wall_friction: f64,
    wall_restitution: f64,
    theta: f64,
    p_kin: f64,
) -> f64 {
    21.0 / 16.0
        * tan_wall_friction
        * tan_wall_friction
        * (1.0 + wall_restitution)
        * (3.0 * theta).sqrt()
        * p_kin
}
