//! Source terms of the granular-energy equation (docs/model.md §1.3; MFIX 21.3.2
//! `model/source_granular_energy.f`, `KT_TYPE = 'LUN_1984'`):
//! (3/2)[∂(εs ρs θ)/∂t + ∇·(εs ρs θ u_s)] = ∇·(κ_s ∇θ) + Π − γ − J_vis + J_slip.
//! γ is [`crate::kinetic::dissipation`].

use crate::guards::SMALL_NUMBER;
use std::f64::consts::PI;

/// Shear production Π = −P_kin tr D + 2 μ_kin tr(D²) + λ_kin (tr D)² [W m⁻³] with
/// tr(D²) = S:S + (tr D)²/3 (docs/model.md §1.3, §0.3). Only the kinetic-theory parts enter:
/// frictional stresses produce no granular energy in MFIX.
#[inline]
pub fn shear_production(p_kin: f64, mu_kin: f64, lambda_kin: f64, tr_d: f64, s_ddot_s: f64) -> f64 {
    let tr_d2 = s_ddot_s + tr_d * tr_d / 3.0;
    -p_kin * tr_d + 2.0 * mu_kin * tr_d2 + lambda_kin * tr_d * tr_d
}

/// Viscous damping by the gas J_vis = 3 F_gs θ [W m⁻³] (Gidaspow 1994; docs/model.md §1.3;
/// implicit in MFIX). Zero without gas.
#[inline]
pub fn viscous_damping(f_gs: f64, theta: f64) -> f64 {
    3.0 * f_gs * theta
}

/// Slip production J_slip = 81 εs μ_g² |u_g − u_s|² / (g0 d³ ρs √π √(θ + 1e-15)) [W m⁻³]
/// (Koch & Sangani 1999; docs/model.md §1.3; MFIX S7 with `SMALL_NUMBER` under the root).
/// MFIX takes |u_g − u_s| from the east/north face velocities of the cell. Zero without gas.
#[inline]
pub fn slip_production(
    eps_s: f64,
    theta: f64,
    g0: f64,
    d_p: f64,
    rho_s: f64,
    mu_g: f64,
    slip: f64,
) -> f64 {
    let viscous_slip = mu_g * slip;
    81.0 * eps_s * viscous_slip * viscous_slip
        / (g0 * d_p * d_p * d_p * rho_s * PI.sqrt() * (theta + SMALL_NUMBER).sqrt())
}
