//! Manufactured-solution tests of every backend on stretched grids, plus error paths.
#![allow(clippy::needless_range_loop)] // several parallel arrays indexed by cell

use runout_linsolve::problems::{
    manufactured_solution, momentum_like, pressure_like, rel_error_inf, set_rhs_from_solution, Grid,
};
use runout_linsolve::{
    build, CellKind, Cycle, LinSolveError, LinearSolverKind, MultigridParams, Pattern, Precond,
    Stencil5,
};

const RTOL: f64 = 1e-10;

/// ‖b − A x‖₂/‖b‖₂ written out independently of the crate, straight from the documented
/// row equation a_P φ_P = Σ a_nb φ_nb + b (fixed cells: a_P φ_P = b).
fn independent_rel_residual(a: &Stencil5, x: &[f64]) -> f64 {
    let p = a.pattern();
    let (nx, ny) = (p.nx(), p.ny());
    let (mut rr, mut bb) = (0.0, 0.0);
    for j in 0..ny {
        for i in 0..nx {
            let k = p.idx(i, j);
            let mut r = a.b[k] - a.a_p[k] * x[k];
            if p.kind(k) == CellKind::Active {
                if i + 1 < nx {
                    r += a.a_e[k] * x[p.idx(i + 1, j)];
                }
                if i > 0 {
                    r += a.a_w[k] * x[p.idx(i - 1, j)];
                }
                if j + 1 < ny {
                    r += a.a_n[k] * x[p.idx(i, j + 1)];
                }
                if j > 0 {
                    r += a.a_s[k] * x[p.idx(i, j - 1)];
                }
            }
            rr += r * r;
            bb += a.b[k] * a.b[k];
        }
    }
    (rr / bb).sqrt()
}

fn iterative_kinds(rtol: f64) -> Vec<LinearSolverKind> {
    let mut v: Vec<LinearSolverKind> = [
        Precond::None,
        Precond::Jacobi,
        Precond::Ilu0,
        Precond::LineY,
        Precond::MultigridV,
        Precond::MultigridK,
    ]
    .into_iter()
    .map(|precond| LinearSolverKind::BiCgStab {
        rtol,
        max_iter: 5000,
        precond,
    })
    .collect();
    for cycle in [Cycle::K, Cycle::V] {
        v.push(LinearSolverKind::MultigridCg(MultigridParams {
            rtol,
            cycle,
            ..MultigridParams::default()
        }));
    }
    v
}

/// Solves `a` (whose b = A x_exact) with `kind` and checks the reported and the
/// independently recomputed residual and the error against x_exact.
fn check_solves(
    a: &Stencil5,
    exact: &[f64],
    kind: &LinearSolverKind,
    rtol: f64,
    max_rel_error: f64,
) {
    let mut s = build(kind);
    s.set_pattern(a.pattern()).unwrap();
    let mut x = vec![0.0; a.len()];
    let stats = s
        .setup_and_solve(a, &mut x)
        .unwrap_or_else(|e| panic!("{}: {e}", s.name()));
    let res = independent_rel_residual(a, &x);
    let err = rel_error_inf(&x, exact);
    assert!(stats.converged, "{}: not converged, {stats:?}", s.name());
    assert!(
        res <= rtol,
        "{}: true residual {res:e} > {rtol:e}",
        s.name()
    );
    assert!(
        // 1e-12: rounding of the two residual evaluations (far below every rtol used)
        (stats.rel_residual - res).abs() <= 1e-3 * res + 1e-12,
        "{}: reported residual {:e} is not the true one {res:e}",
        s.name(),
        stats.rel_residual
    );
    assert!(
        err <= max_rel_error,
        "{}: error {err:e} > {max_rel_error:e}",
        s.name()
    );
}

fn pressure_system(nx: usize, ny: usize) -> (Stencil5, Vec<f64>) {
    let g = Grid::paper(nx, ny);
    let exact = manufactured_solution(&g);
    let mut a = pressure_like(&g).unwrap();
    set_rhs_from_solution(&mut a, &exact).unwrap();
    (a, exact)
}

