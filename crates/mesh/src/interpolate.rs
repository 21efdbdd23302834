//! Piecewise-linear interpolation in a sampled series: a profile against height, a front
//! against time (the calibration's misfits and synthetic measurements, the relaxation
//! check, the paper's error-against-run-time study), the single-phase solver's probes
//! (`u_at`, `v_at`) and the 1-D chute's initial profile. (Those two blended
//! (1 − t) y[k−1] + t y[k] until 2026-12-08, the same line rounded differently: their values
//! moved by round-off when they came here.)

/// What [`interpolate`] gives outside the sampled range `[xs[0], xs[n−1]]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Beyond {
    /// the end sample's value (constant continuation)
    Clamp,
    /// the end chord continued (linear extrapolation from the two end samples)
    Extrapolate,
    /// no value (`None`); an end abscissa itself still counts as inside
    Missing,
}

/// The value at `x` of the piecewise-linear interpolant of the samples `(xs[i], ys[i])`,
/// `xs` non-decreasing and as long as `ys`.
///
/// Between the samples k−1 and k around `x` (xs[k−1] ≤ x < xs[k]):
///
///   y(x) = y[k−1] + (y[k] − y[k−1]) (x − x[k−1]) / (x[k] − x[k−1])
///
/// On a sample abscissa it is that sample's value alone, so a non-finite neighbour (a
/// history sample without a front, NaN) does not spread onto it. Outside the range it
/// follows `beyond`; with `Beyond::Extrapolate` the chord of the two end samples is
/// continued. Units are those of `xs` and `ys`.
///
/// Edge cases: no samples gives `None` for every `beyond`; a single sample gives its value
/// everywhere with `Clamp` and `Extrapolate`, and only at its own abscissa with `Missing`.
/// With `Clamp` or `Missing` an abscissa at or beyond an end takes that end's first sample
/// (repeated end abscissae: the outermost).
pub fn interpolate(xs: &[f64], ys: &[f64], x: f64, beyond: Beyond) -> Option<f64> {
    debug_assert_eq!(xs.len(), ys.len(), "one value per abscissa");
    let n = xs.len().min(ys.len());
    let (first, last) = (*xs.first()?, xs[n - 1]);
    if beyond != Beyond::Extrapolate {
        let keep = beyond == Beyond::Clamp;
        if x <= first {
            return (keep || x == first).then_some(ys[0]);
        }
        if x >= last {
            return (keep || x == last).then_some(ys[n - 1]);
        }
    }
    if n == 1 {
        return Some(ys[0]);
    }
    // the chord around x: the first abscissa above x closes it (the end chords beyond)
    let k = xs[..n].partition_point(|&a| a <= x).clamp(1, n - 1);
    let (x0, x1, y0, y1) = (xs[k - 1], xs[k], ys[k - 1], ys[k]);
    Some(if x == x0 {
        y0
    } else if x == x1 {
        y1
    } else {
        y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    })
}

#[cfg(test)]
mod tests {
    use super::{interpolate, Beyond};

    const XS: [f64; 3] = [0.0, 1.0, 2.0];
    const YS: [f64; 3] = [0.0, 2.0, 1.0];

    #[test]
    fn between_samples_on_the_chord() {
        for beyond in [Beyond::Clamp, Beyond::Extrapolate, Beyond::Missing] {
            assert_eq!(interpolate(&XS, &YS, 0.5, beyond), Some(1.0));
            assert_eq!(interpolate(&XS, &YS, 1.5, beyond), Some(1.5));
            assert_eq!(interpolate(&XS, &YS, 1.0, beyond), Some(2.0));
            assert_eq!(interpolate(&XS, &YS, 2.0, beyond), Some(1.0));
            assert_eq!(interpolate(&XS, &YS, 0.0, beyond), Some(0.0));
        }
    }

    #[test]
    fn outside_the_range_as_asked() {
        assert_eq!(interpolate(&XS, &YS, -1.0, Beyond::Clamp), Some(0.0));
        assert_eq!(interpolate(&XS, &YS, 3.0, Beyond::Clamp), Some(1.0));
        assert_eq!(interpolate(&XS, &YS, -1.0, Beyond::Extrapolate), Some(-2.0));
        assert_eq!(interpolate(&XS, &YS, 3.0, Beyond::Extrapolate), Some(0.0));
        assert_eq!(interpolate(&XS, &YS, -1.0, Beyond::Missing), None);
        assert_eq!(interpolate(&XS, &YS, 3.0, Beyond::Missing), None);
    }

    #[test]
    fn empty_and_single_samples() {
        for beyond in [Beyond::Clamp, Beyond::Extrapolate, Beyond::Missing] {
            assert_eq!(interpolate(&[], &[], 0.0, beyond), None);
            assert_eq!(interpolate(&[1.0], &[4.0], 1.0, beyond), Some(4.0));
        }
        assert_eq!(interpolate(&[1.0], &[4.0], 7.0, Beyond::Clamp), Some(4.0));
        assert_eq!(
            interpolate(&[1.0], &[4.0], 7.0, Beyond::Extrapolate),
            Some(4.0)
        );
        assert_eq!(interpolate(&[1.0], &[4.0], 7.0, Beyond::Missing), None);
    }

    #[test]
    fn a_nan_neighbour_stays_off_the_samples() {
        let ys = [f64::NAN, 3.0, 5.0];
        assert_eq!(interpolate(&XS, &ys, 1.0, Beyond::Extrapolate), Some(3.0));
        assert_eq!(interpolate(&XS, &ys, 1.5, Beyond::Clamp), Some(4.0));
        assert!(interpolate(&XS, &ys, 0.5, Beyond::Clamp).unwrap().is_nan());
    }
}
