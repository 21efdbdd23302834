//! Verification problems of the single-phase core (issue 6), shared by the fast tests and
//! `cargo xtask verify`.