fn momentum_system(nx: usize, ny: usize, peclet: f64, cfl: f64) -> (Stencil5, Vec<f64>) {
    let g = Grid::paper(nx, ny);
    let exact = manufactured_solution(&g);
    let mut a = momentum_like(&g, peclet, cfl).unwrap();
    set_rhs_from_solution(&mut a, &exact).unwrap();
    (a, exact)
}

#[test]
fn grid_is_paper_like() {
    let g = Grid::paper(120, 60);
    assert!((g.dx(60) - 0.02).abs() < 1e-15 && (g.dy(0) - 0.005).abs() < 1e-15);
    assert!((g.dx(0) / g.dx(1) - 1.1).abs() < 1e-12 || g.dx(0) / g.dx(1) == 1.0);
    assert!((g.dy(31) / g.dy(30) - 1.1).abs() < 1e-12);
    assert!(g.max_aspect_ratio() >= 4.0);
}

#[test]
fn pressure_like_all_backends() {
    // 2 400 cells, stretched both ways, pinned reference cell
    let (a, exact) = pressure_system(60, 40);
    for kind in [LinearSolverKind::SparseLu, LinearSolverKind::Cholesky] {
        check_solves(&a, &exact, &kind, 1e-12, 1e-10);
    }
    for kind in iterative_kinds(RTOL) {
        check_solves(&a, &exact, &kind, RTOL, 1e-6);
    }
}

#[test]
fn momentum_like_all_backends() {
    for (peclet, cfl) in [(1.0, 1.0), (100.0, 1.0), (100.0, 20.0)] {
        let (a, exact) = momentum_system(60, 40, peclet, cfl);
        check_solves(&a, &exact, &LinearSolverKind::SparseLu, 1e-12, 1e-10);
        for kind in iterative_kinds(RTOL) {
            if matches!(kind, LinearSolverKind::MultigridCg(_)) {
                continue; // CG needs a symmetric matrix
            }
            check_solves(&a, &exact, &kind, RTOL, 1e-6);
        }
    }
}

#[test]
fn pressure_with_obstacle_cells() {
    // a block of dead cells (a_P = 1, b = 0) and the pinned reference
    let g = Grid::paper(48, 32);
    let exact0 = manufactured_solution(&g);
    let base = pressure_like(&g).unwrap();
    let dead = |i: usize, j: usize| (10..17).contains(&i) && (5..20).contains(&j);
    let pattern = Pattern::from_fn(48, 32, |i, j| {
        if dead(i, j) || base.pattern().kind(base.pattern().idx(i, j)) == CellKind::Fixed {
            CellKind::Fixed
        } else {
            CellKind::Active
        }
    })
    .unwrap();
    let mut a = Stencil5::new(pattern.clone());
    let mut exact = exact0.clone();
    for k in 0..a.len() {
        let (i, j) = (k % 48, k / 48);
        a.a_p[k] = base.a_p[k];
        a.a_e[k] = base.a_e[k];
        a.a_w[k] = base.a_w[k];
        a.a_n[k] = base.a_n[k];
        a.a_s[k] = base.a_s[k];
        if dead(i, j) {
            (a.a_p[k], a.a_e[k], a.a_w[k], a.a_n[k], a.a_s[k]) = (1.0, 0.0, 0.0, 0.0, 0.0);
            exact[k] = 0.0;
        }
    }
    set_rhs_from_solution(&mut a, &exact).unwrap();
    for kind in [LinearSolverKind::SparseLu, LinearSolverKind::Cholesky] {
        check_solves(&a, &exact, &kind, 1e-12, 1e-10);
    }
    for kind in iterative_kinds(RTOL) {
        check_solves(&a, &exact, &kind, RTOL, 1e-6);
    }
}

