//! The bulk monitor (`bulk.csv`): the solids mass, the whole-cell front `front_x` (the east
//! face of the furthest floor cell with εs at or above the threshold: the paper's
//! definition, moving in whole cells), the εs-weighted mean u_s, and the interpolated front
//! `front_x_interpolated` (where the floor row's εs falls through the threshold, linear
//! between cell centres: the front tracker's definition, continuous in time and in the
//! case's parameters), at its interval. The last column was added for calibration (issue
//! 48); readers of older files fall back to `front_x`.

use runout_mesh::Grid;
use runout_output::OutputError;

use super::schedule::Sampled;
use super::Hook;
use crate::case_solver::CaseSolver;

/// The columns of `bulk.csv`.
pub(super) const BULK_HEADER: [&str; 5] = [
    "t",
    "solids_mass",
    "front_x",
    "mean_u_s",
    "front_x_interpolated",
];
/// The file's name in a run folder.
pub(super) const BULK_FILE: &str = "bulk.csv";

/// The bulk hook: its series and its front threshold (εs).
pub(super) struct Bulk {
    pub(super) sampled: Sampled,
    pub(super) front_threshold: f64,
}

impl Hook for Bulk {
    fn after_step(
        &mut self,
        solver: &mut dyn CaseSolver,
        _grid: &Grid,
        time: f64,
        _end: f64,
    ) -> Result<(), OutputError> {
        if self.sampled.due(time) {
            let interpolated = solver.interpolated_front(self.front_threshold);
            let row = solver
                .bulk(self.front_threshold)
                .zip(interpolated)
                .map(|((front, mean_u), x)| vec![time, solver.solids_mass(), front, mean_u, x]);
            self.sampled.push_and_advance(time, row)?;
        }
        Ok(())
    }
}
