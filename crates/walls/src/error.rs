//! Parameter errors of the wall models (style A6.4: validated at construction, the message
//! names each field and its allowed range).

/// One wall-model parameter outside its valid range.
#[derive(Clone, Debug, PartialEq)]
pub struct OutOfRange {
    /// parameter name as in the case file
    pub field: &'static str,
    /// the offending value
    pub value: f64,
    /// the allowed range, in interval notation
    pub range: &'static str,
}

/// The out-of-range parameters of one wall condition: every one a constructor found (at
/// least one), so a case check reports them all at once.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("wall model: {}", describe(.fields))]
pub struct WallError {
    /// the fields in the order they were checked
    pub fields: Vec<OutOfRange>,
}

fn describe(fields: &[OutOfRange]) -> String {
    let each: Vec<String> = fields
        .iter()
        .map(|f| format!("`{}` = {} is outside {}", f.field, f.value, f.range))
        .collect();
    each.join("; ")
}

/// Collects the parameter checks of one constructor (NaN always fails them, since they are
/// written as positive comparisons).
#[derive(Default)]
pub(crate) struct Checks {
    fields: Vec<OutOfRange>,
}

impl Checks {
    /// Records `field` = `value` as out of `range` unless `ok(value)`; returns `value`.
    pub(crate) fn check(
        &mut self,
        field: &'static str,
        value: f64,
        range: &'static str,
        ok: impl Fn(f64) -> bool,
    ) -> f64 {
        if !ok(value) {
            self.fields.push(OutOfRange {
                field,
                value,
                range,
            });
        }
        value
    }

    /// The value of a nested constructor, its errors recorded.
    pub(crate) fn take<T>(&mut self, result: Result<T, WallError>) -> Option<T> {
        result.map_err(|e| self.fields.extend(e.fields)).ok()
    }

    /// `Ok(value)` if every check passed (`value` is then `Some`), else every failure.
    pub(crate) fn finish<T>(self, value: Option<T>) -> Result<T, WallError> {
        match value {
            Some(v) if self.fields.is_empty() => Ok(v),
            _ => Err(WallError {
                fields: self.fields,
            }),
        }
    }
}
