//! Which solver made a run: `git describe --always --dirty` of the checkout a sweep ran
//! from, written into each run folder the sweep finished (file [`SOLVER_FILE`]), so the
//! metrics ledger (docs/reports/results/ledger/) can name the solver of every row.

use std::path::Path;
use std::process::Command;
use std::time::SystemTime;

use runout_case::Fidelity;

/// The file of a run folder holding the `git describe` of the build that ran it.
pub const SOLVER_FILE: &str = "git_describe";

/// `git describe --always --dirty` of the checkout at `root`; `None` without git.
pub fn git_describe(root: &Path) -> Option<String> {
    let out = Command::new("git")
        .args(["describe", "--always", "--dirty"])
        .current_dir(root)
        .output()
        .ok()
        .filter(|o| o.status.success())?;
    let text = String::from_utf8(out.stdout).ok()?.trim().to_string();
    (!text.is_empty()).then_some(text)
}

/// Writes `describe` into each run folder `runs/<case>/<fidelity>/` whose summary.json was
/// written at or after `since` and that records no solver yet; returns how many.
pub fn stamp_finished<'a>(
    runs: &Path,
    cases: impl IntoIterator<Item = &'a str>,
    fidelity: Fidelity,
    since: SystemTime,
    describe: &str,
) -> usize {
    let mut n = 0;
    for case in cases {
        let dir = runs.join(case).join(fidelity.name());
        let written = std::fs::metadata(dir.join("summary.json")).and_then(|m| m.modified());
        let fresh = written.is_ok_and(|t| t >= since);
        if fresh && !dir.join(SOLVER_FILE).exists() {
            n +=
                usize::from(std::fs::write(dir.join(SOLVER_FILE), format!("{describe}\n")).is_ok());
        }
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_post::fixture::*;

    #[test]
    fn only_runs_finished_since_the_start_are_stamped() {
        let tmp = TempDir::new("stamp");
        let runs = tmp.0.join("runs");
        write_run(&runs, "old", "coarse", 1.0, &[]);
        std::fs::write(runs.join("old/coarse").join(SOLVER_FILE), "abc1234\n").unwrap();
        let since = SystemTime::now() - std::time::Duration::from_secs(60);
        write_run(&runs, "new", "coarse", 1.0, &[]);
        let n = stamp_finished(
            &runs,
            ["old", "new", "absent"],
            Fidelity::Coarse,
            since,
            "def5678",
        );
        assert_eq!(n, 1);
        let read = |c: &str| {
            std::fs::read_to_string(runs.join(c).join("coarse").join(SOLVER_FILE)).unwrap()
        };
        assert_eq!(read("old"), "abc1234\n", "a recorded solver is kept");
        assert_eq!(read("new"), "def5678\n");
        let later = SystemTime::now() + std::time::Duration::from_secs(60);
        assert_eq!(
            stamp_finished(&runs, ["new"], Fidelity::Coarse, later, "x"),
            0
        );
    }
}
