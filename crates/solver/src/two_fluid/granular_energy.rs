//! Step 5 of the outer iteration (docs/model.md §4.9): the granular energy of each solids
//! phase (docs/model.md §4.8, assembled by [`crate::energy`]), with the θ closures of the
//! state-dependent walls. Each cell's row is of one of two classes:
//! - dense (εs > DIL_EP_S): the θ equation, under-relaxed a_P/ω (docs/model.md §4.10), or
//!   with Schaeffer friction a fixed row θ = θ_small where εg < εg* (docs/model.md §1.3, as
//!   MFIX, not relaxed);
//! - dilute: the mean θ of its dense neighbour cells, or kept if none (MFIX `source_phi.f`,
//!   [`super::dilute::dilute_cell_row`]); optionally a cell whose class changes back within
//!   a step is frozen dilute ([`super::dilute::next_dilute_class`]).
//!
//! The residual Σ|Σ a_nb θ_nb + b − a_P θ_P| / Σ|a_P θ_P| is taken over the dense rows before
//! relaxation (docs/model.md §4.11); after the solve θ ≥ θ_small (MFIX `adjust_theta.f`).

use std::time::Instant;

use rayon::prelude::*;

use runout_linsolve::Stencil5;

use super::diagnostics::{since, Diagnostics};
use super::dilute::{dilute_cell_row, next_dilute_class};
use super::model::Model;
use super::sidewalls::add_theta_flux;
use super::{
    lin, PhaseCoefficients, PhaseWallClosures, PhaseWork, State, TwoFluidError, Workspace,
    DIL_EP_S, THETA_SMALL,
};
use crate::energy::{assemble_theta, EnergyInputs};
use crate::momentum::RowCoefficients;

/// Step 5: granular energy of each solids phase (module doc); returns the θ residual
/// summed over phases.
pub(super) fn granular_energy(
    model: &Model,
    state: &mut State,
    coefficients: &[PhaseCoefficients],
    wall_closures: &[PhaseWallClosures],
    work: &mut Workspace,
    diagnostics: &mut Diagnostics,
    dt: f64,
) -> Result<f64, TwoFluidError> {
    let mut worst_theta = (0.0, 0);
    let relax = model.settings.relax_theta;
    let nx = model.grid.nx();
    let freeze = model.settings.freeze_cycling_dilute_class && !work.flags.theta_class_fresh;
    let mut residual = 0.0;
    let (gas, phases) = state.gas_and_phases_mut();
    let eps_g = gas.eps();
    let solids = work.solids.iter_mut().zip(phases).zip(coefficients);
    let solids = solids.zip(wall_closures).zip(&model.solids_specs);
    for ((((s, p), coef), w), spec) in solids {
        // the class of each row first: the dilute rows are not assembled (replaced below)
        classify_rows(p.eps(), s, freeze);
        let inputs = EnergyInputs {
            bulk_density: p.bulk_density(),
            bulk_density_old: &p.old().rho_eps,
            conductivity: &coef.kappa,
            p_kin_over_theta: &coef.p_kin_over_theta,
            mu_kin: &coef.mu_kin,
            lambda_kin: &coef.lambda_kin,
            dissipation_over_theta: &coef.gamma_over_theta,
            drag: &coef.f_gs,
            slip_production: &coef.j_slip,
            tr_d: &coef.tr_d,
            tr_d2: &coef.tr_d2,
            skip: Some(&s.theta_dilute),
        };
        assemble_theta(
            &model.grid,
            &inputs,
            &spec.theta_faces(),
            Some(&w.wall_theta),
            &p.u,
            &p.v,
            &p.old().theta,
            dt,
            model.settings.scheme,
            &p.theta,
            &mut work.c_faces,
            &mut s.a_theta,
        );
        if model.sidewalls.is_some() {
            add_theta_flux(&model.grid, &coef.sidewall, &mut s.a_theta); // docs/model.md §8
        }
        // θ = θ_small where εg < εg* if the friction model pins it (docs/model.md §1.3)
        let eps_g_star = spec
            .params
            .friction_model
            .pins_theta_below(&spec.params.friction);
        let rows = ThetaRows {
            theta: &p.theta,
            dense: &s.theta_dense,
            eps_g,
            eps_g_star,
            relax,
            nx,
        };
        residual += rows.finish(&mut s.a_theta, &mut s.theta_terms, &mut worst_theta);
        let t = Instant::now();
        diagnostics.profile.iterations.theta += work
            .solvers
            .theta
            .setup_and_solve(&s.a_theta, &mut p.theta)
            .map_err(lin("granular energy"))?
            .iterations as u64;
        let solve = since(t);
        diagnostics.profile.theta_solve += solve;
        diagnostics.profile.theta_assembly -= solve;
        p.theta.iter_mut().for_each(|t| *t = t.max(THETA_SMALL));
    }
    work.flags.theta_class_fresh = false;
    diagnostics.worst.theta = worst_theta;
    Ok(residual)
}

