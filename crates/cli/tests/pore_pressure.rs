//! `runout pore-pressure` end to end (issue 60 item 5): its numbers against Ergun's closed
//! forms written here, and its refusals naming the option.

use std::process::{Command, Output};

fn runout(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_runout"))
        .args(args)
        .output()
        .expect("runout runs")
}

fn json(args: &[&str]) -> serde_json::Value {
    let o = runout(args);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    serde_json::from_slice(&o.stdout).expect("JSON")
}

const BEADS: [&str; 10] = [
    "--diameter",
    "8e-5",
    "--density",
    "2500",
    "--gas-density",
    "1.2041",
    "--drag",
    "gidaspow",
    "--eps-s",
    "0.58",
];

/// Gidaspow's dense branch is Ergun's: β = 150 εs² μ/(εg d²) at rest, so a rigid bed in air
/// has D = P εg/β, t½ = 0.19673 H²/D, and U_mf solves Ergun's quadratic.
#[test]
fn the_fine_beads_time_scales_follow_ergun() {
    let mut args = vec![
        "pore-pressure",
        "--heights",
        "0.03,0.3",
        "--dilated-eps-s",
        "0.5",
    ];
    args.extend(BEADS);
    let v = json(&args);
    let (p, eg, es, d, mu) = (101_325.0, 0.42_f64, 0.58_f64, 8e-5_f64, 1.8e-5);
    let beta = 150.0 * es * es * mu / (eg * d * d);
    let rigid = v["diffusivity"]["rigid"].as_f64().unwrap();
    assert!((rigid / (p * eg / beta) - 1.0).abs() < 1e-9, "{rigid}");
    let h = &v["heights"];
    for (k, height) in [0.03, 0.3].into_iter().enumerate() {
        let t = h[k]["half_time_rigid"].as_f64().unwrap();
        assert!((t / (0.19673 * height * height / rigid) - 1.0).abs() < 1e-12);
        let slower = h[k]["half_time_consolidating"].as_f64().unwrap();
        assert!(slower > t, "the bed's compaction stores gas too");
        assert!(h[k]["settling_time"].as_f64().unwrap() > 0.0);
    }
    let (a, b, c) = (
        1.75 * 1.2041 / (eg.powi(3) * d),
        150.0 * mu * es / (eg.powi(3) * d * d),
        -(2500.0 - 1.2041) * 9.81,
    );
    let ergun = (-b + (b * b - 4.0 * a * c).sqrt()) / (2.0 * a);
    let u_mf = v["bed"]["u_mf"].as_f64().unwrap();
    assert!((u_mf / ergun - 1.0).abs() < 1e-9, "{u_mf} {ergun}");
}

/// A gas of constant density stores nothing: a rigid bed has no time scale (null), a
/// consolidating one only its compaction's.
#[test]
fn a_constant_density_gas_leaves_only_the_compaction() {
    let mut args = vec!["pore-pressure", "--heights", "0.1", "--constant-density"];
    args.extend(BEADS);
    let v = json(&args);
    assert!(v["diffusivity"]["rigid"].is_null());
    assert!(v["diffusivity"]["consolidating"].as_f64().unwrap() > 0.0);
    assert_eq!(v["bed"]["gas_storage"].as_f64(), Some(0.0));
}

#[test]
fn bad_options_are_refused_by_name() {
    for (bad, named) in [
        (["--eps-s", "0.7", "--heights", "0.1"], "--eps-s"),
        (["--eps-s", "0.58", "--heights", "-1"], "--heights"),
        (["--eps-s", "0.58", "--heights", "0,1"], "--heights"),
    ] {
        let mut args = vec!["pore-pressure"];
        args.extend(bad);
        let o = runout(&args);
        assert!(!o.status.success());
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains(named), "{err}");
    }
    let o = runout(&[
        "pore-pressure",
        "--eps-s",
        "0.58",
        "--heights",
        "0.1",
        "--dilated-eps-s",
        "0.6",
    ]);
    assert!(String::from_utf8_lossy(&o.stderr).contains("--dilated-eps-s"));
}
