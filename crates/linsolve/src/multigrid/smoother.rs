//! The smoother of the multigrid levels: zebra line Gauss–Seidel on x lines and y lines,
//! each line solved by its LU (Thomas) factors, y lines of large levels in two halves
//! (module doc of [`super`]).

use super::Level;
use crate::kernels::SharedMut;
use crate::team::Team;
use crate::LinSolveError;

/// Levels with fewer cells factor their x and y lines in one task, larger ones in two
/// (the set-up runs on rayon, outside the solve's team).
const LINES_PAR_MIN_CELLS: usize = 1 << 12;

/// Levels with at least this many cells (and 4 rows) solve their y lines in two halves
/// (module doc: split y lines).
pub(super) const Y_SPLIT_MIN_CELLS: usize = 1 << 13;

impl Level {
    /// The LU factors of the x lines and of the y lines. The two sets are independent, so
    /// on levels from [`LINES_PAR_MIN_CELLS`] cells they are computed as two tasks; a zero
    /// pivot of the x lines is reported first, as one pass doing x before y would.
    pub(super) fn factor_lines(&mut self) -> Result<(), LinSolveError> {
        let op = &self.op;
        let (nx, n) = (op.nx, op.len());
        let x_lines = |(inv, up, low): (&mut [f64], &mut [f64], &mut [f64])| {
            let west = |k: usize| (!k.is_multiple_of(nx)).then(|| k - 1);
            factor_recurrence(&op.ap, &op.aw, &op.ae, 0..n, west, inv, up)?;
            // the forward sweep's multiplier a_W/d, so that its recurrence is one
            // multiply-add per cell (`x_line`)
            for (k, l) in low.iter_mut().enumerate() {
                *l = if !k.is_multiple_of(nx) {
                    op.aw[k] * inv[k]
                } else {
                    0.0
                };
            }
            Ok(())
        };
        let split = self.y_split;
        let y_lines = |inv: &mut [f64], up: &mut [f64], join: &mut [f64]| {
            let south = |k: usize| (k >= nx).then(|| k - nx);
            if split == 0 {
                return factor_recurrence(&op.ap, &op.as_, &op.an, 0..n, south, inv, up);
            }
            let mid = split * nx;
            factor_recurrence(&op.ap, &op.as_, &op.an, 0..mid, south, inv, up)?;
            let north = |k: usize| (k + nx < n).then(|| k + nx);
            factor_recurrence(&op.ap, &op.an, &op.as_, (mid..n).rev(), north, inv, up)?;
            for (i, j) in join.iter_mut().enumerate() {
                // x_(m−1) = (g + u h)/(1 − u z) (module doc)
                let d = 1.0 - up[mid - nx + i] * up[mid + i];
                if d == 0.0 || !d.is_finite() {
                    return Err(LinSolveError::Singular {
                        detail: format!("multigrid y line {i} cannot be joined ({d})"),
                    });
                }
                *j = 1.0 / d;
            }
            Ok(())
        };
        let x_factors = (&mut self.x_inv[..], &mut self.x_up[..], &mut self.x_low[..]);
        let (y_inv, y_up, y_join) = (&mut self.y_inv, &mut self.y_up, &mut self.y_join);
        let (x, y) = if n < LINES_PAR_MIN_CELLS {
            (x_lines(x_factors), y_lines(y_inv, y_up, y_join))
        } else {
            rayon::join(|| x_lines(x_factors), || y_lines(y_inv, y_up, y_join))
        };
        x.and(y)
    }

    /// Block Gauss–Seidel on the x lines j ≡ colour (mod 2). Lines of one colour only read
    /// lines of the other colour, so they are solved in parallel.
    fn x_lines(&mut self, colour: usize, team: &Team<'_>) {
        let (nx, ny) = (self.op.nx, self.op.ny);
        let n_lines = (ny + 1 - colour.min(ny)) / 2;
        let x = SharedMut(self.sol.as_mut_ptr());
        let this = &*self;
        // SAFETY: line j writes only row j (colour c) and reads rows j ± 1 (the other
        // colour), which no task writes during this half-sweep; all indices are < nx·ny.
        let line = |m: usize| unsafe { this.x_line(colour + 2 * m, x) };
        let per_chunk = if nx * ny < team.min_len() {
            n_lines.max(1)
        } else {
            (team.min_chunk() / nx).max(1)
        };
        team.for_each(n_lines.div_ceil(per_chunk), |c| {
            (c * per_chunk..((c + 1) * per_chunk).min(n_lines)).for_each(line)
        });
    }

