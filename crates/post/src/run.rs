//! Everything `runout post RUN_DIR` reports of one run folder: its summary, the station time
//! and the flow metrics there.

use std::path::Path;

use runout_output::RunSummary;
use serde::Serialize;

use crate::basal_load::FlowLoad;
use crate::deposit::{read_deposit, Deposit, DEFAULT_REST_FRACTION};
use crate::folder::{read_resolved_unvalidated, read_summary};
use crate::metrics::{flow_metrics, station_time, FlowMetrics};
use crate::table::Table;

/// Largest distance between the station time and a bulk sample read for it when no sample
/// lies beyond it [s] (the bulk interval of the shipped case files: a run that ends at the
/// station time has its last sample up to one interval before).
pub const BULK_TIME_TOLERANCE: f64 = 0.01;

/// The metrics of one run folder.
#[derive(Clone, Debug, Serialize)]
pub struct RunMetrics {
    /// the run's summary.json (absent for a run still going or killed)
    pub summary: Option<RunSummary>,
    /// the paper's t = 1.25 s in the run's clock [s] (docs/studies/impact.md §4)
    pub station_time: f64,
    /// the time bulk.csv is read at [s]: the station time, or the nearest sample to it
    pub bulk_time: Option<f64>,
    /// the front x [m] and εs-weighted mean u_s [m/s] of bulk.csv at `bulk_time`
    pub front_x: Option<f64>,
    /// see `front_x`
    pub mean_u_s: Option<f64>,
    /// the station profile's metrics, h_w^u at the probe and gate speeds
    pub flow: FlowMetrics,
    /// where the solids stopped, or why not read ([`crate::deposit`], v_rest = 1 % of
    /// √(g H∞))
    pub deposit: Result<Deposit, String>,
    /// the flow's basal load and its shares at each field file ([`crate::basal_load`]),
    /// read on request (`runout post --basal-load`)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub basal_load: Option<Vec<FlowLoad>>,
}

/// Reads the run in `dir`; `described` holds the (gate number, speed) pairs the gate MSE
/// compares with (empty: no MSE). An error names the folder when it is not a run folder.
pub fn run_metrics(dir: &Path, described: &[(usize, f64)]) -> Result<RunMetrics, String> {
    if !dir.join("resolved.ron").exists() && !dir.join("summary.json").exists() {
        return Err(format!(
            "{}: not a run folder (no resolved.ron or summary.json)",
            dir.display()
        ));
    }
    let summary = read_summary(dir).transpose().map_err(|e| e.to_string())?;
    // unvalidated: a resolved smoke case keeps the paper's profile time beyond its end
    let resolved = read_resolved_unvalidated(dir).ok();
    let at = station_time(resolved.as_ref());
    let bulk = bulk_at(dir, at);
    Ok(RunMetrics {
        summary,
        station_time: at,
        bulk_time: bulk.map(|b| b.0),
        front_x: bulk.map(|b| b.1),
        mean_u_s: bulk.map(|b| b.2),
        flow: flow_metrics(dir, described),
        deposit: match &resolved {
            Some(case) => read_deposit(dir, case, DEFAULT_REST_FRACTION).map(|(d, _)| d),
            None => Err("no readable resolved.ron".into()),
        },
        basal_load: None,
    })
}

/// (time, front x, mean u_s) of bulk.csv at `t` ([`Table::row_at`] with
/// [`BULK_TIME_TOLERANCE`]).
pub fn bulk_at(dir: &Path, t: f64) -> Option<(f64, f64, f64)> {
    let bulk = Table::read(&dir.join("bulk.csv")).ok()?;
    let (at, front) = bulk.value_at("t", "front_x", t, BULK_TIME_TOLERANCE).ok()?;
    let (_, mean) = bulk
        .value_at("t", "mean_u_s", t, BULK_TIME_TOLERANCE)
        .ok()?;
    Some((at, front, mean))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn folder(test: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("runout-post-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn the_bulk_sample_nearest_the_station_time_is_read() {
        let dir = folder("bulk");
        std::fs::write(
            dir.join("bulk.csv"),
            "t,solids_mass,front_x,mean_u_s\n1.24,120,10.0,4.0\n1.26,120,10.4,4.2\n",
        )
        .unwrap();
        let (t, front, mean) = bulk_at(&dir, 1.25).unwrap();
        assert_eq!(t, 1.25, "interpolated at the asked time");
        assert!((front - 10.2).abs() < 1e-12 && (mean - 4.1).abs() < 1e-12);
        assert_eq!(
            bulk_at(&dir, 1.264),
            Some((1.26, 10.4, 4.2)),
            "the last sample, 4 ms before"
        );
        assert_eq!(bulk_at(&dir, 2.0), None, "no sample within the tolerance");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn a_folder_without_run_files_is_refused_by_name() {
        let dir = folder("empty");
        let err = run_metrics(&dir, &[]).unwrap_err();
        assert!(err.contains("not a run folder"), "{err}");
        std::fs::write(dir.join("summary.json"), "{").unwrap();
        assert!(run_metrics(&dir, &[])
            .unwrap_err()
            .contains("unreadable summary.json"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
