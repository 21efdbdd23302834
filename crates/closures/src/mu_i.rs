//! Rate-dependent friction, the μ(I) law (docs/model.md §2.4.4): a Coulomb stress whose
//! friction coefficient grows with the inertial number, so that a deposit below μ_s stops.
//!
//! μ(I) = μ_s + (μ_2 − μ_s)/(I_0/I + 1),  I = d γ̇ / √(P/ρ_s)
//! (Jop, Forterre & Pouliquen 2006, Nature 441, Eqs. 1–2; GDR MiDi 2004), with
//! γ̇ = √(2 S:S) the second invariant of the strain rate (= |du/dy| in simple shear) and the
//! frictional stress τ = 2 μ_fric S, μ_fric = μ(I) P/γ̇_r, γ̇_r = √(γ̇² + γ̇_min²).
//!
//! **Pressure.** P is the total solids pressure P_s = P_kin + P_c(εs): the collisional
//! pressure of the kinetic theory (Lun et al. 1984, §2.2) plus the critical-state pressure
//! P_c(εs) = Fr (εs − εs,min)²/(εs,max − εs)⁵ that the Princeton model already has (paper
//! Eq. 10, [`PrincetonConstants`] with MFIX's constants). The μ(I) law was measured on the
//! grains' total normal stress (GDR MiDi 2004; da Cruz et al. 2005), and Chialvo, Sun &
//! Sundaresan (2012, Phys. Fluids 24) apply the friction coefficient to the total pressure
//! when they join the kinetic and frictional regimes. Only P_c is added to the momentum
//! equation as P_fric (P_kin is already in P_s, §2.3), and K_cp = dP_c/dεs as with
//! Princeton. With P_c alone the Coulomb stress vanishes wherever a flowing layer dilates
//! below εs,min, and the collapses of docs/reports/collapse.md did not stop (runout 5.9 L0 at a = 1,
//! against 2.3 L0 with the total pressure). Pressure from εs and θ with a rate-independent
//! μ(I) is a compressible form in the sense of Heyman et al. (2017, JFM 830, R1), which
//! removes the short-wave ill-posedness of incompressible μ(I) (Barker et al. 2015, JFM 779);
//! the φ(I) dilatancy law of Schaeffer et al. (2019, JFM 874) is not implemented.
//!
//! **Joined with the kinetic theory as the larger.** μ(I) is the whole dense shear stress
//! (its collisional part included), so the stress it returns carries
//! [`KineticJoin::LargerOf`]: μ_s = (μ_kin⁴ + μ_fric⁴)^(1/4) rather than MFIX's sum (§2.3,
//! §2.4.4); and the solver averages its viscosity arithmetically to the cell corners
//! ([`crate::FrictionModel::corner_viscosity_mean`]). Both are checked by
//! `cargo xtask verify incline` (a layer on a rough incline against the Bagnold profile, and
//! at rest below μ_s).
//!
//! **Regularisation.** At γ̇ → 0 the viscosity is capped at μ(0) P/γ̇_min. A layer loaded to
//! a fraction r < 1 of its static strength (τ = r μ_s P) then creeps at
//! γ̇ = γ̇_min r/√(1 − r²) (solve μ_s P γ̇/√(γ̇² + γ̇_min²) = r μ_s P; I ≈ 0), i.e. a layer of
//! depth h slides at most h γ̇_min r/√(1 − r²) ([`creep_shear_rate`]). The default
//! γ̇_min = 1e-3 s⁻¹ gives 2.6e-5 m/s for h = 5 cm at r = 0.46 (a deposit surface at 10°
//! with μ_s = 0.38): 4e-5 of √(g h).

use crate::friction::{FrictionParams, FrictionalStress, PrincetonConstants};
use crate::stress::KineticJoin;

/// Default strain-rate floor γ̇_min = 1e-3 s⁻¹ of the viscosity regularisation (module doc:
/// creep below 1e-4 of √(g h) for laboratory columns).
pub const DEFAULT_SHEAR_RATE_FLOOR: f64 = 1e-3;

