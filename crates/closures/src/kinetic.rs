//! Kinetic theory of Lun et al. (1984) as MFIX codes it (`KT_TYPE = 'LUN_1984'`, K. Agrawal's
//! implementation with the interstitial-gas correction and the (2+α)/3 factor):
//! docs/model.md §2.2, MFIX 21.3.2 `model/calc_mu_s.f` GT_PDE_LUN (identical in 2016-1);
//! collisional dissipation from `model/source_granular_energy.f` (docs/model.md §1.3).
//!
//! One solids phase: ξ = εs g0 stands for MFIX's Σ_k ε_k g0_mk. η = (1 + e)/2.
//! MFIX stress convention τ = −P I + 2μ D + λ (tr D) I (docs/model.md §0.3).

use crate::cell::Particles;
use crate::guards::SMALL_NUMBER;
use crate::radial::RadialDistribution;
use serde::Serialize;
use std::f64::consts::PI;

/// α = `ALPHA` = 1.6 [-] in the adjustable factor (2 + α)/3 of the shear viscosity
/// (MFIX `constant_mod.f` parameter, docs/model.md §2.2 and §5; α = 1 recovers Lun et al.).
pub const LUN_ALPHA: f64 = 1.6;

/// The local solids state the kinetic-theory closures need (style A6.2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolidsState {
    /// solids volume fraction εs [-]
    pub eps_s: f64,
    /// granular temperature θ [m²/s²] (θ = ⟨c'²⟩/3, paper Eq. 7)
    pub theta: f64,
    /// solids material density ρs [kg/m³]
    pub rho_s: f64,
    /// particle diameter d \[m\]
    pub d_p: f64,
    /// particle–particle restitution coefficient e [-] (`C_E`)
    pub restitution: f64,
    /// radial distribution at contact g0(εs) [-] (docs/model.md §2.1)
    pub g0: f64,
}

impl SolidsState {
    /// State at (εs, θ) for the given particles, with g0 from the chosen radial
    /// distribution (docs/model.md §2.1).
    #[inline]
    pub fn new(eps_s: f64, theta: f64, particles: &Particles, radial: RadialDistribution) -> Self {
        Self {
            eps_s,
            theta,
            rho_s: particles.density,
            d_p: particles.diameter,
            restitution: particles.restitution,
            g0: radial.g0(eps_s),
        }
    }

    /// η = (1 + e)/2 [-] (docs/model.md §0.3; MFIX `check_solids_continuum.f`).
    #[inline]
    pub fn eta(&self) -> f64 {
        0.5 * (1.0 + self.restitution)
    }

    /// ξ = εs g0 [-], MFIX's Σ_k ε_k g0 for one solids phase (docs/model.md §2.2).
    #[inline]
    pub fn xi(&self) -> f64 {
        self.eps_s * self.g0
    }
}

/// How the interstitial gas modifies the dilute viscosity and conductivity μ*, κ*
/// (MFIX `SWITCH = 1`; docs/model.md §2.2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GasCoupling {
    /// No gas (ρ_g = 0): μ* = μ₀, κ* = κ₀.
    Dry,
    /// Gas present, with the drag coefficient per unit solids fraction
    /// DgA = F_gs/εs [kg m⁻³ s⁻¹] (Model A, docs/model.md §2.6). Below `DIL_EP_S` MFIX passes the
    /// single-particle drag instead ([`crate::drag::dga_single_particle`]); at walls the
    /// Wen–Yu estimate ([`crate::drag::dga_wall_wen_yu`]).
    Drag(f64),
}

impl GasCoupling {
    /// Gas coupling from the drag coefficient F_gs [kg m⁻³ s⁻¹] of a cell with solids
    /// fraction εs > 0: DgA = F_gs/εs (docs/model.md §2.2 table, μ* row).
    #[inline]
    pub fn from_f_gs(f_gs: f64, eps_s: f64) -> Self {
        Self::Drag(f_gs / eps_s)
    }
}

