//! The reduced system an iterative solver ([`BiCgStab`](crate::BiCgStab),
//! [`MultigridCg`](crate::MultigridCg)) iterates on, and the stages of
//! [`LinearSolver`](crate::LinearSolver) around its iteration: the coefficients read by
//! `setup` and `refresh`, the checks and the right-hand side before `solve`, the statistics
//! from the true residual after it.

use std::time::{Duration, Instant};

use crate::kernels::{first_non_finite, norm2};
use crate::stencil::{check_len, reduced_rhs, set_fixed_values, Op5};
use crate::{LinSolveError, Pattern, SolveStats, Stencil5};

/// The reduced operator and right-hand side on the pattern of `set_pattern`.
pub(crate) struct ReducedSystem {
    pattern: Pattern,
    /// the operator of the last `setup` or `refresh`
    pub op: Op5,
    /// the right-hand side of the current `solve`, a_nb·φ_fixed moved into it
    pub b: Vec<f64>,
    /// whether the last `setup` succeeded
    ready: bool,
    t_setup: Duration,
}

impl ReducedSystem {
    /// Zero operator and right-hand side for `pattern`, not ready for `solve`.
    pub fn new(pattern: &Pattern) -> Self {
        Self {
            pattern: pattern.clone(),
            op: Op5::zeros(pattern.nx(), pattern.ny()),
            b: vec![0.0; pattern.len()],
            ready: false,
            t_setup: Duration::ZERO,
        }
    }

    /// Whether a `setup` succeeded since `set_pattern`.
    pub fn is_ready(&self) -> bool {
        self.ready
    }

    /// `setup`: reads the coefficients of `a`, then builds the preconditioner on them with
    /// `build` (operator, fixed-cell mask); ready for `solve` once both succeed.
    pub fn setup(
        &mut self,
        a: &Stencil5,
        build: impl FnOnce(&Op5, &[bool]) -> Result<(), LinSolveError>,
    ) -> Result<(), LinSolveError> {
        let t0 = Instant::now();
        self.check_pattern(a)?;
        self.ready = false;
        self.read_coefficients(a)?;
        build(&self.op, a.pattern().fixed_mask())?;
        self.ready = true;
        self.t_setup = t0.elapsed();
        Ok(())
    }

    /// `refresh`: reads the coefficients of `a`; the preconditioner of the last `setup` is kept.
    pub fn refresh(&mut self, a: &Stencil5) -> Result<(), LinSolveError> {
        self.check_pattern(a)?;
        self.read_coefficients(a)
    }

    /// `solve` before the iteration: checks `a.b` and the initial guess `x`, reduces the
    /// right-hand side into `b` and returns ‖a.b‖₂, the caller's norm the tolerance refers to.
    pub fn load_rhs(&mut self, a: &Stencil5, x: &[f64]) -> Result<f64, LinSolveError> {
        if !self.ready {
            return Err(LinSolveError::NotReady("setup"));
        }
        self.check_pattern(a)?;
        check_len("x", a.len(), x.len())?;
        a.validate_rhs()?;
        if let Some(cell) = first_non_finite(x) {
            return Err(LinSolveError::NonFinite {
                what: "initial guess x",
                cell,
            });
        }
        reduced_rhs(a, &mut self.b);
        Ok(norm2(&a.b))
    }

    /// `solve` after the iteration: sets the fixed cells of `x` and reports the relative
    /// residual recomputed from `a` (`work`: scratch of the cells' length), converged when
    /// it is ≤ `rtol`; the solve's time counts from `t0`.
    pub fn stats(
        &self,
        a: &Stencil5,
        x: &mut [f64],
        iterations: usize,
        rtol: f64,
        t0: Instant,
        work: &mut [f64],
    ) -> Result<SolveStats, LinSolveError> {
        set_fixed_values(a, x);
        let rel_residual = a.rel_residual(x, work)?;
        Ok(SolveStats {
            iterations,
            rel_residual,
            converged: rel_residual <= rtol,
            t_setup: self.t_setup,
            t_solve: t0.elapsed(),
        })
    }

    fn check_pattern(&self, a: &Stencil5) -> Result<(), LinSolveError> {
        if a.pattern() != &self.pattern {
            return Err(LinSolveError::PatternMismatch);
        }
        Ok(())
    }

    fn read_coefficients(&mut self, a: &Stencil5) -> Result<(), LinSolveError> {
        a.validate_coefficients()?;
        self.op.reduce_from(a);
        Ok(())
    }
}
