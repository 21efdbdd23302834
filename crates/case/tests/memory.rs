//! The size and memory estimate of a case (issue 21): computed from the segments without
//! building the grid, proportional to the cells, larger for the two-fluid model.

use std::path::Path;

use runout_case::{
    available_memory_bytes, case_size, estimated_memory_bytes, load, Fidelity, Loaded,
};

fn case(rel: &str) -> runout_case::Case {
    let file = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel);
    match load(&file).unwrap() {
        Loaded::Cases(mut c) => c.remove(0).case,
        Loaded::Analytic(_) => unreachable!(),
    }
}

#[test]
fn estimate_follows_cells_and_phases() {
    let slide = case("cases/mfix-slope/jj.ron");
    let s = case_size(&slide).unwrap();
    assert_eq!((s.nx, s.ny, s.cells), (200, 50, 10_000));
    assert_eq!(s.unknowns, 10_000 * 7);
    // measured peak 32 504 KiB for this grid with a checkpoint written (issue 44; 26 880
    // KiB without): the estimate is within 15 % above
    let measured = 32_504.0 * 1024.0;
    let ratio = s.memory_bytes as f64 / measured;
    assert!((1.0..1.15).contains(&ratio), "{ratio}");
    assert_eq!(estimated_memory_bytes(&slide), s.memory_bytes);
    // the cavity (gas only) at 64 x 64: 3 unknowns per cell, less memory per cell
    let cavity = case("examples/cavity-re100.ron");
    let c = case_size(&cavity).unwrap();
    assert_eq!((c.cells, c.unknowns), (4096, 3 * 4096));
    let per_cell = |a: &runout_case::CaseSize, b: &runout_case::CaseSize| {
        (a.memory_bytes - b.memory_bytes) as f64 / (a.cells - b.cells) as f64
    };
    let smoke = case_size(&slide.at_fidelity(Fidelity::Smoke)).unwrap();
    let cavity_smoke = case_size(&cavity.at_fidelity(Fidelity::Smoke)).unwrap();
    assert!(per_cell(&s, &smoke) > 2.2 * 1000.0);
    assert!(per_cell(&c, &cavity_smoke) < 1100.0);
}

#[test]
fn a_grid_over_the_cap_is_estimated_without_being_built() {
    let mut big = case("cases/mfix-slope/jj.ron");
    if let runout_mesh::Segment::Uniform { cells, .. } = &mut big.domain.x.segments[0] {
        *cells = 40_000;
    }
    if let runout_mesh::Segment::Uniform { cells, .. } = &mut big.domain.y.segments[0] {
        *cells = 25_000;
    }
    // ~1.95 TB: far more than any machine here has
    let bytes = estimated_memory_bytes(&big);
    assert!(bytes > 1_900_000_000_000, "{bytes}");
    if let Some(avail) = available_memory_bytes() {
        assert!(avail > 0 && bytes > avail);
    }
}
