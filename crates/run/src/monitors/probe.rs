//! A floor wall probe (`wall_probe_south_x<x>.csv`): the solids wall coefficient h_w^u of
//! the floor face nearest x (docs/model.md §3), at its interval.

use std::path::{Path, PathBuf};

use runout_mesh::Grid;
use runout_output::OutputError;

use super::schedule::Sampled;
use super::Hook;
use crate::case_solver::CaseSolver;

/// The columns of a probe's file.
pub(super) const PROBE_HEADER: [&str; 2] = ["t", "h_w_u"];

/// The file of the floor probe at `at` in a run folder.
pub(super) fn probe_path(out_dir: &Path, at: f64) -> PathBuf {
    out_dir.join(format!("wall_probe_south_x{at}.csv"))
}

/// A floor-probe hook: its series and its x [m].
pub(super) struct FloorProbe {
    pub(super) sampled: Sampled,
    pub(super) at: f64,
}

impl Hook for FloorProbe {
    fn after_step(
        &mut self,
        solver: &mut dyn CaseSolver,
        _grid: &Grid,
        time: f64,
        _end: f64,
    ) -> Result<(), OutputError> {
        if self.sampled.due(time) {
            let row = solver.floor_h_u(self.at).map(|h| vec![time, h]);
            self.sampled.push_and_advance(time, row)?;
        }
        Ok(())
    }
}