#[test]
fn multigrid_iterations_independent_of_size() {
    // K-cycle iterations to 1e-8 from 2.5k to 40k cells stay within ±30 % of the smallest
    let mut its = Vec::new();
    for (nx, ny) in [(70, 36), (141, 71), (283, 141)] {
        let (a, exact) = pressure_system(nx, ny);
        let mut s = build(&LinearSolverKind::MultigridCg(MultigridParams::default()));
        s.set_pattern(a.pattern()).unwrap();
        let mut x = vec![0.0; a.len()];
        let st = s.setup_and_solve(&a, &mut x).unwrap();
        assert!(st.converged && rel_error_inf(&x, &exact) < 1e-5);
        its.push(st.iterations as f64);
    }
    for &n in &its[1..] {
        assert!((n / its[0] - 1.0).abs() <= 0.3, "iterations {its:?}");
    }
}

#[test]
fn refill_values_and_reuse_pattern() {
    let (mut a, exact) = momentum_system(50, 30, 50.0, 1.0);
    let kinds = [
        LinearSolverKind::SparseLu,
        LinearSolverKind::transport_default(RTOL, 200),
    ];
    for kind in kinds {
        let mut s = build(&kind);
        s.set_pattern(a.pattern()).unwrap();
        for cfl in [1.0, 10.0, 0.1] {
            let m = momentum_like(&Grid::paper(50, 30), 50.0, cfl).unwrap();
            a.a_p.copy_from_slice(&m.a_p); // refill in place
            a.a_e.copy_from_slice(&m.a_e);
            a.a_w.copy_from_slice(&m.a_w);
            a.a_n.copy_from_slice(&m.a_n);
            a.a_s.copy_from_slice(&m.a_s);
            set_rhs_from_solution(&mut a, &exact).unwrap();
            let mut x = vec![0.0; a.len()];
            let st = s.setup_and_solve(&a, &mut x).unwrap();
            assert!(
                st.converged && rel_error_inf(&x, &exact) < 1e-6,
                "{} cfl {cfl}: {st:?}",
                s.name()
            );
        }
    }
}

#[test]
fn zero_rhs_gives_zero_solution() {
    let (mut a, _) = pressure_system(20, 10);
    a.b.fill(0.0);
    for kind in iterative_kinds(1e-8)
        .into_iter()
        .chain([LinearSolverKind::SparseLu])
    {
        let mut s = build(&kind);
        s.set_pattern(a.pattern()).unwrap();
        let mut x = vec![1.0; a.len()];
        let st = s.setup_and_solve(&a, &mut x).unwrap();
        assert!(
            x.iter().all(|&v| v == 0.0) && st.rel_residual == 0.0,
            "{}",
            s.name()
        );
    }
}

#[test]
fn iteration_cap_respected_and_reported() {
    let (a, _) = pressure_system(60, 40);
    for kind in [
        LinearSolverKind::BiCgStab {
            rtol: 1e-12,
            max_iter: 3,
            precond: Precond::Jacobi,
        },
        LinearSolverKind::MultigridCg(MultigridParams {
            rtol: 1e-12,
            max_iter: 2,
            ..MultigridParams::default()
        }),
    ] {
        let mut s = build(&kind);
        s.set_pattern(a.pattern()).unwrap();
        let mut x = vec![0.0; a.len()];
        let st = s.setup_and_solve(&a, &mut x).unwrap();
        let cap = if matches!(kind, LinearSolverKind::BiCgStab { .. }) {
            3
        } else {
            2
        };
        assert_eq!(st.iterations, cap, "{}", s.name());
        assert!(!st.converged && st.rel_residual > 1e-12);
        assert!(
            (st.rel_residual - independent_rel_residual(&a, &x)).abs() < 1e-6 * st.rel_residual
        );
    }
}

fn all_kinds() -> Vec<LinearSolverKind> {
    let mut v = vec![LinearSolverKind::SparseLu, LinearSolverKind::Cholesky];
    v.extend(iterative_kinds(1e-8));
    v
}

