//! The time loop with a stand-in solver whose steps fail on demand: a solver error (a
//! failed linear solve) is retried with a smaller Δt, and a step cut to land on the end
//! time shrinks when it fails instead of being retried unchanged (issue 21).

use std::path::{Path, PathBuf};

use runout_case::{load, Case, Fidelity, Loaded, RunControl};
use runout_mesh::Grid;
use runout_output::{OutputError, PvdSeries, RunStatus};

use crate::case_solver::{CaseSolver, StepReport};
use crate::{run_solver, RunError, RunOptions};
use runout_solver::state::{SolverState, StateError};

/// A solver whose step errors while the step is longer than `largest_good_dt` or for
/// its first `errors` attempts; otherwise it converges in 3 iterations.
struct Flaky {
    grid: Grid,
    errors: usize,
    largest_good_dt: f64,
    attempts: usize,
}

impl CaseSolver for Flaky {
    fn step(&mut self, dt: f64, _run: &RunControl) -> Result<StepReport, RunError> {
        self.attempts += 1;
        if self.attempts <= self.errors {
            return Err(RunError::Unsupported {
                case: String::new(),
                reason: "singular matrix: multigrid line pivot 0".into(),
            });
        }
        Ok(StepReport {
            converged: dt <= self.largest_good_dt,
            iterations: 3,
            residual: 0.0,
            detail: String::new(),
        })
    }
    fn restore(&mut self) {}
    fn write_fields(&mut self, _: &mut PvdSeries, _: f64) -> Result<(), OutputError> {
        Ok(())
    }
    fn profile_header(&self) -> &'static [&'static str] {
        &["y"]
    }
    fn profile(&self, _x: f64, y: f64) -> Vec<f64> {
        vec![y]
    }
    fn grid(&self) -> &Grid {
        &self.grid
    }
    fn mass_imbalance_ratio(&self) -> f64 {
        0.0
    }
    fn save_state(&self) -> SolverState {
        SolverState::default()
    }
    fn load_state(&mut self, _: &SolverState) -> Result<(), StateError> {
        Ok(())
    }
}

fn cavity(end_time: f64) -> Case {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/cavity-re100.ron");
    let Loaded::Cases(cases) = load(&file).unwrap() else {
        panic!("a case")
    };
    let mut case = cases
        .into_iter()
        .next()
        .unwrap()
        .case
        .at_fidelity(Fidelity::Smoke);
    case.run.end_time = end_time;
    case.monitors.profiles.clear();
    case
}

fn folder(tag: &str) -> PathBuf {
    std::env::temp_dir().join(format!("runout-loop-{tag}-{}", std::process::id()))
}

fn run(case: &Case, solver: &mut Flaky, tag: &str) -> runout_output::RunSummary {
    let options = RunOptions {
        replace: true,
        ..RunOptions::default()
    };
    let dir = folder(tag);
    let summary = run_solver(case, Fidelity::Smoke, &dir, &options, solver, &mut |_| {}).unwrap();
    let _ = std::fs::remove_dir_all(dir);
    summary
}

#[test]
fn a_solver_error_is_a_failed_step_retried_with_a_smaller_dt() {
    let case = cavity(0.05);
    let mut solver = Flaky {
        grid: case.grid().unwrap(),
        errors: 2,
        largest_good_dt: f64::INFINITY,
        attempts: 0,
    };
    let s = run(&case, &mut solver, "error");
    assert_eq!(s.status, RunStatus::Completed);
    assert_eq!(s.rejected_steps, 2);
    // a step undone by a solver error reports no outer iterations
    assert_eq!(s.rejected_outer_iterations, 0);
    // the first accepted step ran at dt_initial × 0.9² (the smallest of the run)
    assert!((s.dt.min - 0.01 * 0.9 * 0.9).abs() < 1e-15, "{:?}", s.dt);
}

#[test]
fn a_step_cut_to_the_end_time_shrinks_when_it_fails() {
    // end time 1e-9 s, far below dt_initial = 0.01 s: the step is cut to 1e-9 s; it
    // converges only at ≤ 5e-10 s, reached by one halving... of the cut step, not of 0.01
    let mut case = cavity(1e-9);
    case.run.dt.min = 1e-12;
    case.run.dt.failure_factor = Some(0.5);
    let mut solver = Flaky {
        grid: case.grid().unwrap(),
        errors: 0,
        largest_good_dt: 5e-10,
        attempts: 0,
    };
    let s = run(&case, &mut solver, "cut");
    assert_eq!(s.status, RunStatus::Completed);
    assert_eq!(
        s.rejected_steps, 1,
        "one retry, not one per halving of 0.01 s"
    );
    // the rejected step's 3 outer iterations are counted apart from the accepted ones
    assert_eq!(s.rejected_outer_iterations, 3);
    assert_eq!(s.outer_iterations, 3 * s.steps);
    // a solver that never converges stops after the retries of the cut step alone
    let mut never = Flaky {
        grid: case.grid().unwrap(),
        errors: 0,
        largest_good_dt: 0.0,
        attempts: 0,
    };
    case.run.dt.min = 2e-10;
    let s = run(&case, &mut never, "never");
    assert!(
        matches!(s.status, RunStatus::Diverged { .. }),
        "{:?}",
        s.status
    );
    assert_eq!(s.rejected_steps, 3, "1e-9 → 5e-10 → 2.5e-10 → below dt_min");
}

