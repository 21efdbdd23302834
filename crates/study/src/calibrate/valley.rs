//! The 2-D region Δχ² ≤ 2.30 along its valley (issue 48): a profile of χ².
//!
//! Two parameters the measurements trade off (a lower specularity with a higher wall
//! restitution slides the same way) give a χ² with a long, curved valley. Nelder–Mead ends
//! somewhere on its floor, and neither the bounding box of its evaluations nor a quadratic
//! fitted to them reaches the valley's ends (docs/reference/calibrate.md, the (φ, e_w) row). The
//! profile of χ² follows the floor instead (Press et al., *Numerical Recipes*, §15.6;
//! Venzon & Moolgavkar 1988, *Appl. Stat.* 37, "profile likelihood"):
//!
//!   P(q) = min_t χ²(q, t),
//!
//! with q the parameter the region is loosest along and t the other, both in unit
//! coordinates. At each *station* q_k (evenly spaced over the box) a 1-D minimisation in t
//! (a bracket found by golden expansion from the floor's predicted t, then Brent) gives the
//! floor P(q_k) and the samples around it. The projection of the joint region on q is where
//! P(q) ≤ χ²_min + Δχ², its edges interpolated in √(P − χ²_min) between a station inside and
//! one outside (exact where P is quadratic in q); its projection on t is the union over the
//! stations inside of the t where χ²(q_k, t) ≤ χ²_min + Δχ², each edge interpolated in
//! √(χ² − P(q_k)) (exact where χ² is quadratic across the valley). Stations march outward
//! from the optimum in two chains, each predicting the next floor from the last, and a chain
//! stops at its first station above the threshold: the edge is then bracketed.
//!
//! Resolution: the projections are exact for a valley whose floor is quadratic in q and
//! whose cross-section is quadratic in t; otherwise their error is of the order of the
//! stations' spacing in q and of Brent's tolerance in t.

use anyhow::Result;

use super::brent::{self, Bracket, Known};
use super::ellipse;

/// At most this many evaluations per station: three to bracket the floor, the rest Brent's.
pub const STATION_EVALUATIONS: usize = 7;

/// The first step from the predicted floor when bracketing it, in unit coordinates.
const FIRST_STEP: f64 = 0.1;

/// The golden ratio: each bracketing step grows by it (Press et al., §10.1, `mnbrak`).
const GROWTH: f64 = 1.618_033_988_749_895;

/// One station of the profile: the loose parameter held at `q`.
#[derive(Clone, Debug, PartialEq)]
pub struct Station {
    /// the loose parameter (unit coordinate)
    pub q: f64,
    /// the lowest sample (t, χ²): the valley's floor at q
    pub floor: Known,
    /// every sample (t, χ²) of this station, sorted by t
    pub samples: Vec<Known>,
}

/// The profile of χ² along the loose parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Valley {
    /// the index of the loose parameter q (the other is t)
    pub along: usize,
    /// the stations made, sorted by q
    pub stations: Vec<Station>,
}

/// The parameter the region χ² ≤ `threshold` is loosest along, from (u, χ²) points in unit
/// coordinates: the longer projection of the fitted quadratic's region
/// ([`ellipse::projections`]) if it has one, else the wider span of the points inside.
pub fn loose_axis(points: &[([f64; 2], f64)], best_chi2: f64, threshold: f64) -> usize {
    let width = |(lo, hi): (f64, f64)| hi.min(1.0) - lo.max(0.0);
    let spans = ellipse::projections(points, threshold - best_chi2).unwrap_or_else(|| {
        [0, 1].map(|d| {
            points
                .iter()
                .filter(|p| p.1 <= threshold)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), p| {
                    (l.min(p.0[d]), h.max(p.0[d]))
                })
        })
    });
    usize::from(width(spans[1]) > width(spans[0]))
}

