//! Right-preconditioned BiCGSTAB for one right-hand side (van der Vorst 1992, Alg. in
//! Saad 2003 §7.4.2), on the reduced 5-point operator. Work vectors are allocated by
//! `set_pattern`; the iteration loop does not allocate.

use std::time::Instant;

use crate::kernels::{axpy, dot, for_each_indexed, norm2};
use crate::precond::PrecondImpl;
use crate::reduced::ReducedSystem;
use crate::stencil::{apply5, residual5};
use crate::{check_rtol, LinSolveError, LinearSolver, Pattern, Precond, SolveStats, Stencil5};

struct Work {
    system: ReducedSystem,
    precond: PrecondImpl,
    r: Vec<f64>,
    r_hat: Vec<f64>,
    p: Vec<f64>,
    v: Vec<f64>,
    p_hat: Vec<f64>,
    s_hat: Vec<f64>,
    t: Vec<f64>,
}

/// Own BiCGSTAB with a choice of [`Precond`]. Stops when the residual ‖b − A x‖₂ ≤
/// `rtol`·‖b‖₂; a converged recursive residual is confirmed against the true one, and
/// the iteration restarts from the true residual when they disagree.
pub struct BiCgStab {
    rtol: f64,
    max_iter: usize,
    kind: Precond,
    work: Option<Work>,
}

impl BiCgStab {
    /// `rtol`: relative tolerance on ‖b − A x‖₂/‖b‖₂; `max_iter`: cap (MFIX: 5–20, §4.13).
    pub fn new(rtol: f64, max_iter: usize, precond: Precond) -> Self {
        Self {
            rtol,
            max_iter,
            kind: precond,
            work: None,
        }
    }
}

impl LinearSolver for BiCgStab {
    fn name(&self) -> String {
        format!("BiCGSTAB+{:?}", self.kind)
    }

    fn set_pattern(&mut self, pattern: &Pattern) -> Result<(), LinSolveError> {
        check_rtol(self.rtol)?;
        let (nx, ny, n) = (pattern.nx(), pattern.ny(), pattern.len());
        let z = || vec![0.0; n];
        self.work = Some(Work {
            system: ReducedSystem::new(pattern),
            precond: PrecondImpl::allocate(self.kind, nx, ny),
            r: z(),
            r_hat: z(),
            p: z(),
            v: z(),
            p_hat: z(),
            s_hat: z(),
            t: z(),
        });
        Ok(())
    }

    fn setup(&mut self, a: &Stencil5) -> Result<(), LinSolveError> {
        let w = self
            .work
            .as_mut()
            .ok_or(LinSolveError::NotReady("set_pattern"))?;
        let precond = &mut w.precond;
        w.system.setup(a, |op, fixed| precond.setup(op, fixed))
    }

    /// With a multigrid preconditioner, keeps its hierarchy from the last `setup` and takes
    /// the new coefficients as the operator; the other preconditioners are rebuilt (they
    /// cost one pass over the matrix).
    fn refresh(&mut self, a: &Stencil5) -> Result<(), LinSolveError> {
        let keeps_hierarchy = matches!(self.kind, Precond::MultigridV | Precond::MultigridK);
        match self.work.as_mut() {
            Some(w) if keeps_hierarchy && w.system.is_ready() => w.system.refresh(a),
            _ => self.setup(a),
        }
    }

    fn solve(&mut self, a: &Stencil5, x: &mut [f64]) -> Result<SolveStats, LinSolveError> {
        let t0 = Instant::now();
        let w = self
            .work
            .as_mut()
            .ok_or(LinSolveError::NotReady("set_pattern"))?;
        let b_norm = w.system.load_rhs(a, x)?;
        let iterations = bicgstab(b_norm, w, x, self.rtol, self.max_iter)?;
        w.system.stats(a, x, iterations, self.rtol, t0, &mut w.t)
    }
}

/// The iteration; returns the number of iterations done.
fn bicgstab(
    b_norm: f64,
    w: &mut Work,
    x: &mut [f64],
    rtol: f64,
    max_iter: usize,
) -> Result<usize, LinSolveError> {
    const METHOD: &str = "BiCGSTAB";
    let c = w.system.op.coeffs();
    // the tolerance refers to the caller's b, as the reported residual does
    if b_norm == 0.0 {
        x.fill(0.0);
        return Ok(0);
    }
    let target = rtol * b_norm;
    residual5(&c, &w.system.b, x, &mut w.r);
    let mut r_norm = norm2(&w.r);
    let mut it = 0;
    // restart loop: (re)start from the true residual
    'restart: while r_norm > target && it < max_iter {
        w.r_hat.copy_from_slice(&w.r);
        w.p.fill(0.0);
        w.v.fill(0.0);
        let (mut rho, mut alpha, mut omega) = (1.0f64, 1.0f64, 1.0f64);
        let mut progressed = false;
        while it < max_iter {
            let rho_new = dot(&w.r_hat, &w.r);
            if rho_new == 0.0 || !rho_new.is_finite() {
                break;
            }
            let beta = (rho_new / rho) * (alpha / omega);
            rho = rho_new;
            {
                let (r, v) = (&w.r, &w.v);
                for_each_indexed(&mut w.p, |k, pk| *pk = r[k] + beta * (*pk - omega * v[k]));
            }
            w.precond.apply(&w.system.op, &w.p, &mut w.p_hat);
            apply5(&c, None, &w.p_hat, &mut w.v);
            let rv = dot(&w.r_hat, &w.v);
            if rv == 0.0 || !rv.is_finite() {
                break;
            }
            alpha = rho / rv;
            it += 1;
            progressed = true;
            // s = r − α v, stored in r
            axpy(-alpha, &w.v, &mut w.r);
            axpy(alpha, &w.p_hat, x);
            let s_norm = norm2(&w.r);
            if s_norm <= target {
                // confirm with the true residual
                residual5(&c, &w.system.b, x, &mut w.r);
                r_norm = norm2(&w.r);
                continue 'restart;
            }
            w.precond.apply(&w.system.op, &w.r, &mut w.s_hat);
            apply5(&c, None, &w.s_hat, &mut w.t);
            let tt = dot(&w.t, &w.t);
            if tt == 0.0 || !tt.is_finite() {
                break;
            }
            omega = dot(&w.t, &w.r) / tt;
            axpy(omega, &w.s_hat, x);
            axpy(-omega, &w.t, &mut w.r);
            r_norm = norm2(&w.r);
            if !r_norm.is_finite() {
                return Err(LinSolveError::Breakdown {
                    method: METHOD,
                    iterations: it,
                });
            }
            if r_norm <= target {
                residual5(&c, &w.system.b, x, &mut w.r);
                r_norm = norm2(&w.r);
                continue 'restart;
            }
            if omega == 0.0 {
                break;
            }
        }
        // breakdown: restart from the true residual unless nothing moved since the last one
        if !progressed {
            return Err(LinSolveError::Breakdown {
                method: METHOD,
                iterations: it,
            });
        }
        residual5(&c, &w.system.b, x, &mut w.r);
        r_norm = norm2(&w.r);
        if !r_norm.is_finite() {
            return Err(LinSolveError::Breakdown {
                method: METHOD,
                iterations: it,
            });
        }
    }
    Ok(it)
}
