//! Frictional stresses (docs/model.md §2.4) and the solids-pressure derivative K_cp (§2.5).
//!
//! - Schaeffer (1987) with MFIX's plastic pressure P* (paper Eq. 8; docs/model.md §2.4.1;
//!   MFIX `calc_mu_s.f` FRICTION_SCHAEFFER, `solids_pressure_mod.f`).
//! - Princeton / Srivastava & Sundaresan (2003), the paper's model (paper Eqs. 9–10 as MFIX
//!   computes them; docs/model.md §2.4.2 and §3.10; MFIX `calc_mu_s.f` FRICTION_PRINCETON).
//!
//! - μ(I), the rate-dependent friction of Jop, Forterre & Pouliquen (2006), not in MFIX
//!   ([`crate::mu_i`]; docs/model.md §2.4.4).
//!
//! Where the paper's printed equations differ, this follows MFIX (docs/model.md §3.10):
//! the P-Eq. 9 exponent is n − 1 (not 1/(N − 1)); in compaction n = N_Pf = 1.03 (not 0);
//! with Princeton there is no A(εg* − εg)^10 branch (P* ≡ 0, P_c is linearly extrapolated
//! above εs,max − δ); and kinetic and frictional stresses are summed, not switched
//! (see [`crate::stress`]).

use crate::guards::{SMALL_NUMBER, THETA_SMALL, TO_SI};
use crate::mu_i::MuIConstants;
use crate::stress::{FaceMean, KineticJoin};
use serde::{Deserialize, Serialize};
use std::f64::consts::SQRT_2;

/// Princeton model constants (MFIX `constant_mod.f` code parameters, docs/model.md §2.4.2, §5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PrincetonConstants {
    /// Fr = 0.5 dyn/cm² = 0.05 Pa (paper Eq. 10 "Fr")
    pub fr: f64,
    /// N_Pc = 2 [-], numerator exponent of P_c (paper's "B")
    pub n_pc: f64,
    /// D_Pc = 5 [-], denominator exponent of P_c (paper's "C")
    pub d_pc: f64,
    /// N_Pf = 1.03 [-], exponent n in compaction (paper Eq. 10 says 0; docs/model.md §3.10.2)
    pub n_pf: f64,
    /// δ = 0.01 [-]: P_c is linearised above εs,max − δ (docs/model.md §2.4.2 step 2)
    pub delta: f64,
}

impl PrincetonConstants {
    /// MFIX 21.3.2 `constant_mod.f` (identical in 2016-1): Fr = 0.5 dyn/cm², N_Pc = 2,
    /// D_Pc = 5, N_Pf = 1.03, δ = 0.01 (docs/model.md §2.4.2, §5).
    pub const MFIX: Self = Self {
        fr: 0.5 * TO_SI,
        n_pc: 2.0,
        d_pc: 5.0,
        n_pf: 1.03,
        delta: 0.01,
    };
}

impl Default for PrincetonConstants {
    /// [`PrincetonConstants::MFIX`].
    fn default() -> Self {
        Self::MFIX
    }
}

/// Schaeffer plastic-pressure constants (MFIX `solids_pressure_mod.f`, `calc_mu_s.f`;
/// paper Eq. 8; docs/model.md §2.4.1, §5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SchaefferConstants {
    /// A = 1e25 dyn/cm² = 1e24 Pa (paper Eq. 8, correct as printed: docs/model.md §3.10.7)
    pub a: f64,
    /// exponent of (εg* − εg): 10 [-]
    pub exponent: i32,
    /// cap on μ_Schaeffer: `MAX_MU_s` = 1000 poise = 100 Pa s
    pub mu_max: f64,
}

impl SchaefferConstants {
    /// A = 1e25 dyn/cm² (`a_ps`), exponent 10 (`b_ps`), μ_max = 1000 poise (`MAX_MU_s`),
    /// MFIX 21.3.2 (docs/model.md §2.4.1).
    pub const MFIX: Self = Self {
        a: 1e25 * TO_SI,
        exponent: 10,
        mu_max: 1000.0 * TO_SI,
    };
}

impl Default for SchaefferConstants {
    /// [`SchaefferConstants::MFIX`].
    fn default() -> Self {
        Self::MFIX
    }
}

