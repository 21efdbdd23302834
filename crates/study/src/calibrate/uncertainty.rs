//! The range of parameters consistent with the measurements: with χ²(p) = Σ (s_i(p) −
//! m_i)²/σ_i² for measurements of independent Gaussian errors σ_i, the region
//! Δχ² = χ²(p) − χ²_min ≤ 1 for one parameter (its 68.3 % interval: the profile of χ²), and
//! Δχ² ≤ 2.30 for two (their joint 68.3 % region) (Press et al., *Numerical Recipes*,
//! §15.6).
//!
//! In 1-D the range spans every evaluation inside, in the minimum's valley or another one
//! (a response with a knee or a dip has several; the truth may sit in either), and an edge is
//! found between the outermost evaluation inside and the next one outside by interpolating
//! √Δχ² linearly: exact for a χ² quadratic in the parameter's scale, where √Δχ² is linear on
//! each side of the minimum. [`edge_proposals`] gives the next evaluation that pins an edge
//! (the same estimate, kept a tenth of the bracket away from its ends); [`gap_proposals`]
//! the evaluations that look into a wide unevaluated gap beside a near-consistent value,
//! where another valley could hide. In 2-D
//! the range is the bounding box of the evaluations inside, widened to the projections of
//! the region of a quadratic fitted to the best evaluations ([`super::ellipse`]) where the
//! fit has a minimum.
//!
//! In 1-D the stated range is the hull of that range and the range of the smooth response
//! ([`super::smooth`]: the residuals smoothed by local regression, the model's scatter about
//! them added to σ in quadrature), so that a model whose outputs wiggle between neighbouring
//! runs does not state a range as narrow as its luckiest wiggle.

use serde::Serialize;

use super::ellipse;
use super::optimise::{Calibration, Evaluation};
use super::smooth::{self, SmoothRange};

/// Δχ² of the 68.3 % interval of one parameter.
pub const DELTA_CHI2_1D: f64 = 1.0;
/// Δχ² of the joint 68.3 % region of two parameters.
pub const DELTA_CHI2_2D: f64 = 2.30;

/// The parameters with χ² ≤ χ²_min + Δχ².
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Range {
    /// Δχ² of the region (1 in 1-D, 2.30 in 2-D)
    pub delta_chi2: f64,
    /// χ²_min + Δχ²
    pub threshold: f64,
    /// per parameter: (low, high)
    pub bounds: Vec<(f64, f64)>,
    /// 1-D: whether each end lies between an evaluation inside and one outside (else it is
    /// the last evaluated point, a bound of the study: the range may go further); 2-D: false
    pub bracketed: (bool, bool),
    /// evaluations within the threshold in another valley than the minimum's, which the
    /// range spans (1-D)
    pub elsewhere: usize,
    /// how the range was found
    pub method: String,
    /// the range of the smooth response (1-D, with residuals; [`super::smooth`])
    pub smooth: Option<SmoothRange>,
}

/// Where √(f − f_min) reaches √Δ between `inside` and `outside` (u, f), linearly.
fn crossing(inside: (f64, f64), outside: (f64, f64), f_min: f64, delta: f64) -> f64 {
    let root = |f: f64| (f - f_min).max(0.0).sqrt();
    let (ri, ro) = (root(inside.1), root(outside.1));
    inside.0 + (delta.sqrt() - ri) / (ro - ri) * (outside.0 - inside.0)
}

/// The range in unit coordinates from (u, χ²) sorted by u: (low, high, bracketed low,
/// bracketed high, the outermost evaluations inside): the hull of every evaluation with
/// Δχ² ≤ `delta`, each end interpolated towards the next evaluation outside.
fn edges_1d(pts: &[(f64, f64)], delta: f64) -> (f64, f64, bool, bool, usize, usize) {
    let f_min = pts.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
    let threshold = f_min + delta;
    let lo = pts.iter().position(|p| p.1 <= threshold).expect("points");
    let hi = pts.iter().rposition(|p| p.1 <= threshold).expect("points");
    let low = if lo > 0 {
        crossing(pts[lo], pts[lo - 1], f_min, delta)
    } else {
        pts[0].0
    };
    let high = if hi + 1 < pts.len() {
        crossing(pts[hi], pts[hi + 1], f_min, delta)
    } else {
        pts[hi].0
    };
    (low, high, lo > 0, hi + 1 < pts.len(), lo, hi)
}

