//! The paper's slide with a Johnson–Jackson floor, S-JJ-phi with φ = 0.1 (issue 7, last
//! check): the block falls, gravity tilts on impact, and the flow slides to the paper's
//! t = 1.25 s (1.25 s after the tilt, docs/impact.md §4) with
//! no NaN, εs ≤ εs,max + 0.02 everywhere at every step, and the solids mass conserved within
//! 1e-8 relative. The smoke version (the smoke grid, 10× coarser than the paper's, run to
//! 1.25 s instead of the preset's 0.4 s) runs in the test suite; the coarse fidelity is
//! `cargo test -p runout-solver --release --test s_jj_phi -- --ignored --nocapture`.

use std::path::Path;

use runout_case::{load, Fidelity, Loaded};
use runout_output::{RunStatus, RunSummary};

/// The run's summary and the end time it must reach [s].
fn run(fidelity: Fidelity) -> (RunSummary, f64) {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/sensitivity/S-JJ-phi.ron");
    let Loaded::Cases(cases) = load(&file).unwrap() else {
        panic!("a sweep")
    };
    let mut case = cases
        .into_iter()
        .find(|c| c.case.name == "S-JJ-phi_phi=0.1")
        .unwrap()
        .case;
    case.fidelity.smoke.end_time = 1.25;
    let end = case.at_fidelity(fidelity).run.end_time;
    let out = std::env::temp_dir().join(format!(
        "runout-sjjphi-{}-{}",
        fidelity.name(),
        std::process::id()
    ));
    let summary = runout_run::run_case(&case, fidelity, &out, |_| {}).unwrap();
    eprintln!(
        "S-JJ-phi φ = 0.1 at {}: {:?}, t = {} s, {} steps ({} rejected), {:.1} outer it./step, \
         mass change {:.2e}, max εs {:.4}, {:.1} s wall, {:.1} s wall per simulated second",
        fidelity.name(),
        summary.status,
        summary.simulated_time,
        summary.steps,
        summary.rejected_steps,
        summary.outer_iterations as f64 / summary.steps.max(1) as f64,
        summary.solids_mass_change,
        summary.max_eps_s,
        summary.wall_time,
        summary.wall_time / summary.simulated_time
    );
    let bulk = std::fs::read_to_string(out.join("bulk.csv")).unwrap();
    assert!(
        !bulk.to_ascii_lowercase().contains("nan") && !bulk.contains("inf"),
        "non-finite monitor values"
    );
    (summary, end)
}

fn check((s, end): &(RunSummary, f64)) {
    assert_eq!(s.status, RunStatus::Completed);
    assert!(
        (s.simulated_time - end).abs() < 1e-9,
        "{}",
        s.simulated_time
    );
    assert!(
        s.solids_mass_change.abs() <= 1e-8,
        "{}",
        s.solids_mass_change
    );
    assert!(s.max_eps_s <= 0.65 + 0.02, "max eps {}", s.max_eps_s);
}

#[test]
fn s_jj_phi_smoke_to_1_25_s() {
    check(&run(Fidelity::Smoke));
}

#[test]
#[ignore = "coarse fidelity, several minutes: run with --ignored"]
fn s_jj_phi_coarse_to_1_25_s() {
    check(&run(Fidelity::Coarse));
}
