//! runout-walls.
#![deny(missing_docs)]
