//! runout-linsolve: sparse linear solvers for the 5-point systems of a structured
//! (stretched, staggered) 2-D grid — pressure correction, solids volume-fraction
//! correction, momentum and granular energy (docs/model.md §4.6–4.8, §4.13).
//!
//! # Usage
//! 1. Describe the block once with a [`Pattern`] (`nx × ny`, cells optionally
//!    [`CellKind::Fixed`]), create a [`Stencil5`] and a solver from a
//!    [`LinearSolverKind`] with [`build`]; call [`LinearSolver::set_pattern`] once.
//! 2. Every outer iteration: refill `a_p, a_e, a_w, a_n, a_s, b` in place (MFIX sign
//!    convention `a_P φ_P = Σ a_nb φ_nb + b`), call [`LinearSolver::setup`]
//!    (numeric factorisation / preconditioner), then [`LinearSolver::solve`] with the
//!    initial guess in `x`.
//! 3. The returned [`SolveStats`] carries the iteration count and the relative residual
//!    ‖b − A x‖₂/‖b‖₂ recomputed from the matrix after the solve (never the solver's
//!    recursive estimate).
//!
//! ```
//! use runout_linsolve::{build, LinearSolverKind, MultigridParams, Pattern, Stencil5};
//! let (nx, ny) = (8, 4);
//! let mut pattern = Pattern::new(nx, ny)?;
//! pattern.fix(0, 0)?; // reference pressure cell
//! let mut a = Stencil5::new(pattern.clone());
//! for j in 0..ny {
//!     for i in 0..nx {
//!         let k = pattern.idx(i, j);
//!         if (i, j) == (0, 0) { a.a_p[k] = 1.0; continue; } // p'_ref = b = 0
//!         if i + 1 < nx { a.a_e[k] = 1.0; }
//!         if i > 0 { a.a_w[k] = 1.0; }
//!         if j + 1 < ny { a.a_n[k] = 1.0; }
//!         if j > 0 { a.a_s[k] = 1.0; }
//!         a.a_p[k] = a.a_e[k] + a.a_w[k] + a.a_n[k] + a.a_s[k];
//!         a.b[k] = if i == nx - 1 { 1.0 } else { 0.0 };
//!     }
//! }
//! a.b[pattern.idx(nx - 1, ny - 1)] -= 1.0 * ny as f64; // compatible sources
//! let mut solver = build(&LinearSolverKind::MultigridCg(MultigridParams::default())); // rtol 1e-8
//! solver.set_pattern(&pattern)?;
//! solver.setup(&a)?;
//! let mut x = vec![0.0; nx * ny];
//! let stats = solver.solve(&a, &mut x)?;
//! assert!(stats.converged && stats.rel_residual <= 1e-8);
//! # Ok::<(), runout_linsolve::LinSolveError>(())
//! ```
//!
//! # Backends ([`LinearSolverKind`])
//! - [`SparseLuSolver`], [`CholeskySolver`]: faer sparse LU / LLᵀ on the CSC matrix built
//!   by [`CscAssembler`] (pattern and argsort cached, symbolic factorisation reused).
//! - [`BiCgStab`] with a [`Precond`]: Jacobi, ILU(0), line-y (Thomas along y),
//!   aggregation multigrid V- or K-cycle.
//! - [`MultigridCg`]: flexible CG + aggregation multigrid (K-cycle by default); iterations
//!   to 1e-8 stay at 12–13 from 10k to 1M cells on paper-like stretched grids.
//!
//! - [`ActiveBox`]: any of these on the rectangle of rows that have links, the rows
//!   outside it (a_P φ = b) solved exactly (the solids equations of a slide).
//!
//! Per-equation defaults: [`LinearSolverKind::pressure_default`],
//! [`LinearSolverKind::volume_fraction_default`], [`LinearSolverKind::momentum_default`],
//! [`LinearSolverKind::granular_energy_default`]; the measurements behind them are in
//! `docs/studies/performance.md` (`cargo run --release -p runout-linsolve --example linsolve_table`).
#![deny(missing_docs)]

mod active_box;
mod band;
mod bicgstab;
mod direct;
mod kernels;
mod multigrid;
mod precond;
pub mod problems;
mod reduced;
mod stencil;
mod team;

use std::time::Duration;

