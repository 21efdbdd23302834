//! Solving only the rectangle where rows are coupled.
//!
//! In a slide most of the domain holds no solids: there the rows of the solids momentum,
//! ε′ and θ equations have no links (a dilute node or cell keeps its value, docs/model.md
//! §2.7, §4.8), `a_P φ_P = b`, and each is solved exactly by φ_P = b/a_P. [`ActiveBox`]
//! finds the smallest rectangle of the block that holds every row with a link (a fixed row's
//! links do not count, the solvers ignore them), solves the rows outside it exactly, moves
//! their values into the right-hand side of the rows inside that link to them,
//!
//! $$ b_k \leftarrow b_k + a_{nb}\, φ_{nb} \quad (nb \text{ outside the rectangle}), $$
//!
//! and gives the rectangle to an inner solver of the same kind. The system is the same; the
//! work scales with the rectangle instead of the block (family M: 3–18 % of its cells hold
//! coupled solids rows over the slide, docs/history/performance-log.md,
//! "The coupled rectangle, mass fluxes once, θ's dilute rows skipped").
//!
//! What differs from solving the whole block: the inner solver's stopping test is relative
//! to the rectangle's right-hand side (with the moved terms) instead of the block's; the
//! rows outside contribute nothing to the residual, being solved exactly. A rectangle larger
//! than [`MAX_FRACTION`] of the block is not worth the copies: the whole block is solved.
//! The rectangle is aligned outwards to [`ALIGN_X`] × [`ALIGN_Y`] cells and kept while it
//! still holds the coupled rows and is at most [`KEEP_SLACK`] times the aligned area needed,
//! so that the inner solver's work storage is reallocated only as the flow spreads.

use std::time::Instant;

use rayon::prelude::*;

use crate::stencil::{for_each_row, rows_per_task};
use crate::{build, LinSolveError, LinearSolver, LinearSolverKind, Pattern, SolveStats, Stencil5};

/// Alignment of the rectangle's x bounds [cells].
pub const ALIGN_X: usize = 8;
/// Alignment of the rectangle's y bounds [cells].
pub const ALIGN_Y: usize = 4;
/// Largest rectangle solved apart, as a fraction of the block's cells.
pub const MAX_FRACTION: f64 = 0.5;
/// A rectangle kept from an earlier set-up may be up to this many times the aligned area
/// the coupled rows need.
pub const KEEP_SLACK: usize = 2;

/// The cells `i0 ≤ i < i1`, `j0 ≤ j < j1` of a block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rect {
    /// first column
    pub i0: usize,
    /// one past the last column
    pub i1: usize,
    /// first row
    pub j0: usize,
    /// one past the last row
    pub j1: usize,
}

impl Rect {
    /// Columns of the rectangle.
    pub fn nx(&self) -> usize {
        self.i1 - self.i0
    }
    /// Rows of the rectangle.
    pub fn ny(&self) -> usize {
        self.j1 - self.j0
    }
    /// Cells of the rectangle.
    pub fn area(&self) -> usize {
        self.nx() * self.ny()
    }
    /// Whether `other` lies inside this rectangle.
    pub fn contains(&self, other: &Rect) -> bool {
        self.i0 <= other.i0 && other.i1 <= self.i1 && self.j0 <= other.j0 && other.j1 <= self.j1
    }
    /// The rectangle grown outwards to multiples of (`ax`, `ay`) cells, within `nx × ny`.
    fn aligned(&self, (ax, ay): (usize, usize), (nx, ny): (usize, usize)) -> Rect {
        Rect {
            i0: self.i0 / ax * ax,
            i1: self.i1.div_ceil(ax) * ax,
            j0: self.j0 / ay * ay,
            j1: self.j1.div_ceil(ay) * ay,
        }
        .clamped((nx, ny))
    }
    fn clamped(self, (nx, ny): (usize, usize)) -> Rect {
        Rect {
            i1: self.i1.min(nx),
            j1: self.j1.min(ny),
            ..self
        }
    }
}

