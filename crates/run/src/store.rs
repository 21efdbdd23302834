//! The run store: how every tool that runs cases (the sweep, the stability suite, the error
//! study, the collapses, the calibration) keeps its runs, one folder per finished run.
//!
//! A run is written into `<done>.partial/` and renamed to `<done>/` only when it ends, so a
//! folder without the suffix always holds a finished run (completed or stopped with a
//! diagnosis), never a half-written one. An interrupted run keeps its `.partial` folder
//! with its checkpoint, and the next request continues it (when the checkpoint is of the
//! same case and solver version; otherwise it starts again). A finished run is reused
//! when the case it ran, as resolved at its fidelity, is the case asked for
//! ([`finished_run`]), and only when it holds every file its summary lists: a damaged
//! folder is run again.
//!
//! A request holds the folder's lock ([`RunLock`]) from before it looks at the folder until
//! the run is in place: a folder another process is writing (the same folder, or its
//! `.partial`) is refused with [`RunError::Running`] and left alone.

use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use std::time::Duration;

use runout_case::{Case, Fidelity};
use runout_output::{RunStatus, RunSummary};

use crate::lock::RunLock;
use crate::{checkpoint, run_locked, seal, Progress, RunError, RunOptions};

/// The folder a run is written into before it is finished: `<done>.partial`.
pub fn partial_dir(done: &Path) -> PathBuf {
    let name = done
        .file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    done.with_file_name(format!("{name}.partial"))
}

/// The summary in `dir`, if it holds one that reads and every file it lists (a damaged
/// folder is logged as a warning and taken as none).
pub fn read_summary(dir: &Path) -> Option<RunSummary> {
    match runout_post::folder::read_summary(dir)? {
        Ok(summary) => Some(summary),
        Err(e) => {
            tracing::warn!("{e}");
            None
        }
    }
}

/// The finished run in `dir` if it ran exactly `resolved`: its `resolved.ron` is read back
/// as a case and compared field by field, so a run made before a schema field was added
/// (whose file lacks it, read with the field's default) still counts when the default is
/// what `resolved` has. The fidelity presets are not compared: a resolved case already
/// carries its fidelity's grid and end time, and runs as it is. The solver version that
/// made the run is not compared either.
///
/// Both sides are compared in the start clock ([`Case::with_start_clock`]): a run writes its
/// case that way, so a case whose times count from the impact matches its own run.
pub fn finished_run(dir: &Path, resolved: &Case) -> Option<RunSummary> {
    let mut stored: Case = runout_post::folder::read_resolved_unvalidated(dir).ok()?;
    stored.fidelity = resolved.fidelity.clone();
    if stored.with_start_clock() != resolved.clone().with_start_clock() {
        return None;
    }
    read_summary(dir)
}

/// When a finished run in the store is taken instead of running again.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reuse {
    /// never: the run is made again
    Never,
    /// when it ran the same resolved case ([`finished_run`])
    SameCase,
    /// whenever the folder holds a finished run's summary (the caller vouches for the case)
    AnyFinished,
}

/// Checkpoints of long runs (sweeps, checks, the error study) every this much wall time: a
/// killed run then loses at most this much, and the same command continues it.
pub const CHECKPOINT_EVERY: Duration = Duration::from_secs(600);

/// How a run is requested from the store.
#[derive(Clone, Debug)]
pub struct Request {
    /// when a finished run is taken instead
    pub reuse: Reuse,
    /// continue an interrupted run from the checkpoint in its `.partial` folder
    pub resume: bool,
    /// also checkpoint after every this much wall time
    pub checkpoint_every: Option<Duration>,
    /// set (by a signal handler) to stop at the end of the current step with a checkpoint
    pub stop: Option<Arc<AtomicBool>>,
    /// the fidelity written into the summary, when it is not the one the case ran at (the
    /// error study runs resolved levels as `Paper`)
    pub label: Option<String>,
}

impl Default for Request {
    fn default() -> Self {
        Request {
            reuse: Reuse::SameCase,
            resume: true,
            checkpoint_every: None,
            stop: None,
            label: None,
        }
    }
}

