//! Properties of the discrete wall-face closure (docs/model.md §3.2) and its convergence to the
//! closed-form Robin profiles of family A (paper Eqs. 12–13; `runout_walls::analytic`).

use proptest::prelude::*;
use runout_walls::analytic::RobinProfile;
use runout_walls::RobinFace;

/// Depth of the family-A profiles [m] (cases/analytic/A-fig1.ron).
const DEPTH: f64 = 0.1;

/// |a − b| ≤ tol · (1 + max(|a|, |b|)).
fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * (1.0 + a.abs().max(b.abs()))
}

/// Max-norm error of the discrete solution over the cell centres and the wall-face value.
/// (The wall-face error alone changes sign near h ≈ 20–50 m⁻¹ on L = 0.1 m, where its Δ²
/// coefficient vanishes and a pointwise order estimate is meaningless; in the max norm the
/// profile error dominates and converges cleanly.)
fn max_error(profile: &RobinProfile, cells: usize) -> f64 {
    let d = profile.discrete(DEPTH, cells);
    d.n.iter()
        .zip(&d.values)
        .map(|(&n, &v)| (v - profile.value(n)).abs())
        .fold((d.wall_value - profile.value(DEPTH)).abs(), f64::max)
}

/// Observed order log2(e(N)/e(2N)) on N₀ → 2N₀ → 4N₀ cells, the smaller of the two, with
/// N₀ = max(10, 4hL) so that hΔ ≤ 1/4 (the asymptotic range) and the errors stay far above
/// the round-off of the tridiagonal solve (~1e-12 of the profile's scale).
fn observed_order(profile: &RobinProfile) -> f64 {
    let n0 = ((4.0 * profile.face.h * DEPTH).ceil() as usize).max(10);
    let e: Vec<f64> = [n0, 2 * n0, 4 * n0]
        .iter()
        .map(|&n| max_error(profile, n))
        .collect();
    (e[0] / e[1]).log2().min((e[1] / e[2]).log2())
}

