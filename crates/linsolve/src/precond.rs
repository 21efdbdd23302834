//! Preconditioners for [`crate::BiCgStab`], all built on the reduced 5-point operator.

use rayon::prelude::*;

use crate::kernels::{for_each_indexed, SharedMut, PAR_MIN_LEN};
use crate::multigrid::Hierarchy;
use crate::stencil::Op5;
use crate::team::Team;
use crate::{Cycle, LinSolveError, MultigridParams};

/// Coarsest level of the multigrid preconditioner at most: its systems (the ε' correction
/// on the coupled rectangle) are small and set up at every outer iteration, where the band
/// LU's factorisation of a 1024-cell level cost more than the levels it replaces (family M
/// to 0.2 s on one thread: ε' solves 0.29–0.30 s with 1024, 0.22 s with 64;
/// docs/studies/performance.md, "The y lines split in two").
const PRECOND_COARSEST_CELLS: usize = 64;

/// Preconditioner choice for BiCGSTAB.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Precond {
    /// None (M = I).
    None,
    /// Jacobi, M = diag(a_P).
    Jacobi,
    /// Incomplete LU with zero fill in the natural ordering (Saad 2003 §10.3.2); for a
    /// 5-point stencil M = (D + L) D⁻¹ (D + U) with D from the ILU recurrence.
    Ilu0,
    /// Line (block-Jacobi) preconditioner: the tridiagonal system along every y line
    /// (wall-normal, the stretched direction) solved exactly by the Thomas algorithm —
    /// MFIX's `LEQ_PC = 'LINE'` idea (docs/model.md §4.13) without the red/black sweeps.
    LineY,
    /// One symmetric V-cycle of the aggregation multigrid of [`crate::MultigridCg`]
    /// (a fixed linear operator, as BiCGSTAB's theory assumes).
    MultigridV,
    /// One K-cycle of the aggregation multigrid. It is not a fixed linear map, so this is
    /// BiCGSTAB with a variable preconditioner, which converges well in practice
    /// (Vogel 2007, "Flexible BiCG and flexible Bi-CGSTAB"); convergence is always
    /// confirmed on the true residual.
    MultigridK,
}

/// Set-up data of a preconditioner; `apply` computes z = M⁻¹ r without allocating.
pub(crate) enum PrecondImpl {
    Identity,
    Jacobi { inv_diag: Vec<f64> },
    Ilu0 { inv_d: Vec<f64> },
    LineY(LineY),
    Multigrid(Box<Hierarchy>),
}

impl PrecondImpl {
    pub fn allocate(kind: Precond, nx: usize, ny: usize) -> Self {
        let n = nx * ny;
        match kind {
            Precond::None => Self::Identity,
            Precond::Jacobi => Self::Jacobi {
                inv_diag: vec![0.0; n],
            },
            Precond::Ilu0 => Self::Ilu0 {
                inv_d: vec![0.0; n],
            },
            Precond::LineY => Self::LineY(LineY::allocate(n)),
            Precond::MultigridV | Precond::MultigridK => {
                let cycle = if kind == Precond::MultigridV {
                    Cycle::V
                } else {
                    Cycle::K
                };
                let params = MultigridParams {
                    cycle,
                    coarsest_max_cells: PRECOND_COARSEST_CELLS,
                    ..MultigridParams::default()
                };
                Self::Multigrid(Box::new(Hierarchy::allocate(nx, ny, &params)))
            }
        }
    }

    /// Builds the preconditioner for `op`; `fixed` marks the fixed cells of level 0.
    pub fn setup(&mut self, op: &Op5, fixed: &[bool]) -> Result<(), LinSolveError> {
        let nx = op.nx;
        match self {
            Self::Identity => {}
            Self::Jacobi { inv_diag } => for_each_indexed(inv_diag, |k, v| *v = 1.0 / op.ap[k]),
            Self::Ilu0 { inv_d } => {
                // d_k = a_P − a_W a_E(k−1)/d_(k−1) − a_S a_N(k−nx)/d_(k−nx)
                for k in 0..op.len() {
                    let (i, j) = (k % nx, k / nx);
                    let mut d = op.ap[k];
                    if i > 0 {
                        d -= op.aw[k] * op.ae[k - 1] * inv_d[k - 1];
                    }
                    if j > 0 {
                        d -= op.as_[k] * op.an[k - nx] * inv_d[k - nx];
                    }
                    if d == 0.0 || !d.is_finite() {
                        return Err(LinSolveError::Singular {
                            detail: format!("ILU(0) pivot {d} at cell {k}"),
                        });
                    }
                    inv_d[k] = 1.0 / d;
                }
            }
            Self::LineY(line) => line.setup(op)?,
            Self::Multigrid(h) => h.setup(op, fixed)?,
        }
        Ok(())
    }