/// The stations' q in the order two chains visit them: `(right, left)`, the right chain
/// from the station nearest `q_best` upward, the left from the one below it downward.
pub fn chains(stations: &[f64], q_best: f64) -> (Vec<f64>, Vec<f64>) {
    let Some(nearest) = (0..stations.len()).min_by(|&a, &b| {
        (stations[a] - q_best)
            .abs()
            .total_cmp(&(stations[b] - q_best).abs())
    }) else {
        return (Vec::new(), Vec::new());
    };
    let right = stations[nearest..].to_vec();
    let left = stations[..nearest].iter().rev().copied().collect();
    (right, left)
}

/// Walks one chain of stations: at each q the floor in t, bracketed from the last floor's t
/// (`t_start` for the first), until a station's floor lies above `threshold()` (re-read at
/// each station: a lower χ² found on the way lowers it). `chi2(q, t)` evaluates the model
/// (`None`: no more evaluations may be made; the chain ends).
pub fn walk_chain(
    qs: &[f64],
    t_start: f64,
    xtol: f64,
    threshold: impl Fn() -> f64,
    mut chi2: impl FnMut(f64, f64) -> Result<Option<f64>>,
) -> Result<Vec<Station>> {
    let mut stations = Vec::new();
    let mut t_predicted = t_start;
    for &q in qs {
        let Some(station) = station(q, t_predicted, xtol, |t| chi2(q, t))? else {
            break;
        };
        t_predicted = station.floor.0;
        let above = station.floor.1 > threshold();
        stations.push(station);
        if above {
            break;
        }
    }
    Ok(stations)
}

/// The floor of χ² in t at one station: a bracket by golden expansion from `t0`, then Brent,
/// at most [`STATION_EVALUATIONS`] evaluations; `None` if `f` gave no value at all.
fn station(
    q: f64,
    t0: f64,
    xtol: f64,
    mut f: impl FnMut(f64) -> Result<Option<f64>>,
) -> Result<Option<Station>> {
    let mut samples: Vec<Known> = Vec::new();
    let mut ask = |t: f64, samples: &mut Vec<Known>| -> Result<Option<f64>> {
        let t = t.clamp(0.0, 1.0);
        if let Some(&(_, v)) = samples.iter().find(|s| s.0 == t) {
            return Ok(Some(v));
        }
        if samples.len() >= STATION_EVALUATIONS {
            return Ok(None);
        }
        let v = f(t)?;
        if let Some(v) = v {
            samples.push((t, v));
        }
        Ok(v)
    };
    if let Some(bracket) = bracket(t0, &mut |t| ask(t, &mut samples))? {
        brent::minimise(bracket, xtol, |t| ask(t, &mut samples))?;
    }
    if samples.is_empty() {
        return Ok(None);
    }
    samples.sort_by(|a, b| a.0.total_cmp(&b.0));
    let floor = *samples
        .iter()
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .expect("samples");
    Ok(Some(Station { q, floor, samples }))
}