/// The smallest rectangle holding every row of `a` with a non-zero link (fixed rows
/// excluded); `None` if no row has one. Rows in parallel: the bounds are minima and maxima,
/// the same in any order.
pub fn coupled_rect(a: &Stencil5) -> Option<Rect> {
    let (nx, ny) = (a.pattern().nx(), a.pattern().ny());
    let fixed = a.pattern().fixed_mask();
    let row_rect = |j: usize| {
        // the row's slices, so that the scans below carry no bounds checks
        let row = nx * j..nx * (j + 1);
        let (ae, aw, an, as_) = (
            &a.a_e[row.clone()],
            &a.a_w[row.clone()],
            &a.a_n[row.clone()],
            &a.a_s[row.clone()],
        );
        let fixed = &fixed[row];
        let linked = |i: usize| {
            ((ae[i] != 0.0) | (aw[i] != 0.0) | (an[i] != 0.0) | (as_[i] != 0.0)) & !fixed[i]
        };
        let first = (0..nx).position(linked)?;
        let last = (first..nx).rposition(linked).map_or(first, |p| first + p);
        Some(Rect {
            i0: first,
            i1: last + 1,
            j0: j,
            j1: j + 1,
        })
    };
    (0..ny)
        .into_par_iter()
        .with_min_len(rows_per_task(nx))
        .filter_map(row_rect)
        .reduce_with(|a, b| Rect {
            i0: a.i0.min(b.i0),
            i1: a.i1.max(b.i1),
            j0: a.j0.min(b.j0),
            j1: a.j1.max(b.j1),
        })
}

/// What the last set-up chose.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    /// not set up
    None,
    /// the whole block by the inner solver
    Whole,
    /// no row has a link: every row solved exactly
    Diagonal,
    /// the rectangle by the inner solver, the rest exactly
    Part(Rect),
}

/// A solver of any [`LinearSolverKind`] that solves only the rectangle of coupled rows
/// (module doc).
pub struct ActiveBox {
    whole: Box<dyn LinearSolver>,
    part: Box<dyn LinearSolver>,
    pattern: Option<Pattern>,
    mode: Mode,
    /// the rectangle the part solver's pattern and `sub` were made for
    part_rect: Option<Rect>,
    sub: Option<Stencil5>,
    x_sub: Vec<f64>,
    /// scratch of the block's size (the residual of a diagonal solve)
    work: Vec<f64>,
}

impl ActiveBox {
    /// Two solvers of `kind`: one for the whole block, one for the rectangles.
    pub fn new(kind: &LinearSolverKind) -> Self {
        Self {
            whole: build(kind),
            part: build(kind),
            pattern: None,
            mode: Mode::None,
            part_rect: None,
            sub: None,
            x_sub: Vec::new(),
            work: Vec::new(),
        }
    }

    /// The rectangle the last set-up solves apart, `None` when it solves the whole block or
    /// no row has a link.
    pub fn rect(&self) -> Option<Rect> {
        match self.mode {
            Mode::Part(r) => Some(r),
            _ => None,
        }
    }

    fn pattern(&self) -> Result<&Pattern, LinSolveError> {
        self.pattern
            .as_ref()
            .ok_or(LinSolveError::NotReady("set_pattern"))
    }

    /// The mode for `a`: the rectangle of coupled rows, aligned, or the one kept.
    fn choose(&self, a: &Stencil5) -> Mode {
        let (nx, ny) = (a.pattern().nx(), a.pattern().ny());
        let Some(needed) = coupled_rect(a) else {
            return Mode::Diagonal;
        };
        let aligned = needed.aligned((ALIGN_X, ALIGN_Y), (nx, ny));
        let rect = match self.part_rect {
            Some(kept) if kept.contains(&needed) && kept.area() <= KEEP_SLACK * aligned.area() => {
                kept
            }
            _ => aligned,
        };
        if rect.area() as f64 > MAX_FRACTION * (nx * ny) as f64 {
            Mode::Whole
        } else {
            Mode::Part(rect)
        }
    }

    /// Copies the rectangle's coefficients into `sub` (links out of it zero), making the
    /// part solver's pattern first if the rectangle changed; checks the rows outside.
    fn fill_part(&mut self, a: &Stencil5, r: Rect) -> Result<(), LinSolveError> {
        check_outside_diagonal(a, Some(r))?;
        if self.part_rect != Some(r) || self.sub.is_none() {
            let full = a.pattern();
            let pattern = Pattern::from_fn(r.nx(), r.ny(), |i, j| {
                full.kind(full.idx(r.i0 + i, r.j0 + j))
            })?;
            self.part.set_pattern(&pattern)?;
            self.sub = Some(Stencil5::new(pattern));
            self.x_sub = vec![0.0; r.area()];
            self.part_rect = Some(r);
        }
        let sub = self.sub.as_mut().expect("made above");
        let nx = a.pattern().nx();
        let snx = r.nx();
        sub.par_fill_rows(|js, row| {
            let k0 = r.i0 + nx * (r.j0 + js);
            let cells = k0..k0 + snx;
            row.a_p.copy_from_slice(&a.a_p[cells.clone()]);
            row.a_e.copy_from_slice(&a.a_e[cells.clone()]);
            row.a_w.copy_from_slice(&a.a_w[cells.clone()]);
            row.a_n.copy_from_slice(&a.a_n[cells.clone()]);
            row.a_s.copy_from_slice(&a.a_s[cells]);
            // links out of the rectangle are moved to b in `solve`
            row.a_w[0] = 0.0;
            row.a_e[snx - 1] = 0.0;
        });
        let sny = r.ny();
        sub.a_s[..snx].iter_mut().for_each(|v| *v = 0.0);
        sub.a_n[snx * (sny - 1)..].iter_mut().for_each(|v| *v = 0.0);
        Ok(())
    }

