//! Synthetic-truth recovery (issue 48): a case run with known parameter values (the truth),
//! measurements taken from its own outputs ([`super::synthetic`]: its interpolated front or
//! its gate speeds, or a profile at a station, with a stated σ, with or without Gaussian noise of that σ), and the
//! calibration started elsewhere. A recovery succeeds when the optimum lies near the truth
//! and the stated range Δχ² ≤ 1 contains it; the range narrows as σ falls.
//!
//! A truth case without the monitors a measurement needs (family M has no gates and no
//! profile station) is given them by [`TruthStudy::monitors`], for the truth and every
//! calibration run alike.
//!
//! The CI tests run family M at smoke fidelity; the tables of docs/reference/calibrate.md are the
//! ignored tests `recovery_table` and `recovery_table_*` (their commands there), at coarse
//! fidelity.

use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use anyhow::{bail, Result};
use indicatif::{MultiProgress, ProgressBar};
use runout_case::{Case, Fidelity, Monitors};
use runout_run::store::Reuse;

use super::measurements::Measurements;
use super::optimise::{calibrate, Calibration, Settings};
use super::path::{set_all, CasePath};
use super::synthetic::{measurements_from_run, Measured};
use super::uncertainty::{range, Range};
use super::{landscape, parse_param, select_case, CaseModel};
use crate::sweep::{run_into, Outcome as RunOutcome};

/// One parameter of a truth study: its path, its true value, and the calibration's
/// `LO:HI[:START][:log]`.
#[derive(Clone, Debug)]
pub struct TrueParam {
    /// the path (as `--param` takes it)
    pub path: String,
    /// the truth
    pub truth: f64,
    /// `LO:HI[:START][:log]`
    pub bounds: String,
}

/// A synthetic-truth study.
#[derive(Clone, Debug)]
pub struct TruthStudy {
    /// the case file (one case), below the workspace root
    pub case_file: PathBuf,
    /// one or two parameters
    pub params: Vec<TrueParam>,
    /// the monitors of every run, if not the case's (gates, profile stations)
    pub monitors: Option<Monitors>,
    /// fidelity of every run
    pub fidelity: Fidelity,
    /// the fidelity preset's end time, if not the case's
    pub end_time: Option<f64>,
    /// what is measured
    pub measured: Measured,
    /// the measurement error σ
    pub sigma: f64,
    /// the seed of the added noise (none: the truth's exact outputs)
    pub noise: Option<u64>,
    /// how to calibrate
    pub settings: Settings,
}

/// What a recovery gave.
pub struct Recovered {
    /// the true values
    pub truth: Vec<f64>,
    /// the calibration
    pub calibration: Calibration,
    /// its range
    pub range: Range,
}

impl Recovered {
    /// The optimum.
    pub fn optimum(&self) -> &[f64] {
        &self.calibration.optimum().x
    }

    /// Whether the range contains the truth, per parameter.
    pub fn contains_truth(&self) -> Vec<bool> {
        self.range
            .bounds
            .iter()
            .zip(&self.truth)
            .map(|(&(lo, hi), &t)| lo <= t && t <= hi)
            .collect()
    }

    /// (optimum − truth)/truth per parameter.
    pub fn relative_error(&self) -> Vec<f64> {
        self.optimum()
            .iter()
            .zip(&self.truth)
            .map(|(o, t)| (o - t) / t)
            .collect()
    }
}

/// The case of the study with its monitors, at its end time.
fn base_case(root: &Path, study: &TruthStudy) -> Result<Case> {
    let mut case = select_case(&root.join(&study.case_file), None)?;
    if let Some(monitors) = &study.monitors {
        case.monitors = monitors.clone();
    }
    match study.end_time {
        Some(t) => {
            let path = CasePath::parse(&format!("fidelity.{}.end_time", study.fidelity), &case)?;
            set_all(&case, &[(&path, t)])
        }
        None => Ok(case),
    }
}

/// Runs the truth, writes its measurements and calibrates against them, all in `dir`
/// (finished runs there are reused).
pub fn recover(root: &Path, study: &TruthStudy, dir: &Path) -> Result<Recovered> {
    recover_in(root, study, dir, dir)
}

