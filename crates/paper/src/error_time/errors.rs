//! The errors of one quantity over a ladder: against the finest level that has it (the
//! reference) and, with three levels or more, the observed order and the errors against the
//! Richardson extrapolation.

use super::measures::{gate_samples, history_samples, norm, profile_samples, range};
use super::quantity::{LevelData, Quantity, Source};
use super::richardson::Order;
use runout_post::convergence::{max_abs, observed_order, richardson};
use runout_post::metrics::FLOW_THRESHOLD;

/// The errors of one quantity over a ladder.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct QuantityErrors {
    /// index of the reference level, if any level has the quantity
    pub reference: Option<usize>,
    /// primary norm against the reference, per level (None: the reference itself, or no data)
    pub vs_reference: Vec<Option<f64>>,
    /// largest difference against the reference (relative to the range for profiles)
    pub max_vs_reference: Vec<Option<f64>>,
    /// primary norm against the Richardson extrapolation, per level
    pub richardson: Vec<Option<f64>>,
    /// observed order, with three levels or more
    pub order: Option<Order>,
    /// samples compared (heights in the flow band, or gates)
    pub samples: usize,
    /// why the quantity has no errors, if so
    pub note: Option<String>,
}

/// The errors of `quantity` over `ladder` (levels in any order).
pub fn quantity_errors(quantity: Quantity, ladder: &[LevelData]) -> QuantityErrors {
    if quantity.source() == Source::Station {
        return super::station_errors::station_errors(quantity, ladder);
    }
    let n = ladder.len();
    let has = |l: &LevelData| match quantity.source() {
        Source::Station => unreachable!("station numbers return above"),
        Source::Profile => l.profile.is_some(),
        Source::Gates => l.gates.is_some(),
        Source::History => l.history.as_ref().is_some_and(|h| !h.t.is_empty()),
    };
    // levels with data, finest first
    let mut with: Vec<usize> = (0..n).filter(|&k| has(&ladder[k])).collect();
    with.sort_by(|&a, &b| ladder[a].h.total_cmp(&ladder[b].h));
    let mut out = QuantityErrors {
        vs_reference: vec![None; n],
        max_vs_reference: vec![None; n],
        richardson: vec![None; n],
        ..QuantityErrors::default()
    };
    let Some(&reference) = with.first() else {
        out.note = Some("no run has it".into());
        return out;
    };
    out.reference = Some(reference);
    // a station profile is compared only where the reference run has flow there: below the
    // threshold the band is a few dilute cells and the range that scales the error is noise
    if let Some(p) = ladder[reference].profile.as_ref() {
        let peak = p.eps_s.iter().copied().fold(0.0, f64::max);
        if quantity.is_profile() && peak < FLOW_THRESHOLD {
            out.note = Some(format!(
                "the reference run has no flow at the station (largest εs {peak:.1e} < \
                 {FLOW_THRESHOLD}): no profile error"
            ));
            return out;
        }
    }
    let samples = match quantity.source() {
        Source::Station => unreachable!("station numbers return above"),
        Source::Profile => profile_samples(quantity, ladder, reference),
        Source::Gates => gate_samples(ladder),
        Source::History => history_samples(quantity, ladder, reference),
    };
    out.samples = samples.weights.len();
    if samples.weights.is_empty() {
        out.note = Some(match quantity.source() {
            Source::Station => unreachable!("station numbers return above"),
            Source::Profile => format!("no run has εs ≥ {FLOW_THRESHOLD} at the station"),
            Source::Gates => "no gate reached by every run".into(),
            Source::History => "no sample time common to every run".into(),
        });
        return out;
    }
    let values = |k: usize| samples.values[k].as_ref().expect("a level with data");
    let diff = |a: &[f64], b: &[f64]| -> Vec<f64> { a.iter().zip(b).map(|(x, y)| x - y).collect() };
    let scale = |v: &[f64]| if quantity.is_profile() { range(v) } else { 1.0 };
    let q_ref = values(reference);
    for &k in &with[1..] {
        let d = diff(values(k), q_ref);
        out.vs_reference[k] = Some(norm(quantity, &samples.weights, &d) / scale(q_ref));
        out.max_vs_reference[k] = Some(max_abs(&d) / scale(q_ref));
    }
    if let [l1, l2, l3, ..] = with[..] {
        let (q1, q2, q3) = (values(l1), values(l2), values(l3));
        let d21 = norm(quantity, &samples.weights, &diff(q2, q1));
        let d32 = norm(quantity, &samples.weights, &diff(q3, q2));
        let h = [ladder[l1].h, ladder[l2].h, ladder[l3].h];
        let p = observed_order(d32, d21, h);
        if let Some(p) = p {
            let extrapolated = richardson(q1, q2, [h[0], h[1]], p);
            for &k in &with {
                let d = diff(values(k), &extrapolated);
                out.richardson[k] =
                    Some(norm(quantity, &samples.weights, &d) / scale(&extrapolated));
            }
        }
        out.order = Some(Order {
            levels: [l1, l2, l3],
            d21,
            d32,
            p,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use runout_case::Convection;

    use super::super::quantity::History;
    use super::super::richardson::asymptotic;
    use super::*;
    use runout_post::profile::Profile;

    /// Linear profiles q_h(y) = f(y) + C hᵖ g(y) on a uniform grid of `cells` cells over
    /// [0, 0.3] m: linear interpolation is exact for them, so every error is known in
    /// closed form.
    fn synthetic(h: f64, cells: usize, c: f64, p: f64) -> LevelData {
        let dy = 0.3 / cells as f64;
        let y: Vec<f64> = (0..cells).map(|k| (k as f64 + 0.5) * dy).collect();
        let profile = |a: f64, b: f64| -> Vec<f64> {
            y.iter()
                .map(|&y| a + b * y + c * h.powf(p) * (1.0 + 2.0 * y))
                .collect()
        };
        LevelData {
            h,
            profile: Some(Profile {
                eps_s: profile(0.2, 1.0),
                u_s: profile(1.0, 10.0),
                theta: profile(0.01, 0.1),
                y,
            }),
            // gate g: speed 2 + g/2 + C hᵖ g
            gates: Some(
                (1..=7)
                    .map(|g| (g, 2.0 + 0.5 * g as f64 + c * h.powf(p) * g as f64))
                    .collect(),
            ),
            history: Some(synthetic_history(h, c, p, 0.0)),
            ..LevelData::default()
        }
    }

    /// A bulk history sampled every 0.01 s from `offset` (levels sample at different times):
    /// no front before t = 0.1 s, then front x = 5 + 2t + C hᵖ t; mean speed 3t + C hᵖ (1 + t).
    /// Both are linear in t, so interpolation onto the reference times is exact.
    fn synthetic_history(h: f64, c: f64, p: f64, offset: f64) -> History {
        let t: Vec<f64> = (0..=100).map(|k| offset + 0.01 * k as f64).collect();
        let e = c * h.powf(p);
        History {
            front_x: t
                .iter()
                .map(|&t| {
                    if t < 0.1 {
                        f64::NAN
                    } else {
                        5.0 + 2.0 * t + e * t
                    }
                })
                .collect(),
            mean_u_s: t.iter().map(|&t| 3.0 * t + e * (1.0 + t)).collect(),
            t,
        }
    }

    #[test]
    fn errors_orders_and_richardson_of_synthetic_ladders_are_exact() {
        let (c, p) = (0.01, 1.3);
        // coarse to fine, in a shuffled order: smoke, finer, coarse, paper of S-JJ-phi
        let ladder = vec![
            synthetic(10.0, 9, c, p),
            synthetic(0.5, 180, c, p),
            synthetic(4.0, 23, c, p),
            synthetic(1.0, 90, c, p),
        ];
        for q in [Quantity::EpsS, Quantity::UsS, Quantity::Theta] {
            let e = quantity_errors(q, &ladder);
            assert_eq!(e.reference, Some(1), "{q:?}: the finest level");
            assert_eq!(e.samples, 180, "{q:?}: every height is in the flow band");
            let slope = match q {
                Quantity::EpsS => 1.0,
                Quantity::UsS => 10.0,
                _ => 0.1,
            };
            // mean of g = 1 + 2y over [0, 0.3] is 1.3; the reference's range over its centres
            let y_span = 0.3 - 0.3 / 180.0;
            let range_ref = (slope + c * 0.5f64.powf(p) * 2.0) * y_span;
            let range_exact = slope * y_span;
            for (k, h) in [(0, 10.0_f64), (2, 4.0), (3, 1.0)] {
                let expected = c * (h.powf(p) - 0.5f64.powf(p)) * 1.3 / range_ref;
                let got = e.vs_reference[k].unwrap();
                assert!(
                    (got / expected - 1.0).abs() < 1e-9,
                    "{q:?} level {k}: {got} vs {expected}"
                );
            }
            assert_eq!(e.vs_reference[1], None);
            let order = e.order.as_ref().unwrap();
            assert_eq!(order.levels, [1, 3, 2], "the three finest, finest first");
            assert!(
                (order.p.unwrap() - p).abs() < 1e-9,
                "{q:?}: p = {:?}",
                order.p
            );
            // the extrapolation is f itself: each level's error is C hᵖ mean(g) / range(f)
            for (k, h) in [(0, 10.0_f64), (1, 0.5), (2, 4.0), (3, 1.0)] {
                let expected = c * h.powf(p) * 1.3 / range_exact;
                let got = e.richardson[k].unwrap();
                assert!(
                    (got / expected - 1.0).abs() < 1e-7,
                    "{q:?} Richardson {k}: {got} vs {expected}"
                );
            }
        }
        // gate speeds: RMS of C (hᵖ − h₁ᵖ) g over g = 1..7 is C (hᵖ − h₁ᵖ) √(140/7)
        let e = quantity_errors(Quantity::GateSpeed, &ladder);
        let rms_g = (140.0f64 / 7.0).sqrt();
        let got = e.vs_reference[3].unwrap();
        let expected = c * (1.0 - 0.5f64.powf(p)) * rms_g;
        assert!((got / expected - 1.0).abs() < 1e-9, "{got} vs {expected}");
        assert!((e.order.unwrap().p.unwrap() - p).abs() < 1e-9);
        assert!((e.richardson[1].unwrap() / (c * 0.5f64.powf(p) * rms_g) - 1.0).abs() < 1e-7);
    }

    #[test]
    fn history_errors_use_the_common_times_with_a_front() {
        let (c, p) = (0.01, 1.0);
        let mut ladder = vec![
            synthetic(4.0, 23, c, p),
            synthetic(2.0, 45, c, p),
            synthetic(1.0, 90, c, p),
        ];
        // the coarsest run samples 3 ms later and stops 0.2 s earlier
        let mut late = synthetic_history(4.0, c, p, 0.003);
        for v in [&mut late.t, &mut late.front_x, &mut late.mean_u_s] {
            v.truncate(81);
        }
        ladder[0].history = Some(late);
        // reference times 0.00 … 1.00: in [0.003, 0.803] and with a front in every run
        // (the late run's first front sample is at 0.103, so 0.10 interpolates towards NaN)
        // → 0.11 … 0.80 for the front; the mean speed exists from the start: 0.01 … 0.80
        let front_times: Vec<f64> = (11..=80).map(|k| 0.01 * k as f64).collect();
        let speed_times: Vec<f64> = (1..=80).map(|k| 0.01 * k as f64).collect();
        let rms = |times: &[f64], g: &dyn Fn(f64) -> f64| {
            (times.iter().map(|&t| g(t) * g(t)).sum::<f64>() / times.len() as f64).sqrt()
        };
        let front = quantity_errors(Quantity::FrontPosition, &ladder);
        assert_eq!(front.reference, Some(2));
        assert_eq!(front.samples, front_times.len());
        let speed = quantity_errors(Quantity::MeanSpeed, &ladder);
        assert_eq!(speed.samples, speed_times.len());
        for (k, h) in [(0, 4.0_f64), (1, 2.0)] {
            let d = c * (h.powf(p) - 1.0);
            let got = front.vs_reference[k].unwrap();
            let expected = rms(&front_times, &|t| d * t);
            assert!(
                (got / expected - 1.0).abs() < 1e-9,
                "front {k}: {got} vs {expected}"
            );
            let got = speed.vs_reference[k].unwrap();
            let expected = rms(&speed_times, &|t| d * (1.0 + t));
            assert!(
                (got / expected - 1.0).abs() < 1e-9,
                "speed {k}: {got} vs {expected}"
            );
        }
        assert!((front.order.unwrap().p.unwrap() - p).abs() < 1e-9);
        assert!((speed.order.unwrap().p.unwrap() - p).abs() < 1e-9);
        // a run without bulk.csv is left out
        ladder[1].history = None;
        assert_eq!(quantity_errors(Quantity::MeanSpeed, &ladder).order, None);
    }

    #[test]
    fn missing_data_and_non_converging_ladders_say_so() {
        let (c, p) = (0.01, 1.0);
        let mut ladder = vec![
            synthetic(10.0, 9, c, p),
            synthetic(4.0, 23, c, p),
            synthetic(1.0, 90, c, p),
        ];
        // the finest run has no profile (it ended early): the next finest is the reference
        ladder[2].profile = None;
        let e = quantity_errors(Quantity::UsS, &ladder);
        assert_eq!(e.reference, Some(1));
        assert!(e.order.is_none(), "two levels give no order");
        assert!(e.vs_reference[0].unwrap() > 0.0);
        // a reference without flow at the station gives no profile error
        let mut dry = ladder.clone();
        for e in &mut dry[1].profile.as_mut().unwrap().eps_s {
            *e = 1e-3;
        }
        let e = quantity_errors(Quantity::UsS, &dry);
        assert!(e.note.unwrap().contains("no flow at the station"));
        assert!(e.vs_reference.iter().all(Option::is_none));
        // a gate the coarsest run never reached is left out for every level
        ladder[0].gates.as_mut().unwrap().retain(|&(g, _)| g < 7);
        assert_eq!(quantity_errors(Quantity::GateSpeed, &ladder).samples, 6);
        // no data at all
        let empty = vec![LevelData {
            h: 1.0,
            ..LevelData::default()
        }];
        assert_eq!(
            quantity_errors(Quantity::EpsS, &empty).note.as_deref(),
            Some("no run has it")
        );
        assert!(asymptotic(1.1, &Convection::Upwind));
        assert!(!asymptotic(2.0, &Convection::Upwind));
        assert!(asymptotic(2.0, &Convection::Superbee));
        assert!(!asymptotic(0.3, &Convection::Superbee));
    }
}