    /// # Safety
    /// `x` points to `sol`; no other thread may access row j or write rows j ± 1.
    unsafe fn x_line(&self, j: usize, x: SharedMut) {
        let op = &self.op;
        let (nx, ny) = (op.nx, op.ny);
        let o = nx * j;
        let row = std::slice::from_raw_parts_mut(x.0.add(o), nx);
        let rhs = &self.rhs[o..o + nx];
        let inv = &self.x_inv[o..o + nx];
        row.copy_from_slice(rhs);
        if j + 1 < ny {
            let up = std::slice::from_raw_parts(x.0.add(o + nx), nx);
            for ((v, a), u) in row.iter_mut().zip(&op.an[o..o + nx]).zip(up) {
                *v += a * u;
            }
        }
        if j > 0 {
            let down = std::slice::from_raw_parts(x.0.add(o - nx), nx);
            for ((v, a), u) in row.iter_mut().zip(&op.as_[o..o + nx]).zip(down) {
                *v += a * u;
            }
        }
        // forward sweep x_i = (r_i + a_W,i x_(i−1))/d_i as r_i/d_i + (a_W,i/d_i) x_(i−1):
        // the product r_i/d_i is off the recurrence's critical path
        let low = &self.x_low[o..o + nx];
        row[0] *= inv[0];
        for i in 1..nx {
            row[i] = row[i] * inv[i] + low[i] * row[i - 1];
        }
        let upper = &self.x_up[o..o + nx];
        for i in (0..nx - 1).rev() {
            row[i] += upper[i] * row[i + 1];
        }
    }

    /// Block Gauss–Seidel on the y lines i ≡ colour (mod 2), all lines advanced together
    /// row by row; split lines (module doc) as two tasks, one per half, that eliminate
    /// and then substitute back.
    fn y_lines(&mut self, colour: usize, team: &Team<'_>) {
        let (nx, ny, m) = (self.op.nx, self.op.ny, self.y_split);
        let x = SharedMut(self.sol.as_mut_ptr());
        let edges = [
            SharedMut(self.y_edge_lower.as_mut_ptr()),
            SharedMut(self.y_edge_upper.as_mut_ptr()),
        ];
        let this = &*self;
        let (south, north) = (-(nx as isize), nx as isize);
        // SAFETY (all three): the lines of colour c read only lines of the other colour,
        // which no task writes during this half-sweep; of a split line the lower task
        // touches rows < m and the upper task rows ≥ m, and each writes only its own edge
        // array; all indices are < nx·ny.
        if m == 0 {
            unsafe {
                this.y_eliminate(colour, 0..ny, &this.op.as_, south, x);
                this.y_substitute(colour, (0..ny.saturating_sub(1)).rev(), north, x);
            }
            return;
        }
        team.for_each(2, |half| unsafe {
            if half == 0 {
                this.y_eliminate(colour, 0..m, &this.op.as_, south, x);
            } else {
                this.y_eliminate(colour, (m..ny).rev(), &this.op.an, north, x);
            }
            let row = if half == 0 { m - 1 } else { m };
            for i in (colour..nx).step_by(2) {
                *edges[half].0.add(i) = *x.0.add(row * nx + i);
            }
        });
        let (lower, upper) = (&this.y_edge_lower, &this.y_edge_upper);
        team.for_each(2, |half| unsafe {
            // the join (module doc), the same expression in both tasks
            let below_mid = |i: usize| {
                let u = this.y_up[(m - 1) * nx + i];
                (lower[i] + u * upper[i]) * this.y_join[i]
            };
            if half == 0 {
                for i in (colour..nx).step_by(2) {
                    *x.0.add((m - 1) * nx + i) = below_mid(i);
                }
                this.y_substitute(colour, (0..m - 1).rev(), north, x);
            } else {
                for i in (colour..nx).step_by(2) {
                    let z = this.y_up[m * nx + i];
                    *x.0.add(m * nx + i) = upper[i] + z * below_mid(i);
                }
                this.y_substitute(colour, m + 1..ny, south, x);
            }
        });
    }

    /// Forward elimination of the y lines of `colour` over `rows` in that order: x_k =
    /// (r_k + a_E x_E + a_W x_W + a_prev,k x_(k+prev)) / d_k, the last term from the second
    /// row on.
    ///
    /// # Safety
    /// `x` points to `sol`; no other thread may access these cells or write the other
    /// colour's.
    unsafe fn y_eliminate(
        &self,
        colour: usize,
        rows: impl Iterator<Item = usize>,
        a_prev: &[f64],
        prev: isize,
        x: SharedMut,
    ) {
        let op = &self.op;
        let nx = op.nx;
        let mut has_prev = false;
        for j in rows {
            let o = nx * j;
            for i in (colour..nx).step_by(2) {
                let k = o + i;
                let mut d = self.rhs[k];
                if i + 1 < nx {
                    d += op.ae[k] * *x.0.add(k + 1);
                }
                if i > 0 {
                    d += op.aw[k] * *x.0.add(k - 1);
                }
                if has_prev {
                    d += a_prev[k] * *x.0.offset(k as isize + prev);
                }
                *x.0.add(k) = d * self.y_inv[k];
            }
            has_prev = true;
        }
    }