/// What the store gave.
#[derive(Clone, Debug)]
pub enum Stored {
    /// a finished run found in the store
    Reused(RunSummary),
    /// run now (completed, or stopped with a diagnosis) and moved into its folder
    Ran(RunSummary),
    /// stopped by a signal: its `.partial` folder holds a checkpoint to continue from
    Interrupted(RunSummary),
}

impl Stored {
    /// The run's summary.
    pub fn summary(&self) -> &RunSummary {
        match self {
            Stored::Reused(s) | Stored::Ran(s) | Stored::Interrupted(s) => s,
        }
    }
}

/// The run of `case` at `fidelity` in folder `done`: reused, continued or made, as
/// `request` says, under the folder's lock (refused with [`RunError::Running`] while another
/// process holds it). A run the solver cannot make leaves no folder; a run that fails to
/// write keeps its `.partial` folder for inspection.
pub fn obtain(
    done: &Path,
    case: &Case,
    fidelity: Fidelity,
    request: &Request,
    progress: impl FnMut(&Progress) + Send,
) -> Result<Stored, RunError> {
    let _lock = RunLock::acquire(done)?;
    obtain_locked(done, case, fidelity, request, progress)
}

/// [`obtain`] with the folder's lock held.
fn obtain_locked(
    done: &Path,
    case: &Case,
    fidelity: Fidelity,
    request: &Request,
    mut progress: impl FnMut(&Progress) + Send,
) -> Result<Stored, RunError> {
    let previous = match request.reuse {
        Reuse::Never => None,
        Reuse::SameCase => finished_run(done, &case.at_fidelity(fidelity)),
        Reuse::AnyFinished => read_summary(done),
    };
    if let Some(summary) = previous {
        return Ok(Stored::Reused(summary));
    }
    let partial = partial_dir(done);
    let mut options = RunOptions {
        restart: request.resume && checkpoint::exists(&partial),
        replace: true,
        checkpoint_every: request.checkpoint_every,
        stop: request.stop.clone(),
    };
    if !options.restart {
        let _ = std::fs::remove_dir_all(&partial);
    }
    let mut result = run_locked(case, fidelity, &partial, &options, &mut progress);
    if let (true, Err(RunError::Checkpoint { source, .. })) = (options.restart, &result) {
        // another case or another runout wrote that checkpoint: start again
        tracing::warn!("{}: starting again ({source})", case.name);
        options.restart = false;
        let _ = std::fs::remove_dir_all(&partial);
        result = run_locked(case, fidelity, &partial, &options, &mut progress);
    }
    let mut summary = match result {
        Err(e @ RunError::Unsupported { .. }) => {
            let _ = std::fs::remove_dir_all(&partial);
            return Err(e);
        }
        other => other?,
    };
    if summary.status == RunStatus::Interrupted {
        return Ok(Stored::Interrupted(summary));
    }
    if let Some(label) = &request.label {
        summary.fidelity = label.clone();
        summary
            .write_json(&partial.join("summary.json"))
            .map_err(|source| RunError::Output {
                case: case.name.clone(),
                source,
            })?;
    }
    move_into_place(&partial, done)?;
    Ok(Stored::Ran(summary))
}

/// Replaces `done` (an earlier run, if any) by the finished run in `partial`, whose files
/// and summary are synced ([`seal`]); the rename itself is synced too.
pub fn move_into_place(partial: &Path, done: &Path) -> Result<(), RunError> {
    let failed = |what: String| RunError::OutDir {
        dir: done.to_path_buf(),
        reason: what,
    };
    seal::sync_folder(partial)
        .map_err(|e| failed(format!("syncing {}: {e}", partial.display())))?;
    let _ = std::fs::remove_dir_all(done);
    std::fs::rename(partial, done)
        .map_err(|e| failed(format!("renaming {} to it: {e}", partial.display())))?;
    match done.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => seal::sync_folder(parent)
            .map_err(|e| failed(format!("syncing {}: {e}", parent.display()))),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_partial_folder_sits_beside_the_finished_one() {
        assert_eq!(
            partial_dir(Path::new("runs/M-JJ/coarse")),
            Path::new("runs/M-JJ/coarse.partial")
        );
    }
}
