//! The 5-point structured matrix and its fixed sparsity pattern.
//!
//! Cells of an `nx × ny` block are numbered `k = i + nx·j` (x fastest, as MFIX's IJK).
//! Each row uses MFIX's sign convention (docs/model.md §4; Patankar 1980 §5.2):
//!
//! $$ a_P φ_P = a_E φ_E + a_W φ_W + a_N φ_N + a_S φ_S + b, $$
//!
//! so the matrix has `a_P` on the diagonal and `−a_nb` off it. A link that points out of
//! the block (e.g. `a_W` in column `i = 0`) is ignored: boundary conditions must already be
//! folded into `a_P` and `b`, as MFIX does. A [`CellKind::Fixed`] cell keeps only its
//! diagonal, `a_P φ_P = b` (a pinned reference pressure, an obstacle, a dead cell);
//! the solvers eliminate the links of active cells into fixed ones symmetrically, moving
//! `a_nb φ_fixed` to the right-hand side, so a symmetric pressure matrix stays symmetric.

use rayon::prelude::*;

use crate::team::Team;
use crate::LinSolveError;

/// Whether a cell is an unknown or has a prescribed value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CellKind {
    /// An ordinary unknown coupled to its neighbours.
    Active,
    /// Value fixed by its own row, `a_P φ_P = b` (neighbour links ignored).
    Fixed,
}

/// The sparsity pattern: an `nx × ny` block of cells and which of them are fixed.
/// Set once per grid; the values are refilled many times.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pattern {
    nx: usize,
    ny: usize,
    fixed: Vec<bool>,
}

impl Pattern {
    /// All cells active.
    pub fn new(nx: usize, ny: usize) -> Result<Self, LinSolveError> {
        if nx == 0 || ny == 0 {
            return Err(LinSolveError::DimensionMismatch {
                what: "grid size nx·ny",
                expected: 1,
                got: 0,
            });
        }
        Ok(Self {
            nx,
            ny,
            fixed: vec![false; nx * ny],
        })
    }

    /// Builds a pattern whose cell `(i, j)` has kind `kind(i, j)`.
    pub fn from_fn(
        nx: usize,
        ny: usize,
        kind: impl Fn(usize, usize) -> CellKind,
    ) -> Result<Self, LinSolveError> {
        let mut p = Self::new(nx, ny)?;
        for j in 0..ny {
            for i in 0..nx {
                p.fixed[i + nx * j] = kind(i, j) == CellKind::Fixed;
            }
        }
        Ok(p)
    }

    /// Marks cell `(i, j)` as fixed; an error if it lies outside the block.
    pub fn fix(&mut self, i: usize, j: usize) -> Result<(), LinSolveError> {
        check_len("fix: i < nx", self.nx, self.nx.max(i + 1))?;
        check_len("fix: j < ny", self.ny, self.ny.max(j + 1))?;
        self.fixed[i + self.nx * j] = true;
        Ok(())
    }

    /// Cells in x.
    pub fn nx(&self) -> usize {
        self.nx
    }
    /// Cells in y.
    pub fn ny(&self) -> usize {
        self.ny
    }
    /// Number of cells (= rows of the matrix).
    pub fn len(&self) -> usize {
        self.nx * self.ny
    }
    /// Always false (a pattern has at least one cell); for clippy's `len_without_is_empty`.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// Linear index of cell `(i, j)`.
    #[inline]
    pub fn idx(&self, i: usize, j: usize) -> usize {
        i + self.nx * j
    }
    /// Kind of cell `k`.
    #[inline]
    pub fn kind(&self, k: usize) -> CellKind {
        if self.fixed[k] {
            CellKind::Fixed
        } else {
            CellKind::Active
        }
    }
    /// Per-cell "is fixed" flags, indexed by `k`.
    pub fn fixed_mask(&self) -> &[bool] {
        &self.fixed
    }
}

/// A 5-point matrix with its right-hand side, `a_P φ_P = Σ a_nb φ_nb + b`.
///
/// Coefficient vectors are public so that assembly code can fill them directly, or row by
/// row in parallel with [`Stencil5::par_fill_rows`]; their lengths must not change.
#[derive(Clone, Debug)]
pub struct Stencil5 {
    pattern: Pattern,
    /// Centre coefficient a_P.
    pub a_p: Vec<f64>,
    /// East link a_E (to `k + 1`).
    pub a_e: Vec<f64>,
    /// West link a_W (to `k − 1`).
    pub a_w: Vec<f64>,
    /// North link a_N (to `k + nx`).
    pub a_n: Vec<f64>,
    /// South link a_S (to `k − nx`).
    pub a_s: Vec<f64>,
    /// Source b.
    pub b: Vec<f64>,
}

