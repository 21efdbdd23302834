//! Properties of the wall models (docs/model.md §3.5–3.8): JJ collisional part linear in φ,
//! h_w^u growing with φ, Li–Benyahia φ(r) shape and the paper's k, φ₀, r*, Jenkins θ
//! coefficients non-negative, and no NaN or infinity for θ → 0, zero slip and εs → 0.

use proptest::prelude::*;
use runout_closures::{ClosureParams, FrictionModel, Gas};
use runout_walls::coefficients::collisional_johnson_jackson;
use runout_walls::specularity::{k_parameter, phi0_from_k};
use runout_walls::{
    LiBenyahia, MomentumBranch, MomentumWallState, SolidsWallModel, ThetaWallState, WallStrain,
};

/// The paper's wall: e_w = 0.7, δ_w = 11° (paper Table 3).
const E_W: f64 = 0.7;
const DELTA_W: f64 = 11.0;

fn params(dry: bool, friction: FrictionModel) -> ClosureParams {
    ClosureParams {
        gas: if dry {
            Gas {
                density: 0.0,
                ..Gas::default()
            }
        } else {
            Gas::default()
        },
        friction_model: friction,
        ..ClosureParams::default()
    }
}

fn friction_model() -> impl Strategy<Value = FrictionModel> {
    prop_oneof![
        Just(FrictionModel::princeton()),
        Just(FrictionModel::schaeffer()),
        Just(FrictionModel::None),
        Just(FrictionModel::MuI(
            runout_closures::MuIConstants::glass_beads_jop_2005()
        ))
    ]
}

/// A consistent near-wall state: strain invariants from a planar velocity gradient at a floor.
fn momentum_state() -> impl Strategy<Value = MomentumWallState> {
    (
        0.0..0.66f64,
        -0.02..0.02f64,
        1e-6..3.0f64,
        0.0..10.0f64,
        0.0..3.0f64,
        prop::array::uniform4(-300.0..300.0f64),
    )
        .prop_map(|(eps_s_fluid, offset, theta, slip, gas_slip, g)| {
            let strain = WallStrain::planar_floor(g[0], g[1], g[2], g[3]);
            MomentumWallState {
                eps_s_fluid,
                eps_s: (eps_s_fluid + offset).clamp(0.0, 0.66),
                theta,
                slip,
                gas_slip,
                tr_d: strain.tr_d,
                s_ddot_s: strain.s_ddot_s,
                s_nn: strain.s_nn,
                extra_normal_load: 0.0,
            }
        })
}

/// Values that probe the limits: 0, tiny, negative (θ), and ordinary.
fn limit_value(ordinary: std::ops::Range<f64>) -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        Just(1e-300),
        Just(1e-20),
        Just(1e-12),
        Just(1e-9),
        ordinary,
    ]
}

