//! The 1-D range from the smooth response (issue 48): what the measurements say about a
//! parameter when the model's own outputs wiggle between neighbouring runs.
//!
//! A run's outputs are a smooth trend plus a grid-scale wiggle (a front moves in whole
//! cells, a gate speed carries it). χ² computed from the runs themselves then has a minimum
//! on a favourable wiggle, and the range Δχ² ≤ 1 around it is as random as the wiggle: the
//! coarse gate speeds of family M fitted at σ = 0.1 m/s gave φ 0.1975–0.2163 for a truth of
//! 0.3 (docs/reference/calibrate.md). Here the wiggle is treated as the model's scatter, a noise of
//! its own added to the measurement's:
//!
//! 1. the normalised residuals r_i(u) = (s_i(u) − m_i)/σ_i of the evaluations are smoothed
//!    in the unit coordinate u by local quadratic regression (LOESS, Cleveland 1979, JASA
//!    74:829): at u₀ the weighted least-squares quadratic through the evaluations with
//!    |u − u₀| < W (at least [`HALF_WIDTH`]), tricube weights w = (1 − (|u − u₀|/W)³)³,
//!    evaluated at u₀.
//!    The fit is linear in the data, r̂(u₀) = Σ_j l_j(u₀) r(u_j), the same weights l for every
//!    measured point i;
//! 2. the scatter about that trend, pooled over the measured points (Cleveland & Devlin
//!    1988, JASA 83:596, the residual variance of a local regression):
//!
//!      s² = (σ_model/σ)² = Σ_i Σ_j (r_i(u_j) − r̂_i(u_j))² / (n_i (n − tr L)),
//!
//!    with n the evaluations with a fit, n_i the measured points and tr L = Σ_j l_j(u_j) the
//!    fit's effective number of parameters;
//! 3. χ² of the trend with the two errors in quadrature, σ_eff² = σ² (1 + s²):
//!
//!      χ²_s(u) = Σ_i r̂_i(u)² / (1 + s²),
//!
//!    on [`GRID`] points of [0, 1], and the range Δχ²_s ≤ 1 around its minimum.
//!
//! The assumption is stated by W: the model's output is smooth over W = 0.3 of a
//! parameter's bounds (0.6 of a decade on a two-decade log scale), and what changes faster
//! is scatter. The coarse gate speeds' wiggle decorrelates over about 0.01 of the unit
//! interval (5 % of φ), the scan's points lie 0.25 apart (`--scan 5`), so every window holds
//! a scan point beside the refinement's cluster. Where fewer than [`MIN_DISTINCT`] distinct
//! values lie within W the window widens to the nearest of them (LOESS's nearest-neighbour
//! bandwidth).
//!
//! [`super::uncertainty::range`] states the hull of this range and the one read from the
//! evaluations' own χ²: with a smooth model (s ≈ 0) the two agree; with a wiggling one the
//! smooth range is the honest one; with too few evaluations the direct one stands alone.
//! Where the trend curves strongly within W the local quadratic is biased and its "scatter"
//! is mostly lack of fit: for the coarse fronts of family M (46 mm between φ = 0.1 and 0.3)
//! the smooth range alone misses the truth by 1–2 % of φ, the runs' own range does not,
//! hence the hull (docs/reference/calibrate.md, the recovery table).

use nalgebra::{Matrix3, Vector3};
use serde::Serialize;

/// Least half-width W of the local regression's window, in unit coordinates (module doc).
pub const HALF_WIDTH: f64 = 0.3;

/// Distinct evaluated values a window holds at least: where fewer lie within
/// [`HALF_WIDTH`] the window widens to the nearest this many (the nearest-neighbour
/// bandwidth of LOESS), so a quadratic (three coefficients) keeps a degree of freedom.
pub const MIN_DISTINCT: usize = 4;

/// Points of [0, 1] on which χ²_s is evaluated.
pub const GRID: usize = 1001;

/// The range of the smooth response, in the parameter's units (the `value` of [`range`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SmoothRange {
    /// (low, high) of Δχ²_s ≤ Δχ² around χ²_s's minimum
    pub bounds: (f64, f64),
    /// whether each end lies where χ²_s rises above the threshold (not at a bound of the
    /// study)
    pub bracketed: (bool, bool),
    /// where χ²_s is least
    pub optimum: f64,
    /// χ²_s there
    pub chi2_min: f64,
    /// s = σ_model/σ, the scatter about the trend in units of σ
    pub scatter: f64,
    /// evaluations used (n)
    pub evaluations: usize,
}

/// The window's half-width at `u0`: [`HALF_WIDTH`], or a little beyond the
/// [`MIN_DISTINCT`]-th nearest distinct value of `distinct` (sorted) where that is further.
fn half_width(distinct: &[f64], u0: f64) -> f64 {
    let mut d: Vec<f64> = distinct.iter().map(|u| (u - u0).abs()).collect();
    d.sort_by(f64::total_cmp);
    HALF_WIDTH.max(1.05 * d[MIN_DISTINCT - 1])
}