/// The next evaluations (unit coordinates) that pin the edges of the range Δχ² ≤ `delta`,
/// from the known (u, χ²) sorted by u: for each edge whose bracket is wider than
/// 2 `xtol`, its current estimate kept a tenth of the bracket from either end.
pub fn edge_proposals(pts: &[(f64, f64)], delta: f64, xtol: f64) -> Vec<f64> {
    if pts.len() < 2 {
        return Vec::new();
    }
    let (low, high, lo_ok, hi_ok, lo, hi) = edges_1d(pts, delta);
    let mut out = Vec::new();
    let mut propose = |estimate: f64, a: f64, b: f64| {
        let (a, b) = (a.min(b), a.max(b));
        if b - a > 2.0 * xtol {
            let margin = 0.1 * (b - a);
            out.push(estimate.clamp(a + margin, b - margin));
        }
    };
    if lo_ok {
        propose(low, pts[lo - 1].0, pts[lo].0);
    }
    if hi_ok {
        propose(high, pts[hi].0, pts[hi + 1].0);
    }
    out
}

/// Δχ² within which an evaluation outside the range marks its gap to the next evaluation as
/// worth a look ([`gap_proposals`]): 4, one parameter's two-standard-deviation (95.4 %)
/// region, values the measurements reject only weakly.
pub const GAP_DELTA_CHI2: f64 = 4.0;

/// Stations that split each gap between neighbouring evaluations outside the range into
/// `GAP_PARTS` equal parts, for gaps wider than `GAP_PARTS` · `xtol` with an end within
/// [`GAP_DELTA_CHI2`] of the minimum (unit coordinates, from (u, χ²) sorted by u). Between
/// two evaluations outside the range the trend is a guess; where one of them nearly fits
/// the measurements, a narrow valley could lie between (issue 62: fronts at 0.1–0.5 s from
/// a truth of 0.45 matched φ = 0.98 to 0.24 mm and no evaluation lay between 0.32 and 0.50,
/// so the stated range 0.58–1 missed the truth).
pub fn gap_proposals(pts: &[(f64, f64)], delta: f64, xtol: f64) -> Vec<f64> {
    if pts.len() < 2 {
        return Vec::new();
    }
    let f_min = pts.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
    let (inside, near) = (f_min + delta, f_min + GAP_DELTA_CHI2);
    pts.windows(2)
        .filter(|w| w[0].1 > inside && w[1].1 > inside)
        .filter(|w| w[0].1.min(w[1].1) <= near)
        .filter(|w| w[1].0 - w[0].0 > GAP_PARTS as f64 * xtol)
        .flat_map(|w| {
            let step = (w[1].0 - w[0].0) / GAP_PARTS as f64;
            (1..GAP_PARTS).map(move |k| w[0].0 + k as f64 * step)
        })
        .collect()
}

/// Parts a gap is split into by [`gap_proposals`].
const GAP_PARTS: usize = 4;

/// The range of `c` ([`DELTA_CHI2_1D`] in 1-D, [`DELTA_CHI2_2D`] in 2-D).
pub fn range(c: &Calibration) -> Range {
    let finite: Vec<&Evaluation> = c
        .evaluations
        .iter()
        .filter(|e| e.chi2.is_finite())
        .collect();
    if c.params.len() == 2 {
        range_2d(c, &finite)
    } else {
        range_1d(c, &finite)
    }
}