/// Kinetic solids pressure P_kin = ρs εs θ (1 + 4 η ξ) \[Pa\]
/// (paper Eq. 6; docs/model.md §2.2).
#[inline]
pub fn p_kin(s: &SolidsState) -> f64 {
    s.rho_s * s.eps_s * s.theta * (1.0 + 4.0 * s.eta() * s.xi())
}

/// Dilute viscosity μ₀ = (5/96) ρs d √(π θ) [Pa s] (docs/model.md §2.2).
#[inline]
pub fn mu_dilute(s: &SolidsState) -> f64 {
    5.0 / 96.0 * s.rho_s * s.d_p * (PI * s.theta).sqrt()
}

/// Bulk viscosity μ_b = (256/(5π)) μ₀ εs ξ [Pa s] (paper Eq. 5 "μ_b"; docs/model.md §2.2).
#[inline]
pub fn mu_bulk(s: &SolidsState) -> f64 {
    256.0 / (5.0 * PI) * mu_dilute(s) * s.eps_s * s.xi()
}

/// Gas-modified dilute coefficient shared by μ* and κ*:
/// c* = ρs εs g0 θ c₀ / (ρs ξ θ + k DgA c₀/ρs) with k = 2 (μ*) or 6/5 (κ*);
/// MFIX writes k F_gs c₀/(ρs εs), the same with F_gs = εs DgA.
#[inline]
fn gas_modified(s: &SolidsState, dilute: f64, drag_factor: f64, gas: GasCoupling) -> f64 {
    match gas {
        GasCoupling::Dry => dilute,
        GasCoupling::Drag(_) if s.theta < SMALL_NUMBER => 0.0,
        // zero drag: c* = c₀ exactly (also the εs → 0 limit, where the ratio is 0/0)
        GasCoupling::Drag(0.0) => dilute,
        GasCoupling::Drag(dga) => {
            s.rho_s * s.eps_s * s.g0 * s.theta * dilute
                / (s.rho_s * s.xi() * s.theta + drag_factor * dga * dilute / s.rho_s)
        }
    }
}

/// Gas-modified dilute viscosity [Pa s] (docs/model.md §2.2; MFIX GT_PDE_LUN):
/// μ* = ρs εs g0 θ μ₀ / (ρs ξ θ + 2 F_gs μ₀/(ρs εs)) with F_gs/εs = DgA;
/// μ* = μ₀ if dry (ρ_g = 0); μ* = 0 if θ < `SMALL_NUMBER` (1e-15).
#[inline]
pub fn mu_star(s: &SolidsState, gas: GasCoupling) -> f64 {
    gas_modified(s, mu_dilute(s), 2.0, gas)
}

/// Kinetic shear viscosity [Pa s] (paper Eq. 5 "μ^k"; docs/model.md §2.2):
/// μ_kin = ((2+α)/3) [ μ*/(η(2−η) g0) · (1 + (8/5)ηξ)(1 + (8/5)η(3η−2)ξ) + (3/5) η μ_b ],
/// α = [`LUN_ALPHA`].
#[inline]
pub fn mu_kin(s: &SolidsState, mu_star: f64) -> f64 {
    let eta = s.eta();
    let xi = s.xi();
    (2.0 + LUN_ALPHA) / 3.0
        * (mu_star / (eta * (2.0 - eta) * s.g0)
            * (1.0 + 8.0 / 5.0 * eta * xi)
            * (1.0 + 8.0 / 5.0 * eta * (3.0 * eta - 2.0) * xi)
            + 3.0 / 5.0 * eta * mu_bulk(s))
}

/// Kinetic second viscosity λ_kin = η μ_b − (2/3) μ_kin [Pa s] (docs/model.md §2.2; the
/// paper's (−P + ημ_b ∇·v) I term of Eq. 5 in MFIX's τ = … + λ (tr D) I convention).
#[inline]
pub fn lambda_kin(s: &SolidsState, mu_kin: f64) -> f64 {
    s.eta() * mu_bulk(s) - 2.0 / 3.0 * mu_kin
}

/// Dilute granular conductivity κ₀ = 75 ρs d √(π θ) / (48 η (41 − 33η)) [kg m⁻¹ s⁻¹]
/// (docs/model.md §2.2).
#[inline]
pub fn kappa_dilute(s: &SolidsState) -> f64 {
    let eta = s.eta();
    75.0 * s.rho_s * s.d_p * (PI * s.theta).sqrt() / (48.0 * eta * (41.0 - 33.0 * eta))
}

