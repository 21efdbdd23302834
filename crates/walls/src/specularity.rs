//! Li & Benyahia (2012) variable specularity φ(r), the paper's "revisited Johnson–Jackson"
//! (paper Eqs. 16–17; docs/model.md §3.7; MFIX 21.3.2 `bc_theta.f` PHIP_JJ and
//! `check_data/check_bc_walls.f` for φ₀, identical in 2016-1).
//!
//! Paper Eq. 16 prints the linear branch as −7√(6π) φ₀² r + φ₀, which jumps at the switch
//! (docs/model.md §3.10.4); MFIX, and this module, use −7√(6π) φ₀² r/(8k) + φ₀, which is
//! continuous: both branches equal φ₀/2 at r* = 4k/(7√(6π) φ₀).

use crate::error::{Checks, WallError};
use std::f64::consts::PI;

/// Factor 7/2 of k = (7/2) tan δ_w (1 + e_w) [-] (paper Eq. 16 text; MFIX `k4phi`).
const K_FACTOR: f64 = 3.5;

/// Coefficients c₀…c₆ of the φ₀(k) polynomial, as MFIX codes them to full precision
/// (docs/model.md §3.7; `check_bc_walls.f`; paper Eq. 17 prints them rounded).
const PHI0_POLYNOMIAL: [f64; 7] = [
    -0.0012596340709032689,
    0.10645510095633175,
    -0.04281476447854031,
    0.009759402181229842,
    -0.0012508257938705263,
    0.00008369829630479206,
    -0.000002269550565981776,
];

/// Below (and at) this k, φ₀ = [`PHI0_SMALL_K_SLOPE`] · k instead of the polynomial
/// (docs/model.md §3.7; `check_bc_walls.f`).
pub const PHI0_SMALL_K: f64 = 0.2;

/// Slope of the small-k branch φ₀ = 0.09094568176225006 k (docs/model.md §3.7).
pub const PHI0_SMALL_K_SLOPE: f64 = 0.09094568176225006;

/// 7√(6π) [-], the constant of both branches of paper Eq. 16.
fn seven_sqrt_6pi() -> f64 {
    7.0 * (6.0 * PI).sqrt()
}

/// k = (7/2) tan δ_w (1 + e_w) [-] (paper Eq. 16 text; docs/model.md §3.7).
#[inline]
pub fn k_parameter(wall_restitution: f64, tan_wall_friction: f64) -> f64 {
    K_FACTOR * tan_wall_friction * (1.0 + wall_restitution)
}

/// φ₀(k) [-]: the sixth-order polynomial of paper Eq. 17 with MFIX's full-precision
/// coefficients, or 0.09094568176225006 k if k ≤ 0.2 (docs/model.md §3.7).
#[inline]
pub fn phi0_from_k(k: f64) -> f64 {
    if k <= PHI0_SMALL_K {
        PHI0_SMALL_K_SLOPE * k
    } else {
        PHI0_POLYNOMIAL.iter().rev().fold(0.0, |acc, c| acc * k + c)
    }
}

/// Normalised slip r = |u_sl|/√(3θ) [-] (paper Eq. 16 text). θ must be > 0 (the wall
/// models floor it first, [`crate::state::wall_theta`]).
#[inline]
pub fn normalized_slip(slip: f64, theta: f64) -> f64 {
    slip / (3.0 * theta).sqrt()
}

/// The Li–Benyahia specularity law of one wall: k and φ₀ (docs/model.md §3.7).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct LiBenyahia {
    /// k = (7/2) tan δ_w (1 + e_w) [-]
    pub k: f64,
    /// φ₀ = φ(r = 0) [-]: MFIX `PHIP0` if given, else [`phi0_from_k`]
    pub phi0: f64,
}

impl LiBenyahia {
    /// The law for particle–wall restitution e_w ∈ [0, 1], tan δ_w ≥ 0 and an optional φ₀
    /// override (MFIX `PHIP0`) in (0, 1] (a specularity; docs/reference/input-validation.md); a φ₀ from
    /// k outside [0, 1] is an input error (docs/model.md §3.7), and so is k = 0 with φ₀ > 0
    /// (the linear branch divides by k).
    pub fn new(
        wall_restitution: f64,
        tan_wall_friction: f64,
        phi0_override: Option<f64>,
    ) -> Result<Self, WallError> {
        let k = k_parameter(wall_restitution, tan_wall_friction);
        let mut checks = Checks::default();
        let phi0 = match phi0_override {
            Some(phi0) => checks.take(Self::check_override(phi0)),
            None => Some(checks.check("phi0", phi0_from_k(k), "[0, 1]", |v| {
                (0.0..=1.0).contains(&v)
            })),
        };
        // the linear branch divides by k: a positive φ₀ needs k > 0, i.e. δ_w > 0
        if phi0.is_some_and(|phi0| phi0 > 0.0) {
            checks.check(
                "k = 3.5 tan(wall_friction_angle) (1 + wall_restitution)",
                k,
                "(0, inf)",
                |v| v > 0.0 && v.is_finite(),
            );
        }
        checks.finish(phi0.map(|phi0| Self { k, phi0 }))
    }

    /// A φ₀ override (MFIX `PHIP0`) in (0, 1].
    pub fn check_override(phi0: f64) -> Result<f64, WallError> {
        let mut checks = Checks::default();
        let phi0 = checks.check("phi0", phi0, "(0, 1]", |v| v > 0.0 && v <= 1.0);
        checks.finish(Some(phi0))
    }

    /// Switch point r* = 4k/(7√(6π) φ₀) [-] between the linear and the 1/r branch
    /// (docs/model.md §3.7); +∞ when φ₀ = 0 (then φ ≡ 0).
    #[inline]
    pub fn switch_ratio(&self) -> f64 {
        if self.phi0 == 0.0 {
            f64::INFINITY
        } else {
            4.0 * self.k / (seven_sqrt_6pi() * self.phi0)
        }
    }

    /// φ(r) [-] (paper Eq. 16 as MFIX codes it, docs/model.md §3.7):
    /// φ₀ − (7√(6π) φ₀²/(8k)) r for r ≤ r*, 2k/(7√(6π) r) beyond. Continuous,
    /// non-increasing, in [0, φ₀] for r ≥ 0.
    #[inline]
    pub fn specularity(&self, r: f64) -> f64 {
        if self.phi0 == 0.0 {
            return 0.0;
        }
        let c = seven_sqrt_6pi();
        if r <= self.switch_ratio() {
            self.phi0 - c * self.phi0 * self.phi0 / (8.0 * self.k) * r
        } else {
            2.0 * self.k / (c * r)
        }
    }

    /// φ at a slip speed |u_sl| [m/s] and granular temperature θ > 0 [m²/s²]:
    /// φ(|u_sl|/√(3θ)).
    #[inline]
    pub fn specularity_at(&self, slip: f64, theta: f64) -> f64 {
        self.specularity(normalized_slip(slip, theta))
    }
}