impl Stencil5 {
    /// All coefficients zero.
    pub fn new(pattern: Pattern) -> Self {
        let n = pattern.len();
        Self {
            pattern,
            a_p: vec![0.0; n],
            a_e: vec![0.0; n],
            a_w: vec![0.0; n],
            a_n: vec![0.0; n],
            a_s: vec![0.0; n],
            b: vec![0.0; n],
        }
    }

    /// The sparsity pattern.
    pub fn pattern(&self) -> &Pattern {
        &self.pattern
    }
    /// Number of unknowns.
    pub fn len(&self) -> usize {
        self.pattern.len()
    }
    /// Always false; see [`Pattern::is_empty`].
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Fills the coefficients row by row (one row = one j, cells i = 0..nx), in parallel
    /// over rows with rayon in tasks of about 2 048 cells. `fill(j, row)` gets mutable
    /// slices of length nx of every coefficient and of b for row j.
    pub fn par_fill_rows<F>(&mut self, fill: F)
    where
        F: Fn(usize, RowMut<'_>) + Sync + Send,
    {
        let mut nothing = vec![(); self.len()];
        self.par_fill_rows_with(&mut nothing, |j, row, _| fill(j, row));
    }

    /// [`Stencil5::par_fill_rows`] with row j of a cell array `side` (nx × ny entries,
    /// x fastest) as well: `fill(j, row, side_row)`.
    ///
    /// # Panics
    /// If `side` does not have one entry per cell.
    pub fn par_fill_rows_with<T, F>(&mut self, side: &mut [T], fill: F)
    where
        T: Send,
        F: Fn(usize, RowMut<'_>, &mut [T]) + Sync + Send,
    {
        assert_eq!(side.len(), self.len(), "one side entry per cell");
        let nx = self.pattern.nx;
        let rows = self
            .a_p
            .par_chunks_mut(nx)
            .zip(self.a_e.par_chunks_mut(nx))
            .zip(self.a_w.par_chunks_mut(nx))
            .zip(self.a_n.par_chunks_mut(nx))
            .zip(self.a_s.par_chunks_mut(nx))
            .zip(self.b.par_chunks_mut(nx))
            .zip(side.par_chunks_mut(nx))
            .enumerate()
            .with_min_len(rows_per_task(nx))
            .with_max_len(rows_per_task(nx));
        rows.for_each(|(j, ((((((a_p, a_e), a_w), a_n), a_s), b), side_row))| {
            let row = RowMut {
                a_p,
                a_e,
                a_w,
                a_n,
                a_s,
                b,
            };
            fill(j, row, side_row)
        });
    }

    /// The coefficients and b of row j.
    pub fn row_mut(&mut self, j: usize) -> RowMut<'_> {
        let nx = self.pattern.nx;
        let cells = nx * j..nx * (j + 1);
        RowMut {
            a_p: &mut self.a_p[cells.clone()],
            a_e: &mut self.a_e[cells.clone()],
            a_w: &mut self.a_w[cells.clone()],
            a_n: &mut self.a_n[cells.clone()],
            a_s: &mut self.a_s[cells.clone()],
            b: &mut self.b[cells],
        }
    }

    /// y = A x for the full matrix described in the module docs.
    pub fn matvec(&self, x: &[f64], y: &mut [f64]) -> Result<(), LinSolveError> {
        check_len("x", self.len(), x.len())?;
        check_len("y", self.len(), y.len())?;
        let c = self.coeffs();
        apply5(&c, Some(self.pattern.fixed_mask()), x, y);
        Ok(())
    }

    /// r = b − A x.
    pub fn residual(&self, x: &[f64], r: &mut [f64]) -> Result<(), LinSolveError> {
        self.matvec(x, r)?;
        let b = &self.b;
        crate::kernels::for_each_indexed(r, |k, v| *v = b[k] - *v);
        Ok(())
    }

    /// True relative residual ‖b − A x‖₂ / ‖b‖₂ (the absolute norm when b = 0), using
    /// `work` (length n) as scratch.
    pub fn rel_residual(&self, x: &[f64], work: &mut [f64]) -> Result<f64, LinSolveError> {
        self.residual(x, work)?;
        let bn = crate::kernels::norm2(&self.b);
        let rn = crate::kernels::norm2(work);
        Ok(if bn > 0.0 { rn / bn } else { rn })
    }

    pub(crate) fn coeffs(&self) -> Coeffs<'_> {
        Coeffs {
            nx: self.pattern.nx,
            ny: self.pattern.ny,
            ap: &self.a_p,
            ae: &self.a_e,
            aw: &self.a_w,
            an: &self.a_n,
            as_: &self.a_s,
        }
    }

