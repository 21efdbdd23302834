//! Property tests of the closures (issue 3 (b); style A6.10a).

use proptest::prelude::*;
use runout_closures::drag::Drag;
use runout_closures::friction::{FrictionParams, PrincetonConstants, SchaefferConstants};
use runout_closures::kinetic::{lun_1984, GasCoupling, SolidsState};
use runout_closures::radial::{
    dg0_deps_carnahan_starling, dg0_deps_ma_ahmadi, g0_carnahan_starling, g0_ma_ahmadi,
    RadialDistribution, MA_AHMADI_EPS_LIMIT,
};
use runout_closures::{evaluate, CellState, ClosureParams, FrictionModel, Gas, Particles};

/// The frictional models' code constants (MFIX 21.3.2).
const PRINCETON: PrincetonConstants = PrincetonConstants::MFIX;
const SCHAEFFER: SchaefferConstants = SchaefferConstants::MFIX;

/// Relative tolerance of analytic derivatives against central differences (issue 3 (b)).
const FD_REL_TOL: f64 = 1e-6;

/// Central difference (f(x + h) − f(x − h))/(2h).
fn central_difference(f: impl Fn(f64) -> f64, x: f64, h: f64) -> f64 {
    (f(x + h) - f(x - h)) / (2.0 * h)
}

fn assert_derivative(what: &str, analytic: f64, fd: f64) {
    let scale = analytic.abs().max(fd.abs());
    assert!(
        (analytic - fd).abs() <= FD_REL_TOL * scale,
        "{what}: analytic {analytic:e}, central difference {fd:e}"
    );
}

fn solids(eps_s: f64, theta: f64, particles: &Particles) -> SolidsState {
    SolidsState {
        eps_s,
        theta,
        rho_s: particles.density,
        d_p: particles.diameter,
        restitution: particles.restitution,
        g0: g0_carnahan_starling(eps_s),
    }
}

fn radial() -> impl Strategy<Value = RadialDistribution> {
    prop_oneof![
        Just(RadialDistribution::CarnahanStarling),
        Just(RadialDistribution::MaAhmadi)
    ]
}

fn friction_model() -> impl Strategy<Value = FrictionModel> {
    prop_oneof![
        Just(FrictionModel::None),
        Just(FrictionModel::schaeffer()),
        Just(FrictionModel::princeton()),
        Just(FrictionModel::MuI(
            runout_closures::MuIConstants::glass_beads_jop_2005()
        ))
    ]
}

fn drag() -> impl Strategy<Value = Drag> {
    prop_oneof![
        Just(Drag::default()),
        Just(Drag::Gidaspow),
        Just(Drag::GidaspowBlend),
        Just(Drag::WenYu)
    ]
}

/// Particle and friction parameters spanning the paper's ranges (paper Table 3).
fn params() -> impl Strategy<Value = ClosureParams> {
    (
        prop_oneof![Just(1e-4), Just(5e-4), Just(1e-3)],
        1000.0..3000.0f64,
        0.5..1.0f64,
        prop_oneof![Just(0.0), Just(1.2)],
        25.0..45.0f64,
        radial(),
        friction_model(),
        drag(),
    )
        .prop_map(
            |(diameter, density, restitution, rho_g, phi, radial, friction_model, drag)| {
                ClosureParams {
                    particles: Particles {
                        diameter,
                        density,
                        restitution,
                    },
                    gas: Gas {
                        density: rho_g,
                        viscosity: 1.8e-5,
                    },
                    friction: FrictionParams::new(0.65, 0.5, phi),
                    radial,
                    friction_model,
                    drag,
                }
            },
        )
}

