//! Roache's grid convergence index (GCI) of one scalar from the three finest levels of a
//! ladder, as the ASME V&V 20 practice states it (Roache 1994, 1998; Celik et al. 2008,
//! "Procedure for estimation and reporting of uncertainty due to discretization in CFD
//! applications", J. Fluids Eng. 130, 078001):
//!
//! - ε₂₁ = q₂ − q₁ and ε₃₂ = q₃ − q₂ (level 1 the finest, h₁ < h₂ < h₃, r₂₁ = h₂/h₁);
//! - the convergence is **monotone** when ε₃₂/ε₂₁ > 0 and |ε₂₁| < |ε₃₂|, **oscillatory** when
//!   ε₃₂/ε₂₁ < 0, **diverging** when the differences grow;
//! - for a monotone ladder, the observed order p solves ε₃₂/ε₂₁ = (h₃ᵖ − h₂ᵖ)/(h₂ᵖ − h₁ᵖ)
//!   ([`crate::convergence::observed_order`]) and the Richardson extrapolation is
//!   q* = q₁ + (q₁ − q₂)/(r₂₁ᵖ − 1) ([`crate::convergence::richardson`]);
//! - GCI₂₁ = Fs |ε₂₁/q₁| / (r₂₁ᵖ − 1) (relative to the fine value; the page also gives
//!   Fs |ε₂₁| / (r₂₁ᵖ − 1) in the quantity's unit, defined where q₁ = 0), with the factor of
//!   safety Fs = 1.25 when three levels give an order in the asymptotic range, and otherwise
//!   Fs = 3 with the scheme's nominal order (Roache's two-grid GCI: the observed order is not
//!   trusted then).

use runout_case::Convection;

use crate::convergence::{observed_order, richardson};

/// An observed order is asymptotic within these fractions of the nominal order range.
pub const ASYMPTOTIC_BAND: (f64, f64) = (0.5, 1.5);

/// The nominal order range of a scheme (upwind: 1; Superbee: 1 at extrema and fronts where
/// the limiter falls back to upwind, 2 where the solution is smooth).
pub fn nominal_order(scheme: &Convection) -> (f64, f64) {
    match scheme {
        Convection::Upwind => (1.0, 1.0),
        Convection::Superbee => (1.0, 2.0),
    }
}

/// Whether an observed order lies within [`ASYMPTOTIC_BAND`] of the scheme's nominal range.
pub fn asymptotic(p: f64, scheme: &Convection) -> bool {
    let (lo, hi) = nominal_order(scheme);
    (ASYMPTOTIC_BAND.0 * lo..=ASYMPTOTIC_BAND.1 * hi).contains(&p)
}

/// Factor of safety with three levels and an observed order in the asymptotic range
/// (Roache 1998; Celik et al. 2008, eq. 7).
pub const FS_THREE_LEVELS: f64 = 1.25;
/// Factor of safety when the observed order is not trusted (two levels, or an order outside
/// the asymptotic range): Roache's two-grid value, used with the nominal order.
pub const FS_NOMINAL_ORDER: f64 = 3.0;

/// How three levels of a scalar approach each other.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Trend {
    /// the differences keep their sign and shrink
    Monotone,
    /// the differences change sign
    Oscillatory,
    /// the differences keep their sign and grow, or the two finest are equal
    Diverging,
}

/// The GCI study of one scalar over the three finest levels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScalarConvergence {
    /// ε₂₁ = q₂ − q₁
    pub eps21: f64,
    /// ε₃₂ = q₃ − q₂
    pub eps32: f64,
    /// how the three levels approach each other
    pub trend: Trend,
    /// the observed order, for a monotone ladder
    pub observed_order: Option<f64>,
    /// whether the observed order lies in the scheme's asymptotic range
    pub asymptotic: bool,
    /// the order the GCI uses: the observed one when asymptotic, else the nominal one
    pub gci_order: f64,
    /// the factor of safety the GCI uses
    pub safety_factor: f64,
    /// Richardson extrapolation q* at the order the GCI uses
    pub extrapolated: f64,
    /// GCI of the finest level in the quantity's unit, Fs |ε₂₁| / (r₂₁ᵖ − 1)
    pub gci_fine_absolute: f64,
    /// GCI of the finest level relative to |q₁| (a fraction, not per cent; NaN if q₁ = 0)
    pub gci_fine: f64,
}

/// How three levels approach each other, from ε₂₁ = q₂ − q₁ and ε₃₂ = q₃ − q₂.
pub fn trend(eps21: f64, eps32: f64) -> Trend {
    if eps21 * eps32 < 0.0 {
        Trend::Oscillatory
    } else if eps21.abs() < eps32.abs() {
        Trend::Monotone
    } else {
        Trend::Diverging
    }
}

/// Roache's GCI of the fine level in the quantity's unit, Fs |q₁ − q₂| / (r₂₁ᵖ − 1); divided
/// by |q₁| it is the relative GCI₂₁ of Celik et al. (2008), eq. 7.
pub fn gci_fine_absolute(
    fine: f64,
    coarse: f64,
    ratio: f64,
    order: f64,
    safety_factor: f64,
) -> f64 {
    safety_factor * (fine - coarse).abs() / (ratio.powf(order) - 1.0)
}

