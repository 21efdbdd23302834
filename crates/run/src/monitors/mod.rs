//! The monitors of a run: hooks called after every accepted step, each on its own schedule
//! and in its own file — the field series ([`fields`]), the bulk monitor ([`bulk`]), the
//! floor's wall probes ([`probe`]), the front tracker and its gate speeds ([`front`]) and
//! the profiles at given times ([`profiles`]); [`schedule`] is their shared clock.
//!
//! A case gets only the hooks it asks for, and the solids hooks only when it has solids.
//! Their state between steps (next sample times, bytes written, the front samples) is
//! [`MonitorsState`], saved in checkpoints: a restarted run cuts every file back to its
//! checkpoint length and goes on writing, so its files equal an uninterrupted run's.

mod bulk;
mod fields;
mod front;
mod probe;
mod profiles;
mod schedule;

use std::path::{Path, PathBuf};

use runout_case::Case;
use runout_mesh::Grid;
use runout_output::{OutputError, PvdSeries};
use serde::{Deserialize, Serialize};

use crate::case_solver::CaseSolver;
use bulk::{Bulk, BULK_FILE, BULK_HEADER};
use fields::Fields;
pub use fields::FIELDS_FILE;
use front::{Front, FRONT_FILE, FRONT_HEADER};
use probe::{probe_path, FloorProbe, PROBE_HEADER};
use profiles::Profile;
use schedule::{Sampled, SampledState};

/// A monitor: called after every accepted step, and once when the run has stopped.
pub(crate) trait Hook {
    /// Samples what is due after the accepted step that reached `time` (`end`: the run's
    /// end time).
    fn after_step(
        &mut self,
        solver: &mut dyn CaseSolver,
        grid: &Grid,
        time: f64,
        end: f64,
    ) -> Result<(), OutputError>;

    /// Writes what is written once the run has stopped (into `out_dir`).
    fn finish(&self, _out_dir: &Path) -> Result<(), OutputError> {
        Ok(())
    }
}

/// Every monitor's state between steps (the checkpoint's record; its layout is part of
/// the checkpoint format).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MonitorsState {
    next_output: f64,
    fields: Vec<(f64, String)>,
    bulk: Option<SampledState>,
    probes: Vec<SampledState>,
    front: Option<(SampledState, Vec<(f64, f64)>)>,
    profiles: Vec<usize>,
}

/// The monitors of one run.
pub(crate) struct Monitors {
    out_dir: PathBuf,
    fields: Fields,
    bulk: Option<Bulk>,
    probes: Vec<FloorProbe>,
    front: Option<Front>,
    profiles: Vec<Profile>,
}

/// The floor probes a case asks for (only south-side probes are sampled, and only with
/// solids).
fn floor_probes(case: &Case) -> Vec<&runout_case::WallProbe> {
    let solids = !case.solids.is_empty();
    case.monitors
        .wall_probes
        .iter()
        .filter(|p| p.side == runout_mesh::Side::South && solids)
        .collect()
}

impl Monitors {
    /// Creates every monitor's file and writes the fields at t = 0.
    pub(crate) fn start(
        case: &Case,
        solver: &mut dyn CaseSolver,
        out_dir: &Path,
    ) -> Result<Self, OutputError> {
        let solids = !case.solids.is_empty();
        let mut series = PvdSeries::new(out_dir.join(FIELDS_FILE));
        solver.write_fields(&mut series, 0.0)?;
        let fields = Fields {
            series,
            interval: case.run.output_interval,
            next: case.run.output_interval,
        };
        let bulk = match &case.monitors.bulk {
            Some(b) if solids => Some(Bulk {
                sampled: Sampled::create(&out_dir.join(BULK_FILE), &BULK_HEADER, b.interval)?,
                front_threshold: b.front_threshold,
            }),
            _ => None,
        };
        let probes = floor_probes(case)
            .into_iter()
            .map(|p| {
                Ok(FloorProbe {
                    sampled: Sampled::create(
                        &probe_path(out_dir, p.at),
                        &PROBE_HEADER,
                        p.interval,
                    )?,
                    at: p.at,
                })
            })
            .collect::<Result<_, OutputError>>()?;
        let front = match &case.monitors.front {
            Some(f) if solids => Some(Front {
                sampled: Sampled::create(&out_dir.join(FRONT_FILE), &FRONT_HEADER, f.interval)?,
                tracker: f.clone(),
                samples: Vec::new(),
            }),
            _ => None,
        };
        Ok(Monitors {
            out_dir: out_dir.to_path_buf(),
            fields,
            bulk,
            probes,
            front,
            profiles: Profile::schedule(case, out_dir.to_path_buf(), None),
        })
    }

