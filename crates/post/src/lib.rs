//! Post-processing of runout's run folders as a library: one definition of each flow metric
//! the paper's figures use (air cushion, cushion and flow thickness, max u_s, h_w^u at the
//! floor probe, gate speeds and their MSE), read from the files a run writes
//! (`profile_*.csv`, `wall_probe_*.csv`, `bulk.csv`, `gates.csv`, `resolved.ron`,
//! `summary.json`). `runout post RUN_DIR` prints [`run::RunMetrics`] as JSON; `cargo xtask`
//! (sweep, report, calibrate) uses the same functions.

pub mod metrics;
pub mod run;
pub mod table;