/// Cell states with εs ∈ [0, εs,max], θ ∈ [0, 100] (both ends included), any tr D, S:S, slip.
fn cell_state(eps_s_max: f64) -> impl Strategy<Value = CellState> {
    (
        prop_oneof![Just(0.0), Just(eps_s_max), 0.0..=eps_s_max],
        prop_oneof![Just(0.0), Just(100.0), 0.0..=100.0f64, 0.0..1e-6f64],
        prop_oneof![Just(0.0), 0.0..100.0f64],
        prop_oneof![Just(0.0), -100.0..100.0f64],
        // S:S ≥ 0 in exact arithmetic; −1e-13 stands for round-off of tr(D²) − (tr D)²/3
        prop_oneof![Just(0.0), Just(-1e-13), 0.0..1e4f64],
    )
        .prop_map(|(eps_s, theta, slip, tr_d, s_ddot_s)| CellState {
            eps_s,
            theta,
            slip,
            tr_d,
            s_ddot_s,
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// g0 ≥ 1 and increasing in εs (CS strictly below εs = 1, Ma–Ahmadi up to its clip).
    #[test]
    fn g0_at_least_one_and_increasing(a in 0.0..0.99f64, b in 0.0..0.99f64) {
        let (lo, hi) = if a < b { (a, b) } else { (b, a) };
        prop_assume!(hi > lo);
        prop_assert!(g0_carnahan_starling(lo) >= 1.0);
        prop_assert!(g0_carnahan_starling(hi) > g0_carnahan_starling(lo));
        prop_assert!(g0_ma_ahmadi(lo) >= 1.0);
        prop_assert!(g0_ma_ahmadi(hi) >= g0_ma_ahmadi(lo));
        if hi <= MA_AHMADI_EPS_LIMIT {
            prop_assert!(g0_ma_ahmadi(hi) > g0_ma_ahmadi(lo));
        }
    }

    /// g0 → 1 as εs → 0: g0(0) = 1 and g0 = 1 + 2.5 εs + O(εs²) (both models).
    #[test]
    fn g0_tends_to_one_in_the_dilute_limit(eps_s in 0.0..1e-2f64) {
        for g0 in [g0_carnahan_starling, g0_ma_ahmadi] {
            prop_assert_eq!(g0(0.0), 1.0);
            let second_order = (g0(eps_s) - 1.0 - 2.5 * eps_s).abs();
            prop_assert!(second_order <= 10.0 * eps_s * eps_s, "remainder {second_order:e}");
        }
    }

    /// Analytic dg0/dεs = central difference (CS on [0, 0.95], Ma–Ahmadi away from its clip).
    #[test]
    fn g0_derivatives_match_central_differences(eps_s in 1e-3..0.95f64) {
        let h = 1e-6;
        assert_derivative(
            "dg0/deps CS",
            dg0_deps_carnahan_starling(eps_s),
            central_difference(g0_carnahan_starling, eps_s, h),
        );
        let ma = eps_s * 0.64 / 0.95;
        assert_derivative(
            "dg0/deps Ma-Ahmadi",
            dg0_deps_ma_ahmadi(ma),
            central_difference(g0_ma_ahmadi, ma, h),
        );
    }

    /// dP_c/dεs, dP*/dεs and K_cp = dP_fric/dεs equal central differences away from the
    /// kinks at εs,min, εs,max − δ and εs,max; the step is a small fraction of the distance.
    #[test]
    fn friction_derivatives_match_central_differences(
        eps_s in 0.501..0.70f64,
        theta in 1e-6..10.0f64,
        tr_d in -50.0..50.0f64,
        s_ddot_s in 0.0..100.0f64,
        phi in 25.0..45.0f64,
    ) {
        let p = FrictionParams::new(0.65, 0.5, phi);
        let d_p = 5e-4;
        let at = p.eps_s_max - PRINCETON.delta;
        let kink_distance = (eps_s - p.eps_s_min).abs().min((eps_s - at).abs());
        prop_assume!(kink_distance > 1e-4);
        let h = 1e-4 * kink_distance;
        assert_derivative(
            "dP_c/deps",
            PRINCETON.dcritical_pressure_deps(eps_s, &p),
            central_difference(|x| PRINCETON.critical_pressure(x, &p), eps_s, h),
        );
        let p_fric = |x| PRINCETON.stress(x, theta, d_p, tr_d, s_ddot_s, &p).p_fric;
        assert_derivative(
            "K_cp Princeton",
            PRINCETON.k_cp(eps_s, theta, d_p, tr_d, s_ddot_s, &p),
            central_difference(p_fric, eps_s, h),
        );
        let above_packing = eps_s - p.eps_s_max;
        if above_packing > 1e-4 {
            let h = 1e-4 * above_packing;
            assert_derivative(
                "dP*/deps",
                SCHAEFFER.dp_star_deps(eps_s, &p),
                central_difference(|x| SCHAEFFER.p_star(x, &p), eps_s, h),
            );
        }
    }

    /// P_kin, μ₀, μ_b, μ*, μ_kin, κ_s and γ ≥ 0 for θ ≥ 0; frictional P and μ ≥ 0; summed
    /// P_s, μ_s ≥ 0; K_cp ≥ 0 (εs ∈ [0, εs,max], θ ∈ [0, 100]).
    #[test]
    fn pressures_viscosities_conductivity_nonnegative(state in cell_state(0.65), params in params()) {
        let set = evaluate(&state, &params);
        let k = set.kinetic;
        for (name, value) in [
            ("p_kin", k.p_kin), ("mu_dilute", k.mu_dilute), ("mu_bulk", k.mu_bulk),
            ("mu_star", k.mu_star), ("mu_kin", k.mu_kin), ("kappa_dilute", k.kappa_dilute),
            ("kappa_star", k.kappa_star), ("kappa_kin", k.kappa_kin), ("dissipation", k.dissipation),
            ("p_fric", set.friction.p_fric), ("mu_fric", set.friction.mu_fric),
            ("p_star", set.friction.p_star), ("p_s", set.stress.p_s), ("mu_s", set.stress.mu_s),
            ("k_cp", set.k_cp), ("f_gs", set.f_gs), ("j_vis", set.j_vis), ("j_slip", set.j_slip),
        ] {
            prop_assert!(value >= 0.0, "{} = {:e} at {:?}, {:?}", name, value, state, params);
        }
    }

    /// No frictional pressure, viscosity or K_cp at or below εs,min (Princeton; μ(I) without
    /// kinetic pressure) or at or below εs,max (Schaeffer).
    #[test]
    fn no_friction_below_eps_s_min(
        eps_s in 0.0..=0.5f64,
        theta in 0.0..100.0f64,
        tr_d in -100.0..100.0f64,
        s_ddot_s in 0.0..1e4f64,
        model in friction_model(),
    ) {
        let p = FrictionParams::default();
        let f = model.stress(eps_s, theta, 5e-4, 2000.0, tr_d, s_ddot_s, 0.0, &p);
        prop_assert_eq!((f.p_fric, f.mu_fric, f.lambda_fric, f.p_star), (0.0, 0.0, 0.0, 0.0));
        prop_assert_eq!(model.k_cp(eps_s, theta, 5e-4, tr_d, s_ddot_s, &p), 0.0);
        prop_assert_eq!(PRINCETON.critical_pressure(eps_s, &p), 0.0);
    }

    /// Princeton is continuous across the linearisation point εs,max − δ: P_c, dP_c/dεs,
    /// P_fric and μ_fric change by O(h) over [at − h, at + h].
    #[test]
    fn princeton_continuous_across_linearisation(
        h in 1e-12..1e-9f64,
        theta in 1e-6..10.0f64,
        tr_d in -50.0..50.0f64,
        s_ddot_s in 0.0..100.0f64,
    ) {
        let p = FrictionParams::default();
        let at = p.eps_s_max - PRINCETON.delta;
        // relative change allowed: slope · 2h / value, with the slope of P_c at εs,at
        let allowed = 1e-5;
        let pairs = [
            (PRINCETON.critical_pressure(at - h, &p), PRINCETON.critical_pressure(at + h, &p)),
            (PRINCETON.dcritical_pressure_deps(at - h, &p), PRINCETON.dcritical_pressure_deps(at + h, &p)),
            (
                PRINCETON.stress(at - h, theta, 5e-4, tr_d, s_ddot_s, &p).p_fric,
                PRINCETON.stress(at + h, theta, 5e-4, tr_d, s_ddot_s, &p).p_fric,
            ),
            (
                PRINCETON.stress(at - h, theta, 5e-4, tr_d, s_ddot_s, &p).mu_fric,
                PRINCETON.stress(at + h, theta, 5e-4, tr_d, s_ddot_s, &p).mu_fric,
            ),
        ];
        for (below, above) in pairs {
            let scale = below.abs().max(above.abs());
            prop_assert!((above - below).abs() <= allowed * scale, "{below:e} vs {above:e}");
        }
    }

    /// No NaN or infinity anywhere in the closure set for εs ∈ [0, εs,max], θ ∈ [0, 100],
    /// every model choice, with and without gas.
    #[test]
    fn closure_set_is_finite(state in cell_state(0.65), params in params()) {
        let set = evaluate(&state, &params);
        // serde_json writes non-finite floats as null: every leaf must stay a number
        let json = serde_json::to_value(set).unwrap();
        let mut stack = vec![("set".to_string(), &json)];
        while let Some((path, value)) = stack.pop() {
            match value {
                serde_json::Value::Object(map) => {
                    stack.extend(map.iter().map(|(k, v)| (format!("{path}.{k}"), v)));
                }
                // numbers, and the unit enum tags (the kinetic join)
                serde_json::Value::Number(_) | serde_json::Value::String(_) => {}
                other => prop_assert!(false, "{} = {} at {:?}, {:?}", path, other, state, params),
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// The K_cp of the closure set (from the Princeton P_f/P_c already computed) equals the
    /// stand-alone MFIX CALC_K_CP form, including its cap with N_Pf, to 1e-13 relative (the
    /// two paths round differently: a 1-ulp difference was seen at εs = 0.5525).
    #[test]
    fn k_cp_shortcut_equals_calc_k_cp(state in cell_state(0.7), phi in 25.0..45.0f64) {
        let params = ClosureParams {
            friction: FrictionParams::new(0.65, 0.5, phi),
            ..ClosureParams::default()
        };
        let set = evaluate(&state, &params);
        let direct = PRINCETON.k_cp(
            state.eps_s, state.theta, params.particles.diameter, state.tr_d, state.s_ddot_s,
            &params.friction,
        );
        // the same formula along two code paths: equal up to the last bits of rounding
        prop_assert!(
            (set.k_cp - direct).abs() <= 1e-13 * direct.abs().max(f64::MIN_POSITIVE),
            "{} vs {}", set.k_cp, direct
        );
    }
}

/// Dry and gas-coupled KT agree when the drag vanishes; the gas correction only lowers μ*, κ*.
#[test]
fn gas_correction_lowers_dilute_coefficients() {
    let particles = Particles::default();
    for (eps_s, theta) in [(0.01, 0.5), (0.3, 0.5), (0.6, 0.01), (0.649, 1e-4)] {
        let s = solids(eps_s, theta, &particles);
        let dry = lun_1984(&s, GasCoupling::Dry);
        assert_eq!(lun_1984(&s, GasCoupling::Drag(0.0)), dry);
        let wet = lun_1984(&s, GasCoupling::Drag(1e4));
        assert!(wet.mu_star < dry.mu_star && wet.kappa_star < dry.kappa_star);
        assert!(wet.mu_kin < dry.mu_kin && wet.kappa_kin < dry.kappa_kin);
        assert_eq!(wet.p_kin, dry.p_kin);
    }
}

/// Model choices are read from case files: unknown fields are rejected.
#[test]
fn model_enums_deserialize_strictly() {
    let drag: Drag = serde_json::from_str(r#"{"SyamlalOBrien":{"c1":0.8,"d1":2.65}}"#).unwrap();
    assert_eq!(drag, Drag::default());
    assert!(
        serde_json::from_str::<Drag>(r#"{"SyamlalOBrien":{"c1":0.8,"d1":2.65,"e1":1}}"#).is_err()
    );
    let model: FrictionModel = serde_json::from_str(r#""Princeton""#).unwrap();
    assert_eq!(model, FrictionModel::princeton());
    assert!(serde_json::from_str::<FrictionModel>(r#""Srivastava""#).is_err());
    let rdf: RadialDistribution = serde_json::from_str(r#""MaAhmadi""#).unwrap();
    assert_eq!(rdf, RadialDistribution::MaAhmadi);
}
