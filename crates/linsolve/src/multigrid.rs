//! Aggregation multigrid on the structured grid, used as the preconditioner of a flexible
//! CG for the pressure-correction equation.
//!
//! * **Coarsening**: 2 × 2 cell agglomeration with piecewise-constant prolongation P and
//!   Galerkin coarse operators A_c = Pᵀ A P ("additive correction multigrid", Hutchinson &
//!   Raithby 1986). On a 5-point matrix Pᵀ A P is again 5-point: a coarse link is the sum
//!   of the fine links crossing the coarse face, a coarse diagonal the sum of the fine
//!   diagonals minus the links inside the aggregate. Fixed cells belong to no aggregate.
//! * **Smoother**: zebra (red/black) line Gauss–Seidel alternating x lines and y lines,
//!   each line solved by the Thomas algorithm, so it is robust for both directions of
//!   anisotropy that a stretched grid produces (Trottenberg et al. 2001 §5.1). The
//!   post-smoother runs the pre-smoother's steps in reverse order, which keeps the cycle
//!   symmetric for a symmetric A.
//! * **Cycle**: piecewise-constant prolongation makes the V-cycle lose accuracy level by
//!   level; the K-cycle (Notay & Vassilevski 2008) replaces each coarse solve by two
//!   flexible-CG steps preconditioned by the next level's cycle, which restores
//!   level-independent convergence at about twice the coarse work. The outer iteration
//!   is flexible CG (Notay 2000, FCG(1)), because the K-cycle is not a fixed linear map.
//! * **Coarsest level** (≤ `coarsest_max_cells`): band LU ([`BandLu`], cost ∝ cells ×
//!   min(nx, ny) per solve). Stopping at ~1000 rather than ~60 cells drops the two or three
//!   smallest levels, whose sweeps cost more per cell than the band solve (on 400 × 100
//!   cells: 57 µs for the 650-cell level's visits against 142 µs for it and the levels
//!   below, per outer iteration; docs/studies/performance.md, "The y lines split in two").
//! * **Split y lines** (`smoother.rs`): on levels from [`smoother::Y_SPLIT_MIN_CELLS`] cells a y line is solved as
//!   two halves, rows below m = ny/2 eliminated upwards and rows from m downwards, joined
//!   at the two middle rows and substituted back outwards (the two-block partition method
//!   for tridiagonal systems, Golub & Van Loan 2013 §4.5.4). With the lower half
//!   eliminated, x_(m−1) = g + u x_m; with the upper half, x_m = h + z x_(m−1); so
//!   x_(m−1) = (g + u h)/(1 − u z). The halves are two tasks that work on the same rows
//!   as the x lines' tasks, so the solution stays in the cache of the core that owns the
//!   rows; split by columns, half of it moved between the cores at every change of
//!   direction, and the y sweep ran no faster on two threads than on one
//!   (docs/studies/performance.md, "The y lines split in two"). The split depends only on
//!   the level's size, so the arithmetic is the same on any number of threads.
//! * **Threads**: a whole flexible-CG solve (a preconditioner application under BiCGSTAB)
//!   runs on one [`Team`], which keeps the pool's threads awake through the coarse levels'
//!   short sweeps; every loop's chunks are fixed by the level's size, so the result is the
//!   same on any number of threads.

use std::time::Instant;

mod smoother;

use crate::band::BandLu;
use crate::kernels::{axpy_on, dot_on, for_each_indexed_on, norm2_on};
use crate::reduced::ReducedSystem;
use crate::stencil::{apply5_on, for_each_row_on, residual5_on, Op5};
use crate::team::Team;
use crate::{check_rtol, LinSolveError, LinearSolver, Pattern, SolveStats, Stencil5};

/// Multigrid cycle type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cycle {
    /// One recursive call per level.
    V,
    /// Two flexible-CG steps per coarse level (Notay & Vassilevski 2008).
    K,
}

