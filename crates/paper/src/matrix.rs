//! The paper's case matrix, expanded from cases/ (except the stiff cases of cases/stability/,
//! which `cargo xtask stability` runs, the column collapse of cases/collapse/, which `cargo
//! xtask verify collapse` runs, and the slide onto a flat run-out of cases/foot/, which
//! `runout sweep cases/foot` runs), and its sweep: run in parallel by the study engine
//! ([`runout_study::sweep`]) into the workspace's `runs/` and `results/summary.csv`; each
//! run folder it finished records the checkout's `git describe` ([`crate::solver_stamp`]).

use std::path::Path;

use anyhow::Result;
use runout_study::sweep::{matrix, study_matrix, Matrix, SweepOptions};

use crate::foot::FOOT_DIR;
use crate::solver_stamp::{git_describe, stamp_finished};

/// The folder of the stability cases below the case directory (`cargo xtask stability`).
pub const STABILITY_DIR: &str = "stability";

/// The folder of the collapse cases under cases/ (`cargo xtask verify collapse`).
pub const COLLAPSE_DIR: &str = "collapse";

/// The folder under cases/ of the slides down beds of several slopes (issue 57), which are
/// not the paper's.
pub const SLOPES_DIR: &str = "slopes";

/// The folder under cases/ of the cases of gas let in through walls (issue 60), which are
/// not the paper's.
pub const GAS_DIR: &str = "gas";

/// The paper's matrix (cases.md families S, F, M and A): every case under `cases_dir` but
/// the stiff cases of `cargo xtask stability`, the column collapse of `cargo xtask verify
/// collapse` (issue 7's check, verification-notes §2f), the slide onto a flat run-out
/// (issue 43 item 5, docs/studies/foot.md), the slides down real slopes ([`SLOPES_DIR`]), the cases of
/// gas let in through walls ([`GAS_DIR`]) and the sweeps of a study.
pub fn paper_matrix(cases_dir: &Path) -> Result<Matrix> {
    let mut m = matrix(cases_dir)?;
    let apart =
        [STABILITY_DIR, COLLAPSE_DIR, FOOT_DIR, SLOPES_DIR, GAS_DIR].map(|d| cases_dir.join(d));
    m.runs
        .retain(|r| r.study.is_none() && !apart.iter().any(|d| r.file.starts_with(d)));
    Ok(m)
}

/// Runs the paper's matrix under `cases_dir` (or the sweeps of `study`) below `root`, with
/// the described gate speeds of the flume (cases/flume/gates.csv) for the summary's
/// `mse_vs_described`.
pub fn sweep(root: &Path, cases_dir: &Path, study: Option<&str>, opts: SweepOptions) -> Result<()> {
    let matrix = match study {
        Some(study) => study_matrix(cases_dir, study)?,
        None => paper_matrix(cases_dir)?,
    };
    let opts = SweepOptions {
        gates: Some(root.join("cases").join("flume").join("gates.csv")),
        ..opts
    };
    let started = std::time::SystemTime::now();
    let describe = git_describe(root);
    let result = runout_study::sweep::sweep(root, &matrix, &opts);
    if let (Some(d), false) = (describe, opts.list) {
        let names = matrix.runs.iter().map(|r| r.case.name.as_str());
        stamp_finished(&root.join("runs"), names, opts.fidelity, started, &d);
    }
    result
}