/// [`recover`] with the runs (the truth's and the calibration's) in `runs`, where studies
/// of other truths and measurements with the same monitors reuse them, and the
/// measurements, evaluations and summary in `out`.
pub fn recover_in(root: &Path, study: &TruthStudy, runs: &Path, out: &Path) -> Result<Recovered> {
    let case = base_case(root, study)?;
    let (paths, params): (Vec<CasePath>, Vec<_>) = study
        .params
        .iter()
        .map(|p| parse_param(&format!("{}={}", p.path, p.bounds), &case))
        .collect::<Result<Vec<_>>>()?
        .into_iter()
        .unzip();
    let truth: Vec<f64> = study.params.iter().map(|p| p.truth).collect();
    let values: Vec<(&CasePath, f64)> = paths.iter().zip(truth.iter().copied()).collect();
    let mut truth_case = set_all(&case, &values)?;
    truth_case.name = truth_name(&case.name, &paths, &truth);
    let truth_dir = runs.join(&truth_case.name).join(study.fidelity.name());
    let stop = Arc::new(AtomicBool::new(false));
    match run_into(
        &truth_case,
        study.fidelity,
        &truth_dir,
        Reuse::SameCase,
        &ProgressBar::hidden(),
        &stop,
    ) {
        RunOutcome::Done(_) | RunOutcome::Skipped(_) | RunOutcome::Copied(..) => {}
        RunOutcome::Interrupted(_) => bail!("the truth run was interrupted"),
        RunOutcome::Elsewhere(holder) => bail!("the truth run is running elsewhere ({holder})"),
        RunOutcome::Unsupported(why) | RunOutcome::Failed(why) => {
            bail!("the truth run failed: {why}")
        }
    }
    let file = out.join("measurements.csv");
    std::fs::write(
        &file,
        measurements_from_run(&truth_dir, &study.measured, study.sigma, study.noise)?,
    )?;
    let measurements = Measurements::read(&file, None)?;
    let mut keys: Vec<String> = paths.iter().map(CasePath::key).collect();
    if keys.len() == 2 && keys[0] == keys[1] {
        keys = vec![format!("{}1", keys[0]), format!("{}2", keys[1])];
    }
    let model = CaseModel {
        base: &case,
        paths: &paths,
        keys,
        fidelity: study.fidelity,
        study: runs.to_path_buf(),
        root,
        measurements: &measurements,
        stop,
        progress: MultiProgress::with_draw_target(indicatif::ProgressDrawTarget::hidden()),
    };
    let calibration = calibrate(&params, &model, &study.settings)?;
    let range = range(&calibration);
    let info = landscape::StudyInfo {
        title: format!("{} truth {truth:?} at {}", case.name, study.fidelity),
        measurements: format!("{} ({})", file.display(), measurements.describe()),
        unit: measurements.unit(),
        sigma: measurements.sigma_source.clone(),
        points: measurements.kind.len(),
        command: "synthetic-truth recovery".into(),
        fields: paths.iter().map(CasePath::fields).collect(),
    };
    landscape::write_csv(&out.join("evaluations.csv"), &calibration)?;
    landscape::write_summary(out, &calibration, &range, &info)?;
    Ok(Recovered {
        truth,
        calibration,
        range,
    })
}

/// The truth run's name: the case's with `_truth` and each parameter's key and true value
/// (runs of several truths share a folder).
fn truth_name(case: &str, paths: &[CasePath], truth: &[f64]) -> String {
    let values: Vec<String> = paths
        .iter()
        .zip(truth)
        .map(|(p, t)| format!("{}={t}", p.key()))
        .collect();
    format!("{case}_truth_{}", values.join("_"))
}

#[cfg(test)]
mod tests {
    use super::super::scatter;
    use super::*;
    use runout_case::{BulkSeries, FrontTracker, Profile};

