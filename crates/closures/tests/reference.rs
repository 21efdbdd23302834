//! Closures against independently computed reference values.
//!
//! `reference/generate.py` implements docs/model.md §1.3 and §2 directly from the spec text in
//! plain Python and writes `reference/values.json`; every closure is compared here at a
//! relative tolerance of 1e-12, at dilute (εs = 0.01), intermediate, dense (εs = 0.6) and
//! near-packing (0.645, 0.649) states. The model spec's own printed check values (§2.2,
//! §2.4.2) are checked to their printed precision in `spec_check_values_*`.

use runout_closures::drag::{
    dga_gidaspow, dga_gidaspow_blend, dga_single_particle, dga_syamlal_obrien, dga_wall_wen_yu,
    dga_wen_yu, Drag, DragInputs,
};
use runout_closures::energy::{shear_production, slip_production, viscous_damping};
use runout_closures::friction::{FrictionParams, PrincetonConstants, SchaefferConstants};
use runout_closures::kinetic::{lun_1984, GasCoupling, SolidsState};
use runout_closures::radial::{
    dg0_deps_carnahan_starling, dg0_deps_ma_ahmadi, g0_carnahan_starling, g0_ma_ahmadi,
};
use runout_closures::{evaluate, CellState, ClosureParams, FrictionModel, Gas, Particles};
use serde_json::Value;

/// The frictional models' code constants (MFIX 21.3.2).
const PRINCETON: PrincetonConstants = PrincetonConstants::MFIX;
const SCHAEFFER: SchaefferConstants = SchaefferConstants::MFIX;

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
fn assert_rel(what: &str, got: f64, want: f64, tol: f64) {
    let scale = got.abs().max(want.abs());
    assert!(
        (got - want).abs() <= tol * scale,
        "{what}: got {got:e}, reference {want:e}, rel. error {:e}",
        (got - want).abs() / scale
    );
}

struct Params {
    d_p: f64,
    rho_s: f64,
    e: f64,
    rho_g: f64,
    mu_g: f64,
    friction: FrictionParams,
}

fn params(v: &Value) -> Params {
    let p = &v["parameters"];
    Params {
        d_p: num(p, "d_p"),
        rho_s: num(p, "rho_s"),
        e: num(p, "e"),
        rho_g: num(p, "rho_g"),
        mu_g: num(p, "mu_g"),
        friction: FrictionParams::new(
            num(p, "eps_s_max"),
            num(p, "eps_s_min"),
            num(p, "phi_internal_deg"),
        ),
    }
}

#[test]
fn radial_distribution_matches_reference() {
    let v = values();
    let rows = v["radial"].as_array().unwrap();
    assert!(rows.len() >= 3);
    for row in rows {
        let eps_s = num(row, "eps_s");
        let at = |f: &str| format!("{f} at eps_s = {eps_s}");
        assert_rel(
            &at("g0 CS"),
            g0_carnahan_starling(eps_s),
            num(row, "g0_cs"),
            REL_TOL,
        );
        assert_rel(
            &at("dg0 CS"),
            dg0_deps_carnahan_starling(eps_s),
            num(row, "dg0_cs"),
            REL_TOL,
        );
        assert_rel(
            &at("g0 MA"),
            g0_ma_ahmadi(eps_s),
            num(row, "g0_ma"),
            REL_TOL,
        );
        assert_rel(
            &at("dg0 MA"),
            dg0_deps_ma_ahmadi(eps_s),
            num(row, "dg0_ma"),
            REL_TOL,
        );
    }
}

#[test]
fn kinetic_theory_matches_reference() {
    let v = values();
    let p = params(&v);
    let rows = v["kinetic"].as_array().unwrap();
    assert!(rows.len() >= 6);
    for row in rows {
        let s = SolidsState {
            eps_s: num(row, "eps_s"),
            theta: num(row, "theta"),
            rho_s: p.rho_s,
            d_p: p.d_p,
            restitution: p.e,
            g0: num(row, "g0"),
        };
        let gas = match row["dga"].as_f64() {
            None => GasCoupling::Dry,
            Some(dga) => GasCoupling::Drag(dga),
        };
        let k = lun_1984(&s, gas);
        let label = format!("eps_s = {}, theta = {}, {gas:?}", s.eps_s, s.theta);
        for (name, got) in [
            ("p_kin", k.p_kin),
            ("mu_dilute", k.mu_dilute),
            ("mu_bulk", k.mu_bulk),
            ("mu_star", k.mu_star),
            ("mu_kin", k.mu_kin),
            ("lambda_kin", k.lambda_kin),
            ("kappa_dilute", k.kappa_dilute),
            ("kappa_star", k.kappa_star),
            ("kappa_kin", k.kappa_kin),
            ("dissipation", k.dissipation),
        ] {
            assert_rel(&format!("{name} ({label})"), got, num(row, name), REL_TOL);
        }
    }
}

