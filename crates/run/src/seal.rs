//! A finished run is complete or it is not finished: before its summary says how it ended,
//! every file of the run is synced to disk and listed in the summary with its size, and the
//! folder itself is synced; the store renames the folder into place only after that, and a
//! reader takes a folder that lacks a listed file as damaged
//! (`runout_post::folder::read_summary`).

use std::fs::File;
use std::path::Path;

use runout_output::RunFile;

use crate::out_dir;

/// Syncs every file of the run in `dir` (not `summary.json`, written after, nor the
/// checkpoints) and the folder, and lists them with their sizes, sorted by name.
pub fn seal(dir: &Path) -> std::io::Result<Vec<RunFile>> {
    let mut files = Vec::new();
    for name in out_dir::run_files(dir) {
        let path = dir.join(&name);
        if name == "summary.json" || name.ends_with(".tmp") || !path.is_file() {
            continue;
        }
        let file = File::open(&path)?;
        file.sync_all()?;
        files.push(RunFile {
            name,
            bytes: file.metadata()?.len(),
        });
    }
    sync_folder(dir)?;
    Ok(files)
}

/// Syncs the folder `dir` itself (its entries: a rename or a new file in it).
pub fn sync_folder(dir: &Path) -> std::io::Result<()> {
    #[cfg(unix)]
    File::open(dir)?.sync_all()?;
    #[cfg(not(unix))]
    let _ = dir;
    Ok(())
}
