//! `runout post --basal-load` end to end (issue 60; docs/reference/deposit.md, "The basal
//! load"): who carries a bed's weight before and while gas fluidises it.

use std::process::Command;

/// cases/gas/fluidised-bed.ron at smoke size (5 × 30 cells, about 2 s): a settled bed of
/// 0.5 mm sand that air fluidises through the floor from 0.2 s. Before the air, the solids
/// pressure carries the bed's weight (λ_s = 1, λ_g = 0); while the air flows, the gas's
/// pressure drop equals the bed's buoyant weight (a fluidised bed's defining balance), so
/// λ_g = 1 on average over the bubbling; the CSV holds every column.
#[test]
fn a_bed_carried_by_its_solids_then_by_the_gas_says_so() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let dir = std::env::temp_dir().join(format!("runout-basal-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let run = Command::new(env!("CARGO_BIN_EXE_runout"))
        .args([
            "run",
            "--fidelity",
            "smoke",
            "--end-time",
            "1.0",
            "--quiet",
            "--out",
        ])
        .arg(&dir)
        .arg(root.join("cases/gas/fluidised-bed.ron"))
        .output()
        .expect("runout runs");
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let csv = dir.join("basal.csv");
    let post = Command::new(env!("CARGO_BIN_EXE_runout"))
        .arg("post")
        .arg(&dir)
        .arg("--basal-load")
        .arg(&csv)
        .output()
        .expect("runout post runs");
    assert!(
        post.status.success(),
        "{}",
        String::from_utf8_lossy(&post.stderr)
    );
    let metrics: serde_json::Value = serde_json::from_slice(&post.stdout).expect("JSON");
    let flow = metrics["basal_load"].as_array().expect("basal_load");
    let at = |from: f64, to: f64| {
        flow.iter()
            .filter(move |f| (from..=to).contains(&f["time"].as_f64().unwrap()))
            .map(|f| {
                (
                    f["gas_share"].as_f64().unwrap(),
                    f["solids_share"].as_f64().unwrap(),
                )
            })
    };
    for (gas, solids) in at(0.15, 0.2) {
        assert!(
            gas.abs() < 0.03 && (solids - 1.0).abs() < 0.03,
            "{gas} {solids}"
        );
    }
    let fluidised: Vec<(f64, f64)> = at(0.4, 1.0).collect();
    let mean_gas = fluidised.iter().map(|s| s.0).sum::<f64>() / fluidised.len() as f64;
    assert!((mean_gas - 1.0).abs() < 0.05, "{mean_gas}");
    assert!(fluidised.iter().all(|s| s.1 < 0.01), "{fluidised:?}");
    let text = std::fs::read_to_string(&csv).unwrap();
    assert!(text.starts_with("t,x,load,gas_share,solids_share\n"));
    // every snapshot lists the box's 5 columns
    assert_eq!(text.lines().count() - 1, 5 * flow.len());
    std::fs::remove_dir_all(&dir).unwrap();
}
