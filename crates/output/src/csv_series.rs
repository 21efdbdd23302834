//! CSV monitor series (time series, profiles).

use std::fs::File;
use std::io::BufWriter;
use std::path::{Path, PathBuf};

use crate::OutputError;

/// A CSV file with a fixed header, appended row by row and flushed after each row so that
/// a stopped run keeps every sample it took.
pub struct CsvSeries {
    path: PathBuf,
    columns: usize,
    writer: csv::Writer<BufWriter<File>>,
}

impl CsvSeries {
    /// Creates (truncates) `path` and writes the header.
    pub fn create(path: &Path, header: &[&str]) -> Result<Self, OutputError> {
        if let Some(dir) = path.parent() {
            if !dir.as_os_str().is_empty() {
                std::fs::create_dir_all(dir).map_err(crate::io_err(dir))?;
            }
        }
        let file = File::create(path).map_err(crate::io_err(path))?;
        let mut writer = csv::Writer::from_writer(BufWriter::new(file));
        let err = |e: csv::Error| OutputError::Csv {
            path: path.to_path_buf(),
            message: e.to_string(),
        };
        writer.write_record(header).map_err(err)?;
        writer.flush().map_err(crate::io_err(path))?;
        Ok(CsvSeries {
            path: path.to_path_buf(),
            columns: header.len(),
            writer,
        })
    }

    /// Reopens a series written earlier for appending, cut back to its first `len` bytes
    /// (the length [`CsvSeries::len_bytes`] gave at a checkpoint): rows a stopped run wrote
    /// after the checkpoint are dropped, and the restarted run writes them again.
    pub fn resume(path: &Path, columns: usize, len: u64) -> Result<Self, OutputError> {
        let file = std::fs::OpenOptions::new()
            .write(true)
            .open(path)
            .map_err(crate::io_err(path))?;
        let found = file.metadata().map_err(crate::io_err(path))?.len();
        if found < len {
            return Err(OutputError::Csv {
                path: path.to_path_buf(),
                message: format!(
                    "holds {found} bytes, fewer than the {len} it had at the checkpoint"
                ),
            });
        }
        file.set_len(len).map_err(crate::io_err(path))?;
        let mut file = file;
        std::io::Seek::seek(&mut file, std::io::SeekFrom::End(0)).map_err(crate::io_err(path))?;
        Ok(CsvSeries {
            path: path.to_path_buf(),
            columns,
            writer: csv::WriterBuilder::new()
                .has_headers(false)
                .from_writer(BufWriter::new(file)),
        })
    }

    /// Bytes written so far (every row is flushed).
    pub fn len_bytes(&self) -> Result<u64, OutputError> {
        std::fs::metadata(&self.path)
            .map(|m| m.len())
            .map_err(crate::io_err(&self.path))
    }

    /// Appends one row; its length must match the header.
    pub fn push(&mut self, row: &[f64]) -> Result<(), OutputError> {
        if row.len() != self.columns {
            return Err(OutputError::Csv {
                path: self.path.clone(),
                message: format!("row of {} values, header has {}", row.len(), self.columns),
            });
        }
        let path = self.path.clone();
        self.writer
            .write_record(row.iter().map(|v| format!("{v:e}")))
            .map_err(|e| OutputError::Csv {
                path: path.clone(),
                message: e.to_string(),
            })?;
        self.writer.flush().map_err(crate::io_err(&path))
    }

    /// The file being written.
    pub fn path(&self) -> &Path {
        &self.path
    }
}