    /// Checks that all coefficients are finite and every diagonal is non-zero.
    pub(crate) fn validate_coefficients(&self) -> Result<(), LinSolveError> {
        for (name, v) in [
            ("a_p", &self.a_p),
            ("a_e", &self.a_e),
            ("a_w", &self.a_w),
            ("a_n", &self.a_n),
            ("a_s", &self.a_s),
        ] {
            check_len(name, self.len(), v.len())?;
            if let Some(cell) = crate::kernels::first_non_finite(v) {
                return Err(LinSolveError::NonFinite { what: name, cell });
            }
        }
        check_len("b", self.len(), self.b.len())?;
        if let Some(cell) = self.a_p.iter().position(|&d| d == 0.0) {
            return Err(LinSolveError::ZeroDiagonal { cell });
        }
        Ok(())
    }

    /// Checks that b is finite.
    pub(crate) fn validate_rhs(&self) -> Result<(), LinSolveError> {
        check_len("b", self.len(), self.b.len())?;
        match crate::kernels::first_non_finite(&self.b) {
            Some(cell) => Err(LinSolveError::NonFinite { what: "b", cell }),
            None => Ok(()),
        }
    }
}

/// Mutable view of one row (fixed j) of a [`Stencil5`], for [`Stencil5::par_fill_rows`].
pub struct RowMut<'a> {
    /// a_P of the row.
    pub a_p: &'a mut [f64],
    /// a_E of the row.
    pub a_e: &'a mut [f64],
    /// a_W of the row.
    pub a_w: &'a mut [f64],
    /// a_N of the row.
    pub a_n: &'a mut [f64],
    /// a_S of the row.
    pub a_s: &'a mut [f64],
    /// b of the row.
    pub b: &'a mut [f64],
}

pub(crate) fn check_len(
    what: &'static str,
    expected: usize,
    got: usize,
) -> Result<(), LinSolveError> {
    if expected == got {
        Ok(())
    } else {
        Err(LinSolveError::DimensionMismatch {
            what,
            expected,
            got,
        })
    }
}

/// Borrowed coefficient arrays of a 5-point operator.
#[derive(Clone, Copy)]
pub(crate) struct Coeffs<'a> {
    pub nx: usize,
    pub ny: usize,
    pub ap: &'a [f64],
    pub ae: &'a [f64],
    pub aw: &'a [f64],
    pub an: &'a [f64],
    pub as_: &'a [f64],
}

/// The reduced operator the solvers work on: links out of the block, into fixed cells
/// and out of fixed cells are zero, so `apply` needs no masks.
#[derive(Clone, Debug, Default)]
pub(crate) struct Op5 {
    pub nx: usize,
    pub ny: usize,
    pub ap: Vec<f64>,
    pub ae: Vec<f64>,
    pub aw: Vec<f64>,
    pub an: Vec<f64>,
    pub as_: Vec<f64>,
}

impl Op5 {
    pub fn zeros(nx: usize, ny: usize) -> Self {
        let n = nx * ny;
        Self {
            nx,
            ny,
            ap: vec![0.0; n],
            ae: vec![0.0; n],
            aw: vec![0.0; n],
            an: vec![0.0; n],
            as_: vec![0.0; n],
        }
    }

    pub fn len(&self) -> usize {
        self.nx * self.ny
    }

