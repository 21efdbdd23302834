//! The flow quantities of results/summary.csv and `runout post`, read from a run's monitor
//! files.
//!
//! Definitions (issue 8; documented in docs/history/status-log.md, "Sweep, report, error against run time"):
//! - **air cushion**: at the station, the floor cell's εs is below 0.8 × the profile's peak εs;
//!   its **thickness** is the height of the top face of the highest cell below the peak whose
//!   εs is below 0.8 × peak;
//! - **flow thickness**: the height of the top face of the highest cell with εs ≥ 0.01 (the
//!   front threshold of cases.md);
//! - **max u_s**: the largest u_s of the profile over cells with εs ≥ 0.01;
//! - **h_w^u at the probe**: the last probe sample at or before t = 1.25 s (paper Fig. 9);
//! - **gate speeds**: the front speed at each gate (`gates.csv` of the run);
//! - **MSE vs described**: the mean square difference between the gate speeds and the speeds
//!   the paper describes (cases/flume/gates.csv, rows with a speed), over the gates both have.

use std::path::Path;

use serde::Serialize;

use crate::folder::{first_csv, read_resolved};
/// The gate files are read in [`crate::gates`].
pub use crate::gates::{described_speeds, gate_speeds};
use crate::table::Table;

/// Fraction of the peak εs below which the floor is an air cushion.
pub const CUSHION_FRACTION: f64 = 0.8;
/// εs that counts as flowing material (cases.md front threshold).
pub const FLOW_THRESHOLD: f64 = 0.01;
/// Time of the paper's profiles and probe reading [s].
pub const PROFILE_TIME: f64 = 1.25;

/// The flow columns of one run; `None` where the run has no such monitor.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct FlowMetrics {
    /// whether the station profile shows an air cushion
    pub air_cushion: Option<bool>,
    /// cushion thickness [m] (0 without a cushion)
    pub cushion_thickness: Option<f64>,
    /// εs of the floor cell at the station
    pub floor_eps_s: Option<f64>,
    /// flow thickness at the station [m]
    pub flow_thickness: Option<f64>,
    /// max u_s at the station [m/s]
    pub max_u_s: Option<f64>,
    /// h_w^u at the probe at t = 1.25 s [1/m]
    pub h_wu_probe: Option<f64>,
    /// front speed at each gate reached [m/s]: (gate number, speed)
    pub gate_speeds: Vec<(usize, f64)>,
    /// mean square error against the described speeds [m²/s²]
    pub mse_vs_described: Option<f64>,
}

/// Rows of the named columns of a CSV file runout wrote; `None` if it cannot be read or
/// lacks one of them.
fn rows(path: &Path, columns: &[&str]) -> Option<Vec<Vec<f64>>> {
    let table = Table::read(path).ok()?;
    let cols: Vec<Vec<f64>> = columns
        .iter()
        .map(|c| table.column(c))
        .collect::<Result<_, _>>()
        .ok()?;
    Some(
        (0..table.len())
            .map(|k| cols.iter().map(|c| c[k]).collect())
            .collect(),
    )
}

/// Profile metrics from rows (y, εs, u_s, θ) ordered from the floor up; `cell_top(k)` is the
/// height of the top face of row k (mid-way to the next centre, mirrored at the top).
pub fn profile_metrics(profile: &[Vec<f64>]) -> FlowMetrics {
    let mut m = FlowMetrics::default();
    if profile.is_empty() {
        return m;
    }
    let y: Vec<f64> = profile.iter().map(|r| r[0]).collect();
    let eps: Vec<f64> = profile.iter().map(|r| r[1]).collect();
    let top = |k: usize| {
        if k + 1 < y.len() {
            0.5 * (y[k] + y[k + 1])
        } else {
            2.0 * y[k] - if k > 0 { 0.5 * (y[k - 1] + y[k]) } else { 0.0 }
        }
    };
    let (peak_index, peak) =
        eps.iter()
            .cloned()
            .enumerate()
            .fold(
                (0, f64::NEG_INFINITY),
                |a, (k, e)| if e > a.1 { (k, e) } else { a },
            );
    m.floor_eps_s = Some(eps[0]);
    if peak >= FLOW_THRESHOLD {
        let cushion = eps[0] < CUSHION_FRACTION * peak;
        m.air_cushion = Some(cushion);
        m.cushion_thickness = Some(if cushion {
            (0..peak_index)
                .rev()
                .find(|&k| eps[k] < CUSHION_FRACTION * peak)
                .map_or(0.0, top)
        } else {
            0.0
        });
        m.flow_thickness = (0..eps.len())
            .rev()
            .find(|&k| eps[k] >= FLOW_THRESHOLD)
            .map(top);
        m.max_u_s = profile
            .iter()
            .filter(|r| r[1] >= FLOW_THRESHOLD)
            .map(|r| r[2])
            .fold(None, |a: Option<f64>, u| Some(a.map_or(u, |a| a.max(u))));
    } else {
        m.air_cushion = Some(false);
        m.cushion_thickness = Some(0.0);
        m.flow_thickness = Some(0.0);
    }
    m
}

