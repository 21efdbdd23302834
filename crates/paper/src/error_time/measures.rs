//! The measures behind every error: linear interpolation, cell heights, the weighted norms
//! (L1 for profiles, RMS otherwise), and the samples of each quantity that all levels of a
//! ladder share (the flow band of a profile, the common gates, the common times).

use super::quantity::{History, LevelData, Quantity};
use runout_mesh::{interpolate, Beyond};
use runout_post::convergence::{weighted_l1, weighted_l2};
use runout_post::metrics::FLOW_THRESHOLD;
use runout_post::profile::Profile;

/// Linear interpolation of (xs, ys) at `x`, extended linearly beyond the ends (xs
/// increasing, at least one point; [`interpolate`]). On a sample point it is that
/// sample's value alone, so a NaN neighbour (a history sample without a front) does not
/// spread onto it.
fn extended(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    interpolate(xs, ys, x, Beyond::Extrapolate).expect("a profile or history has samples")
}

/// Cell heights from cell-centre heights above a floor at y = 0 (each centre is the midpoint
/// of its faces).
pub fn cell_heights(centres: &[f64]) -> Vec<f64> {
    let mut face = 0.0;
    centres
        .iter()
        .map(|&c| {
            let top = 2.0 * c - face;
            let w = (top - face).max(0.0);
            face = top;
            w
        })
        .collect()
}

/// Weighted norm of a difference: weighted L1 for profiles, RMS for gate speeds.
pub(super) fn norm(quantity: Quantity, weights: &[f64], diff: &[f64]) -> f64 {
    if quantity.is_profile() {
        weighted_l1(weights, diff)
    } else {
        weighted_l2(weights, diff)
    }
}

/// Range (max − min) of `values`; the scale of a profile error.
pub(super) fn range(values: &[f64]) -> f64 {
    let (lo, hi) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    hi - lo
}

/// The samples of one quantity: weights and each level's values on them (None: no data).
pub(super) struct Samples {
    pub(super) weights: Vec<f64>,
    pub(super) values: Vec<Option<Vec<f64>>>,
}

/// Samples of a profile quantity on the reference heights within the flow band.
pub(super) fn profile_samples(
    quantity: Quantity,
    ladder: &[LevelData],
    reference: usize,
) -> Samples {
    let r = ladder[reference]
        .profile
        .as_ref()
        .expect("the reference has a profile");
    let heights = cell_heights(&r.y);
    let on_reference = |p: &Profile, v: &[f64]| -> Vec<f64> {
        r.y.iter().map(|&y| extended(&p.y, v, y)).collect()
    };
    // the flow band: any level's εs ≥ FLOW_THRESHOLD
    let eps: Vec<Vec<f64>> = ladder
        .iter()
        .filter_map(|l| l.profile.as_ref())
        .map(|p| on_reference(p, &p.eps_s))
        .collect();
    let band: Vec<usize> = (0..r.y.len())
        .filter(|&k| eps.iter().any(|e| e[k] >= FLOW_THRESHOLD))
        .collect();
    Samples {
        weights: band.iter().map(|&k| heights[k]).collect(),
        values: ladder
            .iter()
            .map(|l| {
                l.profile.as_ref().map(|p| {
                    let v = on_reference(p, quantity.of_profile(p));
                    band.iter().map(|&k| v[k]).collect()
                })
            })
            .collect(),
    }
}

/// Samples of the gate speeds: the gates every level with gate data reached.
pub(super) fn gate_samples(ladder: &[LevelData]) -> Samples {
    let with: Vec<&Vec<(usize, f64)>> = ladder.iter().filter_map(|l| l.gates.as_ref()).collect();
    let common: Vec<usize> = with
        .first()
        .map(|g| g.iter().map(|&(n, _)| n).collect::<Vec<_>>())
        .unwrap_or_default()
        .into_iter()
        .filter(|n| with.iter().all(|g| g.iter().any(|(m, _)| m == n)))
        .collect();
    Samples {
        weights: vec![1.0; common.len()],
        values: ladder
            .iter()
            .map(|l| {
                l.gates.as_ref().map(|g| {
                    common
                        .iter()
                        .map(|n| g.iter().find(|(m, _)| m == n).map_or(f64::NAN, |&(_, v)| v))
                        .collect()
                })
            })
            .collect(),
    }
}

/// Samples of a history on the reference run's times that every level covers (for the front,
/// where every level has one). Each level is interpolated linearly in time; a time between a
/// sample with a front and one without is left out.
pub(super) fn history_samples(
    quantity: Quantity,
    ladder: &[LevelData],
    reference: usize,
) -> Samples {
    let r = ladder[reference]
        .history
        .as_ref()
        .expect("the reference has a history");
    let with: Vec<&History> = ladder.iter().filter_map(|l| l.history.as_ref()).collect();
    let start = with
        .iter()
        .map(|h| h.t[0])
        .fold(f64::NEG_INFINITY, f64::max);
    let end = with
        .iter()
        .map(|h| h.t[h.t.len() - 1])
        .fold(f64::INFINITY, f64::min);
    // interpolated in time; NaN between a sample with a front and one without
    let at = |h: &History, t: f64| extended(&h.t, quantity.of_history(h), t);
    let times: Vec<f64> =
        r.t.iter()
            .copied()
            .filter(|&t| (start..=end).contains(&t))
            .filter(|&t| with.iter().all(|h| at(h, t).is_finite()))
            .collect();
    Samples {
        weights: vec![1.0; times.len()],
        values: ladder
            .iter()
            .map(|l| {
                l.history
                    .as_ref()
                    .map(|h| times.iter().map(|&t| at(h, t)).collect())
            })
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_and_cell_heights() {
        let (x, y) = ([0.5, 1.5, 2.5], [1.0, 3.0, 2.0]);
        assert_eq!(extended(&x, &y, 1.0), 2.0);
        assert_eq!(extended(&x, &y, 2.5), 2.0);
        // extended linearly beyond the ends
        assert_eq!(extended(&x, &y, 0.0), 0.0);
        assert_eq!(extended(&x, &y, 3.0), 1.5);
        assert_eq!(extended(&[1.0], &[4.0], 7.0), 4.0);
        // on a sample point its own value, whatever its neighbours hold
        let nan = [f64::NAN, 3.0, f64::NAN];
        assert_eq!(extended(&x, &nan, 1.5), 3.0);
        assert!(extended(&x, &nan, 1.0).is_nan());
        let h = cell_heights(&[0.005, 0.015, 0.03, 0.06]);
        let expected = [0.01, 0.01, 0.02, 0.04];
        assert!(
            h.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-15),
            "{h:?}"
        );
    }
}
