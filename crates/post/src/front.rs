//! The front position of a run against time, with the definition it has. Two definitions
//! exist (docs/reference/calibrate.md, "Fronts"):
//! - **interpolated**: where the floor row's εs falls through the monitor's threshold beyond
//!   its last cell at or above it, linear between the centres of that cell and the next
//!   (the front tracker's `front.csv`, and `bulk.csv`'s `front_x_interpolated`): continuous
//!   in time and in the case's parameters, for calibration and gate speeds;
//! - **whole-cell**: the east face of the last floor cell at or above the threshold
//!   (`bulk.csv`'s `front_x`, the paper's definition, cases.md family F): it moves in whole
//!   cells, so a misfit against it is a staircase in the parameters.

use std::path::Path;

use crate::table::Table;

/// Which front a series is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrontDefinition {
    /// the threshold crossing interpolated between cell centres
    Interpolated,
    /// the east face of the last floor cell at or above the threshold
    WholeCell,
}

impl FrontDefinition {
    /// Lower-case name for messages and notes.
    pub fn name(self) -> &'static str {
        match self {
            FrontDefinition::Interpolated => "interpolated",
            FrontDefinition::WholeCell => "whole-cell",
        }
    }
}

/// The interpolated front of the run in `dir`, (t, x) in time order, from `front.csv` (the
/// front tracker) or else `bulk.csv`'s `front_x_interpolated`; a run written before that
/// column existed gives its whole-cell `front_x`, with [`FrontDefinition::WholeCell`].
/// Rows without a front are left out. The error names the file.
pub fn front_series(dir: &Path) -> Result<(FrontDefinition, Vec<(f64, f64)>), String> {
    let tracker = dir.join("front.csv");
    let (definition, pairs) = if tracker.exists() {
        let table = Table::read(&tracker)?;
        (FrontDefinition::Interpolated, table.pairs("t", "front_x"))
    } else {
        let table = Table::read(&dir.join("bulk.csv"))?;
        match table.pairs("t", "front_x_interpolated") {
            Ok(p) => (FrontDefinition::Interpolated, Ok(p)),
            Err(_) => (FrontDefinition::WholeCell, table.pairs("t", "front_x")),
        }
    };
    let pairs = pairs.map_err(|e| format!("{}: {e}", dir.display()))?;
    Ok((
        definition,
        pairs
            .into_iter()
            .filter(|(t, x)| !t.is_nan() && !x.is_nan())
            .collect(),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_interpolated_front_is_preferred_and_old_files_still_read() {
        let dir = std::env::temp_dir().join(format!("runout-post-front-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let bulk = dir.join("bulk.csv");
        std::fs::write(&bulk, "t,solids_mass,front_x,mean_u_s\n0.1,1,0.54,0\n").unwrap();
        assert_eq!(
            front_series(&dir).unwrap(),
            (FrontDefinition::WholeCell, vec![(0.1, 0.54)])
        );
        std::fs::write(
            &bulk,
            "t,solids_mass,front_x,mean_u_s,front_x_interpolated\n0.1,1,0.54,0,0.531\n0.2,1,,0,\n",
        )
        .unwrap();
        assert_eq!(
            front_series(&dir).unwrap(),
            (FrontDefinition::Interpolated, vec![(0.1, 0.531)])
        );
        std::fs::write(dir.join("front.csv"), "t,front_x\n0.1,0.6\n").unwrap();
        assert_eq!(
            front_series(&dir).unwrap(),
            (FrontDefinition::Interpolated, vec![(0.1, 0.6)])
        );
        let _ = std::fs::remove_dir_all(&dir);
        assert!(front_series(&dir).unwrap_err().contains("bulk.csv"));
    }
}
