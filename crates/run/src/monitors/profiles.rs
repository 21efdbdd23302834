//! The profiles (`profile_x<x>_t<t>.csv`): every quantity of the solver's profile header
//! along the column nearest x, at each listed time (the first step reaching it).

use std::path::PathBuf;

use runout_case::Case;
use runout_mesh::Grid;
use runout_output::{CsvSeries, OutputError};

use super::Hook;
use crate::case_solver::CaseSolver;

/// One profile monitor: its x [m], its times [s] and the index of the next time.
pub(super) struct Profile {
    pub(super) out_dir: PathBuf,
    pub(super) x: f64,
    pub(super) times: Vec<f64>,
    pub(super) next: usize,
}

impl Profile {
    /// The case's profile monitors, each at its next time (`next`, from a checkpoint, or
    /// the first).
    pub(super) fn schedule(case: &Case, out_dir: PathBuf, next: Option<&[usize]>) -> Vec<Self> {
        case.monitors
            .profiles
            .iter()
            .enumerate()
            .map(|(k, p)| Profile {
                out_dir: out_dir.clone(),
                x: p.x,
                times: p.times.clone(),
                next: next.map_or(0, |n| n[k]),
            })
            .collect()
    }
}

impl Hook for Profile {
    fn after_step(
        &mut self,
        solver: &mut dyn CaseSolver,
        grid: &Grid,
        time: f64,
        _end: f64,
    ) -> Result<(), OutputError> {
        while self.next < self.times.len() && time >= self.times[self.next] * (1.0 - 1e-9) {
            let path = self.out_dir.join(format!(
                "profile_x{}_t{}.csv",
                self.x, self.times[self.next]
            ));
            let mut csv = CsvSeries::create(&path, solver.profile_header())?;
            for &y in grid.y.centres() {
                csv.push(&solver.profile(self.x, y))?;
            }
            self.next += 1;
        }
        Ok(())
    }
}
