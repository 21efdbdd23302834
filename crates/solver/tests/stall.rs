//! MFIX's stall detection (`DETECT_STALL`, docs/model.md §4.11): a step whose momentum and
//! continuity residual sum stops falling fails at the first 5th outer iteration after the
//! 10th where the sum is not below its value 5 iterations before, instead of iterating to
//! the cap, and the fields are restored so that the step can be retried with a smaller Δt.

use runout_closures::FrictionModel;
use runout_mesh::{Axis, Grid, Sides};
use runout_solver::two_fluid::{SolidsSpec, TwoFluid, TwoFluidSettings};
use runout_solver::{Fluid, SideBc};
use runout_walls::{RobinFace, SolidsWallModel};

mod common;
use common::paper_particles_in_air;

/// A settling suspension in a closed 3 × 20 box (εs = 0.3 in the lower two thirds).
fn suspension(detect_stall: bool) -> TwoFluid {
    let (nx, ny) = (3, 20);
    let grid = Grid::new(
        Axis::uniform(0.0, 0.03, nx).unwrap(),
        Axis::uniform(0.0, 0.2, ny).unwrap(),
    );
    let gas_walls = Sides::all(SideBc::Wall(RobinFace::dirichlet(0.0)));
    let spec = SolidsSpec {
        params: paper_particles_in_air(FrictionModel::princeton(), 0.65),
        eps_max: 0.65,
        walls: Sides::all(Some(SolidsWallModel::NoSlip)),
    };
    let gas = Fluid {
        density: 1.2,
        viscosity: 1.8e-5,
    };
    let settings = TwoFluidSettings {
        detect_stall,
        ..TwoFluidSettings::default()
    };
    let mut tf = TwoFluid::new(
        grid.clone(),
        gas,
        gas_walls,
        vec![spec],
        (0.0, -9.81),
        settings,
    )
    .unwrap();
    tf.state_mut().update_solids(0, |s| {
        for (k, (e, t)) in s.eps.iter_mut().zip(s.theta.iter_mut()).enumerate() {
            if grid.y.centres()[k / nx] < 0.13 {
                *e = 0.3;
            }
            *t = 1e-4;
        }
    });
    tf
}

#[test]
fn a_step_that_cannot_meet_its_tolerance_stops_as_stalled_and_is_undone() {
    // tolerances below round-off: the residual sum falls to its floor and then stops falling
    let (tol, cap) = (1e-300, 500);
    let mut tf = suspension(true);
    let eps0 = tf.solids(0).eps().to_vec();
    let out = tf.step(1e-3, tol, tol, 1e30, cap).unwrap();
    assert!(!out.converged);
    let failure = out.failure.as_deref().unwrap_or("");
    assert!(failure.starts_with("stalled"), "failure: {failure:?}");
    assert!(
        out.iterations >= 15 && out.iterations.is_multiple_of(5) && out.iterations < cap,
        "stopped at outer iteration {}",
        out.iterations
    );
    assert_eq!(
        tf.solids(0).eps(),
        eps0,
        "a failed step restores the fields"
    );

    // without the detection the same step runs to the cap
    let mut tf = suspension(false);
    let out = tf.step(1e-3, tol, tol, 1e30, 60).unwrap();
    assert!(!out.converged);
    assert_eq!(out.iterations, 60);
    assert!(out.failure.is_none(), "{:?}", out.failure);
}
