//! runout-closures: the constitutive closures of the two-fluid model exactly as MFIX 21.3.2
//! computes them for the paper's cases (`docs/model.md` §2; paper Eqs. 6–10).
//!
//! Pure, allocation-free `f64` functions of a small state, each citing its equation:
//! - [`radial`]: g0 (Carnahan–Starling as MFIX codes it, Ma–Ahmadi) and dg0/dεs (§2.1);
//! - [`kinetic`]: Lun et al. (1984) as MFIX/Agrawal code it, α = 1.6, with the gas-modified
//!   μ*, κ* (§2.2), and the collisional dissipation γ (§1.3);
//! - [`friction`]: Schaeffer with P* (§2.4.1), Princeton (§2.4.2), K_cp = dP_s/dεs (§2.5);
//! - [`mu_i`]: the rate-dependent μ(I) friction (§2.4.4; not in MFIX);
//! - [`drag`]: Syamlal–O'Brien, Gidaspow, blended Gidaspow, Wen–Yu, the wall Wen–Yu estimate
//!   and the single-particle KT drag (§2.6);
//! - [`energy`]: the granular-energy sources Π, J_vis, J_slip (§1.3);
//! - [`stress`]: additive assembly of kinetic and frictional stresses (§2.3);
//! - [`pore_pressure`]: the pore pressure's Darcy mobility, U_mf, storage and diffusion time (§2.8);
//! - [`guards`]: the small-value guards of §2.7;
//! - [`cell`]: the full closure set of one cell state, [`evaluate`].
//!
//! Where the paper's printed equations differ from MFIX the code follows MFIX (docs/model.md
//! §3.10): stresses are summed, not switched (P-Eq. 5); the P-Eq. 9 exponent is n − 1; the
//! compaction exponent is 1.03, not 0; there is no A(εg* − εg)^10 branch with Princeton.
//!
//! ```
//! use runout_closures::{evaluate, CellState, ClosureParams};
//! // the paper's parameters: d = 0.5 mm, ρs = 2000, e = 0.9, Princeton, Syamlal–O'Brien
//! let params = ClosureParams::default();
//! let state = CellState { eps_s: 0.6, theta: 0.01, slip: 0.3, tr_d: 0.0, s_ddot_s: 100.0 };
//! let set = evaluate(&state, &params);
//! // docs/model.md §2.4.2 check value: P_f = 1600 Pa at εs = 0.6, tr D = 0
//! assert!((set.friction.p_fric - 1600.0).abs() < 1e-6);
//! // stresses are summed (docs/model.md §2.3)
//! assert_eq!(set.stress.mu_s, set.kinetic.mu_kin + set.friction.mu_fric);
//! ```
//!
//! Units are SI throughout; angles enter in degrees and are converted once
//! ([`friction::FrictionParams::new`]).
#![deny(missing_docs)]

pub mod cell;
pub mod drag;
pub mod energy;
pub mod friction;
pub mod gas_law;
pub mod guards;
pub mod kinetic;
pub mod mu_i;
pub mod pore_pressure;
pub mod radial;
pub mod stress;

pub use cell::{evaluate, evaluate_in_gas, CellState, ClosureParams, ClosureSet, Gas, Particles};
pub use drag::{Drag, DragInputs};
pub use friction::{
    FrictionModel, FrictionName, FrictionParams, FrictionalStress, PrincetonConstants,
    SchaefferConstants,
};
pub use gas_law::GasLaw;
pub use kinetic::{GasCoupling, KineticStress, SolidsState};
pub use mu_i::MuIConstants;
pub use radial::RadialDistribution;
pub use stress::SolidsStress;
pub use stress::{FaceMean, KineticJoin};
