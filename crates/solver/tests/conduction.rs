//! Steady conduction in the assembled granular-energy equation (`runout_solver::energy`):
//! the two-point fluxes and the eliminated Robin closures of the θ walls reproduce a linear
//! profile exactly. (Haff's law through the same equation is the `haff` check of
//! runout-verification.)

use runout_linsolve::{build, LinearSolverKind, Pattern, Stencil5};
use runout_mesh::{Axis, Grid, Segment, Sides};
use runout_solver::energy::{assemble_theta, EnergyInputs};
use runout_solver::{FaceData, Scheme};
use runout_walls::RobinFace;

/// Steady conduction with constant κ between a flux wall (the manual form dθ/dn = C,
/// docs/model.md §3.3, at the floor) and a wall held at θ_top: θ = θ_top + C (H − y), linear,
/// which the two-point fluxes and the eliminated Robin closures reproduce exactly.
#[test]
fn steady_conduction_with_flux_and_dirichlet_walls_is_exact() {
    let (flux, theta_top, height) = (0.7, 0.2, 0.1);
    let y = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: height,
            cells: 7,
            growth: 1.25,
        }],
    )
    .unwrap();
    let grid = Grid::new(Axis::uniform(0.0, 0.3, 3).unwrap(), y);
    let (nx, ny, n) = (grid.nx(), grid.ny(), grid.cell_count());
    let ones = vec![1.0; n];
    let zeros = vec![0.0; n];
    let kappa = vec![0.8; n];
    let walls = Sides {
        west: Some(RobinFace::ZERO_GRADIENT),
        east: Some(RobinFace::ZERO_GRADIENT),
        south: Some(RobinFace::user_theta(0.0, 0.0, flux)),
        north: Some(RobinFace::dirichlet(theta_top)),
    };
    let inputs = EnergyInputs {
        bulk_density: &ones,
        bulk_density_old: &ones,
        conductivity: &kappa,
        p_kin_over_theta: &zeros,
        mu_kin: &zeros,
        lambda_kin: &zeros,
        dissipation_over_theta: &zeros,
        drag: &zeros,
        slip_production: &zeros,
        tr_d: &zeros,
        tr_d2: &zeros,
        skip: None,
    };
    let pattern = Pattern::new(nx, ny).unwrap();
    let mut a = Stencil5::new(pattern.clone());
    let mut faces = FaceData::zeros(nx, ny);
    let (u, v) = (vec![0.0; (nx + 1) * ny], vec![0.0; nx * (ny + 1)]);
    let mut theta = vec![0.5; n];
    let old = theta.clone();
    assemble_theta(
        &grid,
        &inputs,
        &walls,
        None,
        &u,
        &v,
        &old,
        f64::INFINITY,
        Scheme::Upwind,
        &old,
        &mut faces,
        &mut a,
    );
    let mut solver = build(&LinearSolverKind::SparseLu);
    solver.set_pattern(&pattern).unwrap();
    solver.setup_and_solve(&a, &mut theta).unwrap();
    for (k, t) in theta.iter().enumerate() {
        let y = grid.y.centres()[k / nx];
        let exact = theta_top + flux * (height - y);
        assert!((t - exact).abs() < 1e-12, "cell {k}: {t} vs {exact}");
    }
}
