//! A case of a sweep that repeats another at its fidelity (the base point shared by several
//! one-factor families) is not run again: the other's finished run folder is copied, under
//! the repeat's lock, with the name changed in `summary.json` and `resolved.ron`.

use std::path::Path;

use anyhow::{Context, Result};
use runout_case::Fidelity;
use runout_output::RunSummary;
use runout_run::checkpoint::CHECKPOINT_DIR;
use runout_run::lock::RunLock;
use runout_run::{seal, store, RunError};

use crate::sweep::Outcome;

/// Copies the finished run of `from` to the folder of `to` (a repeat of the same case),
/// with the case name in its summary and resolved case changed to `to`; skipped if `to` is
/// finished already. The checkpoints stay with the run that wrote them (they restart
/// `from`'s case, and a restart refuses another case).
pub fn copy_run(runs: &Path, from: &str, to: &str, fidelity: Fidelity) -> Outcome {
    let done = runs.join(to).join(fidelity.name());
    let _lock = match RunLock::acquire(&done) {
        Ok(lock) => lock,
        Err(RunError::Running { holder, .. }) => return Outcome::Elsewhere(holder),
        Err(e) => return Outcome::Failed(e.to_string()),
    };
    if let Some(summary) = store::read_summary(&done) {
        return Outcome::Skipped(summary);
    }
    let source = runs.join(from).join(fidelity.name());
    let partial = store::partial_dir(&done);
    let copy = || -> Result<RunSummary> {
        // the source's summary, checked against its own file list before anything changes
        let mut summary = store::read_summary(&source)
            .with_context(|| format!("no complete run in {}", source.display()))?;
        let _ = std::fs::remove_dir_all(&partial);
        std::fs::create_dir_all(&partial)?;
        copy_outputs(&source, &partial)?;
        let resolved = partial.join("resolved.ron");
        if let Ok(text) = std::fs::read_to_string(&resolved) {
            let renamed =
                text.replacen(&format!("name: \"{from}\""), &format!("name: \"{to}\""), 1);
            std::fs::write(&resolved, renamed)?;
        }
        summary.case = to.to_string();
        // the renamed resolved.ron has another size: the list is made again
        summary.files = seal::seal(&partial)?;
        summary.write_json(&partial.join("summary.json"))?;
        store::move_into_place(&partial, &done)?;
        Ok(summary)
    };
    match copy() {
        Ok(summary) => Outcome::Copied(summary, from.to_string()),
        Err(e) => Outcome::Failed(format!("copying the run of {from}: {e:#}")),
    }
}

/// Copies the files of the run folder `source` into `dest`, and its folders (but its
/// checkpoints) recursively.
fn copy_outputs(source: &Path, dest: &Path) -> Result<()> {
    std::fs::create_dir_all(dest)?;
    for entry in std::fs::read_dir(source)? {
        let entry = entry?;
        let (from, to) = (entry.path(), dest.join(entry.file_name()));
        if entry.file_type()?.is_dir() {
            if entry.file_name() != CHECKPOINT_DIR {
                copy_outputs(&from, &to)?;
            }
        } else {
            std::fs::copy(&from, &to).with_context(|| format!("copying {}", from.display()))?;
        }
    }
    Ok(())
}

/// The outcome of a repeat (the same case as `from`, the sweep's `duplicates`) from its original's: a
/// copy of a finished original's folder, the original's failure or lack of support, a wait
/// for a run going elsewhere; `None` (not started, as the cases after a stop) when the
/// original was interrupted or never started because the sweep was stopped.
pub fn repeat_outcome(
    from: &str,
    original: Option<&Outcome>,
    copy: impl FnOnce() -> Outcome,
) -> Option<Outcome> {
    match original? {
        Outcome::Done(_) | Outcome::Skipped(_) | Outcome::Copied(..) => Some(copy()),
        Outcome::Elsewhere(holder) => Some(Outcome::Elsewhere(holder.clone())),
        Outcome::Failed(why) => Some(Outcome::Failed(format!(
            "its original `{from}` failed: {why}"
        ))),
        Outcome::Unsupported(why) => Some(Outcome::Unsupported(why.clone())),
        Outcome::Interrupted(_) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A repeat of a finished `wall` run (which holds a checkpoints folder) is copied with
    /// its outputs and its name, without the checkpoints (the copy of every `wall` repeat of
    /// issue 19's sweep failed on that folder, 2026-12-03).
    #[test]
    fn a_repeat_is_copied_without_the_checkpoints() {
        use runout_post::fixture::{write_run, TempDir};
        let tmp = TempDir::new("sweep-copy");
        let runs = tmp.0.join("runs");
        write_run(
            &runs,
            "a",
            "wall",
            0.4,
            &[
                ("bulk.csv", "t\n0\n"),
                ("resolved.ron", "Case(name: \"a\")"),
            ],
        );
        // a finished run lists its files with their sizes (issue 44): seal the source
        let source = runs.join("a").join("wall");
        let mut sealed = store::read_summary(&source).unwrap();
        sealed.files = seal::seal(&source).unwrap();
        sealed.write_json(&source.join("summary.json")).unwrap();
        let checkpoints = runs.join("a").join("wall").join(CHECKPOINT_DIR);
        std::fs::create_dir_all(&checkpoints).unwrap();
        std::fs::write(checkpoints.join("step_0000000001.ckpt"), "x").unwrap();
        let outcome = copy_run(&runs, "a", "b", Fidelity::Wall);
        let Outcome::Copied(summary, from) = outcome else {
            panic!("not copied");
        };
        assert_eq!((summary.case.as_str(), from.as_str()), ("b", "a"));
        let copy = runs.join("b").join("wall");
        assert_eq!(
            std::fs::read_to_string(copy.join("bulk.csv")).unwrap(),
            "t\n0\n"
        );
        assert_eq!(store::read_summary(&copy).unwrap().case, "b");
        assert_eq!(
            std::fs::read_to_string(copy.join("resolved.ron")).unwrap(),
            "Case(name: \"b\")"
        );
        assert!(!copy.join(CHECKPOINT_DIR).exists());
        assert!(checkpoints.join("step_0000000001.ckpt").exists());
    }

    /// A repeat follows its original: copied when it finished, the failure named when it
    /// failed, and not started when the sweep was stopped before or during it (it was
    /// reported as a failed copy before).
    #[test]
    fn a_repeat_of_an_interrupted_or_unstarted_run_is_not_started() {
        let copied = || Outcome::Copied(crate::sweep::tests::summary(), "S-a".into());
        let done = Outcome::Done(crate::sweep::tests::summary());
        assert!(matches!(
            repeat_outcome("S-a", Some(&done), copied),
            Some(Outcome::Copied(..))
        ));
        let interrupted = Outcome::Interrupted(crate::sweep::tests::summary());
        assert!(repeat_outcome("S-a", Some(&interrupted), copied).is_none());
        assert!(repeat_outcome("S-a", None, copied).is_none());
        let failed = Outcome::Failed("diverged".into());
        assert!(matches!(
            repeat_outcome("S-a", Some(&failed), copied),
            Some(Outcome::Failed(why)) if why == "its original `S-a` failed: diverged"
        ));
        let elsewhere = Outcome::Elsewhere("pid 7".into());
        assert!(matches!(
            repeat_outcome("S-a", Some(&elsewhere), copied),
            Some(Outcome::Elsewhere(h)) if h == "pid 7"
        ));
    }
}
