//! Issue 7, inclined-plane check (fast version): steady, fully developed flow down a 25°
//! slope with a Johnson–Jackson floor; the 2-D two-fluid solver on a periodic column against
//! the 1-D steady solve of the same equations (`runout_solver::chute_check`, docs/chute.md).
//! The full-size run is `cargo xtask verify chute`.

use runout_solver::chute_check::{run, ChuteCheckSetup};

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
