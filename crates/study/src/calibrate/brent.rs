//! Brent's minimisation in one dimension (Brent 1973, *Algorithms for Minimization without
//! Derivatives*, ch. 5, `localmin`: golden-section steps safeguarding parabolic
//! interpolation), started from a bracket whose three points are already evaluated.
//!
//! argmin's `BrentOpt` starts from the bounds alone and evaluates its own first points; a
//! calibration run costs minutes, so the refinement starts from the scan instead: the best
//! point x and its neighbours a < x < b with their known values. The first step is the
//! parabola through those three points; no known point is evaluated again.

use anyhow::Result;

/// A point and its value.
pub type Known = (f64, f64);

/// A bracket a < x < b (or x at an end of [a, b]) with f(x) ≤ f(a), f(b), all known.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bracket {
    /// the lower end
    pub a: Known,
    /// the best point
    pub x: Known,
    /// the upper end
    pub b: Known,
}

/// (3 − √5)/2, the golden section's smaller part.
const GOLDEN: f64 = 0.381_966_011_250_105_1;

/// Minimises `f` from `bracket` until the bracket of the minimum is narrower than
/// 2 `xtol` (Brent's test |x − m| ≤ 2 tol − (b − a)/2 with tol = `xtol`), or `f` returns
/// `None` (its evaluations are spent). An `Err` of `f` is returned.
pub fn minimise(
    bracket: Bracket,
    xtol: f64,
    mut f: impl FnMut(f64) -> Result<Option<f64>>,
) -> Result<()> {
    let (mut a, mut b) = (bracket.a.0, bracket.b.0);
    let (mut x, mut fx) = bracket.x;
    // w: the second best point, v: the previous w (here the worse neighbour)
    let ((mut w, mut fw), (mut v, mut fv)) = if bracket.a.1 <= bracket.b.1 {
        (bracket.a, bracket.b)
    } else {
        (bracket.b, bracket.a)
    };
    // a large "step before last" lets the first step be the parabola through the three
    let (mut d, mut e): (f64, f64) = (0.0, b - a);
    loop {
        let m = 0.5 * (a + b);
        let tol1 = xtol + f64::EPSILON * x.abs();
        let tol2 = 2.0 * tol1;
        if (x - m).abs() <= tol2 - 0.5 * (b - a) {
            return Ok(());
        }
        let mut parabolic = false;
        if e.abs() > tol1 && x != w && x != v && w != v {
            let r = (x - w) * (fx - fv);
            let mut q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            } else {
                q = -q;
            }
            let e_before = e;
            if p.abs() < (0.5 * q * e_before).abs() && p > q * (a - x) && p < q * (b - x) {
                e = d;
                d = p / q;
                let u = x + d;
                if u - a < tol2 || b - u < tol2 {
                    d = tol1.copysign(m - x);
                }
                parabolic = true;
            }
        }
        if !parabolic {
            e = if x < m { b - x } else { a - x };
            d = GOLDEN * e;
        }
        let u = if d.abs() >= tol1 {
            x + d
        } else {
            x + tol1.copysign(d)
        };
        let Some(fu) = f(u)? else {
            return Ok(());
        };
        if fu <= fx {
            if u < x {
                b = x;
            } else {
                a = x;
            }
            (v, fv) = (w, fw);
            (w, fw) = (x, fx);
            (x, fx) = (u, fu);
        } else {
            if u < x {
                a = u;
            } else {
                b = u;
            }
            if fu <= fw || w == x {
                (v, fv) = (w, fw);
                (w, fw) = (u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Runs [`minimise`] on `f` from the bracket at `a < x < b`; returns the points asked.
    fn asked(f: impl Fn(f64) -> f64, a: f64, x: f64, b: f64, budget: usize) -> Vec<f64> {
        let mut points = Vec::new();
        let bracket = Bracket {
            a: (a, f(a)),
            x: (x, f(x)),
            b: (b, f(b)),
        };
        minimise(bracket, 1e-6, |u| {
            if points.len() == budget {
                return Ok(None);
            }
            points.push(u);
            Ok(Some(f(u)))
        })
        .unwrap();
        points
    }

    #[test]
    fn a_parabola_is_found_in_one_step_from_its_known_bracket() {
        let f = |u: f64| (u - 0.37).powi(2);
        let points = asked(f, 0.25, 0.5, 0.75, 10);
        assert!((points[0] - 0.37).abs() < 1e-12, "{points:?}");
        assert!(points.len() <= 4, "{points:?}");
    }

    #[test]
    fn a_smooth_minimum_is_found_to_the_tolerance_without_asking_known_points() {
        let f = |u: f64| ((u - 0.61).powi(2) + 0.04).sqrt() + 0.3 * (u - 0.61).powi(3);
        let points = asked(f, 0.5, 0.75, 1.0, 40);
        let best = points
            .iter()
            .copied()
            .min_by(|p, q| f(*p).total_cmp(&f(*q)))
            .unwrap();
        assert!((best - 0.61).abs() < 1e-5, "{best} from {points:?}");
        assert!(points.iter().all(|&u| u != 0.5 && u != 0.75 && u != 1.0));
        assert!(points.iter().all(|&u| (0.5..=1.0).contains(&u)));
        // the first point lies between the best known point and its better neighbour
        assert!((0.5..0.75).contains(&points[0]), "{points:?}");
    }

    #[test]
    fn a_minimum_at_the_bracket_end_is_approached() {
        let f = |u: f64| u;
        let points = asked(f, 0.0, 0.0, 0.5, 60);
        let last = *points.last().unwrap();
        assert!(last < 1e-4, "{points:?}");
    }

    #[test]
    fn the_budget_stops_it() {
        let f = |u: f64| (u - 0.3).abs();
        assert_eq!(asked(f, 0.0, 0.5, 1.0, 3).len(), 3);
    }
}