/// Parameters of [`MultigridCg`].
#[derive(Clone, Debug, PartialEq)]
pub struct MultigridParams {
    /// Stop when ‖b − A x‖₂ ≤ rtol ‖b‖₂.
    pub rtol: f64,
    /// Iteration cap of the outer flexible CG.
    pub max_iter: usize,
    /// Cycle type.
    pub cycle: Cycle,
    /// Coarsening stops once a level has at most this many cells; that level is solved by
    /// band LU (factor ∝ cells × min(nx, ny)², solve ∝ cells × min(nx, ny), per visit).
    pub coarsest_max_cells: usize,
}

impl Default for MultigridParams {
    fn default() -> Self {
        Self {
            rtol: 1e-8,
            max_iter: 200,
            cycle: Cycle::K,
            coarsest_max_cells: 1024,
        }
    }
}

/// One grid level with its operator, line factorisations and work vectors.
struct Level {
    op: Op5,
    active: Vec<bool>,
    /// Thomas factors of the x lines: 1/denom, a_E/denom and a_W/denom
    x_inv: Vec<f64>,
    x_up: Vec<f64>,
    x_low: Vec<f64>,
    /// Thomas factors of the y lines: 1/denom and a_N/denom (rows below `y_split`), or
    /// a_S/denom eliminating from the top (rows from `y_split`)
    y_inv: Vec<f64>,
    y_up: Vec<f64>,
    /// first row of the upper half of the split y lines, 0 if they are not split
    y_split: usize,
    /// per column, 1/(1 − u z) joining the halves (module doc)
    y_join: Vec<f64>,
    /// per column, the eliminated values of the rows y_split − 1 (g) and y_split (h)
    y_edge_lower: Vec<f64>,
    y_edge_upper: Vec<f64>,
    rhs: Vec<f64>,
    sol: Vec<f64>,
    res: Vec<f64>,
    // used when this level is the coarse problem of the level above
    coarse_rhs: Vec<f64>,
    corr: Vec<f64>,
    v1: Vec<f64>,
    w1: Vec<f64>,
    r2: Vec<f64>,
    w2: Vec<f64>,
}

impl Level {
    fn new(nx: usize, ny: usize) -> Self {
        let n = nx * ny;
        let z = || vec![0.0; n];
        let y_split = if n >= smoother::Y_SPLIT_MIN_CELLS && ny >= 4 {
            ny / 2
        } else {
            0
        };
        Self {
            y_split,
            y_join: vec![0.0; nx],
            y_edge_lower: vec![0.0; nx],
            y_edge_upper: vec![0.0; nx],
            op: Op5::zeros(nx, ny),
            active: vec![true; n],
            x_inv: z(),
            x_up: z(),
            x_low: z(),
            y_inv: z(),
            y_up: z(),
            rhs: z(),
            sol: z(),
            res: z(),
            coarse_rhs: z(),
            corr: z(),
            v1: z(),
            w1: z(),
            r2: z(),
            w2: z(),
        }
    }
}

/// Builds coarse = Pᵀ fine P for 2 × 2 agglomeration.
fn galerkin(fine: &Level, coarse: &mut Level) {
    let (nxf, nyf) = (fine.op.nx, fine.op.ny);
    let (nxc, nyc) = (coarse.op.nx, coarse.op.ny);
    let f = &fine.op;
    for jc in 0..nyc {
        for ic in 0..nxc {
            let kc = ic + nxc * jc;
            let (mut ap, mut ae, mut aw, mut an, mut as_) = (0.0, 0.0, 0.0, 0.0, 0.0);
            let mut any = false;
            for dj in 0..2 {
                for di in 0..2 {
                    let (i, j) = (2 * ic + di, 2 * jc + dj);
                    if i >= nxf || j >= nyf {
                        continue;
                    }
                    let k = i + nxf * j;
                    if !fine.active[k] {
                        continue;
                    }
                    any = true;
                    ap += f.ap[k];
                    if di == 0 {
                        ap -= f.ae[k];
                        aw += f.aw[k];
                    } else {
                        ae += f.ae[k];
                        ap -= f.aw[k];
                    }
                    if dj == 0 {
                        ap -= f.an[k];
                        as_ += f.as_[k];
                    } else {
                        an += f.an[k];
                        ap -= f.as_[k];
                    }
                }
            }
            let c = &mut coarse.op;
            if any {
                (c.ap[kc], c.ae[kc], c.aw[kc], c.an[kc], c.as_[kc]) = (ap, ae, aw, an, as_);
            } else {
                (c.ap[kc], c.ae[kc], c.aw[kc], c.an[kc], c.as_[kc]) = (1.0, 0.0, 0.0, 0.0, 0.0);
            }
            coarse.active[kc] = any;
        }
    }
}