    /// Back substitution of the y lines of `colour` over `rows` in that order:
    /// x_k += up_k x_(k+next).
    ///
    /// # Safety
    /// As [`Level::y_eliminate`].
    unsafe fn y_substitute(
        &self,
        colour: usize,
        rows: impl Iterator<Item = usize>,
        next: isize,
        x: SharedMut,
    ) {
        let nx = self.op.nx;
        for j in rows {
            let o = nx * j;
            for i in (colour..nx).step_by(2) {
                let k = o + i;
                *x.0.add(k) += self.y_up[k] * *x.0.offset(k as isize + next);
            }
        }
    }

    pub(super) fn pre_smooth(&mut self, team: &Team<'_>) {
        self.x_lines(0, team);
        self.x_lines(1, team);
        self.y_lines(0, team);
        self.y_lines(1, team);
    }

    pub(super) fn post_smooth(&mut self, team: &Team<'_>) {
        self.y_lines(1, team);
        self.y_lines(0, team);
        self.x_lines(1, team);
        self.x_lines(0, team);
    }
}

/// The forward elimination of tridiagonal lines a_P x_k − a_prev x_prev(k) − a_next x_next(k)
/// = r (Thomas algorithm) over `cells` in elimination order: inv_k = 1/d_k and up_k =
/// a_next,k/d_k with d_k = a_P,k − a_prev,k up_prev(k) where `prev(k)` exists, else a_P,k.
fn factor_recurrence(
    ap: &[f64],
    a_prev: &[f64],
    a_next: &[f64],
    cells: impl Iterator<Item = usize>,
    prev: impl Fn(usize) -> Option<usize>,
    inv: &mut [f64],
    up: &mut [f64],
) -> Result<(), LinSolveError> {
    for k in cells {
        let mut d = ap[k];
        if let Some(p) = prev(k) {
            d -= a_prev[k] * up[p];
        }
        if d == 0.0 || !d.is_finite() {
            return Err(LinSolveError::Singular {
                detail: format!("multigrid line pivot {d} at cell {k}"),
            });
        }
        inv[k] = 1.0 / d;
        up[k] = a_next[k] / d;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A level with a diagonally dominant operator, strongly coupled in y, and a
    /// right-hand side and start vector that vary from cell to cell.
    fn level(nx: usize, ny: usize) -> Level {
        let mut lv = Level::new(nx, ny);
        for k in 0..nx * ny {
            let (i, j) = (k % nx, k / nx);
            let wave = |s: f64| 1.0 + 0.5 * (s * k as f64).sin();
            let op = &mut lv.op;
            op.ae[k] = if i + 1 < nx { wave(0.3) } else { 0.0 };
            op.aw[k] = if i > 0 { wave(0.7) } else { 0.0 };
            op.an[k] = if j + 1 < ny { 40.0 * wave(1.1) } else { 0.0 };
            op.as_[k] = if j > 0 { 40.0 * wave(1.3) } else { 0.0 };
            op.ap[k] = op.ae[k] + op.aw[k] + op.an[k] + op.as_[k] + 0.01;
            lv.rhs[k] = (0.37 * k as f64).cos();
            lv.sol[k] = (0.11 * k as f64).sin();
        }
        lv.factor_lines().unwrap();
        lv
    }

    /// After a half-sweep of y lines every line of that colour satisfies its equations,
    /// a_P x − Σ a_nb x_nb = r with the other colour's values, whether the lines are
    /// split in two halves (8192 and 8281 cells, even and odd rows) or not.
    #[test]
    fn y_lines_solve_their_equations() {
        for (nx, ny) in [(128, 64), (91, 91), (64, 7), (90, 91)] {
            let mut lv = level(nx, ny);
            assert_eq!(lv.y_split > 0, nx * ny >= Y_SPLIT_MIN_CELLS, "{nx} × {ny}");
            for colour in [0, 1] {
                Team::run(|team| lv.y_lines(colour, team));
                let (op, x) = (&lv.op, &lv.sol);
                let size = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                for k in (0..nx * ny).filter(|k| k % nx % 2 == colour) {
                    let link = |a: &[f64], offset: isize| {
                        if a[k] == 0.0 {
                            0.0
                        } else {
                            a[k] * x[(k as isize + offset) as usize]
                        }
                    };
                    let (e, n) = (1, nx as isize);
                    let lhs = op.ap[k] * x[k]
                        - link(&op.ae, e)
                        - link(&op.aw, -e)
                        - link(&op.an, n)
                        - link(&op.as_, -n);
                    let tol = 1e-12 * (op.ap[k] * size + lv.rhs[k].abs());
                    assert!(
                        (lhs - lv.rhs[k]).abs() <= tol,
                        "{nx} × {ny}, colour {colour}, cell {k}: {lhs} against {}",
                        lv.rhs[k]
                    );
                }
            }
        }
    }
}
