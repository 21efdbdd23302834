//! The run folder: a new run refuses (or, when asked, clears) a folder that holds another
//! run, so that no file of an earlier run (a `.vtr` beyond the new run's last output, a
//! summary saying "Completed") is left beside the new run's.

use std::path::Path;

use crate::checkpoint::CHECKPOINT_DIR;
use crate::monitors::FIELDS_FILE;

/// The files a run writes, by name: the summary, the resolved case, the field series and
/// its `.vtr` files, the monitors' CSV files and any temporary file of an atomic write.
fn is_run_file(name: &str) -> bool {
    let stem = FIELDS_FILE.trim_end_matches(".pvd");
    matches!(
        name,
        "summary.json" | "resolved.ron" | "bulk.csv" | "front.csv" | "gates.csv"
    ) || name == FIELDS_FILE
        || (name.starts_with(&format!("{stem}_")) && name.ends_with(".vtr"))
        || (name.starts_with("wall_probe_") && name.ends_with(".csv"))
        || (name.starts_with("profile_x") && name.ends_with(".csv"))
        || name.ends_with(".tmp")
}

/// What `dir` holds of a run: its file names (sorted), empty when it holds none.
pub fn run_files(dir: &Path) -> Vec<String> {
    let Ok(listing) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut names: Vec<String> = listing
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| is_run_file(n) || n == CHECKPOINT_DIR)
        .collect();
    names.sort();
    names
}

/// Removes the files of a run from `dir` (only those: other files stay).
pub fn clear_run(dir: &Path) -> std::io::Result<()> {
    for name in run_files(dir) {
        let path = dir.join(&name);
        if name == CHECKPOINT_DIR {
            std::fs::remove_dir_all(&path)?;
        } else {
            std::fs::remove_file(&path)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clearing_removes_the_run_and_keeps_other_files() {
        let dir = std::env::temp_dir().join(format!("runout-outdir-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join(CHECKPOINT_DIR)).unwrap();
        for f in [
            "summary.json",
            "fields.pvd",
            "fields_00007.vtr",
            "bulk.csv",
            "profile_x11_t1.25.csv",
            "notes.txt",
            "fields_00001.vtr.tmp",
        ] {
            std::fs::write(dir.join(f), "x").unwrap();
        }
        assert_eq!(run_files(&dir).len(), 7);
        clear_run(&dir).unwrap();
        assert!(run_files(&dir).is_empty());
        assert!(dir.join("notes.txt").exists(), "a file of the user's stays");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
