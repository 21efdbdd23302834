//! The run summary: what a run did, as JSON.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::{write_atomic, OutputError};

/// How a run ended.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum RunStatus {
    /// reached the end time
    Completed,
    /// still running (the summary is rewritten as the run goes)
    Running,
    /// stopped: a step failed below dt_min; the diagnosis says which equation, where, when
    Diverged {
        /// human-readable diagnosis
        diagnosis: String,
    },
    /// stopped by the user or a signal (a checkpoint was written: restart from it)
    Interrupted,
    /// stopped because output could not be written (e.g. a full disk)
    Failed {
        /// what failed
        reason: String,
    },
}

/// Time-step statistics [s].
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct DtStats {
    /// smallest accepted Δt, not counting a last step shortened to land on the end time
    pub min: f64,
    /// largest accepted Δt
    pub max: f64,
    /// mean accepted Δt
    pub mean: f64,
}

/// What a run did.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunSummary {
    /// case name
    pub case: String,
    /// fidelity the case ran at
    pub fidelity: String,
    /// cells in x and y
    pub cells: (usize, usize),
    /// simulated time reached [s]
    pub simulated_time: f64,
    /// wall-clock time [s]
    pub wall_time: f64,
    /// accepted time steps
    pub steps: u64,
    /// rejected (retried) time steps
    pub rejected_steps: u64,
    /// total outer iterations of accepted steps
    pub outer_iterations: u64,
    /// outer iterations spent on rejected steps (left out of `outer_iterations`; a step
    /// undone by a solver error counts none): with them, the run's whole iteration work
    #[serde(default)]
    pub rejected_outer_iterations: u64,
    /// Δt statistics
    pub dt: DtStats,
    /// relative change of the total solids mass over the run [-]
    pub solids_mass_change: f64,
    /// largest net continuity imbalance of a converged step, relative to the flow through
    /// the domain [-]
    pub max_mass_imbalance: f64,
    /// largest solids volume fraction εs of any phase in any cell, over the initial state
    /// and every accepted step [-] (0 without solids)
    #[serde(default)]
    pub max_eps_s: f64,
    /// how the run ended
    pub status: RunStatus,
    /// wall time per part of the solver's iteration [s] (closures, walls, each assembly and
    /// linear solve), where the solver reports it; empty otherwise (always written, as
    /// [`RunSummary::files`])
    #[serde(default)]
    pub profile: Vec<(String, f64)>,
    /// linear-solver iterations per equation over the run, where the solver reports them;
    /// empty otherwise (always written)
    #[serde(default)]
    pub linear_iterations: Vec<(String, u64)>,
    /// every file a finished run wrote besides `summary.json` (not its checkpoints), with
    /// its size: a folder that lacks one, or holds it shorter, is damaged. Empty while the
    /// run goes and in runs made before the list existed. (Always written: a checkpoint
    /// stores the summary in a format without field names.)
    #[serde(default)]
    pub files: Vec<RunFile>,
}

/// A file of a finished run, as its summary lists it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct RunFile {
    /// its name in the run folder
    pub name: String,
    /// its size [bytes]
    pub bytes: u64,
}

impl RunSummary {
    /// Writes the summary as pretty JSON, atomically.
    pub fn write_json(&self, path: &Path) -> Result<(), OutputError> {
        let text = serde_json::to_string_pretty(self).expect("a summary always serialises");
        write_atomic(path, text.as_bytes())
    }
}