/// The 2-D range: the box of the evaluations inside Δχ² ≤ 2.30, widened to the valley
/// profile's or the fitted quadratic's projections (module doc).
fn range_2d(c: &Calibration, finite: &[&Evaluation]) -> Range {
    let best = c.optimum();
    let threshold = best.chi2 + DELTA_CHI2_2D;
    let inside: Vec<&&Evaluation> = finite.iter().filter(|e| e.chi2 <= threshold).collect();
    let mut bounds: Vec<(f64, f64)> = (0..2)
        .map(|d| {
            inside
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), e| {
                    (l.min(e.x[d]), h.max(e.x[d]))
                })
        })
        .collect();
    let units: Vec<([f64; 2], f64)> = finite
        .iter()
        .map(|e| ([c.params[0].unit(e.x[0]), c.params[1].unit(e.x[1])], e.chi2))
        .collect();
    let widened = match &c.valley {
        Some(v) => {
            let (q, t) = (v.along, 1 - v.along);
            let u = [c.params[0].unit(best.x[0]), c.params[1].unit(best.x[1])];
            v.projections((u[q], u[t], best.chi2), threshold)
                .map(|[pq, pt]| {
                    let mut axes = [(0.0, 0.0); 2];
                    (axes[q], axes[t]) = (pq, pt);
                    axes
                })
        }
        None => ellipse::projections(&units, DELTA_CHI2_2D),
    };
    if let Some(axes) = widened {
        for (d, (lo, hi)) in axes.into_iter().enumerate() {
            let p = &c.params[d];
            bounds[d].0 = bounds[d].0.min(p.value(lo.clamp(0.0, 1.0)));
            bounds[d].1 = bounds[d].1.max(p.value(hi.clamp(0.0, 1.0)));
        }
    }
    let how = match (&c.valley, widened.is_some()) {
        (Some(v), true) => format!(
            ", widened to the projections of the profile of χ² along {} ({} stations, \
             calibrate/valley.rs)",
            c.params[v.along].name,
            v.stations.len()
        ),
        (Some(_), false) => " (no station of the profile along the valley lies inside)".into(),
        (None, true) => ", widened to the projections of the region Δχ² ≤ 2.30 of a quadratic \
                         fitted to the best evaluations"
            .into(),
        (None, false) => " (the quadratic fitted to the best evaluations has no minimum: the \
                          scan grid and the simplex's points only)"
            .into(),
    };
    Range {
        delta_chi2: DELTA_CHI2_2D,
        threshold,
        bounds,
        bracketed: (false, false),
        elsewhere: 0,
        method: format!(
            "the bounding box of the {} evaluations with Δχ² ≤ 2.30{how}",
            inside.len()
        ),
        smooth: None,
    }
}

/// The 1-D range: the hull of the evaluations' own Δχ² ≤ 1 and the smooth response's
/// (module doc).
fn range_1d(c: &Calibration, finite: &[&Evaluation]) -> Range {
    let best = c.optimum();
    let p = &c.params[0];
    let mut pts: Vec<(f64, f64)> = finite.iter().map(|e| (p.unit(e.x[0]), e.chi2)).collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    pts.dedup_by(|a, b| a.0 == b.0);
    let (low, high, lo_ok, hi_ok, lo, hi) = edges_1d(&pts, DELTA_CHI2_1D);
    let threshold = best.chi2 + DELTA_CHI2_1D;
    // the evaluations inside that the minimum's own valley does not reach
    let k = pts.iter().position(|q| q.1 == best.chi2).unwrap_or(lo);
    let valley_lo = (lo..=k)
        .rev()
        .take_while(|&j| pts[j].1 <= threshold)
        .last()
        .unwrap_or(k);
    let valley_hi = (k..=hi)
        .take_while(|&j| pts[j].1 <= threshold)
        .last()
        .unwrap_or(k);
    let elsewhere = (lo..=hi)
        .filter(|&j| (j < valley_lo || j > valley_hi) && pts[j].1 <= threshold)
        .count();
    let direct = "√Δχ² interpolated linearly between the evaluations either side of each edge \
                  (exact for a quadratic χ²)";
    let with_residuals: Vec<(f64, &[f64])> = finite
        .iter()
        .filter(|e| !e.residuals.is_empty())
        .map(|e| (p.unit(e.x[0]), e.residuals.as_slice()))
        .collect();
    let smooth = smooth::range(&with_residuals, DELTA_CHI2_1D, |u| p.value(u));
    let (mut bounds, mut bracketed) = ((p.value(low), p.value(high)), (lo_ok, hi_ok));
    let method = match &smooth {
        None => direct.to_string(),
        Some(s) => {
            if s.bounds.0 < bounds.0 {
                (bounds.0, bracketed.0) = (s.bounds.0, s.bracketed.0);
            }
            if s.bounds.1 > bounds.1 {
                (bounds.1, bracketed.1) = (s.bounds.1, s.bracketed.1);
            }
            format!(
                "the hull of the evaluations' own range ({direct}: {}–{}) and the smooth \
                 response's ({}–{}: the residuals of {} evaluations smoothed by local quadratic \
                 regression, the model's scatter about them, {:.2} σ pooled and up to {:.2} σ \
                 at one point, added to σ in quadrature; calibrate/smooth.rs)",
                short(p.value(low)),
                short(p.value(high)),
                short(s.bounds.0),
                short(s.bounds.1),
                s.evaluations,
                s.scatter,
                s.scatter_max
            )
        }
    };
    Range {
        delta_chi2: DELTA_CHI2_1D,
        threshold,
        bounds: vec![bounds],
        bracketed,
        elsewhere,
        method,
        smooth,
    }
}