/// coarse_rhs = Pᵀ r, by coarse rows (each coarse cell adds its fine cells row by row, x
/// fastest, as one pass over the fine grid would).
fn restrict(fine: &Level, r: &[f64], coarse_rhs: &mut [f64], nxc: usize, team: &Team<'_>) {
    let (nxf, nyf) = (fine.op.nx, fine.op.ny);
    let active = &fine.active;
    for_each_row_on(team, coarse_rhs, nxc, |jc, row| {
        row.fill(0.0);
        for j in (2 * jc..2 * jc + 2).filter(|&j| j < nyf) {
            let o = nxf * j;
            for i in 0..nxf {
                if active[o + i] {
                    row[i / 2] += r[o + i];
                }
            }
        }
    });
}

/// x += P e.
fn prolong_add(fine: &mut Level, e: &[f64], nxc: usize, team: &Team<'_>) {
    let nxf = fine.op.nx;
    let active = &fine.active;
    let add_row = |j: usize, row: &mut [f64]| {
        let (o, co) = (nxf * j, nxc * (j / 2));
        for (i, v) in row.iter_mut().enumerate() {
            if active[o + i] {
                *v += e[co + i / 2];
            }
        }
    };
    for_each_row_on(team, &mut fine.sol, nxf, add_row);
}

/// The level hierarchy and the cycle; shared by [`MultigridCg`] and the BiCGSTAB
/// multigrid preconditioner.
pub(crate) struct Hierarchy {
    levels: Vec<Level>,
    coarsest: BandLu,
    cycle: Cycle,
}

impl Hierarchy {
    pub fn allocate(nx: usize, ny: usize, params: &MultigridParams) -> Self {
        let (mut nx, mut ny) = (nx, ny);
        let mut levels = vec![Level::new(nx, ny)];
        while nx * ny > params.coarsest_max_cells.max(1) && (nx > 1 || ny > 1) {
            nx = nx.div_ceil(2);
            ny = ny.div_ceil(2);
            levels.push(Level::new(nx, ny));
        }
        Self {
            levels,
            coarsest: BandLu::default(),
            cycle: params.cycle,
        }
    }

    pub fn n_levels(&self) -> usize {
        self.levels.len()
    }

    pub fn setup(&mut self, op: &Op5, fixed: &[bool]) -> Result<(), LinSolveError> {
        {
            let l0 = &mut self.levels[0];
            l0.op.ap.copy_from_slice(&op.ap);
            l0.op.ae.copy_from_slice(&op.ae);
            l0.op.aw.copy_from_slice(&op.aw);
            l0.op.an.copy_from_slice(&op.an);
            l0.op.as_.copy_from_slice(&op.as_);
            for (a, &f) in l0.active.iter_mut().zip(fixed) {
                *a = !f;
            }
        }
        for l in 1..self.levels.len() {
            let (fine, coarse) = self.levels.split_at_mut(l);
            galerkin(&fine[l - 1], &mut coarse[0]);
        }
        let last = self.levels.len() - 1;
        for lv in &mut self.levels[..last] {
            lv.factor_lines()?;
        }
        self.coarsest.factor(&self.levels[last].op)
    }

    /// z = B r, one cycle from a zero initial guess, by `team`.
    pub fn precondition(&mut self, team: &Team<'_>, r: &[f64], z: &mut [f64]) {
        self.levels[0].rhs.copy_from_slice(r);
        cycle(&mut self.levels, &mut self.coarsest, self.cycle, team);
        z.copy_from_slice(&self.levels[0].sol);
    }
}

