//! One verification check behind one trait: a [`Check`] runs at a [`Size`] and returns an
//! [`Outcome`], the measured numbers with their limits. The fast size is what the test suite
//! (`crates/verification/tests/`) runs in CI; the full size is what `cargo xtask verify`
//! runs. A check prints its progress and numbers as it goes (the long ones take minutes).

use std::fmt;

/// How large a check's runs are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Size {
    /// small grids and short runs: seconds to a minute, run by the test suite (CI)
    Fast,
    /// the acceptance sizes: minutes, run by `cargo xtask verify`
    Full,
}

impl Size {
    /// "fast" or "full".
    pub fn name(self) -> &'static str {
        match self {
            Size::Fast => "fast",
            Size::Full => "full",
        }
    }
}

/// The acceptance limit of a measured number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Limit {
    /// value < limit
    Below(f64),
    /// value ≤ limit
    AtMost(f64),
    /// value > limit
    Above(f64),
    /// value ≥ limit
    AtLeast(f64),
    /// lo ≤ value < hi
    Within(f64, f64),
    /// value == expected
    Equals(f64),
    /// a condition (value 1 when it holds, 0 when not)
    Holds,
}

impl Limit {
    /// Whether `value` meets the limit (NaN never does).
    pub fn admits(self, value: f64) -> bool {
        match self {
            Limit::Below(l) => value < l,
            Limit::AtMost(l) => value <= l,
            Limit::Above(l) => value > l,
            Limit::AtLeast(l) => value >= l,
            Limit::Within(lo, hi) => (lo..hi).contains(&value),
            Limit::Equals(e) => value == e,
            Limit::Holds => value == 1.0,
        }
    }
}

impl fmt::Display for Limit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Limit::Below(l) => write!(f, "< {l:e}"),
            Limit::AtMost(l) => write!(f, "<= {l:e}"),
            Limit::Above(l) => write!(f, "> {l:e}"),
            Limit::AtLeast(l) => write!(f, ">= {l:e}"),
            Limit::Within(lo, hi) => write!(f, "in [{lo}, {hi})"),
            Limit::Equals(e) => write!(f, "= {e}"),
            Limit::Holds => write!(f, "holds"),
        }
    }
}

/// One measured number of a check with its limit.
#[derive(Clone, Debug, PartialEq)]
pub struct Measure {
    /// what was measured
    pub name: String,
    /// the measured value (1 or 0 for a condition)
    pub value: f64,
    /// the acceptance limit
    pub limit: Limit,
}

impl Measure {
    /// Whether the value meets its limit.
    pub fn passed(&self) -> bool {
        self.limit.admits(self.value)
    }
}

impl fmt::Display for Measure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let verdict = if self.passed() { "PASS" } else { "FAIL" };
        match self.limit {
            Limit::Holds => write!(f, "{}: {verdict}", self.name),
            limit => write!(f, "{}: {:.6e} ({limit})  {verdict}", self.name, self.value),
        }
    }
}

/// What a check measured, with the limits: it passed when every measure meets its limit.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// the check's name
    pub check: &'static str,
    /// the size it ran at
    pub size: Size,
    /// the measured numbers, in the order they were taken
    pub measures: Vec<Measure>,
}

impl Outcome {
    /// An outcome with no measures yet.
    pub fn new(check: &'static str, size: Size) -> Self {
        Self {
            check,
            size,
            measures: Vec::new(),
        }
    }

    /// Records `value` against `limit`.
    pub fn measure(&mut self, name: impl Into<String>, value: f64, limit: Limit) {
        self.measures.push(Measure {
            name: name.into(),
            value,
            limit,
        });
    }

    /// Records a condition.
    pub fn holds(&mut self, name: impl Into<String>, condition: bool) {
        self.measure(name, if condition { 1.0 } else { 0.0 }, Limit::Holds);
    }

    /// Every measure met its limit (and there was at least one).
    pub fn passed(&self) -> bool {
        !self.measures.is_empty() && self.measures.iter().all(Measure::passed)
    }

    /// The measures that missed their limits.
    pub fn failures(&self) -> impl Iterator<Item = &Measure> {
        self.measures.iter().filter(|m| !m.passed())
    }
}

impl fmt::Display for Outcome {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let verdict = if self.passed() { "PASS" } else { "FAIL" };
        writeln!(f, "{} ({}): {verdict}", self.check, self.size.name())?;
        for m in &self.measures {
            writeln!(f, "  {m}")?;
        }
        Ok(())
    }
}

/// A verification check: a problem, its reference and its limits at two sizes.
pub trait Check: Send + Sync {
    /// Short name, as given to `cargo xtask verify <name>`.
    fn name(&self) -> &'static str;

    /// One line: what is checked against what.
    fn description(&self) -> &'static str;

    /// Runs the check at `size`. An error is a run that could not finish (a solver failure,
    /// a step that did not converge); a finished run that misses a limit is an [`Outcome`]
    /// that did not pass.
    fn run(&self, size: Size) -> anyhow::Result<Outcome>;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_admit_as_the_old_assertions_did() {
        assert!(Limit::Below(1.0).admits(0.5) && !Limit::Below(1.0).admits(1.0));
        assert!(Limit::AtMost(1.0).admits(1.0) && !Limit::AtMost(1.0).admits(f64::NAN));
        assert!(Limit::Within(0.9, 1.2).admits(0.9) && !Limit::Within(0.9, 1.2).admits(1.2));
        let mut o = Outcome::new("x", Size::Fast);
        assert!(!o.passed());
        o.holds("ok", true);
        o.measure("e", 0.1, Limit::Below(0.01));
        assert!(!o.passed());
        assert_eq!(o.failures().count(), 1);
    }
}
