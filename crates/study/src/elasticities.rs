//! `runout sensitivity`: the elasticity of every numeric column of `results/summary.csv`,
//! and of the front and the mean u_s at each run's end (its `bulk.csv`), over every
//! one-factor family of the sweeps in a case matrix ([`crate::families`]), from the rows of
//! one fidelity. The computation is [`crate::sensitivity`]'s: the least-squares
//! slope of ln y against ln p over a family's points (an arc elasticity where p ≤ 0).

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::Path;

use anyhow::{bail, Context, Result};
use runout_case::Fidelity;

use crate::families::{families, Family};
use crate::sensitivity::{summary, Method, Summary};
use crate::sweep::{csv_field, Matrix};

/// Columns of the summary that are not outputs of a run's flow or cost: the key, the
/// status, the yes/no air cushion and the list of gate speeds.
const NOT_OUTPUTS: [&str; 5] = ["case", "fidelity", "status", "air_cushion", "gate_speeds"];

/// The summary's rows of one fidelity: the output columns' names and, per case, their
/// values (`None` for an empty or non-numeric field).
pub struct Rows {
    /// the output columns, in the file's order
    pub columns: Vec<String>,
    /// case name → one value per column
    pub values: HashMap<String, Vec<Option<f64>>>,
}

/// Reads the rows of `fidelity` of the summary file `path`.
pub fn read_rows(path: &Path, fidelity: Fidelity) -> Result<Rows> {
    let mut reader = csv::Reader::from_path(path).with_context(|| {
        format!(
            "reading {} (written by a sweep: run `runout sweep` first)",
            path.display()
        )
    })?;
    let header: Vec<String> = reader.headers()?.iter().map(str::to_string).collect();
    let (Some(case), Some(fid)) = (
        header.iter().position(|h| h == "case"),
        header.iter().position(|h| h == "fidelity"),
    ) else {
        bail!("{}: no `case` and `fidelity` columns", path.display());
    };
    let outputs: Vec<usize> = (0..header.len())
        .filter(|&k| !NOT_OUTPUTS.contains(&header[k].as_str()))
        .collect();
    let mut values = HashMap::new();
    for record in reader.records() {
        let record = record.with_context(|| format!("reading {}", path.display()))?;
        if record.get(fid) != Some(fidelity.name()) {
            continue;
        }
        let row = outputs
            .iter()
            .map(|&k| record.get(k).and_then(|v| v.trim().parse::<f64>().ok()))
            .collect();
        values.insert(record.get(case).unwrap_or_default().to_string(), row);
    }
    Ok(Rows {
        columns: outputs.iter().map(|&k| header[k].clone()).collect(),
        values,
    })
}

/// The columns of a run's `bulk.csv` whose last value is an output: (column, name in the
/// table).
const BULK_OUTPUTS: [(&str, &str); 2] = [
    ("front_x_interpolated", "front_x_end_m"),
    ("mean_u_s", "mean_u_s_end_m_s"),
];

/// Adds the [`BULK_OUTPUTS`] to `rows`: the last row of `runs/<case>/<fidelity>/bulk.csv` of
/// every case (empty where a run has none).
pub fn add_bulk_outputs(rows: &mut Rows, runs: &Path, fidelity: Fidelity) {
    rows.columns
        .extend(BULK_OUTPUTS.iter().map(|(_, name)| name.to_string()));
    for (case, values) in rows.values.iter_mut() {
        let file = runs.join(case).join(fidelity.name()).join("bulk.csv");
        let last = last_values(&file);
        values.extend(
            BULK_OUTPUTS
                .iter()
                .map(|(column, _)| last.as_ref().and_then(|l| l.get(*column).copied())),
        );
    }
}

/// The numeric values of the last record of a CSV file, by column name.
fn last_values(file: &Path) -> Option<HashMap<String, f64>> {
    let mut reader = csv::Reader::from_path(file).ok()?;
    let header = reader.headers().ok()?.clone();
    let last = reader.records().filter_map(|r| r.ok()).last()?;
    Some(
        header
            .iter()
            .zip(last.iter())
            .filter_map(|(h, v)| Some((h.to_string(), v.trim().parse().ok()?)))
            .collect(),
    )
}

/// One family's summary elasticity of each output column.
pub struct FamilyElasticities {
    /// the family
    pub family: Family,
    /// one summary per column of [`Rows::columns`]
    pub summaries: Vec<Summary>,
}

/// The elasticities of every output column over every one-factor family of the sweeps
/// below `dir` in `matrix`.
pub fn compute(matrix: &Matrix, dir: &Path, rows: &Rows) -> Result<Vec<FamilyElasticities>> {
    let out = families(matrix, dir)?
        .into_iter()
        .map(|family| {
            let summaries = (0..rows.columns.len())
                .map(|c| {
                    let points: Vec<(f64, Result<f64, String>)> = family
                        .points
                        .iter()
                        .map(|(p, case)| (*p, point_value(rows, case, c)))
                        .collect();
                    summary(&points)
                })
                .collect();
            FamilyElasticities { family, summaries }
        })
        .collect();
    Ok(out)
}

/// The value of column `c` of `case`'s row, or why there is none.
fn point_value(rows: &Rows, case: &str, c: usize) -> Result<f64, String> {
    match rows.values.get(case) {
        None => Err(format!("{case}: no row (not run at this fidelity)")),
        Some(v) => v[c].ok_or_else(|| format!("{case}: empty")),
    }
}

/// The elasticity as the table shows it: the value to 2 decimals, `(arc)` for an arc
/// elasticity, `—` with no value.
fn shown(s: &Summary) -> String {
    match &s.elasticity {
        Ok(e) if e.method == Method::Arc => format!("{:.2} (arc)", e.value),
        Ok(e) => format!("{:.2}", e.value),
        Err(_) => "—".into(),
    }
}

