//! One writer per run folder (issue 44): sweeps, `--overwrite` runs and restarts of the same
//! run folder at once end with one complete run folder and one summary row per case; a
//! holder killed with SIGKILL leaves its case to the next sweep; a damaged folder is run
//! again.
//!
//! Each test sweeps a temporary root (`XTASK_ROOT`) holding a small cavity case (32 × 32
//! cells to 1 s, about 2 s). A sweep is frozen (SIGSTOP) while it holds its run's lock, so
//! the second writer meets a running run however fast the machine; a run in this process
//! is held in its first step's progress callback likewise.

use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use runout_case::{load, Case, Fidelity, Loaded};
use runout_output::RunStatus;
use runout_run::lock::RunLock;
use runout_run::store::{self, Request, Stored};
use runout_run::{run_case_with, RunError, RunOptions};

/// A temporary root with `cases/` (the cavity as `tiny`, and `tiny-b` with half the lid
/// speed), removed on drop.
struct Root(PathBuf);

impl Root {
    fn new(test: &str) -> Root {
        let dir =
            std::env::temp_dir().join(format!("runout-one-writer-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("cases")).unwrap();
        let cavity = std::fs::read_to_string(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/cavity-re100.ron"),
        )
        .unwrap()
        .replace(
            "smoke: (coarsen: 4, end_time: 1.0)",
            "smoke: (coarsen: 2, end_time: 1.0)",
        );
        let tiny = cavity.replace("name: \"cavity-re100\"", "name: \"tiny\"");
        let tiny_b = cavity
            .replace("name: \"cavity-re100\"", "name: \"tiny-b\"")
            .replace("Moving(u_w: 1.0)", "Moving(u_w: 0.5)");
        std::fs::write(dir.join("cases/tiny.ron"), tiny).unwrap();
        std::fs::write(dir.join("cases/tiny-b.ron"), tiny_b).unwrap();
        Root(dir)
    }

    fn done(&self, case: &str) -> PathBuf {
        self.0.join("runs").join(case).join("smoke")
    }

    fn case(&self, name: &str) -> Case {
        let Loaded::Cases(cases) = load(&self.0.join(format!("cases/{name}.ron"))).unwrap() else {
            panic!("a case")
        };
        cases[0].case.clone()
    }

    /// Starts `cargo xtask sweep --fidelity smoke` over this root's cases with `args`; its
    /// output goes to `<root>/<tag>.out`.
    fn sweep(&self, tag: &str, args: &[&str]) -> Child {
        let out = File::create(self.0.join(format!("{tag}.out"))).unwrap();
        Command::new(env!("CARGO_BIN_EXE_xtask"))
            .args(["sweep", "--fidelity", "smoke", "--cases"])
            .arg(self.0.join("cases"))
            .args(args)
            .env("XTASK_ROOT", &self.0)
            .env("RUST_BACKTRACE", "0")
            .stdout(Stdio::from(out.try_clone().unwrap()))
            .stderr(Stdio::from(out))
            .spawn()
            .unwrap()
    }

    /// Runs a sweep to its end: its exit status and output.
    fn sweep_to_end(&self, tag: &str, args: &[&str]) -> (ExitStatus, String) {
        let status = self.sweep(tag, args).wait().unwrap();
        (status, self.output(tag))
    }

    fn output(&self, tag: &str) -> String {
        std::fs::read_to_string(self.0.join(format!("{tag}.out"))).unwrap()
    }

    /// The rows of `case` in results/summary.csv.
    fn rows(&self, case: &str) -> usize {
        std::fs::read_to_string(self.0.join("results/summary.csv"))
            .unwrap_or_default()
            .lines()
            .filter(|l| l.starts_with(&format!("{case},")))
            .count()
    }

    /// Asserts that `case` has one complete, finished run folder and no `.partial` one:
    /// its summary reads, lists every file of the folder and the folder holds them all.
    fn assert_complete(&self, case: &str) {
        let done = self.done(case);
        let summary = runout_post::folder::read_summary(&done)
            .unwrap_or_else(|| panic!("{}: no summary", done.display()))
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(summary.status, RunStatus::Completed, "{case}");
        let mut listed: Vec<_> = summary.files.iter().map(|f| f.name.clone()).collect();
        listed.push("summary.json".into());
        listed.sort();
        let mut present: Vec<_> = std::fs::read_dir(&done)
            .unwrap()
            .flatten()
            .filter(|e| e.path().is_file())
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect();
        present.sort();
        assert_eq!(
            listed, present,
            "{case}: the files listed are the files there"
        );
        // the cavity at smoke: resolved.ron, fields.pvd and its 2 .vtr files
        assert!(listed.len() >= 5, "{case}: {listed:?}");
        assert!(
            !store::partial_dir(&done).exists(),
            "{case}: a .partial left"
        );
    }
}

impl Drop for Root {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn signal(child: &Child, sig: &str) {
    let ok = Command::new("kill")
        .args([sig, &child.id().to_string()])
        .status()
        .unwrap()
        .success();
    assert!(ok, "kill {sig}");
}

/// Waits until `child` holds the lock of `dir`'s run (its pid is in the lock file and the
/// lock is taken), then freezes it with SIGSTOP.
fn freeze_holding(child: &Child, dir: &Path) {
    let lock = runout_run::lock::lock_path(dir).unwrap();
    let pid = format!("pid {} ", child.id());
    let start = Instant::now();
    while !std::fs::read_to_string(&lock).is_ok_and(|t| t.starts_with(&pid)) {
        assert!(start.elapsed() < Duration::from_secs(120), "no lock taken");
        std::thread::sleep(Duration::from_millis(2));
    }
    signal(child, "-STOP");
    match RunLock::acquire(dir) {
        Err(RunError::Running { .. }) => {}
        other => panic!("the sweep ended before it was frozen: {other:?}"),
    }
}

/// Runs `case` into `dir` in this process, held in its first step until `release` gets a
/// message; `started` gets one when it holds the folder.
fn held_run(
    case: Case,
    dir: PathBuf,
    options: RunOptions,
) -> (
    std::thread::JoinHandle<Result<runout_output::RunSummary, RunError>>,
    mpsc::Receiver<()>,
    mpsc::Sender<()>,
) {
    let (started_tx, started) = mpsc::channel();
    let (release, release_rx) = mpsc::channel::<()>();
    let handle = std::thread::spawn(move || {
        let mut first = true;
        run_case_with(&case, Fidelity::Smoke, &dir, &options, move |_| {
            if std::mem::take(&mut first) {
                started_tx.send(()).unwrap();
                release_rx.recv().unwrap();
            }
        })
    });
    (handle, started, release)
}

#[test]
fn two_sweeps_of_one_case_at_once_leave_one_complete_run_and_one_row() {
    let root = Root::new("two-sweeps");
    let first = root.sweep("first", &["--only", "tiny-b"]);
    freeze_holding(&first, &root.done("tiny-b"));
    let (status, out) = root.sweep_to_end("second", &["--only", "tiny-b"]);
    let pid = format!("running elsewhere (pid {} on host ", first.id());
    assert!(!status.success() && out.contains(&pid), "{out}");
    assert_eq!(
        root.rows("tiny-b"),
        0,
        "the second sweep leaves the row alone"
    );
    signal(&first, "-CONT");
    let mut first = first;
    assert!(first.wait().unwrap().success(), "{}", root.output("first"));
    root.assert_complete("tiny-b");
    assert_eq!(root.rows("tiny-b"), 1);
    // the other order: a sweep after the first ended takes its finished run
    let (status, out) = root.sweep_to_end("third", &["--only", "tiny-b"]);
    assert!(status.success() && out.contains("skipped 1"), "{out}");
    root.assert_complete("tiny-b");
    assert_eq!(root.rows("tiny-b"), 1);
}

#[test]
fn an_overwrite_run_and_a_sweep_of_one_folder_exclude_each_other_both_ways() {
    let root = Root::new("overwrite");
    let done = root.done("tiny-b");
    let replace = RunOptions {
        replace: true,
        ..RunOptions::default()
    };
    // a sweep runs: `runout run --overwrite` into its folder, or into its .partial, is refused
    let sweep = root.sweep("sweep", &["--only", "tiny-b"]);
    freeze_holding(&sweep, &done);
    for dir in [done.clone(), store::partial_dir(&done)] {
        let err = run_case_with(
            &root.case("tiny-b"),
            Fidelity::Smoke,
            &dir,
            &replace,
            |_| {},
        )
        .unwrap_err();
        let text = err.to_string();
        assert!(matches!(err, RunError::Running { .. }), "{text}");
        assert!(
            text.contains("is running") && !text.contains("earlier run"),
            "{text}"
        );
    }
    signal(&sweep, "-CONT");
    let mut sweep = sweep;
    assert!(sweep.wait().unwrap().success(), "{}", root.output("sweep"));
    root.assert_complete("tiny-b");
    assert_eq!(root.rows("tiny-b"), 1);

    // `runout run --overwrite` runs in the finished folder: a sweep leaves it alone
    let (run, started, release) = held_run(root.case("tiny-b"), done.clone(), replace);
    started.recv().unwrap();
    let (status, out) = root.sweep_to_end("beside", &["--only", "tiny-b"]);
    assert!(
        !status.success() && out.contains("running elsewhere (pid"),
        "{out}"
    );
    release.send(()).unwrap();
    let summary = run.join().unwrap().unwrap();
    assert_eq!(summary.status, RunStatus::Completed);
    root.assert_complete("tiny-b");
    assert_eq!(root.rows("tiny-b"), 1);
}

#[test]
fn a_sweep_beside_a_restart_of_its_folder_leaves_it_alone() {
    let root = Root::new("restart");
    let done = root.done("tiny");
    // an interrupted sweep run: a checkpoint in runs/tiny/smoke.partial
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let request = Request {
        stop: Some(stop.clone()),
        ..Request::default()
    };
    let stored = store::obtain(&done, &root.case("tiny"), Fidelity::Smoke, &request, |p| {
        if p.steps >= 5 {
            stop.store(true, std::sync::atomic::Ordering::SeqCst);
        }
    })
    .unwrap();
    assert!(matches!(stored, Stored::Interrupted(_)), "{stored:?}");
    let partial = store::partial_dir(&done);
    // `runout run --restart runs/tiny/smoke.partial`, held in its first step
    let restart = RunOptions {
        restart: true,
        ..RunOptions::default()
    };
    let (run, started, release) = held_run(root.case("tiny"), partial.clone(), restart);
    if started.recv().is_err() {
        panic!("the restart did not start: {:?}", run.join());
    }
    let (status, out) = root.sweep_to_end("beside", &["--only", "tiny"]);
    assert!(
        !status.success() && out.contains("running elsewhere (pid"),
        "{out}"
    );
    assert!(!done.exists(), "the sweep made no folder");
    assert_eq!(root.rows("tiny"), 0);
    release.send(()).unwrap();
    assert_eq!(run.join().unwrap().unwrap().status, RunStatus::Completed);
    // the next sweep moves the continued run into place
    let (status, out) = root.sweep_to_end("after", &["--only", "tiny"]);
    assert!(status.success(), "{out}");
    root.assert_complete("tiny");
    assert_eq!(root.rows("tiny"), 1);
}

#[test]
fn two_overlapping_shards_run_each_case_once() {
    let root = Root::new("shards");
    let whole = root.sweep("whole", &["--jobs", "1", "--shard", "1/1"]);
    // freeze the whole matrix's sweep in whichever case it runs first
    let lock_of = |case: &str| runout_run::lock::lock_path(&root.done(case)).unwrap();
    let pid = format!("pid {} ", whole.id());
    let start = Instant::now();
    let held = loop {
        if let Some(case) = ["tiny", "tiny-b"]
            .into_iter()
            .find(|c| std::fs::read_to_string(lock_of(c)).is_ok_and(|t| t.starts_with(&pid)))
        {
            break case;
        }
        assert!(start.elapsed() < Duration::from_secs(120), "no lock taken");
        std::thread::sleep(Duration::from_millis(2));
    };
    freeze_holding(&whole, &root.done(held));
    // the other shard runs the case it is given if it is free, and skips it if held
    let (_, out) = root.sweep_to_end("half", &["--jobs", "1", "--shard", "2/2"]);
    signal(&whole, "-CONT");
    let mut whole = whole;
    assert!(whole.wait().unwrap().success(), "{}", root.output("whole"));
    for case in ["tiny", "tiny-b"] {
        root.assert_complete(case);
        assert_eq!(root.rows(case), 1, "{case}\n{out}");
    }
    let ran = |text: &str| text.matches("Completed, ").count();
    assert_eq!(
        ran(&out) + ran(&root.output("whole")),
        2,
        "each case ran once:\n{out}\n{}",
        root.output("whole")
    );
}

#[test]
fn a_sweep_killed_while_running_leaves_its_case_to_the_next() {
    let root = Root::new("killed");
    let mut killed = root.sweep("killed", &["--only", "tiny-b"]);
    freeze_holding(&killed, &root.done("tiny-b"));
    killed.kill().unwrap(); // SIGKILL
    killed.wait().unwrap();
    let (status, out) = root.sweep_to_end("next", &["--only", "tiny-b"]);
    assert!(status.success() && out.contains("Completed, "), "{out}");
    root.assert_complete("tiny-b");
    assert_eq!(root.rows("tiny-b"), 1);
    let lock = runout_run::lock::lock_path(&root.done("tiny-b")).unwrap();
    assert!(!std::fs::read_to_string(lock)
        .unwrap()
        .starts_with(&format!("pid {} ", killed.id())));

    // a finished folder that lost a file is damaged: read as no result, and run again
    std::fs::remove_file(root.done("tiny-b").join("fields_00001.vtr")).unwrap();
    let err = runout_post::folder::read_summary(&root.done("tiny-b"))
        .unwrap()
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("damaged") && err.contains("fields_00001.vtr missing"),
        "{err}"
    );
    let (status, out) = root.sweep_to_end("rerun", &["--only", "tiny-b"]);
    assert!(status.success() && out.contains("Completed, "), "{out}");
    root.assert_complete("tiny-b");
    assert_eq!(root.rows("tiny-b"), 1);
}
