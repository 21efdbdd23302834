//! Convergence tools of grid studies: error norms, the observed order of accuracy and
//! Richardson extrapolation (Roache 1998, *Verification and Validation in Computational
//! Science and Engineering*, ch. 5; Oberkampf & Roy 2010, §8.4).
//!
//! With a discretisation error e(h) = C hᵖ + o(hᵖ):
//! - against a known solution, two levels with ratio r = h_coarse/h_fine give
//!   p = ln(e_coarse/e_fine)/ln r ([`observed_orders`]);
//! - without one, three levels h1 < h2 < h3 give p from the differences of consecutive
//!   solutions, d21 = ‖q2 − q1‖ and d32 = ‖q3 − q2‖, as the root of
//!   d32/d21 = (h3ᵖ − h2ᵖ)/(h2ᵖ − h1ᵖ) ([`observed_order`]; for a constant ratio r this is
//!   p = ln(d32/d21)/ln r);
//! - the Richardson extrapolation of the two finest levels is
//!   q* = q1 + (q1 − q2) h1ᵖ/(h2ᵖ − h1ᵖ) ([`richardson`]), exact when e = C hᵖ.

/// Largest order [`observed_order`] looks for.
pub const MAX_ORDER: f64 = 20.0;

/// Weighted L1 norm Σ wᵢ|dᵢ| / Σ wᵢ.
pub fn weighted_l1(weights: &[f64], diff: &[f64]) -> f64 {
    let total: f64 = weights.iter().sum();
    weights
        .iter()
        .zip(diff)
        .map(|(w, d)| w * d.abs())
        .sum::<f64>()
        / total
}

/// Weighted L2 (RMS) norm (Σ wᵢ dᵢ² / Σ wᵢ)^½.
pub fn weighted_l2(weights: &[f64], diff: &[f64]) -> f64 {
    let total: f64 = weights.iter().sum();
    (weights
        .iter()
        .zip(diff)
        .map(|(w, d)| w * d * d)
        .sum::<f64>()
        / total)
        .sqrt()
}

/// L∞ norm maxᵢ |dᵢ| (0 for no values).
pub fn max_abs(diff: &[f64]) -> f64 {
    diff.iter().fold(0.0, |m, d| m.max(d.abs()))
}

/// Observed orders ln(e_k/e_{k+1}) / ln(r_k) of errors against a known solution on
/// successively refined levels, r_k the refinement ratio between levels k and k + 1.
pub fn observed_orders(errors: &[f64], ratios: &[f64]) -> Vec<f64> {
    errors
        .windows(2)
        .zip(ratios)
        .map(|(e, r)| (e[0] / e[1]).ln() / r.ln())
        .collect()
}

/// The observed order p > 0 with d32/d21 = (h3ᵖ − h2ᵖ)/(h2ᵖ − h1ᵖ) for h1 < h2 < h3, if any
/// p in (0, [`MAX_ORDER`]] solves it (the right side grows with p from
/// ln(h3/h2)/ln(h2/h1)); found by bisection.
pub fn observed_order(d32: f64, d21: f64, h: [f64; 3]) -> Option<f64> {
    let [h1, h2, h3] = h;
    if !(d21 > 0.0 && d32.is_finite() && h1 < h2 && h2 < h3 && h1 > 0.0) {
        return None;
    }
    let ratio = d32 / d21;
    let g = |p: f64| (h3.powf(p) - h2.powf(p)) / (h2.powf(p) - h1.powf(p));
    let (mut lo, mut hi) = (1e-9, MAX_ORDER);
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

/// The Richardson extrapolation q* = q1 + (q1 − q2) h1ᵖ/(h2ᵖ − h1ᵖ) of the values `fine`
/// (spacing h1) and `coarse` (spacing h2 > h1) for order p, value by value.
pub fn richardson(fine: &[f64], coarse: &[f64], h: [f64; 2], p: f64) -> Vec<f64> {
    let factor = h[0].powf(p) / (h[1].powf(p) - h[0].powf(p));
    fine.iter()
        .zip(coarse)
        .map(|(a, b)| a + (a - b) * factor)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// e = C hᵖ exactly.
    fn power_law(c: f64, p: f64, h: f64) -> f64 {
        c * h.powf(p)
    }

    #[test]
    fn norms_of_a_known_difference() {
        let w = [1.0, 1.0, 2.0];
        let d = [1.0, -3.0, 2.0];
        assert_eq!(weighted_l1(&w, &d), (1.0 + 3.0 + 4.0) / 4.0);
        assert_eq!(weighted_l2(&w, &d), ((1.0 + 9.0 + 8.0) / 4.0f64).sqrt());
        assert_eq!(max_abs(&d), 3.0);
        assert_eq!(max_abs(&[]), 0.0);
    }

    #[test]
    fn errors_of_a_power_law_give_its_order() {
        for p in [1.0, 1.5, 2.0] {
            let h = [0.1, 0.05, 0.02];
            let e: Vec<f64> = h.iter().map(|&h| power_law(3.0, p, h)).collect();
            let orders = observed_orders(&e, &[2.0, 2.5]);
            assert_eq!(orders.len(), 2);
            for q in orders {
                assert!((q - p).abs() < 1e-12, "{q} against {p}");
            }
        }
    }

    #[test]
    fn three_levels_of_a_power_law_give_its_order_for_any_ratios() {
        // q_h = q* + C hᵖ: the differences are C (h2ᵖ − h1ᵖ) and C (h3ᵖ − h2ᵖ)
        for p in [0.8, 1.0, 2.0, 3.5] {
            let h = [0.01, 0.013, 0.03];
            let q = |h: f64| 1.0 + power_law(0.5, p, h);
            let (d21, d32) = (q(h[1]) - q(h[0]), q(h[2]) - q(h[1]));
            let got = observed_order(d32, d21, h).unwrap();
            assert!((got - p).abs() < 1e-9, "{got} against {p}");
        }
        // constant ratio r: p = ln(d32/d21)/ln r
        assert!((observed_order(8.0, 2.0, [1.0, 2.0, 4.0]).unwrap() - 2.0).abs() < 1e-9);
        // differences that grow, or none on the finest pair: no order
        assert_eq!(observed_order(1.0, 2.0, [1.0, 2.0, 4.0]), None);
        assert_eq!(observed_order(1.0, 0.0, [1.0, 2.0, 4.0]), None);
        assert_eq!(observed_order(1.0, 1.0, [2.0, 1.0, 4.0]), None);
    }

    #[test]
    fn richardson_of_a_quadratic_series_is_its_limit() {
        // q(h) = 2 + 5 h² at every point: the extrapolation is 2 exactly
        let (h1, h2) = (0.1, 0.2);
        let fine = [2.0 + 5.0 * h1 * h1, 7.0 + 5.0 * h1 * h1];
        let coarse = [2.0 + 5.0 * h2 * h2, 7.0 + 5.0 * h2 * h2];
        let limit = richardson(&fine, &coarse, [h1, h2], 2.0);
        assert!((limit[0] - 2.0).abs() < 1e-12 && (limit[1] - 7.0).abs() < 1e-12);
    }
}
