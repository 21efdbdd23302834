//! The monitors of a run, each on its schedule after every accepted step: the field series
//! (VTK), the bulk monitor (solids mass, front, mean u_s), the floor's wall probes, the front
//! tracker (and its gate speeds at the end) and the profiles at given times.
//!
//! Their state between steps (next sample times, bytes written, the front samples) is
//! [`MonitorsState`], saved in checkpoints: a restarted run cuts every file back to its
//! checkpoint length and goes on writing, so its files equal an uninterrupted run's.

use std::path::{Path, PathBuf};

use runout_case::{Case, FrontTracker};
use runout_mesh::Grid;
use runout_output::{CsvSeries, OutputError, PvdSeries};
use serde::{Deserialize, Serialize};

use super::case_solver::CaseSolver;

/// The name of the field series in a run folder.
pub const FIELDS_FILE: &str = "fields.pvd";

const BULK_HEADER: [&str; 4] = ["t", "solids_mass", "front_x", "mean_u_s"];
const PROBE_HEADER: [&str; 2] = ["t", "h_w_u"];
const FRONT_HEADER: [&str; 2] = ["t", "front_x"];

/// A schedule advances by at most this many additions of its interval per step; beyond,
/// it jumps past the current time (an interval far below the step would otherwise take
/// as many additions as steps of it fit into Δt; validation bounds intervals as well).
const MAX_SCHEDULE_ADDITIONS: usize = 1000;

/// Moves `next` past `time` by adding `interval` (the schedule's own arithmetic), or, if
/// that takes more than [`MAX_SCHEDULE_ADDITIONS`], to one interval past `time` (at least the
/// next representable number: the monitor then samples every step).
fn advance(next: &mut f64, interval: f64, time: f64) {
    let target = time * (1.0 + 1e-9);
    for _ in 0..MAX_SCHEDULE_ADDITIONS {
        if *next > target {
            return;
        }
        *next += interval;
    }
    if *next <= target {
        let jumped = target + interval;
        *next = if jumped > target {
            jumped
        } else {
            f64::from_bits(target.to_bits() + 1) // target ≥ 0: the next number up
        };
    }
}

struct Sampled {
    csv: CsvSeries,
    interval: f64,
    next: f64,
}

impl Sampled {
    fn due(&self, time: f64) -> bool {
        time >= self.next * (1.0 - 1e-9)
    }

    fn push_and_advance(&mut self, time: f64, row: Option<Vec<f64>>) -> Result<(), OutputError> {
        if let Some(row) = row {
            self.csv.push(&row)?;
        }
        advance(&mut self.next, self.interval, time);
        Ok(())
    }

    fn state(&self) -> Result<SampledState, OutputError> {
        Ok(SampledState {
            next: self.next,
            bytes: self.csv.len_bytes()?,
        })
    }
}

/// A sampled monitor's state at a checkpoint.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SampledState {
    next: f64,
    bytes: u64,
}

/// Every monitor's state between steps.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MonitorsState {
    next_output: f64,
    fields: Vec<(f64, String)>,
    bulk: Option<SampledState>,
    probes: Vec<SampledState>,
    front: Option<(SampledState, Vec<(f64, f64)>)>,
    profiles: Vec<usize>,
}

/// The front tracker's file, its settings and its samples (t, x) for the gate speeds.
type FrontMonitor = (Sampled, FrontTracker, Vec<(f64, f64)>);

/// The monitors of one run.
pub(super) struct Monitors {
    out_dir: PathBuf,
    output_interval: f64,
    next_output: f64,
    series: PvdSeries,
    /// the bulk monitor and its front threshold
    bulk: Option<(Sampled, f64)>,
    /// floor probes and their x
    probes: Vec<(Sampled, f64)>,
    /// the front tracker and its samples (t, x) for the gate speeds
    front: Option<FrontMonitor>,
    /// (x, times, index of the next time)
    profiles: Vec<(f64, Vec<f64>, usize)>,
}

fn probe_path(out_dir: &Path, at: f64) -> PathBuf {
    out_dir.join(format!("wall_probe_south_x{at}.csv"))
}

