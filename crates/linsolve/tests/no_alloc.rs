//! The iterative solvers allocate nothing in `solve` once `set_pattern` and `setup` ran
//! (their work vectors are owned by the solver). Counted per thread with a global
//! allocator.

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use runout_linsolve::problems::{
    manufactured_solution, momentum_like, pressure_like, set_rhs_from_solution, Grid,
};
use runout_linsolve::{build, Cycle, LinearSolverKind, MultigridParams, Precond};

struct Counting;
thread_local! {
    /// allocations made by this thread (const-initialised: reading it never allocates)
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count() {
    // try_with: the slot may already be gone while a thread shuts down
    let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
}

fn allocations() -> usize {
    ALLOCATIONS.with(|c| c.get())
}

// SAFETY: forwards to the system allocator, only counting calls.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        System.realloc(ptr, layout, new_size)
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

#[test]
fn iterative_solves_do_not_allocate() {
    // 200 × 100 = 20k cells: above the parallel threshold, so rayon paths are exercised
    let g = Grid::paper(200, 100);
    let exact = manufactured_solution(&g);
    let mut p = pressure_like(&g).unwrap();
    set_rhs_from_solution(&mut p, &exact).unwrap();
    let mut m = momentum_like(&g, 100.0, 1.0).unwrap();
    set_rhs_from_solution(&mut m, &exact).unwrap();
    let mut kinds: Vec<(LinearSolverKind, bool)> = [
        Precond::None,
        Precond::Jacobi,
        Precond::Ilu0,
        Precond::LineY,
        Precond::MultigridV,
        Precond::MultigridK,
    ]
    .into_iter()
    .map(|precond| {
        let kind = LinearSolverKind::BiCgStab {
            rtol: 1e-8,
            max_iter: 50,
            precond,
        };
        (kind, false)
    })
    .collect();
    for cycle in [Cycle::K, Cycle::V] {
        let params = MultigridParams {
            cycle,
            ..MultigridParams::default()
        };
        kinds.push((LinearSolverKind::MultigridCg(params), true));
    }
    for (kind, pressure) in kinds {
        let a = if pressure { &p } else { &m };
        let mut s = build(&kind);
        s.set_pattern(a.pattern()).unwrap();
        s.setup(a).unwrap();
        let mut x = vec![0.0; a.len()];
        // Run inside the rayon pool, as the time loop will: a parallel call made from a
        // thread outside the pool goes through rayon's global injector queue, which
        // allocates a block every 63 jobs (not our allocation, and avoided this way).
        let (st, during) = rayon::ThreadPoolBuilder::new()
            .build()
            .unwrap()
            .install(|| {
                s.solve(a, &mut x).unwrap(); // warm-up: worker deques grow to their size
                x.fill(0.0);
                let before = allocations();
                let st = s.solve(a, &mut x).unwrap();
                (st, allocations() - before)
            });
        assert!(st.iterations > 0);
        assert_eq!(during, 0, "{} allocated {during} times in solve", s.name());
    }
}