/// The weights l_j of the local quadratic at `u0` over the evaluations at `us` (r̂(u₀) = Σ_j
/// l_j r_j), `distinct` the sorted distinct values of `us` (at least [`MIN_DISTINCT`]);
/// `None` if the normal equations are singular.
fn local_weights(us: &[f64], distinct: &[f64], u0: f64) -> Option<Vec<f64>> {
    let width = half_width(distinct, u0);
    let tricube = |u: f64| {
        let d = (u - u0).abs() / width;
        if d < 1.0 {
            (1.0 - d * d * d).powi(3)
        } else {
            0.0
        }
    };
    // basis 1, d, d² with d = (u − u₀)/W; r̂(u₀) = e₀ᵀ (XᵀWX)⁻¹ XᵀW r
    let basis = |u: f64| {
        let d = (u - u0) / width;
        Vector3::new(1.0, d, d * d)
    };
    let w: Vec<f64> = us.iter().map(|&u| tricube(u)).collect();
    let mut normal = Matrix3::zeros();
    for (&u, &wj) in us.iter().zip(&w) {
        let b = basis(u);
        normal += wj * b * b.transpose();
    }
    let row0 = normal.try_inverse()?.row(0).transpose();
    Some(
        us.iter()
            .zip(&w)
            .map(|(&u, &wj)| wj * row0.dot(&basis(u)))
            .collect(),
    )
}

/// The trend r̂(u₀) of every measured point from the weights `l`.
fn trend(l: &[f64], residuals: &[&[f64]]) -> Vec<f64> {
    let columns = residuals[0].len();
    (0..columns)
        .map(|i| l.iter().zip(residuals).map(|(lj, r)| lj * r[i]).sum())
        .collect()
}

/// The smooth range Δχ²_s ≤ `delta` from evaluations given as (unit coordinate, normalised
/// residuals), stated through `value` (unit coordinate → the parameter's value); `None` with
/// fewer than [`MIN_DISTINCT`] distinct evaluated values with residuals of one length, or
/// without a degree of freedom for the scatter.
pub fn range(
    evaluations: &[(f64, &[f64])],
    delta: f64,
    value: impl Fn(f64) -> f64,
) -> Option<SmoothRange> {
    let columns = evaluations.iter().find(|e| !e.1.is_empty())?.1.len();
    let usable: Vec<&(f64, &[f64])> = evaluations
        .iter()
        .filter(|e| e.1.len() == columns && columns > 0)
        .collect();
    let us: Vec<f64> = usable.iter().map(|e| e.0).collect();
    let mut distinct = us.clone();
    distinct.sort_by(f64::total_cmp);
    distinct.dedup();
    if distinct.len() < MIN_DISTINCT {
        return None;
    }
    let rs: Vec<&[f64]> = usable.iter().map(|e| e.1).collect();
    // 2. the scatter about the trend at the evaluations themselves
    let (mut rss, mut trace, mut fitted) = (0.0, 0.0, 0usize);
    for (j, &u) in us.iter().enumerate() {
        let Some(l) = local_weights(&us, &distinct, u) else {
            continue;
        };
        rss += trend(&l, &rs)
            .iter()
            .zip(rs[j])
            .map(|(fit, r)| (r - fit).powi(2))
            .sum::<f64>();
        trace += l[j];
        fitted += 1;
    }
    let dof = fitted as f64 - trace;
    if dof <= 0.0 {
        return None;
    }
    let s2 = rss / (columns as f64 * dof);
    // 3. χ²_s on the grid (None where the normal equations are singular)
    let chi2: Vec<Option<f64>> = (0..GRID)
        .map(|k| {
            let u = k as f64 / (GRID - 1) as f64;
            local_weights(&us, &distinct, u)
                .map(|l| trend(&l, &rs).iter().map(|r| r * r).sum::<f64>() / (1.0 + s2))
        })
        .collect();
    let (k_min, chi2_min) = chi2
        .iter()
        .enumerate()
        .filter_map(|(k, c)| c.map(|c| (k, c)))
        .min_by(|a, b| a.1.total_cmp(&b.1))?;
    let threshold = chi2_min + delta;
    let inside = |k: usize| chi2[k].is_some_and(|c| c <= threshold);
    let (mut lo, mut hi) = (k_min, k_min);
    while lo > 0 && inside(lo - 1) {
        lo -= 1;
    }
    while hi + 1 < GRID && inside(hi + 1) {
        hi += 1;
    }
    let at = |k: usize| value(k as f64 / (GRID - 1) as f64);
    Some(SmoothRange {
        bounds: (at(lo), at(hi)),
        bracketed: (
            lo > 0 && chi2[lo - 1].is_some(),
            hi + 1 < GRID && chi2[hi + 1].is_some(),
        ),
        optimum: at(k_min),
        chi2_min,
        scatter: s2.sqrt(),
        evaluations: fitted,
    })
}

