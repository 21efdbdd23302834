//! VTK XML rectilinear grids (`.vtr`) and `.pvd` time-series collections.
//!
//! Format: VTK "XML file formats" (RectilinearGrid, Collection), ASCII data arrays.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use runout_mesh::Grid;

use crate::{write_atomic, OutputError};

/// A cell-centred field to write: a scalar (1 component) or a vector (2 components per
/// cell, written as 3-component VTK vectors with z = 0). Values run x fastest, like
/// [`Grid::cell_index`].
#[derive(Clone, Copy, Debug)]
pub struct CellField<'a> {
    /// name shown in ParaView
    pub name: &'a str,
    /// values, `components` per cell
    pub values: &'a [f64],
    /// 1 (scalar) or 2 (vector)
    pub components: usize,
}

impl<'a> CellField<'a> {
    /// A scalar field.
    pub fn scalar(name: &'a str, values: &'a [f64]) -> Self {
        CellField {
            name,
            values,
            components: 1,
        }
    }

    /// A 2-D vector field, interleaved (u0, v0, u1, v1, …).
    pub fn vector(name: &'a str, values: &'a [f64]) -> Self {
        CellField {
            name,
            values,
            components: 2,
        }
    }
}

/// Writes one time level as `.vtr`. Refuses non-finite values: NaN is never written as a
/// result (architecture.md, Errors).
pub fn write_vtr(
    path: &Path,
    grid: &Grid,
    time: f64,
    fields: &[CellField<'_>],
) -> Result<(), OutputError> {
    let n = grid.cell_count();
    for f in fields {
        if f.values.len() != n * f.components {
            return Err(OutputError::FieldLength {
                name: f.name.to_string(),
                len: f.values.len(),
                expected: n * f.components,
            });
        }
        if let Some(k) = f.values.iter().position(|v| !v.is_finite()) {
            return Err(OutputError::NonFinite {
                name: f.name.to_string(),
                index: k / f.components,
            });
        }
    }
    let (nx, ny) = (grid.nx(), grid.ny());
    let mut s = String::with_capacity(64 + n * 24 * fields.len().max(1));
    let extent = format!("0 {nx} 0 {ny} 0 0");
    s.push_str("<?xml version=\"1.0\"?>\n");
    s.push_str("<VTKFile type=\"RectilinearGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n");
    let _ = writeln!(s, "  <RectilinearGrid WholeExtent=\"{extent}\">");
    // The simulated time as field data (ParaView shows it; the .pvd carries it too).
    s.push_str("    <FieldData>\n");
    let _ = writeln!(
        s,
        "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">{time:e}</DataArray>"
    );
    s.push_str("    </FieldData>\n");
    let _ = writeln!(s, "    <Piece Extent=\"{extent}\">");
    s.push_str("      <CellData>\n");
    for f in fields {
        let comps = if f.components == 2 { 3 } else { 1 };
        let _ = write!(
            s,
            "        <DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{comps}\" format=\"ascii\">\n          ",
            xml_escape(f.name)
        );
        if f.components == 2 {
            for pair in f.values.chunks_exact(2) {
                let _ = write!(s, "{:e} {:e} 0 ", pair[0], pair[1]);
            }
        } else {
            for v in f.values {
                let _ = write!(s, "{v:e} ");
            }
        }
        s.push_str("\n        </DataArray>\n");
    }
    s.push_str("      </CellData>\n      <Coordinates>\n");
    for (name, coords) in [
        ("x", grid.x.faces()),
        ("y", grid.y.faces()),
        ("z", &[0.0][..]),
    ] {
        let _ = write!(
            s,
            "        <DataArray type=\"Float64\" Name=\"{name}\" format=\"ascii\">\n          "
        );
        for c in coords {
            let _ = write!(s, "{c:e} ");
        }
        s.push_str("\n        </DataArray>\n");
    }
    s.push_str("      </Coordinates>\n    </Piece>\n  </RectilinearGrid>\n</VTKFile>\n");
    write_atomic(path, s.as_bytes())
}

fn xml_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A `.pvd` collection: (time, `.vtr` file) entries, rewritten atomically on every push so
/// that the series on disk is always complete up to the last written step.
#[derive(Clone, Debug)]
pub struct PvdSeries {
    path: PathBuf,
    entries: Vec<(f64, String)>,
}

impl PvdSeries {
    /// A new, empty series written to `path` (the `.vtr` files are referenced relative to
    /// its folder).
    pub fn new(path: impl Into<PathBuf>) -> Self {
        PvdSeries {
            path: path.into(),
            entries: Vec::new(),
        }
    }

    /// Continues a series whose first entries are `entries` (from [`PvdSeries::entries`] at
    /// a checkpoint): the `.pvd` is rewritten with them, and `.vtr` files of the series
    /// numbered beyond them (written by a stopped run after the checkpoint) are removed.
    pub fn resume(
        path: impl Into<PathBuf>,
        entries: Vec<(f64, String)>,
    ) -> Result<Self, OutputError> {
        let series = PvdSeries {
            path: path.into(),
            entries,
        };
        let dir = series.path.parent().unwrap_or(Path::new("")).to_path_buf();
        let stem = series.stem();
        let listing = std::fs::read_dir(if dir.as_os_str().is_empty() {
            Path::new(".")
        } else {
            &dir
        })
        .map_err(crate::io_err(&dir))?;
        for entry in listing.flatten() {
            let name = entry.file_name().to_string_lossy().into_owned();
            let index = name
                .strip_prefix(&format!("{stem}_"))
                .and_then(|rest| rest.strip_suffix(".vtr"))
                .and_then(|n| n.parse::<usize>().ok());
            if index.is_some_and(|k| k >= series.entries.len()) {
                std::fs::remove_file(entry.path()).map_err(crate::io_err(&entry.path()))?;
            }
        }
        series.write()?;
        Ok(series)
    }

    /// The (time, file) entries written so far.
    pub fn entries(&self) -> &[(f64, String)] {
        &self.entries
    }

    fn stem(&self) -> String {
        self.path
            .file_stem()
            .map_or("fields".into(), |s| s.to_string_lossy().into_owned())
    }

    /// Writes `fields` at `time` as `<stem>_<index>.vtr` next to the `.pvd` and adds it.
    pub fn push(
        &mut self,
        grid: &Grid,
        time: f64,
        fields: &[CellField<'_>],
    ) -> Result<PathBuf, OutputError> {
        let stem = self.stem();
        let file = format!("{stem}_{:05}.vtr", self.entries.len());
        let dir = self.path.parent().unwrap_or(Path::new(""));
        let vtr = dir.join(&file);
        write_vtr(&vtr, grid, time, fields)?;
        self.entries.push((time, file));
        self.write()?;
        Ok(vtr)
    }

    /// Number of time levels written.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// Whether nothing was written yet.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    fn write(&self) -> Result<(), OutputError> {
        let mut s = String::from(
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n  <Collection>\n",
        );
        for (t, f) in &self.entries {
            let _ = writeln!(
                s,
                "    <DataSet timestep=\"{t:e}\" group=\"\" part=\"0\" file=\"{}\"/>",
                xml_escape(f)
            );
        }
        s.push_str("  </Collection>\n</VTKFile>\n");
        write_atomic(&self.path, s.as_bytes())
    }
}

/// The values of the ASCII DataArray `name` in a `.vtr` file written by [`write_vtr`] (its
/// components interleaved for a vector), or `None` if there is no such array or a value is
/// not a number.
pub fn read_vtr_array(xml: &str, name: &str) -> Option<Vec<f64>> {
    let start = xml.find(&format!("Name=\"{name}\""))?;
    let open = start + xml[start..].find('>')? + 1;
    let close = open + xml[open..].find("</DataArray>")?;
    xml[open..close]
        .split_whitespace()
        .map(|t| t.parse().ok())
        .collect()
}

/// The datasets a `.pvd` collection lists, as (time, file name) in the file's order; lines
/// without both attributes are skipped.
pub fn read_pvd(xml: &str) -> Vec<(f64, String)> {
    let attribute = |line: &str, key: &str| -> Option<String> {
        let start = line.find(&format!("{key}=\""))? + key.len() + 2;
        let end = start + line[start..].find('"')?;
        Some(line[start..end].to_string())
    };
    xml.lines()
        .filter(|l| l.contains("<DataSet"))
        .filter_map(|l| {
            let time = attribute(l, "timestep")?.parse().ok()?;
            Some((time, attribute(l, "file")?))
        })
        .collect()
}

/// The cell counts (nx, ny) of a `.vtr` (its `WholeExtent="0 nx 0 ny 0 0"`).
pub fn read_vtr_cells(xml: &str) -> Option<(usize, usize)> {
    let extent = xml.split("WholeExtent=\"").nth(1)?.split('"').next()?;
    let n: Vec<usize> = extent
        .split_whitespace()
        .map(|t| t.parse().ok())
        .collect::<Option<_>>()?;
    match n[..] {
        [0, nx, 0, ny, ..] => Some((nx, ny)),
        _ => None,
    }
}

#[cfg(test)]
mod read_tests {
    use super::read_vtr_array;

    #[test]
    fn reads_a_named_array() {
        let text = "<DataArray type=\"Float64\" Name=\"eps_s\" format=\"ascii\">1 2.5 3e-1</DataArray>\n<DataArray Name=\"u_s\">4</DataArray>";
        assert_eq!(read_vtr_array(text, "eps_s").unwrap(), vec![1.0, 2.5, 0.3]);
        assert_eq!(read_vtr_array(text, "u_s").unwrap(), vec![4.0]);
        assert!(read_vtr_array(text, "theta").is_none());
        assert!(read_vtr_array("<DataArray Name=\"x\">1 a</DataArray>", "x").is_none());
    }

    #[test]
    fn reads_a_collection_and_the_extent() {
        use super::{read_pvd, read_vtr_cells};
        let pvd = "<Collection>\n<DataSet timestep=\"0.5\" part=\"0\" file=\"f_00001.vtr\"/>\n\
                   <DataSet file=\"no_time.vtr\"/>\n<DataSet timestep=\"1e0\" file=\"f_00002.vtr\"/>\n";
        assert_eq!(
            read_pvd(pvd),
            vec![(0.5, "f_00001.vtr".into()), (1.0, "f_00002.vtr".into())]
        );
        let vtr = "<RectilinearGrid WholeExtent=\"0 250 0 23 0 0\">";
        assert_eq!(read_vtr_cells(vtr), Some((250, 23)));
        assert_eq!(
            read_vtr_cells("<RectilinearGrid WholeExtent=\"1 2\">"),
            None
        );
    }
}
