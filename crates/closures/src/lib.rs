//! runout-closures.
#![deny(missing_docs)]
