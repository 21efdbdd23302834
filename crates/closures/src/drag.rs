//! Gas–solids drag (docs/model.md §2.6; MFIX 21.3.2 `model/drag_gs.f`, `model/drag_mod.f`).
//!
//! Each law returns the per-particle-volume coefficient DgA [kg m⁻³ s⁻¹]; the Model-A
//! interphase coefficient is F_gs = εs · DgA ([`Drag::f_gs`]). |v| = |u_g − u_s| is the
//! relative speed from cell-centred averages of the face velocities of both phases.

use crate::guards::{LARGE_NUMBER, SMALL_NUMBER};
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// Syamlal–O'Brien default `DRAG_C1` = 0.8 [-] (MFIX keyword default, docs/model.md §2.6, §5).
pub const SYAMLAL_OBRIEN_C1: f64 = 0.8;
/// Syamlal–O'Brien default `DRAG_D1` = 2.65 [-] (MFIX keyword default, docs/model.md §2.6, §5).
pub const SYAMLAL_OBRIEN_D1: f64 = 2.65;
/// εg at which Syamlal–O'Brien's B switches from c1 εg^1.28 to εg^d1: 0.85 [-] (docs/model.md §2.6).
pub const SYAMLAL_OBRIEN_EPS_G_SWITCH: f64 = 0.85;
/// Exponent of εg in Syamlal–O'Brien's A = εg^4.14 [-] (docs/model.md §2.6).
const SO_EXPONENT_A: f64 = 4.14;
/// Exponent of εg in Syamlal–O'Brien's dense B = c1 εg^1.28 [-] (docs/model.md §2.6).
const SO_EXPONENT_B: f64 = 1.28;
/// Coefficient 0.06 of Re in the terminal-velocity ratio V_r (docs/model.md §2.6).
const SO_RE_COEFFICIENT: f64 = 0.06;
/// Dalla Valle (1948) C_d Re/V_r = (0.63 √(Re/V_r) + 4.8)² coefficients (MFIX C_DSXRE_DV).
const DALLA_VALLE: (f64, f64) = (0.63, 4.8);
/// Ergun coefficients 150 (viscous) and 1.75 (inertial) (docs/model.md §2.6, Gidaspow dense branch).
const ERGUN: (f64, f64) = (150.0, 1.75);
/// εg separating Gidaspow's Ergun and Wen–Yu branches: 0.8 [-] (docs/model.md §2.6).
pub const GIDASPOW_EPS_G_SWITCH: f64 = 0.8;
/// Wen–Yu voidage exponent: DgA ∝ εg^−2.65 (docs/model.md §2.6).
const WEN_YU_EXPONENT: f64 = 2.65;
/// Schiller–Naumann C_d = 24(1 + 0.15 Re^0.687)/Re coefficients (MFIX C_DS_SN).
const SCHILLER_NAUMANN: (f64, f64, f64) = (24.0, 0.15, 0.687);
/// Reynolds number above which C_d = 0.44 (Newton regime) (docs/model.md §2.6).
const RE_NEWTON: f64 = 1000.0;
/// Newton-regime drag coefficient C_d = 0.44 (docs/model.md §2.6).
const CD_NEWTON: f64 = 0.44;

/// Local state a drag law needs (docs/model.md §2.6).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DragInputs {
    /// gas volume fraction εg [-]
    pub eps_g: f64,
    /// gas density ρ_g [kg/m³]
    pub rho_g: f64,
    /// gas viscosity μ_g [Pa s]
    pub mu_g: f64,
    /// relative speed |v| = |u_g − u_s| [m/s]
    pub slip: f64,
    /// particle diameter d \[m\]
    pub d_p: f64,
}

/// Particle Reynolds number d |v| ρ / μ_g [-] with ρ the given density (ρ_g, or ρ_g εg for
/// Gidaspow/Wen–Yu); `LARGE_NUMBER` if μ_g ≤ 0 (MFIX `drag_gs.f`).
#[inline]
fn reynolds(d_p: f64, slip: f64, density: f64, mu_g: f64) -> f64 {
    if mu_g > 0.0 {
        d_p * slip * density / mu_g
    } else {
        LARGE_NUMBER
    }
}

/// Single-sphere drag coefficient [-]: Schiller–Naumann C_d = 24(1 + 0.15 Re^0.687)/(Re + 1e-15)
/// for Re ≤ 1000, else 0.44 (docs/model.md §2.6; MFIX C_DS_SN with `SMALL_NUMBER`).
#[inline]
pub fn cd_schiller_naumann(re: f64) -> f64 {
    let (a, b, exponent) = SCHILLER_NAUMANN;
    if re <= RE_NEWTON {
        a * (1.0 + b * re.powf(exponent)) / (re + SMALL_NUMBER)
    } else {
        CD_NEWTON
    }
}

