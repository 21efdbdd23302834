//! The solids hold one wall table per phase (`SolidsSpec::walls`): a wall model on each wall
//! side, `None` on an outlet. The solver refuses a phase whose sides are not walls exactly
//! where the gas's are, and tells the per-face models (docs/model.md §3.5–3.8) from the
//! fixed ones.

use runout_closures::FrictionModel;
use runout_mesh::{Axis, Grid, Side, Sides};
use runout_solver::two_fluid::{SolidsSpec, TwoFluid, TwoFluidError, TwoFluidSettings};
use runout_solver::{Fluid, SideBc};
use runout_walls::{RobinFace, SolidsWallModel};

mod common;
use common::paper_particles_in_air;

/// A 3 × 10 box with the gas conditions `gas_walls` and the solids walls `walls`.
fn solver(
    gas_walls: Sides<SideBc>,
    walls: Sides<Option<SolidsWallModel>>,
) -> Result<TwoFluid, TwoFluidError> {
    let axis = |cells| Axis::uniform(0.0, 0.03, cells).unwrap();
    let spec = SolidsSpec {
        params: paper_particles_in_air(FrictionModel::princeton(), 0.65),
        eps_max: 0.65,
        walls,
    };
    let gas = Fluid {
        density: 1.2,
        viscosity: 1.8e-5,
    };
    let grid = Grid::new(axis(3), axis(10));
    let settings = TwoFluidSettings::default();
    TwoFluid::new(grid, gas, gas_walls, vec![spec], (0.0, -9.81), settings)
}

/// Free-slip gas walls with an outlet on top.
fn open_top() -> Sides<SideBc> {
    Sides {
        north: SideBc::Outlet(0.0),
        ..Sides::all(SideBc::Wall(RobinFace::ZERO_GRADIENT))
    }
}

#[test]
fn a_solids_side_must_be_a_wall_exactly_where_the_gas_side_is() {
    let jj = SolidsWallModel::johnson_jackson(0.1, 0.7, 11.0, 0.0).unwrap();
    let matching = Sides {
        south: Some(jj),
        north: None,
        ..Sides::all(Some(SolidsWallModel::FreeSlip))
    };
    let tf = solver(open_top(), matching.clone()).unwrap();
    assert!(tf.has_floor_model(0));

    let outlet_under_gas_wall = Sides {
        west: None,
        ..matching.clone()
    };
    let e = solver(open_top(), outlet_under_gas_wall).err().unwrap();
    assert!(matches!(
        e,
        TwoFluidError::SolidsSideMismatch {
            phase: 1,
            side: "west",
            ..
        }
    ));
    assert_eq!(
        e.to_string(),
        "solids phase 1: the west side is an outlet for the solids but a wall for the gas; a \
         side is a wall or an outlet for every phase"
    );

    let wall_under_gas_outlet = Sides {
        north: Some(SolidsWallModel::NoSlip),
        ..matching
    };
    let e = solver(open_top(), wall_under_gas_outlet).err().unwrap();
    assert!(e
        .to_string()
        .contains("north side is a wall for the solids"));
}

#[test]
fn only_the_state_dependent_models_are_evaluated_per_face() {
    let jj = SolidsWallModel::johnson_jackson(0.1, 0.7, 11.0, 0.0).unwrap();
    let spec = SolidsSpec {
        params: paper_particles_in_air(FrictionModel::princeton(), 0.65),
        eps_max: 0.65,
        walls: Sides {
            west: Some(SolidsWallModel::NoSlip),
            east: Some(SolidsWallModel::partial_slip(10.0, 0.0, 10.0, 0.01, 1.0).unwrap()),
            south: Some(jj),
            north: None,
        },
    };
    assert_eq!(spec.wall(Side::South), Some(&jj));
    assert_eq!(spec.per_face_model(Side::South), Some(&jj));
    assert_eq!(spec.wall(Side::North), None);
    for side in [Side::West, Side::East, Side::North] {
        assert_eq!(spec.per_face_model(side), None, "{side:?}");
    }
}
