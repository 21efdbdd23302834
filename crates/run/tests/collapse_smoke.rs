//! Issue 7's column collapse (family C, cases/collapse/C-a1.ron, a = H0/L0 = 1) at smoke
//! fidelity through the two-fluid solver: the run completes, conserves the solids mass,
//! keeps εs ≤ εs,max + 0.02, and the front moves forward without retreating and stays
//! inside the domain. Whether the deposit stops is a separate (ignored) test: it does not
//! yet (docs/reports/collapse-princeton.md). `cargo xtask verify collapse` compares the runout with the
//! laboratory laws.

use std::path::{Path, PathBuf};

use runout_case::{load, Case, Fidelity, Loaded};
use runout_output::{RunStatus, RunSummary};

/// The values of the DataArray `name` in a .vtr file written by runout-output.
fn vtr_array(xml: &str, name: &str) -> Vec<f64> {
    runout_output::read_vtr_array(xml, name).expect("array present")
}

/// (t, solids mass, front x, εs-weighted mean u_s) rows of bulk.csv.
fn bulk_rows(out: &Path) -> Vec<[f64; 4]> {
    std::fs::read_to_string(out.join("bulk.csv"))
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|x| x.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

/// Runs C-a1 at smoke fidelity into a fresh temporary folder.
fn run_a1(tag: &str) -> (Case, PathBuf, RunSummary) {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/collapse/C-a1.ron");
    let Loaded::Cases(mut cases) = load(&file).unwrap() else {
        panic!("a case file")
    };
    let case = cases.remove(0).case;
    let out = std::env::temp_dir().join(format!("runout-collapse-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let summary = runout_run::run_case(&case, Fidelity::Smoke, &out, |_| {}).unwrap();
    eprintln!("{summary:?}");
    (case, out, summary)
}

#[test]
fn a1_smoke_runs_conserves_mass_and_the_front_advances_inside_the_domain() {
    let (case, out, summary) = run_a1("advance");
    assert_eq!(summary.status, RunStatus::Completed);
    // the solids mass is conserved to the per-step continuity tolerance where the column
    // compacts (the selective relaxation of the ε correction at packing, docs/model.md §4.7,
    // leaves an imbalance that the converged step keeps): 2.2e-8 here
    assert!(
        summary.solids_mass_change.abs() <= 1e-7,
        "{}",
        summary.solids_mass_change
    );
    let grid = case.at_fidelity(Fidelity::Smoke).grid().unwrap();
    let dx = grid.x.widths()[0];
    let l0 = case.initial.regions[0].x.1;
    let rows = bulk_rows(&out);
    let (first, last) = (rows[0], rows[rows.len() - 1]);
    // the front starts at the column's foot and moves at least one column width
    assert!(first[2] <= l0 + 2.0 * dx, "first front {}", first[2]);
    assert!(last[2] >= 2.0 * l0, "front {} did not advance", last[2]);
    // it never retreats by more than one cell (it moves by whole cells)
    for w in rows.windows(2) {
        assert!(w[1][2] >= w[0][2] - dx - 1e-12, "front retreats: {w:?}");
    }
    // and it stays inside the domain (the laboratory laws give L∞ ≈ 2.2–2.8 L0)
    assert!(
        last[2] < grid.x.end(),
        "front reached the end wall at x = {}",
        grid.x.end()
    );
    // packing bound in the last field file
    let pvd = std::fs::read_to_string(out.join("fields.pvd")).unwrap();
    let last_file = pvd
        .rsplit("file=\"")
        .next()
        .unwrap()
        .split('"')
        .next()
        .unwrap();
    let xml = std::fs::read_to_string(out.join(last_file)).unwrap();
    let max_eps = vtr_array(&xml, "eps_s").into_iter().fold(0.0, f64::max);
    assert!(max_eps <= 0.65 + 0.02, "max eps {max_eps}");
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
#[ignore = "known failure: the a = 1 deposit is still moving at the end (docs/reports/collapse-princeton.md)"]
fn a1_smoke_deposit_stops() {
    let (case, out, summary) = run_a1("stops");
    assert_eq!(summary.status, RunStatus::Completed);
    let h0 = case.initial.regions[0].y.1;
    let u_ref = (9.81 * h0).sqrt();
    let rows = bulk_rows(&out);
    let last = rows[rows.len() - 1];
    // εs-weighted mean u_s below 1 % of √(g H0) at 6.3 √(H0/g)
    assert!(
        last[3].abs() < 0.01 * u_ref,
        "mean u_s {} m/s at t = {} s (limit {})",
        last[3],
        last[0],
        0.01 * u_ref
    );
    let _ = std::fs::remove_dir_all(&out);
}
