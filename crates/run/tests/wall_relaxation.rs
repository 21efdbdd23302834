//! Under-relaxation of the solids momentum wall closures between outer iterations
//! (`numerics.relaxation.wall_closures`, not in MFIX; docs/history/performance-log.md,
//! "Relaxed wall closures").
//!
//! With a Johnson–Jackson floor of specularity 1 and the closures used as computed (ω = 1,
//! MFIX), the floor's slip and strain cycle with period 2 between outer iterations, the
//! hydrodynamic residuals stop falling and steps are rejected as stalled. The smoke S-JJ-phi
//! φ = 1 slide to 0.4 s shows it: with ω = 1 steps are rejected, with ω = 0.5 none
//! are, and both runs give the same front and a mean solids velocity within 3 % (the ω = 1
//! run accepts iterates of the cycle that happen to be under the tolerances). Relaxing only
//! the wall nodes whose closure cycles (`wall_closures_at: Oscillating`) does the same.

use std::path::Path;

use runout_case::{load, Case, Fidelity, Loaded, WallRelaxationScope};
use runout_output::{RunStatus, RunSummary};

fn case() -> Case {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/sensitivity/S-JJ-phi.ron");
    let Loaded::Cases(cases) = load(&file).unwrap() else {
        panic!("a sweep")
    };
    cases
        .into_iter()
        .find(|c| c.case.name == "S-JJ-phi_phi=1")
        .unwrap()
        .case
}

/// The run's summary and its last bulk-monitor row (t, solids mass, front x, mean u_s).
fn run(wall_closures: f64, scope: WallRelaxationScope) -> (RunSummary, Vec<f64>) {
    let mut case = case();
    // MFIX's classification of dilute cells and Δt controller, which the sensitivity base
    // changes for speed: this test is about the wall closures alone
    case.numerics.dilute_cells = runout_case::DiluteCellClass::EveryIteration;
    case.run.dt.steps_per_change = 5;
    case.run.dt.failure_factor = None;
    case.numerics.relaxation.wall_closures = wall_closures;
    case.numerics.relaxation.wall_closures_at = scope;
    let out = std::env::temp_dir().join(format!(
        "runout-wall-relax-{wall_closures}-{scope:?}-{}",
        std::process::id()
    ));
    let summary = runout_run::run_case(&case, Fidelity::Smoke, &out, |_| {}).unwrap();
    let last = last_bulk_row(&out);
    eprintln!(
        "ω = {wall_closures} ({scope:?}): {:?} at t = {} s, {} steps ({} rejected), front {} m, mean u_s {} m/s",
        summary.status,
        summary.simulated_time,
        summary.steps,
        summary.rejected_steps,
        last[2],
        last[3]
    );
    let _ = std::fs::remove_dir_all(&out);
    (summary, last)
}

/// The last row of a run's `bulk.csv` (t, solids mass, front x, mean u_s), read with the
/// post-processing library's one CSV reader.
fn last_bulk_row(run_dir: &Path) -> Vec<f64> {
    let bulk = runout_post::table::Table::read(&run_dir.join("bulk.csv")).unwrap();
    ["t", "solids_mass", "front_x", "mean_u_s"]
        .iter()
        .map(|c| *bulk.column(c).unwrap().last().unwrap())
        .collect()
}

#[test]
fn relaxed_wall_closures_remove_the_stalls_of_a_specularity_1_floor() {
    let (mfix, mfix_last) = run(1.0, WallRelaxationScope::Everywhere);
    let (relaxed, relaxed_last) = run(0.5, WallRelaxationScope::Everywhere);
    let (cycling, cycling_last) = run(0.5, WallRelaxationScope::Oscillating);
    for s in [&mfix, &relaxed, &cycling] {
        assert_eq!(s.status, RunStatus::Completed);
    }
    assert!(
        mfix.rejected_steps >= 5,
        "ω = 1 rejected {} steps: the period-2 cycle this relaxation is for no longer occurs",
        mfix.rejected_steps
    );
    assert_eq!(relaxed.rejected_steps, 0);
    assert!(relaxed.outer_iterations < mfix.outer_iterations);
    assert_eq!(relaxed_last[2], mfix_last[2], "front x");
    let du = (relaxed_last[3] - mfix_last[3]).abs() / mfix_last[3].abs();
    assert!(du < 0.03, "mean u_s differs by {du:.3}");
    // relaxing only the cycling nodes: as few rejections, the relaxed run's answer
    assert!(
        cycling.rejected_steps <= 1,
        "{} rejected",
        cycling.rejected_steps
    );
    assert!(cycling.outer_iterations < mfix.outer_iterations);
    assert_eq!(cycling_last[2], relaxed_last[2], "front x");
    let du = (cycling_last[3] - relaxed_last[3]).abs() / relaxed_last[3].abs();
    assert!(
        du < 0.01,
        "mean u_s differs from the relaxed run's by {du:.3}"
    );
}
