//! runout-solver: the finite-volume machinery of runout (docs/model.md §4).
//!
//! - [`transport`]: upwind/Superbee convection and diffusion on a structured block;
//! - [`momentum`]: one phase's momentum equations with variable ρε, ε, μ (docs/model.md §4.4),
//!   u and v assembled once: each term written in the component's own coordinates and
//!   compiled per direction (`direction`), dispatched from the [`staggered`] component view;
//! - [`momentum_form`]: the momentum equations' continuity-subtracted (MFIX) or conservative
//!   form (docs/model.md §4.3);
//! - [`single_phase`]: the incompressible SIMPLE core on a stretched staggered grid, whose
//!   patterns and pressure-correction update the two-fluid gas shares (`node_block`);
//! - [`two_fluid`]: the first two-fluid model (gas + M solids, docs/model.md §4.9) built from
//!   [`energy`] (granular energy, §4.8),
//!   [`kinematics`] (cell strain rates), [`pea`] (partial elimination of drag, §4.5),
//!   [`volume_fraction`] (the solids volume-fraction correction, §4.7);
//! - [`state`]: a solver's state between steps as named arrays (checkpoints);
//! - [`bent_floor`]: gravity and the centrifugal force of a slope whose foot turns (§9).
//!
//! The verification problems, the reference solutions and the 1-D chute reference solver
//! are in `runout-verification` (crates/verification).
#![deny(missing_docs)]
// Stencil loops index several staggered arrays with the same (i, j); indices read better
// than zipped iterators there.
#![allow(clippy::needless_range_loop)]

/// The floor of a slope whose foot turns (docs/model.md §9), from runout-mesh.
pub use runout_mesh::bent_floor;
pub(crate) mod direction;
pub mod energy;
pub mod kinematics;
pub mod momentum;
pub mod momentum_form;
pub(crate) mod node_block;
pub mod pea;
pub mod side;
pub mod single_phase;
pub mod staggered;
pub mod state;
pub mod stress;
pub mod transport;
pub mod two_fluid;
pub mod volume_fraction;

pub use runout_closures::GasLaw;
pub use single_phase::{
    Fluid, Residuals, Settings, SideBc, SinglePhase, SolverError, SteadyReport,
};
pub use transport::{FaceData, Scheme};
