//! Tests of the stability suite.

use super::*;

fn row(outcome: Outcome) -> Row {
    Row {
        case: "ST-x".into(),
        stresses: "a | b, \"c\"".into(),
        cells: (100, 9),
        end_time: 0.35,
        outcome,
        time: 0.2,
        min_dt: Some(1e-5),
        steps: 40,
        rejected: Some(3),
        mass_error: Some(-2e-12),
        max_eps_s: Some(0.651),
        eps_s_max: 0.65,
        wall_time: 1.5,
        non_finite: Vec::new(),
    }
}

fn csv_width(line: &str) -> usize {
    csv::ReaderBuilder::new()
        .has_headers(false)
        .from_reader(line.as_bytes())
        .records()
        .next()
        .expect("one record")
        .expect("valid CSV")
        .len()
}

#[test]
fn the_scan_finds_every_spelling_of_a_non_finite_number_and_nothing_else() {
    assert_eq!(
        non_finite_tokens("t,eps\n1e0,NaN\n2e0,-inf\n3e0,inf", false),
        3
    );
    assert_eq!(non_finite_tokens("1 nan 2 Infinity -INF +inf", false), 4);
    assert_eq!(
        non_finite_tokens(
            "<DataArray type=\"Float64\" Name=\"eps_s\" format=\"ascii\">0e0 6.5e-1 1e-12",
            false
        ),
        0
    );
    // words that contain the letters are not numbers
    assert_eq!(
        non_finite_tokens("information nano infinite_loop", false),
        0
    );
    assert_eq!(non_finite_tokens("{\"min\": null}", true), 1);
    assert_eq!(non_finite_tokens("{\"min\": null}", false), 0);
}

