//! One writer per run folder (issue 44), end to end: `runout run` into a folder another
//! `runout run` is writing is refused as running (with `--overwrite` and `--restart` too),
//! and a folder whose writer was killed with SIGKILL is taken over by the next run.
//!
//! The first run (the cavity at coarse fidelity to 2 s, a few seconds) is frozen with
//! SIGSTOP while it holds the folder, so the second meets a running run on any machine.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant, SystemTime};

use runout_run::lock::{lock_path, RunLock};
use runout_run::RunError;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn runout(out: &Path, extra: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_runout"));
    c.args([
        "run",
        "examples/cavity-re100.ron",
        "--fidelity",
        "coarse",
        "--end-time",
        "2",
        "--quiet",
        "--out",
    ])
    .arg(out)
    .args(extra)
    .current_dir(root())
    .stdout(Stdio::piped())
    .stderr(Stdio::piped());
    c
}

fn text(o: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    )
}

fn signal(child: &Child, sig: i32) {
    // SAFETY: kill(2) on our own child's pid
    assert_eq!(unsafe { libc::kill(child.id() as i32, sig) }, 0);
}

/// Waits until `child` holds `dir`'s lock, then freezes it (SIGSTOP).
fn freeze_holding(child: &Child, dir: &Path) {
    let pid = format!("pid {} ", child.id());
    let start = Instant::now();
    while !std::fs::read_to_string(lock_path(dir).unwrap()).is_ok_and(|t| t.starts_with(&pid)) {
        assert!(start.elapsed() < Duration::from_secs(120), "no lock taken");
        std::thread::sleep(Duration::from_millis(2));
    }
    signal(child, libc::SIGSTOP);
    match RunLock::acquire(dir) {
        Err(RunError::Running { .. }) => {}
        other => panic!("the first run ended before it was frozen: {other:?}"),
    }
}

/// Waits until a file of `dir` other than its lock was modified at or after `since`.
fn wait_for_a_file_written_since(dir: &Path, since: SystemTime) {
    let lock = lock_path(dir).unwrap();
    let start = Instant::now();
    let written = || {
        std::fs::read_dir(dir).is_ok_and(|entries| {
            entries.flatten().any(|e| {
                e.path() != lock
                    && e.metadata()
                        .and_then(|m| m.modified())
                        .is_ok_and(|t| t >= since)
            })
        })
    };
    while !written() {
        assert!(
            start.elapsed() < Duration::from_secs(120),
            "nothing written"
        );
        std::thread::sleep(Duration::from_millis(2));
    }
}

fn assert_complete(dir: &Path) {
    let summary = runout_post::folder::read_summary(dir)
        .expect("a summary")
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(summary.status, runout_output::RunStatus::Completed);
    assert!(!summary.files.is_empty(), "the summary lists the files");
}

#[test]
fn a_second_run_into_a_running_folder_is_refused_whatever_the_flags() {
    let base = std::env::temp_dir().join(format!("runout-cli-one-writer-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&base);
    let dir = base.join("cavity");

    let first = runout(&dir, &[]).spawn().unwrap();
    freeze_holding(&first, &dir);
    for extra in [&[][..], &["--overwrite"], &["--restart"]] {
        let o = runout(&dir, extra).output().unwrap();
        let t = text(&o);
        assert!(!o.status.success(), "{extra:?}: {t}");
        let pid = format!("is running in this folder (pid {} on host ", first.id());
        assert!(
            t.contains(&pid) && !t.contains("earlier run"),
            "{extra:?}: {t}"
        );
    }
    signal(&first, libc::SIGCONT);
    let o = first.wait_with_output().unwrap();
    assert!(o.status.success(), "{}", text(&o));
    assert_complete(&dir);

    // a holder killed with SIGKILL: its lock is free at once, its files an earlier run. It
    // is frozen once it has written a file of its own: `--overwrite` first removes the
    // earlier run's files, and a holder killed between that and its first write leaves an
    // empty folder, which the next run may take (seen on a loaded machine).
    let since = SystemTime::now();
    let killed = runout(&dir, &["--overwrite"]).spawn().unwrap();
    freeze_holding(&killed, &dir);
    signal(&killed, libc::SIGCONT);
    wait_for_a_file_written_since(&dir, since);
    signal(&killed, libc::SIGSTOP);
    signal(&killed, libc::SIGKILL);
    killed.wait_with_output().unwrap();
    let o = runout(&dir, &[]).output().unwrap();
    assert!(
        !o.status.success() && text(&o).contains("holds an earlier run, not running now"),
        "{}",
        text(&o)
    );
    let o = runout(&dir, &["--overwrite"]).output().unwrap();
    assert!(o.status.success(), "{}", text(&o));
    assert_complete(&dir);
    std::fs::remove_dir_all(&base).unwrap();
}
