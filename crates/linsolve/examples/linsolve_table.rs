//! Solve time and iterations of every backend on the pressure-like (SPD) and
//! momentum-like (non-symmetric) model systems at about 10k, 100k and 1M unknowns, printed
//! as a markdown table (the table in docs/studies/performance.md).
//!
//! Run: `cargo run --release -p runout-linsolve --example linsolve_table -- [--max-cells N] [--reps R] [--filter SUBSTRING]`
//! Runtime: about 1 min up to 100k cells; the 1M row adds a few minutes (2 cores).

use std::time::Duration;

use runout_linsolve::problems::{
    manufactured_solution, momentum_like, pressure_like, rel_error_inf, set_rhs_from_solution, Grid,
};
use runout_linsolve::{build, Cycle, LinearSolverKind, MultigridParams, Precond, Stencil5};

// ---- command line ---------------------------------------------------------------------
fn arg(name: &str, default: usize) -> usize {
    let args: Vec<String> = std::env::args().collect();
    args.iter()
        .position(|a| a == name)
        .and_then(|p| args.get(p + 1))
        .map(|v| v.parse().expect("integer argument"))
        .unwrap_or(default)
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

// ---- one measurement ------------------------------------------------------------------
fn run(
    system: &str,
    a: &Stencil5,
    exact: &[f64],
    kind: &LinearSolverKind,
    label: &str,
    reps: usize,
) {
    if let Some(f) = std::env::args().skip_while(|a| a != "--filter").nth(1) {
        if !format!("{system} {label}").contains(&f) {
            return;
        }
    }
    let mut solver = build(kind);
    let mut x = vec![0.0; a.len()];
    let t0 = std::time::Instant::now();
    if let Err(e) = solver.set_pattern(a.pattern()) {
        println!(
            "| {system} | {} | {label} | error: {e} | | | | | |",
            a.len()
        );
        return;
    }
    let t_pattern = t0.elapsed();
    let mut best: Option<runout_linsolve::SolveStats> = None;
    for _ in 0..reps {
        x.fill(0.0);
        match solver.setup_and_solve(a, &mut x) {
            Ok(s) => {
                if best.is_none_or(|b| s.t_setup + s.t_solve < b.t_setup + b.t_solve) {
                    best = Some(s);
                }
            }
            Err(e) => {
                println!(
                    "| {system} | {} | {label} | error: {e} | | | | | |",
                    a.len()
                );
                return;
            }
        }
    }
    let s = best.expect("reps ≥ 1");
    println!(
        "| {system} | {} | {label} | {}{} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1e} | {:.1e} |",
        a.len(),
        s.iterations,
        if s.converged { "" } else { " (cap)" },
        ms(t_pattern),
        ms(s.t_setup),
        ms(s.t_solve),
        ms(s.t_setup + s.t_solve),
        s.rel_residual,
        rel_error_inf(&x, exact),
    );
}

fn bicg(rtol: f64, max_iter: usize, precond: Precond) -> LinearSolverKind {
    LinearSolverKind::BiCgStab {
        rtol,
        max_iter,
        precond,
    }
}

fn mg(cycle: Cycle, rtol: f64) -> LinearSolverKind {
    LinearSolverKind::MultigridCg(MultigridParams {
        rtol,
        cycle,
        ..MultigridParams::default()
    })
}

fn main() {
    let max_cells = arg("--max-cells", 1_000_000);
    let reps_small = arg("--reps", 3);
    println!("| system | unknowns | backend | iterations | pattern ms | setup ms | solve ms | total ms | rel. residual | rel. error |");
    println!("|---|---|---|---|---|---|---|---|---|---|");
    for cells in [10_000usize, 100_000, 1_000_000] {
        if cells > max_cells {
            continue;
        }
        let big = cells >= 1_000_000;
        let reps = if big { 1 } else { reps_small };
        let grid = Grid::paper_with_cells(cells);
        eprintln!(
            "grid {} × {}, max aspect ratio {:.0}",
            grid.nx(),
            grid.ny(),
            grid.max_aspect_ratio()
        );
        let exact = manufactured_solution(&grid);
        let cap = 2000;
        pressure_rows(&grid, &exact, reps, big, cap);
        momentum_rows(&grid, &exact, reps, cap);
        diffusive_rows(&grid, &exact, reps, big, cap);
    }
}

/// The rows of the pressure-like (SPD) system.
fn pressure_rows(grid: &Grid, exact: &[f64], reps: usize, big: bool, cap: usize) {
    // ---- pressure-like (SPD) ----------------------------------------------------------
    let mut p = pressure_like(grid).expect("grid");
    set_rhs_from_solution(&mut p, exact).expect("sizes");
    let sys = "pressure";
    run(sys, &p, exact, &LinearSolverKind::SparseLu, "faer LU", reps);
    run(
        sys,
        &p,
        exact,
        &LinearSolverKind::Cholesky,
        "faer Cholesky",
        reps,
    );
    run(
        sys,
        &p,
        exact,
        &mg(Cycle::K, 1e-8),
        "AMG K-cycle + FCG, 1e-8",
        reps,
    );
    run(
        sys,
        &p,
        exact,
        &mg(Cycle::V, 1e-8),
        "AMG V-cycle + FCG, 1e-8",
        reps,
    );
    run(
        sys,
        &p,
        exact,
        &mg(Cycle::K, 1e-4),
        "AMG K-cycle + FCG, 1e-4",
        reps,
    );
    for (name, pc) in [
        ("AMG-K", Precond::MultigridK),
        ("AMG-V", Precond::MultigridV),
    ] {
        let label = format!("BiCGSTAB + {name}, 1e-8");
        run(sys, &p, exact, &bicg(1e-8, cap, pc), &label, reps);
    }
    if !big {
        // Jacobi/line/ILU(0) need O(√n)–O(n) iterations on an elliptic problem: hopeless at 1M
        run(
            sys,
            &p,
            exact,
            &bicg(1e-8, cap, Precond::Ilu0),
            "BiCGSTAB + ILU(0), 1e-8",
            reps,
        );
        run(
            sys,
            &p,
            exact,
            &bicg(1e-8, cap, Precond::LineY),
            "BiCGSTAB + line-y, 1e-8",
            reps,
        );
        run(
            sys,
            &p,
            exact,
            &bicg(1e-8, cap, Precond::Jacobi),
            "BiCGSTAB + Jacobi, 1e-8",
            reps,
        );
    }
    run(
        sys,
        &p,
        exact,
        &bicg(1e-4, 20, Precond::LineY),
        "BiCGSTAB + line-y, 1e-4, cap 20 (MFIX-like)",
        reps,
    );
    run(
        sys,
        &p,
        exact,
        &bicg(1e-4, 20, Precond::Ilu0),
        "BiCGSTAB + ILU(0), 1e-4, cap 20",
        reps,
    );
}

/// The rows of the momentum-like system (non-symmetric, cell Péclet 100, CFL 1).
fn momentum_rows(grid: &Grid, exact: &[f64], reps: usize, cap: usize) {
    // ---- momentum-like (non-symmetric, cell Péclet 100, CFL 1) -------------------------
    let mut m = momentum_like(grid, 100.0, 1.0).expect("grid");
    set_rhs_from_solution(&mut m, exact).expect("sizes");
    let sys = "momentum";
    run(sys, &m, exact, &LinearSolverKind::SparseLu, "faer LU", reps);
    for (rtol, cap_it) in [(1e-8, cap), (1e-4, cap)] {
        run(
            sys,
            &m,
            exact,
            &bicg(rtol, cap_it, Precond::Ilu0),
            &format!("BiCGSTAB + ILU(0), {rtol:.0e}"),
            reps,
        );
        run(
            sys,
            &m,
            exact,
            &bicg(rtol, cap_it, Precond::LineY),
            &format!("BiCGSTAB + line-y, {rtol:.0e}"),
            reps,
        );
        run(
            sys,
            &m,
            exact,
            &bicg(rtol, cap_it, Precond::Jacobi),
            &format!("BiCGSTAB + Jacobi, {rtol:.0e}"),
            reps,
        );
        run(
            sys,
            &m,
            exact,
            &bicg(rtol, cap_it, Precond::MultigridK),
            &format!("BiCGSTAB + AMG-K, {rtol:.0e}"),
            reps,
        );
    }
}

/// The rows of the diffusion-dominated non-symmetric system (cell Péclet 1, CFL 100).
fn diffusive_rows(grid: &Grid, exact: &[f64], reps: usize, big: bool, cap: usize) {
    // ---- diffusion-dominated non-symmetric (cell Péclet 1, CFL 100): like the
    // εs correction in a packed bed, where K_cp diffusion dominates ----------------------
    let mut e = momentum_like(grid, 1.0, 100.0).expect("grid");
    set_rhs_from_solution(&mut e, exact).expect("sizes");
    let sys = "diffusive-nsym";
    run(sys, &e, exact, &LinearSolverKind::SparseLu, "faer LU", reps);
    for (rtol, cap_it) in [(1e-8, cap), (1e-4, cap)] {
        if rtol < 1e-6 && big {
            continue; // hundreds of iterations at 1M: only the AMG rows below
        }
        for (name, pc) in [("ILU(0)", Precond::Ilu0), ("line-y", Precond::LineY)] {
            let label = format!("BiCGSTAB + {name}, {rtol:.0e}");
            run(sys, &e, exact, &bicg(rtol, cap_it, pc), &label, reps);
        }
    }
    for rtol in [1e-8, 1e-4] {
        for (name, pc) in [
            ("AMG-K", Precond::MultigridK),
            ("AMG-V", Precond::MultigridV),
        ] {
            let label = format!("BiCGSTAB + {name}, {rtol:.0e}");
            run(sys, &e, exact, &bicg(rtol, cap, pc), &label, reps);
        }
    }
}
