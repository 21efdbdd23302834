//! Direct solvers on faer: sparse LU (partial pivoting) and sparse Cholesky LLᵀ.
//!
//! The CSC pattern of the reduced 5-point operator is built once with
//! `SymbolicSparseColMat::try_new_from_indices`, which also returns the argsort that maps
//! our value order to CSC order; every refill goes through `SparseColMat::new_from_argsort`
//! (3 ms at 1 M nnz against 12 ms for a triplet sort, style.md §B2). The symbolic
//! factorisation (fill-reducing ordering, elimination tree) is computed once per pattern.

use std::time::{Duration, Instant};

use faer::linalg::solvers::SolveCore;
use faer::sparse::linalg::solvers::{Llt, Lu, SymbolicLlt, SymbolicLu};
use faer::sparse::{
    Argsort, FaerError, Pair, SparseColMat, SparseColMatRef, SymbolicSparseColMat,
    SymbolicSparseColMatRef,
};
use faer::{Conj, MatMut, Side};
use rayon::prelude::*;

use crate::stencil::{check_len, reduced_rhs, Op5};
use crate::{LinSolveError, LinearSolver, Pattern, SolveStats, Stencil5};

/// A direct solve whose recomputed relative residual exceeds this is reported as
/// [`LinSolveError::Singular`]. LU with partial pivoting and Cholesky are backward stable,
/// so on a non-singular matrix the residual is ~1e-14 whatever the condition number;
/// only a (numerically) singular matrix gets near this bound.
pub const DIRECT_MAX_REL_RESIDUAL: f64 = 1e-6;

#[derive(Clone, Copy)]
enum Slot {
    P,
    E,
    W,
    N,
    S,
}

/// Conversion of a [`Stencil5`] to a faer CSC matrix with a fixed pattern.
///
/// The matrix is that of the *reduced* system the solvers work on: rows of fixed cells
/// hold only a_P, and links between active and fixed cells are dropped (their
/// contribution a_nb·φ_fixed is in [`CscAssembler::reduced_rhs`]). Links pointing out of
/// the block are ignored. The pattern and the argsort are built once by
/// [`CscAssembler::new`]; [`CscAssembler::matrix`] only refills values.
pub struct CscAssembler {
    pattern: Pattern,
    symbolic: SymbolicSparseColMat<usize>,
    argsort: Argsort<usize>,
    /// (row cell, which coefficient) for each value, in `try_new_from_indices` order
    slots: Vec<(usize, Slot)>,
    values: Vec<f64>,
    op: Op5,
    rhs: Vec<f64>,
    work: Vec<f64>,
}

impl CscAssembler {
    /// Builds the CSC pattern and argsort for `pattern`.
    pub fn new(pattern: &Pattern) -> Result<Self, LinSolveError> {
        let (nx, ny) = (pattern.nx(), pattern.ny());
        let fixed = pattern.fixed_mask();
        let mut pairs = Vec::with_capacity(5 * pattern.len());
        let mut slots = Vec::with_capacity(5 * pattern.len());
        for j in 0..ny {
            for i in 0..nx {
                let k = i + nx * j;
                pairs.push(Pair::new(k, k));
                slots.push((k, Slot::P));
                if fixed[k] {
                    continue;
                }
                let mut link = |inside: bool, m: usize, s: Slot| {
                    if inside && !fixed[m] {
                        pairs.push(Pair::new(k, m));
                        slots.push((k, s));
                    }
                };
                link(i + 1 < nx, k + 1, Slot::E);
                link(i > 0, k.wrapping_sub(1), Slot::W);
                link(j + 1 < ny, k + nx, Slot::N);
                link(j > 0, k.wrapping_sub(nx), Slot::S);
            }
        }
        let n = pattern.len();
        let (symbolic, argsort) = SymbolicSparseColMat::try_new_from_indices(n, n, &pairs)
            .map_err(|e| LinSolveError::Faer(format!("{e:?}")))?;
        Ok(Self {
            pattern: pattern.clone(),
            symbolic,
            argsort,
            values: vec![0.0; slots.len()],
            slots,
            op: Op5::zeros(nx, ny),
            rhs: vec![0.0; n],
            work: vec![0.0; n],
        })
    }

    /// The symbolic CSC structure (for a faer symbolic factorisation).
    pub fn symbolic(&self) -> &SymbolicSparseColMat<usize> {
        &self.symbolic
    }

    /// The reduced right-hand side for `a` (b plus a_nb·φ_fixed of fixed neighbours).
    pub fn reduced_rhs(&mut self, a: &Stencil5) -> Result<&[f64], LinSolveError> {
        if a.pattern() != &self.pattern {
            return Err(LinSolveError::PatternMismatch);
        }
        a.validate_rhs()?;
        reduced_rhs(a, &mut self.rhs);
        Ok(&self.rhs)
    }

