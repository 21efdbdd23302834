//! What the single-phase solver and the two-fluid gas do alike on a velocity component's
//! node block, written once and compiled per direction ([`Direction`]): the block's pattern
//! with the wall nodes fixed (docs/model.md §3.1), and the pressure correction's pattern and
//! update of the velocities (docs/model.md §4.6).

use runout_linsolve::{for_each_row, LinSolveError, Pattern};
use runout_mesh::{Grid, Sides};

use crate::direction::Direction;
use crate::side::SideBc;

/// The pattern of component `D`'s node block with the nodes on a wall end fixed (they hold
/// the zero normal velocity); an outlet end's nodes are unknowns, and on a periodic column
/// node 0 is the line's unknown and the high end's node its copy (fixed).
pub(crate) fn wall_pattern<D: Direction>(
    grid: &Grid,
    bcs: &Sides<SideBc>,
) -> Result<Pattern, LinSolveError> {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (n_a, n_b) = (D::along(grid).len(), D::across(grid).len());
    let mut pattern = Pattern::new(D::row_len(nx), D::pick(ny, ny + 1))?;
    let (low, high) = D::ends(bcs);
    let fix = |pattern: &mut Pattern, a: usize, b: usize| {
        let (i, j) = D::xy(a, b);
        pattern.fix(i, j)
    };
    for b in 0..n_b {
        if !low.is_outlet() && !D::periodic(grid) {
            fix(&mut pattern, 0, b)?;
        }
        if !high.is_outlet() {
            fix(&mut pattern, n_a, b)?;
        }
    }
    Ok(pattern)
}

/// The pattern of the pressure correction and whether it is pinned: a closed domain fixes
/// P' in cell 0 (its continuity follows from the others').
pub(crate) fn pressure_pattern(
    grid: &Grid,
    bcs: &Sides<SideBc>,
) -> Result<(Pattern, bool), LinSolveError> {
    let mut pattern = Pattern::new(grid.nx(), grid.ny())?;
    let pinned = !bcs.iter().any(|(_, b)| b.is_outlet());
    if pinned {
        pattern.fix(0, 0)?;
    }
    Ok((pattern, pinned))
}

/// φ += d (P'_low − P'_high) on every node of component `D` with d ≠ 0, P' = 0 beyond the
/// domain (docs/model.md §4.6); rows in parallel (each node's update is its own).
pub(crate) fn correct_velocity<D: Direction>(
    (nx, ny): (usize, usize),
    pc: &[f64],
    d: &[f64],
    phi: &mut [f64],
) {
    let n_a = D::pick(nx, ny);
    let mx = D::row_len(nx);
    for_each_row(phi, mx, |j, row| {
        for (i, phi) in row.iter_mut().enumerate() {
            let k = i + mx * j;
            if d[k] != 0.0 {
                let (a, b) = D::ab(i, j);
                let p_lo = if a == 0 {
                    0.0
                } else {
                    pc[D::cell(a - 1, b, nx)]
                };
                let p_hi = if a == n_a { 0.0 } else { pc[D::cell(a, b, nx)] };
                *phi += d[k] * (p_lo - p_hi);
            }
        }
    });
}