/// Parameters of the μ(I) law, one set per case (`friction: MuI(mu_s: …, mu_2: …, i_0: …)`,
/// read through [`crate::FrictionName::MuI`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MuIConstants {
    /// static friction coefficient μ_s = tan θ_1 [-] (below it a layer stays at rest)
    pub mu_s: f64,
    /// limiting friction coefficient μ_2 = tan θ_2 [-] at I → ∞, μ_2 > μ_s
    pub mu_2: f64,
    /// inertial-number scale I_0 [-], > 0
    pub i_0: f64,
    /// strain-rate floor γ̇_min [1/s] of the regularisation γ̇_r = √(γ̇² + γ̇_min²)
    pub shear_rate_floor: f64,
}

/// [`DEFAULT_SHEAR_RATE_FLOOR`], for serde's field default.
pub fn default_shear_rate_floor() -> f64 {
    DEFAULT_SHEAR_RATE_FLOOR
}

impl MuIConstants {
    /// Glass beads of d = 0.53 mm (Jop, Forterre & Pouliquen 2005, JFM 541, §2, fitted on
    /// the h_stop curve of Pouliquen 1999): μ_s = tan 20.9°, μ_2 = tan 32.76°, I_0 = 0.279;
    /// the same values as Jop et al. (2006).
    pub fn glass_beads_jop_2005() -> Self {
        Self {
            mu_s: 20.9_f64.to_radians().tan(),
            mu_2: 32.76_f64.to_radians().tan(),
            i_0: 0.279,
            shear_rate_floor: DEFAULT_SHEAR_RATE_FLOOR,
        }
    }

    /// μ(I) = μ_s + (μ_2 − μ_s)/(I_0/I + 1) [-], written as μ_s + Δμ I/(I_0 + I) so that
    /// I = 0 gives μ_s exactly (Jop et al. 2006, Eq. 2), and I = +∞ (a pressure whose
    /// P/ρ_s underflows, [`inertial_number`]) μ_2 rather than ∞/∞ — a NaN viscosity in a
    /// dilute cell at a deposit's edge ended cases/collapse/floor-long's Jenkins run at
    /// t = 2.05 s. Valid for I ≥ 0.
    #[inline]
    pub fn friction_coefficient(&self, inertial_number: f64) -> f64 {
        let share = if inertial_number.is_infinite() {
            1.0
        } else {
            inertial_number / (self.i_0 + inertial_number)
        };
        self.mu_s + (self.mu_2 - self.mu_s) * share
    }

    /// dμ/dI = (μ_2 − μ_s) I_0/(I_0 + I)² [-] of [`MuIConstants::friction_coefficient`].
    #[inline]
    pub fn dfriction_coefficient_di(&self, inertial_number: f64) -> f64 {
        let denominator = self.i_0 + inertial_number;
        (self.mu_2 - self.mu_s) * self.i_0 / (denominator * denominator)
    }

    /// Frictional stress at one state (module doc), `p_kin` the kinetic pressure \[Pa\]:
    /// P_c = P_c(εs) (0 at or below εs,min), P = P_kin + P_c, γ̇ = √(2 S:S),
    /// I = d γ̇/√(P/ρ_s), μ_fric = μ(I) P/√(γ̇² + γ̇_min²), λ_fric = −(2/3) μ_fric (a
    /// deviatoric stress, as Princeton's), P_fric = P_c; zero where P = 0. `zeta` reports
    /// γ̇_r.
    #[inline]
    pub fn stress(
        &self,
        eps_s: f64,
        d_p: f64,
        rho_s: f64,
        s_ddot_s: f64,
        p_kin: f64,
        p: &FrictionParams,
    ) -> FrictionalStress {
        let p_c = CRITICAL_STATE.critical_pressure(eps_s, p);
        let pressure = p_kin.max(0.0) + p_c;
        if pressure <= 0.0 {
            return FrictionalStress::default();
        }
        let rate = shear_rate(s_ddot_s);
        let regularised = rate.hypot(self.shear_rate_floor);
        let inertial = inertial_number(d_p, rate, pressure, rho_s);
        let mu_fric = self.friction_coefficient(inertial) * pressure / regularised;
        FrictionalStress {
            p_fric: p_c,
            mu_fric,
            lambda_fric: -2.0 / 3.0 * mu_fric,
            p_star: 0.0,
            p_c,
            pf_over_pc: 1.0,
            zeta: regularised,
            n: 0.0,
            inertial_number: inertial,
            kinetic_join: KineticJoin::LargerOf,
        }
    }