#[test]
fn dimension_and_pattern_mismatch_are_errors() {
    let (a, _) = pressure_system(12, 8);
    let (other, _) = pressure_system(8, 12);
    for kind in all_kinds() {
        let mut s = build(&kind);
        assert!(matches!(s.setup(&a), Err(LinSolveError::NotReady(_))));
        s.set_pattern(a.pattern()).unwrap();
        let mut x = vec![0.0; a.len()];
        assert!(
            matches!(s.solve(&a, &mut x), Err(LinSolveError::NotReady(_))),
            "{}",
            s.name()
        );
        assert_eq!(s.setup(&other), Err(LinSolveError::PatternMismatch));
        s.setup(&a).unwrap();
        let mut short = vec![0.0; a.len() - 1];
        assert!(
            matches!(
                s.solve(&a, &mut short),
                Err(LinSolveError::DimensionMismatch { .. })
            ),
            "{}",
            s.name()
        );
    }
    let mut bad = a.clone();
    bad.a_e.pop();
    assert!(matches!(
        build(&LinearSolverKind::SparseLu).setup_and_solve(&bad, &mut [0.0; 96]),
        Err(LinSolveError::NotReady(_))
    ));
    let mut s = build(&LinearSolverKind::SparseLu);
    s.set_pattern(bad.pattern()).unwrap();
    assert!(matches!(
        s.setup(&bad),
        Err(LinSolveError::DimensionMismatch { what: "a_e", .. })
    ));
}

#[test]
fn non_finite_entries_are_errors() {
    let (a, _) = pressure_system(12, 8);
    for kind in all_kinds() {
        let mut s = build(&kind);
        s.set_pattern(a.pattern()).unwrap();
        let mut bad = a.clone();
        bad.a_n[17] = f64::NAN;
        assert_eq!(
            s.setup(&bad),
            Err(LinSolveError::NonFinite {
                what: "a_n",
                cell: 17
            })
        );
        let mut bad = a.clone();
        bad.b[5] = f64::INFINITY;
        s.setup(&bad).unwrap();
        let mut x = vec![0.0; a.len()];
        assert_eq!(
            s.solve(&bad, &mut x),
            Err(LinSolveError::NonFinite { what: "b", cell: 5 })
        );
        let mut bad = a.clone();
        bad.a_p[3] = 0.0;
        assert_eq!(s.setup(&bad), Err(LinSolveError::ZeroDiagonal { cell: 3 }));
    }
}

#[test]
fn singular_matrix_is_an_error_or_reported_unconverged() {
    // pure Neumann (no reference cell) with an incompatible source: no solution exists
    let g = Grid::paper(30, 20);
    let pinned = pressure_like(&g).unwrap();
    let mut a = Stencil5::new(Pattern::new(30, 20).unwrap());
    for k in 0..a.len() {
        a.a_e[k] = pinned.a_e[k];
        a.a_w[k] = pinned.a_w[k];
        a.a_n[k] = pinned.a_n[k];
        a.a_s[k] = pinned.a_s[k];
        a.a_p[k] = a.a_e[k] + a.a_w[k] + a.a_n[k] + a.a_s[k];
        a.b[k] = 1.0;
    }
    // the reference cell of `pinned` had no links of its own: give it its neighbours' ones
    let r = a.len() - 1;
    a.a_w[r] = a.a_e[r - 1];
    a.a_s[r] = a.a_n[r - 30];
    a.a_p[r] = a.a_w[r] + a.a_s[r];
    for kind in [LinearSolverKind::SparseLu, LinearSolverKind::Cholesky] {
        let mut s = build(&kind);
        s.set_pattern(a.pattern()).unwrap();
        let mut x = vec![0.0; a.len()];
        let out = s.setup_and_solve(&a, &mut x);
        assert!(
            matches!(
                out,
                Err(LinSolveError::Singular { .. }) | Err(LinSolveError::NotSpd { .. })
            ),
            "{}: {out:?}",
            s.name()
        );
    }
    for kind in iterative_kinds(1e-8) {
        let mut s = build(&kind);
        s.set_pattern(a.pattern()).unwrap();
        let mut x = vec![0.0; a.len()];
        match s.setup_and_solve(&a, &mut x) {
            Err(_) => {}
            Ok(st) => {
                assert!(
                    !st.converged && st.rel_residual > 1e-3,
                    "{}: {st:?}",
                    s.name()
                );
                assert!(st.iterations <= 5000);
            }
        }
    }
}