/// `run.stop_at_rest`: the still stretch starts at the first slow step, restarts when the
/// front moves or the speed rises, and ends the run once it has lasted the duration.
#[test]
fn rest_watch_counts_one_still_stretch() {
    let rule = runout_case::StopAtRest {
        speed: 0.01,
        duration: 0.1,
        front_threshold: 0.01,
    };
    let mut watch = crate::RestWatch::default();
    assert!(!watch.at_rest_after(Some((0.3, 0.5)), 0.0, &rule));
    assert!(!watch.at_rest_after(Some((0.3, 0.005)), 0.1, &rule));
    assert!(!watch.at_rest_after(Some((0.35, 0.005)), 0.15, &rule)); // the front moved
    assert!(!watch.at_rest_after(Some((0.35, 0.005)), 0.2, &rule));
    assert!(!watch.at_rest_after(None, 0.22, &rule)); // no solids: no rest
    assert!(!watch.at_rest_after(Some((0.35, 0.005)), 0.25, &rule));
    assert!(watch.at_rest_after(Some((0.35, 0.001)), 0.35, &rule));
}

/// A μ(I) column at smoke size with a generous rest rule (mean u_s ≤ 0.2 m/s and a still
/// front for 0.02 s: its front moves a 1 cm cell about every 0.03 s after 0.2 s) ends before
/// its end time (issue 43 item 4).
#[test]
fn a_run_at_rest_ends_itself() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let Loaded::Cases(cases) = load(&root.join("cases/collapse/CM-a1.ron")).unwrap() else {
        panic!("CM-a1.ron is a case file")
    };
    let mut case = cases[0].case.clone();
    case.fidelity.smoke.end_time = 0.5;
    case.run.stop_at_rest = Some(runout_case::StopAtRest {
        speed: 0.2,
        duration: 0.02,
        front_threshold: 0.01,
    });
    let dir = std::env::temp_dir().join(format!("runout-rest-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let summary = crate::run_case(&case, Fidelity::Smoke, &dir, |_| {}).unwrap();
    assert_eq!(summary.status, RunStatus::Completed);
    assert!(summary.simulated_time < 0.45, "{}", summary.simulated_time);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A block falling before its tilt on impact (the family-FS slide at smoke size: free fall
/// until 0.286 s) has no u_s and no front, but is not at rest: with a rest rule that a still
/// 0.05 s would satisfy, the run goes past the tilt (it stopped at 0.2 s before the rule
/// waited for the tilt).
#[test]
fn a_falling_block_is_not_at_rest() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut case = runout_case::load_case(&root.join("cases/foot/mu-i/base.ron")).unwrap();
    case.fidelity.smoke.end_time = 0.35;
    case.run.stop_at_rest = Some(runout_case::StopAtRest {
        speed: 0.014,
        duration: 0.05,
        front_threshold: 0.01,
    });
    let dir = std::env::temp_dir().join(format!("runout-fall-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let summary = crate::run_case(&case, Fidelity::Smoke, &dir, |_| {}).unwrap();
    assert_eq!(summary.status, RunStatus::Completed);
    assert!(summary.simulated_time > 0.3, "{}", summary.simulated_time);
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A pile at rest behind its gate is not at rest for `run.stop_at_rest` until the gate has
/// opened (cases/slopes/gated-pile.ron at smoke size, its gate removed at 0.1 s: with a rule a
/// still 0.05 s satisfies, the run stopped at 0.05 s before the rule waited for the gate).
#[test]
fn a_pile_behind_its_gate_is_not_at_rest() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut case = runout_case::load_case(&root.join("cases/slopes/gated-pile.ron")).unwrap();
    case.fidelity.smoke.end_time = 0.15;
    case.run.stop_at_rest = Some(runout_case::StopAtRest {
        speed: 0.005,
        duration: 0.05,
        front_threshold: 0.01,
    });
    let dir = std::env::temp_dir().join(format!("runout-gate-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let summary = crate::run_case(&case, Fidelity::Smoke, &dir, |_| {}).unwrap();
    assert_eq!(summary.status, RunStatus::Completed);
    assert!(summary.simulated_time > 0.14, "{}", summary.simulated_time);
    std::fs::remove_dir_all(&dir).unwrap();
}
