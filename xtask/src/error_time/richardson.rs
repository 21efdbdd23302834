//! The observed order of accuracy from the three finest levels
//! ([`runout_post::convergence::observed_order`]), and whether it lies in the scheme's
//! asymptotic range (which decides whether the Richardson extrapolation of
//! [`super::errors`] is to be trusted).

use runout_case::Convection;

/// An observed order is asymptotic within these fractions of the nominal order range.
pub(super) const ASYMPTOTIC_BAND: (f64, f64) = (0.5, 1.5);

/// The nominal order range of a scheme (upwind: 1; Superbee: 1 at extrema and fronts where
/// the limiter falls back to upwind, 2 where the solution is smooth).
pub(super) fn nominal_order(scheme: &Convection) -> (f64, f64) {
    match scheme {
        Convection::Upwind => (1.0, 1.0),
        Convection::Superbee => (1.0, 2.0),
    }
}
/// The observed order of a quantity from the three finest levels.
#[derive(Clone, Debug, PartialEq)]
pub struct Order {
    /// the three levels (indices into the ladder), finest first
    pub levels: [usize; 3],
    /// norm of (level 2 − level 1) and of (level 3 − level 2), in the quantity's unit
    pub d21: f64,
    /// see `d21`
    pub d32: f64,
    /// the observed order, if the differences shrink at a positive rate (p ≤ 20)
    pub p: Option<f64>,
}

/// Whether an observed order lies within [`ASYMPTOTIC_BAND`] of the scheme's nominal range.
pub fn asymptotic(p: f64, scheme: &Convection) -> bool {
    let (lo, hi) = nominal_order(scheme);
    (ASYMPTOTIC_BAND.0 * lo..=ASYMPTOTIC_BAND.1 * hi).contains(&p)
}