#[test]
fn cholesky_and_cg_reject_non_spd() {
    let (m, _) = momentum_system(20, 10, 100.0, 1.0);
    let mut s = build(&LinearSolverKind::Cholesky);
    s.set_pattern(m.pattern()).unwrap();
    assert!(matches!(s.setup(&m), Err(LinSolveError::NotSpd { .. })));

    let (mut p, _) = pressure_system(20, 10);
    for v in [&mut p.a_p, &mut p.a_e, &mut p.a_w, &mut p.a_n, &mut p.a_s] {
        v.iter_mut().for_each(|c| *c = -*c); // negative definite
    }
    let mut s = build(&LinearSolverKind::MultigridCg(MultigridParams::default()));
    s.set_pattern(p.pattern()).unwrap();
    let mut x = vec![0.0; p.len()];
    assert!(matches!(
        s.setup_and_solve(&p, &mut x),
        Err(LinSolveError::NotSpd { .. })
    ));
}

#[test]
fn invalid_tolerance_is_an_error() {
    let p = Pattern::new(4, 4).unwrap();
    for rtol in [0.0, -1.0, f64::NAN, 1.5] {
        let mut s = build(&LinearSolverKind::BiCgStab {
            rtol,
            max_iter: 10,
            precond: Precond::Jacobi,
        });
        assert!(matches!(
            s.set_pattern(&p),
            Err(LinSolveError::InvalidParameter { .. })
        ));
    }
    assert!(Pattern::new(0, 3).is_err());
    let mut p = Pattern::new(4, 3).unwrap();
    assert!(p.fix(3, 2).is_ok() && p.kind(11) == CellKind::Fixed);
    assert!(matches!(
        p.fix(4, 0),
        Err(LinSolveError::DimensionMismatch { .. })
    ));
    assert!(matches!(
        p.fix(0, 3),
        Err(LinSolveError::DimensionMismatch { .. })
    ));
}

#[test]
fn csc_assembler_matches_stencil_matvec() {
    // no fixed cells: the reduced matrix is the full one
    let (a, exact) = momentum_system(17, 9, 30.0, 2.0);
    let mut asm = runout_linsolve::CscAssembler::new(a.pattern()).unwrap();
    let m = asm.matrix(&a).unwrap();
    let m = m.as_ref();
    let (col_ptr, row_idx, val) = (m.col_ptr(), m.row_idx(), m.val());
    let mut y_csc = vec![0.0; a.len()];
    for col in 0..a.len() {
        for p in col_ptr[col]..col_ptr[col + 1] {
            y_csc[row_idx[p]] += val[p] * exact[col];
        }
    }
    assert_eq!(val.len(), 5 * 17 * 9 - 2 * 17 - 2 * 9);
    for (u, v) in y_csc.iter().zip(&a.b) {
        assert!((u - v).abs() <= 1e-12 * v.abs().max(1.0));
    }
    assert_eq!(asm.reduced_rhs(&a).unwrap(), &a.b[..]);
}

