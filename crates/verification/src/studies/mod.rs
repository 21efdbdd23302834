//! The studies of the registry ([`crate::registry::studies`]), one per module, each run with
//! its options into run folders and a page ([`crate::study`]).

pub mod collapse;

pub use collapse::Collapse;