/// One cycle on `levels[0]`: `sol` ← B `rhs`.
fn cycle(levels: &mut [Level], coarsest: &mut BandLu, kind: Cycle, team: &Team<'_>) {
    let (lv, rest) = levels.split_first_mut().expect("at least one level");
    if rest.is_empty() {
        coarsest.solve(&lv.rhs, &mut lv.sol);
        return;
    }
    lv.sol.fill(0.0);
    lv.pre_smooth(team);
    residual5_on(team, &lv.op.coeffs(), &lv.rhs, &lv.sol, &mut lv.res);
    let nxc = rest[0].op.nx;
    restrict(lv, &lv.res, &mut rest[0].coarse_rhs, nxc, team);
    coarse_correction(rest, coarsest, kind, team);
    prolong_add(lv, &rest[0].corr, nxc, team);
    lv.post_smooth(team);
}

/// Approximately solves `levels[0]` with rhs `coarse_rhs`, result in `corr`.
fn coarse_correction(levels: &mut [Level], coarsest: &mut BandLu, kind: Cycle, team: &Team<'_>) {
    let lv0_is_coarsest = levels.len() == 1;
    let lv = &mut levels[0];
    lv.rhs.copy_from_slice(&lv.coarse_rhs);
    cycle(levels, coarsest, kind, team);
    let lv = &mut levels[0];
    lv.corr.copy_from_slice(&lv.sol);
    if kind == Cycle::V || lv0_is_coarsest {
        return;
    }
    // K-cycle: two flexible-CG steps (Notay & Vassilevski 2008, Alg. 2.1 with t = 0)
    let c = lv.op.coeffs();
    lv.v1.copy_from_slice(&lv.sol);
    apply5_on(team, &c, None, &lv.v1, &mut lv.w1);
    let rho1 = dot_on(team, &lv.v1, &lv.w1);
    let alpha1 = dot_on(team, &lv.v1, &lv.coarse_rhs);
    if rho1 <= 0.0 || !rho1.is_finite() {
        return; // corr = v1: plain V-cycle step
    }
    {
        let (r, w1) = (&lv.coarse_rhs, &lv.w1);
        let f = alpha1 / rho1;
        for_each_indexed_on(team, &mut lv.r2, |k, v| *v = r[k] - f * w1[k]);
    }
    lv.rhs.copy_from_slice(&lv.r2);
    cycle(levels, coarsest, kind, team);
    let lv = &mut levels[0];
    let c = lv.op.coeffs();
    apply5_on(team, &c, None, &lv.sol, &mut lv.w2); // v2 = sol
    let gamma = dot_on(team, &lv.sol, &lv.w1);
    let beta = dot_on(team, &lv.sol, &lv.w2);
    let alpha2 = dot_on(team, &lv.sol, &lv.r2);
    let rho2 = beta - gamma * gamma / rho1;
    let (v1, v2) = (&lv.v1, &lv.sol);
    if rho2 <= 0.0 || !rho2.is_finite() {
        let f = alpha1 / rho1;
        for_each_indexed_on(team, &mut lv.corr, |k, v| *v = f * v1[k]);
    } else {
        let f1 = alpha1 / rho1 - gamma * alpha2 / (rho1 * rho2);
        let f2 = alpha2 / rho2;
        for_each_indexed_on(team, &mut lv.corr, |k, v| *v = f1 * v1[k] + f2 * v2[k]);
    }
}

struct CgWork {
    system: ReducedSystem,
    hierarchy: Hierarchy,
    r: Vec<f64>,
    z: Vec<f64>,
    p: Vec<f64>,
    q: Vec<f64>,
}

/// Flexible CG (FCG(1), Notay 2000) preconditioned by the aggregation multigrid
/// K-cycle (or V-cycle). For symmetric positive definite matrices — the pressure
/// correction (docs/model.md §4.6); a non-SPD matrix is detected by pᵀAp ≤ 0 and reported.
pub struct MultigridCg {
    params: MultigridParams,
    work: Option<CgWork>,
}

impl MultigridCg {
    /// A solver with the given parameters; call [`LinearSolver::set_pattern`] next.
    pub fn new(params: MultigridParams) -> Self {
        Self { params, work: None }
    }

    /// Number of grid levels (after `set_pattern`).
    pub fn n_levels(&self) -> usize {
        self.work.as_ref().map_or(0, |w| w.hierarchy.n_levels())
    }
}

impl LinearSolver for MultigridCg {
    fn name(&self) -> String {
        format!("AMG-{:?}+FCG", self.params.cycle)
    }

