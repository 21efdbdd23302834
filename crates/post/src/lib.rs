//! Post-processing of runout's run folders as a library: typed readers of the files a run
//! writes (`profile_*.csv`, `wall_probe_*.csv`, `bulk.csv`, `front.csv`, `gates.csv`,
//! `resolved.ron`, `summary.json`) and of the described gates of a case, one definition of
//! each flow metric the paper's figures use (air cushion, cushion and flow thickness, max
//! u_s, h_w^u at the floor probe, gate speeds and their MSE), and the convergence tools of
//! grid studies (error norms, observed order, Richardson extrapolation, Roache's GCI:
//! [`gci`]; the grid error of a deposit: [`grid_error`]). `runout post
//! RUN_DIR` prints [`run::RunMetrics`] as JSON, with the deposit ([`deposit`]: at rest and
//! when, L∞, H∞, the profile); `cargo xtask` (sweep, report, calibrate,
//! error-time) uses the same functions.

pub mod basal_load;
pub mod bulk;
pub mod case_data;
pub mod chosen;
pub mod convergence;
pub mod deposit;
pub mod fields;
#[cfg(any(test, feature = "fixture"))]
pub mod fixture;
pub mod folder;
pub mod front;
pub mod gates;
pub mod gci;
pub mod grid_error;
pub mod metrics;
pub mod profile;
pub mod run;
pub mod table;
