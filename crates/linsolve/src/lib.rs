//! runout-linsolve.
#![deny(missing_docs)]
