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
//!    |u − u₀| < W (W chosen below), tricube weights w = (1 − (|u − u₀|/W)³)³,
//!    evaluated at u₀.
//!    The fit is linear in the data, r̂(u₀) = Σ_j l_j(u₀) r(u_j), the same weights l for every
//!    measured point i;
//! 2. the scatter about that trend at each measured point i (Cleveland & Devlin 1988, JASA
//!    83:596, the residual variance of a local regression):
//!
//!      s_i² = (σ_model,i/σ_i)² = Σ_j (r_i(u_j) − r̂_i(u_j))² / (n − tr L),
//!
//!    with n the evaluations with a fit and tr L = Σ_j l_j(u_j) the fit's effective number
//!    of parameters. Per point, not pooled: a front scatters by a third of a cell late in a
//!    slide and not at all early on or once it has left the domain (issue 62's fronts at
//!    0.2–1.0 s: s_i from 0 to about 0.5), and a pooled s would understate the scatter
//!    exactly where the fit is decided;
//!    and, beside it, how the scatter of one point goes with another's, the covariance
//!
//!      C_ik = Σ_j e_i(u_j) e_k(u_j) / (n − tr L),  e = r − r̂,  C_ii = s_i²:
//!
//!    a run whose front is a cell ahead at 0.6 s is ahead at 0.7 and 0.8 s too (issue 62's
//!    truths 0.45 and 0.6), so the scatter of a slide's fronts is one offset more than nine
//!    independent draws, and nine points weighed as independent make the range too narrow;
//! 3. χ² of the trend with the two errors added as covariances (generalised least squares;
//!    the measurements' own errors independent, σ_i),
//!
//!      χ²_s(u) = r̂(u)ᵀ (I + C)⁻¹ r̂(u),
//!
//!    (with C diagonal, Σ_i r̂_i² / (1 + s_i²): σ_eff,i² = σ_i² (1 + s_i²)), on [`GRID`]
//!    points of [0, 1], and the range Δχ²_s ≤ 1 around its minimum.
//!
//! The window W is chosen from the data: of the half-widths [`HALF_WIDTHS`], the one with
//! the least generalised cross-validation score (Craven & Wahba 1979, Numer. Math. 31:377;
//! for local regression Cleveland & Grosse 1991, Stat. Comput. 1:47)
//!
//!   GCV(W) = n · RSS(W) / (n − tr L(W))²,
//!
//! RSS the squared residuals about the trend pooled over the measured points. A window wider
//! than the trend's bends is biased (a misfit that falls steeply to a knee and is flat
//! beyond it, fitted by one quadratic across the knee, puts its minimum in the middle of the
//! flat part: issue 62's truth 0.45, docs/reference/calibrate.md); a narrower one follows
//! the scatter; GCV weighs the two. Where fewer than [`MIN_DISTINCT`] distinct values lie
//! within W the window widens to the nearest of them (LOESS's nearest-neighbour bandwidth).
//! The trend is only as good as the evaluations that carry it: `calibrate`'s last stage
//! samples the smooth range at a quarter of its width ([`sampling_proposals`]).
//!
//! [`super::uncertainty::range`] states the hull of this range and the one read from the
//! evaluations' own χ²: with a smooth model (s ≈ 0) the two agree; with a wiggling one the
//! smooth range is the honest one; with too few evaluations the direct one stands alone.
//! Where the trend curves strongly within W the local quadratic is biased and its "scatter"
//! is mostly lack of fit: for the coarse fronts of family M (46 mm between φ = 0.1 and 0.3)
//! the smooth range alone misses the truth by 1–2 % of φ, the runs' own range does not,
//! hence the hull (docs/reference/calibrate.md, the recovery table).

use nalgebra::{DMatrix, DVector, Matrix3, Vector3};
use serde::Serialize;

/// The half-widths W of the local regression's window the data choose from, in unit
/// coordinates (module doc): from 0.05 (a tenth of a decade on a two-decade log scale) to 0.3.
pub const HALF_WIDTHS: [f64; 6] = [0.05, 0.075, 0.1, 0.15, 0.2, 0.3];

/// Distinct evaluated values a window holds at least: where fewer lie within
/// the window's W it widens to the nearest this many (the nearest-neighbour
/// bandwidth of LOESS), so a quadratic (three coefficients) keeps a degree of freedom.
pub const MIN_DISTINCT: usize = 4;

