//! Plane Poiseuille flow between partial-slip walls (user h_u, paper Eq. 12 for the gas):
//! pressure inlet and outlet at the ends, walls at y = 0 and y = H.
//!
//! Closed form: with G = (p_in − p_out)/L and the Robin condition du/dn + h u = 0 at both
//! walls (n from the fluid into the wall), u(y) = G/(2μ) [y (H − y) + H/h]
//! (u'(0) = G H/(2μ) = h u(0)). The fully developed profile is an exact solution of the
//! discrete x-direction equations, so the error is that of the wall-normal discretisation
//! and the wall closure; observed orders are measured on uniform and stretched grids.

use runout_linsolve::LinearSolverKind;
use runout_mesh::{Axis, Grid, Segment, Sides};
use runout_solver::{Fluid, Scheme, Settings, SideBc, SinglePhase};
use runout_walls::RobinFace;

const H: f64 = 1.0;
const L: f64 = 2.0;
const MU: f64 = 0.5;
const RHO: f64 = 1.0;
const DP: f64 = 1.0;
const H_SLIP: f64 = 4.0;

fn exact(y: f64) -> f64 {
    DP / L / (2.0 * MU) * (y * (H - y) + H / H_SLIP)
}

/// Max |u − exact| over the cell centres of the middle column, for a y axis.
fn error(y: Axis) -> f64 {
    let grid = Grid::new(Axis::uniform(0.0, L, 4).unwrap(), y);
    let wall = SideBc::Wall(RobinFace::partial_slip(H_SLIP, 0.0));
    let bcs = Sides {
        west: SideBc::Outlet(DP),
        east: SideBc::Outlet(0.0),
        south: wall,
        north: wall,
    };
    // Direct solves, so that the outer iterations converge to round-off; SIMPLE's
    // relaxation pair with ω_p = 1 − ω_u (Patankar 1980 §6.7) converges fastest here.
    let settings = Settings {
        scheme: Scheme::Superbee,
        relax_velocity: 0.9,
        relax_pressure: 0.1,
        momentum_solver: LinearSolverKind::SparseLu,
        pressure_solver: LinearSolverKind::SparseLu,
    };
    let mut s = SinglePhase::new(
        grid,
        Fluid {
            density: RHO,
            viscosity: MU,
        },
        bcs,
        (0.0, 0.0),
        settings,
    )
    .unwrap();
    let report = s.solve_steady(20_000, 1e-9, 1.0).unwrap();
    assert!(report.converged, "{report:?}");
    let g = s.grid();
    let i = 2; // middle x-face
    let mut err: f64 = 0.0;
    for (j, &y) in g.y.centres().iter().enumerate() {
        err = err.max((s.u[i + (g.nx() + 1) * j] - exact(y)).abs());
    }
    // the wall face value of the closure, too
    let u0 = RobinFace::partial_slip(H_SLIP, 0.0).face_value(s.u[i], g.y.widths()[0]);
    err.max((u0 - exact(0.0)).abs())
}

/// Symmetric stretched axis: cells grow by `growth` from each wall to the middle.
fn stretched(cells_per_half: usize, growth: f64) -> Axis {
    Axis::from_segments(
        0.0,
        &[
            Segment::Geometric {
                length: 0.5 * H,
                cells: cells_per_half,
                growth,
            },
            Segment::Geometric {
                length: 0.5 * H,
                cells: cells_per_half,
                growth: 1.0 / growth,
            },
        ],
    )
    .unwrap()
}

fn orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect()
}

#[test]
fn poiseuille_partial_slip_second_order_uniform() {
    let errors: Vec<f64> = [8, 16, 32]
        .iter()
        .map(|&n| error(Axis::uniform(0.0, H, n).unwrap()))
        .collect();
    let p = orders(&errors);
    eprintln!("uniform: errors {errors:?}, observed orders {p:?}");
    assert!(p.iter().all(|&o| o >= 1.8), "{p:?}");
}

#[test]
fn poiseuille_partial_slip_second_order_stretched() {
    // refinement halves every cell: double the count, square-root the growth
    let levels = [(4, 1.2f64), (8, 1.2f64.sqrt()), (16, 1.2f64.sqrt().sqrt())];
    let errors: Vec<f64> = levels
        .iter()
        .map(|&(n, g)| error(stretched(n, g)))
        .collect();
    let p = orders(&errors);
    eprintln!("stretched: errors {errors:?}, observed orders {p:?}");
    assert!(p.iter().all(|&o| o >= 1.8), "{p:?}");
}