    fn set_pattern(&mut self, pattern: &Pattern) -> Result<(), LinSolveError> {
        check_rtol(self.params.rtol)?;
        let (nx, ny, n) = (pattern.nx(), pattern.ny(), pattern.len());
        let z = || vec![0.0; n];
        self.work = Some(CgWork {
            system: ReducedSystem::new(pattern),
            hierarchy: Hierarchy::allocate(nx, ny, &self.params),
            r: z(),
            z: z(),
            p: z(),
            q: z(),
        });
        Ok(())
    }

    fn setup(&mut self, a: &Stencil5) -> Result<(), LinSolveError> {
        let w = self
            .work
            .as_mut()
            .ok_or(LinSolveError::NotReady("set_pattern"))?;
        let hierarchy = &mut w.hierarchy;
        w.system.setup(a, |op, fixed| hierarchy.setup(op, fixed))
    }

    /// Keeps the hierarchy of the last `setup` as the preconditioner and takes the new
    /// coefficients as the operator of the flexible CG.
    fn refresh(&mut self, a: &Stencil5) -> Result<(), LinSolveError> {
        match self.work.as_mut() {
            Some(w) if w.system.is_ready() => w.system.refresh(a),
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
        let (rtol, max_iter) = (self.params.rtol, self.params.max_iter);
        let iterations = fcg(b_norm, w, x, rtol, max_iter)?;
        w.system.stats(a, x, iterations, rtol, t0, &mut w.q)
    }
}

/// FCG(1): p_k = z_k − (z_kᵀ q_(k−1) / p_(k−1)ᵀ q_(k−1)) p_(k−1), q = A p; the whole
/// iteration runs on one [`Team`], which keeps the pool's threads awake between the short
/// sweeps of the coarse levels.
fn fcg(
    b_norm: f64,
    w: &mut CgWork,
    x: &mut [f64],
    rtol: f64,
    max_iter: usize,
) -> Result<usize, LinSolveError> {
    // the tolerance refers to the caller's b, as the reported residual does
    if b_norm == 0.0 {
        x.fill(0.0);
        return Ok(0);
    }
    Team::run_for(x.len(), |team| fcg_on(team, rtol * b_norm, w, x, max_iter))
}

/// The iterations of [`fcg`] by `team`, to ‖r‖₂ ≤ `target`.
fn fcg_on(
    team: &Team<'_>,
    target: f64,
    w: &mut CgWork,
    x: &mut [f64],
    max_iter: usize,
) -> Result<usize, LinSolveError> {
    let c = w.system.op.coeffs();
    residual5_on(team, &c, &w.system.b, x, &mut w.r);
    let mut r_norm = norm2_on(team, &w.r);
    let mut it = 0;
    let mut pq_prev = 0.0;
    let mut fresh = true;
    while r_norm > target && it < max_iter {
        w.hierarchy.precondition(team, &w.r, &mut w.z);
        if fresh {
            w.p.copy_from_slice(&w.z);
        } else {
            let beta = dot_on(team, &w.z, &w.q) / pq_prev;
            let z = &w.z;
            for_each_indexed_on(team, &mut w.p, |k, v| *v = z[k] - beta * *v);
        }
        apply5_on(team, &c, None, &w.p, &mut w.q);
        let pq = dot_on(team, &w.p, &w.q);
        if pq <= 0.0 || !pq.is_finite() {
            return Err(LinSolveError::NotSpd {
                detail: format!("pᵀAp = {pq:.3e} in flexible CG at iteration {it}"),
            });
        }
        let alpha = dot_on(team, &w.p, &w.r) / pq;
        axpy_on(team, alpha, &w.p, x);
        axpy_on(team, -alpha, &w.q, &mut w.r);
        pq_prev = pq;
        fresh = false;
        it += 1;
        r_norm = norm2_on(team, &w.r);
        if r_norm <= target {
            // confirm with the true residual; restart the recurrence if they disagree
            residual5_on(team, &c, &w.system.b, x, &mut w.r);
            r_norm = norm2_on(team, &w.r);
            fresh = true;
        }
    }
    Ok(it)
}
