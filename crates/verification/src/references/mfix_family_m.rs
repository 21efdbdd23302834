//! MFIX 21.3.2's results for family M, the paper's slide on MFIX's own 200 × 50 grid with a
//! Johnson–Jackson floor (issue 9): the numbers of the case specification (cases.md,
//! "Family M"), measured by the MFIX run there, not re-measured here. The reference of
//! `cargo xtask verify mfix-slope` (docs/reports/mfix-slope.md).

/// MFIX's results: (t \[s\], front x \[m\], εs-weighted mean solids x-velocity ū_s \[m/s\]).
pub const MFIX: [(f64, f64, f64); 3] = [(0.3, 1.04, 1.25), (0.5, 1.66, 1.97), (0.8, 2.92, 3.01)];

/// MFIX's cost: CPU seconds per simulated second, serial, on MFIX's machine.
pub const MFIX_CPU_PER_SIMULATED_SECOND: f64 = 490.0;

/// MFIX's rejected steps over the 1 s run.
pub const MFIX_REJECTED: u64 = 72;
