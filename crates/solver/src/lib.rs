//! runout-solver.
#![deny(missing_docs)]