/// Material parameters of the frictional closures (docs/model.md §2.4, §5), per solids
/// phase from the case; the models' code constants travel with the model
/// ([`FrictionModel::Schaeffer`], [`FrictionModel::Princeton`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionParams {
    /// εs,max = 1 − `EP_STAR` [-] (paper: 0.65, "ε_s*")
    pub eps_s_max: f64,
    /// εs,min = `EPS_F_MIN` [-] (MFIX default 0.5; paper: 0.5)
    pub eps_s_min: f64,
    /// sin φ of the internal friction angle φ = `PHI` [-] (converted once from degrees)
    pub sin_phi: f64,
}

impl FrictionParams {
    /// Parameters from εs,max, εs,min and the internal friction angle φ in degrees
    /// (style A6.13: degrees in, converted once).
    pub fn new(eps_s_max: f64, eps_s_min: f64, phi_internal_deg: f64) -> Self {
        Self {
            eps_s_max,
            eps_s_min,
            sin_phi: phi_internal_deg.to_radians().sin(),
        }
    }
}

impl Default for FrictionParams {
    /// The paper's sensitivity-analysis values (paper Table 3): εs,max = 0.65, εs,min = 0.5,
    /// φ = 35°.
    fn default() -> Self {
        Self::new(0.65, 0.5, 35.0)
    }
}

/// Frictional stress contributions at one state (docs/model.md §2.4). Intermediate Princeton
/// quantities are reported for diagnostics and the wall BCs; they are 0 when not evaluated.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct FrictionalStress {
    /// frictional pressure P_fric \[Pa\] (Princeton P_f; 0 for Schaeffer, whose pressure is P*)
    pub p_fric: f64,
    /// frictional shear viscosity [Pa s] (Princeton μ_fric or Schaeffer μ_Schaeffer)
    pub mu_fric: f64,
    /// frictional second viscosity [Pa s] (Princeton −(2/3) μ_fric; 0 for Schaeffer)
    pub lambda_fric: f64,
    /// Schaeffer plastic pressure P* \[Pa\], applied as its own gradient −∇P* (0 for Princeton)
    pub p_star: f64,
    /// Princeton critical pressure P_c \[Pa\]
    pub p_c: f64,
    /// Princeton ratio P_f/P_c [-] after the cap
    pub pf_over_pc: f64,
    /// Princeton strain scale ζ [1/s]
    pub zeta: f64,
    /// Princeton exponent n [-]
    pub n: f64,
    /// μ(I) inertial number I [-] (0 for the other models)
    pub inertial_number: f64,
    /// how μ_kin and λ_kin join this stress (MFIX's sum but for μ(I))
    pub kinetic_join: KineticJoin,
}

// ---------------------------------------------------------------- Schaeffer (§2.4.1)

impl SchaefferConstants {
    /// Plastic pressure P* = A (εg* − εg)^10 for εg < εg*, else 0 \[Pa\], with εg = 1 − εs,
    /// εg* = 1 − εs,max, A = 1e24 Pa (paper Eq. 8; docs/model.md §2.4.1; MFIX Neg_H).
    /// Not used with the Princeton model (docs/model.md §3.10.3).
    #[inline]
    pub fn p_star(&self, eps_s: f64, p: &FrictionParams) -> f64 {
        let excess = ((1.0 - p.eps_s_max) - (1.0 - eps_s)).max(0.0);
        self.a * excess.powi(self.exponent)
    }

    /// Inverse of [`SchaefferConstants::p_star`]: εg = εg* − (P*/A)^{1/10} [-], used to
    /// rebuild εs in packed cells (docs/model.md §2.4.1; MFIX INV_H). Valid for P* ≥ 0.
    #[inline]
    pub fn eps_g_from_p_star(&self, p_star: f64, p: &FrictionParams) -> f64 {
        (1.0 - p.eps_s_max) - (p_star / self.a).powf(1.0 / f64::from(self.exponent))
    }

    /// dP*/dεs = 10 A (εs − εs,max)^9 for εs > εs,max, else 0 \[Pa\] (docs/model.md §2.4.1,
    /// §2.5; MFIX dPodEP_s, written with εg* − εg like P*). K_cp of the Schaeffer model.
    #[inline]
    pub fn dp_star_deps(&self, eps_s: f64, p: &FrictionParams) -> f64 {
        let excess = ((1.0 - p.eps_s_max) - (1.0 - eps_s)).max(0.0);
        let exponent = self.exponent;
        f64::from(exponent) * self.a * excess.powi(exponent - 1)
    }

