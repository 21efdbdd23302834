//! ron's parse errors in the terms of the case file: a number where an integer is expected
//! says so and names the field (ron said "Expected comma" for `cells: 2.5`).

use ron::error::{Error, SpannedError};

/// The message of a parse error of `text`: ron's, or, when the error lies in a number that
/// does not fit an integer field, "`field` = value: expected an integer ...".
pub(crate) fn message(text: &str, e: &SpannedError) -> String {
    integer_message(text, e).unwrap_or_else(|| e.code.to_string())
}

fn integer_message(text: &str, e: &SpannedError) -> Option<String> {
    let chars: Vec<char> = text.chars().collect();
    let at = char_index(&chars, e.span.start.line, e.span.start.col)?;
    let (start, token) = number_around(&chars, at)?;
    let field = field_before(&chars, start).map_or(String::new(), |f| format!("`{f}` = "));
    let plain = token.replace('_', "");
    let is_integer = plain.parse::<i128>().is_ok();
    let is_float = !is_integer && plain.parse::<f64>().is_ok();
    let integer_expected = matches!(
        e.code,
        Error::ExpectedInteger | Error::InvalidIntegerDigit { .. }
    ) || at > start;
    if is_float && integer_expected {
        Some(format!("{field}{token}: expected an integer"))
    } else if is_integer && e.code == Error::IntegerOutOfBounds {
        Some(format!(
            "{field}{token}: expected an integer in range (counts are >= 0)"
        ))
    } else {
        None
    }
}

/// The index into `chars` of 1-based (line, column), counted in characters as ron does.
fn char_index(chars: &[char], line: usize, col: usize) -> Option<usize> {
    let mut line_start = 0;
    for _ in 1..line {
        line_start += chars[line_start..].iter().position(|&c| c == '\n')? + 1;
    }
    let i = line_start + col.checked_sub(1)?;
    (i < chars.len()).then_some(i)
}

/// The number-like token that contains index `at` (or follows it after white space, where
/// ron points before a value): its start and its text.
fn number_around(chars: &[char], at: usize) -> Option<(usize, String)> {
    let part = |c: char| c.is_ascii_alphanumeric() || "._+-".contains(c);
    let at = (at..chars.len()).find(|&i| !chars[i].is_whitespace())?;
    if !part(chars[at]) {
        return None;
    }
    let start = (0..at)
        .rev()
        .take_while(|&i| part(chars[i]))
        .last()
        .unwrap_or(at);
    let end = (at..chars.len())
        .take_while(|&i| part(chars[i]))
        .last()
        .map_or(at, |i| i + 1);
    let token: String = chars[start..end].iter().collect();
    Some((start, token))
}

/// The identifier of `ident: ` right before index `start`, if the token is a field value.
fn field_before(chars: &[char], start: usize) -> Option<String> {
    let mut i = start;
    while i > 0 && chars[i - 1].is_whitespace() {
        i -= 1;
    }
    if i == 0 || chars[i - 1] != ':' {
        return None;
    }
    i -= 1;
    while i > 0 && chars[i - 1].is_whitespace() {
        i -= 1;
    }
    let end = i;
    while i > 0 && (chars[i - 1].is_ascii_alphanumeric() || chars[i - 1] == '_') {
        i -= 1;
    }
    (i < end).then(|| chars[i..end].iter().collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, serde::Deserialize)]
    #[allow(dead_code)]
    struct S {
        cells: usize,
        x: f64,
        pair: (f64, f64),
    }

    fn msg(text: &str) -> String {
        let e = ron::from_str::<S>(text).expect_err("rejected");
        message(text, &e)
    }

    #[test]
    fn fractional_counts_say_expected_an_integer() {
        for v in ["2.5", "2e3", "1e300", "NaN", "inf", "-2.5"] {
            let m = msg(&format!("(cells: {v}, x: 1.0, pair: (1, 2))"));
            assert_eq!(m, format!("`cells` = {v}: expected an integer"), "{v}");
        }
        let m = msg("(\n  cells:\n    -3, x: 1.0, pair: (1, 2))");
        assert!(
            m.starts_with("`cells` = -3: expected an integer in range"),
            "{m}"
        );
    }

    #[test]
    fn other_errors_keep_ron_s_message() {
        let m = msg("(cells: 2, x: 1.0, pair: (1.5, 2.5, 3.5))");
        assert!(!m.contains("integer"), "{m}");
        let m = msg("(cells: 2, x: 1.0,, pair: (1, 2))");
        assert!(!m.contains("integer"), "{m}");
    }
}