    /// The right-hand side of the rectangle: b plus the links to the rows outside, whose
    /// values `x` already holds (module doc).
    fn part_rhs(&mut self, a: &Stencil5, x: &[f64], r: Rect) {
        let sub = self.sub.as_mut().expect("set up");
        let (nx, ny) = (a.pattern().nx(), a.pattern().ny());
        let fixed = a.pattern().fixed_mask();
        let snx = r.nx();
        for_each_row(&mut sub.b, snx, |js, sub_b| {
            let j = r.j0 + js;
            for i in r.i0..r.i1 {
                let k = i + nx * j;
                let mut b = a.b[k];
                if !fixed[k] {
                    if i == r.i0 && i > 0 && a.a_w[k] != 0.0 {
                        b += a.a_w[k] * x[k - 1];
                    }
                    if i + 1 == r.i1 && i + 1 < nx && a.a_e[k] != 0.0 {
                        b += a.a_e[k] * x[k + 1];
                    }
                    if j == r.j0 && j > 0 && a.a_s[k] != 0.0 {
                        b += a.a_s[k] * x[k - nx];
                    }
                    if j + 1 == r.j1 && j + 1 < ny && a.a_n[k] != 0.0 {
                        b += a.a_n[k] * x[k + nx];
                    }
                }
                sub_b[i - r.i0] = b;
            }
        });
    }

    /// The index in the block of the rectangle's cell `s`, for an error of the part solver.
    fn to_block(r: Rect, nx: usize) -> impl Fn(LinSolveError) -> LinSolveError {
        move |e| {
            let map = |s: usize| (r.i0 + s % r.nx()) + nx * (r.j0 + s / r.nx());
            match e {
                LinSolveError::NonFinite { what, cell } => LinSolveError::NonFinite {
                    what,
                    cell: map(cell),
                },
                LinSolveError::ZeroDiagonal { cell } => {
                    LinSolveError::ZeroDiagonal { cell: map(cell) }
                }
                other => other,
            }
        }
    }
}

/// The index ranges of row j's cells outside `r` (the whole row if `None`) in an `nx`-wide
/// block.
fn outside_of_row(nx: usize, j: usize, r: Option<Rect>) -> [std::ops::Range<usize>; 2] {
    let row = nx * j;
    match r {
        Some(r) if (r.j0..r.j1).contains(&j) => [row..row + r.i0, row + r.i1..row + nx],
        _ => [row..row + nx, 0..0],
    }
}