    /// Schaeffer viscosity μ = min(P* sin²φ / (√(4 sin²φ I₂D) + 1e-15), μ_max) [Pa s]
    /// (≈ P* sinφ/(2√I₂D); docs/model.md §2.4.1; MFIX FRICTION_SCHAEFFER), μ_max = 100 Pa s.
    /// `i2_dev_d` = I₂D [1/s²], second invariant of the deviatoric strain rate (= S:S/2).
    #[inline]
    pub fn viscosity(&self, p_star: f64, i2_dev_d: f64, p: &FrictionParams) -> f64 {
        let sin2_phi = p.sin_phi * p.sin_phi;
        (p_star * sin2_phi / ((4.0 * sin2_phi * i2_dev_d).sqrt() + SMALL_NUMBER)).min(self.mu_max)
    }

    /// Schaeffer model at one state (docs/model.md §2.4.1): P* and μ_Schaeffer with S:S
    /// floored at 0 and I₂D = S:S/2 (I₂D = ½ D':D' and S:S = D':D' for the deviator D' of D),
    /// λ = 0, P_fric = 0. Active only where εg < εg* (P* = 0 elsewhere, so μ = 0).
    #[inline]
    pub fn stress(&self, eps_s: f64, s_ddot_s: f64, p: &FrictionParams) -> FrictionalStress {
        let p_star = self.p_star(eps_s, p);
        FrictionalStress {
            p_star,
            mu_fric: self.viscosity(p_star, 0.5 * s_ddot_s.max(0.0), p),
            ..FrictionalStress::default()
        }
    }
}

// ---------------------------------------------------------------- Princeton (§2.4.2)

/// Strain scale ζ = √(θ/d² + S:S) [1/s] (MFIX 21.3.2 SAVAGE = 2, paper Eq. 9; docs/model.md
/// §2.4.2 step 1), S:S = tr(D²) − (tr D)²/3 ≥ 0 from the cell-centred solids strain rate.
/// θ is floored at [`THETA_SMALL`] (MFIX never has θ below it, docs/model.md §1.3), so ζ > 0
/// and μ_fric = m_f/(2ζ) stays finite when there is neither strain nor fluctuation; S:S is
/// floored at 0, removing only round-off of tr(D²) − (tr D)²/3.
#[inline]
pub fn strain_scale(theta: f64, d_p: f64, s_ddot_s: f64) -> f64 {
    (theta.max(THETA_SMALL) / (d_p * d_p) + s_ddot_s.max(0.0)).sqrt()
}

/// Uncapped P_f/P_c [-] (paper Eq. 9 with exponent n − 1, docs/model.md §2.4.2 step 4):
/// r = tr D/(n √2 sinφ ζ); 0 if r > 1; 1 if tr D = 0 exactly; else (1 − r)^{n−1}.
#[inline]
pub fn pf_over_pc_uncapped(tr_d: f64, zeta: f64, n: f64, sin_phi: f64) -> f64 {
    let r = tr_d / (zeta * n * SQRT_2 * sin_phi);
    if r > 1.0 {
        0.0
    } else if tr_d == 0.0 {
        1.0
    } else {
        (1.0 - r).powf(n - 1.0)
    }
}

/// Upper bound of P_f/P_c, (n/(n − 1))^{n−1} [-] (≈ 1.112 for n = 1.03), beyond which
/// m_f would be negative (docs/model.md §2.4.2 step 5).
#[inline]
pub fn pf_over_pc_max(n: f64) -> f64 {
    (n / (n - 1.0)).powf(n - 1.0)
}

impl PrincetonConstants {
    /// Linearisation point εs,at = εs,max − δ of P_c (docs/model.md §2.4.2 step 2).
    #[inline]
    pub fn eps_s_at(&self, p: &FrictionParams) -> f64 {
        p.eps_s_max - self.delta
    }

