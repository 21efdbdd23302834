//! The near-wall states the wall models take, and the small gathering rules MFIX applies when
//! it builds them (docs/model.md §3.5 "Where the quantities are evaluated", §3.6 "Evaluation
//! point", §2.7).
//!
//! The solver gathers one [`MomentumWallState`] per wall face of a solids tangential velocity
//! (e.g. each U-face on a floor) and one [`ThetaWallState`] per wall face of a fluid cell,
//! from the latest iterate (lagged, as MFIX does each outer iteration).

use runout_closures::guards::{THETA_SMALL, THETA_WALL_FLOOR};
use serde::Serialize;

/// Floor on S:S at the wall: S:S = max(1e-10, tr(D²) − (tr D)²/3) [1/s²]
/// (docs/model.md §3.5 step 3; MFIX `calc_s_ddot_s.f`).
pub const WALL_S_DDOT_S_FLOOR: f64 = 1e-10;

/// Near-wall state of the solids tangential-momentum condition at one wall face
/// (docs/model.md §3.5). For U on a floor: the U-location (x_{i+½}) of the wall face.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MomentumWallState {
    /// εs of the fluid cell next to the wall (MFIX IJK2) [-]: decides the dilute skip
    /// (≤ `DIL_EP_S` → free slip) and whether the frictional branch applies (> εs,min)
    pub eps_s_fluid: f64,
    /// εs linearly interpolated (AVG_X) between the two fluid cells on either side of the
    /// velocity face [-]; g0, the gas fraction εg = 1 − εs and the friction test use it
    pub eps_s: f64,
    /// θ averaged over the four cells around the wall-face corner point [m²/s²]
    /// ([`corner_theta`]); θ ≤ 0 is replaced by 1e-8 inside the models ([`wall_theta`])
    pub theta: f64,
    /// slip speed |u_sl| = |u_s,face − u_w| [m/s], with u_s,face the mean of ghost and fluid
    /// values (the face value of the lagged [`crate::RobinFace`]) and the normal component 0
    pub slip: f64,
    /// gas–solids relative speed |u_g − u_s| at the wall face [m/s], for the Wen–Yu drag in
    /// μ*, κ* (docs/model.md §2.6 last bullet)
    pub gas_slip: f64,
    /// tr D = ∇·u_s at the wall location [1/s] (MFIX CALC_S_DDOT_S, from ghost and fluid
    /// velocities)
    pub tr_d: f64,
    /// S:S = tr(D²) − (tr D)²/3 at the wall location [1/s²] (floored at 1e-10 inside)
    pub s_ddot_s: f64,
    /// S_nn = D_nn − tr D/3, the normal–normal deviatoric strain rate, n = wall normal [1/s]
    pub s_nn: f64,
    /// the solids' normal load on the wall beyond the isotropic pressure at this location
    /// \[Pa\]: N_w − P_s, with N_w = −n·σ_s·n the normal traction (the viscous normal stress
    /// −τ_nn of the wall cells and their half cell's normal body load, docs/model.md
    /// §3.11). Read by the Coulomb wall only; MFIX's JJ and Jenkins read the pressure.
    pub extra_normal_load: f64,
}

/// Near-wall state of the granular-temperature condition at one wall face (docs/model.md §3.6):
/// the fluid cell's own values, no interpolation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ThetaWallState {
    /// εs of the fluid cell [-] (g0 = G_0 of the cell)
    pub eps_s: f64,
    /// θ on the wall face, the mean of ghost and fluid θ [m²/s²] ([`face_theta`]);
    /// θ ≤ 0 is replaced by 1e-8 inside the models
    pub theta: f64,
    /// tangential slip speed |u_s − u_w| at the wall-face centre [m/s]: the mean of the ghost-
    /// and fluid-row tangential velocities, each first averaged to the cell centre
    pub slip: f64,
    /// gas–solids relative speed at the wall face [m/s] (Wen–Yu drag in κ*)
    pub gas_slip: f64,
}

/// Strain-rate invariants at the wall location (docs/model.md §3.5 step 3).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct WallStrain {
    /// tr D [1/s]
    pub tr_d: f64,
    /// S:S = tr(D²) − (tr D)²/3 [1/s²]
    pub s_ddot_s: f64,
    /// S_nn = D_nn − tr D/3 [1/s]
    pub s_nn: f64,
}

impl WallStrain {
    /// Invariants of a planar (x, y) solids velocity gradient at a wall whose normal is y (a
    /// floor or a roof), as MFIX's CALC_S_DDOT_S forms them: D = ½(∇u + ∇uᵀ), D_zz = 0,
    /// tr D = ∂u/∂x + ∂v/∂y, tr(D²) = D_xx² + D_yy² + 2 D_xy², S_nn = D_yy − tr D/3.
    /// For a wall with normal x swap the roles of the components.
    pub fn planar_floor(du_dx: f64, du_dy: f64, dv_dx: f64, dv_dy: f64) -> Self {
        let d_xy = 0.5 * (du_dy + dv_dx);
        let tr_d = du_dx + dv_dy;
        let tr_d2 = du_dx * du_dx + dv_dy * dv_dy + 2.0 * d_xy * d_xy;
        Self {
            tr_d,
            s_ddot_s: tr_d2 - tr_d * tr_d / 3.0,
            s_nn: dv_dy - tr_d / 3.0,
        }
    }
}

/// θ used by the JJ/Jenkins coefficient routines: values ≤ 0 become 1e-8 m²/s²
/// (docs/model.md §2.7 last row, §3.5–3.6; MFIX `calc_grbdry.f` CALC_MU_SV_BDRY, `bc_theta.f`).
/// Positive values below θ_small = 1e-12 m²/s² are raised to θ_small: MFIX never holds such
/// a θ (`adjust_theta.f` clips every solve, docs/model.md §2.7), and below `SMALL_NUMBER` κ*
/// would vanish, leaving the θ face with g = 0 (and h = 0 for e_w = 1).
#[inline]
pub fn wall_theta(theta: f64) -> f64 {
    if theta <= 0.0 {
        THETA_WALL_FLOOR
    } else {
        theta.max(THETA_SMALL)
    }
}

/// θ at the wall-face corner point for the momentum condition (docs/model.md §3.5; MFIX
/// CALC_BDRY_QOI): the mean of the x-averaged ghost-row and fluid-row values, where a negative
/// row value is replaced by the other row's value, and θ_small = 1e-12 m²/s² if both are
/// negative. `ghost_row`, `fluid_row` are the x-averages AVG_X in each row.
#[inline]
pub fn corner_theta(ghost_row: f64, fluid_row: f64) -> f64 {
    match (ghost_row < 0.0, fluid_row < 0.0) {
        (true, true) => THETA_SMALL,
        (true, false) => fluid_row,
        (false, true) => ghost_row,
        (false, false) => 0.5 * (ghost_row + fluid_row),
    }
}

/// θ on a wall face for the θ condition (docs/model.md §3.6; MFIX `bc_theta.f`): the mean of
/// ghost and fluid θ, θ_small = 1e-12 m²/s² if negative.
#[inline]
pub fn face_theta(ghost: f64, fluid: f64) -> f64 {
    let mean = 0.5 * (ghost + fluid);
    if mean < 0.0 {
        THETA_SMALL
    } else {
        mean
    }
}
