//! What the report reads of a run folder: the chosen run, its monitor CSVs and the
//! quantities derived from them.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use runout_case::{load_case, Fidelity};
use runout_output::{RunStatus, RunSummary};

use crate::metrics::{profile_metrics, station_time, FlowMetrics, PROFILE_TIME};
/// The monitor-CSV reader lives in the post-processing library.
pub use runout_post::table::Table;

/// Fidelities from the best down: the default choice per case.
const BEST_FIRST: [Fidelity; 4] = [
    Fidelity::Paper,
    Fidelity::Wall,
    Fidelity::Coarse,
    Fidelity::Smoke,
];
/// Largest distance between a requested time past the last bulk sample and that sample [s]
/// (inside the series the values are interpolated): the bulk interval of the case files.
const BULK_TIME_TOLERANCE: f64 = runout_post::run::BULK_TIME_TOLERANCE;

/// The finished run chosen for a case.
#[derive(Clone, Debug)]
pub struct Run {
    /// its fidelity
    pub fidelity: Fidelity,
    /// its folder
    pub dir: PathBuf,
    /// its summary.json
    pub summary: RunSummary,
}

impl Run {
    /// Why a quantity at time `t` is missing if the run ended before `t`.
    pub fn ended_before(&self, t: f64) -> Option<String> {
        let end = self.summary.simulated_time;
        (end < t * (1.0 - 1e-9)).then(|| {
            let how = match self.summary.status {
                RunStatus::Diverged { .. } => " (diverged)",
                RunStatus::Interrupted => " (interrupted)",
                _ => "",
            };
            format!(
                "the {} run ends at t = {end:.2} s{how}, before t = {t} s",
                self.fidelity
            )
        })
    }
}

/// The run of `case` under `runs`: at `requested` fidelity, or the best that exists.
pub fn choose_run(runs: &Path, case: &str, requested: Option<Fidelity>) -> Result<Run, String> {
    let candidates = requested.map_or(BEST_FIRST.to_vec(), |f| vec![f]);
    for fidelity in candidates {
        let dir = runs.join(case).join(fidelity.name());
        let Ok(text) = std::fs::read_to_string(dir.join("summary.json")) else {
            continue;
        };
        let summary: RunSummary = serde_json::from_str(&text)
            .map_err(|e| format!("unreadable {fidelity} summary.json: {e}"))?;
        return Ok(Run {
            fidelity,
            dir,
            summary,
        });
    }
    Err(match requested {
        Some(f) => format!("not run at {f} fidelity"),
        None => "not run".into(),
    })
}

/// Wall-normal profile at the station: distance from the floor y (the domains start at
/// y = 0) and εs, u_s, θ.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    /// cell-centre heights [m]
    pub y: Vec<f64>,
    /// solids volume fraction [-]
    pub eps_s: Vec<f64>,
    /// solids x-velocity [m/s]
    pub u_s: Vec<f64>,
    /// granular temperature [m²/s²]
    pub theta: Vec<f64>,
}

impl Profile {
    /// The summary.csv metrics of this profile (crate::metrics definitions).
    pub fn metrics(&self) -> FlowMetrics {
        let rows: Vec<Vec<f64>> = (0..self.y.len())
            .map(|k| vec![self.y[k], self.eps_s[k], self.u_s[k], self.theta[k]])
            .collect();
        profile_metrics(&rows)
    }
}

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
    /// time for a case whose times count from the impact, docs/impact.md §4) [s]
    pub station_time: f64,
}

/// The files of `dir` whose names start with `prefix` and end with `.csv`, sorted.
fn csv_files(dir: &Path, prefix: &str) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|entries| {
            entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| {
                    p.file_name()
                        .and_then(|n| n.to_str())
                        .is_some_and(|n| n.starts_with(prefix) && n.ends_with(".csv"))
                })
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    files
}

/// The time in a profile file name `profile_x<x>_t<t>.csv`.
fn profile_file_time(name: &str) -> Option<f64> {
    name.strip_prefix("profile_x")?
        .strip_suffix(".csv")?
        .rsplit_once("_t")?
        .1
        .parse()
        .ok()
}

