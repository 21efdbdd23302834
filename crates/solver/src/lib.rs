//! runout-solver: the finite-volume machinery of runout (model-spec §4).
//!
//! Part 1 (issue 6, in progress): [`transport`] assembles upwind/Superbee convection and
//! diffusion on a structured block; [`single_phase`] is the incompressible SIMPLE core on
//! a stretched staggered grid that the two-fluid model will reuse.
#![deny(missing_docs)]
// Stencil loops index several staggered arrays with the same (i, j); indices read better
// than zipped iterators there.
#![allow(clippy::needless_range_loop)]

pub mod energy;
pub mod momentum;
pub mod run;
pub mod single_phase;
pub mod transport;
pub mod verify;

pub use run::{run_case, DtController, Progress, RunError};
pub use single_phase::{
    Fluid, Residuals, Settings, SideBc, SinglePhase, SolverError, SteadyReport,
};
pub use transport::{FaceData, Scheme};
