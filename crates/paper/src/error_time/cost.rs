//! The cost of one run of the ladder: the rayon threads it ran on and the CPU seconds this
//! process spent on it (getrusage, user + system, all threads), kept beside the run as
//! `cost.json` so a reused run still reports its CPU time.

use std::path::Path;

use serde::{Deserialize, Serialize};

/// The file beside `summary.json` that holds a run's cost.
const COST_FILE: &str = "cost.json";

/// Threads and CPU time of one run.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub(super) struct RunCost {
    /// rayon threads the run had
    pub(super) threads: usize,
    /// CPU time of the run, all threads [s]
    pub(super) cpu_seconds: f64,
    /// whether the run continued from a checkpoint (then `cpu_seconds` counts only the part
    /// run by the last process)
    pub(super) resumed: bool,
}

/// Writes `cost` into the run folder `dir`.
pub(super) fn write_cost(dir: &Path, cost: &RunCost) -> anyhow::Result<()> {
    let text = serde_json::to_string_pretty(cost)?;
    runout_output::write_atomic(&dir.join(COST_FILE), text.as_bytes())?;
    Ok(())
}

/// The cost stored in the run folder `dir`, if any.
pub(super) fn read_cost(dir: &Path) -> Option<RunCost> {
    let text = std::fs::read_to_string(dir.join(COST_FILE)).ok()?;
    serde_json::from_str(&text).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cost_reads_back_as_written() {
        let dir = std::env::temp_dir().join(format!("error-time-cost-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let cost = RunCost {
            threads: 1,
            cpu_seconds: 12.5,
            resumed: false,
        };
        write_cost(&dir, &cost).unwrap();
        assert_eq!(read_cost(&dir), Some(cost));
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(read_cost(&dir), None);
    }
}