/// Four decimals.
fn short(v: f64) -> String {
    format!("{v:.4}")
}

#[cfg(test)]
mod tests {
    use super::super::optimise::{calibrate, Param, Settings, Stage};
    use super::*;

    fn param(lo: f64, hi: f64, start: f64) -> Param {
        Param {
            name: "a".into(),
            lo,
            hi,
            start,
            log: false,
        }
    }

    fn settings(scan: usize, refine: usize, profile: usize) -> Settings {
        Settings {
            scan,
            refine,
            jobs: 1,
            xtol: 1e-4,
            ftol: 1e-3,
            profile,
            valley: 0,
        }
    }

    #[test]
    fn the_range_of_a_quadratic_chi2_is_exact_from_a_coarse_scan() {
        // χ² = 3 + ((x − 2)/0.25)²: Δχ² ≤ 1 for |x − 2| ≤ 0.25
        let f = |x: &[f64]| 3.0 + ((x[0] - 2.0) / 0.25).powi(2);
        let c = calibrate(&[param(0.0, 4.0, 1.0)], &f, &settings(9, 0, 0)).unwrap();
        let r = range(&c);
        assert!((r.threshold - 4.0).abs() < 1e-12);
        let (lo, hi) = r.bounds[0];
        assert!(
            (lo - 1.75).abs() < 1e-9 && (hi - 2.25).abs() < 1e-9,
            "{lo} {hi}"
        );
        assert_eq!(r.bracketed, (true, true));
        // a range that reaches a bound is not bracketed there
        let c = calibrate(&[param(1.9, 4.0, 3.0)], &f, &settings(9, 0, 0)).unwrap();
        let r = range(&c);
        assert_eq!(r.bounds[0].0, 1.9);
        assert_eq!(r.bracketed, (false, true));
    }

    #[test]
    fn profile_runs_pin_the_edges_of_a_skewed_chi2() {
        // χ² = (e^(x − 1) − 1)²/0.1²: Δχ² ≤ 1 for x ∈ [1 + ln 0.9, 1 + ln 1.1]
        let f = |x: &[f64]| ((x[0] - 1.0).exp() - 1.0).powi(2) / 0.01;
        let c = calibrate(&[param(0.0, 3.0, 0.5)], &f, &settings(5, 10, 8)).unwrap();
        let (lo, hi) = range(&c).bounds[0];
        assert!((lo - (1.0 + 0.9f64.ln())).abs() < 2e-3, "{lo}");
        assert!((hi - (1.0 + 1.1f64.ln())).abs() < 2e-3, "{hi}");
        assert!(c.evaluations.iter().any(|e| e.stage.name() == "profile"));
    }

    #[test]
    fn edge_proposals_stop_at_the_tolerance() {
        let pts = [(0.0, 9.0), (0.5, 0.0), (1.0, 9.0)];
        let u = edge_proposals(&pts, 1.0, 1e-3);
        assert_eq!(u.len(), 2);
        assert!((u[0] - (0.5 - 0.5 / 3.0)).abs() < 1e-12, "{u:?}");
        assert!(edge_proposals(&pts, 1.0, 0.3).is_empty());
    }

    /// A closed-form "front" x(t; φ) = t² (4 − ln φ)/2 measured at nine times with Gaussian
    /// noise of σ: over 200 noise seeds the range Δχ² ≤ 1 contains the truth in 68 ± 7 % of
    /// the recoveries (its stated coverage), and the mean range width is proportional to σ.
    #[test]
    fn the_range_covers_the_truth_as_stated_and_narrows_with_sigma() {
        use super::super::synthetic::Normal;
        let truth: f64 = 0.3;
        let front = |phi: f64, t: f64| t * t * (4.0 - phi.ln()) / 2.0;
        let times: Vec<f64> = (2..=10).map(|k| k as f64 / 10.0).collect();
        let mut widths = Vec::new();
        for sigma in [0.02, 0.01] {
            let (mut inside, mut width) = (0, 0.0);
            let seeds = 200;
            for seed in 0..seeds {
                let mut noise = Normal::new(seed);
                let measured: Vec<f64> = times
                    .iter()
                    .map(|&t| front(truth, t) + sigma * noise.sample())
                    .collect();
                let chi2 = |x: &[f64]| {
                    times
                        .iter()
                        .zip(&measured)
                        .map(|(&t, m)| ((front(x[0], t) - m) / sigma).powi(2))
                        .sum::<f64>()
                };
                let mut p = param(0.01, 1.0, 0.05);
                p.log = true;
                let c = calibrate(&[p], &chi2, &settings(5, 8, 3)).unwrap();
                let (lo, hi) = range(&c).bounds[0];
                inside += usize::from(lo <= truth && truth <= hi);
                width += (hi / lo).ln() / seeds as f64;
            }
            let coverage = inside as f64 / 200.0;
            assert!(
                (coverage - 0.683).abs() < 0.07,
                "σ {sigma}: coverage {coverage}"
            );
            widths.push(width);
        }
        let ratio = widths[0] / widths[1];
        assert!((ratio - 2.0).abs() < 0.1, "widths {widths:?}");
    }

