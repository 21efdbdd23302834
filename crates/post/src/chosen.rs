//! The finished run chosen for a case among its fidelities: `runs/<case>/<fidelity>/` with a
//! `summary.json`, at a requested fidelity or the best that exists.

use std::path::{Path, PathBuf};

use runout_case::Fidelity;
use runout_output::{RunStatus, RunSummary};

use crate::folder::read_summary;

/// Fidelities from the best down: the default choice per case.
pub const BEST_FIRST: [Fidelity; 4] = [
    Fidelity::Paper,
    Fidelity::Wall,
    Fidelity::Coarse,
    Fidelity::Smoke,
];

/// The finished run chosen for a case.
#[derive(Clone, Debug)]
pub struct Run {
    /// its fidelity
    pub fidelity: Fidelity,
    /// its folder
    pub dir: PathBuf,
    /// its summary.json
    pub summary: RunSummary,
}

impl Run {
    /// Why a quantity at time `t` is missing if the run ended before `t`.
    pub fn ended_before(&self, t: f64) -> Option<String> {
        let end = self.summary.simulated_time;
        (end < t * (1.0 - 1e-9)).then(|| {
            let how = match self.summary.status {
                RunStatus::Diverged { .. } => " (diverged)",
                RunStatus::Interrupted => " (interrupted)",
                _ => "",
            };
            format!(
                "the {} run ends at t = {end:.2} s{how}, before t = {t} s",
                self.fidelity
            )
        })
    }
}

impl Run {
    /// The finished run in `dir` (any folder with a summary.json), at the fidelity its
    /// summary names unless `fidelity` is given.
    pub fn read(dir: &Path, fidelity: Option<Fidelity>) -> Result<Run, String> {
        let summary = read_summary(dir)
            .ok_or_else(|| format!("{}: no summary.json (not a finished run)", dir.display()))?
            .map_err(|e| format!("{}: {e}", dir.display()))?;
        let fidelity = match fidelity {
            Some(f) => f,
            None => summary
                .fidelity
                .parse()
                .map_err(|e| format!("{}: fidelity `{}`: {e}", dir.display(), summary.fidelity))?,
        };
        Ok(Run {
            fidelity,
            dir: dir.to_path_buf(),
            summary,
        })
    }
}

/// The run of `case` under `runs`: at `requested` fidelity, or the best that exists.
pub fn choose_run(runs: &Path, case: &str, requested: Option<Fidelity>) -> Result<Run, String> {
    let candidates = requested.map_or(BEST_FIRST.to_vec(), |f| vec![f]);
    for fidelity in candidates {
        let dir = runs.join(case).join(fidelity.name());
        let Some(summary) = read_summary(&dir) else {
            continue;
        };
        let summary = summary.map_err(|e| format!("{fidelity} run: {e}"))?;
        return Ok(Run {
            fidelity,
            dir,
            summary,
        });
    }
    Err(match requested {
        Some(f) => format!("not run at {f} fidelity"),
        None => "not run".into(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixture::*;

    #[test]
    fn the_best_finished_run_is_chosen_unless_a_fidelity_is_asked() {
        let tmp = TempDir::new("choose");
        let runs = tmp.0.join("runs");
        write_run(&runs, "A", "smoke", 0.4, &[]);
        write_run(&runs, "A", "coarse", 1.25, &[]);
        // a folder without summary.json (a run still going) does not count
        std::fs::create_dir_all(runs.join("A").join("paper")).unwrap();
        assert_eq!(
            choose_run(&runs, "A", None).unwrap().fidelity,
            Fidelity::Coarse
        );
        let smoke = choose_run(&runs, "A", Some(Fidelity::Smoke)).unwrap();
        assert_eq!(smoke.fidelity, Fidelity::Smoke);
        assert_eq!(smoke.summary.simulated_time, 0.4);
        assert_eq!(
            choose_run(&runs, "A", Some(Fidelity::Paper)).unwrap_err(),
            "not run at paper fidelity"
        );
        assert_eq!(choose_run(&runs, "B", None).unwrap_err(), "not run");
        // the wall-resolving run ranks above coarse, below paper
        write_run(&runs, "A", "wall", 1.25, &[]);
        assert_eq!(
            choose_run(&runs, "A", None).unwrap().fidelity,
            Fidelity::Wall
        );
        write_run(&runs, "A", "paper", 1.25, &[]);
        assert_eq!(
            choose_run(&runs, "A", None).unwrap().fidelity,
            Fidelity::Paper
        );
    }

    #[test]
    fn a_folder_that_lacks_a_file_its_summary_lists_is_reported_damaged() {
        let tmp = TempDir::new("damaged");
        let runs = tmp.0.join("runs");
        write_run(&runs, "A", "coarse", 1.25, &[("bulk.csv", "t\n0\n")]);
        let dir = runs.join("A").join("coarse");
        let mut summary = read_summary(&dir).unwrap().unwrap();
        summary.files = vec![
            runout_output::RunFile {
                name: "bulk.csv".into(),
                bytes: 4,
            },
            runout_output::RunFile {
                name: "fields.pvd".into(),
                bytes: 10,
            },
        ];
        summary.write_json(&dir.join("summary.json")).unwrap();
        let err = choose_run(&runs, "A", None).unwrap_err();
        assert!(err.contains("damaged run: fields.pvd missing"), "{err}");
        std::fs::write(dir.join("fields.pvd"), "short").unwrap();
        let err = choose_run(&runs, "A", None).unwrap_err();
        assert!(err.contains("fields.pvd has 5 bytes, listed 10"), "{err}");
        std::fs::write(dir.join("fields.pvd"), "0123456789").unwrap();
        assert_eq!(
            choose_run(&runs, "A", None).unwrap().fidelity,
            Fidelity::Coarse
        );
    }
}
