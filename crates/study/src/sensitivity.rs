//! Normalised sensitivities (elasticities) of an output over a one-factor family (issue 23,
//! item 3): pure functions of the swept parameter values and the output's values.
//!
//! A one-factor family is a set of runs that differ in one parameter p only (the points
//! p₀ < p₁ < … of a sweep); y is one output of those runs. The elasticity
//! E = ∂ ln y / ∂ ln p is the relative change of y per relative change of p (E = 0.5: 1 %
//! more p gives 0.5 % more y), a number without units that compares parameters of
//! different units and sizes.
//!
//! - **Local values** ([`local`]): for the neighbours pᵢ < pᵢ₊₁ the log–log difference
//!   E = (ln yᵢ₊₁ − ln yᵢ) / (ln pᵢ₊₁ − ln pᵢ), placed at the geometric mid-point
//!   √(pᵢ pᵢ₊₁). It is exact for a power law y = a pᵇ (E = b at every pair); for any other
//!   smooth response it is the elasticity somewhere in [pᵢ, pᵢ₊₁] (the mean-value theorem in
//!   ln p), e.g. for y = b p (linear through 0) exactly 1.
//! - **p ≤ 0** (the 0° slope): ln p does not exist. Such a pair gets the **arc elasticity**
//!   E = ((yᵢ₊₁ − yᵢ)/ȳ) / ((pᵢ₊₁ − pᵢ)/p̄) with ȳ, p̄ the pair's arithmetic means, placed at
//!   p̄; it is marked [`Method::Arc`]. It is exact for a linear response y = a + b p at p̄
//!   (E = b p̄/(a + b p̄), since ȳ = y(p̄)). On a pair (0, p) the p-factor is always 2, so E is
//!   half the relative change Δy/ȳ, within ±1 for positive y: a measure of how much y
//!   changes, not comparable in size with the log–log values.
//! - **y missing or ≤ 0**: no logarithm; the point has no value and says why (the reason of
//!   the caller, e.g. "no flow at the station", or "y ≤ 0").
//! - **Summary** ([`summary`]), one number per (family, output): the least-squares slope of
//!   ln y against ln p over all points with p > 0 and a usable y (the local value itself for
//!   two points; b for a power law). A family with fewer than two such points but an arc pair
//!   (the slope families {0°, 40°}) gets the mean of its arc elasticities. Points without a
//!   usable y are left out, and the summary says how many it used and over which range.
//!
//! Limits, stated with the report's table: one-at-a-time (the other parameters stay at the
//! family's base, so interactions are not seen), local (secants between swept points that
//! are far apart), and only as good as the runs' outputs.

/// How an elasticity was computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Δ ln y / Δ ln p (p > 0)
    LogLog,
    /// (Δy/ȳ)/(Δp/p̄), for a pair with p ≤ 0
    Arc,
}

/// An elasticity and its method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Elasticity {
    /// ∂ ln y / ∂ ln p [-]
    pub value: f64,
    /// how it was computed
    pub method: Method,
}

/// The elasticity between two neighbouring points.
#[derive(Clone, Debug, PartialEq)]
pub struct Local {
    /// the pair's parameter values (low, high)
    pub p: (f64, f64),
    /// where the value is placed: the geometric mid-point (log–log) or the arithmetic one
    /// (arc)
    pub at: f64,
    /// the value, or why there is none
    pub elasticity: Result<Elasticity, String>,
}

/// One summary elasticity of a family's output.
#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    /// the value, or why there is none
    pub elasticity: Result<Elasticity, String>,
    /// points used
    pub used: usize,
    /// points of the family
    pub of: usize,
    /// the parameter range of the points used (low, high)
    pub range: Option<(f64, f64)>,
}

/// y if it has a logarithm, else why not.
fn usable(y: &Result<f64, String>) -> Result<f64, String> {
    match y {
        Err(why) => Err(why.clone()),
        Ok(y) if !y.is_finite() => Err(format!("y is {y}")),
        Ok(y) if *y <= 0.0 => Err(format!("y = {y:.3e} ≤ 0 has no logarithm")),
        Ok(y) => Ok(*y),
    }
}

/// The points sorted by p.
fn sorted(points: &[(f64, Result<f64, String>)]) -> Vec<(f64, Result<f64, String>)> {
    let mut s = points.to_vec();
    s.sort_by(|a, b| a.0.total_cmp(&b.0));
    s
}

/// The elasticity of one pair (p sorted), or why there is none.
fn pair(p0: f64, y0: f64, p1: f64, y1: f64) -> Result<Elasticity, String> {
    if p0 == p1 {
        return Err(format!("two points at p = {p0}"));
    }
    if p0 > 0.0 && p1 > 0.0 {
        return Ok(Elasticity {
            value: (y1.ln() - y0.ln()) / (p1.ln() - p0.ln()),
            method: Method::LogLog,
        });
    }
    let p_mean = 0.5 * (p0 + p1);
    if p_mean == 0.0 {
        return Err("p̄ = 0: no relative change of p".into());
    }
    Ok(Elasticity {
        value: ((y1 - y0) / (0.5 * (y0 + y1))) / ((p1 - p0) / p_mean),
        method: Method::Arc,
    })
}

