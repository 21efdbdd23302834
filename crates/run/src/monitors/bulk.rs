//! The bulk monitor (`bulk.csv`): the solids mass, the front (the furthest cell with
//! εs above the threshold) and the εs-weighted mean u_s, at its interval.

use runout_mesh::Grid;
use runout_output::OutputError;

use super::schedule::Sampled;
use super::Hook;
use crate::case_solver::CaseSolver;

/// The columns of `bulk.csv`.
pub(super) const BULK_HEADER: [&str; 4] = ["t", "solids_mass", "front_x", "mean_u_s"];
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
            let row = solver
                .bulk(self.front_threshold)
                .map(|(front, mean_u)| vec![time, solver.solids_mass(), front, mean_u]);
            self.sampled.push_and_advance(time, row)?;
        }
        Ok(())
    }
}
