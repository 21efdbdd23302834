//! The writers produce files their readers accept: VTK XML that declares the grid's extent
//! and coordinates, a .pvd listing every step, CSV rows that read back, JSON that parses.

use runout_mesh::{Axis, Grid};
use runout_output::{
    write_vtr, CellField, CsvSeries, DtStats, OutputError, PvdSeries, RunStatus, RunSummary,
};

fn grid() -> Grid {
    Grid::new(
        Axis::from_faces(vec![0.0, 0.5, 1.5, 3.0]).unwrap(),
        Axis::uniform(0.0, 1.0, 2).unwrap(),
    )
}

fn tmp(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("runout-output-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d.join(name)
}

/// The numbers between the opening and closing tag of the DataArray named `name`.
fn array(xml: &str, name: &str) -> Vec<f64> {
    let start = xml.find(&format!("Name=\"{name}\"")).unwrap();
    let open = start + xml[start..].find('>').unwrap() + 1;
    let close = open + xml[open..].find("</DataArray>").unwrap();
    xml[open..close]
        .split_whitespace()
        .map(|t| t.parse().unwrap())
        .collect()
}

#[test]
fn vtr_holds_faces_and_cell_data() {
    let g = grid();
    let eps: Vec<f64> = (0..6).map(|k| k as f64 * 0.1).collect();
    let vel: Vec<f64> = (0..12).map(|k| k as f64).collect();
    let path = tmp("a.vtr");
    write_vtr(
        &path,
        &g,
        0.25,
        &[
            CellField::scalar("eps_s", &eps),
            CellField::vector("u_s", &vel),
        ],
    )
    .unwrap();
    let xml = std::fs::read_to_string(&path).unwrap();
    assert!(xml.contains("WholeExtent=\"0 3 0 2 0 0\""));
    assert_eq!(array(&xml, "x"), vec![0.0, 0.5, 1.5, 3.0]);
    assert_eq!(array(&xml, "y"), vec![0.0, 0.5, 1.0]);
    assert_eq!(array(&xml, "eps_s"), eps);
    let u = array(&xml, "u_s");
    assert_eq!(u.len(), 18);
    assert_eq!(&u[3..6], &[2.0, 3.0, 0.0]);
    assert_eq!(array(&xml, "TimeValue"), vec![0.25]);
}

#[test]
fn vtr_refuses_nan_and_wrong_lengths() {
    let g = grid();
    let mut eps = vec![0.1; 6];
    eps[4] = f64::NAN;
    let e = write_vtr(
        &tmp("nan.vtr"),
        &g,
        0.0,
        &[CellField::scalar("eps_s", &eps)],
    )
    .unwrap_err();
    assert!(matches!(e, OutputError::NonFinite { index: 4, .. }), "{e}");
    let e = write_vtr(
        &tmp("len.vtr"),
        &g,
        0.0,
        &[CellField::scalar("p", &[1.0; 5])],
    )
    .unwrap_err();
    assert!(
        matches!(
            e,
            OutputError::FieldLength {
                len: 5,
                expected: 6,
                ..
            }
        ),
        "{e}"
    );
    assert!(!tmp("nan.vtr").exists());
}

#[test]
fn pvd_lists_every_step() {
    let g = grid();
    let mut s = PvdSeries::new(tmp("series/run.pvd"));
    for k in 0..3 {
        s.push(
            &g,
            0.1 * k as f64,
            &[CellField::scalar("p", &[k as f64; 6])],
        )
        .unwrap();
    }
    let pvd = std::fs::read_to_string(tmp("series/run.pvd")).unwrap();
    assert_eq!(pvd.matches("<DataSet").count(), 3);
    assert!(pvd.contains("file=\"run_00002.vtr\""));
    assert!(tmp("series/run_00002.vtr").exists());
}

#[test]
fn csv_rows_read_back() {
    let path = tmp("m.csv");
    let mut c = CsvSeries::create(&path, &["t", "front"]).unwrap();
    c.push(&[0.0, 0.5]).unwrap();
    c.push(&[0.1, 0.75]).unwrap();
    assert!(c.push(&[1.0]).is_err());
    let mut r = csv::Reader::from_path(&path).unwrap();
    let rows: Vec<Vec<f64>> = r
        .records()
        .map(|x| x.unwrap().iter().map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows, vec![vec![0.0, 0.5], vec![0.1, 0.75]]);
}

#[test]
fn summary_round_trips() {
    let s = RunSummary {
        case: "M-JJ".into(),
        fidelity: "smoke".into(),
        cells: (40, 10),
        simulated_time: 0.1,
        wall_time: 1.5,
        steps: 100,
        rejected_steps: 2,
        outer_iterations: 900,
        rejected_outer_iterations: 12,
        dt: DtStats {
            min: 1e-4,
            max: 1e-3,
            mean: 5e-4,
        },
        solids_mass_change: 1e-12,
        max_mass_imbalance: 1e-11,
        max_eps_s: 0.6,
        status: RunStatus::Diverged {
            diagnosis: "theta at (3, 4), t = 0.05 s".into(),
        },
        profile: vec![("closures".into(), 0.25), ("pressure_solve".into(), 0.5)],
        linear_iterations: Vec::new(),
        files: Vec::new(),
    };
    let path = tmp("summary.json");
    s.write_json(&path).unwrap();
    let back: RunSummary = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
    assert_eq!(back, s);
}

/// A summary written before `rejected_outer_iterations` existed still reads, with 0.
#[test]
fn an_older_summary_without_rejected_iterations_reads() {
    let old = r#"{"case": "M-JJ", "fidelity": "smoke", "cells": [40, 10], "simulated_time": 0.1,
        "wall_time": 1.5, "steps": 100, "rejected_steps": 2, "outer_iterations": 900,
        "dt": {"min": 1e-4, "max": 1e-3, "mean": 5e-4}, "solids_mass_change": 0.0,
        "max_mass_imbalance": 0.0, "status": "Completed"}"#;
    let s: RunSummary = serde_json::from_str(old).unwrap();
    assert_eq!((s.outer_iterations, s.rejected_outer_iterations), (900, 0));
}
