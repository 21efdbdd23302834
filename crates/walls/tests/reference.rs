//! Wall coefficients against independently computed reference values.
//!
//! `reference/generate.py` implements docs/model.md §2.2, §2.4.2, §2.6 (wall Wen–Yu) and
//! §3.5–3.8 directly from the spec text in plain Python and writes `reference/values.json`:
//! the JJ (φ = 1, 0.1, 0.01), revisited-JJ and Jenkins momentum and θ coefficients at dense
//! sliding, kinetic, near-packing (dilating and compacting), zero-slip, negative-θ, air-cushion
//! and dilute-skip states, and Li–Benyahia's k, φ₀, r* and φ(r). Every value is compared at a
//! relative tolerance of 1e-12.

use runout_closures::{ClosureParams, FrictionParams, Gas, Particles};
use runout_walls::{LiBenyahia, MomentumWallState, SolidsWallModel, ThetaWallState};
use serde_json::Value;

const REL_TOL: f64 = 1e-12;

fn values() -> Value {
    serde_json::from_str(include_str!("reference/values.json")).expect("values.json parses")
}

fn num(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing in {v}"))
}

/// |a − b| ≤ tol · max(|a|, |b|); exact zeros must match exactly.
fn assert_rel(what: &str, got: f64, want: f64) {
    let scale = got.abs().max(want.abs());
    assert!(
        (got - want).abs() <= REL_TOL * scale,
        "{what}: got {got:e}, reference {want:e}, rel. error {:e}",
        (got - want).abs() / scale
    );
}

struct Setup {
    params: ClosureParams,
    wall_restitution: f64,
    wall_friction_angle: f64,
}

fn setup(v: &Value) -> Setup {
    let p = &v["parameters"];
    Setup {
        params: ClosureParams {
            particles: Particles {
                diameter: num(p, "d_p"),
                density: num(p, "rho_s"),
                restitution: num(p, "e"),
            },
            gas: Gas {
                density: num(p, "rho_g"),
                viscosity: num(p, "mu_g"),
            },
            friction: FrictionParams::new(
                num(p, "eps_s_max"),
                num(p, "eps_s_min"),
                num(p, "phi_internal_deg"),
            ),
            ..ClosureParams::default()
        },
        wall_restitution: num(p, "wall_restitution"),
        wall_friction_angle: num(p, "wall_friction_angle_deg"),
    }
}

fn model(s: &Setup, row: &Value) -> SolidsWallModel {
    let (e_w, angle) = (s.wall_restitution, s.wall_friction_angle);
    match row["model"].as_str().unwrap() {
        "jj" => SolidsWallModel::johnson_jackson(num(row, "specularity"), e_w, angle, 0.0),
        "rjj" => SolidsWallModel::revisited_johnson_jackson(e_w, angle, None, 0.0),
        "jenkins" => SolidsWallModel::jenkins(e_w, angle, 0.0),
        other => panic!("unknown model {other}"),
    }
    .unwrap()
}

fn label(row: &Value) -> String {
    format!(
        "{} {} phi={}",
        row["state"], row["model"], row["specularity"]
    )
}

#[test]
fn momentum_coefficients_match_reference() {
    let v = values();
    let s = setup(&v);
    let rows = v["momentum"].as_array().unwrap();
    assert!(rows.len() >= 40);
    for row in rows {
        let state = MomentumWallState {
            eps_s_fluid: num(row, "eps_s_fluid"),
            eps_s: num(row, "eps_s"),
            theta: num(row, "theta"),
            slip: num(row, "slip"),
            gas_slip: num(row, "gas_slip"),
            tr_d: num(row, "tr_d"),
            s_ddot_s: num(row, "s_ddot_s"),
            s_nn: num(row, "s_nn"),
            extra_normal_load: 0.0,
        };
        let got = model(&s, row).momentum(&state, &s.params);
        let want = &row["result"];
        let at = |f: &str| format!("{f} at {}", label(row));
        let d = got.diagnostics;
        assert_rel(&at("h_u"), d.h_u, num(want, "h"));
        assert_rel(&at("face.h"), got.face.h, num(want, "h"));
        assert_eq!(got.face.g, 1.0, "{}", at("g"));
        assert_eq!(got.face.c, 0.0, "{}", at("c = h U_w with U_w = 0"));
        assert_rel(&at("COL"), d.col, num(want, "col"));
        assert_rel(&at("FRI"), d.fri, num(want, "fri"));
        assert_rel(&at("mu_k"), d.mu_kin, num(want, "mu_k"));
        assert_rel(&at("mu_f"), d.mu_fric, num(want, "mu_f"));
        match want["phi"].as_f64() {
            Some(phi) => assert_rel(&at("phi"), d.specularity.unwrap(), phi),
            None => assert!(d.specularity.is_none(), "{}", at("phi")),
        }
    }
}

#[test]
fn theta_coefficients_match_reference() {
    let v = values();
    let s = setup(&v);
    let rows = v["theta"].as_array().unwrap();
    assert!(rows.len() >= 25);
    for row in rows {
        let state = ThetaWallState {
            eps_s: num(row, "eps_s"),
            theta: num(row, "theta"),
            slip: num(row, "slip"),
            gas_slip: num(row, "gas_slip"),
        };
        let got = model(&s, row).granular_temperature(&state, &s.params);
        let want = &row["result"];
        let at = |f: &str| format!("{f} at {}", label(row));
        assert_rel(&at("g = kappa"), got.face.g, num(want, "g"));
        assert_rel(&at("h_theta"), got.face.h, num(want, "h"));
        assert_rel(&at("c_theta"), got.face.c, num(want, "c"));
        match want["phi"].as_f64() {
            Some(phi) => assert_rel(&at("phi"), got.diagnostics.specularity.unwrap(), phi),
            None => assert!(got.diagnostics.specularity.is_none(), "{}", at("phi")),
        }
    }
}

#[test]
fn li_benyahia_matches_reference() {
    let v = values();
    let s = setup(&v);
    let lb = &v["li_benyahia"];
    let law = LiBenyahia::new(
        s.wall_restitution,
        s.wall_friction_angle.to_radians().tan(),
        None,
    )
    .unwrap();
    assert_rel("k", law.k, num(lb, "k"));
    assert_rel("phi0", law.phi0, num(lb, "phi0"));
    assert_rel("r*", law.switch_ratio(), num(lb, "r_switch"));
    for row in lb["table"].as_array().unwrap() {
        let r = num(row, "r");
        assert_rel(&format!("phi({r})"), law.specularity(r), num(row, "phi"));
    }
}