    /// Two parameters: a closed-form front x(t; φ, δ) = t² (4 − ln φ)/2 − t δ/20 with
    /// noise-free measurements at nine times and σ = 5 mm, recovered by Nelder–Mead from the
    /// best cell of a 5 × 5 scan: the optimum within 5 % of the truth (0.3, 11) in both, and
    /// the box Δχ² ≤ 2.30 containing it; with σ = 2 mm the box is no wider.
    #[test]
    fn two_parameters_are_recovered_with_a_box_that_contains_the_truth() {
        let front = |x: &[f64], t: f64| t * t * (4.0 - x[0].ln()) / 2.0 - t * x[1] / 20.0;
        let times: Vec<f64> = (2..=10).map(|k| k as f64 / 10.0).collect();
        let truth = [0.3, 11.0];
        let boxes: Vec<Vec<(f64, f64)>> = [0.005, 0.002]
            .iter()
            .map(|&sigma| {
                let chi2 = |x: &[f64]| {
                    times
                        .iter()
                        .map(|&t| ((front(x, t) - front(&truth, t)) / sigma).powi(2))
                        .sum::<f64>()
                };
                let mut phi = param(0.01, 1.0, 0.05);
                phi.log = true;
                let mut delta = param(5.0, 20.0, 8.0);
                delta.name = "delta".into();
                let c = calibrate(&[phi, delta], &chi2, &settings(5, 60, 0)).unwrap();
                let best = &c.optimum().x;
                assert!((best[0] / truth[0] - 1.0).abs() < 0.05, "{best:?}");
                assert!((best[1] / truth[1] - 1.0).abs() < 0.05, "{best:?}");
                let r = range(&c);
                for (d, &(lo, hi)) in r.bounds.iter().enumerate() {
                    assert!(lo <= truth[d] && truth[d] <= hi, "{d}: {lo}–{hi}");
                }
                r.bounds
            })
            .collect();
        for d in 0..2 {
            let width = |b: &[(f64, f64)]| b[d].1 - b[d].0;
            assert!(width(&boxes[1]) <= width(&boxes[0]), "{boxes:?}");
        }
    }

    /// A curved valley where the optimum found is not the truth: χ² of a banana whose floor
    /// t = 0.3 + 0.8 (q − 0.6)² lies within Δχ² ≤ 2.30 from q = 0.22 to 0.98, the truth at
    /// (0.6, 0.3), a 3 × 3 scan and 6 Nelder–Mead steps (a short refinement, as a real one
    /// is). The profile along the valley (9 stations) gives the region's projections to
    /// the stations' spacing, where the box of the evaluations and the fitted quadratic alone
    /// do not reach the ends of q's range.
    #[test]
    fn a_curved_valley_is_followed_to_its_ends() {
        let banana = |x: &[f64]| {
            let floor = 0.3 + 0.8 * (x[0] - 0.6).powi(2);
            ((x[1] - floor) / 0.03).powi(2) + ((x[0] - 0.6) / 0.25).powi(2)
        };
        let (mut q, mut t) = (param(0.0, 1.0, 0.1), param(0.0, 1.0, 0.1));
        (q.name, t.name) = ("q".into(), "t".into());
        let params = [q, t];
        let short = Settings {
            valley: 0,
            ..settings(3, 6, 0)
        };
        let without = range(&calibrate(&params, &banana, &short).unwrap());
        let with = range(&calibrate(&params, &banana, &Settings { valley: 9, ..short }).unwrap());
        // brute force: q ∈ 0.6 ± 0.25 √2.30, t from 0.3 − 0.03 √2.30 to ~0.416
        let q_edges = (0.6 - 0.25 * 2.30f64.sqrt(), 0.6 + 0.25 * 2.30f64.sqrt());
        let (q_low, q_high) = with.bounds[0];
        assert!((q_low - q_edges.0).abs() < 0.01, "{with:?}");
        assert!((q_high - q_edges.1).abs() < 0.01, "{with:?}");
        let (t_low, t_high) = with.bounds[1];
        assert!(
            (t_low - (0.3 - 0.03 * 2.30f64.sqrt())).abs() < 0.01,
            "{with:?}"
        );
        assert!(t_high > 0.40 && t_high < 0.43, "{with:?}");
        assert!(
            with.method.contains("profile of χ² along q"),
            "{}",
            with.method
        );
        let span = |r: &Range| r.bounds[0].1 - r.bounds[0].0;
        println!("without the profile: {without:?}\nwith it: {with:?}");
        assert!(span(&without) < 0.9 * span(&with), "{without:?} {with:?}");
    }