#[test]
fn princeton_matches_reference() {
    let v = values();
    let p = params(&v);
    let rows = v["princeton"].as_array().unwrap();
    for row in rows {
        let (eps_s, theta, tr_d, s_ddot_s) = (
            num(row, "eps_s"),
            num(row, "theta"),
            num(row, "tr_d"),
            num(row, "s_ddot_s"),
        );
        let f = PRINCETON.stress(eps_s, theta, p.d_p, tr_d, s_ddot_s, &p.friction);
        let label = format!("eps_s = {eps_s}, theta = {theta}, trD = {tr_d}, S:S = {s_ddot_s}");
        for (name, got) in [
            ("p_c", f.p_c),
            ("n", f.n),
            ("zeta", f.zeta),
            ("pf_over_pc", f.pf_over_pc),
            ("p_fric", f.p_fric),
            ("mu_fric", f.mu_fric),
            ("lambda_fric", f.lambda_fric),
        ] {
            assert_rel(&format!("{name} ({label})"), got, num(row, name), REL_TOL);
        }
        let k_cp = PRINCETON.k_cp(eps_s, theta, p.d_p, tr_d, s_ddot_s, &p.friction);
        assert_rel(&format!("k_cp ({label})"), k_cp, num(row, "k_cp"), REL_TOL);
    }
    for row in v["critical_pressure"].as_array().unwrap() {
        let eps_s = num(row, "eps_s");
        assert_rel(
            &format!("P_c at {eps_s}"),
            PRINCETON.critical_pressure(eps_s, &p.friction),
            num(row, "p_c"),
            REL_TOL,
        );
        assert_rel(
            &format!("dP_c/deps at {eps_s}"),
            PRINCETON.dcritical_pressure_deps(eps_s, &p.friction),
            num(row, "dp_c"),
            REL_TOL,
        );
    }
}

#[test]
fn schaeffer_matches_reference() {
    let v = values();
    let p = params(&v);
    for row in v["schaeffer"].as_array().unwrap() {
        let (eps_s, s_ddot_s) = (num(row, "eps_s"), num(row, "s_ddot_s"));
        let label = format!("eps_s = {eps_s}, S:S = {s_ddot_s}");
        let f = SCHAEFFER.stress(eps_s, s_ddot_s, &p.friction);
        assert_rel(
            &format!("P* ({label})"),
            f.p_star,
            num(row, "p_star"),
            REL_TOL,
        );
        assert_rel(
            &format!("mu ({label})"),
            f.mu_fric,
            num(row, "mu_schaeffer"),
            REL_TOL,
        );
        assert_rel(
            &format!("dP*/deps ({label})"),
            SCHAEFFER.dp_star_deps(eps_s, &p.friction),
            num(row, "dp_star_deps"),
            REL_TOL,
        );
        assert_rel(
            &format!("INV_H ({label})"),
            SCHAEFFER.eps_g_from_p_star(f.p_star, &p.friction),
            num(row, "eps_g_from_p_star"),
            REL_TOL,
        );
    }
}