/// A bracket of the minimum of `f` on [0, 1] from `t0`: `t0 ± FIRST_STEP`, then steps growing
/// by the golden ratio downhill until the value rises or the bound is reached (then the
/// bound is the bracket's best point). `None` if the evaluations ran out first.
fn bracket(t0: f64, f: &mut impl FnMut(f64) -> Result<Option<f64>>) -> Result<Option<Bracket>> {
    let t0 = t0.clamp(0.0, 1.0);
    let (lo, hi) = if t0 + FIRST_STEP > 1.0 {
        (1.0 - 2.0 * FIRST_STEP, 1.0 - FIRST_STEP)
    } else if t0 - FIRST_STEP < 0.0 {
        (FIRST_STEP, 2.0 * FIRST_STEP)
    } else {
        (t0 - FIRST_STEP, t0 + FIRST_STEP)
    };
    let mut pts: Vec<Known> = Vec::new();
    for t in [lo, t0, hi] {
        let Some(v) = f(t)? else { return Ok(None) };
        pts.push((t, v));
    }
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    pts.dedup_by(|a, b| a.0 == b.0);
    loop {
        let k = (0..pts.len())
            .min_by(|&a, &b| pts[a].1.total_cmp(&pts[b].1))
            .expect("points");
        if k > 0 && k + 1 < pts.len() {
            return Ok(Some(Bracket {
                a: pts[k - 1],
                x: pts[k],
                b: pts[k + 1],
            }));
        }
        // the lowest is an end: step beyond it, or stop at the bound
        let (end, inner) = if k == 0 {
            (pts[0], pts[1])
        } else {
            (pts[k], pts[k - 1])
        };
        if end.0 == 0.0 || end.0 == 1.0 {
            let (a, b) = if k == 0 { (end, inner) } else { (inner, end) };
            return Ok(Some(Bracket { a, x: end, b }));
        }
        let next = (end.0 + GROWTH * (end.0 - inner.0)).clamp(0.0, 1.0);
        let Some(v) = f(next)? else { return Ok(None) };
        pts.push((next, v));
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
}

/// Where √(f − `floor`) reaches √(`threshold` − `floor`) between `inside` and `outside`,
/// linearly (exact where f is quadratic about its minimum `floor`).
fn crossing(inside: Known, outside: Known, floor: f64, threshold: f64) -> f64 {
    let root = |f: f64| (f - floor).max(0.0).sqrt();
    let (ri, ro) = (root(inside.1), root(outside.1));
    if ro <= ri {
        return inside.0;
    }
    inside.0 + ((threshold - floor).max(0.0).sqrt() - ri) / (ro - ri) * (outside.0 - inside.0)
}

/// The extent of `pts` (sorted by position) at or below `threshold`: each run of points
/// inside ends at its crossing with the neighbour outside, or at the last point inside if
/// it has none; `None` if no point is inside.
fn extent_below(pts: &[Known], floor: f64, threshold: f64) -> Option<(f64, f64)> {
    let inside = |k: usize| pts[k].1 <= threshold;
    let first = (0..pts.len()).find(|&k| inside(k))?;
    let last = (0..pts.len()).rfind(|&k| inside(k))?;
    let low = if first > 0 {
        crossing(pts[first], pts[first - 1], floor, threshold)
    } else {
        pts[first].0
    };
    let high = if last + 1 < pts.len() {
        crossing(pts[last], pts[last + 1], floor, threshold)
    } else {
        pts[last].0
    };
    Some((low, high))
}

impl Valley {
    /// The projections (q, t) of the region χ² ≤ `threshold` in unit coordinates, with
    /// `best` = (q, t, χ²) the lowest evaluation of the calibration (a station of its own:
    /// its q need not be a station's); `None` if no station's floor is inside.
    pub fn projections(&self, best: (f64, f64, f64), threshold: f64) -> Option<[(f64, f64); 2]> {
        let (q_best, t_best, chi2_best) = best;
        let mut floors: Vec<Known> = self.stations.iter().map(|s| (s.q, s.floor.1)).collect();
        if !floors.iter().any(|f| f.0 == q_best) {
            floors.push((q_best, chi2_best));
        }
        floors.sort_by(|a, b| a.0.total_cmp(&b.0));
        let q_range = extent_below(&floors, chi2_best, threshold)?;
        let t_range = self
            .stations
            .iter()
            .filter_map(|s| extent_below(&s.samples, s.floor.1, threshold))
            .fold((t_best, t_best), |(l, h), (lo, hi)| (l.min(lo), h.max(hi)));
        Some([q_range, t_range])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A banana: the floor t = 0.3 + 0.8 (q − 0.6)², quadratic across it with half-width w
    /// per unit χ², and along it with half-width s.
    fn banana(q: f64, t: f64) -> f64 {
        let floor = 0.3 + 0.8 * (q - 0.6).powi(2);
        ((t - floor) / 0.03).powi(2) + ((q - 0.6) / 0.25).powi(2)
    }

    /// The banana's projections at Δχ² = 2.30, by brute force on a fine grid.
    fn brute_force(delta: f64) -> [(f64, f64); 2] {
        let n = 2000;
        let mut r = [(f64::INFINITY, f64::NEG_INFINITY); 2];
        for i in 0..=n {
            for j in 0..=n {
                let (q, t) = (i as f64 / n as f64, j as f64 / n as f64);
                if banana(q, t) <= delta {
                    r[0] = (r[0].0.min(q), r[0].1.max(q));
                    r[1] = (r[1].0.min(t), r[1].1.max(t));
                }
            }
        }
        r
    }

    fn walk(qs: &[f64], t0: f64) -> Vec<Station> {
        walk_chain(qs, t0, 1e-3, || 2.30, |q, t| Ok(Some(banana(q, t)))).unwrap()
    }

    /// Each station finds the floor of the banana's cross-section (a parabola in t: Brent's
    /// first parabolic step is exact) within the tolerance.
    #[test]
    fn a_station_finds_the_floor_across_the_valley() {
        for q in [0.3, 0.6, 0.9] {
            let s = &walk(&[q], 0.5)[0];
            let floor = 0.3 + 0.8 * (q - 0.6).powi(2);
            assert!((s.floor.0 - floor).abs() < 2e-3, "q {q}: {:?}", s.floor);
            assert!(s.samples.len() <= STATION_EVALUATIONS);
        }
    }

    /// A chain stops at its first station above the threshold.
    #[test]
    fn a_chain_stops_past_the_edge() {
        let qs: Vec<f64> = (6..=10).map(|k| k as f64 / 10.0).collect();
        let stations = walk(&qs, 0.3);
        // P(q) = ((q − 0.6)/0.25)²: 1.44 at 0.9, 2.56 at 1.0 (above 2.30: the last)
        assert_eq!(stations.len(), 5);
        let stations = walk(&[0.6, 1.0, 0.0], 0.3);
        assert_eq!(stations.len(), 2, "{stations:?}");
    }

    /// The profile's projections of the banana's region Δχ² ≤ 2.30 agree with brute force:
    /// in q exactly (P is quadratic in q), in t to the stations' spacing.
    #[test]
    fn the_projections_of_a_curved_valley_match_brute_force() {
        let qs: Vec<f64> = (0..=8).map(|k| k as f64 / 8.0).collect();
        let (right, left) = chains(&qs, 0.6);
        assert_eq!(right, [0.625, 0.75, 0.875, 1.0]);
        assert_eq!(left, [0.5, 0.375, 0.25, 0.125, 0.0]);
        let mut stations = walk(&right, 0.3);
        stations.extend(walk(&left, 0.3));
        stations.sort_by(|a, b| a.q.total_cmp(&b.q));
        let valley = Valley { along: 0, stations };
        let [q, t] = valley.projections((0.6, 0.3, 0.0), 2.30).unwrap();
        let [bq, bt] = brute_force(2.30);
        assert!(
            (q.0 - bq.0).abs() < 0.01 && (q.1 - bq.1).abs() < 0.01,
            "{q:?} {bq:?}"
        );
        assert!(
            (t.0 - bt.0).abs() < 0.01 && (t.1 - bt.1).abs() < 0.02,
            "{t:?} {bt:?}"
        );
    }

    /// The loose axis of the banana is q, whichever index it has.
    #[test]
    fn the_loose_axis_is_the_long_one() {
        let pts: Vec<([f64; 2], f64)> = (0..=10)
            .flat_map(|i| (0..=10).map(move |j| (i as f64 / 10.0, j as f64 / 10.0)))
            .map(|(q, t)| ([q, t], banana(q, t)))
            .collect();
        assert_eq!(loose_axis(&pts, 0.0, 2.30), 0);
        let swapped: Vec<([f64; 2], f64)> = pts.iter().map(|p| ([p.0[1], p.0[0]], p.1)).collect();
        assert_eq!(loose_axis(&swapped, 0.0, 2.30), 1);
    }
}
