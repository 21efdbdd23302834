//! Checkpoints of a run (issue 21): everything the next step reads, so that a run restarted
//! from one repeats the uninterrupted run.
//!
//! A checkpoint holds the solver's state ([`crate::state::SolverState`]), the Δt controller,
//! the summary so far, every monitor's state and the time. It is written atomically into
//! `<run>/checkpoints/step_<accepted steps>.ckpt`, and only the newest two are kept, so a
//! run killed while writing one still has the one before.
//!
//! Format (versioned): the 16-byte magic `runout-ckpt\0\0\0\0\0`, the format version as a
//! little-endian u32, then the [`Checkpoint`] record in postcard (serde's compact binary
//! encoding; f64 values are stored as their 8 bytes, so they come back exactly). A
//! checkpoint of another format version, another solver version or another case is
//! refused with a message that says which.

use std::path::{Path, PathBuf};

use runout_output::{OutputError, RunSummary};
use serde::{Deserialize, Serialize};

use crate::dt_controller::DtController;
use crate::monitors::MonitorsState;
use runout_solver::state::SolverState;

/// The folder of a run's checkpoints.
pub const CHECKPOINT_DIR: &str = "checkpoints";

/// The format version; a reader refuses any other (2: the summary lists the run's files and
/// always writes its lists, so a single-phase run's checkpoint, whose empty lists were left
/// out, reads back).
pub const FORMAT_VERSION: u32 = 2;

const MAGIC: &[u8; 16] = b"runout-ckpt\0\0\0\0\0";

/// Checkpoints kept: the newest and the one before (in case the newest was being written).
const KEPT: usize = 2;

/// The solver version a checkpoint belongs to: the crate's version.
pub const SOLVER_VERSION: &str = env!("CARGO_PKG_VERSION");

/// One checkpoint.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Checkpoint {
    /// [`SOLVER_VERSION`] of the writer
    pub solver_version: String,
    /// the resolved case (RON) the run was started from
    pub case: String,
    /// the fidelity's name
    pub fidelity: String,
    /// simulated time [s]
    pub time: f64,
    /// the Δt controller
    pub dt: DtController,
    /// the summary so far (its Δt mean still a sum, its wall time the time spent so far)
    pub summary: RunSummary,
    /// the solids mass at t = 0 [kg m⁻¹]
    pub initial_solids_mass: f64,
    /// the monitors' schedules and files
    pub monitors: MonitorsState,
    /// the solver's fields and carried-over caches
    pub solver: SolverState,
}

/// Why a checkpoint cannot be used.
#[derive(Debug, thiserror::Error)]
pub enum CheckpointError {
    /// Reading or writing failed.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// No checkpoint in the run folder.
    #[error("{0}: no checkpoint to restart from")]
    None(PathBuf),
    /// A file that is not a checkpoint of this format.
    #[error("{path}: {reason}")]
    Unreadable {
        /// the file
        path: PathBuf,
        /// what is wrong
        reason: String,
    },
    /// A checkpoint of another case, fidelity or solver version.
    #[error("{path}: {reason}")]
    Mismatch {
        /// the file
        path: PathBuf,
        /// what differs
        reason: String,
    },
}

fn io(path: &Path) -> impl FnOnce(std::io::Error) -> CheckpointError + '_ {
    move |source| {
        CheckpointError::Output(OutputError::Io {
            path: path.to_path_buf(),
            source,
        })
    }
}

/// The checkpoint files of a run folder, newest (most steps) first.
fn listing(run_dir: &Path) -> Result<Vec<PathBuf>, CheckpointError> {
    let dir = run_dir.join(CHECKPOINT_DIR);
    if !dir.is_dir() {
        return Ok(Vec::new());
    }
    let mut found: Vec<(u64, PathBuf)> = std::fs::read_dir(&dir)
        .map_err(io(&dir))?
        .flatten()
        .filter_map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            let steps = name
                .strip_prefix("step_")?
                .strip_suffix(".ckpt")?
                .parse()
                .ok()?;
            Some((steps, e.path()))
        })
        .collect();
    found.sort_by_key(|f| std::cmp::Reverse(f.0));
    Ok(found.into_iter().map(|(_, p)| p).collect())
}