impl Monitors {
    /// Creates every monitor's file and writes the fields at t = 0.
    pub(super) fn start(
        case: &Case,
        solver: &mut dyn CaseSolver,
        out_dir: &Path,
    ) -> Result<Self, OutputError> {
        let solids = !case.solids.is_empty();
        let mut series = PvdSeries::new(out_dir.join(FIELDS_FILE));
        solver.write_fields(&mut series, 0.0)?;
        let bulk = match &case.monitors.bulk {
            Some(b) if solids => Some((
                Sampled {
                    csv: CsvSeries::create(&out_dir.join("bulk.csv"), &BULK_HEADER)?,
                    interval: b.interval,
                    next: 0.0,
                },
                b.front_threshold,
            )),
            _ => None,
        };
        let mut probes = Vec::new();
        for p in &case.monitors.wall_probes {
            if p.side == runout_mesh::Side::South && solids {
                let csv = CsvSeries::create(&probe_path(out_dir, p.at), &PROBE_HEADER)?;
                probes.push((
                    Sampled {
                        csv,
                        interval: p.interval,
                        next: 0.0,
                    },
                    p.at,
                ));
            }
        }
        let front = match &case.monitors.front {
            Some(f) if solids => Some((
                Sampled {
                    csv: CsvSeries::create(&out_dir.join("front.csv"), &FRONT_HEADER)?,
                    interval: f.interval,
                    next: 0.0,
                },
                f.clone(),
                Vec::new(),
            )),
            _ => None,
        };
        Ok(Monitors {
            out_dir: out_dir.to_path_buf(),
            output_interval: case.run.output_interval,
            next_output: case.run.output_interval,
            series,
            bulk,
            probes,
            front,
            profiles: Self::profile_schedule(case, None),
        })
    }

    fn profile_schedule(case: &Case, next: Option<&[usize]>) -> Vec<(f64, Vec<f64>, usize)> {
        case.monitors
            .profiles
            .iter()
            .enumerate()
            .map(|(k, p)| (p.x, p.times.clone(), next.map_or(0, |n| n[k])))
            .collect()
    }

    /// Reopens the monitors of a run at a checkpoint's `state`: every file cut back to its
    /// length then, field files written after it removed.
    pub(super) fn resume(
        case: &Case,
        out_dir: &Path,
        state: &MonitorsState,
    ) -> Result<Self, OutputError> {
        let mismatch = |what: &str| OutputError::Csv {
            path: out_dir.to_path_buf(),
            message: format!("the checkpoint's {what} do not match the case's monitors"),
        };
        let series = PvdSeries::resume(out_dir.join(FIELDS_FILE), state.fields.clone())?;
        let reopen = |path: PathBuf, columns: usize, interval: f64, s: &SampledState| {
            Ok::<_, OutputError>(Sampled {
                csv: CsvSeries::resume(&path, columns, s.bytes)?,
                interval,
                next: s.next,
            })
        };
        let bulk = match (&case.monitors.bulk, &state.bulk) {
            (Some(b), Some(s)) => Some((
                reopen(out_dir.join("bulk.csv"), BULK_HEADER.len(), b.interval, s)?,
                b.front_threshold,
            )),
            (_, None) => None,
            (None, Some(_)) => return Err(mismatch("bulk monitor")),
        };
        let south: Vec<_> = case
            .monitors
            .wall_probes
            .iter()
            .filter(|p| p.side == runout_mesh::Side::South && !case.solids.is_empty())
            .collect();
        if south.len() != state.probes.len() {
            return Err(mismatch("wall probes"));
        }
        let mut probes = Vec::new();
        for (p, s) in south.iter().zip(&state.probes) {
            let path = probe_path(out_dir, p.at);
            probes.push((reopen(path, PROBE_HEADER.len(), p.interval, s)?, p.at));
        }
        let front = match (&case.monitors.front, &state.front) {
            (Some(f), Some((s, samples))) => Some((
                reopen(out_dir.join("front.csv"), FRONT_HEADER.len(), f.interval, s)?,
                f.clone(),
                samples.clone(),
            )),
            (_, None) => None,
            (None, Some(_)) => return Err(mismatch("front tracker")),
        };
        if state.profiles.len() != case.monitors.profiles.len() {
            return Err(mismatch("profiles"));
        }
        Ok(Monitors {
            out_dir: out_dir.to_path_buf(),
            output_interval: case.run.output_interval,
            next_output: state.next_output,
            series,
            bulk,
            probes,
            front,
            profiles: Self::profile_schedule(case, Some(&state.profiles)),
        })
    }

