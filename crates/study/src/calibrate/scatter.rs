//! The model's own scatter between neighbouring runs (issue 48): how far a calibration's
//! χ² can be trusted at the stated σ.
//!
//! A run's outputs are not a smooth function of its parameters: a front on a grid moves with
//! a cell-scale wiggle, and a gate speed carries it (docs/reference/calibrate.md: coarse gate speeds
//! of runs 1 % apart in φ differ by 0.01–0.05 m/s). If that scatter is not small against σ,
//! χ²'s minimum sits on a favourable wiggle and the range Δχ² ≤ 1 around it is as random
//! as the wiggle. With r_i(u) = (s_i(u) − m_i)/σ_i the normalised residuals of an
//! evaluation at unit coordinates u, the pairs of neighbouring evaluations give the estimate
//!
//!   (σ_model/σ)² ≈ Σ_pairs Σ_i (r_i(u_a) − r_i(u_b))² / (2 Σ_pairs n),
//!
//! over each evaluation and its nearest neighbour (if within [`CLOSE`]), the variance of a
//! difference of two independent draws being twice each one's. The smooth change of r over
//! the pair's distance adds to it (near χ²'s minimum, where Brent and Nelder–Mead cluster
//! their points, that change is small). A wiggle that decorrelates only over distances
//! longer than the pairs' is not seen: the coarse gate speeds of family M differ by
//! ~0.02 m/s between runs 1 % apart in φ but by ~0.1 m/s between runs 5 % apart
//! (docs/reference/calibrate.md), so a small σ_model/σ is necessary for a trustworthy range, not
//! sufficient. When σ_model/σ exceeds [`RELIABLE_RATIO`] the summary says so and names the σ
//! the scatter would not dominate (3 σ_model).

use serde::Serialize;

use super::optimise::{Calibration, Param};

/// Pairs of evaluations closer than this (Euclidean, unit coordinates) measure the scatter.
pub const CLOSE: f64 = 0.02;

/// Above this σ_model/σ the range is not to be trusted: the scatter moves χ² by about
/// 2 (σ_model/σ) √n between neighbouring runs, comparable to Δχ² = 1 for n of a few.
pub const RELIABLE_RATIO: f64 = 1.0 / 3.0;

/// The model's scatter between runs closer than [`CLOSE`].
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Scatter {
    /// σ_model/σ: the RMS scatter of the residuals between close runs, per run, in units
    /// of each point's σ
    pub ratio: f64,
    /// close pairs used
    pub pairs: usize,
    /// their largest distance (unit coordinates)
    pub widest: f64,
}

impl Scatter {
    /// Whether the scatter is small enough against σ for the range to mean what it says.
    pub fn reliable(&self) -> bool {
        self.ratio <= RELIABLE_RATIO
    }
}

/// The scatter of `evaluations` given as (unit coordinates, residuals): each evaluation
/// paired with its nearest neighbour if that lies within [`CLOSE`] (each pair once), so that
/// the smooth change of r over the pair's distance stays small; `None` without such a pair
/// with residuals of the same length.
pub fn estimate(evaluations: &[(Vec<f64>, &[f64])]) -> Option<Scatter> {
    let distance = |a: &[f64], b: &[f64]| {
        a.iter()
            .zip(b)
            .map(|(p, q)| (p - q).powi(2))
            .sum::<f64>()
            .sqrt()
    };
    let usable = |k: usize| !evaluations[k].1.is_empty();
    let mut pairs: Vec<(usize, usize)> = (0..evaluations.len())
        .filter(|&a| usable(a))
        .filter_map(|a| {
            let nearest = (0..evaluations.len())
                .filter(|&b| b != a && usable(b))
                .filter(|&b| evaluations[b].1.len() == evaluations[a].1.len())
                .min_by(|&b, &c| {
                    let d = |k: usize| distance(&evaluations[a].0, &evaluations[k].0);
                    d(b).total_cmp(&d(c))
                })?;
            (distance(&evaluations[a].0, &evaluations[nearest].0) <= CLOSE)
                .then_some((a.min(nearest), a.max(nearest)))
        })
        .collect();
    pairs.sort_unstable();
    pairs.dedup();
    if pairs.is_empty() {
        return None;
    }
    let (mut sum, mut terms, mut widest) = (0.0, 0usize, 0.0f64);
    for &(a, b) in &pairs {
        let ((ua, ra), (ub, rb)) = (&evaluations[a], &evaluations[b]);
        sum += ra
            .iter()
            .zip(*rb)
            .map(|(p, q)| (p - q).powi(2))
            .sum::<f64>();
        terms += ra.len();
        widest = widest.max(distance(ua, ub));
    }
    Some(Scatter {
        ratio: (sum / (2.0 * terms as f64)).sqrt(),
        pairs: pairs.len(),
        widest,
    })
}

/// The scatter of a calibration's evaluations with residuals.
pub fn of(c: &Calibration) -> Option<Scatter> {
    let units = |x: &[f64], params: &[Param]| -> Vec<f64> {
        params.iter().zip(x).map(|(p, &v)| p.unit(v)).collect()
    };
    let with: Vec<(Vec<f64>, &[f64])> = c
        .evaluations
        .iter()
        .filter(|e| e.chi2.is_finite() && !e.residuals.is_empty())
        .map(|e| (units(&e.x, &c.params), e.residuals.as_slice()))
        .collect();
    estimate(&with)
}

#[cfg(test)]
pub(super) mod tests {
    use super::*;

    /// A deterministic draw in [−1, 1) (a hash of k), of variance 1/3.
    pub(in crate::calibrate) fn draw(k: u64) -> f64 {
        let mut z = k.wrapping_mul(0x9E37_79B9_7F4A_7C15);
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) as f64 / u64::MAX as f64 * 2.0 - 1.0
    }

    /// Residuals r_i(u) = 3 (u − 0.4) + i/10 (smooth) plus noise of RMS a: the estimate from
    /// runs clustered near u = 0.4 (steps 0.001) is a within 10 %; far pairs are not used.
    #[test]
    fn the_scatter_of_clustered_runs_is_the_noise() {
        for a in [0.05, 0.5, 2.0] {
            let amplitude = a * 3f64.sqrt(); // uniform on [−A, A] has RMS A/√3
            let runs: Vec<(Vec<f64>, Vec<f64>)> = (0..40)
                .map(|k| {
                    let u = 0.4 + 0.001 * (k as f64 - 20.0);
                    let r = (0..8)
                        .map(|i| 3.0 * (u - 0.4) + i as f64 / 10.0 + amplitude * draw(100 * k + i))
                        .collect();
                    (vec![u], r)
                })
                .chain([(vec![0.9], vec![50.0; 8])])
                .collect();
            let view: Vec<(Vec<f64>, &[f64])> = runs
                .iter()
                .map(|(u, r)| (u.clone(), r.as_slice()))
                .collect();
            let s = estimate(&view).unwrap();
            assert!((s.ratio / a - 1.0).abs() < 0.1, "a {a}: {s:?}");
            assert!(s.widest <= CLOSE);
            assert_eq!(s.reliable(), a <= RELIABLE_RATIO);
        }
    }

    /// No close pair, or residuals of different lengths: no estimate.
    #[test]
    fn without_close_pairs_there_is_none() {
        let (r1, r2) = (vec![0.1, 0.2], vec![0.3]);
        assert!(estimate(&[(vec![0.1], &r1), (vec![0.5], &r1)]).is_none());
        assert!(estimate(&[(vec![0.1], &r1), (vec![0.105], &r2)]).is_none());
    }
}
