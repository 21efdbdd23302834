//! Band LU of a 5-point operator: the direct solve of the multigrid's coarsest level.
//!
//! Numbered with the grid's shorter side fastest, the 5-point matrix of an nx × ny grid is
//! a band matrix of half-width w = min(nx, ny): a cell's neighbours along the short side
//! are ±1 away, along the long side ±w. Gaussian elimination without pivoting keeps the
//! factors inside the band (Golub & Van Loan 2013, §4.3: L has lower and U upper
//! bandwidth w), so with n = nx ny cells
//!
//! * the factorisation costs ≈ n w² multiply-adds, and
//! * a solve 2 n w (forward L y = b, backward U x = y), each row's w products summed in
//!   four interleaved partial sums: one running sum would make every row a chain of w
//!   dependent additions, at the adder's latency rather than its throughput,
//!
//! against n³/3 and n² for a dense LU. Without pivoting the elimination is stable for the
//! matrices the multigrid sees: the Galerkin coarse operators of a diagonally dominant
//! M-matrix (the pressure and volume-fraction corrections, docs/model.md §4.6–4.7) are
//! again diagonally dominant, and for those Gaussian elimination needs no pivoting
//! (Golub & Van Loan 2013, Thm 3.4.3). A pivot that is not larger than n ε max|a| is
//! reported as singular, the threshold of the dense LU it replaces.

use crate::kernels::dot_serial;
use crate::stencil::Op5;
use crate::LinSolveError;

/// LU factors of a 5-point operator in band storage.
#[derive(Default)]
pub(crate) struct BandLu {
    n: usize,
    /// half-bandwidth: the length of the fast (shorter) side
    w: usize,
    /// the grid's nx: cell k = i + nx j of the operator
    nx: usize,
    /// true when y is the fast index of the band numbering (nx > ny)
    transposed: bool,
    /// row m of the band numbering holds columns m − w ..= m + w at m (2w + 1) + (c − m + w);
    /// L below the diagonal (unit diagonal not stored), U on and above it
    band: Vec<f64>,
    /// 1 / U_mm
    inv_diag: Vec<f64>,
    /// right-hand side and solution in the band numbering
    work: Vec<f64>,
}

impl BandLu {
    /// The band position of cell k = i + nx j.
    fn position(&self, k: usize) -> usize {
        if self.transposed {
            let ny = self.w;
            (k / self.nx) + ny * (k % self.nx)
        } else {
            k
        }
    }

    /// Factors `op` (links a_nb enter the matrix as −a_nb, eq. of docs/model.md §4.6).
    pub fn factor(&mut self, op: &Op5) -> Result<(), LinSolveError> {
        let (nx, ny) = (op.nx, op.ny);
        let n = op.len();
        self.n = n;
        self.nx = nx;
        self.transposed = nx > ny;
        self.w = nx.min(ny);
        let (w, width) = (self.w, 2 * self.w + 1);
        self.band.clear();
        self.band.resize(n * width, 0.0);
        self.inv_diag.clear();
        self.inv_diag.resize(n, 0.0);
        self.work.clear();
        self.work.resize(n, 0.0);
        // the fast side's neighbours are ±1 in the band numbering, the slow side's ±w
        let (fast_lo, fast_hi, slow_lo, slow_hi) = if self.transposed {
            (&op.as_, &op.an, &op.aw, &op.ae)
        } else {
            (&op.aw, &op.ae, &op.as_, &op.an)
        };
        for k in 0..n {
            let m = self.position(k);
            let (i, j) = (k % nx, k / nx);
            let (at_fast_start, at_fast_end, at_slow_start, at_slow_end) = if self.transposed {
                (j == 0, j + 1 == ny, i == 0, i + 1 == nx)
            } else {
                (i == 0, i + 1 == nx, j == 0, j + 1 == ny)
            };
            let row = &mut self.band[m * width..(m + 1) * width];
            row[w] = op.ap[k];
            if !at_fast_start {
                row[w - 1] = -fast_lo[k];
            }
            if !at_fast_end {
                row[w + 1] = -fast_hi[k];
            }
            if !at_slow_start {
                row[0] = -slow_lo[k];
            }
            if !at_slow_end {
                row[2 * w] = -slow_hi[k];
            }
        }
        let scale = self.band.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let tiny = n as f64 * f64::EPSILON * scale;
        let a = &mut self.band;
        for p in 0..n {
            let pivot = a[p * width + w];
            if pivot.abs() <= tiny || !pivot.is_finite() {
                return Err(LinSolveError::Singular {
                    detail: format!("coarsest multigrid level ({n} cells) has pivot {pivot:.3e}"),
                });
            }
            let inv = 1.0 / pivot;
            self.inv_diag[p] = inv;
            let last = (p + w).min(n - 1);
            // row p's U part: columns p+1 ..= last, at offsets w+1 ..
            let (upper, below) = a.split_at_mut((p + 1) * width);
            let pivot_row = &upper[p * width + w + 1..p * width + w + 1 + (last - p)];
            for r in p + 1..=last {
                // entry (r, p) sits at offset p − r + w of row r
                let row = &mut below[(r - p - 1) * width..(r - p) * width];
                let l = row[p + w - r] * inv;
                row[p + w - r] = l;
                if l != 0.0 {
                    let o = p + 1 + w - r;
                    for (v, u) in row[o..o + (last - p)].iter_mut().zip(pivot_row) {
                        *v -= l * u;
                    }
                }
            }
        }
        Ok(())
    }

