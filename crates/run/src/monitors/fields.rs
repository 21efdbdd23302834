//! The field series: every field of the solver as VTK (`fields.pvd` and its `.vtr` files),
//! at t = 0, every `run.output_interval` and at the end time.

use runout_mesh::Grid;
use runout_output::{OutputError, PvdSeries};

use super::schedule::advance;
use super::Hook;
use crate::case_solver::CaseSolver;

/// The name of the field series in a run folder.
pub const FIELDS_FILE: &str = "fields.pvd";

/// The field-series hook.
pub(super) struct Fields {
    pub(super) series: PvdSeries,
    pub(super) interval: f64,
    pub(super) next: f64,
}

impl Hook for Fields {
    fn after_step(
        &mut self,
        solver: &mut dyn CaseSolver,
        _grid: &Grid,
        time: f64,
        end: f64,
    ) -> Result<(), OutputError> {
        if time >= self.next * (1.0 - 1e-9) || time >= end * (1.0 - 1e-12) {
            solver.write_fields(&mut self.series, time)?;
            advance(&mut self.next, self.interval, time);
        }
        Ok(())
    }
}
