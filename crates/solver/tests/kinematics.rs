//! Strain rates from staggered velocities are exact for a linear velocity field on a
//! stretched grid, with and without wall face values.

use runout_mesh::{Axis, Grid, Segment};
use runout_solver::kinematics::{strain_rates, Strain, WallVelocities};

#[test]
fn linear_field_gives_exact_invariants() {
    let (a, b, c, e) = (0.7, -1.3, 0.4, 2.1);
    let x = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: 1.0,
            cells: 6,
            growth: 1.2,
        }],
    )
    .unwrap();
    let y = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: 0.5,
            cells: 5,
            growth: 0.8,
        }],
    )
    .unwrap();
    let grid = Grid::new(x, y);
    let (nx, ny) = (grid.nx(), grid.ny());
    let mut u = vec![0.0; (nx + 1) * ny];
    let mut v = vec![0.0; nx * (ny + 1)];
    for j in 0..ny {
        for i in 0..=nx {
            let (px, py) = grid.u_face_position(i, j);
            u[i + (nx + 1) * j] = a * px + b * py;
        }
    }
    for j in 0..=ny {
        for i in 0..nx {
            let (px, py) = grid.v_face_position(i, j);
            v[i + nx * j] = c * px + e * py;
        }
    }
    let tr_d = a + e;
    let d12 = 0.5 * (b + c);
    let tr_d2 = a * a + e * e + 2.0 * d12 * d12;
    let south: Vec<f64> = grid.x.centres().iter().map(|&px| a * px).collect();
    let north: Vec<f64> = grid
        .x
        .centres()
        .iter()
        .map(|&px| a * px + b * grid.y.end())
        .collect();
    let west: Vec<f64> = grid.y.centres().iter().map(|&py| e * py).collect();
    let east: Vec<f64> = grid
        .y
        .centres()
        .iter()
        .map(|&py| c * grid.x.end() + e * py)
        .collect();
    let with_walls = WallVelocities {
        south: Some(&south),
        north: Some(&north),
        west: Some(&west),
        east: Some(&east),
    };
    for walls in [with_walls, WallVelocities::default()] {
        let mut out = vec![Strain::default(); nx * ny];
        strain_rates(&grid, &u, &v, &walls, &mut out);
        for s in &out {
            assert!((s.tr_d - tr_d).abs() < 1e-12, "{s:?}");
            assert!((s.tr_d2 - tr_d2).abs() < 1e-12, "{s:?}");
            assert!(
                (s.s_ddot_s - (tr_d2 - tr_d * tr_d / 3.0)).abs() < 1e-12,
                "{s:?}"
            );
        }
    }
}
