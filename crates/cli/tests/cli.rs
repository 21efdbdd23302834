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
    format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    )
}

#[test]
fn check_accepts_every_shipped_case() {
    let o = runout(&["check", "cases"]);
    assert!(o.status.success(), "{}", text(&o));
    let t = text(&o);
    for name in [
        "S-JJ-phi_phi=0.01",
        "S-RJJ",
        "F-JEN",
        "M-JJ",
        "M-RJJ",
        "M-JEN",
        "M-PS",
        "A-fig1",
    ] {
        assert!(t.contains(name), "{name} not listed:\n{t}");
    }
}

#[test]
fn check_prints_cells_unknowns_and_memory() {
    let o = runout(&["check", "cases/mfix-slope/jj.ron"]);
    assert!(o.status.success(), "{}", text(&o));
    let t = text(&o);
    assert!(
        t.contains("paper 200x50 = 10000 cells, 70000 unknowns, ~3") && t.contains(" MiB"),
        "{t}"
    );
    assert!(t.contains("smoke 40x10 = 400 cells"), "{t}");
}

#[test]
fn check_rejects_bad_files_without_panicking() {
    let dir = std::env::temp_dir().join(format!("runout-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let good = std::fs::read_to_string(root().join("cases/mfix-slope/jj.ron")).unwrap();
    let bad = dir.join("neg.ron");
    std::fs::write(&bad, good.replacen("diameter: 5e-4", "diameter: -1e-3", 1)).unwrap();
    let o = runout(&["check", bad.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    let t = text(&o);
    assert!(
        t.contains("neg.ron") && t.contains("solids[0].diameter") && t.contains("[1e-6, 1] m"),
        "{t}"
    );
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
    assert!(
        t.contains("x: [0, 20] m, dx min 0.020000 m, max 0.020000 m"),
        "{t}"
    );
    assert!(t.contains("y: [0, 1.8] m, dy min 0.005000 m"), "{t}");
    let o = runout(&["mesh", "cases/flume/base.ron"]);
    let t = text(&o);
    assert!(t.contains("x: [0, 7.5] m, dx min 0.010000 m"), "{t}");
    assert!(t.contains("y: [0, 1.8] m, dy min 0.010000 m"), "{t}");
    let o = runout(&["mesh", "--fidelity", "smoke", "cases/mfix-slope/jj.ron"]);
    assert!(text(&o).contains("cells: 40 x 10 = 400"), "{}", text(&o));
}

/// `runout run <file> --fidelity smoke --quiet [extra] --out <a temp folder named by tag>`:
/// the output and the folder.
fn run_smoke(file: &str, tag: &str, extra: &[&str]) -> (Output, PathBuf) {
    let out = std::env::temp_dir().join(format!("runout-run{tag}-{}", std::process::id()));
    let mut args = vec!["run", file, "--fidelity", "smoke", "--quiet"];
    args.extend_from_slice(extra);
    args.extend_from_slice(&["--out", out.to_str().unwrap()]);
    (runout(&args), out)
}

#[test]
fn run_writes_fields_monitors_and_summary() {
    let (o, out) = run_smoke("examples/cavity-re100.ron", "", &[]);
    assert!(o.status.success(), "{}", text(&o));
    let summary = std::fs::read_to_string(out.join("summary.json")).unwrap();
    assert!(summary.contains("\"Completed\""), "{summary}");
    let pvd = std::fs::read_to_string(out.join("fields.pvd")).unwrap();
    assert!(pvd.matches("<DataSet").count() >= 2, "{pvd}");
    assert!(out.join("resolved.ron").exists());
}

#[test]
fn run_end_time_overrides_the_fidelity_and_rejects_a_bad_value() {
    let (o, _) = run_smoke("examples/cavity-re100.ron", "-t", &["--end-time", "0.25"]);
    assert!(o.status.success(), "{}", text(&o));
    // the smoke preset ends at 1.0 s
    assert!(text(&o).contains("at t = 0.25 s"), "{}", text(&o));
    let o = runout(&["run", "examples/cavity-re100.ron", "--end-time=-1"]);
    assert!(!o.status.success());
    assert!(
        text(&o).contains("-1: allowed (0, inf) seconds"),
        "{}",
        text(&o)
    );
}

#[test]
fn run_solves_the_mfix_slide_with_its_johnson_jackson_floor_at_smoke_fidelity() {
    let (o, out) = run_smoke("cases/mfix-slope/jj.ron", "-m", &[]);
    assert!(o.status.success(), "{}", text(&o));
    let summary = std::fs::read_to_string(out.join("summary.json")).unwrap();
    assert!(summary.contains("\"Completed\""), "{summary}");
    assert!(
        std::fs::read_to_string(out.join("bulk.csv"))
            .unwrap()
            .lines()
            .count()
            > 2
    );
    // the wall probe of the Johnson–Jackson floor (paper Fig. 9's h_w^u over time)
    let probe = std::fs::read_to_string(out.join("wall_probe_south_x1.csv")).unwrap();
    assert!(
        probe.starts_with("t,h_w_u") && probe.lines().count() > 2,
        "{probe}"
    );
    // `runout post` reads the folder: the summary and the probe's last h_w^u
    let o = runout(&["post", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", text(&o));
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(json["summary"]["status"], "Completed", "{json}");
    let last_h_u: f64 = probe
        .lines()
        .last()
        .and_then(|l| l.split(',').nth(1))
        .and_then(|h| h.parse().ok())
        .unwrap();
    assert_eq!(
        json["flow"]["h_wu_probe"].as_f64(),
        Some(last_h_u),
        "{json}"
    );
    // the deposit is read at smoke fidelity too (its resolved case, whose profile time is
    // past the smoke end time, is read without validation)
    assert!(json["deposit"]["Ok"]["at_rest"].is_boolean(), "{json}");
    let o = runout(&["post", std::env::temp_dir().to_str().unwrap()]);
    assert!(!o.status.success());
    assert!(text(&o).contains("not a run folder"), "{}", text(&o));
}

#[test]
fn run_refuses_what_the_two_fluid_solver_lacks_before_any_step() {
    let dir = std::env::temp_dir().join(format!("runout-run-algebraic-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let text0 = std::fs::read_to_string(root().join("cases/mfix-slope/jj.ron")).unwrap();
    // the algebraic kinetic theory (no θ PDE) is not implemented in the two-fluid solver
    let algebraic = text0.replacen(
        "kinetic_theory: Lun1984(alpha: 1.6),",
        "kinetic_theory: Algebraic,",
        1,
    );
    assert_ne!(algebraic, text0);
    let case = dir.join("algebraic.ron");
    std::fs::write(&case, algebraic).unwrap();
    let out = dir.join("out");
    let o = runout(&[
        "run",
        case.to_str().unwrap(),
        "--fidelity",
        "smoke",
        "--quiet",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    let t = text(&o);
    assert!(
        t.contains("only the Lun 1984 kinetic theory with the θ PDE is implemented"),
        "{t}"
    );
    assert!(!out.join("summary.json").exists());
}

#[test]
fn a_run_that_cannot_converge_stops_with_a_diagnosis_and_keeps_its_output() {
    let dir = std::env::temp_dir().join(format!("runout-run-div-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // two outer iterations can never reach a 1e-12 residual: every step fails until dt < dt_min
    let text0 = std::fs::read_to_string(root().join("examples/cavity-re100.ron")).unwrap();
    let bad = text0
        .replacen(
            "tolerances: (residual: 1e-4)",
            "tolerances: (residual: 1e-12, max_iterations: 2)",
            1,
        )
        .replacen("min: 1e-5", "min: 5e-3", 1);
    assert_ne!(bad, text0);
    let case = dir.join("stuck.ron");
    std::fs::write(&case, bad).unwrap();
    let out = dir.join("out");
    let o = runout(&[
        "run",
        case.to_str().unwrap(),
        "--fidelity",
        "smoke",
        "--quiet",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    let summary = std::fs::read_to_string(out.join("summary.json")).unwrap();
    assert!(
        summary.contains("Diverged") && summary.contains("dt_min"),
        "{summary}"
    );
    // the diagnosis names the equations, where their largest residual is, and the history
    assert!(
        summary.contains("u momentum")
            && summary.contains("largest at x =")
            && summary.contains("residual history"),
        "{summary}"
    );
    // the initial fields were written and kept
    assert!(out.join("fields_00000.vtr").exists());
}
