//! The schedule every sampled monitor shares: a CSV series written at a fixed interval of
//! simulated time, and its state at a checkpoint.

use runout_output::{CsvSeries, OutputError};
use serde::{Deserialize, Serialize};

/// A schedule advances by at most this many additions of its interval per step; beyond,
/// it jumps past the current time (an interval far below the step would otherwise take
/// as many additions as steps of it fit into Δt; validation bounds intervals as well).
const MAX_SCHEDULE_ADDITIONS: usize = 1000;

/// Moves `next` past `time` by adding `interval` (the schedule's own arithmetic), or, if
/// that takes more than [`MAX_SCHEDULE_ADDITIONS`], to one interval past `time` (at least the
/// next representable number: the monitor then samples every step).
pub(super) fn advance(next: &mut f64, interval: f64, time: f64) {
    let target = time * (1.0 + 1e-9);
    for _ in 0..MAX_SCHEDULE_ADDITIONS {
        if *next > target {
            return;
        }
        *next += interval;
    }
    if *next <= target {
        let jumped = target + interval;
        *next = if jumped > target {
            jumped
        } else {
            f64::from_bits(target.to_bits() + 1) // target ≥ 0: the next number up
        };
    }
}

/// A CSV series sampled every `interval` of simulated time.
pub(super) struct Sampled {
    csv: CsvSeries,
    interval: f64,
    next: f64,
}

impl Sampled {
    /// A new series at `path` with `header`, first sampled at t = 0.
    pub(super) fn create(
        path: &std::path::Path,
        header: &[&str],
        interval: f64,
    ) -> Result<Self, OutputError> {
        Ok(Sampled {
            csv: CsvSeries::create(path, header)?,
            interval,
            next: 0.0,
        })
    }

    /// The series at `path` reopened at a checkpoint's `state` (cut back to its length).
    pub(super) fn resume(
        path: &std::path::Path,
        columns: usize,
        interval: f64,
        state: &SampledState,
    ) -> Result<Self, OutputError> {
        Ok(Sampled {
            csv: CsvSeries::resume(path, columns, state.bytes)?,
            interval,
            next: state.next,
        })
    }

    /// Whether a sample is due at `time`.
    pub(super) fn due(&self, time: f64) -> bool {
        time >= self.next * (1.0 - 1e-9)
    }

    /// Writes `row` (none where the quantity is undefined, e.g. no front yet) and moves
    /// the schedule past `time`.
    pub(super) fn push_and_advance(
        &mut self,
        time: f64,
        row: Option<Vec<f64>>,
    ) -> Result<(), OutputError> {
        if let Some(row) = row {
            self.csv.push(&row)?;
        }
        advance(&mut self.next, self.interval, time);
        Ok(())
    }

    /// The state to save in a checkpoint.
    pub(super) fn state(&self) -> Result<SampledState, OutputError> {
        Ok(SampledState {
            next: self.next,
            bytes: self.csv.len_bytes()?,
        })
    }
}

/// A sampled monitor's state at a checkpoint.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SampledState {
    next: f64,
    bytes: u64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_schedule_advances_as_before_and_never_spins() {
        // the ordinary case: the same additions as `next += interval`
        let mut next = 0.1;
        advance(&mut next, 0.1, 0.35);
        assert_eq!(next, 0.1 + 0.1 + 0.1 + 0.1);
        // an interval far below the step: bounded work, past the time
        let mut next = 0.0;
        advance(&mut next, 1e-300, 1.0);
        assert!(next > 1.0 && next.is_finite());
        // an interval that cannot move next at all: just past the time
        let mut next = 1.0;
        advance(&mut next, 1e-300, 1.0);
        assert!(next > 1.0 + 1e-9 && next < 1.0 + 2e-9);
    }
}
