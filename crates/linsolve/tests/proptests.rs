//! Property tests on random small diagonally dominant systems with random fixed cells.
#![allow(clippy::needless_range_loop)] // several parallel arrays indexed by cell

use proptest::prelude::*;
use runout_linsolve::{build, CellKind, LinearSolverKind, Pattern, Precond, Stencil5};

fn system() -> impl Strategy<Value = Stencil5> {
    (1usize..12, 1usize..12).prop_flat_map(|(nx, ny)| {
        let n = nx * ny;
        (
            proptest::collection::vec(0.0f64..1.0, 4 * n),
            proptest::collection::vec(-1.0f64..1.0, n),
            proptest::collection::vec(0.0f64..1.0, n),
            proptest::collection::vec(any::<bool>(), n),
        )
            .prop_map(move |(links, b, extra, fix)| {
                // at most a quarter of the cells fixed
                let pattern = Pattern::from_fn(nx, ny, |i, j| {
                    let k = i + nx * j;
                    if fix[k] && k % 4 == 0 {
                        CellKind::Fixed
                    } else {
                        CellKind::Active
                    }
                })
                .unwrap();
                let mut a = Stencil5::new(pattern);
                for k in 0..n {
                    a.a_e[k] = links[4 * k];
                    a.a_w[k] = links[4 * k + 1];
                    a.a_n[k] = links[4 * k + 2];
                    a.a_s[k] = links[4 * k + 3];
                    // strictly diagonally dominant ⇒ non-singular
                    a.a_p[k] = links[4 * k..4 * k + 4].iter().sum::<f64>() + 0.1 + extra[k];
                    a.b[k] = b[k];
                }
                a
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// LU and preconditioned BiCGSTAB agree (also on 1 × n and n × 1 blocks) and both satisfy the full system (fixed cells included).
    #[test]
    fn direct_and_iterative_agree(a in system()) {
        let mut x_lu = vec![0.0; a.len()];
        let mut lu = build(&LinearSolverKind::SparseLu);
        lu.set_pattern(a.pattern()).unwrap();
        let st = lu.setup_and_solve(&a, &mut x_lu).unwrap();
        prop_assert!(st.rel_residual < 1e-12);
        for precond in [Precond::Ilu0, Precond::LineY, Precond::MultigridV, Precond::MultigridK] {
            let mut x_it = vec![0.0; a.len()];
            let mut it = build(&LinearSolverKind::BiCgStab { rtol: 1e-12, max_iter: 500, precond });
            it.set_pattern(a.pattern()).unwrap();
            let st = it.setup_and_solve(&a, &mut x_it).unwrap();
            prop_assert!(st.converged && st.rel_residual <= 1e-12, "{:?}: {:?}", precond, st);
            for (u, v) in x_lu.iter().zip(&x_it) {
                prop_assert!((u - v).abs() < 1e-9 * (1.0 + u.abs()));
            }
        }
        for k in 0..a.len() {
            if a.pattern().kind(k) == CellKind::Fixed {
                prop_assert_eq!(x_lu[k], a.b[k] / a.a_p[k]);
            }
        }
    }
}
