//! The 2-D region Δχ² ≤ 2.30 from a quadratic fitted to the best evaluations (issue 48):
//! χ² ≈ c + gᵀu + ½ uᵀHu in unit coordinates, least squares through the `FIT_POINTS` lowest
//! χ², and the region's projection on each axis, the centre u* = −H⁻¹g ± √(2 Δχ² (H⁻¹)_ii)
//! (Press et al., *Numerical Recipes*, §15.6: the projection of the ellipse ½ δuᵀHδu ≤ Δχ²
//! on parameter i). Nelder–Mead stops with few points near the minimum, so the bounding box
//! of the evaluations inside the region alone misses the region's ends along a valley.

/// How many of the lowest evaluations the quadratic is fitted to (six coefficients).
pub const FIT_POINTS: usize = 10;

/// The projections (low, high) of the region χ² ≤ χ²_fit,min + `delta` on both unit axes, from
/// (u, χ²) points; `None` without six points, or if the fit has no minimum (H not positive
/// definite).
pub fn projections(points: &[([f64; 2], f64)], delta: f64) -> Option<[(f64, f64); 2]> {
    let mut best: Vec<&([f64; 2], f64)> = points.iter().filter(|p| p.1.is_finite()).collect();
    best.sort_by(|a, b| a.1.total_cmp(&b.1));
    best.truncate(FIT_POINTS);
    if best.len() < 6 {
        return None;
    }
    let coefficients = least_squares(&best)?;
    let [_, g0, g1, h00, h01, h11] = coefficients;
    let det = h00 * h11 - h01 * h01;
    if !(h00 > 0.0 && det > 0.0) {
        return None;
    }
    let inverse = [[h11 / det, -h01 / det], [-h01 / det, h00 / det]];
    let centre = [
        -(inverse[0][0] * g0 + inverse[0][1] * g1),
        -(inverse[1][0] * g0 + inverse[1][1] * g1),
    ];
    let half = |i: usize| (2.0 * delta * inverse[i][i]).sqrt();
    Some([0, 1].map(|i| (centre[i] - half(i), centre[i] + half(i))))
}

/// The basis of the quadratic at u: 1, u₀, u₁, ½u₀², u₀u₁, ½u₁².
fn basis(u: [f64; 2]) -> [f64; 6] {
    [
        1.0,
        u[0],
        u[1],
        0.5 * u[0] * u[0],
        u[0] * u[1],
        0.5 * u[1] * u[1],
    ]
}

/// The coefficients (c, g₀, g₁, H₀₀, H₀₁, H₁₁) by the normal equations; `None` if singular.
fn least_squares(points: &[&([f64; 2], f64)]) -> Option<[f64; 6]> {
    let mut a = [[0.0; 7]; 6];
    for (u, f) in points {
        let b = basis(*u);
        for i in 0..6 {
            for j in 0..6 {
                a[i][j] += b[i] * b[j];
            }
            a[i][6] += b[i] * f;
        }
    }
    solve(a)
}

/// Gaussian elimination with partial pivoting of the augmented 6 × 7 system.
fn solve(mut a: [[f64; 7]; 6]) -> Option<[f64; 6]> {
    let scale = a.iter().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
    for k in 0..6 {
        let p = (k..6).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()))?;
        if a[p][k].abs() <= 1e-12 * scale {
            return None;
        }
        a.swap(k, p);
        let pivot = a[k];
        for row in a.iter_mut().skip(k + 1) {
            let m = row[k] / pivot[k];
            for (v, p) in row.iter_mut().zip(pivot).skip(k) {
                *v -= m * p;
            }
        }
    }
    let mut x = [0.0; 6];
    for k in (0..6).rev() {
        let rest: f64 = (k + 1..6).map(|j| a[k][j] * x[j]).sum();
        x[k] = (a[k][6] - rest) / a[k][k];
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// χ² = 1 + 2 (δu₀ + δu₁)²/0.01 + (δu₀ − δu₁)²/0.25 about (0.4, 0.6), a tilted valley:
    /// the projections are exact.
    #[test]
    fn a_quadratic_valley_is_projected_exactly() {
        let f = |u: [f64; 2]| {
            let (a, b) = (u[0] - 0.4, u[1] - 0.6);
            1.0 + 2.0 * (a + b).powi(2) / 0.01 + (a - b).powi(2) / 0.25
        };
        let points: Vec<([f64; 2], f64)> = (0..4)
            .flat_map(|i| (0..4).map(move |j| [0.3 + 0.05 * i as f64, 0.5 + 0.07 * j as f64]))
            .map(|u| (u, f(u)))
            .collect();
        let [p0, p1] = projections(&points, 2.3).unwrap();
        // H = (4/0.01) [[1, 1], [1, 1]] + (2/0.25) [[1, −1], [−1, 1]]
        let (h_sum, h_diff): (f64, f64) = (4.0 / 0.01, 2.0 / 0.25);
        let h = [
            [h_sum + h_diff, h_sum - h_diff],
            [h_sum - h_diff, h_sum + h_diff],
        ];
        let det = h[0][0] * h[1][1] - h[0][1] * h[1][0];
        let half = (2.0 * 2.3 * h[1][1] / det).sqrt();
        assert!((p0.0 - (0.4 - half)).abs() < 1e-9, "{p0:?}");
        assert!((p1.1 - (0.6 + half)).abs() < 1e-9, "{p1:?}");
        assert!(projections(&points[..5], 2.3).is_none());
    }
}
