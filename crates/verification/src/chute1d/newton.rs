//! The Newton solver of the 1-D chute (module doc of [`super`]): the progress norms of the
//! pseudo-transient continuation, the banded finite-difference Jacobian (factorised by faer's
//! sparse LU with partial pivoting), the Sherman–Morrison step for the holdup row (docs/model.md §4.1 grid) and the
//! step length that keeps ln εs, ln θ and εs < 1 in range.

use super::*;

/// Root-mean-square residual with each row divided by a fixed reference of its equation
/// (the progress measure of the pseudo-transient continuation): the floor-normal weight
/// W_n = ρs g cos α M for the y-momentum rows, M for the holdup, the floor-parallel weight
/// W_t = ρs g sin α M for the x-momentum rows and W_t √(g cos α M) (the weight's power at the
/// free-fall speed over the depth M) for the granular-energy rows.
pub(super) fn global_norm(problem: &Problem, e: &Evaluation) -> f64 {
    let n = problem.n();
    let holdup = problem.p.holdup;
    let weight_normal = problem.rho_s * problem.g_normal * holdup;
    let weight_tangential = problem.rho_s * problem.g_tangential * holdup;
    let power = weight_tangential * (problem.g_normal * holdup).sqrt();
    let sum: f64 = e
        .residual
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let reference = match k % VARS {
                EPS if k / VARS + 1 == n => holdup,
                EPS => weight_normal,
                U => weight_tangential,
                _ => power,
            };
            (r / reference).powi(2)
        })
        .sum();
    (sum / e.residual.len() as f64).sqrt()
}

/// Max over rows of |residual|/Σ|terms| and the row where it occurs.
pub(super) fn normalised_residual(e: &Evaluation) -> (f64, usize) {
    e.residual
        .iter()
        .zip(&e.scale)
        .enumerate()
        .map(|(k, (r, s))| {
            let value = if *s > 0.0 { r.abs() / s } else { r.abs() };
            (
                if value.is_finite() {
                    value
                } else {
                    f64::INFINITY
                },
                k,
            )
        })
        .fold(
            (0.0, 0),
            |best, item| if item.0 > best.0 { item } else { best },
        )
}

/// A banded matrix with lower and upper bandwidths `kl`, `ku`, stored row-wise (row i holds
/// columns i − kl … i + ku); assembled here, factorised by faer ([`BandMatrix::solve_in_place`]).
pub(super) struct BandMatrix {
    pub(super) n: usize,
    pub(super) kl: usize,
    pub(super) ku: usize,
    pub(super) width: usize,
    pub(super) data: Vec<f64>,
}

impl BandMatrix {
    pub(super) fn new(n: usize, kl: usize, ku: usize) -> Self {
        let width = kl + ku + 1;
        Self {
            n,
            kl,
            ku,
            width,
            data: vec![0.0; n * width],
        }
    }

    #[inline]
    pub(super) fn index(&self, i: usize, j: usize) -> usize {
        debug_assert!(j + self.kl >= i && j <= i + self.ku);
        i * self.width + (j + self.kl - i)
    }

    pub(super) fn add(&mut self, i: usize, j: usize, value: f64) {
        let k = self.index(i, j);
        self.data[k] += value;
    }

    pub(super) fn get(&self, i: usize, j: usize) -> f64 {
        self.data[self.index(i, j)]
    }

    /// Solves the system for every right-hand side in `rhs` (each of length n, overwritten
    /// with the solutions) by faer's sparse LU with partial pivoting: the band's entries
    /// (structural zeros left out) as a compressed-column matrix.
    pub(super) fn solve_in_place(self, rhs: &mut [Vec<f64>]) -> Result<(), Chute1dError> {
        use faer::linalg::solvers::SolveCore;
        let n = self.n;
        let mut triplets = Vec::new();
        for i in 0..n {
            let first = i.saturating_sub(self.kl);
            let last = (i + self.ku).min(n - 1);
            for j in first..=last {
                let v = self.get(i, j);
                if v != 0.0 {
                    triplets.push(faer::sparse::Triplet::new(i, j, v));
                }
            }
        }
        let matrix =
            faer::sparse::SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &triplets)
                .map_err(|_| Chute1dError::Singular(0))?;
        let lu = matrix.as_ref().sp_lu().map_err(|e| match e {
            faer::sparse::linalg::LuError::SymbolicSingular { index } => {
                Chute1dError::Singular(index)
            }
            _ => Chute1dError::Singular(n),
        })?;
        for r in rhs.iter_mut() {
            lu.solve_in_place_with_conj(
                faer::Conj::No,
                faer::MatMut::from_column_major_slice_mut(r, n, 1),
            );
            if let Some(k) = r.iter().position(|v| !v.is_finite()) {
                return Err(Chute1dError::Singular(k));
            }
        }
        Ok(())
    }
}