/// Every row outside `r` (all rows if `None`) has a finite, non-zero a_P: its exact solve
/// needs nothing else (its links are zero, or it is fixed). Rows in parallel; the error
/// names the first such cell, as a serial scan would.
fn check_outside_diagonal(a: &Stencil5, r: Option<Rect>) -> Result<(), LinSolveError> {
    let (nx, ny) = (a.pattern().nx(), a.pattern().ny());
    let bad_in_row = |j: usize| {
        outside_of_row(nx, j, r).into_iter().find_map(|range| {
            let start = range.start;
            let s = a.a_p[range]
                .iter()
                .position(|d| !d.is_finite() || *d == 0.0)?;
            let cell = start + s;
            Some(if a.a_p[cell] == 0.0 {
                LinSolveError::ZeroDiagonal { cell }
            } else {
                LinSolveError::NonFinite { what: "a_p", cell }
            })
        })
    };
    match (0..ny)
        .into_par_iter()
        .with_min_len(rows_per_task(nx))
        .find_map_first(bad_in_row)
    {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// x = b/a_P on every row outside `r` (all rows if `None`), rows in parallel; a non-finite
/// b is reported at the first such cell, as a serial pass would.
fn solve_outside(a: &Stencil5, x: &mut [f64], r: Option<Rect>) -> Result<(), LinSolveError> {
    let nx = a.pattern().nx();
    let solve_row = |(j, x_row): (usize, &mut [f64])| {
        for range in outside_of_row(nx, j, r)
            .into_iter()
            .filter(|c| !c.is_empty())
        {
            let start = range.start;
            let (b, d) = (&a.b[range.clone()], &a.a_p[range.clone()]);
            if let Some(s) = b.iter().position(|b| !b.is_finite()) {
                return Some(LinSolveError::NonFinite {
                    what: "b",
                    cell: start + s,
                });
            }
            let local = range.start - nx * j..range.end - nx * j;
            for ((x, b), d) in x_row[local].iter_mut().zip(b).zip(d) {
                *x = b / d;
            }
        }
        None
    };
    match x
        .par_chunks_mut(nx)
        .enumerate()
        .with_min_len(rows_per_task(nx))
        .find_map_first(solve_row)
    {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

impl LinearSolver for ActiveBox {
    fn name(&self) -> String {
        format!("{} on the coupled rectangle", self.whole.name())
    }

    fn set_pattern(&mut self, pattern: &Pattern) -> Result<(), LinSolveError> {
        self.whole.set_pattern(pattern)?;
        self.pattern = Some(pattern.clone());
        self.work = vec![0.0; pattern.len()];
        (self.mode, self.part_rect, self.sub) = (Mode::None, None, None);
        Ok(())
    }

    fn setup(&mut self, a: &Stencil5) -> Result<(), LinSolveError> {
        if a.pattern() != self.pattern()? {
            return Err(LinSolveError::PatternMismatch);
        }
        self.mode = Mode::None;
        let mode = self.choose(a);
        match mode {
            Mode::Whole => self.whole.setup(a)?,
            Mode::Diagonal => check_outside_diagonal(a, None)?,
            Mode::Part(r) => {
                self.fill_part(a, r)?;
                let sub = self.sub.as_ref().expect("filled");
                self.part
                    .setup(sub)
                    .map_err(Self::to_block(r, a.pattern().nx()))?;
            }
            Mode::None => unreachable!("choose never returns None"),
        }
        self.mode = mode;
        Ok(())
    }

    /// Keeps the inner solver's preconditioner ([`LinearSolver::refresh`]) when the
    /// rectangle is the last set-up's; otherwise a full set-up.
    fn refresh(&mut self, a: &Stencil5) -> Result<(), LinSolveError> {
        if a.pattern() != self.pattern()? {
            return Err(LinSolveError::PatternMismatch);
        }
        let mode = self.choose(a);
        match (self.mode, mode) {
            (Mode::Whole, Mode::Whole) => self.whole.refresh(a),
            (Mode::Part(last), Mode::Part(r)) if last == r => {
                self.mode = Mode::None;
                self.fill_part(a, r)?;
                let sub = self.sub.as_ref().expect("filled");
                self.part
                    .refresh(sub)
                    .map_err(Self::to_block(r, a.pattern().nx()))?;
                self.mode = mode;
                Ok(())
            }
            _ => self.setup(a),
        }
    }

    fn solve(&mut self, a: &Stencil5, x: &mut [f64]) -> Result<SolveStats, LinSolveError> {
        let t0 = Instant::now();
        if a.pattern() != self.pattern()? {
            return Err(LinSolveError::PatternMismatch);
        }
        crate::stencil::check_len("x", a.len(), x.len())?;
        match self.mode {
            Mode::None => Err(LinSolveError::NotReady("setup")),
            Mode::Whole => self.whole.solve(a, x),
            Mode::Diagonal => {
                solve_outside(a, x, None)?;
                let rel_residual = a.rel_residual(x, &mut self.work)?;
                Ok(SolveStats {
                    iterations: 0,
                    rel_residual,
                    converged: true,
                    t_setup: Default::default(),
                    t_solve: t0.elapsed(),
                })
            }
            Mode::Part(r) => {
                solve_outside(a, x, Some(r))?;
                self.part_rhs(a, x, r);
                let nx = a.pattern().nx();
                let snx = r.nx();
                for j in r.j0..r.j1 {
                    let (k0, s0) = (r.i0 + nx * j, snx * (j - r.j0));
                    self.x_sub[s0..s0 + snx].copy_from_slice(&x[k0..k0 + snx]);
                }
                let sub = self.sub.as_ref().expect("set up");
                let stats = self
                    .part
                    .solve(sub, &mut self.x_sub)
                    .map_err(Self::to_block(r, nx))?;
                for j in r.j0..r.j1 {
                    let (k0, s0) = (r.i0 + nx * j, snx * (j - r.j0));
                    x[k0..k0 + snx].copy_from_slice(&self.x_sub[s0..s0 + snx]);
                }
                Ok(SolveStats {
                    t_solve: t0.elapsed(),
                    ..stats
                })
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Precond, SparseLuSolver};

    /// A block whose rows inside `inner` are a diffusion–convection problem and outside
    /// it diagonal rows `a_P φ = b`, except one diagonal row beside the rectangle that the
    /// rectangle links to.
    fn slide_like(nx: usize, ny: usize, inner: Rect) -> Stencil5 {
        let mut pattern = Pattern::new(nx, ny).unwrap();
        pattern.fix(nx - 1, ny - 1).unwrap();
        let mut a = Stencil5::new(pattern);
        for j in 0..ny {
            for i in 0..nx {
                let k = i + nx * j;
                let h = ((k * 7919) % 97) as f64 / 97.0;
                a.b[k] = 0.3 + h;
                if !(inner.i0..inner.i1).contains(&i) || !(inner.j0..inner.j1).contains(&j) {
                    a.a_p[k] = 1.0 + h;
                    continue;
                }
                // links also out of the rectangle: to the diagonal rows beside it
                a.a_e[k] = if i + 1 < nx { 1.0 + 0.5 * h } else { 0.0 };
                a.a_w[k] = if i > 0 { 1.0 } else { 0.0 };
                a.a_n[k] = if j + 1 < ny { 0.7 } else { 0.0 };
                a.a_s[k] = if j > 0 { 0.7 + h } else { 0.0 };
                a.a_p[k] = a.a_e[k] + a.a_w[k] + a.a_n[k] + a.a_s[k] + 0.1;
            }
        }
        a
    }

    fn direct(a: &Stencil5) -> Vec<f64> {
        let mut lu = SparseLuSolver::new();
        lu.set_pattern(a.pattern()).unwrap();
        let mut x = vec![0.0; a.len()];
        lu.setup_and_solve(a, &mut x).unwrap();
        x
    }

    #[test]
    fn the_coupled_rectangle_is_the_bounding_box_of_the_linked_rows() {
        let inner = Rect {
            i0: 5,
            i1: 13,
            j0: 0,
            j1: 3,
        };
        let mut a = slide_like(40, 12, inner);
        assert_eq!(coupled_rect(&a), Some(inner));
        // a fixed row's links are ignored by the solvers and do not count
        a.a_w[40 * 12 - 1] = 1.0;
        assert_eq!(coupled_rect(&a), Some(inner));
        a.a_w[40 * 12 - 2] = 1.0;
        assert_eq!(
            coupled_rect(&a),
            Some(Rect {
                i0: 5,
                i1: 39,
                j0: 0,
                j1: 12
            })
        );
        let mut diag = Stencil5::new(Pattern::new(4, 4).unwrap());
        diag.a_p.iter_mut().for_each(|d| *d = 2.0);
        assert_eq!(coupled_rect(&diag), None);
    }

    #[test]
    fn solving_the_rectangle_matches_a_direct_solve_of_the_block() {
        let inner = Rect {
            i0: 5,
            i1: 13,
            j0: 0,
            j1: 3,
        };
        let a = slide_like(40, 12, inner);
        let reference = direct(&a);
        for kind in [
            LinearSolverKind::transport_default(1e-12, 200),
            LinearSolverKind::BiCgStab {
                rtol: 1e-12,
                max_iter: 200,
                precond: Precond::MultigridK,
            },
        ] {
            let mut solver = ActiveBox::new(&kind);
            solver.set_pattern(a.pattern()).unwrap();
            let mut x = vec![0.5; a.len()];
            let stats = solver.setup_and_solve(&a, &mut x).unwrap();
            assert!(stats.converged);
            // aligned outwards: x to multiples of 8, y to multiples of 4
            assert_eq!(
                solver.rect(),
                Some(Rect {
                    i0: 0,
                    i1: 16,
                    j0: 0,
                    j1: 4
                })
            );
            for (k, (x, r)) in x.iter().zip(&reference).enumerate() {
                assert!((x - r).abs() <= 1e-10 * r.abs().max(1.0), "{k}: {x} vs {r}");
            }
        }
    }

    #[test]
    fn a_rectangle_over_half_the_block_solves_the_whole_block() {
        let inner = Rect {
            i0: 0,
            i1: 30,
            j0: 0,
            j1: 10,
        };
        let a = slide_like(40, 12, inner);
        let mut solver = ActiveBox::new(&LinearSolverKind::transport_default(1e-12, 200));
        solver.set_pattern(a.pattern()).unwrap();
        let mut x = vec![0.0; a.len()];
        solver.setup_and_solve(&a, &mut x).unwrap();
        assert_eq!(solver.rect(), None);
        let reference = direct(&a);
        for (x, r) in x.iter().zip(&reference) {
            assert!((x - r).abs() <= 1e-10 * r.abs().max(1.0));
        }
    }

    #[test]
    fn a_rectangle_is_kept_while_it_holds_the_coupled_rows() {
        let mut solver = ActiveBox::new(&LinearSolverKind::transport_default(1e-12, 200));
        let a = slide_like(
            64,
            16,
            Rect {
                i0: 2,
                i1: 10,
                j0: 0,
                j1: 3,
            },
        );
        solver.set_pattern(a.pattern()).unwrap();
        solver.setup(&a).unwrap();
        let first = solver.rect().unwrap();
        assert_eq!(
            first,
            Rect {
                i0: 0,
                i1: 16,
                j0: 0,
                j1: 4
            }
        );
        // the flow spreads by a few cells inside the kept rectangle
        let b = slide_like(
            64,
            16,
            Rect {
                i0: 2,
                i1: 14,
                j0: 0,
                j1: 4,
            },
        );
        solver.refresh(&b).unwrap();
        assert_eq!(solver.rect(), Some(first));
        let mut x = vec![0.0; b.len()];
        solver.solve(&b, &mut x).unwrap();
        let reference = direct(&b);
        for (x, r) in x.iter().zip(&reference) {
            assert!((x - r).abs() <= 1e-10 * r.abs().max(1.0));
        }
        // and past it: a new rectangle
        let c = slide_like(
            64,
            16,
            Rect {
                i0: 2,
                i1: 20,
                j0: 0,
                j1: 4,
            },
        );
        solver.setup(&c).unwrap();
        assert_eq!(
            solver.rect(),
            Some(Rect {
                i0: 0,
                i1: 24,
                j0: 0,
                j1: 4
            })
        );
    }

    #[test]
    fn only_diagonal_rows_are_solved_exactly() {
        let mut a = Stencil5::new(Pattern::new(6, 3).unwrap());
        for k in 0..a.len() {
            a.a_p[k] = 2.0 + k as f64;
            a.b[k] = k as f64;
        }
        let mut solver = ActiveBox::new(&LinearSolverKind::transport_default(1e-12, 20));
        solver.set_pattern(a.pattern()).unwrap();
        let mut x = vec![9.0; a.len()];
        let stats = solver.setup_and_solve(&a, &mut x).unwrap();
        assert_eq!(stats.iterations, 0);
        for (k, x) in x.iter().enumerate() {
            assert_eq!(*x, k as f64 / (2.0 + k as f64));
        }
    }

    #[test]
    fn errors_name_the_cell_of_the_block() {
        let inner = Rect {
            i0: 5,
            i1: 13,
            j0: 0,
            j1: 3,
        };
        let mut a = slide_like(40, 12, inner);
        let mut solver = ActiveBox::new(&LinearSolverKind::transport_default(1e-12, 200));
        solver.set_pattern(a.pattern()).unwrap();
        // inside the rectangle
        let k = 7 + 40 * 2;
        a.a_n[k] = f64::NAN;
        assert_eq!(
            solver.setup(&a),
            Err(LinSolveError::NonFinite {
                what: "a_n",
                cell: k
            })
        );
        a.a_n[k] = 0.7;
        // outside it
        let k = 30 + 40 * 9;
        a.a_p[k] = 0.0;
        assert_eq!(
            solver.setup(&a),
            Err(LinSolveError::ZeroDiagonal { cell: k })
        );
        a.a_p[k] = 1.0;
        solver.setup(&a).unwrap();
        a.b[k] = f64::INFINITY;
        let mut x = vec![0.0; a.len()];
        assert_eq!(
            solver.solve(&a, &mut x).map(|_| ()),
            Err(LinSolveError::NonFinite { what: "b", cell: k })
        );
    }
}