    /// Refills the values from `a` (parallel over entries) and returns the CSC matrix of the
    /// reduced system.
    pub fn matrix(&mut self, a: &Stencil5) -> Result<SparseColMat<usize, f64>, LinSolveError> {
        if a.pattern() != &self.pattern {
            return Err(LinSolveError::PatternMismatch);
        }
        a.validate_coefficients()?;
        self.op.reduce_from(a);
        let op = &self.op;
        self.values
            .par_iter_mut()
            .zip(self.slots.par_iter())
            .with_min_len(1 << 14)
            .for_each(|(v, &(k, s))| {
                *v = match s {
                    Slot::P => op.ap[k],
                    Slot::E => -op.ae[k],
                    Slot::W => -op.aw[k],
                    Slot::N => -op.an[k],
                    Slot::S => -op.as_[k],
                }
            });
        SparseColMat::new_from_argsort(self.symbolic.clone(), &self.argsort, &self.values)
            .map_err(|e| LinSolveError::Faer(format!("{e:?}")))
    }

    /// Solves with `solve_in_place` applied to the reduced right-hand side, then checks the
    /// true residual.
    pub(crate) fn solve_with(
        &mut self,
        a: &Stencil5,
        x: &mut [f64],
        t_setup: Duration,
        solve_in_place: impl FnOnce(MatMut<'_, f64>),
    ) -> Result<SolveStats, LinSolveError> {
        let t0 = Instant::now();
        if a.pattern() != &self.pattern {
            return Err(LinSolveError::PatternMismatch);
        }
        check_len("x", a.len(), x.len())?;
        a.validate_rhs()?;
        reduced_rhs(a, &mut self.rhs);
        x.copy_from_slice(&self.rhs);
        let n = x.len();
        solve_in_place(MatMut::from_column_major_slice_mut(x, n, 1));
        if let Some(cell) = crate::kernels::first_non_finite(x) {
            return Err(LinSolveError::Singular {
                detail: format!("non-finite solution at cell {cell}"),
            });
        }
        crate::stencil::set_fixed_values(a, x);
        let rel_residual = a.rel_residual(x, &mut self.work)?;
        if rel_residual > DIRECT_MAX_REL_RESIDUAL {
            return Err(LinSolveError::Singular {
                detail: format!("relative residual {rel_residual:.3e} after a direct solve"),
            });
        }
        Ok(SolveStats {
            iterations: 0,
            rel_residual,
            converged: true,
            t_setup,
            t_solve: t0.elapsed(),
        })
    }
}

/// The state both direct solvers keep: the CSC assembler and the symbolic factorisation of
/// the pattern of `set_pattern`, the numeric factorisation of the last `setup`.
struct Factored<S, N> {
    csc: Option<CscAssembler>,
    symbolic: Option<S>,
    numeric: Option<N>,
    t_setup: Duration,
}

impl<S, N> Default for Factored<S, N> {
    fn default() -> Self {
        Self {
            csc: None,
            symbolic: None,
            numeric: None,
            t_setup: Duration::ZERO,
        }
    }
}

impl<S, N> Factored<S, N> {
    /// `set_pattern`: the CSC pattern and its symbolic factorisation by `analyse`.
    fn set_pattern(
        &mut self,
        pattern: &Pattern,
        analyse: impl FnOnce(SymbolicSparseColMatRef<'_, usize>) -> Result<S, FaerError>,
    ) -> Result<(), LinSolveError> {
        let csc = CscAssembler::new(pattern)?;
        let symbolic =
            analyse(csc.symbolic.as_ref()).map_err(|e| LinSolveError::Faer(format!("{e:?}")))?;
        self.csc = Some(csc);
        self.symbolic = Some(symbolic);
        self.numeric = None;
        Ok(())
    }

    /// `setup`: refills the matrix from `a` and factors it by `factor` (symbolic
    /// factorisation, reduced operator, matrix).
    fn setup(
        &mut self,
        a: &Stencil5,
        factor: impl FnOnce(&S, &Op5, SparseColMatRef<'_, usize, f64>) -> Result<N, LinSolveError>,
    ) -> Result<(), LinSolveError> {
        let t0 = Instant::now();
        let (Some(csc), Some(symbolic)) = (self.csc.as_mut(), self.symbolic.as_ref()) else {
            return Err(LinSolveError::NotReady("set_pattern"));
        };
        let mat = csc.matrix(a)?;
        self.numeric = None; // a failed factorisation leaves none for `solve`
        self.numeric = Some(factor(symbolic, &csc.op, mat.as_ref())?);
        self.t_setup = t0.elapsed();
        Ok(())
    }

    /// `solve`: `solve_in_place` by the numeric factorisation on the reduced right-hand side.
    fn solve(
        &mut self,
        a: &Stencil5,
        x: &mut [f64],
        solve_in_place: impl FnOnce(&N, MatMut<'_, f64>),
    ) -> Result<SolveStats, LinSolveError> {
        let (Some(csc), Some(numeric)) = (self.csc.as_mut(), self.numeric.as_ref()) else {
            return Err(LinSolveError::NotReady("setup"));
        };
        csc.solve_with(a, x, self.t_setup, |rhs| solve_in_place(numeric, rhs))
    }
}

/// faer sparse LU with the symbolic factorisation reused across refills.
#[derive(Default)]
pub struct SparseLuSolver(Factored<SymbolicLu<usize>, Lu<usize, f64>>);

impl SparseLuSolver {
    /// An unconfigured solver; call [`LinearSolver::set_pattern`] next.
    pub fn new() -> Self {
        Self::default()
    }
}

impl LinearSolver for SparseLuSolver {
    fn name(&self) -> String {
        "faer LU".into()
    }

    fn set_pattern(&mut self, pattern: &Pattern) -> Result<(), LinSolveError> {
        self.0.set_pattern(pattern, SymbolicLu::try_new)
    }

    fn setup(&mut self, a: &Stencil5) -> Result<(), LinSolveError> {
        self.0.setup(a, |symbolic, _, mat| {
            Lu::try_new_with_symbolic(symbolic.clone(), mat).map_err(|e| match e {
                faer::sparse::linalg::LuError::SymbolicSingular { index } => {
                    LinSolveError::Singular {
                        detail: format!("structurally singular at pivot {index}"),
                    }
                }
                other => LinSolveError::Faer(format!("{other:?}")),
            })
        })
    }

    fn solve(&mut self, a: &Stencil5, x: &mut [f64]) -> Result<SolveStats, LinSolveError> {
        self.0
            .solve(a, x, |lu, rhs| lu.solve_in_place_with_conj(Conj::No, rhs))
    }
}

/// faer sparse Cholesky LLᵀ (lower triangle) with the symbolic factorisation reused.
/// `setup` rejects a matrix whose reduced operator is not symmetric.
#[derive(Default)]
pub struct CholeskySolver(Factored<SymbolicLlt<usize>, Llt<usize, f64>>);

impl CholeskySolver {
    /// An unconfigured solver; call [`LinearSolver::set_pattern`] next.
    pub fn new() -> Self {
        Self::default()
    }
}

/// Relative tolerance of the symmetry check a_E(k) = a_W(k+1), a_N(k) = a_S(k+nx): a few
/// hundred ulps, so that coefficients computed twice in a different order still pass.
const SYMMETRY_RTOL: f64 = 1e-12;

fn check_symmetric(op: &Op5) -> Result<(), LinSolveError> {
    let (nx, ny) = (op.nx, op.ny);
    let close = |a: f64, b: f64| (a - b).abs() <= SYMMETRY_RTOL * a.abs().max(b.abs());
    for j in 0..ny {
        for i in 0..nx {
            let k = i + nx * j;
            if i + 1 < nx && !close(op.ae[k], op.aw[k + 1]) {
                return Err(LinSolveError::NotSpd {
                    detail: format!(
                        "a_E({k}) = {} but a_W({}) = {}",
                        op.ae[k],
                        k + 1,
                        op.aw[k + 1]
                    ),
                });
            }
            if j + 1 < ny && !close(op.an[k], op.as_[k + nx]) {
                return Err(LinSolveError::NotSpd {
                    detail: format!(
                        "a_N({k}) = {} but a_S({}) = {}",
                        op.an[k],
                        k + nx,
                        op.as_[k + nx]
                    ),
                });
            }
        }
    }
    Ok(())
}

impl LinearSolver for CholeskySolver {
    fn name(&self) -> String {
        "faer Cholesky".into()
    }

    fn set_pattern(&mut self, pattern: &Pattern) -> Result<(), LinSolveError> {
        self.0
            .set_pattern(pattern, |csc| SymbolicLlt::try_new(csc, Side::Lower))
    }

    fn setup(&mut self, a: &Stencil5) -> Result<(), LinSolveError> {
        self.0.setup(a, |symbolic, op, mat| {
            check_symmetric(op)?;
            Llt::try_new_with_symbolic(symbolic.clone(), mat, Side::Lower).map_err(|e| {
                LinSolveError::NotSpd {
                    detail: format!("{e:?}"),
                }
            })
        })
    }

    fn solve(&mut self, a: &Stencil5, x: &mut [f64]) -> Result<SolveStats, LinSolveError> {
        self.0
            .solve(a, x, |llt, rhs| llt.solve_in_place_with_conj(Conj::No, rhs))
    }
}
