//! Criterion benchmarks: setup (numeric factorisation / preconditioner) + solve of the
//! pressure-like and momentum-like model systems on paper-like stretched grids.
//!
//! `cargo bench -p runout-linsolve` runs 10k and 100k unknowns; set
//! `RUNOUT_BENCH_MAX_CELLS=1000000` to add 1M (slow). For a one-shot table over all
//! backends use the `linsolve_table` example instead.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use runout_linsolve::problems::{
    manufactured_solution, momentum_like, pressure_like, set_rhs_from_solution, Grid,
};
use runout_linsolve::{build, LinearSolverKind, MultigridParams, Precond, Stencil5};

fn sizes() -> Vec<usize> {
    let max: usize = std::env::var("RUNOUT_BENCH_MAX_CELLS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(100_000);
    [10_000, 100_000, 1_000_000]
        .into_iter()
        .filter(|&n| n <= max)
        .collect()
}

fn bench_system(
    c: &mut Criterion,
    group_name: &str,
    make: fn(&Grid) -> Stencil5,
    kinds: &[(&str, LinearSolverKind)],
) {
    let mut group = c.benchmark_group(group_name);
    group.sample_size(10);
    for cells in sizes() {
        let grid = Grid::paper_with_cells(cells);
        let exact = manufactured_solution(&grid);
        let mut a = make(&grid);
        set_rhs_from_solution(&mut a, &exact).expect("sizes");
        for (label, kind) in kinds {
            let mut solver = build(kind);
            solver.set_pattern(a.pattern()).expect("pattern");
            let mut x = vec![0.0; a.len()];
            group.bench_with_input(BenchmarkId::new(*label, a.len()), &a, |b, a| {
                b.iter(|| {
                    x.fill(0.0);
                    let st = solver.setup_and_solve(a, &mut x).expect("solve");
                    assert!(st.converged);
                    st.iterations
                })
            });
        }
    }
    group.finish();
}

fn pressure(c: &mut Criterion) {
    let kinds = [
        ("cholesky", LinearSolverKind::Cholesky),
        ("lu", LinearSolverKind::SparseLu),
        (
            "amg_k_fcg_1e-8",
            LinearSolverKind::MultigridCg(MultigridParams::default()),
        ),
        (
            "amg_k_fcg_1e-4",
            LinearSolverKind::MultigridCg(MultigridParams {
                rtol: 1e-4,
                ..MultigridParams::default()
            }),
        ),
    ];
    bench_system(c, "pressure", |g| pressure_like(g).expect("grid"), &kinds);
}

fn momentum(c: &mut Criterion) {
    let bicg = |rtol, precond| LinearSolverKind::BiCgStab {
        rtol,
        max_iter: 1000,
        precond,
    };
    let kinds = [
        ("lu", LinearSolverKind::SparseLu),
        ("bicgstab_ilu0_1e-4", bicg(1e-4, Precond::Ilu0)),
        ("bicgstab_ilu0_1e-8", bicg(1e-8, Precond::Ilu0)),
        ("bicgstab_line_y_1e-4", bicg(1e-4, Precond::LineY)),
        ("bicgstab_jacobi_1e-4", bicg(1e-4, Precond::Jacobi)),
    ];
    bench_system(
        c,
        "momentum",
        |g| momentum_like(g, 100.0, 1.0).expect("grid"),
        &kinds,
    );
}

criterion_group!(benches, pressure, momentum);
criterion_main!(benches);
