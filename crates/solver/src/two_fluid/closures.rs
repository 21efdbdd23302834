//! Step 1 of the outer iteration (docs/model.md §4.9): the closures of every cell and solids
//! phase at the current iterate (docs/model.md §2): μ_s, λ_s, P_s (kinetic + frictional),
//! Schaeffer's P*, κ_s, K_cp, F_gs and the θ sources, from runout-closures' `evaluate`. The
//! strain rates of the wall cells use the tangential velocity on the wall faces that the wall
//! closures imply (docs/model.md §3.2, §4.4; MFIX's ghost cells), the gas–solids slip the
//! cell-centred averages of the face velocities (docs/model.md §2.6).

use rayon::prelude::*;

use runout_closures::{evaluate_in_gas, CellState, ClosureParams, Gas};
use runout_mesh::Grid;

use super::walls::wall_face_velocities;
use super::{
    PhaseCoefficients, PhaseState, PhaseWallClosures, SolidsSpec, State, PAR_MIN_CELLS, THETA_SMALL,
};
use crate::kinematics::{strain_rates, Strain, WallVelocities};

/// The closure values one cell contributes to the solver (docs/model.md §2), all zero where
/// εs = 0.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CellClosures {
    /// P_s = P_kin + P_fric [Pa]
    pub p_s: f64,
    /// Schaeffer plastic pressure P* [Pa], 0 with other friction models (docs/model.md §2.4.1)
    pub p_star: f64,
    /// μ_s = μ_kin + μ_fric [Pa s]
    pub mu: f64,
    /// λ_s = λ_kin + λ_fric [Pa s]
    pub lambda: f64,
    /// κ_s [kg m⁻¹ s⁻¹]
    pub kappa: f64,
    /// K_cp = dP_s/dεs [Pa]
    pub k_cp: f64,
    /// F_gs [kg m⁻³ s⁻¹]
    pub f_gs: f64,
    /// P_kin/θ [kg m⁻³]
    pub p_kin_over_theta: f64,
    /// μ_kin [Pa s]
    pub mu_kin: f64,
    /// λ_kin [Pa s]
    pub lambda_kin: f64,
    /// γ/θ, collisional dissipation over θ [kg m⁻³ s⁻¹]
    pub gamma_over_theta: f64,
    /// J_slip, drag production of θ [kg m⁻¹ s⁻³]
    pub j_slip: f64,
}

impl CellClosures {
    /// The values of one cell from runout-closures' `evaluate` (θ ≥ θ_small expected).
    pub fn evaluate(state: &CellState, params: &ClosureParams) -> Self {
        Self::evaluate_in_gas(state, params, &params.gas)
    }

    /// [`CellClosures::evaluate`] in the gas `gas` (a compressible gas's density of the cell).
    pub fn evaluate_in_gas(state: &CellState, params: &ClosureParams, gas: &Gas) -> Self {
        let c = evaluate_in_gas(state, params, gas);
        CellClosures {
            p_s: c.stress.p_s,
            p_star: c.stress.p_star,
            mu: c.stress.mu_s,
            lambda: c.stress.lambda_s,
            kappa: c.kinetic.kappa_kin,
            k_cp: c.k_cp,
            f_gs: c.f_gs,
            p_kin_over_theta: c.kinetic.p_kin / state.theta,
            mu_kin: c.kinetic.mu_kin,
            lambda_kin: c.kinetic.lambda_kin,
            gamma_over_theta: c.kinetic.dissipation / state.theta,
            j_slip: c.j_slip,
        }
    }
}

/// Step 1: the closures of every solids phase at the current iterate (module doc), written
/// in place into `coefficients`, with the wall face velocities of `walls`; returns how many
/// cells were evaluated (those with solids, summed over the phases).
pub(super) fn update_closures(
    grid: &Grid,
    state: &State,
    walls: &mut [PhaseWallClosures],
    coefficients: &mut [PhaseCoefficients],
    specs: &[SolidsSpec],
) -> u64 {
    let mut evaluated = 0;
    let gas = state.gas();
    let phases = state
        .phases()
        .iter()
        .zip(walls)
        .zip(coefficients.iter_mut());
    for (((phase, w), c), spec) in phases.zip(specs) {
        wall_strain_rates(grid, spec, phase, w, &mut c.strain);
        // a compressible gas's density per cell; a constant one is the closures' own
        let rho_g = gas.law().is_compressible().then(|| gas.density());
        evaluate_cells(grid, (&gas.u, &gas.v), rho_g, phase, c, &spec.params);
        c.keep_strain_traces();
        evaluated += phase.eps().iter().filter(|&&e| e != 0.0).count() as u64;
    }
    evaluated
}

/// The strain rates of every cell, those of the wall cells with the wall face velocities.
fn wall_strain_rates(
    grid: &Grid,
    spec: &SolidsSpec,
    phase: &PhaseState,
    w: &mut PhaseWallClosures,
    strain: &mut [Strain],
) {
    let on_wall = wall_face_velocities(grid, spec, phase, w);
    let walls = WallVelocities {
        south: on_wall.south.then_some(&w.wall_face_velocity.south[..]),
        north: on_wall.north.then_some(&w.wall_face_velocity.north[..]),
        west: on_wall.west.then_some(&w.wall_face_velocity.west[..]),
        east: on_wall.east.then_some(&w.wall_face_velocity.east[..]),
    };
    strain_rates(grid, &phase.u, &phase.v, &walls, strain);
}

/// The closure values of every cell of one phase, written in place, rows in parallel
/// (rayon).
fn evaluate_cells(
    grid: &Grid,
    (u_g, v_g): (&[f64], &[f64]),
    rho_g: Option<&[f64]>,
    phase: &PhaseState,
    c: &mut PhaseCoefficients,
    params: &ClosureParams,
) {
    let nx = grid.nx();
    let (u, v, eps, theta) = (&phase.u, &phase.v, phase.eps(), &phase.theta);
    let (strain, rows) = c.closure_rows(nx);
    // tasks of at least PAR_MIN_CELLS cells: a small grid runs as one task
    let rows_per_task = PAR_MIN_CELLS.div_ceil(nx);
    rows.with_min_len(rows_per_task)
        .with_max_len(rows_per_task)
        .enumerate()
        .for_each(|(j, mut row)| {
            for i in 0..nx {
                let k = i + nx * j;
                if eps[k] == 0.0 {
                    // no solids: every closure value the solver reads is zero
                    // (runout-closures gives exactly that at εs = 0; checked by
                    // the test `closures_vanish_without_solids`)
                    row.put(i, &CellClosures::default());
                    continue;
                }
                // |u_g − u_s| from cell-centred averages of the face velocities (§2.6)
                let du = 0.5
                    * ((u_g[i + (nx + 1) * j] - u[i + (nx + 1) * j])
                        + (u_g[i + 1 + (nx + 1) * j] - u[i + 1 + (nx + 1) * j]));
                let dv = 0.5 * ((v_g[k] - v[k]) + (v_g[k + nx] - v[k + nx]));
                let st = strain[k];
                let state = CellState {
                    eps_s: eps[k],
                    theta: theta[k].max(THETA_SMALL),
                    slip: (du * du + dv * dv).sqrt(),
                    tr_d: st.tr_d,
                    s_ddot_s: st.s_ddot_s,
                };
                let closures = match rho_g {
                    None => CellClosures::evaluate(&state, params),
                    Some(rho) => {
                        let gas = Gas {
                            density: rho[k],
                            ..params.gas
                        };
                        CellClosures::evaluate_in_gas(&state, params, &gas)
                    }
                };
                row.put(i, &closures);
            }
        });
}