/// The GCI study of values `q` = [q₁, q₂, q₃] at spacings `h` = [h₁, h₂, h₃] (finest first,
/// h₁ < h₂ < h₃) run with `scheme`.
pub fn scalar_convergence(q: [f64; 3], h: [f64; 3], scheme: &Convection) -> ScalarConvergence {
    let (eps21, eps32) = (q[1] - q[0], q[2] - q[1]);
    let trend = trend(eps21, eps32);
    let observed = match trend {
        Trend::Monotone => observed_order(eps32.abs(), eps21.abs(), h),
        _ => None,
    };
    let asymptotic = observed.is_some_and(|p| asymptotic(p, scheme));
    let (gci_order, safety_factor) = match observed {
        Some(p) if asymptotic => (p, FS_THREE_LEVELS),
        _ => (nominal_order(scheme).0, FS_NOMINAL_ORDER),
    };
    let extrapolated = richardson(&[q[0]], &[q[1]], [h[0], h[1]], gci_order)[0];
    let absolute = gci_fine_absolute(q[0], q[1], h[1] / h[0], gci_order, safety_factor);
    ScalarConvergence {
        eps21,
        eps32,
        trend,
        observed_order: observed,
        asymptotic,
        gci_order,
        safety_factor,
        extrapolated,
        gci_fine_absolute: absolute,
        gci_fine: if q[0] == 0.0 {
            f64::NAN
        } else {
            absolute / q[0].abs()
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Celik et al. (2008), Table 1, the φ column: three grids of 18 000, 8 000 and 4 500
    /// cells (r₂₁ = 1.5, r₃₂ = 1.333), φ = 6.063, 5.972, 5.863; the paper gives p = 1.53,
    /// φ_ext = 6.1685, e_a = 1.5 %, e_ext = 1.7 % and GCI_fine = 2.2 %. Their scheme is
    /// second order, so the order is asymptotic for Superbee's range (1–2) here.
    #[test]
    fn the_worked_example_of_celik_et_al_is_reproduced() {
        let h = [1.0, 1.5, 1.5 * 1.333];
        let q = [6.063, 5.972, 5.863];
        let s = scalar_convergence(q, h, &Convection::Superbee);
        assert_eq!(s.trend, Trend::Monotone);
        let p = s.observed_order.unwrap();
        assert!((p - 1.53).abs() < 0.01, "p = {p}");
        assert!(s.asymptotic);
        assert_eq!(s.safety_factor, FS_THREE_LEVELS);
        assert!((s.extrapolated - 6.1685).abs() < 5e-4, "{}", s.extrapolated);
        let approximate = ((q[0] - q[1]) / q[0]).abs();
        assert!((approximate - 0.015).abs() < 5e-4);
        let extrapolated_error = ((s.extrapolated - q[0]) / s.extrapolated).abs();
        assert!((extrapolated_error - 0.017).abs() < 5e-4);
        assert!((s.gci_fine - 0.022).abs() < 5e-4, "GCI {}", s.gci_fine);
    }

    /// q = q* + C hᵖ exactly: the order and the limit come back, and the GCI is Fs times
    /// the true relative error of the fine level.
    #[test]
    fn a_power_law_ladder_gives_its_order_limit_and_gci() {
        let (limit, c, p) = (7.0, 0.4, 1.2);
        let h = [1.0, 2.0, 3.956];
        let q = h.map(|h: f64| limit + c * h.powf(p));
        let s = scalar_convergence(q, h, &Convection::Upwind);
        assert!((s.observed_order.unwrap() - p).abs() < 1e-9);
        assert!(s.asymptotic);
        assert!((s.extrapolated - limit).abs() < 1e-9);
        let true_error = ((q[0] - limit) / q[0]).abs();
        assert!((s.gci_fine - FS_THREE_LEVELS * true_error).abs() < 1e-9);
    }

    /// Outside the asymptotic range, oscillating or diverging: Fs = 3 at the nominal order.
    #[test]
    fn an_untrusted_order_falls_back_to_fs_3_and_the_nominal_order() {
        let h = [1.0, 2.0, 4.0];
        // p = 3 for upwind: not asymptotic
        let steep = scalar_convergence([1.0, 1.1, 1.9], h, &Convection::Upwind);
        assert!((steep.observed_order.unwrap() - 3.0).abs() < 1e-9);
        assert!(!steep.asymptotic);
        assert_eq!(
            (steep.gci_order, steep.safety_factor),
            (1.0, FS_NOMINAL_ORDER)
        );
        assert!((steep.gci_fine - 3.0 * 0.1).abs() < 1e-12);
        assert!((steep.gci_fine_absolute - 3.0 * 0.1).abs() < 1e-12);
        assert!((steep.extrapolated - 0.9).abs() < 1e-12);
        let oscillating = scalar_convergence([1.0, 1.1, 1.0], h, &Convection::Upwind);
        assert_eq!(oscillating.trend, Trend::Oscillatory);
        assert_eq!(oscillating.observed_order, None);
        assert_eq!(oscillating.safety_factor, FS_NOMINAL_ORDER);
        let diverging = scalar_convergence([1.0, 1.2, 1.3], h, &Convection::Upwind);
        assert_eq!(diverging.trend, Trend::Diverging);
        assert!(!diverging.asymptotic);
        assert_eq!(trend(0.0, 0.0), Trend::Diverging);
        // a cushion absent at the two finest levels: no relative GCI, an absolute one of 0
        let absent = scalar_convergence([0.0, 0.0, 0.005], h, &Convection::Upwind);
        assert!(absent.gci_fine.is_nan());
        assert_eq!(absent.gci_fine_absolute, 0.0);
    }
}