/// The table of every family (rows) and output column with a value for at least one
/// family (columns), as Markdown; the columns without any are named below it.
pub fn table(columns: &[String], all: &[FamilyElasticities]) -> String {
    let (shown_columns, empty): (Vec<usize>, Vec<usize>) =
        (0..columns.len()).partition(|&c| all.iter().any(|f| f.summaries[c].elasticity.is_ok()));
    let names =
        |list: &[usize]| -> Vec<&str> { list.iter().map(|&c| columns[c].as_str()).collect() };
    let mut md = format!("| family | {} |\n", names(&shown_columns).join(" | "));
    let _ = writeln!(md, "|---{}|", "|---:".repeat(shown_columns.len()));
    for f in all {
        let cells: Vec<String> = shown_columns
            .iter()
            .map(|&c| shown(&f.summaries[c]))
            .collect();
        let _ = writeln!(md, "| {} | {} |", f.family.label(), cells.join(" | "));
    }
    if !empty.is_empty() {
        let _ = writeln!(
            md,
            "\nno value (no two usable points): {}",
            names(&empty).join(", ")
        );
    }
    md
}

/// Header of the elasticities CSV.
const CSV_HEADER: &str =
    "family,parameter,unit,output,elasticity,method,points_used,points,p_low,p_high,note";

/// Every (family, output) pair as a CSV line with its method, the points used and the
/// reason where there is no value.
pub fn csv(columns: &[String], all: &[FamilyElasticities]) -> String {
    let mut out = format!("{CSV_HEADER}\n");
    for f in all {
        for (column, s) in columns.iter().zip(&f.summaries) {
            let (value, method, note) = match &s.elasticity {
                Ok(e) => (
                    format!("{}", e.value),
                    format!("{:?}", e.method),
                    String::new(),
                ),
                Err(why) => (String::new(), String::new(), why.clone()),
            };
            let (lo, hi) = s.range.map_or((String::new(), String::new()), |(a, b)| {
                (a.to_string(), b.to_string())
            });
            let _ = writeln!(
                out,
                "{},{},{},{},{value},{method},{},{},{lo},{hi},{}",
                csv_field(&f.family.label()),
                csv_field(f.family.symbol),
                csv_field(f.family.unit),
                csv_field(column),
                s.used,
                s.of,
                csv_field(&note)
            );
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A summary whose max_u_s goes as p^0.5 over a two-parameter sweep gives 0.5 for each
    /// family of that parameter, and an empty column no value.
    #[test]
    fn a_power_law_in_the_summary_is_recovered() {
        let dir = std::env::temp_dir().join(format!("runout-elasticities-{}", std::process::id()));
        let cases = dir.join("cases");
        std::fs::create_dir_all(&cases).unwrap();
        let base = std::fs::read_to_string(
            Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/sensitivity/base.ron"),
        )
        .unwrap();
        std::fs::write(cases.join("base.ron"), base).unwrap();
        std::fs::write(
            cases.join("sweep.ron"),
            "Sweep(name: \"T\", base: \"base.ron\", vary: [Diameter([0.0001, 0.0004]), \
             Specularity([0.1, 0.2])])",
        )
        .unwrap();
        let matrix = crate::sweep::matrix(&cases).unwrap();
        let mut csv_text = String::from("case,fidelity,status,max_u_s,flow_thickness_m\n");
        for d in ["0.0001", "0.0004"] {
            for (phi, u) in [("0.1", 1.0), ("0.2", 1.0)] {
                let u = u * (d.parse::<f64>().unwrap() / 1e-4).sqrt();
                let _ = writeln!(csv_text, "T_d={d}_phi={phi},smoke,Completed,{u},");
            }
        }
        let path = dir.join("summary.csv");
        std::fs::write(&path, csv_text).unwrap();
        let rows = read_rows(&path, Fidelity::Smoke).unwrap();
        assert_eq!(rows.columns, ["max_u_s", "flow_thickness_m"]);
        let all = compute(&matrix, &cases, &rows).unwrap();
        let labels: Vec<String> = all.iter().map(|f| f.family.label()).collect();
        assert_eq!(labels.len(), 4, "{labels:?}");
        for f in &all {
            let e = f.summaries[0].elasticity.as_ref().unwrap().value;
            let expected = if f.family.symbol == "d" { 0.5 } else { 0.0 };
            assert!((e - expected).abs() < 1e-12, "{}: {e}", f.family.label());
            assert!(f.summaries[1].elasticity.is_err());
        }
        let mut rows = rows;
        let runs = dir.join("runs");
        let run = runs.join("T_d=0.0001_phi=0.1").join("smoke");
        std::fs::create_dir_all(&run).unwrap();
        std::fs::write(
            run.join("bulk.csv"),
            "t,front_x_interpolated,mean_u_s\n0,1,0\n1,2,0.5\n",
        )
        .unwrap();
        add_bulk_outputs(&mut rows, &runs, Fidelity::Smoke);
        assert_eq!(rows.columns[2..], ["front_x_end_m", "mean_u_s_end_m_s"]);
        assert_eq!(
            rows.values["T_d=0.0001_phi=0.1"][2..],
            [Some(2.0), Some(0.5)]
        );
        assert_eq!(rows.values["T_d=0.0004_phi=0.1"][2..], [None, None]);
        let md = table(&rows.columns[..2], &all);
        assert!(md.contains("| T: d (φ = 0.1) | 0.50 |\n"), "{md}");
        assert!(
            md.contains("no value (no two usable points): flow_thickness_m"),
            "{md}"
        );
        assert_eq!(csv(&rows.columns, &all).lines().count(), 1 + 4 * 2);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
