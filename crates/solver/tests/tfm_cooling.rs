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
use runout_walls::RobinFace;

mod common;
use common::paper_particles_in_air;

const EPS_S: f64 = 0.3;
const THETA0: f64 = 0.5;

fn params() -> ClosureParams {
    paper_particles_in_air(FrictionModel::Princeton, 0.65)
}

/// The exact θ(t) of the cooling law above.
fn exact(t: f64) -> f64 {
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
    let inv = if b == 0.0 {
        // Haff's law: the drag vanishes at zero slip (DgA = 0 at Re = 0, docs/model.md §2.6)
        1.0 / THETA0.sqrt() + 0.5 * a * t
    } else {
        (1.0 / THETA0.sqrt() + a / b) * (0.5 * b * t).exp() - a / b
    };
    1.0 / (inv * inv)
}

/// Runs the box to `t_end` in `steps` steps; returns the solver.
fn cool(t_end: f64, steps: usize) -> TwoFluid {
    let x = Axis::uniform(0.0, 0.04, 4).unwrap();
    let y = Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: 0.03,
            cells: 3,
            growth: 1.3,
        }],
    )
    .unwrap();
    let grid = Grid::new(x, y);
    let free_slip = SideBc::Wall(RobinFace::ZERO_GRADIENT);
    let walls = Sides {
        west: free_slip,
        east: free_slip,
        south: free_slip,
        north: free_slip,
    };
    let zero_flux = Some(RobinFace::ZERO_GRADIENT);
    let spec = SolidsSpec {
        params: params(),
        eps_max: 0.65,
        walls: walls.clone(),
        theta_walls: Sides {
            west: zero_flux,
            east: zero_flux,
            south: zero_flux,
            north: zero_flux,
        },
        wall_models: Sides {
            west: None,
            east: None,
            south: None,
            north: None,
        },
    };
    let gas = Fluid {
        density: 1.2,
        viscosity: 1.8e-5,
    };
    let mut tf = TwoFluid::new(
        grid,
        gas,
        walls,
        vec![spec],
        (0.0, 0.0),
        TwoFluidSettings::default(),
    )
    .unwrap();
    tf.solids[0].eps.iter_mut().for_each(|e| *e = EPS_S);
    tf.solids[0].theta.iter_mut().for_each(|t| *t = THETA0);
    tf.sync_volume_fractions();
    let dt = t_end / steps as f64;
    for _ in 0..steps {
        // the whole outer iteration, repeated until θ has converged; `TwoFluid::step`'s
        // momentum test (MFIX's, normalised by the speed) is meaningless for a phase at
        // rest, whose only velocities are the linear solvers' round-off (below 1e-8 m/s)
        tf.begin_step();
        let mut converged = false;
        for _ in 0..50 {
            let r = tf.outer_iteration(dt).unwrap();
            if r.theta < 1e-7 {
                converged = true;
                break;
            }
        }
        assert!(converged);
    }
    tf
}

#[test]
fn cooling_box_stays_at_rest_and_follows_the_cooling_law() {
    // about three Haff times t0 = 2/(a √θ0)
    let t_end = 0.005;
    let (coarse, fine) = (cool(t_end, 400), cool(t_end, 800));
    let want = exact(t_end);
    let theta_of = |tf: &TwoFluid| {
        let th = &tf.solids[0].theta;
        let mean = th.iter().sum::<f64>() / th.len() as f64;
        // uniform: every cell the same to the linear solvers' tolerance
        assert!(th.iter().all(|t| (t - mean).abs() <= 1e-6 * mean), "{th:?}");
        mean
    };
    let (t1, t2) = (theta_of(&coarse), theta_of(&fine));
    let (e1, e2) = ((t1 - want) / want, (t2 - want) / want);
    eprintln!(
        "θ(t_end): exact {want:.6e} (θ0 = {THETA0}); 400 steps {t1:.6e} ({:+.3} %), 800 steps {t2:.6e} ({:+.3} %); order {:.2}",
        e1 * 100.0,
        e2 * 100.0,
        (e1 / e2).log2()
    );
    assert!(e2.abs() < 0.01, "{e2}");
    // implicit Euler: first order in Δt
    let order = (e1 / e2).log2();
    assert!((order - 1.0).abs() < 0.15, "order {order}");
    // no motion, no change of εs or gas pressure gradient
    for tf in [&coarse, &fine] {
        let s = &tf.solids[0];
        let speed =
            s.u.iter()
                .chain(&s.v)
                .chain(&tf.u_g)
                .chain(&tf.v_g)
                .fold(0.0_f64, |m, x| m.max(x.abs()));
        // the linear solvers' round-off only: 1e-8 m/s against a fluctuation speed √θ ≥ 0.2 m/s
        assert!(speed < 1e-8, "largest velocity {speed}");
        let drift = s.eps.iter().fold(0.0_f64, |m, e| m.max((e - EPS_S).abs()));
        assert!(drift < 1e-9, "εs drift {drift}");
    }
}