    /// x = A⁻¹ b, both in the grid's numbering.
    pub fn solve(&mut self, b: &[f64], x: &mut [f64]) {
        let (n, w, width) = (self.n, self.w, 2 * self.w + 1);
        for (k, &v) in b.iter().enumerate() {
            let m = self.position(k);
            self.work[m] = v;
        }
        let (a, y) = (&self.band, &mut self.work);
        // L y = b, unit lower triangular
        for m in 1..n {
            let first = m.saturating_sub(w);
            let row = &a[m * width + first + w - m..m * width + w];
            y[m] -= dot_serial(row, &y[first..m]);
        }
        // U x = y
        for m in (0..n).rev() {
            let last = (m + w).min(n - 1);
            let row = &a[m * width + w + 1..m * width + w + 1 + (last - m)];
            y[m] = (y[m] - dot_serial(row, &y[m + 1..=last])) * self.inv_diag[m];
        }
        for (k, v) in x.iter_mut().enumerate() {
            *v = self.work[self.position(k)];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A diagonally dominant, non-symmetric 5-point operator with varying coefficients.
    fn operator(nx: usize, ny: usize) -> Op5 {
        let mut op = Op5::zeros(nx, ny);
        for k in 0..nx * ny {
            let (i, j) = ((k % nx) as f64, (k / nx) as f64);
            op.ae[k] = if k % nx + 1 < nx {
                1.0 + 0.3 * (i * 0.7).sin()
            } else {
                0.0
            };
            op.aw[k] = if k % nx > 0 {
                0.8 + 0.2 * (j * 1.3).cos()
            } else {
                0.0
            };
            op.an[k] = if k + nx < nx * ny {
                2.0 + 0.5 * (i + j).sin()
            } else {
                0.0
            };
            op.as_[k] = if k >= nx { 1.5 } else { 0.0 };
            op.ap[k] = op.ae[k] + op.aw[k] + op.an[k] + op.as_[k] + 0.05 + 0.01 * i;
        }
        op
    }

    /// A x by the stencil: a_P x_k − Σ a_nb x_nb.
    fn apply(op: &Op5, x: &[f64]) -> Vec<f64> {
        let (nx, n) = (op.nx, op.len());
        (0..n)
            .map(|k| {
                let mut v = op.ap[k] * x[k];
                if k % nx + 1 < nx {
                    v -= op.ae[k] * x[k + 1];
                }
                if k % nx > 0 {
                    v -= op.aw[k] * x[k - 1];
                }
                if k + nx < n {
                    v -= op.an[k] * x[k + nx];
                }
                if k >= nx {
                    v -= op.as_[k] * x[k - nx];
                }
                v
            })
            .collect()
    }

    #[test]
    fn band_lu_recovers_a_known_solution_in_both_numberings() {
        for (nx, ny) in [(1, 1), (7, 1), (1, 6), (9, 4), (4, 9), (13, 13), (40, 11)] {
            let op = operator(nx, ny);
            let exact: Vec<f64> = (0..nx * ny)
                .map(|k| (k as f64 * 0.37).sin() + 1.0)
                .collect();
            let b = apply(&op, &exact);
            let mut lu = BandLu::default();
            lu.factor(&op).unwrap();
            let mut x = vec![0.0; nx * ny];
            lu.solve(&b, &mut x);
            let err = x
                .iter()
                .zip(&exact)
                .fold(0.0f64, |m, (a, e)| m.max((a - e).abs()));
            assert!(err < 1e-12, "{nx} × {ny}: max error {err:.2e}");
        }
    }

    #[test]
    fn band_lu_reports_a_singular_operator() {
        // pure Neumann Laplacian: every row sums to zero, constants are its null space
        let (nx, ny) = (6, 5);
        let mut op = Op5::zeros(nx, ny);
        for k in 0..nx * ny {
            op.ae[k] = if k % nx + 1 < nx { 1.0 } else { 0.0 };
            op.aw[k] = if k % nx > 0 { 1.0 } else { 0.0 };
            op.an[k] = if k + nx < nx * ny { 1.0 } else { 0.0 };
            op.as_[k] = if k >= nx { 1.0 } else { 0.0 };
            op.ap[k] = op.ae[k] + op.aw[k] + op.an[k] + op.as_[k];
        }
        let mut lu = BandLu::default();
        assert!(matches!(
            lu.factor(&op),
            Err(LinSolveError::Singular { .. })
        ));
    }
}