    pub fn coeffs(&self) -> Coeffs<'_> {
        Coeffs {
            nx: self.nx,
            ny: self.ny,
            ap: &self.ap,
            ae: &self.ae,
            aw: &self.aw,
            an: &self.an,
            as_: &self.as_,
        }
    }

    /// Copies `a` into `self`, dropping links out of the block and to/from fixed cells.
    pub fn reduce_from(&mut self, a: &Stencil5) {
        let (nx, ny) = (a.pattern.nx, a.pattern.ny);
        debug_assert_eq!(self.len(), a.len());
        let fixed = a.pattern.fixed_mask();
        let rows = self
            .ap
            .par_chunks_mut(nx)
            .zip(self.ae.par_chunks_mut(nx))
            .zip(self.aw.par_chunks_mut(nx))
            .zip(self.an.par_chunks_mut(nx))
            .zip(self.as_.par_chunks_mut(nx))
            .enumerate()
            .with_min_len(rows_per_task(nx))
            .with_max_len(rows_per_task(nx));
        rows.for_each(|(j, ((((ap, ae), aw), an), as_))| {
            let row = nx * j..nx * (j + 1);
            ap.copy_from_slice(&a.a_p[row.clone()]);
            // a link survives when its own row and the neighbour's are free: a select per
            // entry over the row's slices (the rows above and below, if any, shifted by nx)
            let own = &fixed[row.clone()];
            let keep = |v: f64, free: bool| if free { v } else { 0.0 };
            let (ae_in, aw_in) = (&a.a_e[row.clone()], &a.a_w[row.clone()]);
            for i in 0..nx {
                let free = !own[i];
                ae[i] = keep(ae_in[i], free && i + 1 < nx && !own[i + 1]);
                aw[i] = keep(aw_in[i], free && i > 0 && !own[i - 1]);
            }
            let vertical = |out: &mut [f64], coeff: &[f64], nb: Option<&[bool]>| match nb {
                Some(nb) => {
                    for ((o, &v), (&f, &g)) in out.iter_mut().zip(coeff).zip(own.iter().zip(nb)) {
                        *o = keep(v, !f && !g);
                    }
                }
                None => out.iter_mut().for_each(|o| *o = 0.0),
            };
            let north = (j + 1 < ny).then(|| &fixed[row.start + nx..row.end + nx]);
            let south = (j > 0).then(|| &fixed[row.start - nx..row.end - nx]);
            vertical(an, &a.a_n[row.clone()], north);
            vertical(as_, &a.a_s[row], south);
        });
    }
}

/// Right-hand side of the reduced system: active cells get `a_nb φ_fixed` of their fixed
/// neighbours (φ_fixed = b/a_P of that cell) added to b.
pub(crate) fn reduced_rhs(a: &Stencil5, b_eff: &mut [f64]) {
    let p = &a.pattern;
    let (nx, ny) = (p.nx, p.ny);
    let fixed = p.fixed_mask();
    b_eff.copy_from_slice(&a.b);
    // visit the (few) fixed cells and push their value into active neighbours' rows
    for m in fixed
        .iter()
        .enumerate()
        .filter_map(|(m, &f)| f.then_some(m))
    {
        let val = a.b[m] / a.a_p[m];
        let (i, j) = (m % nx, m / nx);
        // neighbour k and the link of k that points back to m
        if i > 0 && !fixed[m - 1] {
            b_eff[m - 1] += a.a_e[m - 1] * val;
        }
        if i + 1 < nx && !fixed[m + 1] {
            b_eff[m + 1] += a.a_w[m + 1] * val;
        }
        if j > 0 && !fixed[m - nx] {
            b_eff[m - nx] += a.a_n[m - nx] * val;
        }
        if j + 1 < ny && !fixed[m + nx] {
            b_eff[m + nx] += a.a_s[m + nx] * val;
        }
    }
}

/// Cells per rayon task of a parallel row loop (whole rows, at least one). Small, so that
/// a loop whose work sits in a few rows (the solids of a slide near its floor) still
/// spreads over the threads: with tasks of 16k cells, 400 × 100 cells made 2–3 tasks and
/// the rows with solids fell to one thread (docs/studies/performance.md,
/// "The y lines split in two"). A row's
/// result never depends on its task.
pub(crate) const ROW_TASK_CELLS: usize = 1 << 11;

/// Rows per task of a parallel row loop over an `nx`-wide block ([`ROW_TASK_CELLS`]).
pub(crate) fn rows_per_task(nx: usize) -> usize {
    (ROW_TASK_CELLS / nx.max(1)).max(1)
}