/// Second order, as style A6.10(c) asks of every convergence test.
const MIN_ORDER: f64 = 1.8;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// h_u → 0: the partial-slip face is free slip (face value = fluid value, zero flux and
    /// zero wall shear τ_w = μ h (u_face − U_w)); h_u = 0 is exactly zero gradient.
    #[test]
    fn small_h_is_free_slip(u_f in -10.0..10.0f64, u_w in -10.0..10.0f64,
                            delta in 1e-4..0.1f64, mu in 1e-3..1e3f64) {
        let exact = RobinFace::partial_slip(0.0, u_w);
        prop_assert_eq!(exact.face_value(u_f, delta), u_f);
        prop_assert_eq!(exact.flux(mu, u_f, delta), 0.0);
        let h = 1e-12;
        let f = RobinFace::partial_slip(h, u_w);
        let face = f.face_value(u_f, delta);
        prop_assert!(close(face, u_f, 1e-12), "{face} vs {u_f}");
        prop_assert!(f.flux(mu, u_f, delta).abs() <= 1e-9 * mu * (u_f - u_w).abs() + 1e-300);
        prop_assert!((mu * h * (face - u_w)).abs() <= 1e-9 * mu * (1.0 + (u_f - u_w).abs()));
    }

    /// h_u → ∞: the face value is the wall velocity (no slip), and the flux tends to the
    /// half-cell Dirichlet flux Γ (u_F − U_w)/(Δ/2).
    #[test]
    fn large_h_is_no_slip(u_f in -10.0..10.0f64, u_w in -10.0..10.0f64,
                          delta in 1e-4..0.1f64, mu in 1e-3..1e3f64) {
        let f = RobinFace::partial_slip(1e14, u_w);
        prop_assert!(close(f.face_value(u_f, delta), u_w, 1e-9));
        let dirichlet = RobinFace::dirichlet(u_w);
        prop_assert!(close(f.flux(mu, u_f, delta), dirichlet.flux(mu, u_f, delta), 1e-9));
    }

    /// For any hΔ ≥ 0 the face value lies between U_w and the fluid value (no overshoot past
    /// U_w, unlike the ghost value beyond hΔ = 2), the implicit coefficient lies in
    /// [0, 2Γ/Δ] and the flux has the sign of u_F − U_w.
    #[test]
    fn bounded_for_any_h_delta(u_f in -10.0..10.0f64, u_w in -10.0..10.0f64,
                               log_h in -6.0..12.0f64, delta in 1e-5..1.0f64,
                               mu in 1e-3..1e3f64) {
        let h = 10f64.powf(log_h);
        let f = RobinFace::partial_slip(h, u_w);
        let face = f.face_value(u_f, delta);
        let (lo, hi) = (u_f.min(u_w), u_f.max(u_w));
        let slack = 1e-12 * (1.0 + hi.abs().max(lo.abs()));
        prop_assert!(face >= lo - slack && face <= hi + slack, "{face} not in [{lo}, {hi}]");
        let (a, _) = f.implicit_parts(mu, delta);
        prop_assert!(a >= 0.0 && a <= 2.0 * mu / delta * (1.0 + 1e-12));
        let flux = f.flux(mu, u_f, delta);
        prop_assert!(flux * (u_f - u_w) >= 0.0);
    }

    /// The whole discrete Robin problem (the family-A BVP) stays within [U_w, U_b] on any
    /// grid, however large hΔ (discrete maximum principle of the eliminated closure).
    #[test]
    fn discrete_profile_bounded(u_b in 0.1..10.0f64, log_h in -2.0..8.0f64,
                                cells in 1usize..60) {
        let profile = RobinProfile::velocity(u_b, 0.0, 10f64.powf(log_h));
        let d = profile.discrete(DEPTH, cells);
        for v in d.values.iter().chain([&d.wall_value]) {
            prop_assert!(*v >= -1e-12 * u_b && *v <= u_b * (1.0 + 1e-12), "{v}");
        }
    }

    /// Second-order convergence of the face closure to the exact velocity profile of paper
    /// Eq. 12, in the max norm over the cell centres and the wall-face value.
    #[test]
    fn velocity_converges_second_order(u_w in -2.0..2.0f64, difference in 0.5..10.0f64,
                                       log_h in -1.0..2.0f64) {
        let profile = RobinProfile::velocity(u_w + difference, u_w, 10f64.powf(log_h));
        let order = observed_order(&profile);
        prop_assert!(order >= MIN_ORDER, "order {order}");
    }

    /// Second-order convergence to the exact θ profile of paper Eq. 13 (c ≠ 0), rising or
    /// falling towards θ_∞ = θ_w + c/h.
    #[test]
    fn temperature_converges_second_order(theta_w in 0.0..0.1f64, log_h in -1.0..2.0f64,
                                          excess in 0.0..1.0f64, difference in 0.05..2.0f64,
                                          falling in any::<bool>()) {
        let h = 10f64.powf(log_h);
        let theta_inf = theta_w + excess;
        let theta_b = if falling { theta_inf + difference } else { theta_inf - difference };
        let profile = RobinProfile::temperature(theta_b, theta_w, h, excess * h);
        let order = observed_order(&profile);
        prop_assert!(order >= MIN_ORDER, "order {order}");
    }

    /// The closed form satisfies its ODE (the Robin relation at every depth) and its start
    /// value.
    #[test]
    fn closed_form_satisfies_eqs_12_13(theta_b in 0.0..2.0f64, theta_w in 0.0..0.1f64,
                                       h in 0.0..100.0f64, c in 0.0..10.0f64,
                                       n in 0.0..DEPTH) {
        let p = RobinProfile::temperature(theta_b, theta_w, h, c);
        prop_assert_eq!(p.value(0.0), theta_b);
        // dθ/dn + h (θ − θ_w) = c
        let residual = p.slope(n) + h * (p.value(n) - theta_w) - c;
        prop_assert!(residual.abs() <= 1e-12 * (1.0 + c + h * theta_b), "{residual}");
        // and the slope is the derivative of the value (central difference)
        let eps = 1e-6;
        let fd = (p.value(n + eps) - p.value(n - eps)) / (2.0 * eps);
        prop_assert!(close(fd, p.slope(n), 1e-5), "{fd} vs {}", p.slope(n));
    }
}

/// With h = 0 the θ profile is linear (θ_b + c n) and the discrete solution is exact.
#[test]
fn pure_flux_condition_is_exact() {
    let p = RobinProfile::temperature(0.5, 0.01, 0.0, 2.0);
    assert_eq!(p.asymptote(), None);
    let d = p.discrete(DEPTH, 7);
    for (n, v) in d.n.iter().zip(&d.values) {
        assert!((v - (0.5 + 2.0 * n)).abs() < 1e-12, "{v}");
    }
    assert!((d.wall_value - (0.5 + 2.0 * DEPTH)).abs() < 1e-12);
}

/// The numbers of verification-notes §2a (Fig. 1 parameters, U_b = 5, U_w = 0).
#[test]
fn fig1_velocity_values() {
    let table = [
        (0.1, [5.000, 4.998, 4.995, 4.990, 4.975, 4.950]),
        (1.0, [5.000, 4.975, 4.950, 4.901, 4.756, 4.524]),
        (10.0, [5.000, 4.756, 4.524, 4.094, 3.033, 1.839]),
        (100.0, [5.000, 3.033, 1.839, 0.677, 0.034, 0.0002]),
    ];
    for (h, row) in table {
        let p = RobinProfile::velocity(5.0, 0.0, h);
        for (n, want) in [0.0, 0.005, 0.01, 0.02, 0.05, 0.1].iter().zip(row) {
            assert!(
                (p.value(*n) - want).abs() < 6e-4,
                "h = {h}, n = {n}: {}",
                p.value(*n)
            );
        }
    }
    // θ_∞ = θ_w + c/h: h = 10, c = 0.1 relaxes to 0.02 (verification-notes §2a)
    let t = RobinProfile::temperature(0.5, 0.01, 10.0, 0.1);
    assert!((t.asymptote().unwrap() - 0.02).abs() < 1e-15);
    assert!((t.value(0.1) - 0.1966).abs() < 1e-4, "{}", t.value(0.1));
}
