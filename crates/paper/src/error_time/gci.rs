//! Roache's grid convergence index: the library's ([`runout_post::gci`]), used by the
//! error-time pages.

pub use runout_post::gci::{
    scalar_convergence, trend, ScalarConvergence, Trend, FS_NOMINAL_ORDER, FS_THREE_LEVELS,
};
