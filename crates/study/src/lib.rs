//! The study engine of runout: what turns many runs into a study, for `runout sweep`,
//! `runout calibrate` and `runout sensitivity` and for the repository's `cargo xtask` tasks.
//!
//! - [`sweep`]: a case, a sweep file or a folder of them expanded into cases and run as a
//!   resumable parallel job queue ([`jobs`]) into `<root>/runs/<case>/<fidelity>/`
//!   (`.partial` until done, continued from its checkpoint), repeats copied ([`repeat`]),
//!   the rows merged under a lock into `<root>/results/summary.csv` ([`summary`]), `--shard
//!   i/n` for a cluster array;
//! - [`calibrate`]: one or two numeric fields of a case fitted to measurements (argmin);
//! - [`sensitivity`] and [`families`]: elasticities over the one-factor families of sweeps,
//!   and [`elasticities`] of the summary's columns;
//! - [`plots`]: the SVG panels and heat maps these draw.
//!
//! Nothing here assumes a repository: every path is below a `root` the caller names.

pub mod calibrate;
pub mod elasticities;
pub mod families;
pub mod jobs;
pub mod plots;
pub mod repeat;
pub mod sensitivity;
pub mod summary;
pub mod sweep;

/// The flow metrics live in the post-processing library (`runout post` reads the same).
use runout_post::metrics;
