//! The files of a run folder: monitor CSVs by name prefix, `summary.json` and
//! `resolved.ron`.

use std::path::{Path, PathBuf};

use runout_output::RunSummary;

/// The files of `dir` whose names start with `prefix` and end with `.csv`, sorted; none if
/// the folder cannot be read.
pub fn csv_files(dir: &Path, prefix: &str) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|entries| {
            entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| {
                    p.file_name()
                        .and_then(|n| n.to_str())
                        .is_some_and(|n| n.starts_with(prefix) && n.ends_with(".csv"))
                })
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    files
}

/// The first of [`csv_files`].
pub fn first_csv(dir: &Path, prefix: &str) -> Option<PathBuf> {
    csv_files(dir, prefix).into_iter().next()
}

/// The run's `summary.json`: `None` without the file (a run still going, or killed), the
/// parse error if it cannot be read as a [`RunSummary`].
pub fn read_summary(dir: &Path) -> Option<Result<RunSummary, serde_json::Error>> {
    let text = std::fs::read_to_string(dir.join("summary.json")).ok()?;
    Some(serde_json::from_str(&text))
}

/// The run's `resolved.ron` (the case as it ran), if it can be read.
pub fn read_resolved(dir: &Path) -> Option<runout_case::Case> {
    runout_case::load_case(&dir.join("resolved.ron")).ok()
}

/// The run's `resolved.ron` read as written, not validated (a resolved smoke case keeps the
/// paper's profile time beyond its end time, which validation refuses); the error is the
/// read or parse error.
pub fn read_resolved_unvalidated(dir: &Path) -> Result<runout_case::Case, String> {
    std::fs::read_to_string(dir.join("resolved.ron"))
        .map_err(|e| e.to_string())
        .and_then(|t| ron::from_str(&t).map_err(|e| e.to_string()))
}
