//! μ(I) against independently computed reference values.
//!
//! `reference/generate_mu_i.py` writes the law μ(I), dμ/dI and the frictional stress from the
//! equations of docs/model.md §2.4.4 in other algebraic forms (μ_s + Δμ/(I_0/I + 1); the shear
//! rate from a velocity gradient; P_c written with εg), into `reference/mu_i_values.json`;
//! every value is compared here at a relative tolerance of 1e-12. The larger-of join of the
//! kinetic and μ(I) viscosities (docs/model.md §2.4.4) against (μ_kin⁴ + μ_fric⁴)^(1/4)
//! written as the larger times (1 + q⁴)^(1/4) with q⁴ in exact fractions.

use runout_closures::friction::FrictionParams;
use runout_closures::{KineticJoin, MuIConstants};
use serde_json::Value;

const REL_TOL: f64 = 1e-12;

fn num(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing in {v}"))
}

fn assert_rel(what: &str, got: f64, want: f64) {
    let scale = got.abs().max(want.abs());
    assert!(
        (got - want).abs() <= REL_TOL * scale,
        "{what}: got {got:e}, reference {want:e}"
    );
}

#[test]
fn mu_i_matches_the_independent_reference() {
    let v: Value = serde_json::from_str(include_str!("reference/mu_i_values.json")).unwrap();
    let p = &v["parameters"];
    let law = MuIConstants {
        mu_s: num(p, "mu_s"),
        mu_2: num(p, "mu_2"),
        i_0: num(p, "i_0"),
        shear_rate_floor: num(p, "shear_rate_floor"),
    };
    assert_rel("mu_s", law.mu_s, MuIConstants::glass_beads_jop_2005().mu_s);
    assert_rel("mu_2", law.mu_2, MuIConstants::glass_beads_jop_2005().mu_2);
    let friction = FrictionParams {
        eps_s_max: num(p, "eps_s_max"),
        eps_s_min: num(p, "eps_s_min"),
        sin_phi: 0.5, // not used by μ(I)
    };
    let (d_p, rho_s) = (num(p, "d_p"), num(p, "rho_s"));
    let rows = v["law"].as_array().unwrap();
    for row in rows {
        let i = num(row, "i");
        assert_rel(
            &format!("mu({i})"),
            law.friction_coefficient(i),
            num(row, "mu"),
        );
        assert_rel(
            &format!("dmu/dI({i})"),
            law.dfriction_coefficient_di(i),
            num(row, "dmu_di"),
        );
    }
    let rows = v["stress"].as_array().unwrap();
    assert_eq!(rows.len(), 105);
    for row in rows {
        let (eps_s, s_ddot_s, p_kin) = (num(row, "eps_s"), num(row, "s_ddot_s"), num(row, "p_kin"));
        let s = law.stress(eps_s, d_p, rho_s, s_ddot_s, p_kin, &friction);
        let at = format!("eps_s = {eps_s}, S:S = {s_ddot_s}, P_kin = {p_kin}");
        assert_rel(&format!("P_fric at {at}"), s.p_fric, num(row, "p_fric"));
        assert_rel(&format!("mu_fric at {at}"), s.mu_fric, num(row, "mu_fric"));
        assert_rel(
            &format!("I at {at}"),
            s.inertial_number,
            num(row, "inertial_number"),
        );
    }
}

#[test]
fn the_larger_of_join_matches_the_independent_reference() {
    let v: Value = serde_json::from_str(include_str!("reference/mu_i_values.json")).unwrap();
    let rows = v["join"].as_array().unwrap();
    assert_eq!(rows.len(), 36);
    for row in rows {
        let (mu_kin, mu_fric) = (num(row, "mu_kin"), num(row, "mu_fric"));
        let joined = KineticJoin::LargerOf.viscosity(mu_kin, mu_fric);
        assert_rel(
            &format!("join({mu_kin}, {mu_fric})"),
            joined,
            num(row, "mu_s"),
        );
        let w = KineticJoin::LargerOf.weight(mu_kin, mu_fric);
        assert!((0.0..=1.0).contains(&w), "w = {w}");
    }
    // MFIX's sum is the sum, bit for bit
    assert_eq!(KineticJoin::Sum.viscosity(0.3, 0.7), 0.3 + 0.7);
}