    fn root() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
    }

    fn settings(scan: usize, refine: usize, profile: usize) -> Settings {
        Settings {
            scan,
            refine,
            jobs: 2,
            xtol: 0.002,
            ftol: 0.05,
            profile,
            valley: 0,
        }
    }

    /// Family M's bulk series with laser gates at `gates` m from x = 0.5 (the block's front)
    /// and a profile station at (x, t), for the truth and every calibration run.
    fn stations(gates: Vec<f64>, (x, t): (f64, f64)) -> Monitors {
        Monitors {
            profiles: vec![Profile { x, times: vec![t] }],
            wall_probes: Vec::new(),
            front: Some(FrontTracker {
                threshold: 0.01,
                gate_origin: 0.5,
                gates,
                interval: 0.002,
            }),
            bulk: Some(BulkSeries {
                interval: 0.01,
                front_threshold: 0.01,
            }),
        }
    }

    /// Family M's specularity alone, from `bounds`, truth 0.3.
    fn specularity(bounds: &str) -> Vec<TrueParam> {
        vec![TrueParam {
            path: "specularity".into(),
            truth: 0.3,
            bounds: bounds.into(),
        }]
    }

    /// Family M's specularity and wall restitution (the Johnson–Jackson floor), truth
    /// (0.3, 0.7).
    fn specularity_and_wall_restitution(bounds: [&str; 2]) -> Vec<TrueParam> {
        vec![
            TrueParam {
                path: "specularity".into(),
                truth: 0.3,
                bounds: bounds[0].into(),
            },
            TrueParam {
                path: "wall_restitution".into(),
                truth: 0.7,
                bounds: bounds[1].into(),
            },
        ]
    }

    /// φ (truth 0.3) and the internal friction angle δ_int (truth 30°, the case's 35°).
    fn specularity_and_friction_angle(bounds: [&str; 2]) -> Vec<TrueParam> {
        vec![
            TrueParam {
                path: "specularity".into(),
                truth: 0.3,
                bounds: bounds[0].into(),
            },
            TrueParam {
                path: "solids[0].internal_friction_angle".into(),
                truth: 30.0,
                bounds: bounds[1].into(),
            },
        ]
    }

    /// A family-M truth study at smoke fidelity to 0.3 s.
    fn smoke(
        params: Vec<TrueParam>,
        monitors: Option<Monitors>,
        measured: Measured,
        sigma: f64,
        settings: Settings,
    ) -> TruthStudy {
        TruthStudy {
            case_file: "cases/mfix-slope/jj.ron".into(),
            params,
            monitors,
            fidelity: Fidelity::Smoke,
            end_time: Some(0.3),
            measured,
            sigma,
            noise: None,
            settings,
        }
    }

    /// Asserts that the range contains the truth and the optimum, per parameter.
    fn assert_recovered(r: &Recovered, what: &str) {
        println!(
            "{what}: truth {:?}, optimum {:?}, range {:?}, {} runs, model scatter {:?}",
            r.truth,
            r.optimum(),
            r.range.bounds,
            r.calibration.evaluations.len(),
            scatter::of(&r.calibration)
        );
        assert!(r.contains_truth().iter().all(|&c| c), "{what}");
        for (&(lo, hi), o) in r.range.bounds.iter().zip(r.optimum()) {
            assert!((lo..=hi).contains(o), "{what}");
        }
    }

    fn scratch(tag: &str) -> PathBuf {
        let dir =
            std::env::temp_dir().join(format!("runout-recovery-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// Family M's Johnson–Jackson specularity at smoke fidelity to 0.3 s: the truth φ = 0.3,
    /// its interpolated front at 0.1–0.28 s as the measurements with σ = 1 mm, calibrated
    /// from φ = 0.15: the stated range contains the truth and the optimum, and with σ =
    /// 0.5 mm (the same runs, reused, and two more for the edges) it is narrower and still
    /// contains the truth. (The smoke grid's front scatters by ~0.05–0.1 mm between nearby
    /// φ, so its χ² has shallow local minima near the truth and the optimum may miss it by
    /// up to ~15 %: a σ near that scatter would state a range that misses the truth.)
    /// About 12 smoke runs.
    #[test]
    fn smoke_truth_of_the_specularity_is_recovered_within_its_range() {
        let dir = scratch("smoke");
        let study = |sigma: f64| TruthStudy {
            case_file: "cases/mfix-slope/jj.ron".into(),
            params: vec![TrueParam {
                path: "specularity".into(),
                truth: 0.3,
                bounds: "0.1:0.5:0.15:log".into(),
            }],
            monitors: None,
            fidelity: Fidelity::Smoke,
            end_time: Some(0.3),
            measured: Measured::Front(vec![0.1, 0.15, 0.2, 0.25, 0.28]),
            sigma,
            noise: None,
            settings: settings(3, 4, 1),
        };
        let wide = recover(&root(), &study(1e-3), &dir).unwrap();
        let (lo, hi) = wide.range.bounds[0];
        println!("σ = 1 mm: optimum {:?}, range {lo}–{hi}", wide.optimum());
        assert_eq!(wide.contains_truth(), [true], "{lo}–{hi}");
        assert!((lo..=hi).contains(&wide.optimum()[0]));
        let narrow = recover(&root(), &study(5e-4), &dir).unwrap();
        let (nlo, nhi) = narrow.range.bounds[0];
        println!(
            "σ = 0.5 mm: optimum {:?}, range {nlo}–{nhi}",
            narrow.optimum()
        );
        assert_eq!(narrow.contains_truth(), [true], "{nlo}–{nhi}");
        assert!(nhi - nlo < hi - lo, "{nlo}–{nhi} against {lo}–{hi}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// Two parameters, the 2-D path: family M's Johnson–Jackson floor at smoke fidelity to
    /// 0.3 s, the truth (φ, e_w) = (0.3, 0.7), its interpolated front at 0.1–0.3 s with σ =
    /// 1 mm, a 3 × 3 scan of φ ∈ [0.1, 0.5] (log) × e_w ∈ [0.5, 0.95] and Nelder–Mead from the
    /// best scan cell: the region Δχ² ≤ 2.30 contains the truth. (The wall friction angle is
    /// the floor's third field, but the front hardly moves with it: 0.4 mm at 0.3 s from 11°
    /// to 20°, docs/reference/calibrate.md.) The region follows the valley of χ² (5 stations of its
    /// profile). About 20 smoke runs and up to 35 along the valley.
    #[test]
    fn smoke_truth_of_two_wall_parameters_is_recovered_within_its_region() {
        let dir = scratch("two");
        let study = smoke(
            specularity_and_wall_restitution(["0.1:0.5:0.15:log", "0.5:0.95:0.6"]),
            None,
            Measured::Front(vec![0.1, 0.15, 0.2, 0.25, 0.28, 0.3]),
            1e-3,
            Settings {
                valley: 5,
                ..settings(3, 10, 0)
            },
        );
        let r = recover(&root(), &study, &dir).unwrap();
        assert_recovered(&r, "φ, e_w from fronts, σ = 1 mm");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// Gate speeds: family M at smoke fidelity to 0.3 s with laser gates at x = 0.2, 0.3,
    /// 0.4 and 0.5 m (family M has none; the flume's smoke run ends at 0.4 s, before its
    /// first gate), the truth φ = 0.3, its four gate speeds with the flume's assumed σ =
    /// 0.3 m/s, calibrated from φ = 0.15: the range contains the truth. With the speed taken
    /// around the first sample past each gate (the run's `gates.csv`) the speeds scattered
    /// by ~1 m/s between neighbouring φ on this grid and the optimum went to 0.495; the
    /// speed interpolated at the crossing (`runout_post::gates::speed_at_gate`) is continuous
    /// in φ. But on this grid the speeds are not monotone in φ: at x = 1.0 m, 7.11, 7.55,
    /// 7.52, 7.64, 7.12 m/s for φ = 0.22, 0.26, 0.30, 0.32, 0.37 (cells of 0.1 m, the gates'
    /// spacing), so χ² has a narrow valley at 0.26–0.32 between higher ground at 0.22 and
    /// 0.37 (χ² 2.3, 3.3) and lower ground toward the bounds (1.6 at 0.1, 1.3 at 0.5); the
    /// three-point scan (0.1, 0.22, 0.5) brackets the wrong side. With MFIX's pooled momentum
    /// residual the refinement happened to land in the valley (χ² 0.03 at 0.25); with the
    /// residual per class of node (docs/model.md §4.11) the range came out 0.447–0.5 (issue
    /// 62: a valley the scan misses). About 10 smoke runs: `cargo test --release -p
    /// runout-study recovered_from_gate_speeds -- --ignored --nocapture`.
    #[test]
    #[ignore = "the smoke grid's gate speeds are not monotone in φ: the scan misses the valley (issue 62)"]
    fn smoke_truth_of_the_specularity_is_recovered_from_gate_speeds() {
        let dir = scratch("gates");
        let study = smoke(
            specularity("0.1:0.5:0.15:log"),
            Some(stations(vec![0.2, 0.3, 0.4, 0.5], (0.3, 0.2))),
            Measured::GateSpeeds,
            0.3,
            settings(3, 4, 1),
        );
        let r = recover(&root(), &study, &dir).unwrap();
        assert_recovered(&r, "φ from gate speeds, σ = 0.3 m/s");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A profile: family M at smoke fidelity, the truth φ = 0.3, its u_s against y at the
    /// station x = 0.3 m at t = 0.2 s where εs ≥ 0.001 (three cells at smoke) with σ =
    /// 0.01 m/s, calibrated from φ = 0.15: the range contains the truth. About 10 smoke runs.
    #[test]
    fn smoke_truth_of_the_specularity_is_recovered_from_a_profile() {
        let dir = scratch("profile");
        let study = smoke(
            specularity("0.1:0.5:0.15:log"),
            Some(stations(vec![0.2, 0.3, 0.4, 0.5], (0.3, 0.2))),
            Measured::Profile {
                file: "profile_x0.3_t0.2.csv".into(),
                column: "u_s".into(),
                min_eps_s: 1e-3,
            },
            0.01,
            settings(3, 4, 1),
        );
        let r = recover(&root(), &study, &dir).unwrap();
        assert_recovered(&r, "φ from a u_s profile, σ = 0.01 m/s");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// The table of docs/reference/calibrate.md: family M at coarse fidelity, several truths, one and
    /// two parameters, with and without noise. About 15 coarse runs (~20 s each on a quiet
    /// core) per row; `cargo test --release -p runout-study recovery_table -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn recovery_table() {
        let root = root();
        let times: Vec<f64> = (2..=10).map(|k| k as f64 / 10.0).collect();
        let one = |truth: f64, sigma: f64, noise: Option<u64>| TruthStudy {
            case_file: "cases/mfix-slope/jj.ron".into(),
            params: vec![TrueParam {
                path: "specularity".into(),
                truth,
                bounds: "0.01:1:0.05:log".into(),
            }],
            monitors: None,
            fidelity: Fidelity::Coarse,
            end_time: None,
            measured: Measured::Front(times.clone()),
            sigma,
            noise,
            settings: settings(5, 8, 2),
        };
        let rows: Vec<(String, TruthStudy)> = vec![
            ("phi0.3".into(), one(0.3, 0.005, None)),
            ("phi0.3".into(), one(0.3, 0.002, None)),
            ("phi0.3-noise".into(), one(0.3, 0.005, Some(1))),
            ("phi0.15".into(), one(0.15, 0.005, None)),
            ("phi0.15-noise".into(), one(0.15, 0.005, Some(2))),
        ];
        println!(
            "| truth | σ [mm] | noise | optimum | error | range Δχ² ≤ 1 | contains | runs | smooth response |"
        );
        for (tag, study) in rows {
            let dir = root.join("runs/calibrate/recovery").join(&tag);
            std::fs::create_dir_all(&dir).unwrap();
            let r = recover(&root, &study, &dir).unwrap();
            let (lo, hi) = r.range.bounds[0];
            let smooth = r.range.smooth.as_ref().map_or("none".into(), |s| {
                format!("{:.2} σ, {:.4}–{:.4}", s.scatter, s.bounds.0, s.bounds.1)
            });
            println!(
                "| {} | {} | {} | {:.4} | {:+.1} % | {lo:.4}–{hi:.4} | {} | {} | {smooth} |",
                r.truth[0],
                1e3 * study.sigma,
                study.noise.map_or("none".into(), |s| format!("seed {s}")),
                r.optimum()[0],
                100.0 * r.relative_error()[0],
                r.contains_truth()[0],
                r.calibration.evaluations.len()
            );
        }
    }

    /// One row of a coarse table: recovers `study` in runs/calibrate/recovery/`tag` (finished
    /// runs there reused) and prints it.
    fn table_row(tag: &str, study: &TruthStudy) {
        let root = root();
        let dir = root.join("runs/calibrate/recovery").join(tag);
        std::fs::create_dir_all(&dir).unwrap();
        let r = recover(&root, study, &dir).unwrap();
        let cells: Vec<String> = (0..r.truth.len())
            .map(|d| {
                let (lo, hi) = r.range.bounds[d];
                format!(
                    "{} | {:.4} | {:+.1} % | {lo:.4}–{hi:.4} | {}",
                    r.truth[d],
                    r.optimum()[d],
                    100.0 * r.relative_error()[d],
                    r.contains_truth()[d]
                )
            })
            .collect();
        let scatter = scatter::of(&r.calibration).map_or("none".into(), |s| {
            format!(
                "{:.2} σ ({} pairs, reliable: {})",
                s.ratio,
                s.pairs,
                s.reliable()
            )
        });
        let smooth = r.range.smooth.as_ref().map_or("none".into(), |s| {
            format!(
                "{:.2} σ, range {:.4}–{:.4}",
                s.scatter, s.bounds.0, s.bounds.1
            )
        });
        println!(
            "| {tag} | σ = {} | {} | {} runs | model scatter {scatter} | smooth response: {smooth} |",
            study.sigma,
            cells.join(" | "),
            r.calibration.evaluations.len()
        );
    }

    /// A family-M truth study at coarse fidelity.
    fn coarse(
        params: Vec<TrueParam>,
        monitors: Option<Monitors>,
        measured: Measured,
        sigma: f64,
        settings: Settings,
    ) -> TruthStudy {
        TruthStudy {
            fidelity: Fidelity::Coarse,
            end_time: None,
            ..smoke(params, monitors, measured, sigma, settings)
        }
    }

    /// The gate-speed and profile rows of docs/reference/calibrate.md: family M at coarse fidelity
    /// with gates at x = 1.0, 1.5, 2.0, 2.5 m and the u_s profile at x = 0.3 m, t = 0.3 s
    /// (εs ≥ 0.001), truth φ = 0.3, each with two σ (the runs shared in one folder). It
    /// prints the rows and asserts nothing: the gate-speed rows miss the truth (the gate
    /// speeds scatter by more than σ near it; docs/reference/calibrate.md);
    /// `cargo test --release -p runout-study recovery_table_stations -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn recovery_table_stations() {
        let profile = Measured::Profile {
            file: "profile_x0.3_t0.3.csv".into(),
            column: "u_s".into(),
            min_eps_s: 1e-3,
        };
        station_rows(&[(profile.clone(), 0.02), (profile, 0.01)]);
    }

    /// The gate-speed rows of docs/reference/calibrate.md (the speed at each gate interpolated from
    /// the front series, `runout_post::gates::speed_at_gate`): family M at coarse fidelity
    /// with gates at x = 0.5–2.0 m, the truth φ = 0.3, σ = 0.3 and 0.1 m/s; `cargo test
    /// --release -p runout-study recovery_table_gate_speeds -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn recovery_table_gate_speeds() {
        station_rows(&[(Measured::GateSpeeds, 0.3), (Measured::GateSpeeds, 0.1)]);
    }

    /// One table row per (measured, σ) of family M at coarse fidelity with the gates and the
    /// station of `recovery_table_stations`, the truth φ = 0.3 calibrated over 0.01–1.
    fn station_rows(rows: &[(Measured, f64)]) {
        let monitors = Some(stations(vec![0.5, 1.0, 1.5, 2.0], (0.3, 0.3)));
        let bounds = "0.01:1:0.05:log";
        for (measured, sigma) in rows {
            let study = coarse(
                specularity(bounds),
                monitors.clone(),
                measured.clone(),
                *sigma,
                settings(5, 8, 2),
            );
            table_row("stations", &study);
        }
    }

    /// The two-parameter row of docs/reference/calibrate.md: family M at coarse fidelity, truth
    /// (φ, e_w) = (0.3, 0.7), its fronts at 0.2–1.0 s with σ = 5 mm, a 3 × 3 scan,
    /// Nelder–Mead and 7 stations of the profile along the valley (φ and e_w trade off along
    /// a valley of the fronts' χ²: without the profile the region missed the truth,
    /// docs/reference/calibrate.md); `cargo test --release -p runout-study recovery_table_two_parameters --
    /// --ignored --nocapture`.
    #[test]
    #[ignore]
    fn recovery_table_two_parameters() {
        two_parameter_front_row(
            "phi0.3-ew0.7",
            specularity_and_wall_restitution(["0.05:1:0.1:log", "0.5:0.95:0.6"]),
        );
    }

    /// The second two-parameter row: (φ, δ_int) = (0.3, 30°) from the same fronts, to see
    /// whether the internal friction angle is a parameter the fronts separate from φ (e_w
    /// is not); `cargo test --release -p runout-study recovery_table_friction_angle --
    /// --ignored --nocapture`.
    #[test]
    #[ignore]
    fn recovery_table_friction_angle() {
        two_parameter_front_row(
            "phi0.3-dint30",
            specularity_and_friction_angle(["0.05:1:0.1:log", "20:45:35"]),
        );
    }

    /// A two-parameter row: family M at coarse fidelity, its fronts at 0.2–1.0 s with
    /// σ = 5 mm, a 3 × 3 scan, 12 Nelder–Mead steps and 7 stations along the valley.
    fn two_parameter_front_row(tag: &str, params: Vec<TrueParam>) {
        let times: Vec<f64> = (2..=10).map(|k| k as f64 / 10.0).collect();
        let study = coarse(
            params,
            None,
            Measured::Front(times),
            0.005,
            Settings {
                valley: 7,
                ..settings(3, 12, 0)
            },
        );
        table_row(tag, &study);
    }
}