/// The paper's t = 1.25 s in a run's clock: the last time of its case's first profile
/// monitor (for a case whose times count from the impact, the tilt time later,
/// docs/studies/impact.md §4); [`PROFILE_TIME`] without one.
pub fn station_time(case: Option<&runout_case::Case>) -> f64 {
    case.and_then(|c| c.monitors.profiles.first())
        .and_then(|p| p.times.last().copied())
        .unwrap_or(PROFILE_TIME)
}

/// All flow metrics of the run in `dir`; `described` holds (gate number, speed) pairs.
pub fn flow_metrics(dir: &Path, described: &[(usize, f64)]) -> FlowMetrics {
    let at = station_time(read_resolved(dir).as_ref());
    // the profile at the station time (the monitors name files by time with `{}`)
    let at_station = std::fs::read_dir(dir).ok().and_then(|entries| {
        entries.filter_map(|e| e.ok().map(|e| e.path())).find(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("profile_") && n.ends_with(&format!("_t{at}.csv")))
        })
    });
    let mut m = at_station
        .or_else(|| first_csv(dir, "profile_"))
        .and_then(|p| rows(&p, &["y", "eps_s", "u_s", "theta"]))
        .map(|r| profile_metrics(&r))
        .unwrap_or_default();
    if let Some(probe) = first_csv(dir, "wall_probe_").and_then(|p| rows(&p, &["t", "h_w_u"])) {
        m.h_wu_probe = probe
            .iter()
            .rfind(|r| r[0] <= at * (1.0 + 1e-9))
            .map(|r| r[1]);
    }
    if let Some(speeds) = gate_speeds(dir) {
        m.gate_speeds = speeds;
        m.mse_vs_described = mse_vs_described(&m.gate_speeds, described).map(|(e, _)| e);
    }
    m
}

/// Mean square difference between gate speeds and the described speeds over the gates both
/// have, with the number of those gates; `None` if they share none. Both lists hold
/// (gate number, speed) pairs.
pub fn mse_vs_described(
    speeds: &[(usize, f64)],
    described: &[(usize, f64)],
) -> Option<(f64, usize)> {
    let squares: Vec<f64> = speeds
        .iter()
        .filter_map(|(g, s)| {
            described
                .iter()
                .find(|(d, _)| d == g)
                .map(|(_, v)| (s - v).powi(2))
        })
        .collect();
    (!squares.is_empty()).then(|| {
        (
            squares.iter().sum::<f64>() / squares.len() as f64,
            squares.len(),
        )
    })
}

impl FlowMetrics {
    /// The eight CSV columns (empty where unknown).
    pub fn csv(&self) -> String {
        let num = |v: Option<f64>| v.map_or(String::new(), |v| format!("{v:.6e}"));
        let speeds: Vec<String> = self
            .gate_speeds
            .iter()
            .map(|(g, s)| format!("L{g}:{s:.3}"))
            .collect();
        format!(
            "{},{},{},{},{},{},{},{}",
            self.air_cushion.map_or(String::new(), |c| if c {
                "yes".into()
            } else {
                "no".into()
            }),
            num(self.cushion_thickness),
            num(self.floor_eps_s),
            num(self.flow_thickness),
            num(self.max_u_s),
            num(self.h_wu_probe),
            speeds.join(";"),
            num(self.mse_vs_described)
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn profile(eps: &[f64], u: f64) -> Vec<Vec<f64>> {
        eps.iter()
            .enumerate()
            .map(|(k, &e)| vec![0.005 * (k as f64 + 0.5), e, u, 0.1])
            .collect()
    }

    #[test]
    fn a_dilute_floor_below_a_dense_layer_is_a_cushion() {
        let m = profile_metrics(&profile(&[0.05, 0.2, 0.55, 0.6, 0.3, 0.005], 3.0));
        assert_eq!(m.air_cushion, Some(true));
        // cells 0 and 1 lie below 0.8 × 0.6 under the peak (cell 3): top of cell 1 is 0.01 m
        assert!((m.cushion_thickness.unwrap() - 0.010).abs() < 1e-12);
        // the highest cell with εs ≥ 0.01 is cell 4: top at 0.025 m
        assert!((m.flow_thickness.unwrap() - 0.025).abs() < 1e-12);
        assert_eq!(m.max_u_s, Some(3.0));
    }

    #[test]
    fn a_dense_floor_is_no_cushion() {
        let m = profile_metrics(&profile(&[0.6, 0.58, 0.4, 0.0], 1.0));
        assert_eq!(m.air_cushion, Some(false));
        assert_eq!(m.cushion_thickness, Some(0.0));
        assert_eq!(m.csv().split(',').count(), 8);
    }
}
