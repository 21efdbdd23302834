//! `runout run` under signals and restarts (issue 21), end to end with real signals:
//! SIGTERM stops the run after its step with a checkpoint, status `Interrupted`, exit 130
//! and the restart command printed; `--restart` then finishes it with the same monitor
//! output as an uninterrupted run; a fresh run refuses a folder holding a run unless
//! `--overwrite`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn runout(args: &[&str]) -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_runout"));
    c.args(args).current_dir(root());
    c
}

fn text(o: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    )
}

/// The family-M slide at coarse fidelity to 0.3 s: a few seconds of work.
const ARGS: [&str; 7] = [
    "run",
    "cases/mfix-slope/jj.ron",
    "--fidelity",
    "coarse",
    "--end-time",
    "0.3",
    "--quiet",
];

fn lines(path: &Path) -> usize {
    std::fs::read_to_string(path).map_or(0, |t| t.lines().count())
}

#[test]
fn sigterm_checkpoints_and_restart_finishes_the_same_run() {
    let base = std::env::temp_dir().join(format!("runout-signals-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&base);
    let (whole, stopped) = (base.join("whole"), base.join("stopped"));

    let o = runout(&ARGS)
        .args(["--out", whole.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", text(&o));

    let child = runout(&ARGS)
        .args(["--out", stopped.to_str().unwrap()])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // wait until the run is under way (a few bulk samples), then SIGTERM
    let started = Instant::now();
    while lines(&stopped.join("bulk.csv")) < 5 {
        assert!(
            started.elapsed() < Duration::from_secs(120),
            "the run never started"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    // SAFETY: kill(2) on our own child's pid
    assert_eq!(unsafe { libc::kill(child.id() as i32, libc::SIGTERM) }, 0);
    let o = child.wait_with_output().unwrap();
    let t = text(&o);
    assert_eq!(o.status.code(), Some(130), "{t}");
    assert!(
        t.contains("--restart"),
        "the restart command is printed: {t}"
    );
    let summary = std::fs::read_to_string(stopped.join("summary.json")).unwrap();
    assert!(summary.contains("\"Interrupted\""), "{summary}");
    assert!(lines(&stopped.join("bulk.csv")) < lines(&whole.join("bulk.csv")));

    // a fresh run refuses the folder, pointing at --restart
    let o = runout(&ARGS)
        .args(["--out", stopped.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o).contains("--restart"), "{}", text(&o));

    let o = runout(&ARGS)
        .args(["--restart", stopped.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", text(&o));
    for file in ["bulk.csv", "wall_probe_south_x1.csv", "fields.pvd"] {
        assert_eq!(
            std::fs::read(whole.join(file)).unwrap(),
            std::fs::read(stopped.join(file)).unwrap(),
            "{file}"
        );
    }
    let o = runout(&ARGS)
        .args(["--out", stopped.to_str().unwrap(), "--overwrite"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", text(&o));
    assert!(!stopped.join("checkpoints").exists(), "the old run is gone");
    let _ = std::fs::remove_dir_all(&base);
}

#[test]
fn run_refuses_a_case_larger_than_the_available_memory_unless_told() {
    let out = std::env::temp_dir().join(format!("runout-memory-{}", std::process::id()));
    let args = [
        "run",
        "cases/mfix-slope/jj.ron",
        "--fidelity",
        "smoke",
        "--end-time",
        "0.002",
        "--quiet",
        "--out",
        out.to_str().unwrap(),
    ];
    // family M at smoke (40 × 10 cells) needs ~11 MiB; say 1 MiB is available
    let o = runout(&args)
        .env(runout_case::AVAILABLE_MEMORY_VAR, "1048576")
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    assert!(text(&o).contains("--ignore-memory"), "{}", text(&o));
    assert!(!out.exists(), "refused before anything is written");
    let o = runout(&args)
        .arg("--ignore-memory")
        .env(runout_case::AVAILABLE_MEMORY_VAR, "1048576")
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", text(&o));
    let _ = std::fs::remove_dir_all(&out);
}
