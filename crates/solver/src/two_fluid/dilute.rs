//! The DIL_EP_S rules of the two-fluid stages (docs/model.md §2.7, §4.8) and the two
//! safeguards of the outer iteration that damp a period-2 cycle (not in MFIX,
//! docs/model.md §0.4).
//!
//! - A solids velocity node whose interpolated εs ≤ DIL_EP_S carries no solids momentum
//!   (MFIX `source_u_s.f`, docs/model.md §2.7): its row becomes the mean of its neighbour
//!   nodes whose test cell is dense, and of its own value ([`dilute_faces`], [`dilute_row`]).
//! - The θ row of a cell with εs ≤ DIL_EP_S is the mean θ of its dense neighbour cells
//!   (MFIX `source_phi.f`, docs/model.md §4.8; [`dilute_cell_row`]); a cell whose class
//!   changes back within a step may be frozen dilute ([`next_dilute_class`]).
//! - A state-dependent wall closure whose slip coefficient turns back between outer
//!   iterations may be under-relaxed ([`turns_back`], [`relax_face`]).

use runout_linsolve::Stencil5;
use runout_walls::RobinFace;

use super::DIL_EP_S;
use crate::momentum::{fixed_row, RowCoefficients};
use crate::staggered::Component;
use runout_mesh::Grid;

/// Marks the dilute velocity nodes of a solids phase, component `c`: εs interpolated to
/// the face (AVG_X / AVG_Y; the one cell's value on a boundary face) ≤ DIL_EP_S
/// (docs/model.md §2.7, MFIX `source_u_s.f`). Fixed (wall) nodes are not dilute: their rows
/// are fixed anyway.
pub(super) fn dilute_faces(
    grid: &Grid,
    c: Component,
    eps: &[f64],
    fixed: &[bool],
    out: &mut [bool],
) {
    let axis = c.axis(grid);
    for j in 0..c.my {
        for i in 0..c.mx {
            let k = i + c.mx * j;
            let [lo, hi] = c
                .cells(i, j, false)
                .map(|cell| cell.map(|(ci, cj)| ci + c.nx * cj));
            let w = if c.interior(i, j) {
                axis.interpolation_weight(c.pick(i, j) - 1)
            } else {
                0.5
            };
            let eps_face = match (lo, hi) {
                (Some(a), Some(b)) => w * eps[a] + (1.0 - w) * eps[b],
                (Some(c), None) | (None, Some(c)) => eps[c],
                (None, None) => 0.0,
            };
            out[k] = !fixed[k] && eps_face <= DIL_EP_S;
        }
    }
}

/// The row of a dilute solids velocity node (i, j) of component `c` (docs/model.md §2.7,
/// MFIX `source_u_s.f`): the mean of its neighbour nodes whose test cell — the neighbour of
/// the node's low-side cell `cell` = (ci, cj) in that direction (MFIX's IJK) — holds
/// εs > DIL_EP_S, and of its own current value; with no such neighbour the node keeps
/// `current`. Neighbours on fixed (wall) nodes do not count.
pub(super) fn dilute_row(
    a: &mut Stencil5,
    c: Component,
    (i, j): (usize, usize),
    current: f64,
    cell: Option<(usize, usize)>,
    eps: &[f64],
) {
    let (mx, my, nx, ny) = (c.mx, c.my, c.nx, c.ny);
    let k = i + mx * j;
    fixed_row(a, k, current);
    let Some((ci, cj)) = cell else {
        return;
    };
    let dense = |ti: Option<usize>, tj: Option<usize>| match (ti, tj) {
        (Some(ti), Some(tj)) if ti < nx && tj < ny => eps[ti + nx * tj] > DIL_EP_S,
        _ => false,
    };
    // (neighbour node exists, its test cell is dense)
    let west = i > 0 && dense(ci.checked_sub(1), Some(cj));
    let east = i + 1 < mx && dense(Some(ci + 1), Some(cj));
    let south = j > 0 && dense(Some(ci), cj.checked_sub(1));
    let north = j + 1 < my && dense(Some(ci), Some(cj + 1));
    let fixed = a.pattern().fixed_mask();
    let (west, east, south, north) = (
        west && !fixed[k - 1],
        east && !fixed[k + 1],
        south && !fixed[k - mx],
        north && !fixed[k + mx],
    );
    // the node's own current value counts once as well: two dilute nodes that would only
    // average each other otherwise form a singular pair (MFIX's plain mean has no self term)
    if let Some(mean) = mean_row([west, east, south, north], Some(current)) {
        mean.put(a, k);
    }
}

/// The row of the plain mean of the neighbours flagged (west, east, south, north), plus
/// the node's `own` value once if given; `None` if no neighbour is flagged.
pub(super) fn mean_row(
    [west, east, south, north]: [bool; 4],
    own: Option<f64>,
) -> Option<RowCoefficients> {
    let count = [west, east, south, north].iter().filter(|&&x| x).count();
    if count == 0 {
        return None;
    }
    let one = |flag: bool| if flag { 1.0 } else { 0.0 };
    Some(RowCoefficients {
        a_p: count as f64 + one(own.is_some()),
        a_e: one(east),
        a_w: one(west),
        a_n: one(north),
        a_s: one(south),
        b: own.unwrap_or(0.0),
    })
}

