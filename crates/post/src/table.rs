//! The one reader of the CSV files runout writes (monitors, gates, summaries): columns by
//! name, numeric rows, and values at a time.

use std::path::Path;

/// A CSV file runout writes (monitors, gates, the summary table): column names and numeric
/// rows (empty cells are NaN).
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    columns: Vec<String>,
    rows: Vec<Vec<f64>>,
}

impl Table {
    /// Parses a header line and numeric rows; `#` lines and blank lines are skipped.
    pub fn parse(text: &str) -> Result<Table, String> {
        let mut lines = text
            .lines()
            .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
        let header = lines.next().ok_or("no header line")?;
        let columns: Vec<String> = header.split(',').map(|c| c.trim().to_string()).collect();
        let mut rows = Vec::new();
        for (k, line) in lines.enumerate() {
            let row = line
                .split(',')
                .map(|v| match v.trim() {
                    "" => Ok(f64::NAN),
                    v => v
                        .parse()
                        .map_err(|_| format!("data row {}: `{v}` is not a number", k + 1)),
                })
                .collect::<Result<Vec<f64>, String>>()?;
            if row.len() != columns.len() {
                return Err(format!(
                    "data row {}: {} values for {} columns",
                    k + 1,
                    row.len(),
                    columns.len()
                ));
            }
            rows.push(row);
        }
        Ok(Table { columns, rows })
    }

    /// Reads and parses `path`; the error names the file.
    pub fn read(path: &Path) -> Result<Table, String> {
        let name = path
            .file_name()
            .map_or(String::new(), |n| n.to_string_lossy().into());
        let text = std::fs::read_to_string(path).map_err(|e| format!("cannot read {name}: {e}"))?;
        Table::parse(&text).map_err(|e| format!("{name}: {e}"))
    }

    /// The values of one column.
    pub fn column(&self, name: &str) -> Result<Vec<f64>, String> {
        let k = self
            .columns
            .iter()
            .position(|c| c == name)
            .ok_or_else(|| format!("no column `{name}` (has {})", self.columns.join(", ")))?;
        Ok(self.rows.iter().map(|r| r[k]).collect())
    }

    /// Two columns as (x, y) pairs.
    pub fn pairs(&self, x: &str, y: &str) -> Result<Vec<(f64, f64)>, String> {
        Ok(self.column(x)?.into_iter().zip(self.column(y)?).collect())
    }
    /// The number of data rows.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// Whether the table has no data rows.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// The row at time `t` of the (ascending) column `time`: interpolated linearly between
    /// the rows on either side of `t`, or, past the ends, the row nearest `t` if it lies
    /// within `tolerance` (a run that ends at `t` has its last sample up to one interval
    /// before). Returns the time used and the row.
    pub fn row_at(&self, time: &str, t: f64, tolerance: f64) -> Result<(f64, Vec<f64>), String> {
        let times = self.column(time)?;
        if let Some(k) = (1..times.len()).find(|&k| times[k - 1] <= t && t <= times[k]) {
            let (a, b) = (&self.rows[k - 1], &self.rows[k]);
            let span = times[k] - times[k - 1];
            let w = if span > 0.0 {
                (t - times[k - 1]) / span
            } else {
                0.0
            };
            let row = a.iter().zip(b).map(|(x, y)| x + w * (y - x)).collect();
            return Ok((t, row));
        }
        (0..times.len())
            .filter(|&k| (times[k] - t).abs() <= tolerance)
            .min_by(|&a, &b| (times[a] - t).abs().total_cmp(&(times[b] - t).abs()))
            .map(|k| (times[k], self.rows[k].clone()))
            .ok_or_else(|| format!("no sample at or within {tolerance} s of {time} = {t}"))
    }

    /// The value of `column` at time `t` of the column `time` ([`Table::row_at`]), with the
    /// time used.
    pub fn value_at(
        &self,
        time: &str,
        column: &str,
        t: f64,
        tolerance: f64,
    ) -> Result<(f64, f64), String> {
        let k = self.index(column)?;
        let (at, row) = self.row_at(time, t, tolerance)?;
        Ok((at, row[k]))
    }

    fn index(&self, name: &str) -> Result<usize, String> {
        self.columns
            .iter()
            .position(|c| c == name)
            .ok_or_else(|| format!("no column `{name}` (has {})", self.columns.join(", ")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_are_read_by_column_name() {
        let t = Table::parse("# a comment\nt, h_w_u\n0.1,5\n\n0.2,\n").unwrap();
        assert_eq!(t.column("t").unwrap(), vec![0.1, 0.2]);
        let h = t.column("h_w_u").unwrap();
        assert_eq!(h[0], 5.0);
        assert!(h[1].is_nan(), "an empty cell is NaN");
        assert_eq!(t.pairs("h_w_u", "t").unwrap()[0], (5.0, 0.1));
        assert!(t.column("speed").unwrap_err().contains("no column `speed`"));
        assert!(Table::parse("t,x\n1,abc\n")
            .unwrap_err()
            .contains("not a number"));
        assert!(Table::parse("t,x\n1\n")
            .unwrap_err()
            .contains("1 values for 2 columns"));
        assert!(Table::parse("# only a comment\n").is_err());
        // a header without rows is an empty table, not an error
        assert!(Table::parse("gate,x,t_cross,speed\n")
            .unwrap()
            .rows
            .is_empty());
    }

    #[test]
    fn rows_are_interpolated_at_a_time_or_taken_near_the_ends() {
        let t = Table::parse("t,front_x\n1.0,10\n1.1,12\n1.2,13\n").unwrap();
        let (at, x) = t.value_at("t", "front_x", 1.05, 0.01).unwrap();
        assert_eq!(at, 1.05);
        assert!((x - 11.0).abs() < 1e-12);
        assert_eq!(t.value_at("t", "front_x", 1.2, 0.0).unwrap(), (1.2, 13.0));
        // past the last sample: the nearest within the tolerance
        assert_eq!(
            t.value_at("t", "front_x", 1.205, 0.01).unwrap(),
            (1.2, 13.0)
        );
        assert!(t
            .value_at("t", "front_x", 1.3, 0.01)
            .unwrap_err()
            .contains("no sample"));
        assert!(t.value_at("t", "speed", 1.05, 0.01).is_err());
    }
}
