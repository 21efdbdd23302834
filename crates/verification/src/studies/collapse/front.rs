//! The front history of a run (`bulk.csv`) and what it says: the runout at the end and when
//! the laboratory fronts stop, whether the front reached the end wall, and whether the
//! deposit stopped.

use std::path::Path;

use anyhow::{bail, Result};
pub use runout_post::bulk::BulkRow;

use super::column::Column;

/// "Stopped": front speed and εs-weighted mean u_s below this fraction of √(g H0).
const STOP_FRACTION: f64 = 0.01;
/// The front speed is measured over this last fraction of the run.
const STOP_WINDOW: f64 = 0.1;
/// The lab fronts stop after about this many √(H0/g) (Lajeunesse et al. 2005); the runout
/// is also reported at this time.
const LAB_STOP_TIMES: f64 = 3.0;

/// Reads `bulk.csv` ([`runout_post::bulk::read_bulk`]); a file without samples is an error.
pub fn read_bulk(path: &Path) -> Result<Vec<BulkRow>> {
    let rows = runout_post::bulk::read_bulk(path).map_err(anyhow::Error::msg)?;
    if rows.is_empty() {
        bail!("{}: no samples", path.display());
    }
    Ok(rows)
}

/// What the front history of one run says.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrontMetrics {
    /// (L∞ − L0)/L0 at the last sample
    pub runout: f64,
    /// (L − L0)/L0 at t = 3 √(H0/g), if the run got there
    pub runout_at_lab_stop: Option<f64>,
    /// the front reached the east wall: the runout is a lower bound
    pub reached_end_wall: bool,
    /// front speed over the last 10 % of the run over √(g H0) [-]
    pub front_speed: f64,
    /// εs-weighted mean u_s at the last sample over √(g H0) [-]
    pub mean_u: f64,
    /// both below 1 %
    pub stopped: bool,
    /// the earliest sample from which the mean u_s stays below 1 % of √(g H0) and the front
    /// no longer moves ([`runout_post::deposit::rest_time`]), in √(H0/g)
    pub rest_time: Option<f64>,
}

/// The front metrics of a bulk history `rows` of a column whose domain ends at `x_end`.
pub fn front_metrics(rows: &[BulkRow], column: &Column, x_end: f64) -> FrontMetrics {
    let last = rows[rows.len() - 1];
    let u_ref = column.velocity_scale();
    let lab_stop = LAB_STOP_TIMES * column.time_scale();
    let runout_at_lab_stop = rows
        .iter()
        .find(|r| r.t >= lab_stop * (1.0 - 1e-9))
        .map(|r| column.runout(r.front));
    let window_start = last.t * (1.0 - STOP_WINDOW);
    let first = rows
        .iter()
        .find(|r| r.t >= window_start)
        .copied()
        .unwrap_or(last);
    let front_speed = if last.t > first.t {
        (last.front - first.front) / (last.t - first.t) / u_ref
    } else {
        f64::INFINITY
    };
    let mean_u = last.mean_u / u_ref;
    FrontMetrics {
        runout: column.runout(last.front),
        runout_at_lab_stop,
        reached_end_wall: last.front >= x_end * (1.0 - 1e-12),
        front_speed,
        mean_u,
        stopped: front_speed.abs() < STOP_FRACTION && mean_u.abs() < STOP_FRACTION,
        rest_time: rest_time(rows, column),
    }
}

/// [`runout_post::deposit::rest_time`] with v_rest = 1 % of √(g H0), in √(H0/g).
fn rest_time(rows: &[BulkRow], column: &Column) -> Option<f64> {
    let times: Vec<f64> = rows.iter().map(|r| r.t).collect();
    let fronts: Vec<f64> = rows.iter().map(|r| r.front).collect();
    let speeds: Vec<f64> = rows.iter().map(|r| r.mean_u).collect();
    let v_rest = STOP_FRACTION * column.velocity_scale();
    runout_post::deposit::rest_time(&times, &fronts, &speeds, v_rest)
        .map(|t| t / column.time_scale())
}

#[cfg(test)]
mod tests {
    use super::*;
    fn column() -> Column {
        Column {
            l0: 0.05,
            h0: 0.05,
            x_wall: 0.0,
            gravity: 9.81,
        }
    }

    #[test]
    fn front_metrics_of_a_stopping_and_a_moving_front() {
        let c = column();
        let u = c.velocity_scale();
        // stops at x = 0.14 (runout 1.8) by t = 0.2, then rests until 0.45
        let rows: Vec<BulkRow> = (1..=90)
            .map(|k| {
                let t = 0.005 * k as f64;
                let front = if t < 0.2 { 0.05 + 0.09 * t / 0.2 } else { 0.14 };
                let mean_u = if t < 0.2 { 0.3 } else { 0.001 * u };
                BulkRow {
                    t,
                    mass: 3.0,
                    front,
                    mean_u,
                }
            })
            .collect();
        let m = front_metrics(&rows, &c, 0.5);
        assert!((m.runout - 1.8).abs() < 1e-12);
        assert!(m.stopped && !m.reached_end_wall);
        assert_eq!(m.front_speed, 0.0);
        // at 3 √(H0/g) = 0.214 s the front has stopped already
        assert!((m.runout_at_lab_stop.unwrap() - 1.8).abs() < 1e-12);
        // the same history still creeping: not stopped
        let creeping: Vec<BulkRow> = rows
            .iter()
            .map(|r| BulkRow {
                front: r.front + 0.05 * r.t,
                mean_u: 0.05 * u,
                ..*r
            })
            .collect();
        let m = front_metrics(&creeping, &c, 0.5);
        assert!(!m.stopped);
        assert!((m.front_speed - 0.05 / u).abs() < 1e-9);
        // a front at the east wall is flagged as a lower bound
        let at_wall: Vec<BulkRow> = rows.iter().map(|r| BulkRow { front: 0.5, ..*r }).collect();
        assert!(front_metrics(&at_wall, &c, 0.5).reached_end_wall);
    }
}
