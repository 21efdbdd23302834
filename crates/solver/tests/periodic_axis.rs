//! Periodicity is a property of the grid's axes (`Axis::periodic`): the two-fluid solver
//! takes a periodic x axis of one column (MFIX `CYCLIC_X` on one cell) and refuses a
//! periodic y axis or a periodic x axis of several columns, with an error that says so.

use runout_closures::FrictionModel;
use runout_mesh::{Axis, Grid, Sides};
use runout_solver::two_fluid::{SolidsSpec, TwoFluid, TwoFluidError, TwoFluidSettings};
use runout_solver::{Fluid, SideBc};
use runout_walls::{RobinFace, SolidsWallModel};

mod common;
use common::paper_particles_in_air;

/// A closed box with free-slip sides on `grid`.
fn solver(grid: Grid) -> Result<TwoFluid, TwoFluidError> {
    let gas_walls = Sides::all(SideBc::Wall(RobinFace::ZERO_GRADIENT));
    let spec = SolidsSpec {
        params: paper_particles_in_air(FrictionModel::princeton(), 0.65),
        eps_max: 0.65,
        walls: Sides::all(Some(SolidsWallModel::FreeSlip)),
    };
    let gas = Fluid {
        density: 1.2,
        viscosity: 1.8e-5,
    };
    let settings = TwoFluidSettings::default();
    TwoFluid::new(grid, gas, gas_walls, vec![spec], (0.0, -9.81), settings)
}

fn axis(cells: usize) -> Axis {
    Axis::uniform(0.0, 0.02, cells).unwrap()
}

#[test]
fn only_a_periodic_x_column_of_one_cell_is_accepted() {
    let column = solver(Grid::new(axis(1).periodic(), axis(10))).unwrap();
    assert!(column.grid().periodic_x() && column.scene().periodic_x);
    assert!(
        !solver(Grid::new(axis(3), axis(10)))
            .unwrap()
            .scene()
            .periodic_x
    );

    let wide = solver(Grid::new(axis(3).periodic(), axis(10))).err();
    assert!(matches!(wide, Some(TwoFluidError::PeriodicColumn(3))));
    let periodic_y = solver(Grid::new(axis(1), axis(10).periodic()))
        .err()
        .unwrap();
    assert!(matches!(periodic_y, TwoFluidError::PeriodicY));
    assert!(periodic_y.to_string().contains("y axis cannot be periodic"));
}
