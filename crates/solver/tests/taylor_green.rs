//! Decaying Taylor–Green vortex in a free-slip box: an exact unsteady Navier–Stokes
//! solution, used as the manufactured solution of issue 6.
//!
//! On [0, 1]², u = sin(πx) cos(πy) F(t), v = −cos(πx) sin(πy) F(t),
//! p = −ρ F²/4 (cos 2πx + cos 2πy), F = exp(−2π² ν t). The normal velocity and the
//! tangential stress vanish on all four sides, so free-slip walls (zero-gradient Robin
//! closure, model-spec §3.2) are exact boundary conditions.
//!
//! Spatial order: the first-order time error of implicit Euler is removed by Richardson
//! extrapolation in time on each grid (2 u(Δt/2) − u(Δt)), then compared with the exact
//! solution. Temporal order: on one grid, the self-convergence ratio of Δt, Δt/2, Δt/4
//! (the spatial error cancels in the differences).

use std::f64::consts::PI;

use runout_linsolve::LinearSolverKind;
use runout_mesh::{Axis, Grid, Sides};
use runout_solver::{Fluid, Scheme, Settings, SideBc, SinglePhase};
use runout_walls::RobinFace;

const RHO: f64 = 1.0;
const MU: f64 = 0.05;
const T_END: f64 = 0.2;

fn decay(t: f64) -> f64 {
    (-2.0 * PI * PI * MU / RHO * t).exp()
}

/// u on the x-faces after integrating to T_END with `steps` steps on an n × n grid.
fn run(n: usize, steps: usize) -> (Grid, Vec<f64>) {
    let grid = Grid::new(
        Axis::uniform(0.0, 1.0, n).unwrap(),
        Axis::uniform(0.0, 1.0, n).unwrap(),
    );
    let slip = SideBc::Wall(RobinFace::ZERO_GRADIENT);
    let bcs = Sides {
        west: slip,
        east: slip,
        south: slip,
        north: slip,
    };
    let settings = Settings {
        scheme: Scheme::Superbee,
        relax_velocity: 0.9,
        relax_pressure: 0.1,
        momentum_solver: LinearSolverKind::SparseLu,
        pressure_solver: LinearSolverKind::SparseLu,
    };
    let mut s = SinglePhase::new(
        grid.clone(),
        Fluid {
            density: RHO,
            viscosity: MU,
        },
        bcs,
        (0.0, 0.0),
        settings,
    )
    .unwrap();
    let (xf, yc) = (grid.x.faces().to_vec(), grid.y.centres().to_vec());
    let (xc, yf) = (grid.x.centres().to_vec(), grid.y.faces().to_vec());
    for (j, &y) in yc.iter().enumerate() {
        for (i, &x) in xf.iter().enumerate() {
            s.u[i + (n + 1) * j] = (PI * x).sin() * (PI * y).cos();
        }
    }
    for (j, &y) in yf.iter().enumerate() {
        for (i, &x) in xc.iter().enumerate() {
            s.v[i + n * j] = -(PI * x).cos() * (PI * y).sin();
        }
    }
    for (j, &y) in yc.iter().enumerate() {
        for (i, &x) in xc.iter().enumerate() {
            s.p[i + n * j] = -RHO / 4.0 * ((2.0 * PI * x).cos() + (2.0 * PI * y).cos());
        }
    }
    let dt = T_END / steps as f64;
    for k in 0..steps {
        let out = s.step(dt, 1e-11, 1e4, 400).unwrap();
        assert!(out.converged, "step {k}: {out:?}");
        // every converged step conserves mass (issue 6: ≤ 1e-10 of the flow through)
        let flow: f64 = s.u.iter().map(|u| u.abs()).sum::<f64>() / n as f64;
        assert!(
            s.mass_imbalance() <= 1e-10 * flow.max(1e-300),
            "{}",
            s.mass_imbalance()
        );
    }
    (grid, s.u)
}

fn max_error_vs_exact(grid: &Grid, u: &[f64]) -> f64 {
    let n = grid.nx();
    let f = decay(T_END);
    let mut e: f64 = 0.0;
    for (j, &y) in grid.y.centres().iter().enumerate() {
        for (i, &x) in grid.x.faces().iter().enumerate() {
            e = e.max((u[i + (n + 1) * j] - (PI * x).sin() * (PI * y).cos() * f).abs());
        }
    }
    e
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

#[test]
fn taylor_green_spatial_order() {
    let mut errors = Vec::new();
    for (n, steps) in [(8, 8), (16, 8)] {
        let (grid, coarse) = run(n, steps);
        let (_, fine) = run(n, 2 * steps);
        let extrapolated: Vec<f64> = fine.iter().zip(&coarse).map(|(f, c)| 2.0 * f - c).collect();
        errors.push(max_error_vs_exact(&grid, &extrapolated));
    }
    let order = (errors[0] / errors[1]).log2();
    eprintln!("Taylor–Green spatial errors {errors:?}, observed order {order:.3}");
    assert!(order >= 1.8, "{order}");
}

#[test]
fn taylor_green_temporal_order() {
    let n = 16;
    let runs: Vec<Vec<f64>> = [5, 10, 20].iter().map(|&steps| run(n, steps).1).collect();
    let order = (max_diff(&runs[0], &runs[1]) / max_diff(&runs[1], &runs[2])).log2();
    eprintln!("Taylor–Green temporal self-convergence order {order:.3}");
    assert!((0.9..1.2).contains(&order), "{order}");
}
