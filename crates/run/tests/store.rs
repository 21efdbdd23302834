//! The run store (`runout_run::store`): a run is written into `.partial` and moved into its
//! folder when it ends; a finished run is reused only for the same resolved case; an
//! interrupted run keeps its checkpoint and is continued by the next request.

use std::path::Path;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use runout_case::{load, Case, Fidelity, Loaded};
use runout_output::RunStatus;
use runout_run::store::{self, Request, Reuse, Stored};

fn cavity() -> Case {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/cavity-re100.ron");
    let Loaded::Cases(cases) = load(&file).unwrap() else {
        panic!("a case")
    };
    cases[0].case.clone()
}

#[test]
fn a_finished_run_is_reused_only_for_the_same_case() {
    let root = std::env::temp_dir().join(format!("runout-store-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let done = root.join("smoke");
    let case = cavity();
    let request = Request::default();

    let first = store::obtain(&done, &case, Fidelity::Smoke, &request, |_| {}).unwrap();
    assert!(matches!(first, Stored::Ran(_)), "{first:?}");
    assert!(done.join("summary.json").exists());
    assert!(!store::partial_dir(&done).exists());

    let again = store::obtain(&done, &case, Fidelity::Smoke, &request, |_| {}).unwrap();
    assert!(matches!(again, Stored::Reused(_)), "{again:?}");
    assert_eq!(again.summary().steps, first.summary().steps);

    // another lid speed is another case: run again, replacing the folder
    let mut other = case.clone();
    other.description.push_str(" (changed)");
    other.run.end_time *= 0.5;
    let changed = store::obtain(&done, &other, Fidelity::Smoke, &request, |_| {}).unwrap();
    assert!(matches!(changed, Stored::Ran(_)), "{changed:?}");

    // `AnyFinished` takes whatever finished run is there; `Never` runs again
    let any = Request {
        reuse: Reuse::AnyFinished,
        ..Request::default()
    };
    let taken = store::obtain(&done, &case, Fidelity::Smoke, &any, |_| {}).unwrap();
    assert!(matches!(taken, Stored::Reused(_)), "{taken:?}");
    let never = Request {
        reuse: Reuse::Never,
        ..Request::default()
    };
    let made = store::obtain(&done, &case, Fidelity::Smoke, &never, |_| {}).unwrap();
    assert!(matches!(made, Stored::Ran(_)), "{made:?}");
    std::fs::remove_dir_all(&root).unwrap();
}

#[test]
fn an_interrupted_run_keeps_its_partial_folder_and_is_continued() {
    let root = std::env::temp_dir().join(format!("runout-store-int-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let done = root.join("smoke");
    let case = cavity();
    let stop = Arc::new(AtomicBool::new(false));
    let request = Request {
        stop: Some(stop.clone()),
        ..Request::default()
    };
    // stop after the first accepted step
    let interrupted = store::obtain(&done, &case, Fidelity::Smoke, &request, |_| {
        stop.store(true, std::sync::atomic::Ordering::SeqCst)
    })
    .unwrap();
    let Stored::Interrupted(at) = &interrupted else {
        panic!("{interrupted:?}")
    };
    assert_eq!(at.status, RunStatus::Interrupted);
    assert!(!done.exists());
    assert!(runout_run::checkpoint::exists(&store::partial_dir(&done)));

    stop.store(false, std::sync::atomic::Ordering::SeqCst);
    let resumed = store::obtain(&done, &case, Fidelity::Smoke, &request, |_| {}).unwrap();
    let Stored::Ran(summary) = &resumed else {
        panic!("{resumed:?}")
    };
    assert_eq!(summary.status, RunStatus::Completed);
    // the continued run is the uninterrupted one, step for step
    let whole = store::obtain(
        &root.join("whole"),
        &case,
        Fidelity::Smoke,
        &Request::default(),
        |_| {},
    )
    .unwrap();
    assert_eq!(summary.steps, whole.summary().steps);
    assert_eq!(summary.simulated_time, whole.summary().simulated_time);
    std::fs::remove_dir_all(&root).unwrap();
}
