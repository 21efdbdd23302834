//! Run folders written for tests into a temporary directory (feature `fixture`, and this
//! crate's own tests).

use std::path::{Path, PathBuf};

use runout_output::{DtStats, RunStatus, RunSummary};

/// A temporary directory, removed on drop.
pub struct TempDir(pub PathBuf);

impl TempDir {
    /// A fresh directory named after the test.
    pub fn new(test: &str) -> TempDir {
        let dir = std::env::temp_dir().join(format!("runout-report-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("a temporary directory");
        TempDir(dir)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Writes `runs/<case>/<fidelity>/` with a summary ending at `end_time` and `files`.
pub fn write_run(runs: &Path, case: &str, fidelity: &str, end_time: f64, files: &[(&str, &str)]) {
    let dir = runs.join(case).join(fidelity);
    std::fs::create_dir_all(&dir).expect("a run folder");
    let summary = RunSummary {
        case: case.into(),
        fidelity: fidelity.into(),
        cells: (10, 4),
        simulated_time: end_time,
        wall_time: 1.0,
        steps: 10,
        rejected_steps: 0,
        outer_iterations: 50,
        rejected_outer_iterations: 0,
        dt: DtStats {
            min: 1e-3,
            max: 1e-3,
            mean: 1e-3,
        },
        solids_mass_change: 0.0,
        max_mass_imbalance: 0.0,
        max_eps_s: 0.6,
        status: RunStatus::Completed,
        profile: Vec::new(),
        linear_iterations: Vec::new(),
        files: Vec::new(),
    };
    summary
        .write_json(&dir.join("summary.json"))
        .expect("a summary");
    for (name, text) in files {
        std::fs::write(dir.join(name), text).expect("a monitor file");
    }
}

/// A station profile with a cushion: floor εs 0.05 below a 0.6 peak (cell 2), flow top
/// at 0.015 m, max u_s 3 m/s, floor θ 1.5 m²/s² (5 mm cells).
pub const CUSHION_PROFILE: &str = "y,eps_s,u_s,theta\n0.0025,0.05,2.0,1.5\n\
    0.0075,0.55,3.0,0.2\n0.0125,0.6,2.5,0.1\n0.0175,0.005,1.0,0.5\n";

/// A dense profile without a cushion, flow top at 0.025 m.
pub const DENSE_PROFILE: &str = "y,eps_s,u_s,theta\n0.0025,0.6,1.0,0.0\n\
    0.0075,0.6,2.0,0.1\n0.0125,0.55,3.0,0.2\n0.0175,0.3,3.5,0.4\n0.0225,0.02,4.0,0.8\n";
