//! Cost of the full closure set of one cell state (issue 3):
//! `cargo bench -p runout-closures --bench closures`.
//! Dense sheared Princeton cell with gas (Syamlal–O'Brien), the paper's parameters.

use criterion::{criterion_group, criterion_main, Criterion};
use runout_closures::{evaluate, CellState, ClosureParams, FrictionModel};
use std::hint::black_box;

fn full_closure_set(c: &mut Criterion) {
    let params = ClosureParams::default();
    let state = CellState {
        eps_s: 0.6,
        theta: 0.01,
        slip: 0.3,
        tr_d: -0.5,
        s_ddot_s: 100.0,
    };
    c.bench_function("closure set, one cell (Princeton, Syamlal-O'Brien)", |b| {
        b.iter(|| evaluate(black_box(&state), black_box(&params)))
    });
    let dilute = CellState {
        eps_s: 0.01,
        ..state
    };
    c.bench_function(
        "closure set, one dilute cell (no friction evaluated)",
        |b| b.iter(|| evaluate(black_box(&dilute), black_box(&params))),
    );
    let schaeffer = ClosureParams {
        friction_model: FrictionModel::schaeffer(),
        ..params
    };
    c.bench_function("closure set, one cell (Schaeffer)", |b| {
        b.iter(|| evaluate(black_box(&state), black_box(&schaeffer)))
    });
}

criterion_group!(benches, full_closure_set);
criterion_main!(benches);