/// The elasticity between each pair of neighbours (points sorted by p; see the module doc).
pub fn local(points: &[(f64, Result<f64, String>)]) -> Vec<Local> {
    let s = sorted(points);
    s.windows(2)
        .map(|w| {
            let ((p0, y0), (p1, y1)) = (&w[0], &w[1]);
            let log_log = *p0 > 0.0 && *p1 > 0.0;
            Local {
                p: (*p0, *p1),
                at: if log_log {
                    (p0 * p1).sqrt()
                } else {
                    0.5 * (p0 + p1)
                },
                elasticity: match (usable(y0), usable(y1)) {
                    (Ok(y0), Ok(y1)) => pair(*p0, y0, *p1, y1),
                    (Err(why), _) => Err(format!("at p = {p0}: {why}")),
                    (_, Err(why)) => Err(format!("at p = {p1}: {why}")),
                },
            }
        })
        .collect()
}

/// The least-squares slope of `y` against `x` (at least two distinct x). Σ(x − x̄)(y − y₀)
/// equals Σ(x − x̄)(y − ȳ) and is exactly 0 for a constant y.
fn slope(x: &[f64], y: &[f64]) -> f64 {
    let xm = x.iter().sum::<f64>() / x.len() as f64;
    let sxy: f64 = x.iter().zip(y).map(|(a, b)| (a - xm) * (b - y[0])).sum();
    let sxx: f64 = x.iter().map(|a| (a - xm) * (a - xm)).sum();
    sxy / sxx
}

/// The reasons of the points without a usable y, each once, joined.
fn reasons(points: &[(f64, Result<f64, String>)]) -> String {
    let mut list: Vec<String> = Vec::new();
    for (_, y) in points {
        if let Err(why) = usable(y) {
            if !list.contains(&why) {
                list.push(why);
            }
        }
    }
    list.join("; ")
}

