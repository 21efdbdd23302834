//! Homogeneous cooling (Haff's law) with the crate's collisional dissipation (issue 3 (c)).
//!
//! A uniform granular gas at rest, without gas, obeys (docs/model.md §1.3)
//! (3/2) ρs εs dθ/dt = −γ(θ), with γ = K θ^{3/2} and (docs/model.md §2.2, §1.3)
//! K = (48/√π) η(1−η) ρs εs² g0 / d = 12 (1 − e²) ρs εs² g0/(√π d).
//! Try θ = θ0/(1 + t/t0)²: dθ/dt = −2θ0/(t0 (1 + t/t0)³) = −(2/(t0 √θ0)) θ^{3/2}, so
//! (3/2) ρs εs · 2/(t0 √θ0) = K, i.e. **t0 = 3 ρs εs/(K √θ0)**
//! = √π d/(4 (1 − e²) εs g0 √θ0) (verification-notes §2c).
//! The test integrates the ODE with RK4 using `kinetic::dissipation` and compares with the
//! closed form; K is computed here from the second form, not from the crate.
//!
//! With gas at rest the viscous damping J_vis = 3 F_gs θ adds a linear sink:
//! dθ/dt = −k θ^{3/2} − a θ, k = 2K/(3 ρs εs) = 2/(t0 √θ0), a = 2 F_gs/(ρs εs); with
//! y = θ^{−1/2}, dy/dt = (k + a y)/2, so y(t) = (y0 + k/a) e^{a t/2} − k/a (verification-notes §2c).

use runout_closures::energy::viscous_damping;
use runout_closures::kinetic::{dissipation, SolidsState};
use runout_closures::radial::g0_carnahan_starling;
use std::f64::consts::PI;

/// Relative tolerance on θ(t) (issue 3 (c)).
const REL_TOL: f64 = 1e-3;
/// RK4 steps per t0: the local error scales as (Δt/t0)^5.
const STEPS_PER_T0: usize = 200;
/// Integrate to 10 t0, where θ = θ0/121.
const T_END_OVER_T0: usize = 10;

struct Case {
    eps_s: f64,
    restitution: f64,
}

const D_P: f64 = 1e-3;
const RHO_S: f64 = 2000.0;
const THETA_0: f64 = 0.5;

fn state(case: &Case, theta: f64) -> SolidsState {
    SolidsState {
        eps_s: case.eps_s,
        theta,
        rho_s: RHO_S,
        d_p: D_P,
        restitution: case.restitution,
        g0: g0_carnahan_starling(case.eps_s),
    }
}

/// K of γ = K θ^{3/2}, second form of docs/model.md §1.3 (independent of the crate's γ).
fn k_haff(case: &Case) -> f64 {
    let g0 = g0_carnahan_starling(case.eps_s);
    12.0 * (1.0 - case.restitution.powi(2)) * RHO_S * case.eps_s.powi(2) * g0 / (PI.sqrt() * D_P)
}

/// One RK4 step of dθ/dt = rhs(θ).
fn rk4(theta: f64, dt: f64, rhs: &impl Fn(f64) -> f64) -> f64 {
    let k1 = rhs(theta);
    let k2 = rhs(theta + 0.5 * dt * k1);
    let k3 = rhs(theta + 0.5 * dt * k2);
    let k4 = rhs(theta + dt * k3);
    theta + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
}

/// Integrate with RK4 and check θ against `exact` after every t0.
fn integrate_and_compare(t0: f64, rhs: impl Fn(f64) -> f64, exact: impl Fn(f64) -> f64) {
    let dt = t0 / STEPS_PER_T0 as f64;
    let mut theta = THETA_0;
    for step in 1..=STEPS_PER_T0 * T_END_OVER_T0 {
        theta = rk4(theta, dt, &rhs);
        if step % STEPS_PER_T0 == 0 {
            let t = step as f64 * dt;
            let want = exact(t);
            let rel = (theta - want).abs() / want;
            assert!(
                rel <= REL_TOL,
                "t/t0 = {}: θ = {theta:e}, exact {want:e}, rel {rel:e}",
                t / t0
            );
        }
    }
}

const CASES: [Case; 5] = [
    Case {
        eps_s: 0.05,
        restitution: 0.9,
    },
    Case {
        eps_s: 0.3,
        restitution: 0.9,
    },
    Case {
        eps_s: 0.3,
        restitution: 0.8,
    },
    Case {
        eps_s: 0.5,
        restitution: 0.9,
    },
    Case {
        eps_s: 0.6,
        restitution: 0.7,
    },
];

#[test]
fn homogeneous_cooling_follows_haff_law() {
    for case in &CASES {
        let bulk = 1.5 * RHO_S * case.eps_s;
        let t0 = 3.0 * RHO_S * case.eps_s / (k_haff(case) * THETA_0.sqrt());
        integrate_and_compare(
            t0,
            |theta| -dissipation(&state(case, theta)) / bulk,
            |t| THETA_0 / (1.0 + t / t0).powi(2),
        );
    }
}

/// t0 of verification-notes §2c (d = 1 mm, θ0 = 0.5 m²/s²) to its printed 3 digits.
#[test]
fn haff_time_matches_verification_notes() {
    for (case, printed) in [
        (
            Case {
                eps_s: 0.05,
                restitution: 0.9,
            },
            5.80e-2,
        ),
        (
            Case {
                eps_s: 0.3,
                restitution: 0.9,
            },
            4.44e-3,
        ),
        (
            Case {
                eps_s: 0.3,
                restitution: 0.8,
            },
            2.34e-3,
        ),
        (
            Case {
                eps_s: 0.5,
                restitution: 0.9,
            },
            1.10e-3,
        ),
        (
            Case {
                eps_s: 0.5,
                restitution: 0.8,
            },
            5.80e-4,
        ),
    ] {
        let t0 = 3.0 * RHO_S * case.eps_s / (k_haff(&case) * THETA_0.sqrt());
        assert!(
            (t0 - printed).abs() <= 0.005 * printed,
            "t0 = {t0:e}, printed {printed:e}"
        );
    }
}

#[test]
fn homogeneous_cooling_with_viscous_damping() {
    // a drag coefficient typical of a dense bed of 1 mm particles in air [kg m⁻³ s⁻¹]
    let f_gs = 1e3;
    for case in &CASES {
        let bulk = 1.5 * RHO_S * case.eps_s;
        let t0 = 3.0 * RHO_S * case.eps_s / (k_haff(case) * THETA_0.sqrt());
        let k = 2.0 / (t0 * THETA_0.sqrt());
        let a = 2.0 * f_gs / (RHO_S * case.eps_s);
        let y0 = 1.0 / THETA_0.sqrt();
        integrate_and_compare(
            t0,
            |theta| -(dissipation(&state(case, theta)) + viscous_damping(f_gs, theta)) / bulk,
            |t| ((y0 + k / a) * (0.5 * a * t).exp() - k / a).powi(-2),
        );
    }
}