    /// z = M⁻¹ r.
    pub fn apply(&mut self, op: &Op5, r: &[f64], z: &mut [f64]) {
        let nx = op.nx;
        match self {
            Self::Identity => z.copy_from_slice(r),
            Self::Jacobi { inv_diag } => for_each_indexed(z, |k, v| *v = r[k] * inv_diag[k]),
            Self::Ilu0 { inv_d } => {
                let ny = op.ny;
                // forward: (D + L) u = r, row by row
                for j in 0..ny {
                    let o = nx * j;
                    if j > 0 {
                        for k in o..o + nx {
                            z[k] = r[k] + op.as_[k] * z[k - nx];
                        }
                    } else {
                        z[..nx].copy_from_slice(&r[..nx]);
                    }
                    z[o] *= inv_d[o];
                    for k in o + 1..o + nx {
                        z[k] = (z[k] + op.aw[k] * z[k - 1]) * inv_d[k];
                    }
                }
                // backward: (D + U) z = D u
                for j in (0..ny).rev() {
                    let o = nx * j;
                    if j + 1 < ny {
                        for k in o..o + nx {
                            z[k] += op.an[k] * z[k + nx] * inv_d[k];
                        }
                    }
                    for k in (o..o + nx - 1).rev() {
                        z[k] += op.ae[k] * z[k + 1] * inv_d[k];
                    }
                }
            }
            Self::LineY(line) => line.apply(op, r, z),
            Self::Multigrid(h) => Team::run_for(r.len(), |team| h.precondition(team, r, z)),
        }
    }
}

/// Columns per parallel task of [`LineY::par_solve`], and half the fewest columns for which
/// [`LineY::apply`] goes parallel: narrower grids stay serial.
const LINE_Y_MIN_BLOCK: usize = 32;

/// The line preconditioner along y ([`Precond::LineY`]): the Thomas factors of every
/// column's tridiagonal system. The columns are independent, so solving them in blocks on
/// several threads gives the bits of the serial solve.
pub(crate) struct LineY {
    /// 1/denom_k of the forward sweep
    inv_denom: Vec<f64>,
    /// c_k = a_N/denom_k, the back-substitution factor
    upper: Vec<f64>,
}

impl LineY {
    fn allocate(n: usize) -> Self {
        Self {
            inv_denom: vec![0.0; n],
            upper: vec![0.0; n],
        }
    }

    /// Thomas factorisation along y: denom_k = a_P − a_S c_(k−nx), c_k = a_N/denom_k.
    fn setup(&mut self, op: &Op5) -> Result<(), LinSolveError> {
        let nx = op.nx;
        for k in 0..op.len() {
            let mut d = op.ap[k];
            if k >= nx {
                d -= op.as_[k] * self.upper[k - nx];
            }
            if d == 0.0 || !d.is_finite() {
                return Err(LinSolveError::Singular {
                    detail: format!("line-preconditioner pivot {d} at cell {k}"),
                });
            }
            self.inv_denom[k] = 1.0 / d;
            self.upper[k] = op.an[k] * self.inv_denom[k];
        }
        Ok(())
    }

    /// z = M⁻¹ r, in parallel column blocks on large grids.
    fn apply(&self, op: &Op5, r: &[f64], z: &mut [f64]) {
        if op.len() < PAR_MIN_LEN || op.nx < 2 * LINE_Y_MIN_BLOCK {
            self.solve_columns(op, r, z);
        } else {
            self.par_solve(op, r, z);
        }
    }

    /// z = M⁻¹ r, all columns on this thread.
    fn solve_columns(&self, op: &Op5, r: &[f64], z: &mut [f64]) {
        assert_eq!(z.len(), op.len());
        // SAFETY: z holds nx·ny values and nothing else accesses it during the call.
        unsafe { self.solve_block(op, r, SharedMut(z.as_mut_ptr()), 0, op.nx) }
    }

