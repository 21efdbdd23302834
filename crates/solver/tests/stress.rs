//! The explicit stress sources (docs/model.md §4.4) integrate the exact divergence of the
//! non-implicit stress parts for fields where the discrete differences are exact, on a
//! stretched grid: a viscosity linear in x with u = a x, a uniform viscosity with v = c x y,
//! and λ tr D with tr D linear in x.

// index loops mirror the grid formulas
#![allow(clippy::needless_range_loop)]

use runout_closures::FaceMean;
use runout_mesh::{Axis, Grid, Segment};
use runout_solver::momentum::cv_width;
use runout_solver::stress::explicit_stress;

fn grid() -> Grid {
    let x = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: 1.0,
            cells: 7,
            growth: 1.15,
        }],
    )
    .unwrap();
    let y = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: 0.6,
            cells: 5,
            growth: 0.85,
        }],
    )
    .unwrap();
    Grid::new(x, y)
}

struct Fields {
    u: Vec<f64>,
    v: Vec<f64>,
    mu: Vec<f64>,
    lambda: Vec<f64>,
    tr_d: Vec<f64>,
}

fn sources(g: &Grid, f: &Fields) -> (Vec<f64>, Vec<f64>) {
    let (nx, ny) = (g.nx(), g.ny());
    let fixed_u: Vec<bool> = (0..(nx + 1) * ny)
        .map(|k| k % (nx + 1) == 0 || k % (nx + 1) == nx)
        .collect();
    let fixed_v: Vec<bool> = (0..nx * (ny + 1))
        .map(|k| k / nx == 0 || k / nx == ny)
        .collect();
    let mut tau_u = vec![f64::NAN; (nx + 1) * ny];
    let mut tau_v = vec![f64::NAN; nx * (ny + 1)];
    explicit_stress(
        g,
        &f.u,
        &f.v,
        &f.mu,
        FaceMean::Harmonic,
        &f.lambda,
        &f.tr_d,
        &fixed_u,
        &fixed_v,
        &mut tau_u,
        &mut tau_v,
    );
    (tau_u, tau_v)
}

#[test]
fn normal_part_with_variable_viscosity() {
    let g = grid();
    let (nx, ny) = (g.nx(), g.ny());
    let (a, m0, m1) = (0.8, 2.0, 3.0);
    let xc = g.x.centres().to_vec();
    let mut f = Fields {
        u: vec![0.0; (nx + 1) * ny],
        v: vec![0.0; nx * (ny + 1)],
        mu: vec![0.0; nx * ny],
        lambda: vec![0.0; nx * ny],
        tr_d: vec![0.0; nx * ny],
    };
    for j in 0..ny {
        for i in 0..=nx {
            f.u[i + (nx + 1) * j] = a * g.x.faces()[i];
        }
        for i in 0..nx {
            f.mu[i + nx * j] = m0 + m1 * xc[i];
        }
    }
    let (tau_u, tau_v) = sources(&g, &f);
    for j in 0..ny {
        for i in 1..nx {
            // ∂/∂x(μ ∂u/∂x) = a m1, over the control volume
            let want = a * m1 * cv_width(g.x.widths(), i) * g.y.widths()[j];
            let got = tau_u[i + (nx + 1) * j];
            assert!(
                (got - want).abs() < 1e-12 * want.abs().max(1.0),
                "{got} vs {want}"
            );
        }
    }
    assert!(tau_v.iter().all(|t| t.abs() < 1e-12));
}

#[test]
fn shear_part_and_lambda_part() {
    let g = grid();
    let (nx, ny) = (g.nx(), g.ny());
    let (c, mu, lam, t0, t1) = (1.3, 0.7, -0.4, 0.2, 1.7);
    let mut f = Fields {
        u: vec![0.0; (nx + 1) * ny],
        v: vec![0.0; nx * (ny + 1)],
        mu: vec![mu; nx * ny],
        lambda: vec![lam; nx * ny],
        tr_d: vec![0.0; nx * ny],
    };
    let xc = g.x.centres().to_vec();
    for j in 0..=ny {
        for i in 0..nx {
            // v = c x y (zero on the floor, as on a wall)
            f.v[i + nx * j] = c * xc[i] * g.y.faces()[j];
        }
    }
    for j in 0..ny {
        for i in 0..nx {
            f.tr_d[i + nx * j] = t0 + t1 * xc[i];
        }
    }
    let (tau_u, _) = sources(&g, &f);
    for j in 0..ny {
        for i in 1..nx {
            // ∂/∂y(μ ∂v/∂x) = μ c, ∂/∂x(λ tr D) = λ t1; μ ∂u/∂x = 0
            let want = (mu * c + lam * t1) * cv_width(g.x.widths(), i) * g.y.widths()[j];
            let got = tau_u[i + (nx + 1) * j];
            assert!((got - want).abs() < 1e-12, "({i}, {j}): {got} vs {want}");
        }
    }
}