    /// The state to save in a checkpoint.
    pub(super) fn state(&self) -> Result<MonitorsState, OutputError> {
        Ok(MonitorsState {
            next_output: self.next_output,
            fields: self.series.entries().to_vec(),
            bulk: self.bulk.as_ref().map(|(s, _)| s.state()).transpose()?,
            probes: self
                .probes
                .iter()
                .map(|(s, _)| s.state())
                .collect::<Result<_, _>>()?,
            front: self
                .front
                .as_ref()
                .map(|(s, _, samples)| Ok::<_, OutputError>((s.state()?, samples.clone())))
                .transpose()?,
            profiles: self.profiles.iter().map(|p| p.2).collect(),
        })
    }

    /// Samples every monitor that is due after the accepted step that reached `time`
    /// (`end`: the run's end time, where the fields are always written).
    pub(super) fn after_step(
        &mut self,
        solver: &mut dyn CaseSolver,
        grid: &Grid,
        time: f64,
        end: f64,
    ) -> Result<(), OutputError> {
        if time >= self.next_output * (1.0 - 1e-9) || time >= end * (1.0 - 1e-12) {
            solver.write_fields(&mut self.series, time)?;
            advance(&mut self.next_output, self.output_interval, time);
        }
        if let Some((bulk, threshold)) = self.bulk.as_mut() {
            if bulk.due(time) {
                let row = solver
                    .bulk(*threshold)
                    .map(|(front, mean_u)| vec![time, solver.solids_mass(), front, mean_u]);
                bulk.push_and_advance(time, row)?;
            }
        }
        for (probe, at) in self.probes.iter_mut() {
            if probe.due(time) {
                let row = solver.floor_h_u(*at).map(|h| vec![time, h]);
                probe.push_and_advance(time, row)?;
            }
        }
        if let Some((front, tracker, samples)) = self.front.as_mut() {
            if front.due(time) {
                let x = solver.interpolated_front(tracker.threshold);
                if let Some(x) = x {
                    samples.push((time, x));
                }
                front.push_and_advance(time, x.map(|x| vec![time, x]))?;
            }
        }
        for (x, times, next) in self.profiles.iter_mut() {
            while *next < times.len() && time >= times[*next] * (1.0 - 1e-9) {
                let path = self
                    .out_dir
                    .join(format!("profile_x{x}_t{}.csv", times[*next]));
                let mut csv = CsvSeries::create(&path, solver.profile_header())?;
                for &y in grid.y.centres() {
                    csv.push(&solver.profile(*x, y))?;
                }
                *next += 1;
            }
        }
        Ok(())
    }

    /// What is written once the run has stopped: the gate speeds of the front tracker.
    pub(super) fn finish(&self) -> Result<(), OutputError> {
        if let Some((_, tracker, samples)) = &self.front {
            write_gate_speeds(&self.out_dir.join("gates.csv"), tracker, samples)?;
        }
        Ok(())
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_schedule_advances_as_before_and_never_spins() {
        // the ordinary case: the same additions as `next += interval`
        let mut next = 0.1;
        advance(&mut next, 0.1, 0.35);
        assert_eq!(next, 0.1 + 0.1 + 0.1 + 0.1);
        // an interval far below the step: bounded work, past the time
        let mut next = 0.0;
        advance(&mut next, 1e-300, 1.0);
        assert!(next > 1.0 && next.is_finite());
        // an interval that cannot move next at all: just past the time
        let mut next = 1.0;
        advance(&mut next, 1e-300, 1.0);
        assert!(next > 1.0 + 1e-9 && next < 1.0 + 2e-9);
    }
}
