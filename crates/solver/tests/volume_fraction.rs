//! The solids volume-fraction correction (docs/model.md §4.7): with K_cp = 0 it restores
//! discrete solids continuity exactly; with K_cp > 0 the velocity corrections enter
//! linearly, so the imbalance left is second order in the correction.

use runout_linsolve::{build, LinearSolverKind, Pattern, Stencil5};
use runout_mesh::{Axis, Grid, Segment};
use runout_solver::transport::Scheme;
use runout_solver::volume_fraction::{
    apply_correction, assemble_correction, mass_imbalance, CorrectionInputs,
};

/// A deterministic pseudo-random number in [0, 1) (no dependency needed for a fixture).
fn rand(k: usize, salt: usize) -> f64 {
    let x = ((k * 2654435761 + salt * 40503) % 1_000_003) as f64;
    x / 1_000_003.0
}

fn setup() -> (Grid, Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>) {
    let x = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: 1.0,
            cells: 7,
            growth: 1.1,
        }],
    )
    .unwrap();
    let y = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: 0.5,
            cells: 5,
            growth: 1.2,
        }],
    )
    .unwrap();
    let grid = Grid::new(x, y);
    let (nx, ny) = (grid.nx(), grid.ny());
    let eps: Vec<f64> = (0..nx * ny).map(|k| 0.2 + 0.3 * rand(k, 1)).collect();
    let eps_old: Vec<f64> = (0..nx * ny)
        .map(|k| eps[k] + 0.01 * (rand(k, 2) - 0.5))
        .collect();
    // closed box: zero normal velocity on the walls
    let mut u = vec![0.0; (nx + 1) * ny];
    for j in 0..ny {
        for i in 1..nx {
            u[i + (nx + 1) * j] = 0.2 * (rand(i + 10 * j, 3) - 0.5);
        }
    }
    let mut v = vec![0.0; nx * (ny + 1)];
    for j in 1..ny {
        for i in 0..nx {
            v[i + nx * j] = 0.2 * (rand(i + 10 * j, 4) - 0.5);
        }
    }
    (grid, eps, eps_old, u, v)
}

fn correct(k_cp_value: f64) -> (f64, f64) {
    let (grid, mut eps, eps_old, mut u, mut v) = setup();
    let (nx, ny) = (grid.nx(), grid.ny());
    let n = nx * ny;
    let k_cp: Vec<f64> = (0..n).map(|k| k_cp_value * (1.0 + rand(k, 5))).collect();
    let mut e_u = vec![0.0; (nx + 1) * ny];
    for j in 0..ny {
        for i in 1..nx {
            e_u[i + (nx + 1) * j] = 1e-4 * (1.0 + rand(i + 7 * j, 6));
        }
    }
    let mut e_v = vec![0.0; nx * (ny + 1)];
    for j in 1..ny {
        for i in 0..nx {
            e_v[i + nx * j] = 1e-4 * (1.0 + rand(i + 7 * j, 7));
        }
    }
    let density = 2000.0;
    let dt = 0.01;
    let pattern = Pattern::new(nx, ny).unwrap();
    let mut a = Stencil5::new(pattern.clone());
    let mut imbalance = vec![0.0; n];
    let inputs = CorrectionInputs {
        density,
        eps: &eps,
        eps_old: &eps_old,
        u: &u,
        v: &v,
        e_u: &e_u,
        e_v: &e_v,
        k_cp: &k_cp,
        dt,
        scheme: Scheme::Upwind,
    };
    assemble_correction(&grid, &inputs, &mut imbalance, &mut a);
    let before = imbalance.iter().map(|x| x.abs()).sum::<f64>();
    let mut eps_prime = vec![0.0; n];
    let mut solver = build(&LinearSolverKind::SparseLu);
    solver.set_pattern(&pattern).unwrap();
    solver.setup_and_solve(&a, &mut eps_prime).unwrap();
    apply_correction(
        &grid,
        &mut eps_prime,
        &mut eps,
        1.0,
        0.5,
        &mut u,
        &mut v,
        &e_u,
        &e_v,
        &k_cp,
    );
    let after_inputs = CorrectionInputs {
        density,
        eps: &eps,
        eps_old: &eps_old,
        u: &u,
        v: &v,
        e_u: &e_u,
        e_v: &e_v,
        k_cp: &k_cp,
        dt,
        scheme: Scheme::Upwind,
    };
    mass_imbalance(&grid, &after_inputs, &mut imbalance);
    let after = imbalance.iter().map(|x| x.abs()).sum::<f64>();
    (before, after)
}

#[test]
fn kinematic_correction_restores_continuity_exactly() {
    let (before, after) = correct(0.0);
    assert!(
        before > 1e-3,
        "the fixture must start out of balance: {before}"
    );
    assert!(after <= 1e-12 * before, "{after} vs {before}");
}

#[test]
fn pressure_driven_correction_leaves_a_second_order_imbalance() {
    let (before, after) = correct(1e4);
    eprintln!("imbalance before {before:.3e}, after {after:.3e}");
    assert!(after <= 1e-2 * before, "{after} vs {before}");
}