/// The summary elasticity of a family's output (see the module doc).
pub fn summary(points: &[(f64, Result<f64, String>)]) -> Summary {
    let s = sorted(points);
    let of = s.len();
    let logs: Vec<(f64, f64)> = s
        .iter()
        .filter(|(p, _)| *p > 0.0)
        .filter_map(|(p, y)| Some((*p, usable(y).ok()?)))
        .collect();
    if logs.len() >= 2 {
        let x: Vec<f64> = logs.iter().map(|(p, _)| p.ln()).collect();
        let y: Vec<f64> = logs.iter().map(|(_, y)| y.ln()).collect();
        return Summary {
            elasticity: Ok(Elasticity {
                value: slope(&x, &y),
                method: Method::LogLog,
            }),
            used: logs.len(),
            of,
            range: Some((logs[0].0, logs[logs.len() - 1].0)),
        };
    }
    let arcs: Vec<(Local, f64)> = local(&s)
        .into_iter()
        .filter_map(|l| match l.elasticity {
            Ok(e) if e.method == Method::Arc => Some((l, e.value)),
            _ => None,
        })
        .collect();
    if !arcs.is_empty() {
        let used: Vec<f64> = s
            .iter()
            .filter(|(p, _)| arcs.iter().any(|(l, _)| l.p.0 == *p || l.p.1 == *p))
            .map(|(p, _)| *p)
            .collect();
        return Summary {
            elasticity: Ok(Elasticity {
                value: arcs.iter().map(|(_, v)| v).sum::<f64>() / arcs.len() as f64,
                method: Method::Arc,
            }),
            used: used.len(),
            of,
            range: Some((used[0], used[used.len() - 1])),
        };
    }
    let usable_count = s.iter().filter(|(_, y)| usable(y).is_ok()).count();
    Summary {
        elasticity: Err(if of < 2 {
            "fewer than two points".into()
        } else if usable_count >= 2 {
            // two usable y, but not two p > 0 and no arc pair between them
            "no two points with a usable output are neighbours or have p > 0".into()
        } else {
            reasons(&s)
        }),
        used: 0,
        of,
        range: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(p: &[f64], f: impl Fn(f64) -> f64) -> Vec<(f64, Result<f64, String>)> {
        p.iter().map(|&p| (p, Ok(f(p)))).collect()
    }

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() <= 1e-12 * b.abs().max(1.0)
    }

    #[test]
    fn a_power_law_is_recovered_at_every_pair_and_in_the_summary() {
        // unsorted, unevenly spaced, as the sweeps list them (φ = 1, 0.1, 0.01)
        let p = [1.0, 0.1, 0.01, 40.0, 3.0];
        for b in [-0.7, 0.0, 0.25, 2.0] {
            let pts = points(&p, |p| 3.5 * p.powf(b));
            let l = local(&pts);
            assert_eq!(l.len(), 4);
            for pair in &l {
                let e = pair.elasticity.as_ref().unwrap();
                assert_eq!(e.method, Method::LogLog);
                assert!(close(e.value, b), "{} vs {b}", e.value);
                assert!(close(pair.at, (pair.p.0 * pair.p.1).sqrt()));
            }
            assert_eq!(l[0].p, (0.01, 0.1), "pairs of neighbours in p");
            let s = summary(&pts);
            assert!(close(s.elasticity.unwrap().value, b));
            assert_eq!((s.used, s.of, s.range), (5, 5, Some((0.01, 40.0))));
        }
    }

    #[test]
    fn a_constant_has_elasticity_zero_and_a_proportional_response_one() {
        let p = [1.0, 10.0, 40.0, 70.0, 100.0];
        let c = summary(&points(&p, |_| 0.02));
        assert_eq!(c.elasticity.unwrap().value, 0.0);
        for l in local(&points(&p, |p| 0.3 * p)) {
            assert!(close(l.elasticity.unwrap().value, 1.0));
        }
        assert!(close(
            summary(&points(&p, |p| 0.3 * p)).elasticity.unwrap().value,
            1.0
        ));
    }

    #[test]
    fn a_linear_response_lies_between_its_end_elasticities_and_its_arc_value_is_exact() {
        let (a, b) = (2.0, 0.5);
        let y = |p: f64| a + b * p;
        let exact = |p: f64| b * p / (a + b * p);
        // log–log: the elasticity at some point of the pair (mean-value theorem)
        for l in local(&points(&[1.0, 10.0, 100.0], y)) {
            let e = l.elasticity.unwrap().value;
            assert!(exact(l.p.0) < e && e < exact(l.p.1), "{e}");
        }
        // a pair with p = 0 (the 0° slope): the arc elasticity, exact at p̄ = 20
        let l = local(&points(&[40.0, 0.0], y));
        let e = l[0].elasticity.as_ref().unwrap();
        assert_eq!(e.method, Method::Arc);
        assert_eq!(l[0].at, 20.0);
        assert!(
            close(e.value, exact(20.0)),
            "{} vs {}",
            e.value,
            exact(20.0)
        );
        let s = summary(&points(&[0.0, 40.0], y));
        let e = s.elasticity.as_ref().unwrap();
        assert_eq!(e.method, Method::Arc);
        assert!(close(e.value, exact(20.0)));
        assert_eq!((s.used, s.range), (2, Some((0.0, 40.0))));
        // with more points the summary is log–log over p > 0; the pair with p = 0 is arc
        let pts = points(&[0.0, 10.0, 40.0], |p| 2.0 * p.sqrt());
        assert!(close(summary(&pts).elasticity.unwrap().value, 0.5));
        assert_eq!(
            local(&pts)[1].elasticity.as_ref().unwrap().method,
            Method::LogLog
        );
    }

    #[test]
    fn missing_and_non_positive_outputs_say_why() {
        let nf = |why: &str| Err(why.to_string());
        let pts = vec![
            (1e-4, nf("no flow at the station")),
            (5e-4, Ok(2.0)),
            (1e-3, Ok(4.0)),
        ];
        let l = local(&pts);
        assert_eq!(
            l[0].elasticity.as_ref().unwrap_err(),
            "at p = 0.0001: no flow at the station"
        );
        assert!(close(
            l[1].elasticity.as_ref().unwrap().value,
            2f64.ln() / 2f64.ln()
        ));
        // the summary uses the two points that have a value, and says so
        let s = summary(&pts);
        assert!(close(s.elasticity.unwrap().value, 1.0));
        assert_eq!((s.used, s.of, s.range), (2, 3, Some((5e-4, 1e-3))));
        // fewer than two usable points: no summary, the distinct reasons
        let s = summary(&[
            (1.0, nf("not run")),
            (10.0, Ok(0.0)),
            (100.0, nf("not run")),
        ]);
        assert_eq!(
            s.elasticity.unwrap_err(),
            "not run; y = 0.000e0 ≤ 0 has no logarithm"
        );
        assert_eq!(s.used, 0);
        let l = local(&[(1.0, Ok(f64::NAN)), (2.0, Ok(1.0))]);
        assert_eq!(l[0].elasticity.as_ref().unwrap_err(), "at p = 1: y is NaN");
        assert_eq!(
            summary(&[(1.0, Ok(1.0))]).elasticity.unwrap_err(),
            "fewer than two points"
        );
        // a pair (0, p) without a usable y at p = 0 has no value; nothing else to use
        let s = summary(&[(0.0, nf("no flow at the station")), (40.0, Ok(1.0))]);
        assert_eq!(s.elasticity.unwrap_err(), "no flow at the station");
    }
}
