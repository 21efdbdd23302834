//! Time per outer iteration of the multigrid-preconditioned CG on the pressure-like system
//! of an nx × ny paper-like grid, on the rayon pool's threads (set RAYON_NUM_THREADS).
//! The figures of docs/studies/performance.md, "The y lines split in two".
//!
//! Run: `RAYON_NUM_THREADS=2 cargo run --release -p runout-linsolve --example mg_threads -- 400 100 100`
//! (nx, ny, solves; about 2 s).

use runout_linsolve::problems::{
    manufactured_solution, pressure_like, set_rhs_from_solution, Grid,
};
use runout_linsolve::{build, LinearSolverKind, MultigridParams};

fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("usage: mg_threads NX NY SOLVES"))
        .collect();
    let [nx, ny, solves] = args[..] else {
        panic!("usage: mg_threads NX NY SOLVES");
    };
    let grid = Grid::paper(nx, ny);
    let exact = manufactured_solution(&grid);
    let mut a = pressure_like(&grid).expect("grid");
    set_rhs_from_solution(&mut a, &exact).expect("sizes");
    let mut solver = build(&LinearSolverKind::MultigridCg(MultigridParams {
        rtol: 1e-6,
        ..MultigridParams::default()
    }));
    solver.set_pattern(a.pattern()).expect("pattern");
    let mut x = vec![0.0; a.len()];
    solver.setup_and_solve(&a, &mut x).expect("first solve");
    let mut iterations = 0;
    let start = std::time::Instant::now();
    for _ in 0..solves {
        x.fill(0.0);
        iterations += solver.solve(&a, &mut x).expect("solve").iterations;
    }
    let seconds = start.elapsed().as_secs_f64();
    println!(
        "{nx} x {ny}, {} threads: {} iterations per solve, {:.1} µs per iteration",
        rayon::current_num_threads(),
        iterations / solves.max(1),
        seconds * 1e6 / iterations.max(1) as f64
    );
}
