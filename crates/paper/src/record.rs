//! One run's record: every scalar the findings and tables of results.md read (the station
//! profile's metrics, h_w^u at the floor probe, the gate speeds, the front and mean u_s at
//! fixed times) with what identifies the run (case, fidelity, grid, end time, solver, date,
//! steps, wall time). A record comes from a run folder on this machine (the *store*,
//! [`RunRecord::from_store`]) or from a row of the committed ledger
//! ([`super::ledger`], [`RunRecord::from_row`]); figures need the folder, the findings only
//! the record.
//!
//! A value a run does not have is an `Err` with the reason: from a run folder, the reason
//! the folder gives; from a ledger row (an empty cell), a reason rebuilt from the row
//! (the run ended before the time, or the row has no such value).

use std::path::Path;
use std::time::SystemTime;

use runout_case::Fidelity;
use runout_output::RunStatus;
use runout_post::case_data::CaseData;
use runout_post::metrics::FLOW_THRESHOLD;

use crate::date;
use crate::solver_stamp::SOLVER_FILE;

/// The solver of a run whose folder does not record it.
pub const UNKNOWN_SOLVER: &str = "unknown";
/// Times at which the bulk monitor's front x and mean u_s are recorded [s] (family M's
/// comparison with MFIX, [`super::figure_sets::MFIX_SLIDE`]).
pub const BULK_TIMES: [f64; 3] = [0.3, 0.5, 0.8];
/// Gates whose front speed is recorded (L1–L7 of cases/flume/gates.csv).
pub const GATES: usize = 7;

/// Where a record comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// a run folder `runs/<case>/<fidelity>/` on this machine
    Store,
    /// a row of docs/reports/results/ledger/<fidelity>.csv
    Ledger,
}

/// The station profile's scalars (runout_post::metrics definitions).
#[derive(Clone, Debug, PartialEq)]
pub struct Station {
    /// largest εs of the profile [-]
    pub peak_eps_s: f64,
    /// εs of the floor cell [-]
    pub floor_eps_s: f64,
    /// θ of the floor cell [m²/s²]
    pub floor_theta: f64,
    /// whether the floor is an air cushion
    pub air_cushion: Option<bool>,
    /// cushion thickness [m] (0 without a cushion)
    pub cushion_thickness: Option<f64>,
    /// flow thickness [m]
    pub flow_thickness: Option<f64>,
    /// largest u_s over the flowing cells [m/s]
    pub max_u_s: Option<f64>,
}

impl Station {
    /// The station's flow metrics; a profile without flowing material says so instead.
    pub fn flow(&self) -> Result<&Station, String> {
        if self.peak_eps_s < FLOW_THRESHOLD {
            return Err(format!(
                "no flow at the station: the largest εs is {:.1e} < {FLOW_THRESHOLD}",
                self.peak_eps_s
            ));
        }
        Ok(self)
    }
}

/// One run's record.
#[derive(Clone, Debug, PartialEq)]
pub struct RunRecord {
    /// case name
    pub case: String,
    /// fidelity
    pub fidelity: Fidelity,
    /// cells in x and y
    pub cells: (usize, usize),
    /// simulated time reached [s]
    pub end_time: f64,
    /// how the run ended: completed or diverged
    pub status: String,
    /// `git describe` of the build that ran it, or [`UNKNOWN_SOLVER`]
    pub solver: String,
    /// the day its summary.json was written (UTC, YYYY-MM-DD)
    pub date: String,
    /// accepted steps
    pub steps: u64,
    /// rejected steps
    pub rejected_steps: u64,
    /// outer iterations of the accepted steps
    pub outer_iterations: u64,
    /// wall time [s] (CPU time is not recorded by runs)
    pub wall_time: f64,
    /// the paper's t = 1.25 s in the run's clock [s]
    pub station_time: f64,
    /// the station profile at the station time
    pub station: Result<Station, String>,
    /// the last floor-probe sample at or before the station time: (t, h_w^u)
    pub probe: Result<(f64, f64), String>,
    /// front speed at each gate reached: (gate number, speed)
    pub gates: Result<Vec<(usize, f64)>, String>,
    /// (front x, mean u_s) of bulk.csv at each of [`BULK_TIMES`]
    pub bulk: Vec<Result<(f64, f64), String>>,
    /// (front x, mean u_s) of bulk.csv at the station time
    pub bulk_station: Result<(f64, f64), String>,
    /// (front x, mean u_s) of bulk.csv at the end time (the sensitivity's time of runs that
    /// end before the station time)
    pub bulk_end: Result<(f64, f64), String>,
    /// where it comes from (not written)
    pub source: Source,
}

/// A status as the ledger writes it.
fn status_name(s: &RunStatus) -> &'static str {
    match s {
        RunStatus::Completed => "completed",
        RunStatus::Running => "running",
        RunStatus::Diverged { .. } => "diverged",
        RunStatus::Interrupted => "interrupted",
        RunStatus::Failed { .. } => "failed",
    }
}

/// Whether a run with this status has ended for good (a row of the ledger): completed or
/// diverged, not running, interrupted (it continues from its checkpoint) or failed.
pub fn is_finished(s: &RunStatus) -> bool {
    matches!(s, RunStatus::Completed | RunStatus::Diverged { .. })
}

