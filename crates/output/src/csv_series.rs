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
