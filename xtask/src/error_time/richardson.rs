//! The observed order of accuracy from the three finest levels, and whether it lies in the
//! scheme's asymptotic range (which decides whether the Richardson extrapolation of
//! [`super::errors`] is to be trusted).

use runout_case::Convection;

/// An observed order is asymptotic within these fractions of the nominal order range.
pub(super) const ASYMPTOTIC_BAND: (f64, f64) = (0.5, 1.5);

/// The nominal order range of a scheme (upwind: 1; Superbee: 1 at extrema and fronts where
/// the limiter falls back to upwind, 2 where the solution is smooth).
fn nominal_order(scheme: &Convection) -> (f64, f64) {
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

/// The observed order p > 0 with d32/d21 = (h3ᵖ − h2ᵖ)/(h2ᵖ − h1ᵖ) for h1 < h2 < h3, if any
/// p in (0, 20] solves it (the right side grows with p from ln(h3/h2)/ln(h2/h1)).
pub fn observed_order(d32: f64, d21: f64, h: [f64; 3]) -> Option<f64> {
    let [h1, h2, h3] = h;
    if !(d21 > 0.0 && d32.is_finite() && h1 < h2 && h2 < h3 && h1 > 0.0) {
        return None;
    }
    let ratio = d32 / d21;
    let g = |p: f64| (h3.powf(p) - h2.powf(p)) / (h2.powf(p) - h1.powf(p));
    let (mut lo, mut hi) = (1e-9, 20.0);
    if !(g(lo) < ratio && ratio <= g(hi)) {
        return None;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if g(mid) < ratio {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// Whether an observed order lies within [`ASYMPTOTIC_BAND`] of the scheme's nominal range.
pub fn asymptotic(p: f64, scheme: &Convection) -> bool {
    let (lo, hi) = nominal_order(scheme);
    (ASYMPTOTIC_BAND.0 * lo..=ASYMPTOTIC_BAND.1 * hi).contains(&p)
}
