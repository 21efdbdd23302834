//! The bulk monitor a run writes (`bulk.csv`: t, solids_mass, front_x, mean_u_s): the
//! solids mass, the front (the furthest floor cell with εs above the monitor's threshold)
//! and the εs-weighted mean u_s over time.

use std::path::Path;

use crate::table::Table;

/// One row of `bulk.csv`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BulkRow {
    /// time [s]
    pub t: f64,
    /// solids mass per unit depth [kg m⁻¹]
    pub mass: f64,
    /// front x [m]
    pub front: f64,
    /// εs-weighted mean u_s [m s⁻¹]
    pub mean_u: f64,
}

/// The rows of a `bulk.csv`, in file order; the error names the file (unreadable, a column
/// missing, a cell that is not a number).
pub fn read_bulk(path: &Path) -> Result<Vec<BulkRow>, String> {
    let table = Table::read(path)?;
    let column = |name: &str| {
        table
            .column(name)
            .map_err(|e| format!("{}: {e}", path.display()))
    };
    let (t, mass, front, mean_u) = (
        column("t")?,
        column("solids_mass")?,
        column("front_x")?,
        column("mean_u_s")?,
    );
    Ok((0..t.len())
        .map(|k| BulkRow {
            t: t[k],
            mass: mass[k],
            front: front[k],
            mean_u: mean_u[k],
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bulk_rows_are_read_by_column_name() {
        let dir = std::env::temp_dir().join(format!("runout-post-bulk-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("bulk.csv");
        std::fs::write(
            &file,
            "t,solids_mass,front_x,mean_u_s\n0.1,120,5.5,0.0\n0.2,120,5.7,1.5\n",
        )
        .unwrap();
        let rows = read_bulk(&file).unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!(
            rows[1],
            BulkRow {
                t: 0.2,
                mass: 120.0,
                front: 5.7,
                mean_u: 1.5
            }
        );
        std::fs::write(&file, "t,front_x\n0.1,5.5\n").unwrap();
        assert!(read_bulk(&file)
            .unwrap_err()
            .contains("no column `solids_mass`"));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