/// Gas-modified dilute conductivity [kg m⁻¹ s⁻¹] (docs/model.md §2.2; MFIX GT_PDE_LUN):
/// κ* = ρs εs g0 θ κ₀ / (ρs ξ θ + (6/5) F_gs κ₀/(ρs εs)) with F_gs/εs = DgA;
/// κ* = κ₀ if dry; κ* = 0 if θ < `SMALL_NUMBER`.
#[inline]
pub fn kappa_star(s: &SolidsState, gas: GasCoupling) -> f64 {
    gas_modified(s, kappa_dilute(s), 6.0 / 5.0, gas)
}

/// Granular conductivity κ_s [kg m⁻¹ s⁻¹] (docs/model.md §2.2, §1.3):
/// κ_s = (κ*/g0) [ (1 + (12/5)ηξ)(1 + (12/5)η²(4η−3)ξ) + (64/(25π))(41 − 33η) η² ξ² ].
#[inline]
pub fn kappa_kin(s: &SolidsState, kappa_star: f64) -> f64 {
    let eta = s.eta();
    let xi = s.xi();
    kappa_star / s.g0
        * ((1.0 + 12.0 / 5.0 * eta * xi) * (1.0 + 12.0 / 5.0 * eta * eta * (4.0 * eta - 3.0) * xi)
            + 64.0 / (25.0 * PI) * (41.0 - 33.0 * eta) * (eta * xi) * (eta * xi))
}

/// Collisional dissipation γ = (48/√π) η(1−η) ρs εs ξ θ^{3/2}/d [W m⁻³]
/// (= 12(1−e²) ρs εs² g0 θ^{3/2}/(d√π)); docs/model.md §1.3 and §2.2, MFIX
/// `source_granular_energy.f` (applied implicitly as γ/θ · θ).
#[inline]
pub fn dissipation(s: &SolidsState) -> f64 {
    let eta = s.eta();
    48.0 / PI.sqrt() * eta * (1.0 - eta) * s.rho_s * s.eps_s * s.xi() * s.theta * s.theta.sqrt()
        / s.d_p
}

/// Every kinetic-theory value at one state (docs/model.md §2.2). These are the paper's
/// "P^k" and "μ^k" (Table 2) and the KT parts that enter the granular-energy production.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct KineticStress {
    /// P_kin \[Pa\], paper Eq. 6
    pub p_kin: f64,
    /// μ₀ [Pa s]
    pub mu_dilute: f64,
    /// μ_b [Pa s]
    pub mu_bulk: f64,
    /// μ* [Pa s]
    pub mu_star: f64,
    /// μ_kin [Pa s]
    pub mu_kin: f64,
    /// λ_kin [Pa s]
    pub lambda_kin: f64,
    /// κ₀ [kg m⁻¹ s⁻¹]
    pub kappa_dilute: f64,
    /// κ* [kg m⁻¹ s⁻¹]
    pub kappa_star: f64,
    /// κ_s [kg m⁻¹ s⁻¹]
    pub kappa_kin: f64,
    /// γ [W m⁻³]
    pub dissipation: f64,
}

/// All Lun (1984) kinetic-theory closures at one state (docs/model.md §2.2, MFIX GT_PDE_LUN).
#[inline]
pub fn lun_1984(s: &SolidsState, gas: GasCoupling) -> KineticStress {
    let mu_star = mu_star(s, gas);
    let mu_kin = mu_kin(s, mu_star);
    let kappa_star = kappa_star(s, gas);
    KineticStress {
        p_kin: p_kin(s),
        mu_dilute: mu_dilute(s),
        mu_bulk: mu_bulk(s),
        mu_star,
        mu_kin,
        lambda_kin: lambda_kin(s, mu_kin),
        kappa_dilute: kappa_dilute(s),
        kappa_star,
        kappa_kin: kappa_kin(s, kappa_star),
        dissipation: dissipation(s),
    }
}