    /// dP_c/dεs of the power law, Fr [N_Pc (εs − εs,min)^{N_Pc−1}/(εs,max − εs)^{D_Pc}
    /// + D_Pc (εs − εs,min)^{N_Pc}/(εs,max − εs)^{D_Pc+1}].
    #[inline]
    fn dpc_power_law(&self, eps_s: f64, p: &FrictionParams) -> f64 {
        let above_min = eps_s - p.eps_s_min;
        let below_max = p.eps_s_max - eps_s;
        self.fr
            * (self.n_pc * above_min.powf(self.n_pc - 1.0) / below_max.powf(self.d_pc)
                + self.d_pc * above_min.powf(self.n_pc) / below_max.powf(self.d_pc + 1.0))
    }

    /// Slope P_c' = Fr [N_Pc (εs,at − εs,min)^{N_Pc−1}/δ^{D_Pc} + D_Pc (εs,at −
    /// εs,min)^{N_Pc}/δ^{D_Pc+1}] of the linear extrapolation, written with δ as MFIX does
    /// (`dpcdep_at`).
    #[inline]
    fn dpc_at(&self, p: &FrictionParams) -> f64 {
        let above_min = self.eps_s_at(p) - p.eps_s_min;
        self.fr
            * (self.n_pc * above_min.powf(self.n_pc - 1.0) / self.delta.powf(self.d_pc)
                + self.d_pc * above_min.powf(self.n_pc) / self.delta.powf(self.d_pc + 1.0))
    }

    /// Princeton critical pressure P_c(εs) \[Pa\] (paper Eq. 10 middle branch; docs/model.md
    /// §2.4.2 step 2; MFIX FRICTION_PRINCETON):
    /// - εs ≤ εs,min: 0 (friction not evaluated);
    /// - εs ≤ εs,max − δ: P_c = Fr (εs − εs,min)^2/(εs,max − εs)^5;
    /// - above: linear extrapolation P_c = P_c,at + P_c' (εs − εs,at), εs,at = εs,max − δ,
    ///   P_c,at = Fr (εs,at − εs,min)²/δ⁵, P_c' = dP_c/dεs at εs,at
    ///   (paper values: 9.8e6 Pa and 5.04e9 Pa). No A(εg* − εg)^10 branch (docs/model.md
    ///   §3.10.3).
    #[inline]
    pub fn critical_pressure(&self, eps_s: f64, p: &FrictionParams) -> f64 {
        let at = self.eps_s_at(p);
        if eps_s <= p.eps_s_min {
            0.0
        } else if eps_s > at {
            let p_c_at = self.fr * (at - p.eps_s_min).powf(self.n_pc) / self.delta.powf(self.d_pc);
            p_c_at + self.dpc_at(p) * (eps_s - at)
        } else {
            self.fr * (eps_s - p.eps_s_min).powf(self.n_pc) / (p.eps_s_max - eps_s).powf(self.d_pc)
        }
    }

    /// dP_c/dεs \[Pa\] of [`PrincetonConstants::critical_pressure`] (docs/model.md §2.5; MFIX
    /// `calc_k_cp.f`): Fr [2(εs − εs,min)/(εs,max − εs)^5 + 5(εs − εs,min)²/(εs,max − εs)^6]
    /// up to εs,max − δ, the constant P_c' beyond, 0 at or below εs,min.
    #[inline]
    pub fn dcritical_pressure_deps(&self, eps_s: f64, p: &FrictionParams) -> f64 {
        let at = self.eps_s_at(p);
        if eps_s <= p.eps_s_min {
            0.0
        } else if eps_s > at {
            self.dpc_at(p)
        } else {
            self.dpc_power_law(eps_s, p)
        }
    }

    /// Exponent n [-]: √3/(2 sinφ) if tr D ≥ 0 (dilatation), N_Pf = 1.03 if tr D < 0
    /// (compaction) (docs/model.md §2.4.2 step 3; paper Eq. 10 text says 0 in compaction:
    /// MFIX uses 1.03, docs/model.md §3.10.2). Requires φ < 60° so that n > 1 in dilatation.
    #[inline]
    pub fn exponent(&self, tr_d: f64, p: &FrictionParams) -> f64 {
        if tr_d >= 0.0 {
            3.0_f64.sqrt() / (2.0 * p.sin_phi)
        } else {
            self.n_pf
        }
    }

