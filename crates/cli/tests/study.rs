//! `runout sweep`, `runout sensitivity` and `runout calibrate` as a user runs them: in a
//! temporary folder outside the repository holding only a copy of a shipped case (the small
//! slide of family M, 40 × 10 cells to 0.1 s at smoke fidelity, under a second a run) and a
//! sweep file of the user's over its specularity.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// A temporary folder with `my-slope/slide.ron` (cases/mfix-slope/jj.ron, case M-JJ with
/// φ = 0.1) and `my-slope/phi.ron` (a sweep of its φ over 0.05, 0.1, 0.5), removed on drop.
struct Folder(PathBuf);

impl Folder {
    fn new(test: &str) -> Folder {
        let dir = std::env::temp_dir().join(format!("runout-study-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("my-slope")).unwrap();
        let shipped = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/mfix-slope/jj.ron");
        std::fs::copy(shipped, dir.join("my-slope/slide.ron")).unwrap();
        std::fs::write(
            dir.join("my-slope/phi.ron"),
            "Sweep(name: \"M-JJ-phi\", base: \"slide.ron\", vary: [Specularity([0.05, 0.1, 0.5])])\n",
        )
        .unwrap();
        Folder(dir)
    }

    /// Runs `runout args…` in this folder; its output, asserted successful.
    fn runout(&self, args: &[&str]) -> String {
        let out: Output = Command::new(env!("CARGO_BIN_EXE_runout"))
            .current_dir(&self.0)
            .args(args)
            .output()
            .unwrap();
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(out.status.success(), "runout {}: {text}", args.join(" "));
        text
    }
}

impl Drop for Folder {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A sweep of the folder runs its four cases (the φ = 0.1 point copied from the slide, the
/// same case), writes their run folders and the summary; a second sweep skips them all; the
/// sensitivity of the summary's columns over the φ family is written.
#[test]
fn a_sweep_and_its_sensitivity_run_in_a_folder_of_the_users() {
    let f = Folder::new("sweep");
    let listed = f.runout(&["sweep", "my-slope", "--fidelity", "smoke", "--list"]);
    assert!(listed.contains("4 of 4 flow case(s)"), "{listed}");
    assert!(!f.0.join("runs").exists(), "--list runs nothing");

    let out = f.runout(&["sweep", "my-slope", "--fidelity", "smoke", "--jobs", "2"]);
    assert!(out.contains("ran 3, copied 1"), "{out}");
    for case in [
        "M-JJ",
        "M-JJ-phi_phi=0.05",
        "M-JJ-phi_phi=0.1",
        "M-JJ-phi_phi=0.5",
    ] {
        let summary =
            f.0.join("runs")
                .join(case)
                .join("smoke")
                .join("summary.json");
        assert!(summary.is_file(), "{}", summary.display());
    }
    let csv = std::fs::read_to_string(f.0.join("results/summary.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 4, "{csv}");
    assert!(
        csv.lines().skip(1).all(|l| l.contains(",smoke,Completed,")),
        "{csv}"
    );

    let again = f.runout(&["sweep", "my-slope", "--fidelity", "smoke"]);
    assert!(
        again.contains("ran 0, copied 0 (repeats of a run), skipped 4"),
        "{again}"
    );

    let table = f.runout(&["sensitivity", "my-slope", "--fidelity", "smoke"]);
    assert!(table.contains("| M-JJ-phi: φ |"), "{table}");
    let pairs = std::fs::read_to_string(f.0.join("results/elasticities.csv")).unwrap();
    assert!(
        pairs.starts_with("family,parameter,unit,output,elasticity"),
        "{pairs}"
    );
    assert!(pairs.contains("M-JJ-phi: φ,φ,-,max_u_s,"), "{pairs}");
    assert!(pairs.contains("M-JJ-phi: φ,φ,-,front_x_end_m,"), "{pairs}");
}

/// Shard 2 of 2 runs every second case; shard 1 the others; the summary holds all four.
#[test]
fn shards_of_a_sweep_fill_one_summary() {
    let f = Folder::new("shards");
    let second = f.runout(&["sweep", "my-slope", "--fidelity", "smoke", "--shard", "2/2"]);
    assert!(second.contains("(shard 2/2)"), "{second}");
    f.runout(&["sweep", "my-slope", "--fidelity", "smoke", "--shard", "1/2"]);
    let csv = std::fs::read_to_string(f.0.join("results/summary.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 4, "{csv}");
}

/// The slide's specularity recovered from its own front at two times: the calibration
/// writes its study folder with the evaluations and the summary, and its best φ lies in the
/// scanned bounds.
#[test]
fn a_calibration_against_a_measured_front_runs_in_a_folder_of_the_users() {
    let f = Folder::new("calibrate");
    f.runout(&["sweep", "my-slope/slide.ron", "--fidelity", "smoke"]);
    // the "measurements": the run's own front_x at t = 0.05 s and 0.1 s (bulk.csv)
    let bulk = std::fs::read_to_string(f.0.join("runs/M-JJ/smoke/bulk.csv")).unwrap();
    let mut rows = bulk.lines();
    let header: Vec<&str> = rows.next().unwrap().split(',').collect();
    let (t, x) = (
        header.iter().position(|h| *h == "t").unwrap(),
        header.iter().position(|h| *h == "front_x").unwrap(),
    );
    let front: Vec<(f64, f64)> = rows
        .filter_map(|line| {
            let v: Vec<&str> = line.split(',').collect();
            Some((v[t].parse().ok()?, v[x].parse().ok()?))
        })
        .collect();
    let middle = front
        .iter()
        .min_by(|a, b| (a.0 - 0.05).abs().total_cmp(&(b.0 - 0.05).abs()))
        .unwrap();
    let last = front.last().unwrap();
    let measured = format!(
        "# sigma: 0.01\nt,x\n{},{}\n{},{}\n",
        middle.0, middle.1, last.0, last.1
    );
    assert_eq!(measured.lines().count(), 4, "{measured}");
    std::fs::write(f.0.join("front.csv"), measured).unwrap();

    let out = f.runout(&[
        "calibrate",
        "my-slope/slide.ron",
        "--param",
        "specularity=0.02:0.5:log",
        "--measurements",
        "front.csv",
        "--fidelity",
        "smoke",
        "--scan",
        "3",
        "--refine",
        "1",
        "--profile",
        "1",
        "--jobs",
        "2",
    ]);
    let study = f.0.join("runs/calibrate/M-JJ");
    for file in [
        "evaluations.csv",
        "landscape.svg",
        "summary.md",
        "summary.json",
    ] {
        assert!(study.join(file).is_file(), "{file}: {out}");
    }
    let summary = std::fs::read_to_string(study.join("summary.md")).unwrap();
    assert!(
        summary.contains("runout calibrate my-slope/slide.ron"),
        "{summary}"
    );
}
