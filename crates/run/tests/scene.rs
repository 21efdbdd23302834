//! The scene (issue 20 item 2): a solver built from a case evaluates only what the case
//! needs, and its counters show that an inactive piece costs nothing.

use std::path::Path;

use runout_case::{load, Case, Fidelity, Loaded};
use runout_mesh::Side;
use runout_run::{explain::explain, run_case, two_fluid_solver};
use runout_solver::two_fluid::{Counters, WallClosure};

fn case(file: &str, index: usize) -> Case {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(file);
    let Loaded::Cases(cases) = load(&path).unwrap() else {
        panic!("cases")
    };
    cases[index].case.clone()
}

/// The counters after `steps` attempted time steps of 1e-4 s of `case` at smoke fidelity.
fn counters_after_steps(case: &Case, steps: usize) -> Counters {
    let mut tf = two_fluid_solver(&case.at_fidelity(Fidelity::Smoke)).unwrap();
    for _ in 0..steps {
        // converged or not (a failed step is undone), the iterations ran
        tf.step(1e-4, 1e-3, 1e-3, 1e3, 50).unwrap();
    }
    tf.counters()
}

#[test]
fn a_single_phase_case_evaluates_no_closure() {
    let cavity = case("examples/cavity-re100.ron", 0);
    let out = std::env::temp_dir().join(format!("runout-scene-sp-{}", std::process::id()));
    let summary = run_case(&cavity, Fidelity::Smoke, &out, |_| {}).unwrap();
    assert!(summary.steps > 0);
    let closure_parts: Vec<_> = summary
        .profile
        .iter()
        .filter(|(name, _)| name.contains("closure") || name.contains("wall"))
        .collect();
    assert!(closure_parts.is_empty(), "{closure_parts:?}");
    let text = explain(&cavity, Fidelity::Smoke).unwrap();
    assert!(text.contains("no closures, no wall closures"), "{text}");
    // the same run loop with solids does report its closures
    let slide = case("cases/sensitivity/S-PS-hu.ron", 0);
    let out2 = std::env::temp_dir().join(format!("runout-scene-tf-{}", std::process::id()));
    let mut short = slide.at_fidelity(Fidelity::Smoke);
    short.run.end_time = 2e-3;
    let summary = run_case(&short, Fidelity::Paper, &out2, |_| {}).unwrap();
    let closures = summary.profile.iter().find(|(n, _)| n == "closures");
    assert!(
        closures.is_some_and(|(_, t)| *t > 0.0),
        "{:?}",
        summary.profile
    );
    let _ = std::fs::remove_dir_all(&out);
    let _ = std::fs::remove_dir_all(&out2);
}

#[test]
fn a_user_partial_slip_floor_computes_no_johnson_jackson_closure() {
    let ps = case("cases/sensitivity/S-PS-hu.ron", 0);
    let scene = two_fluid_solver(&ps.at_fidelity(Fidelity::Smoke))
        .unwrap()
        .scene()
        .clone();
    assert!(
        matches!(scene.phases[0].walls.south, WallClosure::Fixed(_)),
        "{scene:?}"
    );
    let counted = counters_after_steps(&ps, 2);
    assert!(counted.cell_closures > 0);
    assert_eq!(
        *counted.wall_closure_faces.get(Side::South),
        0,
        "{counted:?}"
    );
    // its Johnson–Jackson back wall is evaluated, per face
    if matches!(scene.phases[0].walls.west, WallClosure::PerFace(_)) {
        assert!(
            *counted.wall_closure_faces.get(Side::West) > 0,
            "{counted:?}"
        );
    }
    // a Johnson–Jackson floor is evaluated on every floor face at every outer iteration
    let jj = case("cases/sensitivity/S-JJ-phi.ron", 0);
    let counted = counters_after_steps(&jj, 2);
    assert!(
        *counted.wall_closure_faces.get(Side::South) > 0,
        "{counted:?}"
    );
}

#[test]
fn a_princeton_case_never_evaluates_the_plastic_pressure() {
    let princeton = case("cases/sensitivity/S-JJ-phi.ron", 0);
    assert!(
        !two_fluid_solver(&princeton.at_fidelity(Fidelity::Smoke))
            .unwrap()
            .scene()
            .phases[0]
            .plastic_pressure
    );
    assert_eq!(
        counters_after_steps(&princeton, 2).plastic_pressure_cells,
        0
    );
    let schaeffer = case("cases/stability/ST-schaeffer.ron", 0);
    let tf = two_fluid_solver(&schaeffer.at_fidelity(Fidelity::Smoke)).unwrap();
    assert!(tf.scene().phases[0].plastic_pressure);
    assert!(counters_after_steps(&schaeffer, 1).plastic_pressure_cells > 0);
}

#[test]
fn explain_names_the_stages_and_the_cost() {
    let jj = case("cases/sensitivity/S-JJ-phi.ron", 0);
    let text = explain(&jj, Fidelity::Coarse).unwrap();
    for expected in [
        "Johnson–Jackson (φ = 1), per face every iteration",
        "no P* term",
        "granular energy",
        "floor probe",
        "unknowns",
    ] {
        assert!(text.contains(expected), "no `{expected}` in\n{text}");
    }
}