    /// K_cp = dP_c/dεs \[Pa\] (docs/model.md §2.5), the derivative of the pressure the law
    /// uses; 0 at or below εs,min.
    #[inline]
    pub fn k_cp(&self, eps_s: f64, p: &FrictionParams) -> f64 {
        CRITICAL_STATE.dcritical_pressure_deps(eps_s, p)
    }
}

/// The critical-state pressure law P_c(εs) of the μ(I) model: Princeton's with MFIX's
/// constants (paper Eq. 10).
const CRITICAL_STATE: PrincetonConstants = PrincetonConstants::MFIX;

/// γ̇ = √(2 S:S) [1/s], S:S = tr(D²) − (tr D)²/3 floored at 0: |du/dy| in simple shear
/// (Jop et al. 2006: |γ̇| = √(½ γ̇_ij γ̇_ij), γ̇_ij = 2 D_ij).
#[inline]
pub fn shear_rate(s_ddot_s: f64) -> f64 {
    (2.0 * s_ddot_s.max(0.0)).sqrt()
}

/// Inertial number I = d γ̇/√(P/ρ_s) [-] (GDR MiDi 2004); +∞ where P = 0 < γ̇, 0 where
/// γ̇ = 0.
#[inline]
pub fn inertial_number(d_p: f64, shear_rate: f64, pressure: f64, rho_s: f64) -> f64 {
    if shear_rate == 0.0 {
        0.0
    } else {
        d_p * shear_rate / (pressure / rho_s).sqrt()
    }
}

