//! Collecting field errors: each names the field path, the value and what is allowed.

use std::fmt;

use runout_mesh::short;

use crate::limits::Band;

/// One out-of-range field.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldError {
    /// path of the field, e.g. `solids[0].diameter`
    pub field: String,
    /// the value found
    pub value: String,
    /// what is allowed
    pub allowed: String,
}

impl fmt::Display for FieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} = {}: allowed {}",
            self.field, self.value, self.allowed
        )
    }
}

/// An interval bound.
#[derive(Clone, Copy)]
pub(crate) enum B {
    Open(f64),
    Closed(f64),
    Inf,
}

/// `[lo, hi)`-style text, numbers in short form (1e-300, never 300 digits).
fn fmt_interval(lo: B, hi: B) -> String {
    let l = match lo {
        B::Open(v) => format!("({}", short(v)),
        B::Closed(v) => format!("[{}", short(v)),
        B::Inf => "(-inf".into(),
    };
    let h = match hi {
        B::Open(v) => format!("{})", short(v)),
        B::Closed(v) => format!("{}]", short(v)),
        B::Inf => "inf)".into(),
    };
    format!("{l}, {h}")
}

/// Where the bands' reasons are written.
const BANDS_DOC: &str = "plausibility band, docs/reference/input-validation.md";

/// Collects field errors.
#[derive(Default)]
pub(crate) struct Checker {
    pub(crate) errors: Vec<FieldError>,
}

impl Checker {
    pub(crate) fn fail(
        &mut self,
        field: impl Into<String>,
        value: impl ToString,
        allowed: impl Into<String>,
    ) {
        self.errors.push(FieldError {
            field: field.into(),
            value: value.to_string(),
            allowed: allowed.into(),
        });
    }

    /// Checks lo ⋚ v ⋚ hi and finiteness.
    pub(crate) fn range(&mut self, field: impl Into<String>, v: f64, lo: B, hi: B) {
        let above = match lo {
            B::Open(l) => v > l,
            B::Closed(l) => v >= l,
            B::Inf => true,
        };
        let below = match hi {
            B::Open(h) => v < h,
            B::Closed(h) => v <= h,
            B::Inf => true,
        };
        if !(v.is_finite() && above && below) {
            self.fail(field, short(v), fmt_interval(lo, hi));
        }
    }

    /// Checks that `v` lies in a plausibility band.
    pub(crate) fn band(&mut self, field: impl Into<String>, v: f64, band: &Band) {
        if !band.contains(v) {
            self.fail(
                field,
                short(v),
                format!("{} ({}: {BANDS_DOC})", band.describe(), band.what),
            );
        }
    }

    /// Checks that `v` lies in a band, intersected with `lo ⋚ v ⋚ hi` (e.g. a time step
    /// within its band and above another field).
    pub(crate) fn band_and_range(
        &mut self,
        field: impl Into<String>,
        v: f64,
        band: &Band,
        lo: B,
        hi: B,
    ) {
        let field = field.into();
        let before = self.errors.len();
        self.band(field.clone(), v, band);
        if self.errors.len() == before {
            self.range(field, v, lo, hi);
        }
    }

    pub(crate) fn unit(&mut self, field: impl Into<String>, v: f64) {
        self.range(field, v, B::Closed(0.0), B::Closed(1.0));
    }

    /// Checks that an integer lies in [lo, hi].
    pub(crate) fn count(&mut self, field: impl Into<String>, v: u64, lo: u64, hi: u64) {
        if !(lo..=hi).contains(&v) {
            self.fail(field, v, format!("an integer in [{lo}, {hi}]"));
        }
    }

    pub(crate) fn increasing(&mut self, field: &str, values: &[f64]) {
        for k in 1..values.len() {
            if values[k] <= values[k - 1] || values[k].is_nan() {
                self.fail(
                    format!("{field}[{k}]"),
                    short(values[k]),
                    format!(
                        "> {field}[{}] = {} (strictly increasing)",
                        k - 1,
                        short(values[k - 1])
                    ),
                );
            }
        }
    }

    pub(crate) fn into_result(self) -> Result<(), Vec<FieldError>> {
        if self.errors.is_empty() {
            Ok(())
        } else {
            Err(self.errors)
        }
    }
}
