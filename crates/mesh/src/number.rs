//! Numbers in messages: the shortest text that reads back as the same `f64`.

/// `v` in plain decimal between 1e-4 and 1e6 (`0.65`, `101325`), in exponent form outside
/// (`1e-300`, `2.5e9`), so that no message prints a 300-digit decimal. Both forms are
/// Rust's shortest round-trip representation, so the text parses back to `v` exactly.
pub fn short(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 || !v.is_finite() || (1e-4..1e6).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

#[cfg(test)]
mod tests {
    use super::short;

    #[test]
    fn short_forms_round_trip() {
        for (v, s) in [
            (0.65, "0.65"),
            (101325.0, "101325"),
            (1e-300, "1e-300"),
            (-1e300, "-1e300"),
            (1e-6, "1e-6"),
            (2.5e9, "2.5e9"),
            (0.0, "0"),
            (f64::NAN, "NaN"),
            (f64::NEG_INFINITY, "-inf"),
        ] {
            assert_eq!(short(v), s);
            if v.is_finite() {
                assert_eq!(s.parse::<f64>().unwrap(), v);
            }
        }
    }
}