/// Writes `checkpoint` into `run_dir` and removes all but the newest [`KEPT`]; returns the
/// file and its size in bytes.
pub fn write(run_dir: &Path, checkpoint: &Checkpoint) -> Result<(PathBuf, u64), CheckpointError> {
    let path = run_dir
        .join(CHECKPOINT_DIR)
        .join(format!("step_{:010}.ckpt", checkpoint.summary.steps));
    let mut bytes = MAGIC.to_vec();
    bytes.extend_from_slice(&FORMAT_VERSION.to_le_bytes());
    let body = postcard::to_stdvec(checkpoint).map_err(|e| CheckpointError::Unreadable {
        path: path.clone(),
        reason: format!("encoding: {e}"),
    })?;
    bytes.extend_from_slice(&body);
    runout_output::write_atomic(&path, &bytes)?;
    for old in listing(run_dir)?.into_iter().skip(KEPT) {
        std::fs::remove_file(&old).map_err(io(&old))?;
    }
    Ok((path, bytes.len() as u64))
}

/// Reads one checkpoint file.
pub fn read(path: &Path) -> Result<Checkpoint, CheckpointError> {
    let bytes = std::fs::read(path).map_err(io(path))?;
    let unreadable = |reason: String| CheckpointError::Unreadable {
        path: path.to_path_buf(),
        reason,
    };
    if bytes.len() < MAGIC.len() + 4 || &bytes[..MAGIC.len()] != MAGIC {
        return Err(unreadable("not a runout checkpoint".into()));
    }
    let version = u32::from_le_bytes(bytes[16..20].try_into().expect("4 bytes"));
    if version != FORMAT_VERSION {
        return Err(unreadable(format!(
            "checkpoint format {version}; this runout reads format {FORMAT_VERSION}"
        )));
    }
    postcard::from_bytes(&bytes[20..]).map_err(|e| unreadable(format!("damaged: {e}")))
}

/// The newest readable checkpoint of `run_dir` (a damaged newest one, e.g. from a kill
/// while it was written, falls back to the one before), checked against the case and
/// fidelity being run and this solver's version.
pub fn latest(
    run_dir: &Path,
    resolved_case: &str,
    fidelity: &str,
) -> Result<(PathBuf, Checkpoint), CheckpointError> {
    let files = listing(run_dir)?;
    let mut first_error = None;
    for path in files {
        match read(&path) {
            Ok(c) => {
                check(&path, &c, resolved_case, fidelity)?;
                return Ok((path, c));
            }
            Err(e) => {
                tracing::warn!("skipping checkpoint: {e}");
                first_error.get_or_insert(e);
            }
        }
    }
    Err(first_error.unwrap_or_else(|| CheckpointError::None(run_dir.to_path_buf())))
}

fn check(
    path: &Path,
    c: &Checkpoint,
    resolved_case: &str,
    fidelity: &str,
) -> Result<(), CheckpointError> {
    let mismatch = |reason: String| CheckpointError::Mismatch {
        path: path.to_path_buf(),
        reason,
    };
    if c.solver_version != SOLVER_VERSION {
        return Err(mismatch(format!(
            "written by runout {}, this is runout {SOLVER_VERSION}: restart it with that \
             version, or start the run again",
            c.solver_version
        )));
    }
    if c.fidelity != fidelity {
        return Err(mismatch(format!(
            "a checkpoint at fidelity {}, not {fidelity}",
            c.fidelity
        )));
    }
    if c.case != resolved_case && !same_but_end_time(&c.case, resolved_case) {
        let line = c
            .case
            .lines()
            .zip(resolved_case.lines())
            .position(|(a, b)| a != b)
            .map_or(String::new(), |k| {
                format!(" (first difference at line {})", k + 1)
            });
        return Err(mismatch(format!(
            "a checkpoint of another case: the case file differs from the one the run was \
             started with{line}"
        )));
    }
    Ok(())
}

/// Whether two resolved cases differ at most in their end time (a run may be continued to
/// a later time, as MFIX's restart with a new `TSTOP`).
fn same_but_end_time(saved: &str, now: &str) -> bool {
    let (Ok(mut saved), Ok(now)) = (
        ron::from_str::<runout_case::Case>(saved),
        ron::from_str::<runout_case::Case>(now),
    ) else {
        return false;
    };
    saved.run.end_time = now.run.end_time;
    saved.fidelity = now.fidelity.clone();
    saved == now
}

/// Whether `run_dir` holds any checkpoint file.
pub fn exists(run_dir: &Path) -> bool {
    listing(run_dir).is_ok_and(|l| !l.is_empty())
}

/// Whether the newest readable checkpoint of `run_dir` was written by this runout's version
/// (false without one): a kept checkpoint another version wrote cannot be continued.
pub fn of_this_version(run_dir: &Path) -> bool {
    listing(run_dir).is_ok_and(|files| {
        files
            .iter()
            .find_map(|path| read(path).ok())
            .is_some_and(|c| c.solver_version == SOLVER_VERSION)
    })
}
