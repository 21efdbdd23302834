//! Closed forms of homogeneous cooling: a uniform granular gas at rest whose granular
//! energy decays by inelastic collisions (and, with a gas, by viscous damping).
//!
//! The granular-energy equation (docs/model.md §1.3) of a uniform phase at rest reduces to
//! (3/2) ρs εs dθ/dt = −K θ^{3/2} − 3 F_gs θ, with K θ^{3/2} the Lun dissipation γ and
//! 3 F_gs θ the viscous damping by the gas.
//!
//! - Without gas (Haff 1983, "Grain flow as a fluid-mechanical phenomenon", J. Fluid Mech.
//!   134, 401–430): θ(t) = θ0 / (1 + t/t0)², t0 = 3 ρs εs / (K √θ0) ([`haff_time`],
//!   [`haff_theta`]).
//! - With the damping: s = √θ obeys ds/dt = −(a/2) s² − (b/2) s with a = 2K/(3 ρs εs),
//!   b = 2 F_gs/(ρs εs), so θ(t) = [(1/√θ0 + a/b) e^{bt/2} − a/b]⁻², which is Haff's law
//!   θ = [1/√θ0 + a t/2]⁻² when F_gs = 0 ([`damped_cooling_theta`]).

/// Haff's time t0 = 3 ρs εs / (K √θ0) \[s\] from the solids density ρs, the volume fraction
/// εs, the dissipation coefficient K (γ at θ = 1) and the initial θ0.
pub fn haff_time(solids_density: f64, eps_s: f64, k: f64, theta0: f64) -> f64 {
    3.0 * solids_density * eps_s / (k * theta0.sqrt())
}

/// Haff's law θ(t) = θ0 / (1 + t/t0)².
pub fn haff_theta(theta0: f64, t: f64, t0: f64) -> f64 {
    theta0 / (1.0 + t / t0).powi(2)
}

/// θ(t) of the cooling law with viscous damping, a = 2K/(3 ρs εs), b = 2 F_gs/(ρs εs);
/// Haff's law when b = 0 (the drag vanishes at zero slip: DgA = 0 at Re = 0,
/// docs/model.md §2.6).
pub fn damped_cooling_theta(theta0: f64, a: f64, b: f64, t: f64) -> f64 {
    let inv = if b == 0.0 {
        1.0 / theta0.sqrt() + 0.5 * a * t
    } else {
        (1.0 / theta0.sqrt() + a / b) * (0.5 * b * t).exp() - a / b
    };
    1.0 / (inv * inv)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_damped_law_without_damping_is_haffs() {
        let (theta0, a): (f64, f64) = (0.5, 40.0);
        // a = 2K/(3 ρs εs) and t0 = 3 ρs εs/(K √θ0) give t0 = 2/(a √θ0)
        let t0 = 2.0 / (a * theta0.sqrt());
        for t in [0.0, 0.01, 0.1] {
            let (h, d) = (
                haff_theta(theta0, t, t0),
                damped_cooling_theta(theta0, a, 0.0, t),
            );
            assert!((h - d).abs() < 1e-14 * theta0, "{h} vs {d}");
        }
    }
}