#[test]
fn the_scan_reports_the_files_of_a_run_that_hold_nan() {
    let dir = std::env::temp_dir().join(format!("runout-stability-scan-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("bulk.csv"), "t,m\n0e0,1e0\n1e-2,NaN\n").unwrap();
    std::fs::write(dir.join("fields_00001.vtr"), "<x>0e0 inf -inf</x>").unwrap();
    std::fs::write(dir.join("summary.json"), "{\"dt\": 1e-3}").unwrap();
    std::fs::write(dir.join("resolved.ron"), "NaN is not scanned here").unwrap();
    assert_eq!(
        scan_run(&dir),
        vec![
            ("bulk.csv".to_string(), 1),
            ("fields_00001.vtr".to_string(), 2)
        ]
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_diagnosis_is_checked_for_equation_cell_and_time() {
    let single = "the step from t = 1.0e-2 s did not converge; u momentum 1e-3 (largest at \
                  x = 0.1 m, y = 0.2 m)";
    assert_eq!(diagnosis_names(single), (true, true, true));
    assert_eq!(diagnosis_gaps(single), "");
    let two_fluid = "the step from t = 3.1e-1 s did not converge: momentum 1e-2, gas \
                     continuity 3e-4";
    assert_eq!(diagnosis_gaps(two_fluid), "no cell");
    assert_eq!(diagnosis_gaps("it broke"), "no equation, no cell, no time");
}

#[test]
fn nan_or_a_panic_fails_the_suite_and_a_diagnosed_stop_does_not() {
    assert!(!row(Outcome::Completed).violates());
    assert!(!row(Outcome::Stopped("t = 1 s".into())).violates());
    assert!(!row(Outcome::Refused("Schaeffer".into())).violates());
    assert!(row(Outcome::Panicked("index out of bounds".into())).violates());
    let mut nan = row(Outcome::Completed);
    nan.non_finite.push(("bulk.csv".into(), 2));
    assert!(nan.violates());
    assert_eq!(nan.status(), "NaN written (completed)");
    // a summary with a non-finite number is caught even if no file shows it
    let mut s = RunSummary {
        case: "ST-x".into(),
        fidelity: "smoke".into(),
        cells: (100, 9),
        simulated_time: 0.35,
        wall_time: 1.0,
        steps: 10,
        rejected_steps: 0,
        outer_iterations: 100,
        rejected_outer_iterations: 0,
        dt: runout_output::DtStats {
            min: 1e-3,
            max: 1e-2,
            mean: 5e-3,
        },
        solids_mass_change: f64::NAN,
        max_mass_imbalance: 0.0,
        max_eps_s: 0.6,
        status: RunStatus::Completed,
        profile: Vec::new(),
        linear_iterations: Vec::new(),
        files: Vec::new(),
    };
    assert!(row_from_summary(row(Outcome::Completed), &s).violates());
    s.solids_mass_change = 0.0;
    s.status = RunStatus::Diverged {
        diagnosis: "t = 0.1 s".into(),
    };
    let r = row_from_summary(row(Outcome::Completed), &s);
    assert!(!r.violates());
    assert_eq!(r.outcome, Outcome::Stopped("t = 0.1 s".into()));
}

#[test]
fn every_row_has_the_width_of_its_header() {
    let md_width = |l: &str| l.matches('|').count();
    let header = MD_HEADER.lines().next().unwrap();
    for outcome in [
        Outcome::Completed,
        Outcome::Stopped("t = 1 s, momentum, x = 2 m".into()),
        Outcome::Stopped("momentum, no place".into()),
        Outcome::Refused("needs \"P*\", not implemented".into()),
        Outcome::Error("x".into()),
    ] {
        let mut r = row(outcome);
        assert_eq!(md_width(&md_row(&r)), md_width(header));
        assert_eq!(
            csv_width(&csv_row(&r, Fidelity::Smoke)),
            csv_width(CSV_HEADER)
        );
        r.non_finite.push(("a.csv".into(), 1));
        r.min_dt = None;
        r.rejected = None;
        assert_eq!(md_width(&md_row(&r)), md_width(header));
        assert_eq!(
            csv_width(&csv_row(&r, Fidelity::Smoke)),
            csv_width(CSV_HEADER)
        );
    }
}

#[test]
fn the_page_holds_the_command_the_date_every_row_and_every_message() {
    let mut nan = row(Outcome::Completed);
    nan.case = "ST-nan".into();
    nan.non_finite.push(("bulk.csv".into(), 2));
    let mut early = row(Outcome::Stopped("t = 6.5e-6 s: momentum 1e-3".into()));
    early.case = "ST-early".into();
    early.time = 6.5e-6;
    let rows = [row(Outcome::Refused("needs P*".into())), nan, early];
    let md = markdown(
        &rows,
        Fidelity::Smoke,
        "cargo xtask stability",
        "2026-01-02",
    );
    assert!(md.contains("`cargo xtask stability` on 2026-01-02"), "{md}");
    assert_eq!(md.lines().filter(|l| l.starts_with("| ST-")).count(), 3);
    assert!(
        md.contains("stopped (diagnosis: no cell) | 6.50e-6 / 0.35"),
        "{md}"
    );
    assert!(md.contains("- **ST-x** (refused): needs P*"), "{md}");
    assert!(md.contains("- **ST-nan**: bulk.csv (2)"), "{md}");
    assert!(md.contains("εs,max = 0.65 in every case"), "{md}");
}

/// CI smoke: one stiff case (Δt_max ten times too large, started at Δt_max) at smoke
/// fidelity, through the same runner as the table; about a second.
#[test]
fn the_dt_max_case_runs_at_smoke_fidelity_without_writing_nan() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let cases = root.join("cases").join(STABILITY_DIR);
    let out = std::env::temp_dir().join(format!("runout-stability-{}", std::process::id()));
    let opts = StabilityOptions {
        fidelity: Fidelity::Smoke,
        only: Some("ST-dt-max".into()),
        jobs: 1,
    };
    let rows = run_cases(&cases, &out, &opts).expect("the case loads");
    assert_eq!(rows.len(), 1);
    let r = &rows[0];
    assert!(
        matches!(r.outcome, Outcome::Completed | Outcome::Stopped(_)),
        "{r:?}"
    );
    assert!(r.non_finite.is_empty(), "{r:?}");
    assert!(r.steps > 0 && r.min_dt.is_some_and(|dt| dt > 0.0), "{r:?}");
    assert!(
        r.mass_error.is_some_and(f64::is_finite) && r.max_eps_s.is_some_and(f64::is_finite),
        "{r:?}"
    );
    // the run folder was really scanned: its bulk monitor exists
    assert!(out
        .join("ST-dt-max")
        .join("smoke")
        .join("bulk.csv")
        .exists());
    std::fs::remove_dir_all(&out).unwrap();
}
