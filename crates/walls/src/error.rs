//! Parameter errors of the wall models (style A6.4: validated at construction, the message
//! names the field and the allowed range).

/// A wall-model parameter outside its valid range.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum WallError {
    /// `field` = `value` is outside `range`.
    #[error("wall model: `{field}` = {value} is outside {range}")]
    OutOfRange {
        /// parameter name as in the case file
        field: &'static str,
        /// the offending value
        value: f64,
        /// the allowed range, in interval notation
        range: &'static str,
    },
}

/// `Ok(value)` if `ok(value)`, else [`WallError::OutOfRange`] (NaN always fails the checks
/// below, since they are written as positive comparisons).
pub(crate) fn check(
    field: &'static str,
    value: f64,
    range: &'static str,
    ok: impl Fn(f64) -> bool,
) -> Result<f64, WallError> {
    if ok(value) {
        Ok(value)
    } else {
        Err(WallError::OutOfRange {
            field,
            value,
            range,
        })
    }
}
