//! runout-output.
#![deny(missing_docs)]
