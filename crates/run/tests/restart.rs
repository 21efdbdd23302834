//! Checkpoint and restart (issue 21): a run stopped mid-way and restarted from its
//! checkpoint repeats the uninterrupted run bit for bit: the same monitor files, the same
//! field files, the same steps, rejected steps, outer iterations and Δt statistics.
//!
//! The case is the paper's Johnson–Jackson slide (S-JJ-phi, φ = 0.1) at smoke fidelity to
//! 0.3 s after the impact: it crosses the tilt on impact (the free-fall time, 0.286 s), has state-dependent wall closures
//! relaxed where they cycle, frozen dilute classes and the bulk, probe and profile
//! monitors, so every piece of carried-over state is exercised. Two interruptions:
//! - a stop request (what SIGINT/SIGTERM set) at step 60: the run writes a checkpoint and
//!   ends `Interrupted`;
//! - a kill: the same stop at step 110 with periodic checkpoints every 0.02 s, after which
//!   the checkpoint written on the stop is deleted, so the restart starts from the last
//!   periodic one and must cut back the files the "killed" run wrote after it.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use runout_case::{load, Case, Fidelity, Loaded};
use runout_output::{RunStatus, RunSummary};
use runout_run::{checkpoint, run_case_with, RunOptions};

fn slide() -> Case {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/sensitivity/S-JJ-phi.ron");
    let Loaded::Cases(cases) = load(&file).unwrap() else {
        panic!("a sweep")
    };
    let mut case = cases
        .into_iter()
        .find(|c| c.case.name == "S-JJ-phi_phi=0.1")
        .unwrap()
        .case;
    case.fidelity.smoke.end_time = 0.3;
    case.monitors.profiles[0].times = vec![0.1, 0.25];
    case.monitors.profiles[0].x = 5.5;
    case.run.output_interval = 0.02;
    case
}

fn folder(tag: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("runout-restart-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

/// Runs `case` into `dir`, setting the stop flag once `stop_at` steps were accepted.
fn run(case: &Case, dir: &Path, restart: bool, stop_at: Option<u64>) -> RunSummary {
    let stop = Arc::new(AtomicBool::new(false));
    let options = RunOptions {
        restart,
        stop: Some(stop.clone()),
        ..RunOptions::default()
    };
    run_case_with(case, Fidelity::Smoke, dir, &options, |p| {
        if stop_at.is_some_and(|n| p.steps >= n) {
            stop.store(true, Ordering::SeqCst);
        }
    })
    .unwrap()
}

/// Every file of a run folder except the summary (its wall time differs), the resolved
/// case (the killed run's names a checkpoint interval) and the checkpoints, by name.
fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .filter(|e| e.path().is_file())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n != "summary.json" && n != "resolved.ron")
        .map(|n| {
            let bytes = std::fs::read(dir.join(&n)).unwrap();
            (n, bytes)
        })
        .collect();
    out.sort();
    out
}

/// The checkpoint files of a run folder, oldest first.
fn checkpoint_files(run_dir: &Path) -> Vec<PathBuf> {
    let mut files: Vec<_> = std::fs::read_dir(run_dir.join(checkpoint::CHECKPOINT_DIR))
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .collect();
    files.sort();
    files
}

fn same_run(a: &RunSummary, b: &RunSummary) {
    assert_eq!(a.status, RunStatus::Completed);
    assert_eq!(b.status, RunStatus::Completed);
    assert_eq!(
        (a.steps, a.rejected_steps, a.outer_iterations),
        (b.steps, b.rejected_steps, b.outer_iterations)
    );
    assert_eq!(a.dt, b.dt);
    assert_eq!(a.simulated_time, b.simulated_time);
    assert_eq!(a.solids_mass_change, b.solids_mass_change);
    assert_eq!(a.max_eps_s, b.max_eps_s);
}

fn same_files(a: &Path, b: &Path) {
    let (fa, fb) = (files(a), files(b));
    let names = |f: &[(String, Vec<u8>)]| f.iter().map(|x| x.0.clone()).collect::<Vec<_>>();
    assert_eq!(names(&fa), names(&fb));
    for ((name, x), (_, y)) in fa.iter().zip(&fb) {
        assert!(x == y, "{name} differs between the runs");
    }
}

#[test]
fn a_stopped_or_killed_run_restarts_to_the_uninterrupted_result() {
    let case = slide();
    let whole = folder("whole");
    let uninterrupted = run(&case, &whole, false, None);
    assert!(uninterrupted.steps > 150, "{uninterrupted:?}");

    // stopped by a signal: a checkpoint and `Interrupted`, then a restart
    let stopped = folder("stopped");
    let first = run(&case, &stopped, false, Some(60));
    assert_eq!(first.status, RunStatus::Interrupted);
    assert_eq!(first.steps, 60);
    let summary: RunSummary =
        serde_json::from_str(&std::fs::read_to_string(stopped.join("summary.json")).unwrap())
            .unwrap();
    assert_eq!(summary.status, RunStatus::Interrupted);
    let restarted = run(&case, &stopped, true, None);
    same_run(&uninterrupted, &restarted);
    same_files(&whole, &stopped);
    let resolved = |d: &Path| std::fs::read_to_string(d.join("resolved.ron")).unwrap();
    assert_eq!(resolved(&whole), resolved(&stopped));

    // killed: the restart starts from an earlier periodic checkpoint
    let mut periodic = case.clone();
    periodic.run.checkpoint_interval = Some(0.02);
    let killed = folder("killed");
    let first = run(&periodic, &killed, false, Some(110));
    assert_eq!(first.status, RunStatus::Interrupted);
    let names = checkpoint_files(&killed);
    assert_eq!(names.len(), 2, "the newest two are kept");
    std::fs::remove_file(names.last().unwrap()).unwrap();
    let restarted = run(&periodic, &killed, true, None);
    same_run(&uninterrupted, &restarted);
    same_files(&whole, &killed);

    // a checkpoint of another case is refused with the reason
    let mut other = periodic.clone();
    other.solids[0].diameter *= 2.0;
    let options = RunOptions {
        restart: true,
        ..RunOptions::default()
    };
    let err = run_case_with(&other, Fidelity::Smoke, &killed, &options, |_| {}).unwrap_err();
    assert!(err.to_string().contains("another case"), "{err}");
    // a fresh run into a folder holding a run is refused unless it replaces it
    let err = run_case_with(
        &case,
        Fidelity::Smoke,
        &killed,
        &RunOptions::default(),
        |_| {},
    )
    .unwrap_err();
    assert!(err.to_string().contains("--restart"), "{err}");
    for dir in [whole, stopped, killed] {
        let _ = std::fs::remove_dir_all(dir);
    }
}