pub use active_box::{coupled_rect, ActiveBox, Rect};
pub use bicgstab::BiCgStab;
pub use direct::{CholeskySolver, CscAssembler, SparseLuSolver, DIRECT_MAX_REL_RESIDUAL};
pub use multigrid::{Cycle, MultigridCg, MultigridParams};
pub use precond::Precond;
pub use stencil::{for_each_row, CellKind, Pattern, RowMut, Stencil5};

/// Errors of the linear solvers. Every failure is reported, never a panic or a hang.
#[derive(Debug, thiserror::Error, Clone, PartialEq)]
pub enum LinSolveError {
    /// A vector or grid has the wrong size.
    #[error("dimension mismatch in {what}: expected {expected}, got {got}")]
    DimensionMismatch {
        /// which argument
        what: &'static str,
        /// expected length
        expected: usize,
        /// actual length
        got: usize,
    },
    /// The stencil was built on a different pattern from the one set on the solver.
    #[error("the stencil's pattern differs from the one given to set_pattern")]
    PatternMismatch,
    /// `setup` or `solve` was called before `set_pattern` / `setup`.
    #[error("solver used before {0}")]
    NotReady(&'static str),
    /// NaN or ±∞ in a coefficient, the right-hand side or the initial guess.
    #[error("non-finite value in {what} at cell {cell}")]
    NonFinite {
        /// which array
        what: &'static str,
        /// linear cell index k = i + nx·j
        cell: usize,
    },
    /// A zero diagonal coefficient a_P.
    #[error("zero diagonal a_P at cell {cell}")]
    ZeroDiagonal {
        /// linear cell index
        cell: usize,
    },
    /// The matrix is (numerically) singular.
    #[error("singular matrix: {detail}")]
    Singular {
        /// what revealed it
        detail: String,
    },
    /// Cholesky was asked to factor a matrix that is not symmetric positive definite.
    #[error("matrix is not symmetric positive definite: {detail}")]
    NotSpd {
        /// what revealed it
        detail: String,
    },
    /// A Krylov method broke down (a zero inner product) and could not restart.
    #[error("{method} breakdown after {iterations} iterations")]
    Breakdown {
        /// solver name
        method: &'static str,
        /// iterations done
        iterations: usize,
    },
    /// Invalid solver parameter.
    #[error("invalid parameter {name}: {detail}")]
    InvalidParameter {
        /// parameter name
        name: &'static str,
        /// why
        detail: String,
    },
    /// Error raised inside faer.
    #[error("faer: {0}")]
    Faer(String),
}

/// Statistics of one solve (cf. russell's `StatsLinSol`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SolveStats {
    /// Iterations done (0 for direct solvers).
    pub iterations: usize,
    /// ‖b − A x‖₂ / ‖b‖₂ recomputed from the matrix after the solve (‖b − A x‖₂ if b = 0).
    pub rel_residual: f64,
    /// Whether `rel_residual ≤ rtol`. False when the iteration cap was hit first; the
    /// caller decides whether an inexact solve is acceptable (MFIX accepts it, §4.13).
    pub converged: bool,
    /// Wall time of the last [`LinearSolver::setup`] (numeric factorisation or
    /// preconditioner construction).
    pub t_setup: Duration,
    /// Wall time of this solve, including the residual check.
    pub t_solve: Duration,
}

/// One interface for every backend (after diffsol's and russell's linear-solver traits).
pub trait LinearSolver: Send {
    /// Short name for tables and logs.
    fn name(&self) -> String;
    /// Fixes the sparsity pattern; builds symbolic factorisations and allocates every work
    /// vector. Call once per grid.
    fn set_pattern(&mut self, pattern: &Pattern) -> Result<(), LinSolveError>;
    /// Reads the coefficients of `a` (not `b`): numeric factorisation or preconditioner set-up.
    /// Call after every refill of the coefficients.
    fn setup(&mut self, a: &Stencil5) -> Result<(), LinSolveError>;
    /// Solves `A x = b` with the coefficients given to the last `setup` and `a.b`; `x` holds
    /// the initial guess on entry (ignored by direct solvers) and the solution on exit.
    fn solve(&mut self, a: &Stencil5, x: &mut [f64]) -> Result<SolveStats, LinSolveError>;
    /// Reads new coefficients of the same pattern like `setup`, but a solver may keep the
    /// preconditioner built by the last `setup` (an approximate inverse of a nearby
    /// matrix, e.g. within one time step): `solve` then iterates with the new coefficients
    /// and confirms convergence on their true residual, so only the iteration count can
    /// change. The default is a full `setup`; the multigrid solvers keep their hierarchy.
    fn refresh(&mut self, a: &Stencil5) -> Result<(), LinSolveError> {
        self.setup(a)
    }
    /// `setup` followed by `solve`.
    fn setup_and_solve(
        &mut self,
        a: &Stencil5,
        x: &mut [f64],
    ) -> Result<SolveStats, LinSolveError> {
        self.setup(a)?;
        self.solve(a, x)
    }
}