/// Finite-difference Jacobian of the banded rows (every row but the holdup's columns beyond
/// the band), coloured by cell index modulo 2·reach + 1.
pub(super) fn jacobian(problem: &Problem, x: &[f64], base: &Evaluation) -> BandMatrix {
    let n = problem.n();
    let size = VARS * n;
    let band = VARS * (STENCIL_REACH + 1) - 1;
    let mut matrix = BandMatrix::new(size, band, band);
    let colours = 2 * STENCIL_REACH + 1;
    // step scales: 1 for the logarithms (a relative change of FD_STEP), the largest |u|
    let mut magnitude: [f64; VARS] = [1.0, 0.0, 1.0];
    for j in 0..n {
        magnitude[U] = magnitude[U].max(x[VARS * j + U].abs());
    }
    let dy = problem.p.grid.widths();
    let mut trial = x.to_vec();
    for colour in 0..colours {
        for v in 0..VARS {
            trial.copy_from_slice(x);
            let mut steps = vec![0.0; n];
            for j in (colour..n).step_by(colours) {
                let k = VARS * j + v;
                let step = FD_STEP * x[k].abs().max(magnitude[v]).max(f64::MIN_POSITIVE);
                trial[k] = x[k] + step;
                steps[j] = trial[k] - x[k];
            }
            let perturbed = problem.evaluate(&trial);
            for j in (colour..n).step_by(colours) {
                let col = VARS * j + v;
                let first = j.saturating_sub(STENCIL_REACH);
                let last = (j + STENCIL_REACH).min(n - 1);
                for cell in first..=last {
                    for r in 0..VARS {
                        let row = VARS * cell + r;
                        if row == size - VARS + EPS {
                            continue; // the holdup row is set exactly below
                        }
                        let d = if r == EPS {
                            // y-momentum: difference the two cell pressures separately, so that
                            // a dilute cell's tiny pressure is not lost beside a dense one's
                            let dp =
                                |c: usize| (perturbed.pressure[c] - base.pressure[c]) / steps[j];
                            let weight = if cell == j || cell + 1 == j {
                                0.5 * problem.rho_s * problem.g_normal * x[col].exp() * dy[j]
                            } else {
                                0.0
                            };
                            dp(cell) - dp(cell + 1) - if v == EPS { weight } else { 0.0 }
                        } else {
                            (perturbed.residual[row] - base.residual[row]) / steps[j]
                        };
                        matrix.add(row, col, d);
                    }
                }
            }
        }
    }
    // holdup row in band: ∂(Σ εs Δy)/∂ln εs_j = εs_j Δy_j for the cells within reach of the
    // last
    let row = size - VARS + EPS;
    for j in n.saturating_sub(STENCIL_REACH + 1)..n {
        matrix.add(row, VARS * j + EPS, x[VARS * j + EPS].exp() * dy[j]);
    }
    matrix
}

/// Solves J δ = −F where J is the band plus the holdup row's entries outside the band
/// (Sherman–Morrison: J = B + e_h vᵀ).
pub(super) fn newton_step(
    problem: &Problem,
    x: &[f64],
    matrix: BandMatrix,
    residual: &[f64],
) -> Result<Vec<f64>, Chute1dError> {
    let n = problem.n();
    let size = VARS * n;
    let row = size - VARS + EPS;
    let dy = problem.p.grid.widths();
    let outside: Vec<(usize, f64)> = (0..n.saturating_sub(STENCIL_REACH + 1))
        .map(|j| (VARS * j + EPS, x[VARS * j + EPS].exp() * dy[j]))
        .collect();
    let mut unit = vec![0.0; size];
    unit[row] = 1.0;
    let mut systems = vec![residual.iter().map(|r| -r).collect::<Vec<f64>>(), unit];
    matrix.solve_in_place(&mut systems)?;
    let (z, w) = (&systems[0], &systems[1]);
    let v_dot = |s: &[f64]| outside.iter().map(|&(k, c)| c * s[k]).sum::<f64>();
    let factor = v_dot(z) / (1.0 + v_dot(w));
    Ok(z.iter().zip(w).map(|(a, b)| a - factor * b).collect())
}

/// Largest λ ≤ 1 such that x + λδ changes no ln εs or ln θ by more than [`MAX_LOG_STEP`]
/// and keeps εs below 1, consuming at most [`FRACTION_TO_BOUNDARY`] of its distance to 1.
pub(super) fn step_length(x: &[f64], delta: &[f64]) -> f64 {
    let mut lambda: f64 = 1.0;
    for (k, (&value, &d)) in x.iter().zip(delta).enumerate() {
        if k % VARS == U {
            continue;
        }
        lambda = lambda.min(MAX_LOG_STEP / d.abs());
        if k % VARS == EPS && d > 0.0 {
            let eps = value.exp();
            let limit = (eps + FRACTION_TO_BOUNDARY * (1.0 - eps)).ln() - value;
            lambda = lambda.min(limit / d);
        }
    }
    lambda
}