    /// Two valleys inside the threshold: the range spans both, and the one the minimum does
    /// not lie in is counted.
    #[test]
    fn the_range_spans_every_valley_inside() {
        let pts = [
            (0.0, 50.0),
            (0.3, 20.0),
            (0.45, 0.5),
            (0.6, 20.0),
            (0.8, 0.8),
            (0.9, 0.0),
            (1.0, 0.3),
        ];
        let (low, high, lo_ok, hi_ok, lo, hi) = edges_1d(&pts, 1.0);
        assert_eq!((lo, hi, lo_ok, hi_ok), (2, 6, true, false));
        // √Δχ² from √0.5 at 0.45 to √20 at 0.3 reaches 1
        let expected = 0.45 + (1.0 - 0.5f64.sqrt()) / (20f64.sqrt() - 0.5f64.sqrt()) * -0.15;
        assert!(
            (low - expected).abs() < 1e-12 && high == 1.0,
            "{low} {high}"
        );
    }

    /// Issue 62's miss in unit coordinates: the scan point 0.75 far outside, the nearest
    /// evaluation beyond the gap (0.85) just outside the range, the minimum at 0.99: the gap
    /// is split in four; a gap whose ends are both far outside, or one inside the range, is
    /// left alone.
    #[test]
    fn a_wide_gap_beside_a_near_fit_is_looked_into() {
        let pts = [
            (0.5, 300.0),
            (0.75, 105.0),
            (0.85, 1.36),
            (0.88, 0.9),
            (0.95, 0.4),
            (0.99, 0.0117),
            (1.0, 0.04),
        ];
        let got = gap_proposals(&pts, 1.0, 0.002);
        let want = [0.775, 0.8, 0.825];
        assert_eq!(got.len(), 3, "{got:?}");
        for (g, w) in got.iter().zip(want) {
            assert!((g - w).abs() < 1e-12, "{got:?}");
        }
        // narrower than four xtol: nothing
        assert!(gap_proposals(&pts, 1.0, 0.03).is_empty());
    }

    /// A broad valley at 0.98 and, beside the point where it rises past the threshold, a
    /// second one at 0.4 that reaches χ² = 0: a scan of five, Brent and the edge runs see
    /// only the broad one (the range ~0.53–1, without the truth 0.4); the gap stage looks
    /// between the scan's 0.25 and 0.5 and the range then spans 0.4. A dip narrower than a
    /// quarter of such a gap can still fall between the stations.
    #[test]
    fn a_second_valley_beside_a_near_fit_is_found() {
        let f = |x: &[f64]| {
            let broad = ((x[0] - 0.98) / 0.45).powi(2);
            let dip = ((x[0] - 0.4) / 0.05).powi(2);
            broad.min(dip)
        };
        let without = Settings {
            profile: 0,
            ..settings(5, 8, 0)
        };
        let c = calibrate(&[param(0.0, 1.0, 0.9)], &f, &without).unwrap();
        let r = range(&c);
        assert!(r.bounds[0].0 > 0.45, "{r:?}");
        let c = calibrate(&[param(0.0, 1.0, 0.9)], &f, &settings(5, 8, 2)).unwrap();
        let r = range(&c);
        assert!(
            c.evaluations.iter().any(|e| e.stage == Stage::Gap),
            "{:?}",
            c.evaluations
        );
        assert!(r.bounds[0].0 < 0.4 && r.bounds[0].1 == 1.0, "{r:?}");
        assert!(r.elsewhere > 0, "{r:?}");
    }
}
