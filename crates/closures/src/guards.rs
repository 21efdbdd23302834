//! Small-value guards and limits that change results (docs/model.md §2.7).
//!
//! MFIX keeps some limits in CGS; [`TO_SI`] converts them. Every value below is the one of
//! MFIX 21.3.2 (`model/param1_mod.f`, `model/init_namelist.f`, `model/adjust_theta.f`).

/// CGS → SI conversion factor `to_SI` = 0.1 [-]: dyn/cm² → Pa and poise → Pa s
/// (docs/model.md §0.3; MFIX `constant_mod.f`).
pub const TO_SI: f64 = 0.1;

/// `DIL_EP_S` = 1e-4 [-]: dilute threshold on εs (docs/model.md §2.7). Cells with εs below it
/// use a single-particle drag in μ*, κ* (docs/model.md §2.2 notes, [`crate::drag::dga_single_particle`]);
/// the solver averages velocities and θ of such cells from their neighbours.
pub const DIL_EP_S: f64 = 1e-4;

/// `ZERO_EP_S` = 1e-8 [-] (MFIX keyword default, docs/model.md §2.7, §5); sets [`THETA_SMALL`].
pub const ZERO_EP_S: f64 = 1e-8;

/// θ_small = to_SI⁴ · `ZERO_EP_S` = 1e-12 m²/s²: lower clip of θ after each granular-energy
/// solve (docs/model.md §1.3, §2.7; MFIX `adjust_theta.f`). Also floors θ in the Princeton strain
/// scale ζ (see [`crate::friction::strain_scale`]), which MFIX never evaluates below θ_small.
pub const THETA_SMALL: f64 = 1e-12;

/// `SMALL_NUMBER` = 1e-15 (MFIX `param1_mod.f`, docs/model.md §2.7): regularisation in μ*, κ*
/// (θ below it means μ* = κ* = 0), in the Schaeffer viscosity denominator, in the
/// Schiller–Naumann C_d denominator and under the root of the Koch–Sangani slip source.
pub const SMALL_NUMBER: f64 = 1e-15;

/// `LARGE_NUMBER` = 1e32 (MFIX `param1_mod.f`): the drag coefficient DgA used at zero slip by
/// the wall Wen–Yu estimate and the single-particle KT drag (docs/model.md §2.6), and the Reynolds
/// number used when μ_g ≤ 0.
pub const LARGE_NUMBER: f64 = 1e32;

/// θ floor at walls = 1e-8 m²/s²: a negative wall θ is reset to this value in the JJ/Jenkins
/// coefficient routines (docs/model.md §2.7; MFIX `calc_grbdry.f`, `bc_theta.f`).
pub const THETA_WALL_FLOOR: f64 = 1e-8;
