//! Preconditioners for [`crate::BiCgStab`], all built on the reduced 5-point operator.

use crate::kernels::for_each_indexed;
use crate::multigrid::Hierarchy;
use crate::stencil::Op5;
use crate::{Cycle, LinSolveError, MultigridParams};

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
    Jacobi {
        inv_diag: Vec<f64>,
    },
    Ilu0 {
        inv_d: Vec<f64>,
    },
    LineY {
        inv_denom: Vec<f64>,
        upper: Vec<f64>,
    },
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
            Precond::LineY => Self::LineY {
                inv_denom: vec![0.0; n],
                upper: vec![0.0; n],
            },
            Precond::MultigridV | Precond::MultigridK => {
                let cycle = if kind == Precond::MultigridV {
                    Cycle::V
                } else {
                    Cycle::K
                };
                let params = MultigridParams {
                    cycle,
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
            Self::LineY { inv_denom, upper } => {
                // Thomas factorisation along y: denom_k = a_P − a_S c_(k−nx), c_k = a_N/denom_k
                for k in 0..op.len() {
                    let mut d = op.ap[k];
                    if k >= nx {
                        d -= op.as_[k] * upper[k - nx];
                    }
                    if d == 0.0 || !d.is_finite() {
                        return Err(LinSolveError::Singular {
                            detail: format!("line-preconditioner pivot {d} at cell {k}"),
                        });
                    }
                    inv_denom[k] = 1.0 / d;
                    upper[k] = op.an[k] * inv_denom[k];
                }
            }
            Self::Multigrid(h) => h.setup(op, fixed)?,
        }
        Ok(())
    }

    /// z = M⁻¹ r.
    pub fn apply(&mut self, op: &Op5, r: &[f64], z: &mut [f64]) {
        let (nx, n) = (op.nx, op.len());
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
            Self::LineY { inv_denom, upper } => {
                // all columns at once, row by row (contiguous, vectorisable)
                for i in 0..nx {
                    z[i] = r[i] * inv_denom[i];
                }
                for k in nx..n {
                    z[k] = (r[k] + op.as_[k] * z[k - nx]) * inv_denom[k];
                }
                for k in (0..n - nx).rev() {
                    z[k] += upper[k] * z[k + nx];
                }
            }
            Self::Multigrid(h) => h.precondition(r, z),
        }
    }
}
