//! runout-walls: the solid–wall boundary conditions of the paper as Robin coefficients
//! (`docs/model.md` §3; paper §2.2, Eqs. 12–20, Table 2).
//!
//! Every wall condition of a tangential quantity φ (a solids velocity component, or θ) is
//! g ∂φ/∂n + h φ = c with n from the fluid into the wall ([`RobinFace`]); MFIX discretises it
//! across the wall face as g (φ_G − φ_F)/Δ + h (φ_G + φ_F)/2 = c (docs/model.md §3.2), and
//! [`RobinFace`] eliminates the ghost value into the face flux and face value the solver uses.
//!
//! A case file's wall condition is a [`SolidsWall`] (serde); [`SolidsWall::model`] validates it
//! into the model the solver evaluates.
//!
//! The models ([`SolidsWallModel`]):
//! - no-slip, free-slip (MFIX NSW, FSW with `BC_JJ_PS = 0`);
//! - user partial slip, paper Eqs. 12–13 in MFIX's manual units (docs/model.md §3.3);
//! - Johnson & Jackson (1987) with a constant specularity: momentum h_w^u = COL/μ_k or
//!   (COL + FRI)/(μ_k + μ_f) with the Princeton frictional add-on (docs/model.md §3.5), θ flux
//!   form κ ∂θ/∂n + h_θ θ = c_θ (§3.6);
//! - revisited JJ with Li & Benyahia's φ(r) in MFIX's continuous form ([`specularity`], §3.7);
//! - Jenkins (1992), small-friction all-sliding limit (§3.8);
//! - a Coulomb wall τ_w = μ_w P regularised at zero slip ([`coulomb`], §3.11; not in MFIX).
//!
//! Where the paper's printed equations differ from MFIX the code follows MFIX (docs/model.md
//! §3.10): Eq. 16's linear branch carries 1/(8k); Table 2's (1 − εs*) is εs,max; the JJ h_θ
//! carries εs g0; FRI is not divided by the slip speed; the manual θ coefficients are in m⁻¹
//! and m s⁻².
//!
//! ```
//! use runout_closures::ClosureParams;
//! use runout_walls::{MomentumWallState, SolidsWallModel, ThetaWallState};
//! // the paper's JJ wall, φ = 0.1, e_w = 0.7, δ_w = 11°, U_w = 0; d = 0.5 mm particles
//! let wall = SolidsWallModel::johnson_jackson(0.1, 0.7, 11.0, 0.0).unwrap();
//! let params = ClosureParams::default();
//! let state = MomentumWallState {
//!     eps_s_fluid: 0.3, eps_s: 0.3, theta: 0.5, slip: 2.0, gas_slip: 0.0,
//!     tr_d: 0.0, s_ddot_s: 0.0, s_nn: 0.0, extra_normal_load: 0.0,
//! };
//! let u = wall.momentum(&state, &params);
//! // below εs,min: h = COL/μ_k, and the face closure has g = 1, c = h U_w
//! let d = u.diagnostics;
//! assert!((d.h_u - d.col / d.mu_kin).abs() < 1e-12 * d.h_u);
//! assert_eq!((u.face.g, u.face.c), (1.0, 0.0));
//! // the solver's flux through the wall face of a 5 mm cell with μ_s = 0.3 Pa s
//! let (a_p, source) = u.face.implicit_parts(0.3, 0.005);
//! assert!(a_p > 0.0 && source == 0.0);
//! let theta = ThetaWallState { eps_s: 0.3, theta: 0.5, slip: 2.0, gas_slip: 0.0 };
//! let t = wall.granular_temperature(&theta, &params);
//! assert!(t.face.g > 0.0 && t.face.h > 0.0 && t.face.c > 0.0);
//! ```
#![deny(missing_docs)]

pub mod analytic;
pub mod coefficients;
pub mod coulomb;
mod error;
mod face;
pub mod model;
pub mod spec;
pub mod specularity;
pub mod state;

pub use error::{OutOfRange, WallError};
pub use face::RobinFace;
pub use model::{
    MomentumBranch, MomentumDiagnostics, MomentumWall, SolidsWallModel, Specularity, ThetaBranch,
    ThetaDiagnostics, ThetaWall, UserPartialSlip, WallContact,
};
pub use spec::{MissingParameter, SolidsWall};
pub use specularity::LiBenyahia;
pub use state::{MomentumWallState, ThetaWallState, WallStrain};