/// Backend selection (a plain enum so that it can be read from a case file).
#[derive(Clone, Debug, PartialEq)]
pub enum LinearSolverKind {
    /// faer sparse LU with partial pivoting; symbolic factorisation reused.
    SparseLu,
    /// faer sparse Cholesky LLᵀ (symmetric positive definite only); symbolic reused.
    Cholesky,
    /// Own right-preconditioned BiCGSTAB.
    BiCgStab {
        /// stop when ‖b − A x‖₂ ≤ rtol ‖b‖₂
        rtol: f64,
        /// iteration cap (always respected)
        max_iter: usize,
        /// preconditioner
        precond: Precond,
    },
    /// Flexible CG preconditioned by aggregation multigrid (symmetric matrices).
    MultigridCg(MultigridParams),
}

/// Defaults per equation, measured in docs/studies/performance.md (table of `linsolve_table`).
/// Tolerances and caps follow MFIX (docs/model.md §4.13: LEQ_TOL = 1e-4; LEQ_IT = 20 for P'
/// and ε', 5 for U/V, 15 for θ); our rtol is ‖b − A x‖/‖b‖, MFIX's ‖r‖/‖r₀‖, the same
/// for the zero initial guess of the correction equations.
impl LinearSolverKind {
    /// Gas pressure correction (§4.6): flexible CG + aggregation-multigrid K-cycle. It
    /// reaches 1e-4 in 6–7 iterations at 10k–1M cells, where MFIX's capped line-BiCGSTAB
    /// stalls near 1e-1.
    pub fn pressure_default() -> Self {
        Self::MultigridCg(MultigridParams {
            rtol: 1e-4,
            max_iter: 20,
            ..MultigridParams::default()
        })
    }
    /// Solids volume-fraction correction (§4.7): BiCGSTAB + multigrid K-cycle, because in
    /// the packed bed the K_cp term makes the equation diffusion dominated (elliptic),
    /// where line/ILU preconditioners need tens to hundreds of iterations.
    pub fn volume_fraction_default() -> Self {
        Self::BiCgStab {
            rtol: 1e-4,
            max_iter: 20,
            precond: Precond::MultigridK,
        }
    }
    /// Momentum (§4.4): BiCGSTAB + line-y preconditioner (MFIX's `LEQ_PC = 'LINE'`),
    /// 3 iterations to 1e-4 at every size.
    pub fn momentum_default() -> Self {
        Self::transport_default(1e-4, 5)
    }
    /// Granular energy (§4.8): BiCGSTAB + line-y, cap 15 as MFIX's `LEQ_IT(8)`.
    pub fn granular_energy_default() -> Self {
        Self::transport_default(1e-4, 15)
    }
    /// BiCGSTAB + line-y with the given tolerance and cap (convection-dominated transport).
    pub fn transport_default(rtol: f64, max_iter: usize) -> Self {
        Self::BiCgStab {
            rtol,
            max_iter,
            precond: Precond::LineY,
        }
    }
}

/// Creates a solver of the given kind.
pub fn build(kind: &LinearSolverKind) -> Box<dyn LinearSolver> {
    match kind {
        LinearSolverKind::SparseLu => Box::new(SparseLuSolver::new()),
        LinearSolverKind::Cholesky => Box::new(CholeskySolver::new()),
        LinearSolverKind::BiCgStab {
            rtol,
            max_iter,
            precond,
        } => Box::new(BiCgStab::new(*rtol, *max_iter, *precond)),
        LinearSolverKind::MultigridCg(p) => Box::new(MultigridCg::new(p.clone())),
    }
}

pub(crate) fn check_rtol(rtol: f64) -> Result<(), LinSolveError> {
    if rtol.is_finite() && rtol > 0.0 && rtol < 1.0 {
        Ok(())
    } else {
        Err(LinSolveError::InvalidParameter {
            name: "rtol",
            detail: format!("{rtol} is not in (0, 1)"),
        })
    }
}
