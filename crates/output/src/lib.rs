//! runout-output: writers for fields, monitors and run summaries.
//!
//! - [`write_vtr`]: one time level as a VTK XML rectilinear grid (`.vtr`), which maps
//!   exactly onto a stretched staggered grid: the face coordinates are the grid lines and
//!   the fields are cell data;
//! - [`PvdSeries`]: the `.pvd` collection that makes a time series of `.vtr` files open in
//!   ParaView as one animated dataset;
//! - [`CsvSeries`]: monitor time series and profiles as CSV;
//! - [`RunSummary`]: what a run did (wall time, steps, dt statistics, iterations, mass
//!   balance, status) as JSON.
//!
//! Every file is written atomically (a temporary name, then a rename), so a run that is
//! killed never leaves a half-written result behind.
#![deny(missing_docs)]

mod csv_series;
mod summary;
mod vtk;

pub use csv_series::CsvSeries;
pub use summary::{DtStats, RunFile, RunStatus, RunSummary};
pub use vtk::{read_pvd, read_vtr_array, read_vtr_cells, write_vtr, CellField, PvdSeries};

use std::io::Write;
use std::path::{Path, PathBuf};

/// Errors writing output.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// An I/O error on a file.
    #[error("{path}: {source}")]
    Io {
        /// the file
        path: PathBuf,
        /// the error
        source: std::io::Error,
    },
    /// A field whose length does not match the grid.
    #[error("field `{name}` has {len} values, the grid has {expected} cells")]
    FieldLength {
        /// field name
        name: String,
        /// values given
        len: usize,
        /// cells in the grid (× components)
        expected: usize,
    },
    /// A value that cannot be written as a result (NaN or infinite).
    #[error("field `{name}` holds a non-finite value at cell {index}")]
    NonFinite {
        /// field name
        name: String,
        /// linear cell index
        index: usize,
    },
    /// CSV writer error.
    #[error("{path}: {message}")]
    Csv {
        /// the file
        path: PathBuf,
        /// the error
        message: String,
    },
}

pub(crate) fn io_err(path: &Path) -> impl FnOnce(std::io::Error) -> OutputError + '_ {
    move |source| OutputError::Io {
        path: path.to_path_buf(),
        source,
    }
}

/// Writes `bytes` to `path` atomically: into `path` + `.tmp`, flushed, then renamed.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    if let Some(dir) = path.parent() {
        if !dir.as_os_str().is_empty() {
            std::fs::create_dir_all(dir).map_err(io_err(dir))?;
        }
    }
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    let tmp = PathBuf::from(tmp);
    let written = (|| {
        let mut f = std::fs::File::create(&tmp)?;
        f.write_all(bytes)?;
        f.sync_all()
    })();
    if let Err(source) = written {
        // a full disk or a failed write leaves no temporary file behind
        let _ = std::fs::remove_file(&tmp);
        return Err(OutputError::Io { path: tmp, source });
    }
    std::fs::rename(&tmp, path).map_err(|source| {
        let _ = std::fs::remove_file(&tmp);
        OutputError::Io {
            path: path.to_path_buf(),
            source,
        }
    })
}