/// How far beyond the [`MIN_DISTINCT`]-th nearest distinct value a widened window reaches,
/// as a multiple of its distance: at 1.5 that value keeps a tricube weight of 0.35. At 1.05
/// (weight 0.003) a window in a dense cluster held three values in effect, the quadratic
/// interpolated them, and the scatter about it came out a third of the truth's (the test
/// `a_scatter_shared_by_every_point_widens_the_range_to_the_truth`).
const NEIGHBOUR_REACH: f64 = 1.5;

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
    /// the scatter about the trend in units of σ, pooled: √(mean of s_i²)
    pub scatter: f64,
    /// the largest scatter of one measured point, max s_i
    pub scatter_max: f64,
    /// the mean correlation of the scatter between two measured points, C_ik/(s_i s_k) over
    /// i ≠ k with s_i, s_k > 0 (0 with one point or no scatter)
    pub correlation: f64,
    /// evaluations used (n)
    pub evaluations: usize,
    /// the window's half-width W the data chose (unit coordinates)
    pub half_width: f64,
}

/// The window's half-width at `u0`: `least`, or a little beyond the [`MIN_DISTINCT`]-th
/// nearest distinct value of `distinct` (sorted) where that is further.
fn half_width(distinct: &[f64], u0: f64, least: f64) -> f64 {
    let mut d: Vec<f64> = distinct.iter().map(|u| (u - u0).abs()).collect();
    d.sort_by(f64::total_cmp);
    least.max(NEIGHBOUR_REACH * d[MIN_DISTINCT - 1])
}