/// The station's scalars of a case's profile, or why there are none.
fn station_of(d: &CaseData) -> Result<Station, String> {
    let p = d.profile.as_ref().map_err(Clone::clone)?;
    let (Some(&floor_eps_s), Some(&floor_theta)) = (p.eps_s.first(), p.theta.first()) else {
        return Err("an empty profile".into());
    };
    let m = p.metrics();
    Ok(Station {
        peak_eps_s: p.eps_s.iter().copied().fold(0.0, f64::max),
        floor_eps_s,
        floor_theta,
        air_cushion: m.air_cushion,
        cushion_thickness: m.cushion_thickness,
        flow_thickness: m.flow_thickness,
        max_u_s: m.max_u_s,
    })
}

/// The solver a run folder records ([`SOLVER_FILE`], written by `cargo xtask sweep`), or
/// [`UNKNOWN_SOLVER`].
pub fn solver_of(dir: &Path) -> String {
    std::fs::read_to_string(dir.join(SOLVER_FILE))
        .ok()
        .map(|s| s.trim().to_string())
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| UNKNOWN_SOLVER.into())
}

/// A day as YYYY-MM-DD (UTC), from days since 1970-01-01 ([`date::civil_date`]).
fn civil_date(days: i64) -> String {
    let (year, month, day) = date::civil_date(days);
    format!("{year:04}-{month:02}-{day:02}")
}

/// The day a file was last written (UTC), or "unknown".
pub fn file_date(path: &Path) -> String {
    std::fs::metadata(path)
        .and_then(|m| m.modified())
        .ok()
        .and_then(|t| t.duration_since(SystemTime::UNIX_EPOCH).ok())
        .map_or("unknown".into(), |d| {
            civil_date((d.as_secs() / 86_400) as i64)
        })
}

impl RunRecord {
    /// The record of a case's chosen run folder; `None` without a run or for a run that has
    /// not ended for good ([`is_finished`]).
    pub fn from_store(case: &str, d: &CaseData) -> Option<RunRecord> {
        let run = d.run.as_ref().ok()?;
        let s = &run.summary;
        if !is_finished(&s.status) {
            return None;
        }
        Some(RunRecord {
            case: case.into(),
            fidelity: run.fidelity,
            cells: s.cells,
            end_time: s.simulated_time,
            status: status_name(&s.status).into(),
            solver: solver_of(&run.dir),
            date: file_date(&run.dir.join("summary.json")),
            steps: s.steps,
            rejected_steps: s.rejected_steps,
            outer_iterations: s.outer_iterations,
            wall_time: s.wall_time,
            station_time: d.station_time,
            station: station_of(d),
            probe: d.probe_at(d.station_time),
            gates: d.gate_pairs(),
            bulk: BULK_TIMES.iter().map(|&t| d.bulk_at(t)).collect(),
            bulk_station: d.bulk_at(d.station_time),
            bulk_end: d.bulk_at(s.simulated_time),
            source: Source::Store,
        })
    }

    /// Why a quantity at time `t` is missing if the run ended before `t` (the words of
    /// [`runout_post::chosen::Run::ended_before`]).
    pub fn ended_before(&self, t: f64) -> Option<String> {
        let end = self.end_time;
        (end < t * (1.0 - 1e-9)).then(|| {
            let how = match self.status.as_str() {
                "diverged" | "interrupted" => format!(" ({})", self.status),
                _ => String::new(),
            };
            format!(
                "the {} run ends at t = {end:.2} s{how}, before t = {t} s",
                self.fidelity
            )
        })
    }

    /// Why a run that has a gates.csv has no gate speed.
    pub fn no_gate_reached(&self) -> String {
        format!(
            "the {} run's front reached no gate by t = {:.2} s",
            self.fidelity, self.end_time
        )
    }

    /// (front x, mean u_s) at one of [`BULK_TIMES`].
    pub fn bulk_at(&self, t: f64) -> Result<(f64, f64), String> {
        BULK_TIMES
            .iter()
            .position(|&b| (b - t).abs() < 1e-12)
            .and_then(|k| self.bulk.get(k))
            .cloned()
            .unwrap_or_else(|| Err(format!("no bulk reading at t = {t} s recorded")))
    }

    /// (front x, mean u_s) at the station time or the end time, the times a record keeps
    /// besides [`BULK_TIMES`].
    pub fn bulk_at_station_or_end(&self, t: f64) -> Result<(f64, f64), String> {
        let near = |a: f64| (a - t).abs() <= 1e-9 * t.abs().max(1.0);
        if near(self.station_time) {
            self.bulk_station.clone()
        } else if near(self.end_time) {
            self.bulk_end.clone()
        } else {
            Err(format!(
                "the record holds bulk.csv at the station time and the end time, not t = {t} s"
            ))
        }
    }

    /// The station's metrics where material flows there.
    pub fn flow(&self) -> Result<&Station, String> {
        self.station.as_ref().map_err(Clone::clone)?.flow()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn days_become_civil_dates() {
        assert_eq!(civil_date(0), "1970-01-01");
        assert_eq!(civil_date(59), "1970-03-01");
        assert_eq!(civil_date(11_016), "2000-02-29");
        assert_eq!(civil_date(20_793), "2026-12-06");
    }
}