/// Creep rate γ̇ = γ̇_min r/√(1 − r²) [1/s] of a layer whose shear stress is the fraction
/// r ∈ [0, 1) of its static strength μ_s P, in the limit I → 0 (module doc).
#[inline]
pub fn creep_shear_rate(shear_rate_floor: f64, load_ratio: f64) -> f64 {
    shear_rate_floor * load_ratio / (1.0 - load_ratio * load_ratio).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn glass() -> MuIConstants {
        MuIConstants::glass_beads_jop_2005()
    }

    /// μ(0) = μ_s, μ(I_0) = (μ_s + μ_2)/2, μ(∞) → μ_2; monotone.
    #[test]
    fn the_law_runs_from_mu_s_to_mu_2() {
        let m = glass();
        assert_eq!(m.friction_coefficient(0.0), m.mu_s);
        let half = m.friction_coefficient(m.i_0);
        assert!((half - 0.5 * (m.mu_s + m.mu_2)).abs() < 1e-15);
        assert!((m.friction_coefficient(1e12) - m.mu_2).abs() < 1e-12);
        let mut last = m.mu_s;
        for k in 1..100 {
            let mu = m.friction_coefficient(f64::from(k) * 0.01);
            assert!(mu > last);
            last = mu;
        }
    }

    /// A pressure whose P/ρ_s underflows gives I = +∞: μ(I) is μ_2 and the stress finite.
    #[test]
    fn a_vanishing_pressure_gives_mu_2_not_nan() {
        let law = glass();
        assert_eq!(law.friction_coefficient(f64::INFINITY), law.mu_2);
        let p = FrictionParams::default();
        let tiny = f64::from_bits(1); // 4.9e-324 Pa: P/ρ_s = 0
        let i = inertial_number(5e-4, 10.0, tiny, 2500.0);
        assert_eq!(i, f64::INFINITY);
        let stress = law.stress(0.01, 5e-4, 2500.0, 50.0, tiny, &p);
        assert!(
            stress.mu_fric.is_finite() && stress.mu_fric >= 0.0,
            "{stress:?}"
        );
        assert_eq!(law.dfriction_coefficient_di(f64::INFINITY), 0.0);
    }

    /// dμ/dI against a central difference (relative 1e-7).
    #[test]
    fn derivative_matches_a_central_difference() {
        let m = glass();
        for i in [1e-4, 1e-2, 0.1, 0.279, 1.0, 5.0] {
            let h = 1e-4 * i;
            let fd = (m.friction_coefficient(i + h) - m.friction_coefficient(i - h)) / (2.0 * h);
            let exact = m.dfriction_coefficient_di(i);
            assert!(
                (fd - exact).abs() <= 1e-7 * exact,
                "I = {i}: {fd} vs {exact}"
            );
        }
    }

    /// In simple shear u(y) = γ̇ y (S:S = γ̇²/2) the shear stress μ_fric γ̇ is μ(I)(P_kin + P_c)
    /// up to the regularisation, and the stress vanishes where both pressures do.
    #[test]
    fn simple_shear_gives_the_coulomb_stress() {
        let m = glass();
        let p = FrictionParams::default();
        let (d, rho) = (5e-4, 2500.0);
        let p_kin = 30.0;
        for rate in [0.1_f64, 10.0, 100.0] {
            let s = m.stress(0.6, d, rho, 0.5 * rate * rate, p_kin, &p);
            let total = s.p_fric + p_kin;
            let i = d * rate / (total / rho).sqrt();
            let tau = s.mu_fric * rate;
            let want = m.friction_coefficient(i) * total;
            let regularisation = rate / rate.hypot(m.shear_rate_floor);
            assert!((tau - want * regularisation).abs() <= 1e-12 * want);
            assert!((s.inertial_number - i).abs() <= 1e-15 * i);
        }
        assert_eq!(
            m.stress(0.5, d, rho, 100.0, 0.0, &p),
            FrictionalStress::default()
        );
        // below εs,min the law acts on the kinetic pressure alone, and adds no P_fric
        let dilated = m.stress(0.4, d, rho, 100.0, p_kin, &p);
        assert_eq!(dilated.p_fric, 0.0);
        assert!(dilated.mu_fric > 0.0);
    }

    /// The creep of a loaded layer: solving μ(I) P γ̇/γ̇_r = r μ_s P by bisection agrees with
    /// the closed form of [`creep_shear_rate`] (I → 0 there), and the default floor keeps a
    /// 5 cm layer at r = 0.9 below 1e-3 of √(g h) (the "at rest" threshold is 1e-2).
    #[test]
    fn creep_below_mu_s_is_the_closed_form() {
        let m = glass();
        let p = FrictionParams::default();
        let (d, rho, eps) = (5e-4, 2500.0, 0.6);
        let pressure = CRITICAL_STATE.critical_pressure(eps, &p);
        for r in [0.1, 0.42, 0.9] {
            let target = r * m.mu_s * pressure;
            let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                let s = m.stress(eps, d, rho, 0.5 * mid * mid, 0.0, &p);
                if s.mu_fric * mid < target {
                    lo = mid
                } else {
                    hi = mid
                }
            }
            let closed = creep_shear_rate(m.shear_rate_floor, r);
            assert!(
                (lo - closed).abs() <= 1e-3 * closed,
                "r = {r}: {lo} vs {closed}"
            );
        }
        let h = 0.05;
        let creep_speed = h * creep_shear_rate(DEFAULT_SHEAR_RATE_FLOOR, 0.9);
        assert!(creep_speed < 1e-3 * (9.81 * h).sqrt());
    }
}
