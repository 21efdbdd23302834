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

/// Why a run folder's summary is not a result.
#[derive(Debug, thiserror::Error)]
pub enum SummaryError {
    /// `summary.json` does not parse
    #[error("{}: unreadable summary.json: {source}", dir.display())]
    Unreadable {
        /// the run folder
        dir: PathBuf,
        /// the parse error
        source: serde_json::Error,
    },
    /// files the summary lists are missing or of another size
    #[error(
        "{}: damaged run: {} (another process wrote into the folder, or files were removed); \
         run the case again (the sweep does so by itself)",
        dir.display(),
        damage.join(", ")
    )]
    Damaged {
        /// the run folder
        dir: PathBuf,
        /// each missing or short file, described
        damage: Vec<String>,
    },
}

/// The run's `summary.json`: `None` without the file (a run still going, or killed), an
/// error if it does not parse or the folder lacks a file it lists ([`damage`]).
pub fn read_summary(dir: &Path) -> Option<Result<RunSummary, SummaryError>> {
    let text = std::fs::read_to_string(dir.join("summary.json")).ok()?;
    let summary: RunSummary = match serde_json::from_str(&text) {
        Ok(s) => s,
        Err(source) => {
            return Some(Err(SummaryError::Unreadable {
                dir: dir.to_path_buf(),
                source,
            }))
        }
    };
    let damage = damage(dir, &summary);
    if !damage.is_empty() {
        return Some(Err(SummaryError::Damaged {
            dir: dir.to_path_buf(),
            damage,
        }));
    }
    Some(Ok(summary))
}

/// The files `summary` lists that `dir` lacks or holds at another size, each described
/// ("bulk.csv missing", "fields.pvd has 120 bytes, listed 400").
pub fn damage(dir: &Path, summary: &RunSummary) -> Vec<String> {
    summary
        .files
        .iter()
        .filter_map(|f| match std::fs::metadata(dir.join(&f.name)) {
            Err(_) => Some(format!("{} missing", f.name)),
            Ok(m) if m.len() != f.bytes => Some(format!(
                "{} has {} bytes, listed {}",
                f.name,
                m.len(),
                f.bytes
            )),
            Ok(_) => None,
        })
        .collect()
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
