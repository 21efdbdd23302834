//! Radial distribution function at contact g0 (docs/model.md §2.1; MFIX `model/rdf_mod.f`).

use serde::{Deserialize, Serialize};

/// Ma–Ahmadi packing fraction ε_s,mx = 0.64356 [-] in the denominator of g0
/// (Ma & Ahmadi 1986; MFIX `rdf_mod.f`, docs/model.md §2.1).
pub const MA_AHMADI_EPS_PACKING: f64 = 0.64356;

/// Ma–Ahmadi clip: εs is limited to ≤ 0.643 [-] (~99.9 % of ε_s,mx) before evaluating g0
/// (MFIX `rdf_mod.f`, docs/model.md §2.1).
pub const MA_AHMADI_EPS_LIMIT: f64 = 0.643;

/// Ma–Ahmadi numerator coefficients 1 + 2.5ε + 4.5094ε² + 4.515439ε³ (docs/model.md §2.1).
const MA_AHMADI_POLY: [f64; 4] = [1.0, 2.5, 4.5094, 4.515439];

/// Ma–Ahmadi exponent 0.678021 of the denominator (docs/model.md §2.1).
const MA_AHMADI_EXPONENT: f64 = 0.678021;

/// Carnahan–Starling g0 as MFIX codes it for one solids phase,
/// g0 = (1 − εs/2)/(1 − εs)³ [-] (= 1/(1−εs) + 3εs/(2(1−εs)²) + εs²/(2(1−εs)³)).
///
/// No cap and no dependence on εs,max: finite at packing (g0(0.65) = 15.74), singular only at
/// εs = 1. Ref: Carnahan & Starling (1969); paper Eq. 6 (g0); docs/model.md §2.1
/// (MFIX 21.3.2 `rdf_mod.f` G_0, identical in 2016-1). Valid for 0 ≤ εs < 1.
#[inline]
pub fn g0_carnahan_starling(eps_s: f64) -> f64 {
    let eps_g = 1.0 - eps_s;
    (1.0 - 0.5 * eps_s) / (eps_g * eps_g * eps_g)
}

/// dg0/dεs of [`g0_carnahan_starling`]: (2.5 − εs)/(1 − εs)⁴ [-]
/// (docs/model.md §2.1; MFIX `rdf_mod.f` DG_0DNU). Valid for 0 ≤ εs < 1.
#[inline]
pub fn dg0_deps_carnahan_starling(eps_s: f64) -> f64 {
    let eps_g = 1.0 - eps_s;
    let eps_g2 = eps_g * eps_g;
    (2.5 - eps_s) / (eps_g2 * eps_g2)
}

/// Ma–Ahmadi g0 = (1 + 2.5ε + 4.5094ε² + 4.515439ε³)/(1 − (ε/0.64356)³)^0.678021 [-],
/// with ε = min(εs, 0.643) (Ma & Ahmadi 1986; docs/model.md §2.1; MFIX `rdf_mod.f`).
/// Constant above [`MA_AHMADI_EPS_LIMIT`].
#[inline]
pub fn g0_ma_ahmadi(eps_s: f64) -> f64 {
    let x = eps_s.min(MA_AHMADI_EPS_LIMIT);
    let [c0, c1, c2, c3] = MA_AHMADI_POLY;
    let numerator = c0 + x * (c1 + x * (c2 + x * c3));
    let ratio = x / MA_AHMADI_EPS_PACKING;
    numerator / (1.0 - ratio * ratio * ratio).powf(MA_AHMADI_EXPONENT)
}

/// dg0/dεs of [`g0_ma_ahmadi`] [-]: (N' + N · 3a ε²/(ε_mx³ − ε³)) / (1 − (ε/ε_mx)³)^a with
/// N the numerator polynomial and a = 0.678021, for εs ≤ 0.643; 0 above (g0 is clipped there).
///
/// docs/model.md §2.1. Differs from MFIX's DG_0DNU above 0.643, which mixes the clipped and the
/// raw εs (and is NaN beyond 0.64356); MFIX uses DG_0DNU only in the disabled Dufour term and
/// the SAVAGE = 1 K_cp, neither of which the paper's cases evaluate.
#[inline]
pub fn dg0_deps_ma_ahmadi(eps_s: f64) -> f64 {
    if eps_s > MA_AHMADI_EPS_LIMIT {
        return 0.0;
    }
    let x = eps_s;
    let [c0, c1, c2, c3] = MA_AHMADI_POLY;
    let numerator = c0 + x * (c1 + x * (c2 + x * c3));
    let dnumerator = c1 + x * (2.0 * c2 + x * 3.0 * c3);
    let x3 = x * x * x;
    let packing3 = MA_AHMADI_EPS_PACKING * MA_AHMADI_EPS_PACKING * MA_AHMADI_EPS_PACKING;
    let denominator = (1.0 - x3 / packing3).powf(MA_AHMADI_EXPONENT);
    (dnumerator + numerator * 3.0 * MA_AHMADI_EXPONENT * x * x / (packing3 - x3)) / denominator
}

/// Choice of radial distribution function (MFIX keyword `RDF_TYPE`, docs/model.md §2.1).
/// Default: Carnahan–Starling (what the MFIX GUI sets for one solids phase, docs/model.md §5).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum RadialDistribution {
    /// `CARNAHAN_STARLING`: [`g0_carnahan_starling`].
    #[default]
    CarnahanStarling,
    /// `MA_AHMADI`: [`g0_ma_ahmadi`].
    MaAhmadi,
}

impl RadialDistribution {
    /// g0(εs) [-] of the chosen model (docs/model.md §2.1).
    #[inline]
    pub fn g0(self, eps_s: f64) -> f64 {
        match self {
            Self::CarnahanStarling => g0_carnahan_starling(eps_s),
            Self::MaAhmadi => g0_ma_ahmadi(eps_s),
        }
    }

    /// dg0/dεs [-] of the chosen model (docs/model.md §2.1).
    #[inline]
    pub fn dg0_deps(self, eps_s: f64) -> f64 {
        match self {
            Self::CarnahanStarling => dg0_deps_carnahan_starling(eps_s),
            Self::MaAhmadi => dg0_deps_ma_ahmadi(eps_s),
        }
    }
}