/// Calls `f(j, row)` for every row j of `row_len` entries of `data` (a cell or face array,
/// x fastest): in parallel over tasks of about 2 048 cells from 16 384 entries,
/// serially below that; the loop of
/// [`Stencil5::par_fill_rows`], for any array. Each row is computed
/// as a serial loop would compute it, so the results do not depend on the number of threads.
pub fn for_each_row<T, F>(data: &mut [T], row_len: usize, f: F)
where
    T: Send,
    F: Fn(usize, &mut [T]) + Sync + Send,
{
    for_each_row_on(&Team::RAYON, data, row_len, f);
}

/// [`for_each_row`] by `team`.
pub(crate) fn for_each_row_on<T, F>(team: &Team<'_>, data: &mut [T], row_len: usize, f: F)
where
    T: Send,
    F: Fn(usize, &mut [T]) + Sync + Send,
{
    if data.len() < team.min_len() {
        data.chunks_mut(row_len)
            .enumerate()
            .for_each(|(j, row)| f(j, row));
    } else {
        let rows = if team.is_rayon() {
            rows_per_task(row_len)
        } else {
            (team.min_chunk() / row_len.max(1)).max(1)
        };
        team.for_each_chunk_mut(data, rows * row_len, |c, block| {
            block
                .chunks_mut(row_len)
                .enumerate()
                .for_each(|(r, row)| f(c * rows + r, row));
        });
    }
}

/// y = A x for a 5-point operator; rows of `fixed` cells use only the diagonal.
pub(crate) fn apply5(c: &Coeffs<'_>, fixed: Option<&[bool]>, x: &[f64], y: &mut [f64]) {
    apply5_on(&Team::RAYON, c, fixed, x, y);
}

/// [`apply5`] by `team`.
pub(crate) fn apply5_on(
    team: &Team<'_>,
    c: &Coeffs<'_>,
    fixed: Option<&[bool]>,
    x: &[f64],
    y: &mut [f64],
) {
    for_each_row_on(team, y, c.nx, |j, yr| apply5_row(c, fixed, x, j, yr));
}

/// Row j of y = A x: each term as a separate branch-free pass over the row (in L1).
fn apply5_row(c: &Coeffs<'_>, fixed: Option<&[bool]>, x: &[f64], j: usize, yr: &mut [f64]) {
    let (nx, ny) = (c.nx, c.ny);
    let o = nx * j;
    let r = o..o + nx;
    let xc = &x[r.clone()];
    for ((y, a), v) in yr.iter_mut().zip(&c.ap[r.clone()]).zip(xc) {
        *y = a * v;
    }
    for ((y, a), v) in yr[..nx - 1]
        .iter_mut()
        .zip(&c.ae[o..o + nx - 1])
        .zip(&xc[1..])
    {
        *y -= a * v;
    }
    for ((y, a), v) in yr[1..].iter_mut().zip(&c.aw[o + 1..o + nx]).zip(xc) {
        *y -= a * v;
    }
    if j + 1 < ny {
        for ((y, a), v) in yr
            .iter_mut()
            .zip(&c.an[r.clone()])
            .zip(&x[o + nx..o + 2 * nx])
        {
            *y -= a * v;
        }
    }
    if j > 0 {
        for ((y, a), v) in yr.iter_mut().zip(&c.as_[r.clone()]).zip(&x[o - nx..o]) {
            *y -= a * v;
        }
    }
    if let Some(f) = fixed {
        for (i, y) in yr.iter_mut().enumerate() {
            if f[o + i] {
                *y = c.ap[o + i] * xc[i];
            }
        }
    }
}

/// r = b − A x for the reduced operator, row by row (A x and the subtraction in one pass
/// while the row is in L1; the same operations as A x followed by b − A x).
pub(crate) fn residual5(c: &Coeffs<'_>, b: &[f64], x: &[f64], r: &mut [f64]) {
    residual5_on(&Team::RAYON, c, b, x, r);
}

/// [`residual5`] by `team`.
pub(crate) fn residual5_on(team: &Team<'_>, c: &Coeffs<'_>, b: &[f64], x: &[f64], r: &mut [f64]) {
    let nx = c.nx;
    for_each_row_on(team, r, nx, |j, rr| {
        apply5_row(c, None, x, j, rr);
        for (v, bk) in rr.iter_mut().zip(&b[nx * j..nx * (j + 1)]) {
            *v = bk - *v;
        }
    });
}

/// Sets x = b/a_P in the fixed cells (exactly what their rows say), so that the residual of
/// the full system equals that of the reduced one.
pub(crate) fn set_fixed_values(a: &Stencil5, x: &mut [f64]) {
    for (k, &f) in a.pattern.fixed_mask().iter().enumerate() {
        if f {
            x[k] = a.b[k] / a.a_p[k];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reduced operator keeps a_P everywhere and a link only between two free cells
    /// inside the block: checked link by link in grid coordinates, on a block with fixed
    /// cells on its edges and inside, below and above the parallel row threshold.
    #[test]
    fn reduced_operator_drops_the_links_of_fixed_cells_and_of_the_edges() {
        for (nx, ny) in [(6, 5), (150, 120)] {
            let is_fixed = |i: usize, j: usize| (i * 7 + j * 3).is_multiple_of(5) || j == 0;
            let pattern = Pattern::from_fn(nx, ny, |i, j| {
                if is_fixed(i, j) {
                    CellKind::Fixed
                } else {
                    CellKind::Active
                }
            })
            .unwrap();
            let mut a = Stencil5::new(pattern);
            let value = |k: usize, s: f64| 1.0 + (k as f64 * s).sin().abs();
            for k in 0..nx * ny {
                (a.a_p[k], a.a_e[k], a.a_w[k]) =
                    (10.0 + value(k, 0.3), value(k, 0.7), value(k, 1.1));
                (a.a_n[k], a.a_s[k]) = (value(k, 1.3), value(k, 1.7));
            }
            let mut op = Op5::zeros(nx, ny);
            op.reduce_from(&a);
            for j in 0..ny {
                for i in 0..nx {
                    let k = i + nx * j;
                    // the link to (ni, nj) survives iff both ends are free cells of the block
                    let expect = |ni: Option<usize>, nj: Option<usize>, v: f64| match (ni, nj) {
                        (Some(ni), Some(nj)) if ni < nx && nj < ny => {
                            if is_fixed(i, j) || is_fixed(ni, nj) {
                                0.0
                            } else {
                                v
                            }
                        }
                        _ => 0.0,
                    };
                    assert_eq!(op.ap[k], a.a_p[k]);
                    assert_eq!(
                        op.ae[k],
                        expect(Some(i + 1), Some(j), a.a_e[k]),
                        "e {i} {j}"
                    );
                    assert_eq!(
                        op.aw[k],
                        expect(i.checked_sub(1), Some(j), a.a_w[k]),
                        "w {i} {j}"
                    );
                    assert_eq!(
                        op.an[k],
                        expect(Some(i), Some(j + 1), a.a_n[k]),
                        "n {i} {j}"
                    );
                    assert_eq!(
                        op.as_[k],
                        expect(Some(i), j.checked_sub(1), a.a_s[k]),
                        "s {i} {j}"
                    );
                }
            }
        }
    }

    /// The fused residual equals A x followed by b − A x bit for bit, on a grid below and one
    /// above the parallel threshold, with every link non-zero.
    #[test]
    fn fused_residual_equals_the_two_pass_form() {
        for (nx, ny) in [(7, 5), (193, 97)] {
            let n = nx * ny;
            let wave = |k: usize, s: f64| 1.0 + 0.5 * ((k as f64) * s).sin();
            let ap: Vec<f64> = (0..n).map(|k| 5.0 + wave(k, 0.37)).collect();
            let ae: Vec<f64> = (0..n).map(|k| wave(k, 0.11)).collect();
            let aw: Vec<f64> = (0..n).map(|k| wave(k, 0.23)).collect();
            let an: Vec<f64> = (0..n).map(|k| wave(k, 0.31)).collect();
            let as_: Vec<f64> = (0..n).map(|k| wave(k, 0.53)).collect();
            let c = Coeffs {
                nx,
                ny,
                ap: &ap,
                ae: &ae,
                aw: &aw,
                an: &an,
                as_: &as_,
            };
            let x: Vec<f64> = (0..n).map(|k| wave(k, 0.71) - 0.3).collect();
            let b: Vec<f64> = (0..n).map(|k| wave(k, 0.97)).collect();
            let mut ax = vec![0.0; n];
            apply5(&c, None, &x, &mut ax);
            let two_pass: Vec<f64> = b.iter().zip(&ax).map(|(b, y)| b - y).collect();
            let mut fused = vec![f64::NAN; n];
            residual5(&c, &b, &x, &mut fused);
            let same = fused
                .iter()
                .zip(&two_pass)
                .all(|(f, t)| f.to_bits() == t.to_bits());
            assert!(same, "{nx} × {ny}: fused residual differs");
        }
    }
}