/// Syamlal–O'Brien DgA [kg m⁻³ s⁻¹] (docs/model.md §2.6; MFIX DRAG_SYAM_OBRIEN):
/// Re = d|v|ρ_g/μ_g (no εg); A = εg^4.14; B = c1 εg^1.28 if εg ≤ 0.85 else εg^d1;
/// V_r = ½[A − 0.06Re + √((0.06Re)² + 0.12Re(2B − A) + A²)];
/// DgA = (3/4) μ_g εg (0.63√(Re/V_r) + 4.8)²/(V_r d²); 0 if Re = 0.
#[inline]
pub fn dga_syamlal_obrien(x: &DragInputs, c1: f64, d1: f64) -> f64 {
    let re = reynolds(x.d_p, x.slip, x.rho_g, x.mu_g);
    if re == 0.0 {
        return 0.0;
    }
    let a = x.eps_g.powf(SO_EXPONENT_A);
    let b = if x.eps_g <= SYAMLAL_OBRIEN_EPS_G_SWITCH {
        c1 * x.eps_g.powf(SO_EXPONENT_B)
    } else {
        x.eps_g.powf(d1)
    };
    let k = SO_RE_COEFFICIENT * re;
    let v_r = 0.5 * (a - k + (k * k + 2.0 * SO_RE_COEFFICIENT * re * (2.0 * b - a) + a * a).sqrt());
    let (c0, c_inf) = DALLA_VALLE;
    let cd_re = (c0 * (re / v_r).sqrt() + c_inf).powi(2);
    0.75 * x.mu_g * x.eps_g * cd_re / (v_r * x.d_p * x.d_p)
}

/// Ergun DgA = 150 (1 − εg) μ_g/(εg d²) + 1.75 ρ_g |v|/d [kg m⁻³ s⁻¹]
/// (Gidaspow dense branch, docs/model.md §2.6).
#[inline]
pub fn dga_ergun(x: &DragInputs) -> f64 {
    let (viscous, inertial) = ERGUN;
    viscous * (1.0 - x.eps_g) * x.mu_g / (x.eps_g * x.d_p * x.d_p)
        + inertial * x.rho_g * x.slip / x.d_p
}

/// Wen–Yu branch without the Re = 0 test: (3/4) C_d |v| ρ_g εg εg^−2.65/d, Re = d|v|ρ_g εg/μ_g.
#[inline]
fn wen_yu_branch(x: &DragInputs, re: f64) -> f64 {
    0.75 * cd_schiller_naumann(re) * x.slip * x.rho_g * x.eps_g * x.eps_g.powf(-WEN_YU_EXPONENT)
        / x.d_p
}

/// Wen–Yu DgA [kg m⁻³ s⁻¹] (docs/model.md §2.6, `WEN_YU`; MFIX DRAG_WEN_YU):
/// Re = d|v|ρ_g εg/μ_g, DgA = (3/4) C_d |v| ρ_g εg εg^−2.65/d with [`cd_schiller_naumann`];
/// 0 if Re = 0.
#[inline]
pub fn dga_wen_yu(x: &DragInputs) -> f64 {
    let re = reynolds(x.d_p, x.slip, x.rho_g * x.eps_g, x.mu_g);
    if re == 0.0 {
        return 0.0;
    }
    wen_yu_branch(x, re)
}

/// Gidaspow DgA [kg m⁻³ s⁻¹] (docs/model.md §2.6, `GIDASPOW`; MFIX DRAG_GIDASPOW):
/// [`dga_ergun`] for εg ≤ 0.8, the Wen–Yu form for εg > 0.8; 0 if Re = 0.
#[inline]
pub fn dga_gidaspow(x: &DragInputs) -> f64 {
    let re = reynolds(x.d_p, x.slip, x.rho_g * x.eps_g, x.mu_g);
    if re == 0.0 {
        0.0
    } else if x.eps_g <= GIDASPOW_EPS_G_SWITCH {
        dga_ergun(x)
    } else {
        wen_yu_branch(x, re)
    }
}

/// Blended Gidaspow DgA = (1 − ψ) Ergun + ψ Wen–Yu [kg m⁻³ s⁻¹],
/// ψ = atan(150 · 1.75 (εg − 0.8))/π + ½ (docs/model.md §2.6, `GIDASPOW_BLEND`; MFIX
/// DRAG_GIDASPOW_BLEND); 0 if Re = 0.
#[inline]
pub fn dga_gidaspow_blend(x: &DragInputs) -> f64 {
    let re = reynolds(x.d_p, x.slip, x.rho_g * x.eps_g, x.mu_g);
    if re == 0.0 {
        return 0.0;
    }
    let (viscous, inertial) = ERGUN;
    let psi = (viscous * inertial * (x.eps_g - GIDASPOW_EPS_G_SWITCH)).atan() / PI + 0.5;
    (1.0 - psi) * dga_ergun(x) + psi * wen_yu_branch(x, re)
}