/// The weights l_j of the local quadratic at `u0` over the evaluations at `us` (r̂(u₀) = Σ_j
/// l_j r_j), `distinct` the sorted distinct values of `us` (at least [`MIN_DISTINCT`]), the
/// window's least half-width `least`; `None` if the normal equations are singular.
fn local_weights(us: &[f64], distinct: &[f64], u0: f64, least: f64) -> Option<Vec<f64>> {
    let width = half_width(distinct, u0, least);
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
    // the window by GCV (module doc), the wider on a tie
    let chosen = HALF_WIDTHS
        .iter()
        .rev()
        .filter_map(|&w| fit(&us, &distinct, &rs, w))
        .min_by(|a, b| a.gcv.total_cmp(&b.gcv))?;
    let width = chosen.half_width;
    // 3. χ²_s = r̂ᵀ (I + C)⁻¹ r̂ on the grid (None where the normal equations are singular);
    // I + C is symmetric positive definite (C a sum of outer products)
    let weight = (DMatrix::identity(columns, columns) + &chosen.covariance).cholesky()?;
    let chi2: Vec<Option<f64>> = (0..GRID)
        .map(|k| {
            let u = k as f64 / (GRID - 1) as f64;
            local_weights(&us, &distinct, u, width).map(|l| {
                let r = DVector::from_vec(trend(&l, &rs));
                r.dot(&weight.solve(&r))
            })
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
    let scatter2: Vec<f64> = chosen.covariance.diagonal().iter().copied().collect();
    Some(SmoothRange {
        bounds: (at(lo), at(hi)),
        bracketed: (
            lo > 0 && chi2[lo - 1].is_some(),
            hi + 1 < GRID && chi2[hi + 1].is_some(),
        ),
        optimum: at(k_min),
        chi2_min,
        scatter: (scatter2.iter().sum::<f64>() / columns as f64).sqrt(),
        scatter_max: scatter2.iter().fold(0.0, |m: f64, s2| m.max(s2.sqrt())),
        correlation: mean_correlation(&chosen.covariance),
        evaluations: chosen.fitted,
        half_width: width,
    })
}

/// The stations that sample a smooth range `low`–`high` (unit coordinates): the range and a
/// quarter of its width beyond each end, a quarter of its width q apart (at least `least`),
/// within [0, 1], leaving out those within q/2 of an evaluation at `evaluated`. A trend
/// carried only by a refinement's cluster and a scan point either side is a guess between
/// them (issue 62's truth 0.45: nothing between 0.40 and 0.49, where the truth lay); these
/// stations put evaluations wherever the range or its edges could move.
pub fn sampling_proposals(low: f64, high: f64, least: f64, evaluated: &[f64]) -> Vec<f64> {
    let q = (0.25 * (high - low)).max(least);
    (-1..=5)
        .map(|k| low + k as f64 * q)
        .filter(|&u| u <= high + q + 1e-12)
        .map(|u| u.clamp(0.0, 1.0))
        .filter(|&u| evaluated.iter().all(|&e| (e - u).abs() > 0.5 * q))
        .fold(Vec::new(), |mut out, u| {
            if out.last() != Some(&u) {
                out.push(u);
            }
            out
        })
}

/// The mean of C_ik/√(C_ii C_kk) over the pairs i ≠ k whose variances are positive; 0
/// without such a pair.
fn mean_correlation(c: &DMatrix<f64>) -> f64 {
    let n = c.nrows();
    let pairs: Vec<f64> = (0..n)
        .flat_map(|i| (0..n).map(move |k| (i, k)))
        .filter(|&(i, k)| i != k && c[(i, i)] > 0.0 && c[(k, k)] > 0.0)
        .map(|(i, k)| c[(i, k)] / (c[(i, i)] * c[(k, k)]).sqrt())
        .collect();
    if pairs.is_empty() {
        0.0
    } else {
        pairs.iter().sum::<f64>() / pairs.len() as f64
    }
}

/// The local regression with least half-width `least` at the evaluations themselves.
struct Fit {
    half_width: f64,
    /// C, the scatter's covariance between measured points, s_i² on its diagonal (step 2 of
    /// the module doc)
    covariance: DMatrix<f64>,
    /// the generalised cross-validation score n RSS/(n − tr L)², RSS per measured point
    gcv: f64,
    /// evaluations with a fit (n)
    fitted: usize,
}

/// The fit of the trend with least half-width `least` (`None` without a degree of freedom
/// for the scatter).
fn fit(us: &[f64], distinct: &[f64], rs: &[&[f64]], least: f64) -> Option<Fit> {
    let columns = rs[0].len();
    let (mut products, mut trace, mut residual_dof, mut fitted) =
        (DMatrix::zeros(columns, columns), 0.0, 0.0, 0usize);
    for (j, &u) in us.iter().enumerate() {
        let Some(l) = local_weights(us, distinct, u, least) else {
            continue;
        };
        let e = DVector::from_iterator(
            columns,
            trend(&l, rs).iter().zip(rs[j]).map(|(fit, r)| r - fit),
        );
        products += &e * e.transpose();
        trace += l[j];
        // row j's share of δ₁ = tr((I − L)ᵀ(I − L)): Σ_m (δ_jm − l_jm)²
        residual_dof += l
            .iter()
            .enumerate()
            .map(|(m, lm)| (f64::from(u8::from(m == j)) - lm).powi(2))
            .sum::<f64>();
        fitted += 1;
    }
    let dof = fitted as f64 - trace;
    let total = products.trace();
    (dof > 0.0 && residual_dof > 0.0).then(|| Fit {
        half_width: least,
        // 2. the scatter about the trend and its covariance (Cleveland & Devlin 1988)
        covariance: products / residual_dof,
        gcv: fitted as f64 * total / columns as f64 / (dof * dof),
        fitted,
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

    /// A scatter shared by every measured point, as a slide's fronts share one offset: nine
    /// residuals linear in u through zero at the truth u* = 0.5 with slopes c_i = 4..12, plus
    /// one wiggle per run of RMS a = 0.5 σ common to all nine; the measurements are the
    /// truth's outputs, so they carry its own wiggle, here a one-a draw (0.5 σ). Weighed as
    /// nine independent draws (C diagonal) the range is δ* ± 0.044 with δ* = 0.057 and misses
    /// u*; with C = a² 11ᵀ it is 0.047 ± 0.065 and holds it (worked in the test's comment).
    #[test]
    fn a_scatter_shared_by_every_point_widens_the_range_to_the_truth() {
        let (truth, a) = (0.5, 0.5_f64);
        let amplitude = a * 3f64.sqrt();
        let offset = a; // the truth run's own wiggle
        let runs: Vec<(f64, Vec<f64>)> = (0..=8)
            .map(|k| k as f64 / 8.0)
            .chain((0..16).map(|k| 0.3 + 0.025 * k as f64))
            .enumerate()
            .map(|(k, u)| {
                let wiggle = amplitude * draw(101 * k as u64 + 7);
                let r = (0..9)
                    .map(|i| 4.0 * (1.0 + i as f64 / 4.0) * (u - truth) + wiggle - offset)
                    .collect();
                (u, r)
            })
            .collect();
        let r = range(&view(&runs), 1.0, |u| u).unwrap();
        // δ* = o Σc (1 − 9β)/(Σc² − β (Σc)²), half-width 1/√(Σc² − β (Σc)²), β = a²/(1 + 9a²)
        assert!(r.correlation > 0.9, "{r:?}");
        assert!(r.bounds.0 <= truth && truth <= r.bounds.1, "{r:?}");
        assert!(
            r.bounds.1 - r.bounds.0 > 2.0 * 0.05,
            "wider than independent: {r:?}"
        );
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
        // Δχ² ≤ 1 for |u − 0.53| ≤ 0.5, to the grid's step
        assert!(
            (r.bounds.0 - 0.03).abs() <= 1.5e-3 && r.bounds.1 == 1.0,
            "{r:?}"
        );
        assert_eq!(r.bracketed, (true, false), "{r:?}");
    }

    /// Issue 62's truth 0.45 in closed form: a misfit that falls steeply to a knee at u = 0.7
    /// and is nearly flat beyond it, the truth at u = 0.85 on the flat part, evaluated by a
    /// five-point scan, a refinement's cluster and the sampled stations. One quadratic
    /// across the knee (W = 0.3) puts the trend's minimum away from the truth; the window
    /// GCV chooses is narrower than the knee's distance and its range holds the truth.
    #[test]
    fn a_knee_chooses_a_narrow_window_and_the_range_holds_the_truth() {
        let truth = 0.85;
        let trend = |u: f64, i: usize| {
            let slope = 1.0 + i as f64 / 4.0;
            40.0 * (0.7 - u).max(0.0) * slope + 4.0 * (u - truth) * slope
        };
        let runs: Vec<(f64, Vec<f64>)> = (0..=4)
            .map(|k| k as f64 / 4.0)
            .chain([0.9, 0.93, 0.95, 0.96, 0.965])
            .chain((0..6).map(|k| 0.75 + 0.04 * k as f64))
            .map(|u| (u, (0..4).map(|i| trend(u, i)).collect()))
            .collect();
        let r = range(&view(&runs), 1.0, |u| u).unwrap();
        assert!(r.half_width < HALF_WIDTHS[HALF_WIDTHS.len() - 1], "{r:?}");
        assert!(r.bounds.0 <= truth && truth <= r.bounds.1, "{r:?}");
        assert!((r.optimum - truth).abs() < 0.02, "{r:?}");
        let (us, rs): (Vec<f64>, Vec<&[f64]>) =
            runs.iter().map(|(u, r)| (*u, r.as_slice())).unzip();
        let mut distinct = us.clone();
        distinct.sort_by(f64::total_cmp);
        distinct.dedup();
        let widest = fit(&us, &distinct, &rs, 0.3).unwrap();
        let chosen = fit(&us, &distinct, &rs, r.half_width).unwrap();
        assert!(chosen.gcv < widest.gcv, "GCV prefers the narrow window");
    }

    /// The stations: the range and a quarter of its width beyond, a quarter apart, within
    /// [0, 1], none beside an evaluation; a range narrower than four `least` is sampled
    /// `least` apart around it.
    #[test]
    fn the_sampling_stations_cover_the_range_and_its_edges() {
        let u = sampling_proposals(0.4, 0.8, 1e-3, &[]);
        let expected = [0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9];
        assert_eq!(u.len(), expected.len(), "{u:?}");
        assert!(
            u.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-12),
            "{u:?}"
        );
        // evaluations within q/2 = 0.05 leave their stations out
        let u = sampling_proposals(0.4, 0.8, 1e-3, &[0.52, 0.71, 0.2]);
        assert_eq!(u.len(), 5, "{u:?}");
        // clamped to the bounds, not repeated
        let u = sampling_proposals(0.0, 0.2, 1e-3, &[]);
        assert_eq!(u.first(), Some(&0.0));
        assert!(u.windows(2).all(|w| w[1] > w[0]), "{u:?}");
        let u = sampling_proposals(0.5, 0.5001, 0.01, &[]);
        assert_eq!(u.len(), 3, "{u:?}");
        assert!((u[1] - u[0] - 0.01).abs() < 1e-12, "{u:?}");
    }
}
