//! runout-mesh.
#![deny(missing_docs)]
