//! The variable-coefficient momentum assembly (`runout_solver::momentum`) on a problem with
//! a closed form: steady Couette flow through two layers of different viscosity. The shear
//! stress is the same in both layers, so u is piecewise linear with slopes τ/μ₁ and τ/μ₂;
//! with the interface on a cell face and harmonic face viscosities (docs/model.md §4.1) the
//! discrete solution is exact up to round-off.

use runout_linsolve::{build, LinearSolverKind, Pattern, Stencil5};
use runout_mesh::{Axis, Grid, Segment, Sides};
use runout_solver::momentum::{assemble_u, Context, PhaseFields};
use runout_solver::{FaceData, Scheme, SideBc};
use runout_walls::RobinFace;

#[test]
fn two_layer_couette_is_exact() {
    let (mu_low, mu_high, lid, height) = (2.0, 0.5, 1.5, 1.0);
    let (nx, ny) = (3, 10);
    // stretched cells, with the interface at y = 0.4 on a face
    let y = Axis::from_segments(
        0.0,
        &[
            Segment::Geometric {
                length: 0.4,
                cells: 4,
                growth: 1.2,
            },
            Segment::Geometric {
                length: 0.6,
                cells: 6,
                growth: 0.9,
            },
        ],
    )
    .unwrap();
    let grid = Grid::new(Axis::uniform(0.0, 1.0, nx).unwrap(), y);
    let interface = 0.4;
    let viscosity: Vec<f64> = (0..nx * ny)
        .map(|k| {
            if grid.y.centres()[k / nx] < interface {
                mu_low
            } else {
                mu_high
            }
        })
        .collect();
    let ones = vec![1.0; nx * ny];
    // open ends at equal pressure: no x variation; floor at rest, lid moving
    let bcs = Sides {
        west: SideBc::Outlet(0.0),
        east: SideBc::Outlet(0.0),
        south: SideBc::Wall(RobinFace::dirichlet(0.0)),
        north: SideBc::Wall(RobinFace::dirichlet(lid)),
    };
    let pressure = vec![0.0; nx * ny];
    let ctx = Context {
        grid: &grid,
        bcs: &bcs,
        gravity: (0.0, 0.0),
        dt: f64::INFINITY,
        scheme: Scheme::Superbee,
        gas_pressure: &pressure,
        wall_faces: None,
    };
    let phase = PhaseFields {
        bulk_density: &ones,
        bulk_density_old: &ones,
        volume_fraction: &ones,
        viscosity: &viscosity,
        solids_pressure: None,
        plastic_pressure: None,
        explicit_source: None,
        skip: None,
    };
    let pattern = Pattern::new(nx + 1, ny).unwrap();
    let mut a = Stencil5::new(pattern.clone());
    let mut faces = FaceData::zeros(nx + 1, ny);
    let mut u = vec![0.0; (nx + 1) * ny];
    let v = vec![0.0; nx * (ny + 1)];
    let old = u.clone();
    assemble_u(&ctx, &phase, &u, &v, &old, &mut faces, &mut a);
    let mut solver = build(&LinearSolverKind::SparseLu);
    solver.set_pattern(&pattern).unwrap();
    solver.setup_and_solve(&a, &mut u).unwrap();
    // exact: τ = lid / (h₁/μ₁ + h₂/μ₂)
    let tau = lid / (interface / mu_low + (height - interface) / mu_high);
    let exact = |y: f64| {
        if y < interface {
            tau * y / mu_low
        } else {
            tau * interface / mu_low + tau * (y - interface) / mu_high
        }
    };
    let mut err: f64 = 0.0;
    for (j, &yc) in grid.y.centres().iter().enumerate() {
        for i in 0..=nx {
            err = err.max((u[i + (nx + 1) * j] - exact(yc)).abs());
        }
    }
    assert!(err < 1e-12, "max error {err}");
}