#[test]
fn drag_matches_reference() {
    let v = values();
    let p = params(&v);
    let rows = v["drag"].as_array().unwrap();
    for row in rows {
        let eps_s = num(row, "eps_s");
        let x = DragInputs {
            eps_g: 1.0 - eps_s,
            rho_g: p.rho_g,
            mu_g: p.mu_g,
            slip: num(row, "slip"),
            d_p: p.d_p,
        };
        let label = format!("eps_s = {eps_s}, |v| = {}", x.slip);
        for (name, got) in [
            ("syamlal_obrien", dga_syamlal_obrien(&x, 0.8, 2.65)),
            ("syamlal_obrien_custom", dga_syamlal_obrien(&x, 0.7, 3.0)),
            ("gidaspow", dga_gidaspow(&x)),
            ("gidaspow_blend", dga_gidaspow_blend(&x)),
            ("wen_yu", dga_wen_yu(&x)),
            ("wall_wen_yu", dga_wall_wen_yu(&x)),
            ("kt_dga", dga_single_particle(&x)),
        ] {
            assert_rel(&format!("{name} ({label})"), got, num(row, name), REL_TOL);
        }
        // the enum dispatches to the same laws
        assert_rel(
            "Drag::default",
            Drag::default().dga(eps_s, &x),
            num(row, "syamlal_obrien"),
            REL_TOL,
        );
        assert_rel(
            "Drag::WenYu",
            Drag::WenYu.dga(eps_s, &x),
            num(row, "wen_yu"),
            REL_TOL,
        );
    }
}

#[test]
fn energy_sources_match_reference() {
    let v = values();
    let p = params(&v);
    for row in v["energy"].as_array().unwrap() {
        let (eps_s, theta, slip) = (num(row, "eps_s"), num(row, "theta"), num(row, "slip"));
        let label = format!("eps_s = {eps_s}, theta = {theta}, |v| = {slip}");
        assert_rel(
            &format!("J_vis ({label})"),
            viscous_damping(num(row, "f_gs"), theta),
            num(row, "j_vis"),
            REL_TOL,
        );
        let j_slip = slip_production(eps_s, theta, num(row, "g0"), p.d_p, p.rho_s, p.mu_g, slip);
        assert_rel(
            &format!("J_slip ({label})"),
            j_slip,
            num(row, "j_slip"),
            REL_TOL,
        );
        let production = shear_production(
            num(row, "p_kin"),
            num(row, "mu_kin"),
            num(row, "lambda_kin"),
            num(row, "tr_d"),
            num(row, "s_ddot_s"),
        );
        assert_rel(
            &format!("Pi ({label})"),
            production,
            num(row, "production"),
            REL_TOL,
        );

        // the full closure set of a dry cell reproduces the same KT values
        let dry = ClosureParams {
            particles: Particles {
                diameter: p.d_p,
                density: p.rho_s,
                restitution: p.e,
            },
            gas: Gas {
                density: 0.0,
                viscosity: p.mu_g,
            },
            friction: p.friction,
            friction_model: FrictionModel::princeton(),
            ..ClosureParams::default()
        };
        let state = CellState {
            eps_s,
            theta,
            slip,
            tr_d: num(row, "tr_d"),
            s_ddot_s: num(row, "s_ddot_s"),
        };
        let set = evaluate(&state, &dry);
        assert_rel("set p_kin", set.kinetic.p_kin, num(row, "p_kin"), REL_TOL);
        assert_rel(
            "set mu_kin",
            set.kinetic.mu_kin,
            num(row, "mu_kin"),
            REL_TOL,
        );
        assert_rel(
            "set production",
            set.production,
            num(row, "production"),
            REL_TOL,
        );
        assert_eq!((set.f_gs, set.j_vis, set.j_slip), (0.0, 0.0, 0.0));
    }
}

/// (name, value as printed in the spec)
type Printed = &'static [(&'static str, &'static str)];

/// docs/model.md §2.2 check values (dry, ρs = 2000, d = 0.5 mm, e = 0.9), to printed precision.
#[test]
fn spec_check_values_kinetic() {
    let printed: [(f64, f64, Printed); 2] = [
        (
            0.3,
            0.5,
            &[
                ("g0", "2.47813"),
                ("p_kin", "1147.52"),
                ("mu_kin", "0.294624"),
                ("mu_bulk", "0.237272"),
                ("lambda_kin", "0.0289919"),
                ("kappa_kin", "0.869694"),
                ("dissipation", "4.05735e5"),
            ],
        ),
        (
            0.55,
            0.1,
            &[
                ("g0", "7.9561"),
                ("p_kin", "1939.11"),
                ("mu_kin", "1.00792"),
                ("kappa_kin", "2.76288"),
                ("dissipation", "3.91603e5"),
            ],
        ),
    ];
    for (eps_s, theta, checks) in printed {
        let g0 = g0_carnahan_starling(eps_s);
        let s = SolidsState {
            eps_s,
            theta,
            rho_s: 2000.0,
            d_p: 5e-4,
            restitution: 0.9,
            g0,
        };
        let k = lun_1984(&s, GasCoupling::Dry);
        for &(name, value) in checks {
            let got = match name {
                "g0" => g0,
                "p_kin" => k.p_kin,
                "mu_kin" => k.mu_kin,
                "mu_bulk" => k.mu_bulk,
                "lambda_kin" => k.lambda_kin,
                "kappa_kin" => k.kappa_kin,
                "dissipation" => k.dissipation,
                other => unreachable!("{other}"),
            };
            assert_printed(&format!("{name} at eps_s = {eps_s}"), got, value);
        }
    }
}

