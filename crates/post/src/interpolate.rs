//! Linear interpolation in a series of (abscissa, value) points: a front against time, a
//! profile against height.

/// The value at `a` of the piecewise-linear series `points` (sorted by abscissa); outside
/// the series the end value if `clamp`, else `None` (an end point itself always counts).
pub fn interpolate(points: &[(f64, f64)], a: f64, clamp: bool) -> Option<f64> {
    let (first, last) = (points.first()?, points.last()?);
    if a <= first.0 {
        return (clamp || a == first.0).then_some(first.1);
    }
    if a >= last.0 {
        return (clamp || a == last.0).then_some(last.1);
    }
    let k = points.partition_point(|p| p.0 <= a);
    let (p, q) = (points[k - 1], points[k]);
    Some(p.1 + (q.1 - p.1) * (a - p.0) / (q.0 - p.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn between_points_on_the_chord_and_outside_only_when_clamped() {
        let series = [(0.0, 0.0), (1.0, 2.0), (2.0, 2.0)];
        assert_eq!(interpolate(&series, 0.5, false), Some(1.0));
        assert_eq!(interpolate(&series, 2.0, false), Some(2.0));
        assert_eq!(interpolate(&series, 3.0, false), None);
        assert_eq!(interpolate(&series, 3.0, true), Some(2.0));
        assert_eq!(interpolate(&series, -1.0, true), Some(0.0));
        assert_eq!(interpolate(&[], 0.0, true), None);
    }
}
