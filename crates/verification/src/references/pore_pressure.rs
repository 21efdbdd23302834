//! Pore-pressure diffusion in a rigid bed whose aeration is shut off (issue 60 item 3).
//!
//! A bed of height H on a closed floor, its top held at the freeboard's pressure, carries the
//! gas's excess pressure p(z, t) by Darcy's law with the gas's storage: for an ideal gas at
//! a fixed temperature in a bed that does not deform,
//!
//!   εg ∂ρg/∂t = ∂/∂z (ρg k/μ ∂p/∂z),  ρg = P M/(R T)  ⇒  ∂p/∂t = D ∂²p/∂z²,  D = P εg/β,
//!
//! with β = εg² μ/k the drag coefficient of the bed at rest (Gidaspow's dense branch,
//! Ergun's viscous term 150 εs² μ/(εg d²)) and P the absolute pressure (the excess ≪ P).
//! The steady aerated bed has the linear profile p(z, 0) = p0 (1 − z/H); with ∂p/∂z = 0 at
//! the closed floor and p = 0 at the top the solution is the Fourier series
//!
//!   p(0, t)/p0 = Σ_{n≥0} 8/((2n + 1)² π²) exp(−(2n + 1)² π² τ/4),  τ = D t/H²
//!
//! (Carslaw & Jaeger 1959, *Conduction of Heat in Solids*, §3.3, with the slab's insulated
//! face at the floor), which halves at τ½ = 0.19673 ([`tau_half`]): t½ = τ½ H²/D.
//! Valid where the bed neither expands nor compacts while the gas drains; a bed whose
//! grains settle as the support goes squeezes gas out and decays more slowly.

use std::f64::consts::PI;

/// p(0, t)/p0 at τ = D t/H² (module doc); 1 at τ ≤ 0.
pub fn basal_fraction(tau: f64) -> f64 {
    if tau <= 0.0 {
        return 1.0;
    }
    (0..10_000)
        .map(|n| {
            let m = (2 * n + 1) as f64;
            8.0 / (m * m * PI * PI) * (-m * m * PI * PI * tau / 4.0).exp()
        })
        .take_while(|term| *term > 1e-18)
        .sum()
}

/// τ½, where the basal excess pressure has halved (bisection of [`basal_fraction`]).
pub fn tau_half() -> f64 {
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if basal_fraction(mid) > 0.5 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The rigid bed's diffusivity D = P εg/β [m²/s] with β = 150 εs² μ/(εg d²) (Ergun's
/// viscous term, Gidaspow's drag at εg < 0.8 and zero slip) from the absolute pressure P
/// [Pa], the bed's εs, the gas viscosity μ [Pa s] and the grain diameter d [m].
pub fn diffusivity(pressure: f64, eps_s: f64, viscosity: f64, diameter: f64) -> f64 {
    let eps_g = 1.0 - eps_s;
    let beta = 150.0 * eps_s * eps_s * viscosity / (eps_g * diameter * diameter);
    pressure * eps_g / beta
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The series against an independent solution: implicit finite differences of
    /// ∂p/∂t = ∂²p/∂z² on [0, 1] (p_z = 0 at 0, p = 0 at 1) from p = 1 − z, on 400 cells
    /// and Δτ = 1e-5; the basal value at τ = 0.05, 0.2 and 0.5, and the half time.
    #[test]
    fn the_series_matches_a_finite_difference_solution() {
        let n = 400;
        let dz = 1.0 / n as f64;
        // nodes z_j = j dz, j = 0..n-1 (z = 1 held at 0); ghost node mirrors j = 1 at j = −1
        let mut p: Vec<f64> = (0..n).map(|j| 1.0 - j as f64 * dz).collect();
        let dt = 1e-5;
        let r = dt / (dz * dz);
        let (mut t, mut half) = (0.0, None);
        let mut checked = 0;
        let marks = [0.05, 0.2, 0.5];
        while checked < marks.len() {
            // tridiagonal (1 + 2r) p_j − r p_{j−1} − r p_{j+1} = p_j^old (Thomas algorithm)
            let (mut c, mut d) = (vec![0.0; n], vec![0.0; n]);
            for j in 0..n {
                let (lower, upper) = match j {
                    0 => (0.0, -2.0 * r),
                    _ if j == n - 1 => (-r, 0.0),
                    _ => (-r, -r),
                };
                let denom = 1.0 + 2.0 * r - lower * if j > 0 { c[j - 1] } else { 0.0 };
                c[j] = upper / denom;
                d[j] = (p[j] - lower * if j > 0 { d[j - 1] } else { 0.0 }) / denom;
            }
            for j in (0..n).rev() {
                p[j] = d[j] - if j + 1 < n { c[j] * p[j + 1] } else { 0.0 };
            }
            let before = t;
            t += dt;
            if half.is_none() && p[0] <= 0.5 {
                half = Some(before + dt / 2.0);
            }
            if t >= marks[checked] - 1e-12 {
                let series = basal_fraction(t);
                assert!(
                    (p[0] - series).abs() < 2e-4,
                    "τ {t}: FD {} series {series}",
                    p[0]
                );
                checked += 1;
            }
        }
        let half = half.expect("halved before τ = 0.5");
        assert!(
            (half - tau_half()).abs() < 2e-4,
            "FD {half} series {}",
            tau_half()
        );
        assert!((tau_half() - 0.19673).abs() < 1e-5, "{}", tau_half());
        // the constant `runout pore-pressure` uses
        let constant = runout_closures::pore_pressure::TAU_HALF;
        assert!((tau_half() - constant).abs() < 5e-6, "{constant}");
        assert!((basal_fraction(1e-9) - 1.0).abs() < 1e-3);
    }

    #[test]
    fn the_diffusivity_is_the_gas_storage_over_the_drag() {
        // 1 kPa, εs 0.6, air, 80 µm: β = 150 · 0.36 · 1.8e-5 / (0.4 · 6.4e-9) = 3.797e5
        let d = diffusivity(1000.0, 0.6, 1.8e-5, 8e-5);
        assert!((d / (1000.0 * 0.4 / 379_687.5) - 1.0).abs() < 1e-12, "{d}");
    }
}