/// Wen–Yu estimate used by the wall BC routines (docs/model.md §2.6 last bullet, §3.5–3.6;
/// MFIX `calc_grbdry.f`): Re = εg ρ_g d|v|/μ_g, C_d = 24(1 + 0.15Re^0.687)/(Re + 1e-15) for
/// Re < 1000 (strict) else 0.44, DgA = 0.75 C_d ρ_g εg |v|/(d εg^2.65) [kg m⁻³ s⁻¹];
/// DgA = `LARGE_NUMBER` = 1e32 if |v| = 0. Independent of the bulk `DRAG_TYPE`.
#[inline]
pub fn dga_wall_wen_yu(x: &DragInputs) -> f64 {
    if x.slip == 0.0 {
        return LARGE_NUMBER;
    }
    let re = x.eps_g * x.rho_g * x.d_p * x.slip / x.mu_g;
    let cd = if re < RE_NEWTON {
        cd_schiller_naumann(re)
    } else {
        CD_NEWTON
    };
    0.75 * cd * x.rho_g * x.eps_g * x.slip / (x.d_p * x.eps_g.powf(WEN_YU_EXPONENT))
}

/// Single-particle drag per unit solids fraction used in μ*, κ* where εs < `DIL_EP_S`
/// (docs/model.md §2.2 notes; MFIX `kintheory_mod.f` KT_DGA): Re = d|v|ρ_g εg/(μ_g + 1e-15),
/// DgA = (3/4) C_d |v| ρ_g εg/d [kg m⁻³ s⁻¹] (Wen–Yu without εg^−2.65);
/// `LARGE_NUMBER` if |v| = 0.
#[inline]
pub fn dga_single_particle(x: &DragInputs) -> f64 {
    if x.slip == 0.0 {
        return LARGE_NUMBER;
    }
    let bulk_density = x.rho_g * x.eps_g;
    let re = x.d_p * x.slip * bulk_density / (x.mu_g + SMALL_NUMBER);
    0.75 * cd_schiller_naumann(re) * x.slip * bulk_density / x.d_p
}

/// Choice of gas–solids drag law (MFIX `DRAG_TYPE`, docs/model.md §2.6). Default: Syamlal–O'Brien
/// with MFIX's default constants (the paper does not state its drag law, docs/model.md §7).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Drag {
    /// `SYAM_OBRIEN` with `DRAG_C1` = c1 and `DRAG_D1` = d1: [`dga_syamlal_obrien`].
    SyamlalOBrien {
        /// `DRAG_C1` [-] (default 0.8)
        c1: f64,
        /// `DRAG_D1` [-] (default 2.65)
        d1: f64,
    },
    /// `GIDASPOW`: [`dga_gidaspow`].
    Gidaspow,
    /// `GIDASPOW_BLEND`: [`dga_gidaspow_blend`].
    GidaspowBlend,
    /// `WEN_YU`: [`dga_wen_yu`].
    WenYu,
}

impl Default for Drag {
    /// `SYAM_OBRIEN`, c1 = 0.8, d1 = 2.65 (MFIX default, docs/model.md §5).
    fn default() -> Self {
        Self::SyamlalOBrien {
            c1: SYAMLAL_OBRIEN_C1,
            d1: SYAMLAL_OBRIEN_D1,
        }
    }
}

impl Drag {
    /// DgA [kg m⁻³ s⁻¹] of the chosen law; 0 if εs ≤ 0 or εg = 0 (MFIX `drag_gs.f`,
    /// docs/model.md §2.6).
    #[inline]
    pub fn dga(self, eps_s: f64, x: &DragInputs) -> f64 {
        if eps_s <= 0.0 || x.eps_g == 0.0 {
            return 0.0;
        }
        match self {
            Self::SyamlalOBrien { c1, d1 } => dga_syamlal_obrien(x, c1, d1),
            Self::Gidaspow => dga_gidaspow(x),
            Self::GidaspowBlend => dga_gidaspow_blend(x),
            Self::WenYu => dga_wen_yu(x),
        }
    }

    /// Model-A interphase drag coefficient F_gs = εs · DgA [kg m⁻³ s⁻¹] (docs/model.md §1.2, §2.6;
    /// `UR_F_GS` = 1, i.e. no under-relaxation).
    #[inline]
    pub fn f_gs(self, eps_s: f64, x: &DragInputs) -> f64 {
        eps_s * self.dga(eps_s, x)
    }
}