    /// Princeton frictional stress at one state (paper Eqs. 9–10 as MFIX computes them,
    /// docs/model.md §2.4.2; MFIX FRICTION_PRINCETON with SAVAGE = 2), zero for εs ≤ εs,min:
    /// ζ = √(θ/d² + S:S); P_f = P_c · (P_f/P_c);
    /// m_f = √2 P_f sinφ [n − (n − 1)(P_f/P_c)^{1/(n−1)}]; if P_f/P_c > (n/(n−1))^{n−1} it is
    /// set to that bound and m_f = 0; μ_fric = m_f/(2ζ) [Pa s] (no upper cap),
    /// λ_fric = −(2/3) μ_fric [Pa s], P_fric = P_f \[Pa\]. One solids phase: the polydisperse
    /// factor εs/Σε_cp is 1.
    #[inline]
    pub fn stress(
        &self,
        eps_s: f64,
        theta: f64,
        d_p: f64,
        tr_d: f64,
        s_ddot_s: f64,
        p: &FrictionParams,
    ) -> FrictionalStress {
        if eps_s <= p.eps_s_min {
            return FrictionalStress::default();
        }
        let zeta = strain_scale(theta, d_p, s_ddot_s);
        let p_c = self.critical_pressure(eps_s, p);
        let n = self.exponent(tr_d, p);
        let mut ratio = pf_over_pc_uncapped(tr_d, zeta, n, p.sin_phi);
        let mut p_f = p_c * ratio;
        let mut m_f = SQRT_2 * p_f * p.sin_phi * (n - (n - 1.0) * ratio.powf(1.0 / (n - 1.0)));
        let cap = pf_over_pc_max(n);
        if ratio > cap {
            ratio = cap;
            p_f = p_c * cap;
            m_f = 0.0;
        }
        let mu_fric = m_f / (2.0 * zeta);
        FrictionalStress {
            p_fric: p_f,
            mu_fric,
            lambda_fric: -2.0 / 3.0 * mu_fric,
            p_star: 0.0,
            p_c,
            pf_over_pc: ratio,
            zeta,
            n,
            inertial_number: 0.0,
            kinetic_join: KineticJoin::Sum,
        }
    }

    /// K_cp = dP_s/dεs \[Pa\] of the Princeton model (docs/model.md §2.5; MFIX `calc_k_cp.f`,
    /// SAVAGE = 2): (P_f/P_c) · dP_c/dεs for εs > εs,min, else 0. Kinetic pressure is left
    /// out (as in MFIX). P_f/P_c as in [`PrincetonConstants::stress`], except that its cap
    /// always uses N_Pf and is applied only when tr D ≠ 0 and r ≤ 1 (MFIX code detail).
    #[inline]
    pub fn k_cp(
        &self,
        eps_s: f64,
        theta: f64,
        d_p: f64,
        tr_d: f64,
        s_ddot_s: f64,
        p: &FrictionParams,
    ) -> f64 {
        if eps_s <= p.eps_s_min {
            return 0.0;
        }
        let zeta = strain_scale(theta, d_p, s_ddot_s);
        let n = self.exponent(tr_d, p);
        let mut ratio = pf_over_pc_uncapped(tr_d, zeta, n, p.sin_phi);
        let general_branch = tr_d != 0.0 && tr_d / (zeta * n * SQRT_2 * p.sin_phi) <= 1.0;
        if general_branch {
            ratio = ratio.min(pf_over_pc_max(self.n_pf));
        }
        ratio * self.dcritical_pressure_deps(eps_s, p)
    }

    /// K_cp \[Pa\] from an already evaluated Princeton stress: (P_f/P_c) · dP_c/dεs, with the
    /// P_f/P_c of [`PrincetonConstants::stress`]. Equal to [`PrincetonConstants::k_cp`]
    /// (SAVAGE = 2): in compaction n = N_Pf, so both caps coincide, and in dilatation
    /// P_f/P_c ≤ 1 stays below either cap. Saves the second evaluation of ζ, n and P_f/P_c
    /// in [`crate::cell::evaluate`].
    #[inline]
    pub fn k_cp_from_stress(
        &self,
        eps_s: f64,
        stress: &FrictionalStress,
        p: &FrictionParams,
    ) -> f64 {
        if eps_s <= p.eps_s_min {
            return 0.0;
        }
        stress.pf_over_pc * self.dcritical_pressure_deps(eps_s, p)
    }
}

