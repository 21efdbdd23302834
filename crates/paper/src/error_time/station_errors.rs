//! The errors of one station or probe number over a ladder: each level's difference from the
//! finest level that has it, the observed order of the three finest (for a monotone ladder)
//! with each level's difference from the Richardson extrapolation, and Roache's GCI
//! ([`super::gci`]).

use runout_case::Convection;
use runout_post::convergence::richardson;

use super::errors::QuantityErrors;
use super::gci::{scalar_convergence, trend, ScalarConvergence, Trend};
use super::quantity::{LevelData, Quantity};
use super::richardson::Order;
use runout_post::convergence::observed_order;

/// The levels with a value of `q`, finest first: (index in the ladder, h, value).
fn levels_with(q: Quantity, ladder: &[LevelData]) -> Vec<(usize, f64, f64)> {
    let mut with: Vec<(usize, f64, f64)> = ladder
        .iter()
        .enumerate()
        .filter_map(|(k, l)| Some((k, l.h, l.station.get(q)?)))
        .collect();
    with.sort_by(|a, b| a.1.total_cmp(&b.1));
    with
}

/// The errors of the station number `q` over `ladder`: |q_k − q_ref| against the finest
/// level, and |q_k − q*| against the Richardson extrapolation where the three finest levels
/// converge monotonically.
pub(super) fn station_errors(q: Quantity, ladder: &[LevelData]) -> QuantityErrors {
    let n = ladder.len();
    let mut out = QuantityErrors {
        vs_reference: vec![None; n],
        max_vs_reference: vec![None; n],
        richardson: vec![None; n],
        ..QuantityErrors::default()
    };
    let with = levels_with(q, ladder);
    let Some(&(reference, _, q_ref)) = with.first() else {
        out.note = Some("no run has it".into());
        return out;
    };
    out.reference = Some(reference);
    out.samples = 1;
    for &(k, _, v) in &with[1..] {
        out.vs_reference[k] = Some((v - q_ref).abs());
        out.max_vs_reference[k] = out.vs_reference[k];
    }
    if let [(l1, h1, q1), (l2, h2, q2), (l3, h3, q3), ..] = with[..] {
        let (eps21, eps32) = (q2 - q1, q3 - q2);
        let p = match trend(eps21, eps32) {
            Trend::Monotone => observed_order(eps32.abs(), eps21.abs(), [h1, h2, h3]),
            _ => None,
        };
        if let Some(p) = p {
            let limit = richardson(&[q1], &[q2], [h1, h2], p)[0];
            for &(k, _, v) in &with {
                out.richardson[k] = Some((v - limit).abs());
            }
        }
        out.order = Some(Order {
            levels: [l1, l2, l3],
            d21: eps21.abs(),
            d32: eps32.abs(),
            p,
        });
    }
    out
}

/// Roache's GCI of the station number `q` from the three finest levels that have it.
pub(super) fn station_gci(
    q: Quantity,
    ladder: &[LevelData],
    scheme: &Convection,
) -> Option<ScalarConvergence> {
    match levels_with(q, ladder)[..] {
        [(_, h1, q1), (_, h2, q2), (_, h3, q3), ..] => {
            Some(scalar_convergence([q1, q2, q3], [h1, h2, h3], scheme))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::super::station::StationValues;
    use super::*;

    fn level(h: f64, max_u_s: Option<f64>) -> LevelData {
        LevelData {
            h,
            station: StationValues {
                air_cushion: None,
                values: vec![(Quantity::MaxUs, max_u_s.ok_or_else(|| "none".to_string()))],
            },
            ..LevelData::default()
        }
    }

    #[test]
    fn a_first_order_ladder_gives_its_errors_order_and_limit() {
        // q = 8 − 0.5 h, in the order coarse, paper, half, and a level without the number
        let q = |h: f64| 8.0 - 0.5 * h;
        let ladder = vec![
            level(4.0, Some(q(4.0))),
            level(1.0, Some(q(1.0))),
            level(2.0, Some(q(2.0))),
            level(8.0, None),
        ];
        let e = station_errors(Quantity::MaxUs, &ladder);
        assert_eq!(e.reference, Some(1));
        assert_eq!(e.vs_reference, vec![Some(1.5), None, Some(0.5), None]);
        let order = e.order.unwrap();
        assert_eq!(order.levels, [1, 2, 0]);
        assert!((order.p.unwrap() - 1.0).abs() < 1e-9);
        // against the limit 8: each level's error is 0.5 h
        for (k, h) in [(0, 4.0), (1, 1.0), (2, 2.0)] {
            assert!((e.richardson[k].unwrap() - 0.5 * h).abs() < 1e-9);
        }
        let gci = station_gci(Quantity::MaxUs, &ladder, &Convection::Upwind).unwrap();
        assert!(gci.asymptotic);
        assert!((gci.extrapolated - 8.0).abs() < 1e-9);
        assert!(station_gci(Quantity::FlowThickness, &ladder, &Convection::Upwind).is_none());
    }

    #[test]
    fn an_oscillating_ladder_has_no_order_and_no_extrapolation() {
        let ladder = vec![
            level(4.0, Some(7.0)),
            level(2.0, Some(7.4)),
            level(1.0, Some(7.2)),
        ];
        let e = station_errors(Quantity::MaxUs, &ladder);
        assert_eq!(e.order.unwrap().p, None);
        assert!(e.richardson.iter().all(Option::is_none));
    }
}
