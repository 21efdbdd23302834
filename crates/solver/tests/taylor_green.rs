//! Decaying Taylor–Green vortex in a free-slip box, the manufactured unsteady solution of
//! issue 6 ([`runout_solver::verify::taylor_green_exact`]), and the per-step mass check.

use runout_solver::verify::{
    mass_conservation, taylor_green_space_order, taylor_green_time_order, MASS_TOLERANCE,
};

#[test]
fn taylor_green_spatial_order() {
    let study = taylor_green_space_order(&[8, 16], 8).unwrap();
    eprintln!(
        "{}: errors {:?}, orders {:?}",
        study.label, study.errors, study.orders
    );
    assert!(study.min_order() >= 1.8, "{:?}", study.orders);
}

#[test]
fn taylor_green_temporal_order() {
    let study = taylor_green_time_order(16, &[5, 10, 20]).unwrap();
    eprintln!(
        "{}: differences {:?}, orders {:?}",
        study.label, study.errors, study.orders
    );
    assert!((0.9..1.2).contains(&study.orders[0]), "{:?}", study.orders);
}

/// Issue 6: the net continuity imbalance of every converged step ≤ 1e-10 of the flow
/// through the domain.
#[test]
fn mass_conserved_every_step() {
    let check = mass_conservation(16, 10).unwrap();
    eprintln!(
        "worst per-step mass ratio {:.2e} over {} steps",
        check.worst,
        check.ratios.len()
    );
    assert_eq!(check.ratios.len(), 10);
    assert!(check.passed(), "{:?}", check.ratios);
    assert!(check.worst <= MASS_TOLERANCE);
}
