//! Everything the results report reads of one case: the chosen run ([`crate::chosen`]), its
//! station profile, floor probe, front, gate crossings and bulk monitor, each with the reason
//! it is missing.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use runout_case::Fidelity;

use crate::chosen::{choose_run, Run};
use crate::folder::{first_csv, read_resolved};
use crate::gates::read_gate_speeds;
use crate::metrics::{station_time, PROFILE_TIME};
use crate::profile::{station_profile, Profile};
use crate::run::BULK_TIME_TOLERANCE;
use crate::table::Table;

/// One gate crossing of a run's gates.csv.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GateSpeed {
    /// gate number (1 = L1)
    pub gate: usize,
    /// front speed at the gate [m/s]
    pub speed: f64,
}

/// Everything the report reads from one case's run; each part says why it is missing.
#[derive(Clone)]
pub struct CaseData {
    /// the chosen run
    pub run: Result<Run, String>,
    /// station profile at t = 1.25 s
    pub profile: Result<Profile, String>,
    /// floor wall probe: (t, h_w^u)
    pub probe: Result<Vec<(f64, f64)>, String>,
    /// front position: (t, x)
    pub front: Result<Vec<(f64, f64)>, String>,
    /// front speed at each gate reached
    pub gates: Result<Vec<GateSpeed>, String>,
    /// bulk monitor
    pub bulk: Result<Table, String>,
    /// x of the flume's channel inlet (the case's gate origin) [m]
    pub gate_origin: Option<f64>,
    /// the paper's t = 1.25 s in the run's clock: its last profile time (later by the tilt
    /// time for a case whose times count from the impact, docs/studies/impact.md §4) [s]
    pub station_time: f64,
}

/// A (t, value) series of a run's monitor file, missing if the run lacks it or it is empty.
fn series(
    run: &Run,
    file: Option<PathBuf>,
    what: &str,
    x: &str,
    y: &str,
) -> Result<Vec<(f64, f64)>, String> {
    let file = file.ok_or_else(|| format!("the {} run has no {what}", run.fidelity))?;
    let points = Table::read(&file)?.pairs(x, y)?;
    if points.is_empty() {
        return Err(format!("the {} run's {what} has no samples", run.fidelity));
    }
    Ok(points)
}

impl CaseData {
    /// Reads what the report needs of `case` from its chosen run under `runs`.
    pub fn load(runs: &Path, case: &str, requested: Option<Fidelity>) -> CaseData {
        match choose_run(runs, case, requested) {
            Ok(r) => CaseData::of_run(r),
            Err(why) => CaseData::missing(&why),
        }
    }

    /// Reads what the report needs of one run (its folder need not be under `runs/`).
    pub fn of_run(run: Run) -> CaseData {
        let r = &run;
        let resolved = read_resolved(&r.dir);
        let station_time = station_time(resolved.as_ref());
        let probe_file = first_csv(&r.dir, "wall_probe_south_x");
        let front_file = Some(r.dir.join("front.csv")).filter(|p| p.exists());
        let gates = if r.dir.join("gates.csv").exists() {
            read_gate_speeds(&r.dir.join("gates.csv")).map(|rows| {
                rows.into_iter()
                    .map(|(gate, speed)| GateSpeed { gate, speed })
                    .collect()
            })
        } else {
            Err(format!("the {} run has no gates.csv", r.fidelity))
        };
        let bulk_file = r.dir.join("bulk.csv");
        CaseData {
            profile: station_profile(r, station_time),
            probe: series(
                r,
                probe_file,
                "floor wall probe (wall_probe_south_x*.csv)",
                "t",
                "h_w_u",
            ),
            front: series(r, front_file, "front.csv", "t", "front_x"),
            gates,
            bulk: if bulk_file.exists() {
                Table::read(&bulk_file)
            } else {
                Err(format!("the {} run has no bulk.csv", r.fidelity))
            },
            gate_origin: resolved.and_then(|c| c.monitors.front.map(|f| f.gate_origin)),
            station_time,
            run: Ok(run),
        }
    }

    /// The run's fidelity, if it has a run.
    pub fn fidelity(&self) -> Option<Fidelity> {
        self.run.as_ref().ok().map(|r| r.fidelity)
    }

    /// The last probe sample at or before `t`: (time, h_w^u).
    pub fn probe_at(&self, t: f64) -> Result<(f64, f64), String> {
        let probe = self.probe.as_ref().map_err(Clone::clone)?;
        probe
            .iter()
            .copied()
            .rfind(|&(s, _)| s <= t * (1.0 + 1e-9))
            .ok_or_else(|| format!("no probe sample at or before t = {t} s"))
    }

    /// (front x, mean u_s) at `t`, interpolated between bulk samples (past the last one, that
    /// sample within [`BULK_TIME_TOLERANCE`]).
    pub fn bulk_at(&self, t: f64) -> Result<(f64, f64), String> {
        if let Some(why) = self.run.as_ref().ok().and_then(|r| r.ended_before(t)) {
            return Err(why);
        }
        let bulk = self.bulk.as_ref().map_err(Clone::clone)?;
        let (_, front) = bulk.value_at("t", "front_x", t, BULK_TIME_TOLERANCE)?;
        let (_, mean) = bulk.value_at("t", "mean_u_s", t, BULK_TIME_TOLERANCE)?;
        Ok((front, mean))
    }

    /// Gate speeds as (gate number, speed) pairs.
    pub fn gate_pairs(&self) -> Result<Vec<(usize, f64)>, String> {
        Ok(self
            .gates
            .as_ref()
            .map_err(Clone::clone)?
            .iter()
            .map(|g| (g.gate, g.speed))
            .collect())
    }
}

/// The cases of the report, by name.
pub struct Cases {
    data: BTreeMap<String, CaseData>,
}

