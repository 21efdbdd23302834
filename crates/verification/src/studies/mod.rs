//! The studies of the registry ([`crate::registry::studies`]), one per module, each run with
//! its options into run folders and a page ([`crate::study`]).

pub mod cavity_re1000;
pub mod collapse;
pub mod mfix_slope;

pub use cavity_re1000::CavityRe1000;
pub use collapse::Collapse;
pub use mfix_slope::MfixSlope;