    /// z = M⁻¹ r, blocks of columns on rayon's threads.
    fn par_solve(&self, op: &Op5, r: &[f64], z: &mut [f64]) {
        assert_eq!(z.len(), op.len());
        let nx = op.nx;
        let width = (nx / (4 * rayon::current_num_threads().max(1))).max(LINE_Y_MIN_BLOCK);
        let z = SharedMut(z.as_mut_ptr());
        // SAFETY: block b reads and writes only its columns b·width..(b+1)·width of z.
        (0..nx.div_ceil(width))
            .into_par_iter()
            .for_each(|b| unsafe {
                self.solve_block(op, r, z, b * width, ((b + 1) * width).min(nx))
            });
    }

    /// The columns i0..i1, advanced together row by row (contiguous, vectorisable).
    ///
    /// # Safety
    /// `z` points to nx·ny values; no other thread accesses columns i0..i1 of them.
    unsafe fn solve_block(&self, op: &Op5, r: &[f64], z: SharedMut, i0: usize, i1: usize) {
        let (nx, ny, w) = (op.nx, op.ny, i1 - i0);
        let row = |j: usize| std::slice::from_raw_parts_mut(z.0.add(nx * j + i0), w);
        let cells = |j: usize| nx * j + i0..nx * j + i1;
        for ((v, rk), inv) in row(0)
            .iter_mut()
            .zip(&r[cells(0)])
            .zip(&self.inv_denom[cells(0)])
        {
            *v = rk * inv;
        }
        for j in 1..ny {
            let (below, this) = (row(j - 1), row(j));
            let k = cells(j);
            let coeffs = r[k.clone()]
                .iter()
                .zip(&op.as_[k.clone()])
                .zip(&self.inv_denom[k]);
            for ((v, zs), ((rk, a_s), inv)) in this.iter_mut().zip(below.iter()).zip(coeffs) {
                *v = (rk + a_s * zs) * inv;
            }
        }
        for j in (0..ny.saturating_sub(1)).rev() {
            let (this, above) = (row(j), row(j + 1));
            for ((v, zn), c) in this.iter_mut().zip(above.iter()).zip(&self.upper[cells(j)]) {
                *v += c * zn;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A diagonally dominant operator with pseudo-random links (a fixed linear
    /// congruential sequence) and a random right-hand side.
    fn random_system(nx: usize, ny: usize) -> (Op5, Vec<f64>) {
        let mut state = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut op = Op5::zeros(nx, ny);
        for k in 0..op.len() {
            (op.ae[k], op.aw[k], op.an[k], op.as_[k]) = (next(), next(), next(), next());
            op.ap[k] = op.ae[k] + op.aw[k] + op.an[k] + op.as_[k] + 0.1 + next();
        }
        let r = (0..op.len()).map(|_| next() - 0.5).collect();
        (op, r)
    }

    #[test]
    fn line_y_in_parallel_column_blocks_is_the_serial_solve() {
        // 203 columns: blocks of unequal width, the last one partial
        let (op, r) = random_system(203, 97);
        let mut line = LineY::allocate(op.len());
        line.setup(&op).unwrap();
        let mut serial = vec![0.0; op.len()];
        line.solve_columns(&op, &r, &mut serial);
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(4)
            .build()
            .unwrap();
        let mut parallel = vec![f64::NAN; op.len()];
        pool.install(|| line.par_solve(&op, &r, &mut parallel));
        assert!(serial
            .iter()
            .zip(&parallel)
            .all(|(a, b)| a.to_bits() == b.to_bits()));
        let mut applied = vec![f64::NAN; op.len()];
        line.apply(&op, &r, &mut applied);
        assert!(serial
            .iter()
            .zip(&applied)
            .all(|(a, b)| a.to_bits() == b.to_bits()));
        // M z = r along every column: the preconditioner is the exact line solve
        for k in 0..op.len() {
            let mut mz = op.ap[k] * serial[k];
            if k >= op.nx {
                mz -= op.as_[k] * serial[k - op.nx];
            }
            if k + op.nx < op.len() {
                mz -= op.an[k] * serial[k + op.nx];
            }
            assert!((mz - r[k]).abs() < 1e-12, "row {k}: {mz} vs {}", r[k]);
        }
    }
}
