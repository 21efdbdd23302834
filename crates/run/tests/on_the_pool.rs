//! A run executes on a thread of the current rayon pool, not on the calling thread
//! (`runout_run::on_the_pool`; docs/history/performance-log.md, "Two threads: the drag
//! elimination's components, the multigrid's coarse lines" and "Runs at once on pools of
//! their own"): the caller waits while the solver's serial stages run on a pool thread.

use std::path::Path;
use std::sync::Mutex;

use runout_case::{load, Fidelity, Loaded};
use runout_run::run_case;

#[test]
fn a_run_called_from_outside_the_pool_steps_on_a_pool_thread() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/cavity-re100.ron");
    let Loaded::Cases(cases) = load(&path).unwrap() else {
        panic!("cases")
    };
    let out = std::env::temp_dir().join(format!("runout-on-pool-{}", std::process::id()));
    let caller = std::thread::current().id();
    let seen = Mutex::new(Vec::new());
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    // the caller is this test's thread, outside `pool`; the run is in `pool` by `install`
    // only for the second call
    for inside in [false, true] {
        let run = || {
            run_case(&cases[0].case, Fidelity::Smoke, &out, |_| {
                let t = std::thread::current().id();
                seen.lock()
                    .unwrap()
                    .push((inside, t != caller, rayon::current_thread_index()));
            })
            .unwrap()
        };
        let summary = if inside { pool.install(run) } else { run() };
        assert!(summary.steps > 0);
    }
    let seen = seen.into_inner().unwrap();
    assert!(!seen.is_empty());
    for (inside, off_caller, index) in seen {
        assert!(
            off_caller,
            "a step ran on the calling thread (installed: {inside})"
        );
        assert!(index.is_some(), "a step ran outside a rayon pool");
    }
    let _ = std::fs::remove_dir_all(&out);
}