/// The class of each θ row: MFIX's εs > DIL_EP_S, unless `freeze` (a cycling cell keeps
/// the class [`next_dilute_class`] gives it); cells in parallel.
fn classify_rows(eps: &[f64], s: &mut PhaseWork, freeze: bool) {
    let cells = eps
        .par_iter()
        .zip(&mut s.theta_dense)
        .zip(&mut s.theta_class_changes)
        .zip(&mut s.theta_dilute)
        .with_min_len(CLASSIFY_MIN_CELLS);
    cells.for_each(|(((eps, dense), changes), dilute)| {
        let dense_now = *eps > DIL_EP_S;
        if freeze {
            next_dilute_class(dense_now, dense, changes);
        } else {
            *dense = dense_now;
            *changes = 0;
        }
        *dilute = !*dense;
    });
}

/// Cells per task of [`classify_rows`].
const CLASSIFY_MIN_CELLS: usize = 1 << 14;

/// What the θ rows of one phase are finished with.
struct ThetaRows<'a> {
    /// θ at the current iterate
    theta: &'a [f64],
    /// the class of each row (true: dense)
    dense: &'a [bool],
    /// εg per cell
    eps_g: &'a [f64],
    /// Schaeffer's εg* = 1 − εs,max (`None` with other friction models)
    eps_g_star: Option<f64>,
    /// θ relaxation ω
    relax: f64,
    /// cells per row
    nx: usize,
}

impl ThetaRows<'_> {
    /// Replaces the dilute rows, fixes the forced ones and relaxes the others of the
    /// assembled `a`, rows in parallel; returns the phase's residual, summed in cell order
    /// from each row's terms kept in `terms`, and keeps its largest (|residual|, cell) in
    /// `worst` (module doc).
    fn finish(&self, a: &mut Stencil5, terms: &mut [(f64, f64)], worst: &mut (f64, usize)) -> f64 {
        let (theta, relax, nx) = (self.theta, self.relax, self.nx);
        a.par_fill_rows_with(terms, |j, mut row, terms| {
            for i in 0..nx {
                let k = i + nx * j;
                terms[i] = (0.0, 0.0);
                if !self.dense[k] {
                    // the mean θ of the neighbours with εs > DIL_EP_S, or kept if none
                    // (docs/model.md §4.8, MFIX `source_phi.f`)
                    dilute_cell_row((i, j), theta[k], self.dense, nx).put_in(&mut row, i);
                    continue;
                }
                // a fixed row before the residual and not relaxed (MFIX
                // `solve_granular_energy.f`, `under_relax.f`)
                let forced = self.eps_g_star.is_some_and(|star| self.eps_g[k] < star);
                if forced {
                    RowCoefficients::fixed(THETA_SMALL).put_in(&mut row, i); // §1.3 (Schaeffer)
                }
                let coefficients = RowCoefficients::of_entry(&row, i);
                let nb = coefficients.neighbour_sum(theta, k, nx) - row.a_p[i] * theta[k];
                terms[i] = (nb.abs(), (row.a_p[i] * theta[k]).abs());
                if forced {
                    continue; // fixed rows are not relaxed (MFIX `under_relax.f`, §1.3)
                }
                let ap = row.a_p[i] / relax;
                row.b[i] += (1.0 - relax) * ap * theta[k];
                row.a_p[i] = ap;
            }
        });
        // a dilute row's terms are zero and change neither sum nor the largest
        let (mut num, mut den) = (0.0, 0.0);
        for (k, &(term, scale)) in terms.iter().enumerate() {
            num += term;
            if term > worst.0 {
                *worst = (term, k);
            }
            den += scale;
        }
        if den > 0.0 {
            num / den
        } else {
            num
        }
    }
}