#[cfg(test)]
mod tests {
    use super::super::scatter::tests::draw;
    use super::*;

    fn view(runs: &[(f64, Vec<f64>)]) -> Vec<(f64, &[f64])> {
        runs.iter().map(|(u, r)| (*u, r.as_slice())).collect()
    }

    /// A smooth response, residuals linear in u through zero at u* = 0.45 with slopes a_i:
    /// χ² = Σ a_i² (u − u*)², Δχ² ≤ 1 for |u − u*| ≤ 1/√Σa_i². The local quadratic is
    /// exact, so the scatter is zero and the range is the exact one to the grid's step.
    #[test]
    fn a_smooth_response_gives_the_exact_range_and_no_scatter() {
        let slopes = [4.0, 6.0, 12.0];
        let runs: Vec<(f64, Vec<f64>)> = (0..=8)
            .map(|k| k as f64 / 8.0)
            .chain([0.44, 0.46, 0.451])
            .map(|u| (u, slopes.iter().map(|a| a * (u - 0.45)).collect()))
            .collect();
        let r = range(&view(&runs), 1.0, |u| u).unwrap();
        let half = 1.0 / slopes.iter().map(|a| a * a).sum::<f64>().sqrt();
        assert!(r.scatter < 1e-6, "{r:?}");
        assert!((r.bounds.0 - (0.45 - half)).abs() <= 1e-3, "{r:?}");
        assert!((r.bounds.1 - (0.45 + half)).abs() <= 1e-3, "{r:?}");
        assert_eq!(r.bracketed, (true, true));
        assert!(r.chi2_min < 1e-6);
    }

    /// The gate speeds' failure in closed form: residuals that fall steeply to u = 0.3 and are
    /// flat above, plus a wiggle of RMS a σ independent from run to run; the measurements are
    /// the truth's outputs (u = 0.6, not among the evaluations). The scatter is a within
    /// 25 %, and the smooth range covers the flat stretch and so the truth, where the runs'
    /// own χ² has its minimum on whichever evaluation's wiggle happens to be smallest.
    #[test]
    fn a_wiggling_response_is_scatter_and_the_range_covers_the_flat_trend() {
        let truth = 0.6;
        let a: f64 = 0.5;
        let amplitude = a * 3f64.sqrt();
        // the trend: steep below u = 0.3 (σ units), flat above
        let trend = |u: f64, i: usize| 4.0 * (0.3 - u).max(0.0) * (1.0 + i as f64 / 4.0);
        let runs: Vec<(f64, Vec<f64>)> = (0..=8)
            .map(|k| k as f64 / 8.0)
            .chain((0..8).map(|k| 0.45 + 0.004 * k as f64))
            .enumerate()
            .map(|(k, u)| {
                let r = (0..4)
                    .map(|i| trend(u, i) + amplitude * draw(37 * k as u64 + i as u64))
                    .collect();
                (u, r)
            })
            .collect();
        let r = range(&view(&runs), 1.0, |u| u).unwrap();
        println!("{r:?}");
        assert!((r.scatter / a - 1.0).abs() < 0.25, "{r:?}");
        assert!(r.bounds.0 <= truth && truth <= r.bounds.1, "{r:?}");
        assert!(r.bounds.0 < 0.35 && r.bounds.1 == 1.0, "{r:?}");
        assert!(!r.bracketed.1);
    }

    /// Fewer than four distinct values: no smooth range; residuals of another length are left
    /// out; sparse evaluations widen the window (a linear trend stays exact).
    #[test]
    fn sparse_evaluations_widen_the_window() {
        let runs: Vec<(f64, Vec<f64>)> = (0..3).map(|k| (k as f64 / 2.0, vec![1.0])).collect();
        assert!(range(&view(&runs), 1.0, |u| u).is_none());
        let mut runs: Vec<(f64, Vec<f64>)> = (0..8)
            .map(|k| {
                let u = 0.5 + 0.01 * k as f64;
                (u, vec![2.0 * (u - 0.53), 3.0])
            })
            .chain([(1.0, vec![2.0 * 0.47, 3.0])])
            .collect();
        runs.push((0.0, vec![1.0]));
        let r = range(&view(&runs), 1.0, |u| u).unwrap();
        assert_eq!(r.evaluations, 9);
        assert!(r.scatter < 1e-6, "{r:?}");
        // Δχ² ≤ 1 for |u − 0.53| ≤ 0.5
        assert!(
            (r.bounds.0 - 0.03).abs() <= 1e-3 && r.bounds.1 == 1.0,
            "{r:?}"
        );
        assert_eq!(r.bracketed, (true, false), "{r:?}");
    }
}
