//! Issue 7, inclined-plane check (fast version): steady, fully developed flow down a 25°
//! slope with a Johnson–Jackson floor; the 2-D two-fluid solver on a periodic column against
//! the 1-D steady solve of the same equations (`runout_solver::chute_check`, docs/chute.md).
//! The full-size run is `cargo xtask verify chute`.

use runout_solver::chute_check::{reference, run, ChuteCheckSetup, SIDEWALL_WIDTH};

#[test]
fn periodic_column_reaches_the_one_dimensional_steady_profile() {
    let setup = ChuteCheckSetup {
        cells: 40,
        verbose: std::env::var("RUNOUT_VERBOSE").is_ok(),
        ..ChuteCheckSetup::default()
    };
    let c = run(&setup).unwrap();
    eprintln!(
        "40 cells: t = {:.3} s, {} steps ({} rejected), rate {:.2e}/s, errors: eps {:.2e}, u {:.2e}, theta {:.2e} (pointwise {:.2e}), mass {:.2e}, drag/weight {:.2e}, {:.1} s wall",
        c.time,
        c.steps,
        c.rejected,
        c.final_rate,
        c.eps_error,
        c.velocity_error,
        c.theta_error,
        c.theta_pointwise_error,
        c.mass_change,
        c.drag_to_weight,
        c.wall_time
    );
    assert!(
        c.steady,
        "not steady by t = {} s (rate {})",
        c.time, c.final_rate
    );
    assert!(c.eps_error < 0.02, "eps error {}", c.eps_error);
    assert!(c.velocity_error < 0.02, "u_s error {}", c.velocity_error);
    assert!(c.theta_error < 0.02, "theta error {}", c.theta_error);
    assert!(c.mass_change.abs() < 1e-10, "mass change {}", c.mass_change);
    assert!(
        c.drag_to_weight < 1e-4,
        "gas not negligible: {}",
        c.drag_to_weight
    );
}

/// Issue 23 item 1: side walls with the floor's JJ condition (docs/model.md §8) in both the
/// 2-D column and the 1-D reference (extended with the same term, written apart). They
/// change the steady profile materially, and the two solvers agree on the changed one.
#[test]
fn periodic_column_with_side_walls_reaches_the_extended_reference() {
    let plane = ChuteCheckSetup {
        cells: 40,
        verbose: std::env::var("RUNOUT_VERBOSE").is_ok(),
        ..ChuteCheckSetup::default()
    };
    let setup = plane.clone().with_floor_sidewalls(SIDEWALL_WIDTH);
    let c = run(&setup).unwrap();
    // the plane reference alone (the 1-D solve takes well under a second)
    let plane_reference = reference(&plane).unwrap();
    let largest = plane_reference.u_s.iter().fold(0.0_f64, |m, u| m.max(*u));
    let change = c
        .reference
        .u_s
        .iter()
        .zip(&plane_reference.u_s)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
        / largest;
    eprintln!(
        "side walls W = {SIDEWALL_WIDTH} m: u_s changed by {change:.2} of the plane's largest; t = {:.3} s, {} steps, errors eps {:.2e}, u {:.2e}, theta {:.2e}",
        c.time, c.steps, c.eps_error, c.velocity_error, c.theta_error
    );
    assert!(change > 0.2, "side walls changed u_s by only {change}");
    assert!(c.steady, "not steady by t = {} s", c.time);
    assert!(c.eps_error < 0.02, "eps error {}", c.eps_error);
    assert!(c.velocity_error < 0.02, "u_s error {}", c.velocity_error);
    assert!(c.theta_error < 0.02, "theta error {}", c.theta_error);
}