    /// Reopens the monitors of a run at a checkpoint's `state`: every file cut back to its
    /// length then, field files written after it removed.
    pub(crate) fn resume(
        case: &Case,
        out_dir: &Path,
        state: &MonitorsState,
    ) -> Result<Self, OutputError> {
        let mismatch = |what: &str| OutputError::Csv {
            path: out_dir.to_path_buf(),
            message: format!("the checkpoint's {what} do not match the case's monitors"),
        };
        let fields = Fields {
            series: PvdSeries::resume(out_dir.join(FIELDS_FILE), state.fields.clone())?,
            interval: case.run.output_interval,
            next: state.next_output,
        };
        let bulk = match (&case.monitors.bulk, &state.bulk) {
            (Some(b), Some(s)) => Some(Bulk {
                sampled: Sampled::resume(
                    &out_dir.join(BULK_FILE),
                    BULK_HEADER.len(),
                    b.interval,
                    s,
                )?,
                front_threshold: b.front_threshold,
            }),
            (_, None) => None,
            (None, Some(_)) => return Err(mismatch("bulk monitor")),
        };
        let south = floor_probes(case);
        if south.len() != state.probes.len() {
            return Err(mismatch("wall probes"));
        }
        let probes = south
            .iter()
            .zip(&state.probes)
            .map(|(p, s)| {
                let path = probe_path(out_dir, p.at);
                Ok(FloorProbe {
                    sampled: Sampled::resume(&path, PROBE_HEADER.len(), p.interval, s)?,
                    at: p.at,
                })
            })
            .collect::<Result<_, OutputError>>()?;
        let front = match (&case.monitors.front, &state.front) {
            (Some(f), Some((s, samples))) => Some(Front {
                sampled: Sampled::resume(
                    &out_dir.join(FRONT_FILE),
                    FRONT_HEADER.len(),
                    f.interval,
                    s,
                )?,
                tracker: f.clone(),
                samples: samples.clone(),
            }),
            (_, None) => None,
            (None, Some(_)) => return Err(mismatch("front tracker")),
        };
        if state.profiles.len() != case.monitors.profiles.len() {
            return Err(mismatch("profiles"));
        }
        Ok(Monitors {
            out_dir: out_dir.to_path_buf(),
            fields,
            bulk,
            probes,
            front,
            profiles: Profile::schedule(case, out_dir.to_path_buf(), Some(&state.profiles)),
        })
    }

    /// The state to save in a checkpoint.
    pub(crate) fn state(&self) -> Result<MonitorsState, OutputError> {
        Ok(MonitorsState {
            next_output: self.fields.next,
            fields: self.fields.series.entries().to_vec(),
            bulk: self.bulk.as_ref().map(|b| b.sampled.state()).transpose()?,
            probes: self
                .probes
                .iter()
                .map(|p| p.sampled.state())
                .collect::<Result<_, _>>()?,
            front: self
                .front
                .as_ref()
                .map(|f| Ok::<_, OutputError>((f.sampled.state()?, f.samples.clone())))
                .transpose()?,
            profiles: self.profiles.iter().map(|p| p.next).collect(),
        })
    }

    /// The active hooks, in the order they are called (the order the files were always
    /// written in).
    fn hooks(&mut self) -> Vec<&mut dyn Hook> {
        let mut hooks: Vec<&mut dyn Hook> = vec![&mut self.fields];
        if let Some(b) = self.bulk.as_mut() {
            hooks.push(b);
        }
        hooks.extend(self.probes.iter_mut().map(|p| p as &mut dyn Hook));
        if let Some(f) = self.front.as_mut() {
            hooks.push(f);
        }
        hooks.extend(self.profiles.iter_mut().map(|p| p as &mut dyn Hook));
        hooks
    }

    /// Calls every hook after the accepted step that reached `time`.
    pub(crate) fn after_step(
        &mut self,
        solver: &mut dyn CaseSolver,
        grid: &Grid,
        time: f64,
        end: f64,
    ) -> Result<(), OutputError> {
        for hook in self.hooks() {
            hook.after_step(solver, grid, time, end)?;
        }
        Ok(())
    }

    /// What is written once the run has stopped (the gate speeds of the front tracker).
    pub(crate) fn finish(&mut self) -> Result<(), OutputError> {
        let out_dir = self.out_dir.clone();
        for hook in self.hooks() {
            hook.finish(&out_dir)?;
        }
        Ok(())
    }
}
