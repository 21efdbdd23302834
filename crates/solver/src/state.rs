//! A solver's state between time steps, as named arrays: what a checkpoint stores and a
//! restart puts back (issue 21).
//!
//! Each solver names every array that its next step reads before writing it (the fields,
//! and the caches that carry over steps: wall closures, lagged closure values, the θ-row
//! classes). Loading checks each name and length against the solver it goes into, so a
//! state of another grid or of another set of phases is refused rather than misread.

use serde::{Deserialize, Serialize};

/// Named arrays of real numbers and of small integers (flags, counters).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SolverState {
    reals: Vec<(String, Vec<f64>)>,
    counts: Vec<(String, Vec<u8>)>,
}

/// Why a state does not fit a solver.
#[derive(Debug, thiserror::Error, PartialEq)]
pub enum StateError {
    /// The state has no array of this name.
    #[error("the saved state has no array `{0}`")]
    Missing(String),
    /// The array has another length than the solver's.
    #[error("the saved array `{name}` has {found} values, the solver has {expected}")]
    Length {
        /// array name
        name: String,
        /// length in the state
        found: usize,
        /// length in the solver
        expected: usize,
    },
}

impl SolverState {
    /// Stores a copy of `values` under `name`.
    pub fn put(&mut self, name: impl Into<String>, values: &[f64]) {
        self.reals.push((name.into(), values.to_vec()));
    }

    /// Stores flags or small counters under `name`.
    pub fn put_counts(&mut self, name: impl Into<String>, values: impl IntoIterator<Item = u8>) {
        self.counts
            .push((name.into(), values.into_iter().collect()));
    }

    /// Copies the array `name` into `into`, whose length it must have.
    pub fn take(&self, name: &str, into: &mut [f64]) -> Result<(), StateError> {
        let values = find(&self.reals, name)?;
        check_length(name, values.len(), into.len())?;
        into.copy_from_slice(values);
        Ok(())
    }

    /// The counters stored under `name`, which must have `expected` values.
    pub fn take_counts(&self, name: &str, expected: usize) -> Result<&[u8], StateError> {
        let values = find(&self.counts, name)?;
        check_length(name, values.len(), expected)?;
        Ok(values)
    }

    /// The length of the real array `name` (for arrays whose length the state decides, such
    /// as the per-node closures of a wall that has them).
    pub fn len_of(&self, name: &str) -> Result<usize, StateError> {
        find(&self.reals, name).map(<[f64]>::len)
    }

    /// Values stored in all, for the checkpoint size.
    pub fn value_count(&self) -> usize {
        self.reals.iter().map(|(_, v)| v.len()).sum::<usize>()
            + self.counts.iter().map(|(_, v)| v.len()).sum::<usize>()
    }
}

fn find<'a, T>(arrays: &'a [(String, Vec<T>)], name: &str) -> Result<&'a [T], StateError> {
    arrays
        .iter()
        .find(|(n, _)| n == name)
        .map(|(_, v)| &v[..])
        .ok_or_else(|| StateError::Missing(name.to_string()))
}

fn check_length(name: &str, found: usize, expected: usize) -> Result<(), StateError> {
    if found == expected {
        Ok(())
    } else {
        Err(StateError::Length {
            name: name.to_string(),
            found,
            expected,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arrays_come_back_by_name_and_length() {
        let mut s = SolverState::default();
        s.put("u", &[1.0, 2.0]);
        s.put_counts("dense", [1, 0, 1]);
        let mut u = [0.0; 2];
        s.take("u", &mut u).unwrap();
        assert_eq!(u, [1.0, 2.0]);
        assert_eq!(s.take_counts("dense", 3).unwrap(), &[1, 0, 1]);
        let mut wrong = [0.0; 3];
        assert_eq!(
            s.take("u", &mut wrong),
            Err(StateError::Length {
                name: "u".into(),
                found: 2,
                expected: 3
            })
        );
        assert_eq!(s.take("v", &mut u), Err(StateError::Missing("v".into())));
        assert_eq!(s.value_count(), 5);
    }
}