/// The station profile of a run at `time`.
fn station_profile(run: &Run, time: f64) -> Result<Profile, String> {
    let file = csv_files(&run.dir, "profile_x").into_iter().find(|p| {
        p.file_name()
            .and_then(|n| n.to_str())
            .and_then(profile_file_time)
            .is_some_and(|t| (t - time).abs() <= 1e-9 * time.max(1.0))
    });
    let Some(file) = file else {
        return Err(run.ended_before(time).unwrap_or_else(|| {
            format!(
                "the {} run has no profile_x*_t{time}.csv (no profile monitor at t = {time} s)",
                run.fidelity
            )
        }));
    };
    let t = Table::read(&file)?;
    Ok(Profile {
        y: t.column("y")?,
        eps_s: t.column("eps_s")?,
        u_s: t.column("u_s")?,
        theta: t.column("theta")?,
    })
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
        let run = choose_run(runs, case, requested);
        let Ok(r) = &run else {
            let why = run.as_ref().err().cloned().unwrap_or_default();
            return CaseData {
                run,
                profile: Err(why.clone()),
                probe: Err(why.clone()),
                front: Err(why.clone()),
                gates: Err(why.clone()),
                bulk: Err(why),
                gate_origin: None,
                station_time: PROFILE_TIME,
            };
        };
        let resolved = load_case(&r.dir.join("resolved.ron")).ok();
        let station_time = station_time(resolved.as_ref());
        let probe_file = csv_files(&r.dir, "wall_probe_south_x").into_iter().next();
        let front_file = Some(r.dir.join("front.csv")).filter(|p| p.exists());
        let gates = if r.dir.join("gates.csv").exists() {
            Table::read(&r.dir.join("gates.csv"))
                .and_then(|t| t.pairs("gate", "speed"))
                .map(|rows| {
                    rows.into_iter()
                        .filter(|(_, s)| s.is_finite())
                        .map(|(g, speed)| GateSpeed {
                            gate: g as usize,
                            speed,
                        })
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
            run,
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
    fn missing(why: &str) -> CaseData {
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

/// Run folders written for tests into a temporary directory.
#[cfg(test)]
pub mod fixture {
    use std::path::{Path, PathBuf};

    use runout_output::{DtStats, RunStatus, RunSummary};

    /// A temporary directory, removed on drop.
    pub struct TempDir(pub PathBuf);

    impl TempDir {
        /// A fresh directory named after the test.
        pub fn new(test: &str) -> TempDir {
            let dir =
                std::env::temp_dir().join(format!("runout-report-{}-{test}", std::process::id()));
            let _ = std::fs::remove_dir_all(&dir);
            std::fs::create_dir_all(&dir).expect("a temporary directory");
            TempDir(dir)
        }
    }

    impl Drop for TempDir {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }

    /// Writes `runs/<case>/<fidelity>/` with a summary ending at `end_time` and `files`.
    pub fn write_run(
        runs: &Path,
        case: &str,
        fidelity: &str,
        end_time: f64,
        files: &[(&str, &str)],
    ) {
        let dir = runs.join(case).join(fidelity);
        std::fs::create_dir_all(&dir).expect("a run folder");
        let summary = RunSummary {
            case: case.into(),
            fidelity: fidelity.into(),
            cells: (10, 4),
            simulated_time: end_time,
            wall_time: 1.0,
            steps: 10,
            rejected_steps: 0,
            outer_iterations: 50,
            dt: DtStats {
                min: 1e-3,
                max: 1e-3,
                mean: 1e-3,
            },
            solids_mass_change: 0.0,
            max_mass_imbalance: 0.0,
            max_eps_s: 0.6,
            status: RunStatus::Completed,
            profile: Vec::new(),
            linear_iterations: Vec::new(),
        };
        summary
            .write_json(&dir.join("summary.json"))
            .expect("a summary");
        for (name, text) in files {
            std::fs::write(dir.join(name), text).expect("a monitor file");
        }
    }

    /// A station profile with a cushion: floor εs 0.05 below a 0.6 peak (cell 2), flow top
    /// at 0.015 m, max u_s 3 m/s, floor θ 1.5 m²/s² (5 mm cells).
    pub const CUSHION_PROFILE: &str = "y,eps_s,u_s,theta\n0.0025,0.05,2.0,1.5\n\
        0.0075,0.55,3.0,0.2\n0.0125,0.6,2.5,0.1\n0.0175,0.005,1.0,0.5\n";

    /// A dense profile without a cushion, flow top at 0.025 m.
    pub const DENSE_PROFILE: &str = "y,eps_s,u_s,theta\n0.0025,0.6,1.0,0.0\n\
        0.0075,0.6,2.0,0.1\n0.0125,0.55,3.0,0.2\n0.0175,0.3,3.5,0.4\n0.0225,0.02,4.0,0.8\n";
}

#[cfg(test)]
mod tests {
    use super::fixture::*;
    use super::*;

    #[test]
    fn the_best_finished_run_is_chosen_unless_a_fidelity_is_asked() {
        let tmp = TempDir::new("choose");
        let runs = tmp.0.join("runs");
        write_run(&runs, "A", "smoke", 0.4, &[]);
        write_run(&runs, "A", "coarse", 1.25, &[]);
        // a folder without summary.json (a run still going) does not count
        std::fs::create_dir_all(runs.join("A").join("paper")).unwrap();
        assert_eq!(
            choose_run(&runs, "A", None).unwrap().fidelity,
            Fidelity::Coarse
        );
        let smoke = choose_run(&runs, "A", Some(Fidelity::Smoke)).unwrap();
        assert_eq!(smoke.fidelity, Fidelity::Smoke);
        assert_eq!(smoke.summary.simulated_time, 0.4);
        assert_eq!(
            choose_run(&runs, "A", Some(Fidelity::Paper)).unwrap_err(),
            "not run at paper fidelity"
        );
        assert_eq!(choose_run(&runs, "B", None).unwrap_err(), "not run");
        // the wall-resolving run ranks above coarse, below paper
        write_run(&runs, "A", "wall", 1.25, &[]);
        assert_eq!(
            choose_run(&runs, "A", None).unwrap().fidelity,
            Fidelity::Wall
        );
        write_run(&runs, "A", "paper", 1.25, &[]);
        assert_eq!(
            choose_run(&runs, "A", None).unwrap().fidelity,
            Fidelity::Paper
        );
    }

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
