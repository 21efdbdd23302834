//! The front tracker (`front.csv`, then `gates.csv`): the interpolated front position at its
//! interval, and at the end the front speed at each gate (cases.md family F).

use std::path::Path;

use runout_case::FrontTracker;
use runout_mesh::Grid;
use runout_output::{CsvSeries, OutputError};

use super::schedule::Sampled;
use super::Hook;
use crate::case_solver::CaseSolver;

/// The columns of `front.csv`.
pub(super) const FRONT_HEADER: [&str; 2] = ["t", "front_x"];
/// The file's name in a run folder.
pub(super) const FRONT_FILE: &str = "front.csv";
/// The gate speeds' file in a run folder.
const GATES_FILE: &str = "gates.csv";

/// The front-tracker hook: its series, its settings and its samples (t, x).
pub(super) struct Front {
    pub(super) sampled: Sampled,
    pub(super) tracker: FrontTracker,
    pub(super) samples: Vec<(f64, f64)>,
}

impl Hook for Front {
    fn after_step(
        &mut self,
        solver: &mut dyn CaseSolver,
        _grid: &Grid,
        time: f64,
        _end: f64,
    ) -> Result<(), OutputError> {
        if self.sampled.due(time) {
            let x = solver.interpolated_front(self.tracker.threshold);
            if let Some(x) = x {
                self.samples.push((time, x));
            }
            self.sampled
                .push_and_advance(time, x.map(|x| vec![time, x]))?;
        }
        Ok(())
    }

    fn finish(&self, out_dir: &Path) -> Result<(), OutputError> {
        write_gate_speeds(&out_dir.join(GATES_FILE), &self.tracker, &self.samples)
    }
}

/// Front speed at each gate (cases.md family F): at the first sample whose front has passed
/// the gate, the slope of the front position over the two samples on either side (a
/// central difference over up to four sampling intervals). Gates the front never reached
/// get no speed.
fn write_gate_speeds(
    path: &Path,
    tracker: &FrontTracker,
    series: &[(f64, f64)],
) -> Result<(), OutputError> {
    let mut csv = CsvSeries::create(path, &["gate", "x", "t_cross", "speed"])?;
    for (g, distance) in tracker.gates.iter().enumerate() {
        let x_gate = tracker.gate_origin + distance;
        let Some(k) = series.iter().position(|&(_, x)| x >= x_gate) else {
            continue;
        };
        let (lo, hi) = (k.saturating_sub(2), (k + 2).min(series.len() - 1));
        let speed = if series[hi].0 > series[lo].0 {
            (series[hi].1 - series[lo].1) / (series[hi].0 - series[lo].0)
        } else {
            f64::NAN
        };
        if speed.is_finite() {
            csv.push(&[(g + 1) as f64, x_gate, series[k].0, speed])?;
        }
    }
    Ok(())
}
