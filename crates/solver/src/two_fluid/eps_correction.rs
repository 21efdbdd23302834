//! Step 3 of the outer iteration (docs/model.md §4.9): the solids volume-fraction
//! correction of each phase (Syamlal 1998, docs/model.md §4.7; assembled and applied by
//! [`crate::volume_fraction`]), εs = εs* + ε' with the selective relaxation beyond εs,max, the
//! solids velocities corrected with e_s K_cp ∇ε', Schaeffer's P* recomputed from the
//! corrected εs (docs/model.md §2.4.1), then εg = 1 − Σεs. Also the optional exact solids
//! continuity at the end of a converged step ([`conservative_finish`], not MFIX).

use std::time::Instant;

use runout_linsolve::{LinSolveError, LinearSolver, Stencil5};

use super::diagnostics::{since, Diagnostics};
use super::model::Model;
use super::state::PhaseMut;
use super::{
    lin, solve_keeping_preconditioner, PhaseCoefficients, State, TwoFluidError, Workspace,
};
use crate::volume_fraction::{
    apply_correction, assemble_correction, mass_imbalance, CorrectionInputs,
};

/// Step 3: ε correction of each solids phase; returns the mean |imbalance| summed.
pub(super) fn volume_fraction_correction(
    model: &Model,
    state: &mut State,
    coefficients: &mut [PhaseCoefficients],
    work: &mut Workspace,
    diagnostics: &mut Diagnostics,
    dt: f64,
) -> Result<f64, TwoFluidError> {
    let n = state.gas().eps().len() as f64;
    let mut total = 0.0;
    state.try_update_all_solids(|m, p| {
        let (s, coef) = (&mut work.solids[m], &mut coefficients[m]);
        let spec = &model.solids_specs[m];
        let inputs = correction_inputs(model, m, &p, [&s.e_u, &s.e_v], coef, dt);
        assemble_correction(&model.grid, &inputs, &mut s.imbalance, &mut s.a_eps);
        total += s.imbalance.iter().map(|x| x.abs()).sum::<f64>() / n;
        let t = Instant::now();
        let iterations = solve_eps_prime(
            work.solvers.eps.as_mut(),
            work.solvers.eps_fallback.as_mut(),
            &s.a_eps,
            &mut s.eps_prime,
        )
        .map_err(lin("solids volume fraction"))?;
        diagnostics.profile.iterations.eps += iterations as u64;
        let solve = since(t);
        diagnostics.profile.eps_solve += solve;
        diagnostics.profile.eps_assembly -= solve;
        apply_correction(
            &model.grid,
            &mut s.eps_prime,
            &mut *p.eps,
            spec.eps_max,
            model.settings.relax_eps,
            &mut *p.u,
            &mut *p.v,
            &s.e_u,
            &s.e_v,
            &coef.k_cp,
        );
        // P* from the corrected εs (Schaeffer only, docs/model.md §4.9 step 5)
        if let Some(star) = spec.params.friction_model.plastic_pressure() {
            for (ps, &e) in coef.p_star.iter_mut().zip(p.eps.iter()) {
                *ps = star.p_star(e, &spec.params.friction);
            }
            diagnostics.counters.plastic_pressure_cells += coef.p_star.len() as u64;
        }
        Ok(())
    })?;
    Ok(total)
}

/// What the ε' system and the mass imbalance of solids phase `m` read: its fields `p`, the
/// e_s of its u and v nodes from the last momentum stage and its K_cp (in `coef`).
fn correction_inputs<'a>(
    model: &Model,
    m: usize,
    p: &'a PhaseMut<'_>,
    [e_u, e_v]: [&'a [f64]; 2],
    coef: &'a PhaseCoefficients,
    dt: f64,
) -> CorrectionInputs<'a> {
    CorrectionInputs {
        density: model.solids_specs[m].params.particles.density,
        eps: p.eps,
        eps_old: &p.old.eps,
        u: p.u,
        v: p.v,
        e_u,
        e_v,
        k_cp: &coef.k_cp,
        dt,
        scheme: model.settings.scheme,
    }
}

/// Ends a converged step with exact discrete solids continuity (if
/// [`super::TwoFluidSettings::exact_solids_continuity`]): each cell's εs becomes
/// εs⁰ − Δt/V Σ (εs,face u·n A) with the step's final face fluxes, i.e. the imbalance
/// the outer iteration left within its tolerance is removed where it sits. Without it
/// that remainder accumulates where solids compact, because the selective relaxation of
/// positive ε' beyond εs,max (docs/model.md §4.7) leaves every step's imbalance with the
/// same sign (3e-7 of the solids over family M, 2e-5 over ST-schaeffer, 1e-7 over a
/// coarse column collapse). The change is of the size of the step tolerance (MFIX keeps
/// the remainder). Internal fluxes cancel in
/// pairs, so the solids mass changes by exactly the boundary flux, up to the mass of any
/// cell that would go below zero (clipped, reported by tracing).
pub(super) fn conservative_finish(
    model: &Model,
    state: &mut State,
    coefficients: &[PhaseCoefficients],
    work: &mut Workspace,
    dt: f64,
) {
    state.update_all_solids(|m, p| {
        let (s, coef) = (&mut work.solids[m], &coefficients[m]);
        let spec = &model.solids_specs[m];
        let density = spec.params.particles.density;
        let inputs = correction_inputs(model, m, &p, [&s.e_u, &s.e_v], coef, dt);
        mass_imbalance(&model.grid, &inputs, &mut s.imbalance);
        let nx = model.grid.nx();
        let (mut largest, mut clipped) = (0.0_f64, 0.0);
        for (k, (e, r)) in p.eps.iter_mut().zip(&s.imbalance).enumerate() {
            let volume = model.grid.cell_volume(k % nx, k / nx);
            let change = -r * dt / (density * volume);
            largest = largest.max(change.abs());
            *e += change;
            if *e < 0.0 {
                clipped -= *e * volume;
                *e = 0.0;
            }
        }
        tracing::trace!(
            largest,
            clipped,
            "conservative finish of the solids continuity"
        );
    });
}

/// Solves the ε' system `a` from ε' = 0 with a fresh multigrid preconditioner (ε' is rebuilt
/// every iteration: its K_cp terms change too much within a step; kept, the solves took 17 %
/// longer on family M); where the multigrid-preconditioned BiCGSTAB breaks down (seen at its
/// first iteration on the paper grid of the sensitivity slide, during the fall), with MFIX's
/// own ε' method (docs/model.md §4.13) instead of failing the step. Returns the iterations.
fn solve_eps_prime(
    solver: &mut dyn LinearSolver,
    fallback: &mut dyn LinearSolver,
    a: &Stencil5,
    eps_prime: &mut [f64],
) -> Result<usize, LinSolveError> {
    eps_prime.iter_mut().for_each(|x| *x = 0.0);
    match solve_keeping_preconditioner(solver, a, eps_prime, true) {
        Err(LinSolveError::Breakdown { .. }) => {
            tracing::debug!("eps' solve: multigrid breakdown, line-relaxed BiCGSTAB instead");
            eps_prime.iter_mut().for_each(|x| *x = 0.0);
            solve_keeping_preconditioner(fallback, a, eps_prime, true)
        }
        solved => solved,
    }
}