/// The cycle watch of one wall node's momentum closure
/// ([`super::TwoFluidSettings::relax_wall_closures_oscillating_only`]).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct ClosureCycle {
    /// the change of the closure's h applied at the last outer iteration
    pub last_change: f64,
    /// whether it has cycled in this time step (it then stays relaxed until the step ends)
    pub cycling: bool,
}

/// A wall node's closure is cycling when its change turns back at more than this fraction of
/// the previous change (an alternating iteration that contracts faster converges unaided).
pub(super) const CYCLE_CONTRACTION: f64 = 0.5;

/// Whether a closure coefficient's `change` at this outer iteration turns back from the
/// previous iteration's `last` without contracting below [`CYCLE_CONTRACTION`] of it: the
/// mark of a period-2 cycle.
pub(super) fn turns_back(change: f64, last: f64) -> bool {
    change * last < 0.0 && change.abs() > CYCLE_CONTRACTION * last.abs()
}

/// Under-relaxed wall closure: ω·`new` + (1 − ω)·`old` in each coefficient
/// ([`super::TwoFluidSettings::relax_wall_closures`]).
pub(super) fn relax_face(new: RobinFace, old: RobinFace, w: f64) -> RobinFace {
    if w >= 1.0 {
        return new;
    }
    RobinFace {
        g: w * new.g + (1.0 - w) * old.g,
        h: w * new.h + (1.0 - w) * old.h,
        c: w * new.c + (1.0 - w) * old.c,
    }
}

/// How often a cell's θ-row class may change within a step before it is frozen dilute
/// ([`super::TwoFluidSettings::freeze_cycling_dilute_class`]): the second change is a change back.
pub(super) const DILUTE_CLASS_CHANGES: u8 = 2;

/// The θ-row class of a cell at this outer iteration, given its class by the current εs
/// (`dense_now`), its class at the last iteration (`dense`, updated) and its class changes
/// within the step (`changes`, updated): it follows εs until it has changed
/// [`DILUTE_CLASS_CHANGES`] times (dense → dilute → dense, or dilute → dense → dilute: a
/// cycle), then stays dilute.
pub(super) fn next_dilute_class(dense_now: bool, dense: &mut bool, changes: &mut u8) {
    if *changes < DILUTE_CLASS_CHANGES && dense_now != *dense {
        *dense = dense_now;
        *changes += 1;
        if *changes == DILUTE_CLASS_CHANGES {
            // frozen dilute: the cell is at the threshold, and a dense θ row there keeps
            // its face velocities and εs cycling (coarse flume to 0.55 s, rejected steps:
            // MFIX's iteration 53, frozen in the class it returned to 42, frozen dilute 25)
            *dense = false;
        }
    }
}

/// The θ row of dilute cell (i, j): the plain mean of its neighbour cells of the dense
/// class (εs > DIL_EP_S), or `current` if there are none (docs/model.md §4.8).
pub(super) fn dilute_cell_row(
    (i, j): (usize, usize),
    current: f64,
    dense_class: &[bool],
    nx: usize,
) -> RowCoefficients {
    let (n, k) = (dense_class.len(), i + nx * j);
    let dense = |c: usize| dense_class[c];
    let west = i > 0 && dense(k - 1);
    let east = i + 1 < nx && dense(k + 1);
    let south = j > 0 && dense(k - nx);
    let north = k + nx < n && dense(k + nx);
    mean_row([west, east, south, north], None).unwrap_or(RowCoefficients::fixed(current))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The classes a cell's θ row takes over a step's outer iterations, given its class by
    /// εs at each (the first iteration classifies afresh, as the solver does).
    fn classes(by_eps: &[bool]) -> Vec<bool> {
        let (mut dense, mut changes) = (by_eps[0], 0);
        let mut out = vec![dense];
        for &now in &by_eps[1..] {
            next_dilute_class(now, &mut dense, &mut changes);
            out.push(dense);
        }
        out
    }

    #[test]
    fn a_cycling_dilute_class_is_frozen_after_changing_back() {
        // the flume's cell (55, 10): dense, dilute, dense, ... is frozen dilute at the 3rd
        assert_eq!(
            classes(&[true, false, true, false, true, false]),
            [true, false, false, false, false, false]
        );
        assert_eq!(
            classes(&[false, true, false, true, true]),
            [false, true, false, false, false]
        );
        // a cell that becomes dense once follows εs, as MFIX's iteration
        assert_eq!(
            classes(&[false, false, true, true, true]),
            [false, false, true, true, true]
        );
        assert_eq!(classes(&[true, false, false]), [true, false, false]);
    }

    #[test]
    fn a_cycle_is_a_change_that_turns_back_without_contracting() {
        // period 2: h alternates between two values
        assert!(turns_back(-1.0, 1.0));
        assert!(turns_back(0.6, -1.0));
        // an alternating iteration contracting by more than half converges unaided
        assert!(!turns_back(-0.4, 1.0));
        // monotone, the first iteration, and no change
        assert!(!turns_back(0.9, 1.0));
        assert!(!turns_back(1.0, 0.0));
        assert!(!turns_back(0.0, 1.0));
        // the relaxation itself: ω = 0.5 averages the coefficients
        let (a, b) = (
            RobinFace::partial_slip(4.0, 0.0),
            RobinFace::partial_slip(2.0, 0.0),
        );
        let r = relax_face(a, b, 0.5);
        assert_eq!((r.g, r.h, r.c), (1.0, 3.0, 0.0));
        assert_eq!(relax_face(a, b, 1.0), a);
    }
}
