//! Plane Poiseuille flow between partial-slip walls (user h_u, paper Eq. 12) against its
//! closed form ([`runout_solver::verify::poiseuille_order`]). The fully developed profile is
//! an exact solution of the discrete x-direction equations, so the error is that of the
//! wall-normal discretisation and the wall closure.

use runout_solver::verify::{poiseuille_order, ChannelGrid, MASS_TOLERANCE};
use runout_solver::Scheme;

fn check(grid: ChannelGrid, levels: &[usize]) {
    let study = poiseuille_order(grid, levels, Scheme::Superbee).unwrap();
    eprintln!(
        "{}: errors {:?}, observed orders {:?}",
        study.label, study.errors, study.orders
    );
    assert!(study.min_order() >= 1.8, "{:?}", study.orders);
    assert!(study.worst_mass_ratio() <= MASS_TOLERANCE, "{study:?}");
}

#[test]
fn poiseuille_partial_slip_second_order_uniform() {
    check(ChannelGrid::Uniform, &[8, 16, 32]);
}

#[test]
fn poiseuille_partial_slip_second_order_stretched() {
    // cells per half; refinement halves every cell (growth 1.2, 1.2^½, 1.2^¼)
    check(ChannelGrid::Stretched { growth: 1.2 }, &[4, 8, 16]);
}