/// docs/model.md §2.4.2 check values (φ = 35°, d = 0.5 mm, θ = 0.01, S:S = 100 s⁻²).
#[test]
fn spec_check_values_princeton() {
    let p = FrictionParams::default();
    let f = PRINCETON.stress(0.60, 0.01, 5e-4, 0.0, 100.0, &p);
    assert_printed("P_f at 0.60", f.p_fric, "1600");
    assert_printed("mu_fric at 0.60", f.mu_fric, "3.2406");
    let f = PRINCETON.stress(0.645, 0.01, 5e-4, 0.5, 100.0, &p);
    assert_printed("P_f at 0.645", f.p_fric, "3.49636e7");
    assert_printed("mu_fric at 0.645", f.mu_fric, "7.08878e4");
    // linearisation point and slope (§2.4.2 step 2)
    let at = p.eps_s_max - PRINCETON.delta;
    assert_printed("P_c,at", PRINCETON.critical_pressure(at, &p), "9.8e6");
    assert_printed(
        "P_c'",
        PRINCETON.dcritical_pressure_deps(0.66, &p),
        "5.04e9",
    );
}

/// `got` rounds to `printed` at the number of significant digits printed in the spec:
/// |got − printed| ≤ ½ unit of the last printed digit.
fn assert_printed(what: &str, got: f64, printed: &str) {
    let value: f64 = printed.parse().expect("printed value parses");
    let mantissa = printed.split(['e', 'E']).next().unwrap();
    let digits = mantissa
        .trim_start_matches(['0', '.'])
        .chars()
        .filter(char::is_ascii_digit)
        .count() as i32;
    let last_digit = 10f64.powi(value.abs().log10().floor() as i32 - (digits - 1));
    assert!(
        (got - value).abs() <= 0.5 * last_digit,
        "{what}: {got} does not round to the printed {printed}"
    );
}

/// The full closure set with gas (Syamlal–O'Brien, single-particle drag in μ*, κ* below
/// `DIL_EP_S`) and Princeton friction, at the paper's parameters.
#[test]
fn closure_set_matches_reference() {
    let v = values();
    let p = params(&v);
    let params = ClosureParams {
        particles: Particles {
            diameter: p.d_p,
            density: p.rho_s,
            restitution: p.e,
        },
        gas: Gas {
            density: p.rho_g,
            viscosity: p.mu_g,
        },
        friction: p.friction,
        ..ClosureParams::default()
    };
    let rows = v["cell"].as_array().unwrap();
    assert!(rows.len() >= 3);
    for row in rows {
        let state = CellState {
            eps_s: num(row, "eps_s"),
            theta: num(row, "theta"),
            slip: num(row, "slip"),
            tr_d: num(row, "tr_d"),
            s_ddot_s: num(row, "s_ddot_s"),
        };
        let set = evaluate(&state, &params);
        for (name, got) in [
            ("g0", set.g0),
            ("dga", set.dga),
            ("f_gs", set.f_gs),
            ("dga_kinetic", set.dga_kinetic),
            ("mu_star", set.kinetic.mu_star),
            ("mu_kin", set.kinetic.mu_kin),
            ("kappa_kin", set.kinetic.kappa_kin),
            ("p_s", set.stress.p_s),
            ("mu_s", set.stress.mu_s),
            ("lambda_s", set.stress.lambda_s),
            ("k_cp", set.k_cp),
            ("production", set.production),
            ("j_vis", set.j_vis),
            ("j_slip", set.j_slip),
        ] {
            assert_rel(&format!("{name} ({state:?})"), got, num(row, name), REL_TOL);
        }
    }
}