/// A checkpoint of another format version or another runout version is refused, naming
/// which; a damaged newest checkpoint falls back to the one before.
#[test]
fn checkpoints_of_another_version_are_refused_and_damaged_ones_skipped() {
    let mut case = slide();
    case.run.checkpoint_interval = Some(0.002);
    let dir = folder("versions");
    let first = run(&case, &dir, false, Some(12));
    assert_eq!(first.status, RunStatus::Interrupted);
    let files = checkpoint_files(&dir);
    let newest = files.last().unwrap().clone();
    let original = std::fs::read(&newest).unwrap();
    let restart = |dir: &Path| {
        let options = RunOptions {
            restart: true,
            ..RunOptions::default()
        };
        run_case_with(&case, Fidelity::Smoke, dir, &options, |_| {})
    };
    // the writer's runout version, as stored (postcard: its length, then its bytes)
    let version = checkpoint::SOLVER_VERSION.as_bytes();
    let at = original
        .windows(version.len())
        .position(|w| w == version)
        .expect("the version is stored");
    assert!(checkpoint::of_this_version(&dir));
    let mut other = original.clone();
    other[at..at + version.len()].copy_from_slice(&b"9.9.99999"[..version.len()]);
    std::fs::write(&newest, &other).unwrap();
    let err = restart(&dir).unwrap_err().to_string();
    assert!(err.contains("written by runout 9.9"), "{err}");
    // the bench's test of a kept checkpoint (xtask bench two-fluid): not this version
    assert!(!checkpoint::of_this_version(&dir));
    assert!(!checkpoint::of_this_version(&dir.join("no such run")));
    // another format version
    let mut other = original.clone();
    other[16] = other[16].wrapping_add(1);
    std::fs::write(&newest, &other).unwrap();
    for path in &files[..files.len() - 1] {
        std::fs::remove_file(path).unwrap();
    }
    let err = restart(&dir).unwrap_err().to_string();
    assert!(err.contains("checkpoint format"), "{err}");
    // damaged (truncated) newest with an intact one before it: the restart uses the older
    std::fs::write(&newest, &original).unwrap();
    let again = run(&case, &dir, true, Some(20));
    assert_eq!(again.status, RunStatus::Interrupted);
    let files = checkpoint_files(&dir);
    let newest = files.last().unwrap();
    let bytes = std::fs::read(newest).unwrap();
    std::fs::write(newest, &bytes[..bytes.len() / 2]).unwrap();
    let done = run(&case, &dir, true, None);
    assert_eq!(done.status, RunStatus::Completed);
    let _ = std::fs::remove_dir_all(dir);
}

/// A restart after the tilt keeps a bent floor (docs/model.md §9): the checkpoint holds only
/// whether the tilt is pending, and the bend comes back with it. The slide's floor turns
/// flat 0.1 m past the block (arc R = 0.5 m), so the bend acts from the tilt on; stopped at
/// t = 0.40 s (after the tilt at the free-fall time 0.286 s; the run ends 0.3 s after it)
/// and restarted, the run ends bit for bit as the uninterrupted one.
#[test]
fn a_restart_after_the_tilt_keeps_the_bent_floor() {
    let mut case = slide();
    case.bed = runout_case::Bed::Bend {
        at: 5.6,
        radius: 0.5,
        slope_after: 0.0,
    };
    runout_case::validate_case(&case).unwrap();
    let run_to = |dir: &Path, restart: bool, stop_time: Option<f64>| {
        let stop = Arc::new(AtomicBool::new(false));
        let options = RunOptions {
            restart,
            stop: Some(stop.clone()),
            ..RunOptions::default()
        };
        run_case_with(&case, Fidelity::Smoke, dir, &options, |p| {
            if stop_time.is_some_and(|t| p.time >= t) {
                stop.store(true, Ordering::SeqCst);
            }
        })
        .unwrap()
    };
    let whole = folder("bend-whole");
    let uninterrupted = run_to(&whole, false, None);
    let stopped = folder("bend-stopped");
    assert_eq!(
        run_to(&stopped, false, Some(0.40)).status,
        RunStatus::Interrupted
    );
    let restarted = run_to(&stopped, true, None);
    same_run(&uninterrupted, &restarted);
    same_files(&whole, &stopped);
    // and the bend changed the flow: the plane slide's files differ
    let plane = folder("bend-plane");
    run(&slide(), &plane, false, None);
    assert_ne!(files(&whole), files(&plane));
    for dir in [whole, stopped, plane] {
        let _ = std::fs::remove_dir_all(dir);
    }
}
