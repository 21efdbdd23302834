//! Homogeneous cooling through the whole two-fluid step (issue 7, first check): a closed box
//! of uniform solids (εs = 0.3, θ0 = 0.5 m²/s²) in air at rest, no gravity. The full outer
//! iteration (closures, momentum with partial elimination, ε and p' corrections, θ) must
//! keep everything at rest and uniform ("no motion appears"), and θ(t) must follow the
//! cooling law of the granular-energy equation (docs/model.md §1.3) with these sinks:
//! (3/2) ρs εs dθ/dt = −K θ^{3/2} − 3 F_gs θ, where K θ^{3/2} is the Lun dissipation (Haff's
//! law alone when F_gs = 0) and 3 F_gs θ the viscous damping by the gas. With s = √θ,
//! ds/dt = −(a/2) s² − (b/2) s, a = 2K/(3 ρs εs), b = 2 F_gs/(ρs εs), so
//! θ(t) = [(1/√θ0 + a/b) e^{bt/2} − a/b]⁻², which is Haff's law θ = [1/√θ0 + a t/2]⁻² when
//! F_gs = 0.

use runout_closures::{kinetic, CellState, ClosureParams, FrictionModel};
use runout_mesh::{Axis, Grid, Segment, Sides};
use runout_solver::two_fluid::{CellClosures, SolidsSpec, TwoFluid, TwoFluidSettings};
use runout_solver::{Fluid, SideBc};
use runout_walls::{RobinFace, SolidsWallModel};

use super::paper_material::paper_particles_in_air;
use crate::references::damped_cooling_theta;

/// Solids volume fraction of the box.
pub const EPS_S: f64 = 0.3;
/// Initial granular temperature θ0 [m²/s²].
pub const THETA0: f64 = 0.5;

/// The paper's material with Princeton friction, εs,max = 0.65.
pub fn params() -> ClosureParams {
    paper_particles_in_air(FrictionModel::princeton(), 0.65)
}

/// The exact θ(t) of the cooling law above ([`damped_cooling_theta`]).
pub fn exact(t: f64) -> f64 {
    let p = params();
    let rho_eps = p.particles.density * EPS_S;
    let state = kinetic::SolidsState::new(EPS_S, 1.0, &p.particles, p.radial);
    let k = kinetic::dissipation(&state); // γ at θ = 1
    let f_gs = CellClosures::evaluate(
        &CellState {
            eps_s: EPS_S,
            theta: THETA0,
            // the phases slip only by the linear solvers' round-off (~1e-11 m/s); DgA is
            // its viscous (Ergun) limit there, not MFIX's exact zero at Re = 0 (§2.6)
            slip: 1e-9,
            tr_d: 0.0,
            s_ddot_s: 0.0,
        },
        &p,
    )
    .f_gs;
    let (a, b) = (2.0 * k / (3.0 * rho_eps), 2.0 * f_gs / rho_eps);
    damped_cooling_theta(THETA0, a, b, t)
}

/// Runs the box to `t_end` in `steps` steps; returns the solver. Fails if a step's θ does
/// not converge in 50 outer iterations.
pub fn cool(t_end: f64, steps: usize) -> anyhow::Result<TwoFluid> {
    let x = Axis::uniform(0.0, 0.04, 4)?;
    let y = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: 0.03,
            cells: 3,
            growth: 1.3,
        }],
    )?;
    let grid = Grid::new(x, y);
    let gas_walls = Sides::all(SideBc::Wall(RobinFace::ZERO_GRADIENT));
    let spec = SolidsSpec {
        params: params(),
        eps_max: 0.65,
        walls: Sides::all(Some(SolidsWallModel::FreeSlip)),
    };
    let gas = Fluid {
        density: 1.2,
        viscosity: 1.8e-5,
    };
    let mut tf = TwoFluid::new(
        grid,
        gas,
        gas_walls,
        vec![spec],
        (0.0, 0.0),
        TwoFluidSettings::default(),
    )?;
    tf.state_mut().update_solids(0, |s| {
        s.eps.iter_mut().for_each(|e| *e = EPS_S);
        s.theta.iter_mut().for_each(|t| *t = THETA0);
    });
    let dt = t_end / steps as f64;
    for _ in 0..steps {
        // the whole outer iteration, repeated until θ has converged; `TwoFluid::step`'s
        // momentum test (MFIX's, normalised by the speed) is meaningless for a phase at
        // rest, whose only velocities are the linear solvers' round-off (below 1e-8 m/s)
        tf.begin_step();
        let mut converged = false;
        for _ in 0..50 {
            let r = tf.outer_iteration(dt)?;
            if r.theta < 1e-7 {
                converged = true;
                break;
            }
        }
        anyhow::ensure!(
            converged,
            "cooling box: θ did not converge in 50 outer iterations"
        );
    }
    Ok(tf)
}