/// Choice of frictional model (MFIX `FRICTION_MODEL`, docs/model.md §2.4), each with its
/// code constants. Default: Princeton (`SRIVASTAVA`), the paper's model (MFIX's own default
/// is Schaeffer). Case files name the model only ([`FrictionName`]); its constants are
/// MFIX's.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(from = "FrictionName", into = "FrictionName")]
pub enum FrictionModel {
    /// `NONE`: kinetic theory only.
    None,
    /// `SCHAEFFER`: [`SchaefferConstants::stress`], with P* as a separate pressure.
    Schaeffer(SchaefferConstants),
    /// `SRIVASTAVA` (Princeton): [`PrincetonConstants::stress`].
    Princeton(PrincetonConstants),
    /// μ(I) with the case's μ_s, μ_2, I_0 (not in MFIX): [`MuIConstants::stress`].
    MuI(MuIConstants),
}

/// The name of a frictional model as case files write it (`friction: Schaeffer`,
/// `friction: MuI(mu_s: 0.38, mu_2: 0.64, i_0: 0.28)`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum FrictionName {
    /// [`FrictionModel::None`]
    None,
    /// [`FrictionModel::Schaeffer`]
    Schaeffer,
    /// [`FrictionModel::Princeton`]
    Princeton,
    /// [`FrictionModel::MuI`] with its parameters ([`MuIConstants`]'s fields)
    MuI {
        /// μ_s [-]
        mu_s: f64,
        /// μ_2 [-]
        mu_2: f64,
        /// I_0 [-]
        i_0: f64,
        /// γ̇_min [1/s], default [`crate::mu_i::DEFAULT_SHEAR_RATE_FLOOR`]
        #[serde(default = "crate::mu_i::default_shear_rate_floor")]
        shear_rate_floor: f64,
    },
}

impl From<FrictionName> for FrictionModel {
    /// The named model with MFIX's constants.
    fn from(name: FrictionName) -> Self {
        match name {
            FrictionName::None => Self::None,
            FrictionName::Schaeffer => Self::schaeffer(),
            FrictionName::Princeton => Self::princeton(),
            FrictionName::MuI {
                mu_s,
                mu_2,
                i_0,
                shear_rate_floor,
            } => Self::MuI(MuIConstants {
                mu_s,
                mu_2,
                i_0,
                shear_rate_floor,
            }),
        }
    }
}

impl From<FrictionModel> for FrictionName {
    fn from(model: FrictionModel) -> Self {
        match model {
            FrictionModel::None => Self::None,
            FrictionModel::Schaeffer(_) => Self::Schaeffer,
            FrictionModel::Princeton(_) => Self::Princeton,
            FrictionModel::MuI(c) => Self::MuI {
                mu_s: c.mu_s,
                mu_2: c.mu_2,
                i_0: c.i_0,
                shear_rate_floor: c.shear_rate_floor,
            },
        }
    }
}

impl Default for FrictionModel {
    /// Princeton with MFIX's constants, the paper's model.
    fn default() -> Self {
        Self::princeton()
    }
}

impl FrictionModel {
    /// Schaeffer with MFIX 21.3.2's constants ([`SchaefferConstants::default`]).
    pub fn schaeffer() -> Self {
        Self::Schaeffer(SchaefferConstants::default())
    }

    /// Princeton with MFIX 21.3.2's constants ([`PrincetonConstants::default`]).
    pub fn princeton() -> Self {
        Self::Princeton(PrincetonConstants::default())
    }