fn every_model() -> Vec<SolidsWallModel> {
    vec![
        SolidsWallModel::NoSlip,
        SolidsWallModel::FreeSlip,
        SolidsWallModel::partial_slip(10.0, 0.0, 10.0, 0.01, 0.1).unwrap(),
        SolidsWallModel::johnson_jackson(1.0, E_W, DELTA_W, 0.0).unwrap(),
        SolidsWallModel::johnson_jackson(0.01, E_W, DELTA_W, 0.5).unwrap(),
        SolidsWallModel::revisited_johnson_jackson(E_W, DELTA_W, None, 0.0).unwrap(),
        SolidsWallModel::jenkins(E_W, DELTA_W, 0.0).unwrap(),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    /// COL = φ · COL(φ = 1): linear in the specularity, exactly 0 at φ = 0.
    #[test]
    fn jj_collisional_linear_in_specularity(phi in 0.0..1.0f64, eps_s in 0.0..0.66f64,
                                            theta in 1e-8..5.0f64) {
        let p = ClosureParams::default();
        let s = runout_closures::SolidsState::new(eps_s, theta, &p.particles, p.radial);
        let eps_max = p.friction.eps_s_max;
        let unit = collisional_johnson_jackson(1.0, &s, eps_max);
        let col = collisional_johnson_jackson(phi, &s, eps_max);
        prop_assert!((col - phi * unit).abs() <= 1e-14 * unit);
        prop_assert_eq!(collisional_johnson_jackson(0.0, &s, eps_max), 0.0);
        // and so is the model's diagnostic COL
        let state = MomentumWallState { eps_s_fluid: eps_s.max(1e-3), eps_s, theta, slip: 1.0,
            gas_slip: 0.1, tr_d: 0.0, s_ddot_s: 10.0, s_nn: 0.0, extra_normal_load: 0.0 };
        let jj = |phi| SolidsWallModel::johnson_jackson(phi, E_W, DELTA_W, 0.0).unwrap()
            .momentum(&state, &p).diagnostics.col;
        prop_assert!((jj(phi) - phi * jj(1.0)).abs() <= 1e-13 * jj(1.0));
        prop_assert_eq!(jj(0.0), 0.0);
    }

    /// h_w^u is non-decreasing in φ, strictly increasing where the slip and the solids
    /// fraction are non-zero; FRI ≥ 0 and h_w^u ≥ 0 for any consistent strain.
    #[test]
    fn jj_h_grows_with_specularity(state in momentum_state(), phi in 0.0..1.0f64,
                                   dphi in 1e-3..1.0f64, dry in any::<bool>(),
                                   friction in friction_model()) {
        let p = params(dry, friction);
        let at = |phi: f64| SolidsWallModel::johnson_jackson(phi, E_W, DELTA_W, 0.0).unwrap()
            .momentum(&state, &p).diagnostics;
        let (lo, hi) = (at(phi), at((phi + dphi).min(1.0)));
        prop_assert!(lo.fri >= 0.0 && lo.h_u >= 0.0, "{lo:?}");
        prop_assert!(hi.h_u >= lo.h_u, "{} < {}", hi.h_u, lo.h_u);
        let active = matches!(lo.branch, MomentumBranch::Kinetic | MomentumBranch::KineticFrictional);
        if active && state.eps_s > 1e-3 && (phi + dphi).min(1.0) > phi {
            prop_assert!(hi.h_u > lo.h_u, "{hi:?} vs {lo:?}");
        }
    }

    /// Li–Benyahia φ(r): φ(0) = φ₀, continuous at r*, non-increasing, in [0, φ₀], for any
    /// wall (e_w ∈ [0, 1], δ_w ∈ [0.5°, 30°]).
    #[test]
    fn li_benyahia_shape(e_w in 0.0..1.0f64, delta_w in 0.5..30.0f64,
                         r1 in 0.0..20.0f64, dr in 0.0..20.0f64) {
        let law = LiBenyahia::new(e_w, delta_w.to_radians().tan(), None).unwrap();
        prop_assert_eq!(law.specularity(0.0), law.phi0);
        let r_star = law.switch_ratio();
        let (below, above) = (law.specularity(r_star), law.specularity(r_star * (1.0 + 1e-12)));
        prop_assert!((below - 0.5 * law.phi0).abs() <= 1e-12 * law.phi0);
        prop_assert!((above - below).abs() <= 1e-10 * law.phi0, "jump {below} → {above}");
        let (a, b) = (law.specularity(r1), law.specularity(r1 + dr));
        prop_assert!(b <= a, "φ({}) = {b} > φ({r1}) = {a}", r1 + dr);
        for phi in [a, b] {
            prop_assert!((0.0..=law.phi0).contains(&phi), "{phi} outside [0, {}]", law.phi0);
        }
    }

    /// Jenkins h_θ ≥ 0 and c_θ ≥ 0 (and κ ≥ 0) for any state.
    #[test]
    fn jenkins_theta_coefficients_non_negative(eps_s in limit_value(0.0..0.66),
                                               theta in limit_value(-1.0..5.0),
                                               slip in limit_value(0.0..20.0),
                                               gas_slip in limit_value(0.0..5.0),
                                               e_w in 0.0..1.0f64, delta_w in 0.0..45.0f64,
                                               dry in any::<bool>()) {
        let wall = SolidsWallModel::jenkins(e_w, delta_w, 0.0).unwrap();
        let t = wall.granular_temperature(&ThetaWallState { eps_s, theta, slip, gas_slip },
                                          &params(dry, FrictionModel::princeton()));
        prop_assert!(t.face.g >= 0.0 && t.face.h >= 0.0 && t.face.c >= 0.0, "{t:?}");
    }

    /// No NaN, no infinity: every face coefficient and diagnostic of every model is finite
    /// for θ → 0 (and θ < 0), zero slip and εs → 0, and the face closure g + hΔ/2 > 0 so the
    /// solver's face value and flux are finite too.
    #[test]
    fn finite_everywhere(eps_s_fluid in limit_value(0.0..0.66), eps_s in limit_value(0.0..0.66),
                         theta in limit_value(-1.0..5.0), slip in limit_value(0.0..20.0),
                         gas_slip in limit_value(0.0..5.0),
                         g in prop::array::uniform4(-300.0..300.0f64),
                         dry in any::<bool>(), friction in friction_model(),
                         delta in 1e-4..0.1f64, phi_fluid in -10.0..10.0f64) {
        let p = params(dry, friction);
        let strain = WallStrain::planar_floor(g[0], g[1], g[2], g[3]);
        let m_state = MomentumWallState { eps_s_fluid, eps_s, theta, slip, gas_slip,
            tr_d: strain.tr_d, s_ddot_s: strain.s_ddot_s, s_nn: strain.s_nn, extra_normal_load: 0.0 };
        let t_state = ThetaWallState { eps_s: eps_s_fluid, theta, slip, gas_slip };
        for wall in every_model() {
            let m = wall.momentum(&m_state, &p);
            let t = wall.granular_temperature(&t_state, &p);
            for face in [m.face, t.face] {
                prop_assert!(face.g.is_finite() && face.h.is_finite() && face.c.is_finite(),
                             "{wall:?}: {face:?}");
                prop_assert!(face.g + 0.5 * face.h * delta > 0.0, "{wall:?}: {face:?}");
                prop_assert!(face.face_value(phi_fluid, delta).is_finite());
                prop_assert!(face.flux(1.0, phi_fluid, delta).is_finite());
            }
            let d = m.diagnostics;
            // h_w^u = +∞ only for no-slip, and for Jenkins where tan δ_w P_k/|u_sl| overflows
            // (|u_sl| = 1e-300 here): never NaN
            let jenkins_overflow = matches!(wall, SolidsWallModel::Jenkins { .. }) && slip < 1e-290;
            let infinite_ok = wall == SolidsWallModel::NoSlip || jenkins_overflow;
            for v in [d.h_u, d.col] {
                prop_assert!(v.is_finite() || (infinite_ok && v == f64::INFINITY), "{wall:?}: {d:?}");
            }
            for v in [d.fri, d.slip, d.theta, d.mu_kin, d.mu_fric, d.p_kin, d.p_fric,
                      d.zeta, d.specularity.unwrap_or(0.0)] {
                prop_assert!(v.is_finite(), "{wall:?}: {d:?}");
            }
            let e = t.diagnostics;
            for v in [e.theta, e.kappa, e.h_theta, e.c_theta, e.slip, e.p_kin,
                      e.specularity.unwrap_or(0.0)] {
                prop_assert!(v.is_finite(), "{wall:?}: {e:?}");
            }
        }
    }
}

/// docs/model.md §3.7: with the paper's e_w = 0.7 and δ_w = 11°, k = 1.1565628,
/// φ₀ = 0.0776198, switch at r = 1.96114; φ(r) at r = 0.5, 1, 2, 5, 10 from
/// verification-notes §2a, printed to 4 decimals (±1 in the last digit: 0.06773 is printed
/// 0.0678 there).
#[test]
fn li_benyahia_paper_values() {
    let tan_w = DELTA_W.to_radians().tan();
    let law = LiBenyahia::new(E_W, tan_w, None).unwrap();
    assert!((law.k - 1.1565628).abs() < 5e-8, "{}", law.k);
    assert!((law.phi0 - 0.0776198).abs() < 5e-8, "{}", law.phi0);
    assert!(
        (law.switch_ratio() - 1.96114).abs() < 5e-6,
        "{}",
        law.switch_ratio()
    );
    for (r, phi) in [
        (0.5, 0.0678),
        (1.0, 0.0578),
        (2.0, 0.0381),
        (5.0, 0.0152),
        (10.0, 0.0076),
    ] {
        assert!(
            (law.specularity(r) - phi).abs() < 1e-4,
            "φ({r}) = {}",
            law.specularity(r)
        );
    }
    assert_eq!(k_parameter(E_W, tan_w), law.k);
    // small-k branch and the PHIP0 override
    assert_eq!(phi0_from_k(0.1), 0.09094568176225006 * 0.1);
    let fixed = LiBenyahia::new(E_W, tan_w, Some(0.05)).unwrap();
    assert_eq!(fixed.specularity(0.0), 0.05);
    assert!(LiBenyahia::new(E_W, tan_w, Some(-0.1)).is_err());
    assert!(LiBenyahia::new(E_W, 0.0, Some(0.05)).is_err());
    assert_eq!(
        LiBenyahia::new(E_W, 0.0, None).unwrap().specularity(3.0),
        0.0
    );
}

/// docs/model.md §3.5 steps 4 and 6, and §3.8: the branch rules.
#[test]
fn branch_rules() {
    let p = ClosureParams::default();
    let jj = SolidsWallModel::johnson_jackson(0.1, E_W, DELTA_W, 2.0).unwrap();
    let dense = MomentumWallState {
        eps_s_fluid: 0.6,
        eps_s: 0.6,
        theta: 0.01,
        slip: 3.0,
        gas_slip: 0.1,
        tr_d: 0.0,
        s_ddot_s: 100.0,
        s_nn: 0.0,
        extra_normal_load: 0.0,
    };
    let m = jj.momentum(&dense, &p);
    assert_eq!(m.diagnostics.branch, MomentumBranch::KineticFrictional);
    let d = m.diagnostics;
    assert!((d.h_u - (d.col + d.fri) / d.viscosity()).abs() < 1e-12 * d.h_u);
    // c = h U_w, g = 1
    assert_eq!((m.face.g, m.face.c), (1.0, d.h_u * 2.0));
    // FRI = tan δ_w P_f at S_nn = 0; P_f = 1600 Pa at εs = 0.6, tr D = 0 (docs/model.md §2.4.2)
    assert!((d.fri - DELTA_W.to_radians().tan() * 1600.0).abs() < 1e-6);
    // zero slip in the frictional branch: h = 0 (a resting block stays put)
    let rest = jj.momentum(&MomentumWallState { slip: 0.0, ..dense }, &p);
    assert_eq!(
        (rest.diagnostics.branch, rest.face.h),
        (MomentumBranch::ZeroSlip, 0.0)
    );
    // fluid cell above εs,min, interpolated below: FRI = μ_f = 0, h = COL/μ_k
    let edge = jj.momentum(
        &MomentumWallState {
            eps_s_fluid: 0.52,
            eps_s: 0.49,
            ..dense
        },
        &p,
    );
    let e = edge.diagnostics;
    assert_eq!((e.fri, e.mu_fric), (0.0, 0.0));
    assert!((e.h_u - e.col / e.mu_kin).abs() < 1e-12 * e.h_u);
    // Schaeffer (no Princeton): h = COL/μ_k even in a dense cell
    let schaeffer = ClosureParams {
        friction_model: FrictionModel::schaeffer(),
        ..p
    };
    let s = jj.momentum(&dense, &schaeffer).diagnostics;
    assert_eq!((s.branch, s.fri), (MomentumBranch::Kinetic, 0.0));
    // dilute fluid cell: free slip for the momentum, zero gradient for θ
    let dilute = jj.momentum(
        &MomentumWallState {
            eps_s_fluid: 1e-4,
            ..dense
        },
        &p,
    );
    assert_eq!(dilute.face, runout_walls::RobinFace::ZERO_GRADIENT);
    let t = jj.granular_temperature(
        &ThetaWallState {
            eps_s: 1e-4,
            theta: 0.1,
            slip: 1.0,
            gas_slip: 0.0,
        },
        &p,
    );
    assert_eq!(t.face, runout_walls::RobinFace::ZERO_GRADIENT);
    // Jenkins at zero slip: COL = 0 (MFIX: "use free slip bc")
    let jenkins = SolidsWallModel::jenkins(E_W, DELTA_W, 0.0).unwrap();
    let kinetic = MomentumWallState {
        eps_s_fluid: 0.3,
        eps_s: 0.3,
        slip: 0.0,
        ..dense
    };
    assert_eq!(jenkins.momentum(&kinetic, &p).face.h, 0.0);
    // no-slip: face value 0 whatever the wall velocity; user partial slip: Eq. 12 as given
    assert_eq!(
        SolidsWallModel::NoSlip
            .momentum(&dense, &p)
            .face
            .face_value(3.0, 0.01),
        0.0
    );
    let user = SolidsWallModel::partial_slip(10.0, 1.0, 10.0, 0.01, 0.1).unwrap();
    assert_eq!(
        user.momentum(&dense, &p).face,
        runout_walls::RobinFace::partial_slip(10.0, 1.0)
    );
    let ut = user.granular_temperature(
        &ThetaWallState {
            eps_s: 0.6,
            theta: 0.1,
            slip: 1.0,
            gas_slip: 0.0,
        },
        &p,
    );
    assert_eq!(
        ut.face,
        runout_walls::RobinFace::user_theta(10.0, 0.01, 0.1)
    );
}

/// With μ(I) a JJ or Jenkins wall adds its friction at every εs, as the interior does
/// (`FrictionModel::wall_friction_acts_at`): h_w^u is continuous across εs,min, where μ(I)'s
/// P_c and its derivative vanish; gated at εs,min as for Princeton it jumped from
/// (COL + FRI)/μ_f to COL/μ_k, and a sheared basal layer cycled across the gate (issue 58).
/// Princeton's coefficient was already continuous there: its μ_f vanishes with P_c. The
/// frictional normal stress on the wall is never tensile (`coefficients::frictional`).
#[test]
fn mu_i_wall_coefficient_is_continuous_across_the_friction_onset() {
    let mu_i = params(
        false,
        FrictionModel::MuI(runout_closures::MuIConstants::glass_beads_jop_2005()),
    );
    let princeton = params(false, FrictionModel::princeton());
    let eps_s_min = mu_i.friction.eps_s_min;
    // the basal layer of the foot study's JJ floor: εs at the onset, θ 0.03 m²/s², 3.6 m/s
    let at = |eps_s: f64| MomentumWallState {
        eps_s_fluid: eps_s,
        eps_s,
        theta: 0.03,
        slip: 3.6,
        gas_slip: 0.1,
        tr_d: 0.0,
        s_ddot_s: 200.0,
        s_nn: -1.0,
        extra_normal_load: 0.0,
    };
    for wall in [
        SolidsWallModel::johnson_jackson(0.1, E_W, DELTA_W, 0.0).unwrap(),
        SolidsWallModel::revisited_johnson_jackson(E_W, DELTA_W, None, 0.0).unwrap(),
        SolidsWallModel::jenkins(E_W, DELTA_W, 0.0).unwrap(),
    ] {
        for p in [&mu_i, &princeton] {
            let below = wall.momentum(&at(eps_s_min - 1e-9), p).diagnostics;
            let above = wall.momentum(&at(eps_s_min + 1e-9), p).diagnostics;
            assert!(
                (below.h_u / above.h_u - 1.0).abs() < 1e-6,
                "{wall:?} {:?}: h {} below εs,min, {} above",
                p.friction_model,
                below.h_u,
                above.h_u
            );
        }
        // μ(I) below the onset: the frictional branch with its μ_f (the interior's)
        let below = wall.momentum(&at(0.3), &mu_i).diagnostics;
        assert_eq!(below.branch, MomentumBranch::KineticFrictional);
        assert!(below.mu_fric > below.mu_kin, "{below:?}");
        assert!(
            (below.h_u - (below.col + below.fri) / below.viscosity()).abs() < 1e-12 * below.h_u
        );
        // stretched normal to the wall (S_nn > 0) below εs,min, P_f = 0: the frictional
        // normal stress −2 μ_f S_nn < 0 is bounded by 0 (a wall is never pulled), h > 0
        let stretched = MomentumWallState {
            s_nn: 5.0,
            ..at(0.3)
        };
        let d = wall.momentum(&stretched, &mu_i).diagnostics;
        assert_eq!(d.fri, 0.0);
        assert!(d.h_u > 0.0 && d.h_u.is_finite(), "{d:?}");
    }
}

/// Invalid parameters are rejected with the field name.
#[test]
fn invalid_parameters_name_the_field() {
    let e = SolidsWallModel::johnson_jackson(1.5, E_W, DELTA_W, 0.0).unwrap_err();
    assert!(
        e.to_string().contains("specularity") && e.to_string().contains("[0, 1]"),
        "{e}"
    );
    let e = SolidsWallModel::jenkins(E_W, 95.0, 0.0).unwrap_err();
    assert!(e.to_string().contains("wall_friction_angle"), "{e}");
    assert!(SolidsWallModel::partial_slip(-1.0, 0.0, 1.0, 0.0, 0.0).is_err());
    assert!(SolidsWallModel::johnson_jackson(f64::NAN, E_W, DELTA_W, 0.0).is_err());
}

/// verification-notes §2a table ("JJ h_u and h_θ do not depend on θ"): dry Lun (1984)
/// closures, CS g0, e = 0.9, e_w = 0.7, εs,max = 0.65, kinetic branch: h_u d/φ and
/// h_θ d = (H_w/κ) d at εs = 0.03 … 0.64, printed to 3 significant digits.
#[test]
fn verification_notes_dry_table() {
    let table = [
        (0.03, 0.398, 0.108),
        (0.1, 1.37, 0.351),
        (0.2, 2.30, 0.578),
        (0.3, 2.49, 0.645),
        (0.4, 2.31, 0.622),
        (0.5, 2.05, 0.565),
        (0.6, 1.79, 0.504),
        (0.64, 1.70, 0.480),
    ];
    let p = params(true, FrictionModel::None);
    let d = p.particles.diameter;
    let phi = 0.1;
    let wall = SolidsWallModel::johnson_jackson(phi, E_W, DELTA_W, 0.0).unwrap();
    for theta in [1e-4, 0.5] {
        for (eps_s, hu_d_over_phi, htheta_d) in table {
            let m = wall.momentum(
                &MomentumWallState {
                    eps_s_fluid: eps_s,
                    eps_s,
                    theta,
                    slip: 1.0,
                    gas_slip: 0.0,
                    tr_d: 0.0,
                    s_ddot_s: 0.0,
                    s_nn: 0.0,
                    extra_normal_load: 0.0,
                },
                &p,
            );
            let got = m.diagnostics.h_u * d / phi;
            assert!(
                (got / hu_d_over_phi - 1.0).abs() < 5e-3,
                "εs {eps_s}: h_u d/φ = {got}"
            );
            let t = wall.granular_temperature(
                &ThetaWallState {
                    eps_s,
                    theta,
                    slip: 1.0,
                    gas_slip: 0.0,
                },
                &p,
            );
            let got = t.face.h / t.face.g * d;
            assert!(
                (got / htheta_d - 1.0).abs() < 5e-3,
                "εs {eps_s}: h_θ d = {got}"
            );
        }
    }
}