#[test]
fn per_equation_defaults_reach_their_tolerance() {
    let (p, _) = pressure_system(120, 60);
    let (m, _) = momentum_system(120, 60, 100.0, 1.0);
    let (e, _) = momentum_system(120, 60, 1.0, 100.0); // diffusion dominated, like packed εs
    for (a, kind) in [
        (&p, LinearSolverKind::pressure_default()),
        (&m, LinearSolverKind::momentum_default()),
        (&m, LinearSolverKind::granular_energy_default()),
        (&e, LinearSolverKind::volume_fraction_default()),
    ] {
        let mut s = build(&kind);
        s.set_pattern(a.pattern()).unwrap();
        let mut x = vec![0.0; a.len()];
        let st = s.setup_and_solve(a, &mut x).unwrap();
        assert!(
            st.converged && st.rel_residual <= 1e-4,
            "{}: {st:?}",
            s.name()
        );
        assert!((st.rel_residual - independent_rel_residual(a, &x)).abs() <= 1e-9);
    }
}

#[test]
fn multigrid_robust_to_coefficient_jumps() {
    // a "packed bed" in the lower quarter where the pressure-correction coefficients
    // (∝ ε_g d_g) are 1e-6 times those above: same iteration count within 30 %
    let g = Grid::paper(141, 71);
    let exact = manufactured_solution(&g);
    let (nx, ny) = (g.nx(), g.ny());
    let ly = g.yf[ny];
    let factor = |j: usize, contrast: f64| if g.yc(j) < 0.25 * ly { contrast } else { 1.0 };
    let mut its = Vec::new();
    for contrast in [1.0, 1e-6] {
        let mut a = pressure_like(&g).unwrap();
        for j in 0..ny {
            for i in 0..nx {
                let k = i + nx * j;
                if a.pattern().kind(k) == CellKind::Fixed {
                    continue;
                }
                let f = factor(j, contrast);
                a.a_e[k] *= f;
                a.a_w[k] *= f;
                a.a_n[k] *= f.min(factor((j + 1).min(ny - 1), contrast));
                a.a_s[k] *= f.min(factor(j.saturating_sub(1), contrast));
                a.a_p[k] = a.a_e[k] + a.a_w[k] + a.a_n[k] + a.a_s[k];
            }
        }
        set_rhs_from_solution(&mut a, &exact).unwrap();
        let mut s = build(&LinearSolverKind::MultigridCg(MultigridParams::default()));
        s.set_pattern(a.pattern()).unwrap();
        let mut x = vec![0.0; a.len()];
        let st = s.setup_and_solve(&a, &mut x).unwrap();
        assert!(st.converged && independent_rel_residual(&a, &x) <= 1e-8);
        its.push(st.iterations as f64);
    }
    assert!(its[1] <= 1.3 * its[0], "iterations {its:?}");
}

/// The multigrid solves (flexible CG, and BiCGSTAB with the multigrid preconditioner) give
/// the same bits on pools of one, two and three threads: their team's chunks are fixed by
/// the vectors' lengths (src/team.rs). 300 × 150 cells puts level 0 on rayon-sized loops
/// and levels 1–2 on the team's smaller ones.
#[test]
fn multigrid_solves_are_the_same_on_any_number_of_threads() {
    let (p, _) = pressure_system(300, 150);
    let (m, _) = momentum_system(300, 150, 1.0, 100.0);
    let kinds = [
        (
            LinearSolverKind::MultigridCg(MultigridParams::default()),
            &p,
        ),
        (
            LinearSolverKind::BiCgStab {
                rtol: 1e-8,
                max_iter: 100,
                precond: Precond::MultigridK,
            },
            &m,
        ),
    ];
    for (kind, a) in kinds {
        let solve = |threads: usize| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            pool.install(|| {
                let mut s = build(&kind);
                s.set_pattern(a.pattern()).unwrap();
                let mut x = vec![0.0; a.len()];
                let stats = s.setup_and_solve(a, &mut x).unwrap();
                (x, stats.iterations)
            })
        };
        let (x1, it1) = solve(1);
        for threads in [2, 3] {
            let (x, it) = solve(threads);
            assert_eq!(it, it1, "{kind:?}: iterations on {threads} threads");
            let same = x.iter().zip(&x1).all(|(a, b)| a.to_bits() == b.to_bits());
            assert!(same, "{kind:?}: the solution differs on {threads} threads");
        }
    }
}
