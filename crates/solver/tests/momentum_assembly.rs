//! The variable-coefficient momentum assembly (`runout_solver::momentum`) on a problem with
//! a closed form: steady Couette flow through two layers of different viscosity. The shear
//! stress is the same in both layers, so u is piecewise linear with slopes τ/μ₁ and τ/μ₂;
//! with the interface on a cell face and harmonic face viscosities (docs/model.md §4.1) the
//! discrete solution is exact up to round-off.

use runout_linsolve::{build, LinearSolverKind, Pattern, Stencil5};
use runout_mesh::{Axis, Grid, Segment, Sides};
use runout_solver::momentum::{assemble, Context, PhaseFields};
use runout_solver::staggered::Component;
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
    let [cu, _] = Component::of_grid(&grid);
    assemble(&ctx, &phase, cu, &u, &v, &old, &mut faces, &mut a);
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

/// u and v are one equation (docs/model.md §4.4): the v system of the transposed problem
/// (x ↔ y in the grid, the fields, gravity and the sides) is the u system with its
/// neighbours renamed (east ↔ north, west ↔ south), up to the order of the products of
/// widths (relative 1e-14). Stretched cells, Superbee, variable ρε, ε, μ, P_s, P*, an
/// explicit source, a wall end, an outlet end with hydrostatic pressure, a no-slip and a
/// partial-slip wall exercise every term of `assemble`.
#[test]
fn v_of_the_transposed_problem_is_u() {
    let (nx, ny) = (5, 4);
    let x = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: 1.0,
            cells: nx,
            growth: 1.15,
        }],
    )
    .unwrap();
    let y = Axis::from_segments(
        0.5,
        &[Segment::Geometric {
            length: 0.8,
            cells: ny,
            growth: 0.9,
        }],
    )
    .unwrap();
    let grid = Grid::new(x.clone(), y.clone());
    let grid_t = Grid::new(y, x);
    // a smooth, non-symmetric cell field and its transpose
    let field = |scale: f64, shift: f64| -> (Vec<f64>, Vec<f64>) {
        let f = |i: usize, j: usize| {
            scale * (1.0 + 0.3 * (i as f64 + shift).sin() + 0.2 * (j as f64 * 1.7).cos())
        };
        let a = (0..nx * ny).map(|k| f(k % nx, k / nx)).collect();
        let t = (0..nx * ny).map(|k| f(k / ny, k % ny)).collect();
        (a, t)
    };
    let (rho, rho_t) = field(900.0, 0.1);
    let (rho_old, rho_old_t) = field(880.0, 0.4);
    let (eps, eps_t) = field(0.4, 0.9);
    let (mu, mu_t) = field(0.02, 1.3);
    let (p_g, p_g_t) = field(1e3, 2.1);
    let (p_s, p_s_t) = field(50.0, 0.7);
    let (p_star, p_star_t) = field(5.0, 1.9);
    // u nodes (nx+1) × ny and v nodes of the transposed grid ny × (nx+1), same values
    let mu_nodes = (nx + 1) * ny;
    let node_t = |k: usize| (k / (nx + 1)) + ny * (k % (nx + 1));
    let u: Vec<f64> = (0..mu_nodes)
        .map(|k| 0.3 * (k as f64 * 0.37).sin())
        .collect();
    let v: Vec<f64> = (0..nx * (ny + 1))
        .map(|k| 0.2 * (k as f64 * 0.53).cos())
        .collect();
    let old: Vec<f64> = u.iter().map(|x| 0.9 * x + 0.01).collect();
    let tau: Vec<f64> = (0..mu_nodes)
        .map(|k| 1e-3 * (k as f64 * 0.11).sin())
        .collect();
    let transpose_nodes = |f: &[f64]| {
        let mut t = vec![0.0; f.len()];
        (0..f.len()).for_each(|k| t[node_t(k)] = f[k]);
        t
    };
    // v of the original is u of the transposed: v node (i, j) → u node (j, i) on ny+1 × nx
    let v_t: Vec<f64> = {
        let mut t = vec![0.0; v.len()];
        (0..v.len()).for_each(|k| t[k / nx + (ny + 1) * (k % nx)] = v[k]);
        t
    };
    let (u_t, old_t, tau_t) = (
        transpose_nodes(&u),
        transpose_nodes(&old),
        transpose_nodes(&tau),
    );
    let wall = |h: f64| SideBc::Wall(RobinFace::partial_slip(h, 0.1));
    let outlet = SideBc::HydrostaticOutlet {
        p0: 200.0,
        density: 1.2,
    };
    let bcs = Sides {
        west: wall(f64::INFINITY),
        east: outlet,
        south: SideBc::Wall(RobinFace::dirichlet(0.0)),
        north: wall(30.0),
    };
    let bcs_t = Sides {
        west: bcs.south,
        east: bcs.north,
        south: bcs.west,
        north: bcs.east,
    };
    let assemble_one = |grid: &Grid,
                        bcs: &Sides<SideBc>,
                        gravity: (f64, f64),
                        fields: [&[f64]; 7],
                        tau: &[f64],
                        (u, v, old): (&[f64], &[f64], &[f64]),
                        c: Component|
     -> Stencil5 {
        let [rho, rho_old, eps, mu, p_g, p_s, p_star] = fields;
        let ctx = Context {
            grid,
            bcs,
            gravity,
            dt: 1e-3,
            scheme: Scheme::Superbee,
            gas_pressure: p_g,
            wall_faces: None,
        };
        let phase = PhaseFields {
            bulk_density: rho,
            bulk_density_old: rho_old,
            volume_fraction: eps,
            viscosity: mu,
            solids_pressure: Some(p_s),
            plastic_pressure: Some(p_star),
            explicit_source: Some(tau),
            skip: None,
        };
        let (mx, my) = (c.cells_along_across().0 + 1, c.cells_along_across().1);
        let (mx, my) = if c == Component::of_grid(grid)[0] {
            (mx, my)
        } else {
            (my, mx)
        };
        let mut pattern = Pattern::new(mx, my).unwrap();
        // the wall end of the line (west for u, south for v) is fixed
        for b in 0..c.cells_along_across().1 {
            let (i, j) = c.xy(0, b);
            pattern.fix(i, j).unwrap();
        }
        let mut a = Stencil5::new(pattern);
        let mut faces = FaceData::zeros(mx, my);
        assemble(&ctx, &phase, c, u, v, old, &mut faces, &mut a);
        a
    };
    let [cu, _] = Component::of_grid(&grid);
    let [_, cv_t] = Component::of_grid(&grid_t);
    let a_u = assemble_one(
        &grid,
        &bcs,
        (2.0, -9.0),
        [&rho, &rho_old, &eps, &mu, &p_g, &p_s, &p_star],
        &tau,
        (&u, &v, &old),
        cu,
    );
    let a_v = assemble_one(
        &grid_t,
        &bcs_t,
        (-9.0, 2.0),
        [&rho_t, &rho_old_t, &eps_t, &mu_t, &p_g_t, &p_s_t, &p_star_t],
        &tau_t,
        (&v_t, &u_t, &old_t),
        cv_t,
    );
    let close = |x: f64, y: f64| (x - y).abs() <= 1e-14 * x.abs().max(y.abs()).max(1e-300);
    let mut nonzero = [0; 6];
    for k in 0..mu_nodes {
        let kt = node_t(k);
        let pairs = [
            (a_u.a_p[k], a_v.a_p[kt]),
            (a_u.a_e[k], a_v.a_n[kt]),
            (a_u.a_w[k], a_v.a_s[kt]),
            (a_u.a_n[k], a_v.a_e[kt]),
            (a_u.a_s[k], a_v.a_w[kt]),
            (a_u.b[k], a_v.b[kt]),
        ];
        for (n, (x, y)) in pairs.into_iter().enumerate() {
            assert!(close(x, y), "node {k}, coefficient {n}: u {x} v {y}");
            nonzero[n] += usize::from(x != 0.0);
        }
    }
    // every coefficient takes part somewhere
    assert!(nonzero.iter().all(|&n| n > 0), "{nonzero:?}");
}
