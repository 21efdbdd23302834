//! runout-walls: wall boundary conditions as Robin coefficients (model-spec §3).
//!
//! [`RobinFace`] is the discrete wall-face closure of model-spec §3.2 that every wall model
//! produces and the solver consumes. The wall models themselves (Johnson–Jackson,
//! Li–Benyahia, Jenkins, user partial slip) come with issue 4.
#![deny(missing_docs)]

mod face;

pub use face::RobinFace;
