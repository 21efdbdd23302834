//! The paper's user partial-slip slide (S-PS-d, d = 0.5 mm, paper Fig. 7d–f) at smoke
//! fidelity through the two-fluid solver: the packed block falls 0.4 m, gravity tilts to
//! 40° on impact, and the material slides. Checks (issue 7's last check, for the case
//! family the solver supports today): the run completes with no rejected-step collapse,
//! the solids mass is conserved within 1e-8, εs ≤ εs,max + 0.02 everywhere, and the
//! material moves downslope.

use std::path::Path;

use runout_case::{load, Fidelity, Loaded};
use runout_output::RunStatus;

/// The values of the DataArray `name` in a .vtr file written by runout-output.
fn vtr_array(xml: &str, name: &str) -> Vec<f64> {
    runout_output::read_vtr_array(xml, name).expect("array present")
}

/// The last row of a run's `bulk.csv` (t, solids mass, front x, mean u_s), read with the
/// post-processing library's one CSV reader.
fn last_bulk_row(run_dir: &Path) -> Vec<f64> {
    let bulk = runout_post::table::Table::read(&run_dir.join("bulk.csv")).unwrap();
    ["t", "solids_mass", "front_x", "mean_u_s"]
        .iter()
        .map(|c| *bulk.column(c).unwrap().last().unwrap())
        .collect()
}

#[test]
fn s_ps_d_smoke_runs_conserves_mass_and_slides() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/sensitivity/S-PS-d.ron");
    let Loaded::Cases(cases) = load(&file).unwrap() else {
        panic!("a sweep")
    };
    let case = cases
        .into_iter()
        .find(|c| c.case.name == "S-PS-d_d=0.0005")
        .unwrap()
        .case;
    let out = std::env::temp_dir().join(format!("runout-sps-smoke-{}", std::process::id()));
    let verbose = std::env::var("RUNOUT_VERBOSE").is_ok();
    let summary = runout_run::run_case(&case, Fidelity::Smoke, &out, |p| {
        if verbose && p.steps % 20 == 0 {
            eprintln!(
                "t = {:.4} s, dt = {:.2e} s, {} it",
                p.time, p.dt, p.iterations
            );
        }
    })
    .unwrap();
    eprintln!("{summary:?}");
    assert_eq!(summary.status, RunStatus::Completed);
    assert!(
        summary.solids_mass_change.abs() <= 1e-8,
        "{}",
        summary.solids_mass_change
    );
    // the last field file
    let pvd = std::fs::read_to_string(out.join("fields.pvd")).unwrap();
    let last = pvd
        .rsplit("file=\"")
        .next()
        .unwrap()
        .split('"')
        .next()
        .unwrap();
    let xml = std::fs::read_to_string(out.join(last)).unwrap();
    let eps = vtr_array(&xml, "eps_s");
    let max_eps = eps.iter().cloned().fold(0.0, f64::max);
    assert!(max_eps <= 0.65 + 0.02, "max eps {max_eps}");
    // εs-weighted mean solids velocity downslope at the end (bulk monitor)
    let last_row = last_bulk_row(&out);
    assert!(last_row[3] > 0.1, "mean u_s {}", last_row[3]);
}
