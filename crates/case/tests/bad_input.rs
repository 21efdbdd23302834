//! Bad input is rejected before anything runs, with the file, the field and the allowed
//! range in the message, and never a panic (issue 2).

use std::path::{Path, PathBuf};

use runout_case::{load, CaseError};

fn shipped(rel: &str) -> String {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../cases")
        .join(rel);
    std::fs::read_to_string(p).unwrap()
}

/// Writes `text` to a fresh temporary file and loads it.
fn load_text(name: &str, text: &str) -> (PathBuf, Result<runout_case::Loaded, CaseError>) {
    let dir = std::env::temp_dir().join(format!("runout-case-tests-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    let r = load(&path);
    (path, r)
}

/// Replaces exactly one occurrence (so a test cannot silently edit nothing).
fn replace_once(text: &str, from: &str, to: &str) -> String {
    assert_eq!(text.matches(from).count(), 1, "`{from}` must occur once");
    text.replacen(from, to, 1)
}

fn rejected(name: &str, text: &str, must_contain: &[&str]) {
    let (path, r) = load_text(name, text);
    let err = match r {
        Ok(_) => panic!("{name} was accepted"),
        Err(e) => e.to_string(),
    };
    assert!(
        err.contains(&path.display().to_string()),
        "no file name in: {err}"
    );
    for s in must_contain {
        assert!(err.contains(s), "`{s}` missing in: {err}");
    }
}

fn mslide() -> String {
    shipped("mfix-slope/jj.ron")
}

#[test]
fn negative_diameter() {
    let t = replace_once(&mslide(), "diameter: 5e-4", "diameter: -1e-3");
    rejected("d.ron", &t, &["solids[0].diameter", "-0.001", "(0, inf)"]);
}

#[test]
fn specularity_above_one() {
    let t = replace_once(&mslide(), "specularity: 0.1", "specularity: 1.5");
    rejected(
        "phi.ron",
        &t,
        &["boundaries.south.solids.specularity", "1.5", "[0, 1]"],
    );
}

#[test]
fn unknown_field() {
    let t = replace_once(
        &mslide(),
        "restitution: 0.9,",
        "restitution: 0.9, colour: 3,",
    );
    rejected("unknown.ron", &t, &["colour", "Solids", "diameter"]);
}

#[test]
fn unknown_boundary_condition() {
    let t = replace_once(
        &mslide(),
        "west: Wall(gas: FreeSlip, solids: FreeSlip)",
        "west: Wall(gas: FreeSlip, solids: Sticky)",
    );
    rejected("bc.ron", &t, &["Sticky", "JohnsonJackson"]);
}

#[test]
fn packing_above_one_and_block_denser_than_packing() {
    let t = replace_once(&mslide(), "max_packing: 0.65", "max_packing: 1.2");
    rejected("pack.ron", &t, &["solids[0].max_packing", "(0, 1)"]);
    let t = replace_once(&mslide(), "eps_s: 0.6,", "eps_s: 0.7,");
    rejected(
        "block.ron",
        &t,
        &["initial.regions[0].solids[0].eps_s", "[0, 0.65]"],
    );
}

#[test]
fn restitution_and_angles() {
    let t = replace_once(&mslide(), "restitution: 0.9,", "restitution: 1.1,");
    rejected("e.ron", &t, &["solids[0].restitution", "[0, 1]"]);
    let t = replace_once(
        &mslide(),
        "internal_friction_angle: 35.0",
        "internal_friction_angle: 95.0",
    );
    rejected(
        "angle.ron",
        &t,
        &["solids[0].internal_friction_angle", "(0, 90)"],
    );
    let t = replace_once(&mslide(), "slope: 40.0", "slope: 120.0");
    rejected("slope.ron", &t, &["gravity.slope", "[0, 90)"]);
}

#[test]
fn time_step_bounds() {
    let t = replace_once(
        &mslide(),
        "dt: (initial: 1e-4, min: 1e-6, max: 1e-3",
        "dt: (initial: 1e-2, min: 1e-6, max: 1e-3",
    );
    rejected("dt.ron", &t, &["run.dt.initial", "[0.000001, 0.001]"]);
    let t = replace_once(
        &mslide(),
        "dt: (initial: 1e-4, min: 1e-6, max: 1e-3",
        "dt: (initial: 1e-4, min: 1e-2, max: 1e-3",
    );
    rejected("dtmin.ron", &t, &["run.dt.min"]);
    let t = replace_once(&mslide(), "factor: 0.9", "factor: 0.9, steps_per_change: 0");
    rejected(
        "dtsteps.ron",
        &t,
        &["run.dt.steps_per_change", "an integer >= 1"],
    );
    let t = replace_once(
        &mslide(),
        "factor: 0.9",
        "factor: 0.9, failure_factor: Some(1.5)",
    );
    rejected("dtfail.ron", &t, &["run.dt.failure_factor", "(0, 1)"]);
}

#[test]
fn block_station_and_gates_inside_domain() {
    let t = replace_once(
        &mslide(),
        "regions: [(x: (0.0, 0.5)",
        "regions: [(x: (3.8, 4.5)",
    );
    rejected("block.ron", &t, &["initial.regions[0].x.1", "[0, 4]"]);
    let flume = shipped("flume/base.ron");
    let t = replace_once(&flume, "gates: [1.65, 2.10,", "gates: [2.10, 1.65,");
    rejected(
        "gates.ron",
        &t,
        &["monitors.front.gates[1]", "strictly increasing"],
    );
    let t = replace_once(&flume, "4.35]", "9.35]");
    rejected("gate_out.ron", &t, &["monitors.front.gates[6]"]);
    let s = shipped("sensitivity/base.ron");
    let t = replace_once(&s, "profiles: [(x: 11.0", "profiles: [(x: 21.0");
    rejected("station.ron", &t, &["monitors.profiles[0].x", "[0, 20]"]);
}

#[test]
fn several_errors_are_all_reported() {
    let t = replace_once(&mslide(), "diameter: 5e-4", "diameter: -1e-3");
    let t = replace_once(&t, "specularity: 0.1", "specularity: 1.5");
    rejected(
        "two.ron",
        &t,
        &["2 invalid fields", "diameter", "specularity"],
    );
}

#[test]
fn syntax_error_has_a_position() {
    let t = replace_once(&mslide(), "density: 2000.0,", "density: 2000.0,,");
    let (path, r) = load_text("syntax.ron", &t);
    let e = r.expect_err("rejected").to_string();
    assert!(e.starts_with(&format!("{}:", path.display())), "{e}");
}

#[test]
fn sweep_that_does_not_apply_is_rejected() {
    let dir = std::env::temp_dir().join(format!("runout-sweep-tests-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("base.ron"), mslide()).unwrap();
    // M-JJ has no user partial-slip wall, so PartialSlipHu has nothing to set
    let sweep = r#"Sweep(name: "X", base: "base.ron", vary: [PartialSlipHu([1.0, 2.0])])"#;
    std::fs::write(dir.join("x.ron"), sweep).unwrap();
    let e = load(&dir.join("x.ron")).expect_err("rejected").to_string();
    assert!(
        e.contains("x.ron") && e.contains("PartialSlipHu") && e.contains("no wall"),
        "{e}"
    );
    // a swept value out of range names the expanded case and the field
    let sweep = r#"Sweep(name: "Y", base: "base.ron", vary: [Specularity([0.5, 2.0])])"#;
    std::fs::write(dir.join("y.ron"), sweep).unwrap();
    let e = load(&dir.join("y.ron")).expect_err("rejected").to_string();
    assert!(
        e.contains("Y_phi=2") && e.contains("specularity") && e.contains("[0, 1]"),
        "{e}"
    );
    // a missing base file names it
    let sweep = r#"Sweep(name: "Z", base: "nope.ron")"#;
    std::fs::write(dir.join("z.ron"), sweep).unwrap();
    let e = load(&dir.join("z.ron")).expect_err("rejected").to_string();
    assert!(e.contains("nope.ron"), "{e}");
}
