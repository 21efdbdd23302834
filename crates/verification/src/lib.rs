//! runout-verification: the verification of runout, apart from the solver it judges
//! (issue 20 item 5). Not published; the dependency goes from here to `runout-solver`.
//!
//! - [`references`]: the reference solutions: published tables (Ghia, Ghia & Shin;
//!   Botella & Peyret), closed forms (Haff's law), laboratory laws (the runout laws of
//!   the column collapse) and another code's numbers (MFIX for family M), each with its
//!   citation;
//! - [`chute1d`]: a 1-D steady inclined-chute boundary-value solver, the computed reference
//!   of the chute check (docs/studies/chute1d.md);
//! - [`problems`]: the verification problems, set up and run on the solver;
//! - [`check`]: the [`Check`] trait, a problem judged at a [`Size`] into an [`Outcome`];
//! - [`checks`] and [`registry()`]: the checks, one per problem, that the tests of
//!   `crates/verification/tests/` run at the fast size (CI) and `cargo xtask verify` at
//!   the full size;
//! - [`study`]: the [`Study`] trait, the whole program run with options ([`Args`]) into
//!   run folders and a page under a [`Context`];
//! - [`mod@studies`] and [`studies()`]: the studies (the column collapse against the laboratory
//!   laws, family M against MFIX, the Re = 1000 cavity), run only by `cargo xtask verify`.
#![deny(missing_docs)]
// Stencil loops index several staggered arrays with the same (i, j); indices read better
// than zipped iterators there.
#![allow(clippy::needless_range_loop)]

pub mod check;
pub mod checks;
pub mod chute1d;
pub mod problems;
pub mod references;
pub mod registry;
pub mod studies;
pub mod study;

pub use check::{Check, Limit, Measure, Outcome, Size};
pub use registry::{find, find_study, group, registry, studies};
pub use study::{Args, Context, Study};
