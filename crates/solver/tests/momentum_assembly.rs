//! The variable-coefficient momentum assembly (`runout_solver::momentum`) on a problem with
//! a closed form: steady Couette flow through two layers of different viscosity. The shear
//! stress is the same in both layers, so u is piecewise linear with slopes τ/μ₁ and τ/μ₂;
//! with the interface on a cell face and harmonic face viscosities (docs/model.md §4.1) the
//! discrete solution is exact up to round-off.

use runout_closures::FaceMean;
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
        bent_floor: None,
        dt: f64::INFINITY,
        scheme: Scheme::Superbee,
        gas_pressure: &pressure,
        wall_faces: None,
        form: runout_solver::momentum::MomentumForm::ContinuitySubtracted,
    };
    let phase = PhaseFields {
        bulk_density: &ones,
        bulk_density_old: &ones,
        volume_fraction: &ones,
        viscosity: &viscosity,
        viscosity_mean: FaceMean::Harmonic,
        solids_pressure: None,
        plastic_pressure: None,
        explicit_source: None,
        skip: None,
        velocity_along: None,
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

/// A momentum problem on a grid: the cell fields (ρε, ρε⁰, ε, μ, P_g, P_s, P*), the
/// velocities, the old velocity and explicit source of the assembled component, the sides
/// and gravity.
struct Problem {
    grid: Grid,
    bcs: Sides<SideBc>,
    gravity: (f64, f64),
    cells: [Vec<f64>; 7],
    u: Vec<f64>,
    v: Vec<f64>,
    old: Vec<f64>,
    tau: Vec<f64>,
}

impl Problem {
    /// Stretched cells, variable fields, a no-slip wall end (west), a hydrostatic outlet end
    /// (east), a no-slip floor and a partial-slip lid.
    fn new(nx: usize, ny: usize) -> Problem {
        let geometric = |origin, length, cells, growth| {
            Axis::from_segments(
                origin,
                &[Segment::Geometric {
                    length,
                    cells,
                    growth,
                }],
            )
            .unwrap()
        };
        let grid = Grid::new(geometric(0.0, 1.0, nx, 1.15), geometric(0.5, 0.8, ny, 0.9));
        let cell_field = |scale: f64, shift: f64| -> Vec<f64> {
            let f =
                |i: f64, j: f64| scale * (1.0 + 0.3 * (i + shift).sin() + 0.2 * (1.7 * j).cos());
            (0..nx * ny)
                .map(|k| f((k % nx) as f64, (k / nx) as f64))
                .collect()
        };
        let node_field = |n: usize, f: &dyn Fn(f64) -> f64| (0..n).map(|k| f(k as f64)).collect();
        let n_u = (nx + 1) * ny;
        Problem {
            bcs: Sides {
                west: SideBc::Wall(RobinFace::dirichlet(0.0)),
                east: SideBc::HydrostaticOutlet {
                    p0: 200.0,
                    density: 1.2,
                },
                south: SideBc::Wall(RobinFace::dirichlet(0.0)),
                north: SideBc::Wall(RobinFace::partial_slip(30.0, 0.1)),
            },
            gravity: (2.0, -9.0),
            cells: [
                cell_field(900.0, 0.1),
                cell_field(880.0, 0.4),
                cell_field(0.4, 0.9),
                cell_field(0.02, 1.3),
                cell_field(1e3, 2.1),
                cell_field(50.0, 0.7),
                cell_field(5.0, 1.9),
            ],
            u: node_field(n_u, &|k| 0.3 * (0.37 * k).sin()),
            v: node_field(nx * (ny + 1), &|k| 0.2 * (0.53 * k).cos()),
            old: node_field(n_u, &|k| 0.9 * 0.3 * (0.37 * k).sin() + 0.01),
            tau: node_field(n_u, &|k| 1e-3 * (0.11 * k).sin()),
            grid,
        }
    }

    /// The same problem with x and y exchanged (u becomes v; `old` and `tau` belong to
    /// the component along the new y).
    fn transposed(&self) -> Problem {
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        // a block of n0 × n1 values, index i + n0 j, read as n1 × n0
        let swap = |f: &[f64], n0: usize, n1: usize| -> Vec<f64> {
            (0..f.len()).map(|k| f[k / n1 + n0 * (k % n1)]).collect()
        };
        Problem {
            grid: Grid::new(self.grid.y.clone(), self.grid.x.clone()),
            bcs: Sides {
                west: self.bcs.south,
                east: self.bcs.north,
                south: self.bcs.west,
                north: self.bcs.east,
            },
            gravity: (self.gravity.1, self.gravity.0),
            cells: self.cells.clone().map(|f| swap(&f, nx, ny)),
            u: swap(&self.v, nx, ny + 1),
            v: swap(&self.u, nx + 1, ny),
            old: swap(&self.old, nx + 1, ny),
            tau: swap(&self.tau, nx + 1, ny),
        }
    }

    /// The system of component `c` in `form`, the low end of its lines fixed (a wall end).
    fn assemble(&self, c: Component, form: runout_solver::momentum::MomentumForm) -> Stencil5 {
        let [rho, rho_old, eps, mu, p_g, p_s, p_star] = &self.cells;
        let ctx = Context {
            grid: &self.grid,
            bcs: &self.bcs,
            gravity: self.gravity,
            bent_floor: None,
            dt: 1e-3,
            scheme: Scheme::Superbee,
            gas_pressure: p_g,
            wall_faces: None,
            form,
        };
        let phase = PhaseFields {
            bulk_density: rho,
            bulk_density_old: rho_old,
            volume_fraction: eps,
            viscosity: mu,
            viscosity_mean: FaceMean::Harmonic,
            solids_pressure: Some(p_s),
            plastic_pressure: Some(p_star),
            explicit_source: Some(&self.tau),
            skip: None,
            velocity_along: None,
        };
        let (n_along, n_across) = c.cells_along_across();
        let (mx, my) = c.xy(n_along + 1, n_across);
        let mut pattern = Pattern::new(mx, my).unwrap();
        for b in 0..n_across {
            let (i, j) = c.xy(0, b);
            pattern.fix(i, j).unwrap();
        }
        let mut a = Stencil5::new(pattern);
        let mut faces = FaceData::zeros(mx, my);
        assemble(
            &ctx, &phase, c, &self.u, &self.v, &self.old, &mut faces, &mut a,
        );
        a
    }
}

/// u and v are one equation (docs/model.md §4.4): the v system of the transposed problem
/// (x ↔ y in the grid, the fields, gravity and the sides) is the u system with its
/// neighbours renamed (east ↔ north, west ↔ south), up to the order of the products of
/// widths (relative 1e-14). Stretched cells, Superbee, variable ρε, ε, μ, P_s, P*, an
/// explicit source, a wall end, an outlet end with hydrostatic pressure, a no-slip floor and
/// a partial-slip lid exercise every term of `assemble`, in both forms of docs/model.md §4.3.
#[test]
fn v_of_the_transposed_problem_is_u() {
    use runout_solver::momentum::MomentumForm;
    for form in [
        MomentumForm::ContinuitySubtracted,
        MomentumForm::Conservative,
    ] {
        v_of_the_transposed_problem_is_u_in(form);
    }
}

fn v_of_the_transposed_problem_is_u_in(form: runout_solver::momentum::MomentumForm) {
    let (nx, ny) = (5, 4);
    let problem = Problem::new(nx, ny);
    let transposed = problem.transposed();
    let a_u = problem.assemble(Component::of_grid(&problem.grid)[0], form);
    let a_v = transposed.assemble(Component::of_grid(&transposed.grid)[1], form);
    let close = |x: f64, y: f64| (x - y).abs() <= 1e-14 * x.abs().max(y.abs()).max(1e-300);
    let mut nonzero = [0; 6];
    for k in 0..(nx + 1) * ny {
        // u node (i, j) is v node (j, i) of the transposed grid
        let kt = k / (nx + 1) + ny * (k % (nx + 1));
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

/// A bent floor (docs/model.md §9) enters the sources as the potential's difference between
/// the cells beside a u node, −g cos α(x) at a v node, and the centrifugal −κ ū² at a v node
/// (ū the mean of the four u nodes around it): on an arc (κ = 1/R) with a uniform u, each
/// interior row's source is its mass times those, to round-off.
#[test]
fn bent_floor_sources_are_its_gravity_and_the_centrifugal_force() {
    use runout_solver::bent_floor::BentFloor;
    let (nx, ny) = (4, 3);
    let grid = Grid::new(
        Axis::uniform(10.0, 12.0, nx).unwrap(),
        Axis::uniform(0.0, 0.3, ny).unwrap(),
    );
    let floor = BentFloor::new(9.81, 40.0, 0.0, 10.0, 4.0).unwrap();
    let (rho_eps, speed) = (1200.0, 3.0);
    let bulk = vec![rho_eps; nx * ny];
    let ones = vec![1.0; nx * ny];
    let zeros = vec![0.0; nx * ny];
    let bcs = Sides::all(SideBc::Wall(RobinFace::partial_slip(0.0, 0.0)));
    let u = vec![speed; (nx + 1) * ny];
    let v = vec![0.0; nx * (ny + 1)];
    let sources = |along: Option<&[f64]>, component: usize| {
        let ctx = Context {
            grid: &grid,
            bcs: &bcs,
            gravity: (0.0, 0.0),
            bent_floor: Some(&floor),
            dt: f64::INFINITY,
            scheme: Scheme::Upwind,
            gas_pressure: &zeros,
            wall_faces: None,
            form: runout_solver::momentum::MomentumForm::ContinuitySubtracted,
        };
        let phase = PhaseFields {
            bulk_density: &bulk,
            bulk_density_old: &bulk,
            volume_fraction: &ones,
            viscosity: &zeros,
            viscosity_mean: FaceMean::Harmonic,
            solids_pressure: None,
            plastic_pressure: None,
            explicit_source: None,
            skip: None,
            velocity_along: along,
        };
        let comp = Component::of_grid(&grid)[component];
        let (mx, my) = if component == 0 {
            (nx + 1, ny)
        } else {
            (nx, ny + 1)
        };
        let mut a = Stencil5::new(Pattern::new(mx, my).unwrap());
        let mut faces = FaceData::zeros(mx, my);
        let old = if component == 0 { u.clone() } else { v.clone() };
        assemble(&ctx, &phase, comp, &u, &v, &old, &mut faces, &mut a);
        a.b.clone()
    };
    let (dx, dy) = (0.5, 0.1);
    let xc = grid.x.centres();
    let yc = grid.y.centres();
    // u nodes between two cells: the potential's difference
    let b_u = sources(None, 0);
    for j in 0..ny {
        for i in 1..nx {
            let expected = rho_eps * dx * dy * floor.force_x_between(xc[i - 1], xc[i], yc[j]);
            let got = b_u[i + (nx + 1) * j];
            assert!(
                (got - expected).abs() < 1e-9 * expected.abs(),
                "u ({i}, {j}): {got} vs {expected}"
            );
        }
    }
    // v nodes between two rows: −g cos α, then the centrifugal force of u = 3 m/s on κ = 1/4
    let (b_plain, b_turning) = (sources(None, 1), sources(Some(&u), 1));
    for j in 1..ny {
        for (i, &x) in xc.iter().enumerate() {
            let k = i + nx * j;
            let mass = rho_eps * dx * dy;
            let gravity = -9.81 * floor.angle(x).cos();
            assert!((b_plain[k] - mass * gravity).abs() < 1e-9 * mass);
            let centrifugal = -speed * speed / 4.0;
            assert!(
                (b_turning[k] - mass * (gravity + centrifugal)).abs() < 1e-9 * mass,
                "v ({i}, {j}): {} vs {}",
                b_turning[k],
                mass * (gravity + centrifugal)
            );
        }
    }
}

/// The conservative form (docs/model.md §4.3, `MomentumForm::Conservative`) against the
/// conservative balance written out independently: for every free u node, with upwind face
/// values and no stress or source,
///
///   a_P u_P − Σ a_nb u_nb − b = (m u_P − m⁰ u_P⁰)/Δt + Σ_f F_f u_upwind(f),
///
/// m the control volume's mass (half of each cell beside it), F_f its face mass fluxes
/// (out positive; the mean of the scalar faces' ρε_upwind u A at its x-faces, half of each
/// cell's ρε_upwind v A at its y-faces). The bulk densities of the two time levels do not
/// satisfy continuity with the velocities, so the remainder takes both signs; the
/// continuity-subtracted row misses the balance by r u_P.
#[test]
fn the_conservative_form_is_the_conservative_balance() {
    use runout_solver::momentum::MomentumForm;
    let (nx, ny) = (6, 5);
    let problem = Problem::new(nx, ny);
    let grid = &problem.grid;
    let [rho, rho_old, eps, ..] = &problem.cells;
    let zeros = vec![0.0; nx * ny];
    let bcs = Sides::all(SideBc::Wall(RobinFace::partial_slip(0.0, 0.0)));
    // no flow through the walls
    let mut u = problem.u.clone();
    for j in 0..ny {
        u[(nx + 1) * j] = 0.0;
        u[nx + (nx + 1) * j] = 0.0;
    }
    let mut v = problem.v.clone();
    for i in 0..nx {
        v[i] = 0.0;
        v[i + nx * ny] = 0.0;
    }
    let dt = 1e-3;
    let rows = |form| {
        let ctx = Context {
            grid,
            bcs: &bcs,
            gravity: (0.0, 0.0),
            bent_floor: None,
            dt,
            scheme: Scheme::Upwind,
            gas_pressure: &zeros,
            wall_faces: None,
            form,
        };
        let phase = PhaseFields {
            bulk_density: rho,
            bulk_density_old: rho_old,
            volume_fraction: eps,
            viscosity: &zeros,
            viscosity_mean: FaceMean::Harmonic,
            solids_pressure: None,
            plastic_pressure: None,
            explicit_source: None,
            skip: None,
            velocity_along: None,
        };
        let mut pattern = Pattern::new(nx + 1, ny).unwrap();
        for j in 0..ny {
            pattern.fix(0, j).unwrap();
            pattern.fix(nx, j).unwrap();
        }
        let mut a = Stencil5::new(pattern);
        let mut faces = FaceData::zeros(nx + 1, ny);
        let [cu, _] = Component::of_grid(grid);
        assemble(&ctx, &phase, cu, &u, &v, &problem.old, &mut faces, &mut a);
        a
    };
    let residual = |a: &Stencil5, k: usize| {
        let mx = nx + 1;
        let at = |kk: Option<usize>| kk.map_or(0.0, |kk| u[kk]);
        let (i, j) = (k % mx, k / mx);
        a.a_p[k] * u[k]
            - a.a_e[k] * at((i + 1 < mx).then(|| k + 1))
            - a.a_w[k] * at(i.checked_sub(1).map(|_| k - 1))
            - a.a_n[k] * at((j + 1 < ny).then(|| k + mx))
            - a.a_s[k] * at(j.checked_sub(1).map(|_| k - mx))
            - a.b[k]
    };
    let (conservative, subtracted) = (
        rows(MomentumForm::Conservative),
        rows(MomentumForm::ContinuitySubtracted),
    );
    let (mut positive, mut negative, mut worst, mut subtracted_worst) = (0, 0, 0.0_f64, 0.0_f64);
    for j in 0..ny {
        for i in 1..nx {
            let k = i + (nx + 1) * j;
            let (balance, remainder, scale) =
                conservative_balance(grid, [rho, rho_old], (&u, &v, &problem.old), dt, (i, j));
            if remainder > 0.0 {
                positive += 1;
            } else {
                negative += 1;
            }
            worst = worst.max((residual(&conservative, k) - balance).abs() / scale);
            subtracted_worst =
                subtracted_worst.max((residual(&subtracted, k) - balance).abs() / scale);
        }
    }
    assert!(positive > 0 && negative > 0, "{positive} {negative}");
    assert!(
        worst < 1e-12,
        "conservative row against the balance: {worst}"
    );
    assert!(
        subtracted_worst > 1e-3,
        "the subtracted row misses it: {subtracted_worst}"
    );
}

/// The conservative balance of u node (i, j), 0 < i < nx, written from the scalar cells
/// (`the_conservative_form_is_the_conservative_balance`): the balance, the control volume's
/// continuity remainder and the row's scale m |u|/Δt.
fn conservative_balance(
    grid: &Grid,
    [rho, rho_old]: [&[f64]; 2],
    (u, v, old): (&[f64], &[f64], &[f64]),
    dt: f64,
    (i, j): (usize, usize),
) -> (f64, f64, f64) {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let cell = |i: usize, j: usize| i + nx * j;
    let upwind = |flow: f64, lo: f64, hi: f64| if flow >= 0.0 { lo } else { hi };
    // ρε u A through the x-face west of cell i (0 at the walls), ρε v A through the y-face
    // south of cell (i, j)
    let x_flux = |i: usize, j: usize| {
        if i == 0 || i == nx {
            return 0.0;
        }
        let vel = u[i + (nx + 1) * j];
        upwind(vel, rho[cell(i - 1, j)], rho[cell(i, j)]) * vel * dy[j]
    };
    let y_flux = |i: usize, j: usize| {
        if j == 0 || j == ny {
            return 0.0;
        }
        let vel = v[i + nx * j];
        upwind(vel, rho[cell(i, j - 1)], rho[cell(i, j)]) * vel * dx[i]
    };
    let k = i + (nx + 1) * j;
    let (w, e) = (i - 1, i);
    let half = |c: usize, f: &[f64]| 0.5 * dx[c] * dy[j] * f[cell(c, j)];
    let (m, m_old) = (
        half(w, rho) + half(e, rho),
        half(w, rho_old) + half(e, rho_old),
    );
    // the control volume's faces: x-faces at the cell centres w and e, y-faces the halves of
    // cells w and e
    let f_west = 0.5 * (x_flux(w, j) + x_flux(w + 1, j));
    let f_east = 0.5 * (x_flux(e, j) + x_flux(e + 1, j));
    let f_south = 0.5 * (y_flux(w, j) + y_flux(e, j));
    let f_north = 0.5 * (y_flux(w, j + 1) + y_flux(e, j + 1));
    let node = |ii: usize, jj: usize| u[ii + (nx + 1) * jj];
    let south = if j > 0 { node(i, j - 1) } else { 0.0 };
    let north = if j + 1 < ny { node(i, j + 1) } else { 0.0 };
    let convection = f_east * upwind(f_east, u[k], node(i + 1, j))
        - f_west * upwind(f_west, node(i - 1, j), u[k])
        + f_north * upwind(f_north, u[k], north)
        - f_south * upwind(f_south, south, u[k]);
    let balance = (m * u[k] - m_old * old[k]) / dt + convection;
    let remainder = (m - m_old) / dt + f_east - f_west + f_north - f_south;
    let scale = (m * u[k] / dt).abs().max(m_old * old[k].abs() / dt);
    (balance, remainder, scale)
}
