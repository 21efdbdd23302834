//! runout-case.
#![deny(missing_docs)]
