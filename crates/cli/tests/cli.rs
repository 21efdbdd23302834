//! The `runout` binary end to end: `check` accepts every shipped case and rejects bad
//! input with a message naming file, field and range (never a panic); `mesh` prints the
//! paper's two grids with their cell sizes (issue 2).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn runout(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_runout"))
        .args(args)
        .current_dir(root())
        .output()
        .expect("runout runs")
}

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn text(o: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr))
}

#[test]
fn check_accepts_every_shipped_case() {
    let o = runout(&["check", "cases"]);
    assert!(o.status.success(), "{}", text(&o));
    let t = text(&o);
    for name in ["S-JJ-phi_phi=0.01", "S-RJJ", "F-JEN", "M-slide", "A-fig1"] {
        assert!(t.contains(name), "{name} not listed:\n{t}");
    }
}

#[test]
fn check_rejects_bad_files_without_panicking() {
    let dir = std::env::temp_dir().join(format!("runout-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = std::fs::read_to_string(root().join("cases/mfix/M-slide.ron")).unwrap();
    let bad = dir.join("neg.ron");
    std::fs::write(&bad, good.replacen("diameter: 5e-4", "diameter: -1e-3", 1)).unwrap();
    let o = runout(&["check", bad.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    let t = text(&o);
    assert!(t.contains("neg.ron") && t.contains("solids[0].diameter") && t.contains("(0, inf)"), "{t}");
    assert!(!t.contains("panicked"), "{t}");
    let o = runout(&["check", dir.join("missing.ron").to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(text(&o).contains("missing.ron"));
}

#[test]
fn mesh_prints_the_two_paper_grids() {
    let o = runout(&["mesh", "cases/sensitivity/base.ron"]);
    assert!(o.status.success(), "{}", text(&o));
    let t = text(&o);
    assert!(t.contains("x: [0, 20] m, dx min 0.020000 m, max 0.020000 m"), "{t}");
    assert!(t.contains("y: [0, 1.8] m, dy min 0.005000 m"), "{t}");
    let o = runout(&["mesh", "cases/flume/base.ron"]);
    let t = text(&o);
    assert!(t.contains("x: [0, 7.5] m, dx min 0.010000 m"), "{t}");
    assert!(t.contains("y: [0, 1.8] m, dy min 0.010000 m"), "{t}");
    let o = runout(&["mesh", "--fidelity", "smoke", "cases/mfix/M-slide.ron"]);
    assert!(text(&o).contains("cells: 40 x 10 = 400"), "{}", text(&o));
}
