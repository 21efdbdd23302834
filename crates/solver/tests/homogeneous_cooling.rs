//! Homogeneous cooling in a closed box (issue 7, first check): the assembled granular-energy
//! equation (`runout_solver::energy`) with the Lun dissipation of runout-closures, on a
//! stretched grid with zero-flux walls and no motion, follows Haff's law.
//!
//! (3/2) ρs εs dθ/dt = −γ = −K θ^{3/2}, K = (48/√π) η (1−η) ρs εs² g0 / d, gives
//! θ(t) = θ0 / (1 + t/t0)², t0 = 3 ρs εs / (K √θ0) (Haff 1983). Implicit Euler is first
//! order, so the step is refined until the result is within 1 % and the observed order in
//! Δt is checked to be one.

use runout_closures::{kinetic, Particles, RadialDistribution};
use runout_linsolve::{build, LinearSolverKind, Pattern, Stencil5};
use runout_mesh::{Axis, Grid, Segment, Sides};
use runout_solver::energy::{assemble_theta, EnergyInputs};
use runout_solver::{FaceData, Scheme};
use runout_walls::RobinFace;

const EPS_S: f64 = 0.3;
const THETA0: f64 = 0.5;

fn particles() -> Particles {
    Particles {
        diameter: 5e-4,
        density: 2000.0,
        restitution: 0.9,
    }
}

fn t0() -> f64 {
    let s = kinetic::SolidsState::new(
        EPS_S,
        1.0,
        &particles(),
        RadialDistribution::CarnahanStarling,
    );
    let k = kinetic::dissipation(&s); // γ at θ = 1 is K
    3.0 * particles().density * EPS_S / (k * THETA0.sqrt())
}

/// θ after `steps` steps to `t_end` in every cell of a stretched closed box.
fn cool(t_end: f64, steps: usize) -> Vec<f64> {
    let y = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: 0.1,
            cells: 6,
            growth: 1.3,
        }],
    )
    .unwrap();
    let grid = Grid::new(Axis::uniform(0.0, 0.2, 5).unwrap(), y);
    let n = grid.cell_count();
    let (nx, ny) = (grid.nx(), grid.ny());
    let bulk = vec![particles().density * EPS_S; n];
    let zeros = vec![0.0; n];
    let mut conductivity = vec![0.0; n];
    let mut p_over_theta = vec![0.0; n];
    let mut mu = vec![0.0; n];
    let mut lambda = vec![0.0; n];
    let mut gamma_over_theta = vec![0.0; n];
    let zero_flux = Some(RobinFace::ZERO_GRADIENT);
    let walls = Sides {
        west: zero_flux,
        east: zero_flux,
        south: zero_flux,
        north: zero_flux,
    };
    let (u, v) = (vec![0.0; (nx + 1) * ny], vec![0.0; nx * (ny + 1)]);
    let pattern = Pattern::new(nx, ny).unwrap();
    let mut a = Stencil5::new(pattern.clone());
    let mut faces = FaceData::zeros(nx, ny);
    let mut solver = build(&LinearSolverKind::SparseLu);
    solver.set_pattern(&pattern).unwrap();
    let mut theta = vec![THETA0; n];
    let dt = t_end / steps as f64;
    for _ in 0..steps {
        let old = theta.clone();
        // outer iterations: closures at the current θ, then the linear θ equation
        for _ in 0..50 {
            for k in 0..n {
                let s = kinetic::SolidsState::new(
                    EPS_S,
                    theta[k],
                    &particles(),
                    RadialDistribution::CarnahanStarling,
                );
                let ks = kinetic::lun_1984(&s, kinetic::GasCoupling::Dry);
                conductivity[k] = ks.kappa_kin;
                p_over_theta[k] = ks.p_kin / theta[k];
                mu[k] = ks.mu_kin;
                lambda[k] = ks.lambda_kin;
                gamma_over_theta[k] = ks.dissipation / theta[k];
            }
            let inputs = EnergyInputs {
                bulk_density: &bulk,
                bulk_density_old: &bulk,
                conductivity: &conductivity,
                p_kin_over_theta: &p_over_theta,
                mu_kin: &mu,
                lambda_kin: &lambda,
                dissipation_over_theta: &gamma_over_theta,
                drag: &zeros,
                slip_production: &zeros,
                tr_d: &zeros,
                tr_d2: &zeros,
            };
            assemble_theta(
                &grid,
                &inputs,
                &walls,
                None,
                &u,
                &v,
                &old,
                dt,
                Scheme::Superbee,
                &theta,
                &mut faces,
                &mut a,
            );
            let previous = theta.clone();
            solver.setup_and_solve(&a, &mut theta).unwrap();
            let change = theta
                .iter()
                .zip(&previous)
                .map(|(a, b)| ((a - b) / b).abs())
                .fold(0.0, f64::max);
            if change < 1e-12 {
                break;
            }
        }
    }
    theta
}

#[test]
fn haff_law_within_one_percent_and_first_order_in_time() {
    let t_end = 2.0 * t0();
    let exact = THETA0 / (1.0 + t_end / t0()).powi(2);
    let mut errors = Vec::new();
    for steps in [100, 200, 400] {
        let theta = cool(t_end, steps);
        // no spatial variation appears in a uniform closed box
        let spread = theta.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
            - theta.iter().cloned().fold(f64::INFINITY, f64::min);
        assert!(spread <= 1e-12 * exact, "spread {spread}");
        errors.push((theta[0] - exact).abs() / exact);
    }
    let order = (errors[1] / errors[2]).log2();
    eprintln!("Haff cooling to t = 2 t0: relative errors {errors:?}, order in dt {order:.3}");
    assert!(errors[2] < 0.01, "{errors:?}");
    assert!((0.9..1.1).contains(&order), "{order}");
}

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