impl Cases {
    /// Loads every named case.
    pub fn load<'a>(
        runs: &Path,
        names: impl IntoIterator<Item = &'a str>,
        requested: Option<Fidelity>,
    ) -> Cases {
        Cases {
            data: names
                .into_iter()
                .map(|n| (n.to_string(), CaseData::load(runs, n, requested)))
                .collect(),
        }
    }

    /// Gives a case without a run the reason `why` instead (e.g. that its numbers come from
    /// elsewhere); a case with a run is left as it is.
    pub fn explain_missing(&mut self, case: &str, why: &str) {
        if let Some(d) = self.data.get_mut(case) {
            if d.run.is_err() {
                *d = CaseData::missing(why);
            }
        }
    }

    /// The data of `case`; a name outside the matrix reads as "not in the case matrix".
    pub fn get(&self, case: &str) -> std::borrow::Cow<'_, CaseData> {
        match self.data.get(case) {
            Some(d) => std::borrow::Cow::Borrowed(d),
            None => std::borrow::Cow::Owned(CaseData::missing("not in the case matrix")),
        }
    }
}

impl CaseData {
    /// Why a run with a gates.csv has no gate speed.
    pub fn no_gate_reached(&self) -> String {
        match &self.run {
            Ok(r) => format!(
                "the {} run's front reached no gate by t = {:.2} s",
                r.fidelity, r.summary.simulated_time
            ),
            Err(e) => e.clone(),
        }
    }

    /// A case with nothing, for `why`.
    pub fn missing(why: &str) -> CaseData {
        let why = why.to_string();
        CaseData {
            run: Err(why.clone()),
            profile: Err(why.clone()),
            probe: Err(why.clone()),
            front: Err(why.clone()),
            gates: Err(why.clone()),
            bulk: Err(why),
            gate_origin: None,
            station_time: PROFILE_TIME,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixture::*;
    use crate::profile::profile_file_time;

    #[test]
    fn profiles_are_found_by_time_and_missing_ones_say_why() {
        let tmp = TempDir::new("profiles");
        let runs = tmp.0.join("runs");
        write_run(
            &runs,
            "done",
            "coarse",
            1.25,
            &[
                ("profile_x11_t0.5.csv", DENSE_PROFILE),
                ("profile_x11_t1.25.csv", CUSHION_PROFILE),
            ],
        );
        write_run(
            &runs,
            "short",
            "smoke",
            0.4,
            &[("profile_x11_t0.25.csv", DENSE_PROFILE)],
        );
        write_run(&runs, "unmonitored", "coarse", 1.25, &[]);
        let done = CaseData::load(&runs, "done", None);
        let p = done.profile.as_ref().unwrap();
        assert_eq!(
            p.eps_s[0], 0.05,
            "the t = 1.25 s file, not the t = 0.5 s one"
        );
        let m = p.metrics();
        assert_eq!(m.air_cushion, Some(true));
        assert!((m.flow_thickness.unwrap() - 0.015).abs() < 1e-12);
        let short = CaseData::load(&runs, "short", None);
        assert_eq!(
            short.profile.unwrap_err(),
            "the smoke run ends at t = 0.40 s, before t = 1.25 s"
        );
        let unmonitored = CaseData::load(&runs, "unmonitored", None);
        assert!(unmonitored
            .profile
            .unwrap_err()
            .contains("has no profile_x*_t1.25.csv"));
        assert_eq!(profile_file_time("profile_x11_t1.25.csv"), Some(1.25));
        assert_eq!(profile_file_time("profile_x2.5_t0.csv"), Some(0.0));
        assert_eq!(profile_file_time("wall_probe_south_x11.csv"), None);
    }

    #[test]
    fn probe_bulk_and_gates_are_read_at_the_right_times() {
        let tmp = TempDir::new("series");
        let runs = tmp.0.join("runs");
        write_run(
            &runs,
            "slide",
            "coarse",
            0.6,
            &[
                ("wall_probe_south_x11.csv", "t,h_w_u\n1.2,100\n1.25,150\n1.3,900\n"),
                (
                    "bulk.csv",
                    "t,solids_mass,front_x,mean_u_s\n0.29,1,0.9,1.0\n0.3005,1,1.1,1.2\n0.31,1,1.3,1.4\n",
                ),
                ("gates.csv", "gate,x,t_cross,speed\n1,2.15,0.5,3.0\n2,2.6,0.6,\n"),
                ("front.csv", "t,front_x\n0.0,0\n"),
            ],
        );
        let d = CaseData::load(&runs, "slide", None);
        assert_eq!(d.probe_at(1.25).unwrap(), (1.25, 150.0));
        assert!(d.probe_at(1.0).is_err());
        assert_eq!(d.bulk_at(0.3005).unwrap(), (1.1, 1.2));
        // between samples: interpolated
        let (front, mean) = d.bulk_at(0.30525).unwrap();
        assert!((front - 1.2).abs() < 1e-9 && (mean - 1.3).abs() < 1e-9);
        assert!(d.bulk_at(0.2).unwrap_err().contains("no sample"));
        assert!(d.bulk_at(0.8).unwrap_err().contains("ends at t = 0.60 s"));
        // a gate without a speed is not a crossing
        assert_eq!(d.gate_pairs().unwrap(), vec![(1, 3.0)]);
        // a front.csv with a header only reads as missing samples
        write_run(
            &runs,
            "empty",
            "smoke",
            0.4,
            &[("front.csv", "t,front_x\n")],
        );
        let e = CaseData::load(&runs, "empty", None);
        assert_eq!(
            e.front.unwrap_err(),
            "the smoke run's front.csv has no samples"
        );
        assert_eq!(e.gates.unwrap_err(), "the smoke run has no gates.csv");
    }
}