    /// The model's name as case files write it.
    pub fn name(self) -> &'static str {
        match self {
            Self::None => "None",
            Self::Schaeffer(_) => "Schaeffer",
            Self::Princeton(_) => "Princeton",
            Self::MuI(_) => "MuI",
        }
    }

    /// The plastic pressure P* of the model, if it has one: it enters the solids momentum
    /// as its own gradient −∇P* and is rebuilt from the corrected εs (Schaeffer: P* =
    /// A (εg* − εg)^10, paper Eq. 8; docs/model.md §2.4.1, §4.4, §4.9 step 5). Princeton
    /// has none: MFIX never computes P* with it (§2.4.2).
    #[inline]
    pub fn plastic_pressure(&self) -> Option<&SchaefferConstants> {
        match self {
            Self::Schaeffer(c) => Some(c),
            Self::None | Self::Princeton(_) | Self::MuI(_) => None,
        }
    }

    /// How the solids viscosity is averaged to the momentum cells' corners
    /// ([`FaceMean`]): arithmetic for μ(I), whose viscosity is a Coulomb strength μ(I) P/γ̇
    /// (docs/model.md §2.4.4), MFIX's harmonic mean otherwise.
    pub fn corner_viscosity_mean(&self) -> FaceMean {
        match self {
            Self::MuI(_) => FaceMean::Arithmetic,
            Self::None | Self::Princeton(_) | Self::Schaeffer(_) => FaceMean::Harmonic,
        }
    }

    /// Whether the solids momentum rows are under-relaxed in proportion to their own part
    /// a_P − Σ a_nb rather than the whole a_P (docs/model.md §4.10): μ(I), whose regularised
    /// viscosity μ(I) P/γ̇_min at rest makes a layer's links about 1e4 times its inertia, so
    /// that Patankar's a_P/ω freezes its rigid motion; MFIX's Patankar form otherwise.
    pub fn relaxes_momentum_by_own_part(&self) -> bool {
        matches!(self, Self::MuI(_))
    }

    /// Whether the model has a plastic pressure P* ([`FrictionModel::plastic_pressure`]).
    #[inline]
    pub fn has_plastic_pressure(self) -> bool {
        self.plastic_pressure().is_some()
    }

    /// The gas fraction εg* = 1 − εs,max below which the model holds θ at θ_small (a fixed
    /// row of the θ system: Schaeffer, docs/model.md §1.3 last bullet, where its plastic
    /// regime εg < εg* has no granular temperature); `None` if θ is never pinned.
    #[inline]
    pub fn pins_theta_below(self, p: &FrictionParams) -> Option<f64> {
        matches!(self, Self::Schaeffer(_)).then_some(1.0 - p.eps_s_max)
    }

    /// The most solids phases the model is implemented for (`None`: no limit). Schaeffer's
    /// P* of several phases uses the mixture εg and εs/Σε_cp weights, not implemented
    /// (docs/model.md §2.4.1 last paragraph, departure M11); μ(I)'s inertial number of a
    /// mixture (which d, which P) is not implemented (§2.4.4).
    #[inline]
    pub fn max_solids_phases(self) -> Option<usize> {
        match self {
            Self::Schaeffer(_) | Self::MuI(_) => Some(1),
            Self::None | Self::Princeton(_) => None,
        }
    }

    /// Whether a Johnson–Jackson or Jenkins wall next to solids at `eps_s` adds the frictional
    /// wall stress FRI = tan δ_w (P_f − 2 μ_f S_nn) and μ_f to its slip coefficient, h_w^u =
    /// (COL + FRI)/(μ_k ⊕ μ_f) (docs/model.md §3.5 step 3); the stress is then
    /// [`FrictionModel::stress`]. The wall answers where the interior does:
    /// - Princeton above εs,min, as MFIX `calc_grbdry.f` (its P_f and μ_f vanish there, so the
    ///   wall's coefficient is continuous across εs,min);
    /// - μ(I) at every εs: its stress acts on the total pressure P_kin + P_c in every cell
    ///   (§2.4.4), so gated at εs,min a wall cell's h jumped from (COL + FRI)/μ_f to COL/μ_k —
    ///   by μ_f/μ_k, orders of magnitude — as a sheared basal layer dilated through εs,min, and
    ///   the layer's outer iterations cycled across it (issue 58: the foot study's JJ floor);
    /// - Schaeffer and no friction never.
    #[inline]
    pub fn wall_friction_acts_at(self, eps_s: f64, p: &FrictionParams) -> bool {
        match self {
            Self::Princeton(_) => eps_s > p.eps_s_min,
            Self::MuI(_) => true,
            Self::None | Self::Schaeffer(_) => false,
        }
    }

    /// Frictional stresses of the chosen model (docs/model.md §2.4); all zero for `None`.
    /// ρ_s and the kinetic pressure P_kin \[Pa\] enter μ(I) only (its I and total pressure).
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub fn stress(
        self,
        eps_s: f64,
        theta: f64,
        d_p: f64,
        rho_s: f64,
        tr_d: f64,
        s_ddot_s: f64,
        p_kin: f64,
        p: &FrictionParams,
    ) -> FrictionalStress {
        match self {
            Self::None => FrictionalStress::default(),
            Self::Schaeffer(c) => c.stress(eps_s, s_ddot_s, p),
            Self::Princeton(c) => c.stress(eps_s, theta, d_p, tr_d, s_ddot_s, p),
            Self::MuI(c) => c.stress(eps_s, d_p, rho_s, s_ddot_s, p_kin, p),
        }
    }

    /// K_cp = dP_s/dεs \[Pa\] for the solids volume-fraction correction (docs/model.md §2.5;
    /// MFIX `calc_k_cp.f`): Princeton [`PrincetonConstants::k_cp`], Schaeffer
    /// [`SchaefferConstants::dp_star_deps`], μ(I) [`MuIConstants::k_cp`], `None` 0 (no
    /// close-packed pressure). The solver
    /// sets K_cp = 0 in wall cells.
    #[inline]
    pub fn k_cp(
        self,
        eps_s: f64,
        theta: f64,
        d_p: f64,
        tr_d: f64,
        s_ddot_s: f64,
        p: &FrictionParams,
    ) -> f64 {
        match self {
            Self::None => 0.0,
            Self::Schaeffer(c) => c.dp_star_deps(eps_s, p),
            Self::Princeton(c) => c.k_cp(eps_s, theta, d_p, tr_d, s_ddot_s, p),
            Self::MuI(c) => c.k_cp(eps_s, p),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The solver's questions: only Schaeffer has P*, pins θ below εg* = 1 − εs,max and is
    /// limited to one phase; Princeton adds FRI at a JJ/Jenkins wall above εs,min, μ(I) at
    /// every εs.
    #[test]
    fn each_model_answers_the_solvers_questions() {
        let p = FrictionParams::default();
        let answers = |m: FrictionModel| {
            (
                m.plastic_pressure().copied(),
                m.pins_theta_below(&p),
                m.max_solids_phases(),
                [0.3, 0.5, 0.55].map(|eps_s| m.wall_friction_acts_at(eps_s, &p)),
            )
        };
        let eps_g_star = 1.0 - p.eps_s_max;
        let schaeffer = SchaefferConstants::default();
        assert_eq!(
            answers(FrictionModel::schaeffer()),
            (Some(schaeffer), Some(eps_g_star), Some(1), [false; 3])
        );
        assert_eq!(
            answers(FrictionModel::princeton()),
            (None, None, None, [false, false, true])
        );
        assert_eq!(answers(FrictionModel::None), (None, None, None, [false; 3]));
        assert_eq!(
            answers(FrictionModel::MuI(MuIConstants::glass_beads_jop_2005())),
            (None, None, Some(1), [true; 3])
        );
    }

    /// Case files name the model only; it comes with MFIX's constants and writes back as
    /// its name.
    #[test]
    fn a_model_reads_and_writes_as_its_name() {
        for (name, model) in [
            ("None", FrictionModel::None),
            ("Schaeffer", FrictionModel::schaeffer()),
            ("Princeton", FrictionModel::princeton()),
        ] {
            let json = format!("\"{name}\"");
            assert_eq!(serde_json::from_str::<FrictionModel>(&json).unwrap(), model);
            assert_eq!(serde_json::to_string(&model).unwrap(), json);
            assert_eq!(model.name(), name);
        }
    }

    /// μ(I) carries its parameters in the case file; the floor defaults to γ̇_min = 1e-3 s⁻¹.
    #[test]
    fn mu_i_reads_with_its_parameters() {
        let json = r#"{"MuI":{"mu_s":0.38,"mu_2":0.64,"i_0":0.28}}"#;
        let unknown = r#"{"MuI":{"mu_s":0.38,"mu_2":0.64,"i_0":0.28,"mu_3":1}}"#;
        assert!(serde_json::from_str::<FrictionModel>(unknown).is_err());
        let model: FrictionModel = serde_json::from_str(json).unwrap();
        let FrictionModel::MuI(c) = model else {
            panic!("{model:?}")
        };
        assert_eq!((c.mu_s, c.mu_2, c.i_0), (0.38, 0.64, 0.28));
        assert_eq!(c.shear_rate_floor, crate::mu_i::DEFAULT_SHEAR_RATE_FLOOR);
        let back: FrictionModel =
            serde_json::from_str(&serde_json::to_string(&model).unwrap()).unwrap();
        assert_eq!(back, model);
        assert!(serde_json::from_str::<FrictionModel>(r#"{"MuI":{"mu_s":0.38}}"#).is_err());
    }
}
