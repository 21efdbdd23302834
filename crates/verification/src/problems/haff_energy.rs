//! Homogeneous cooling in a closed box (issue 7, first check): the assembled granular-energy
//! equation (`runout_solver::energy`) with the Lun dissipation of runout-closures, on a
//! stretched grid with zero-flux walls and no motion, follows Haff's law
//! ([`crate::references::haff`]).
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

use crate::references::haff_time;

/// Solids volume fraction of the box.
pub const EPS_S: f64 = 0.3;
/// Initial granular temperature θ0 [m²/s²].
pub const THETA0: f64 = 0.5;

/// The paper's particles (paper Table 3).
pub fn particles() -> Particles {
    Particles {
        diameter: 5e-4,
        density: 2000.0,
        restitution: 0.9,
    }
}

/// Haff's time t0 of the box [s].
pub fn t0() -> f64 {
    let s = kinetic::SolidsState::new(
        EPS_S,
        1.0,
        &particles(),
        RadialDistribution::CarnahanStarling,
    );
    let k = kinetic::dissipation(&s); // γ at θ = 1 is K
    haff_time(particles().density, EPS_S, k, THETA0)
}

/// θ after `steps` steps to `t_end` in every cell of a stretched closed box.
pub fn cool(t_end: f64, steps: usize) -> anyhow::Result<Vec<f64>> {
    let y = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: 0.1,
            cells: 6,
            growth: 1.3,
        }],
    )?;
    let grid = Grid::new(Axis::uniform(0.0, 0.2, 5)?, y);
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
    let pattern = Pattern::new(nx, ny)?;
    let mut a = Stencil5::new(pattern.clone());
    let mut faces = FaceData::zeros(nx, ny);
    let mut solver = build(&LinearSolverKind::SparseLu);
    solver.set_pattern(&pattern)?;
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
                skip: None,
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
            solver.setup_and_solve(&a, &mut theta)?;
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
    Ok(theta)
}
