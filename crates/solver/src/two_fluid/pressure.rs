//! Step 4 of the outer iteration (docs/model.md §4.9): the gas pressure correction from gas
//! continuity (docs/model.md §4.6). Per cell, with the face εg of the convection scheme
//! (MFIX `DISCRETIZE(1)`, docs/model.md §4.2; 1 on a distributor's faces) and d_g of the
//! partial elimination ([`super::momentum_pea`]):
//!   Σ_f ρ_g ε_g,f d_f A_f (P'_P − P'_nb) = b,
//!   b = ρ_g (−(εg − εg⁰) V/Δt + Σ_f ε_g,f u_f·n_in A_f),
//! then u_g += d_g (P'_low − P'_high) on every face with d ≠ 0 and P_g += ω_P P'. The solids
//! velocities are not corrected with P'_g. The pressure is pinned at cell 0 where no side is
//! open.
//!
//! An ideal gas (docs/model.md §1.4) keeps ρ_g inside the balance, with the face's ρ_g from
//! the upwind cell (the inside cell on the boundary), and its change with the pressure
//! correction, ρ_g += ω_P (dρ_g/dP) P', on the diagonal (MFIX `SOURCE_PP_G`, the `RO_G0`
//! undefined branch):
//!   [Σ_f ρ_g,f ε_g,f d_f A_f + ω_P (dρ_g/dP) εg V/Δt] P'_P − Σ_f ρ_g,f ε_g,f d_f A_f P'_nb = b,
//!   b = −(ρ_g εg − ρ_g⁰ εg⁰) V/Δt + Σ_f ρ_g,f ε_g,f u_f·n_in A_f;
//! its pressure level is set by its mass: P' is not pinned. ρ_g follows the corrected P.

use std::time::Instant;

use runout_linsolve::Stencil5;
use runout_mesh::{Grid, Sides};

use super::diagnostics::{since, Diagnostics};
use super::model::Model;
use super::{lin, solve_keeping_preconditioner, State, TwoFluidError, Workspace};
use crate::direction::{X, Y};
use crate::momentum::fixed_row;
use crate::node_block::correct_velocity;
use crate::transport::{face_value, Scheme};
use runout_closures::GasLaw;

/// Step 4: gas pressure correction (module doc); returns the mean |gas imbalance|.
pub(super) fn pressure_correction(
    model: &Model,
    state: &mut State,
    work: &mut Workspace,
    diagnostics: &mut Diagnostics,
    dt: f64,
) -> Result<f64, TwoFluidError> {
    let (nx, ny) = (model.grid.nx(), model.grid.ny());
    let g = state.gas();
    let gas = GasContinuity {
        law: g.law(),
        rho: g.density(),
        bulk: g.bulk_density(),
        bulk_old: &g.old().rho_eps,
        relax_pressure: model.settings.relax_pressure,
        eps: g.eps(),
        eps_old: &g.old().eps,
        u: &g.u,
        v: &g.v,
        d_u: &work.d_u,
        d_v: &work.d_v,
        inflow: &model.gas_inflow,
        scheme: model.settings.scheme,
        pinned: work.flags.pressure_pinned,
    };
    let total = assemble(&model.grid, &gas, dt, &mut work.imbalance, &mut work.a_p);
    work.p_corr.iter_mut().for_each(|x| *x = 0.0);
    let t = Instant::now();
    diagnostics.profile.iterations.pressure += solve_keeping_preconditioner(
        work.solvers.p.as_mut(),
        &work.a_p,
        &mut work.p_corr,
        work.flags.rebuild_preconditioners,
    )
    .map_err(lin("gas pressure correction"))? as u64;
    // both multigrid hierarchies of this step are built (ε' is solved first)
    work.flags.rebuild_preconditioners = false;
    let solve = since(t);
    diagnostics.profile.pressure_solve += solve;
    diagnostics.profile.pressure_assembly -= solve;
    let g = state.gas_mut();
    correct_velocity::<X>((nx, ny), &work.p_corr, &work.d_u, &mut g.u);
    correct_velocity::<Y>((nx, ny), &work.p_corr, &work.d_v, &mut g.v);
    let w = model.settings.relax_pressure;
    g.p.iter_mut()
        .zip(&work.p_corr)
        .for_each(|(p, c)| *p += w * c);
    state.sync_gas_density();
    Ok(total / (nx * ny) as f64)
}

/// What gas continuity is assembled from.
struct GasContinuity<'a> {
    /// the equation of state
    law: GasLaw,
    /// ρ_g per cell, ρ_g εg now and at the old time level (an ideal gas's balance)
    rho: &'a [f64],
    bulk: &'a [f64],
    bulk_old: &'a [f64],
    /// ω_P, the share of P' added to P (an ideal gas's density change)
    relax_pressure: f64,
    /// εg per cell, now and at the old time level
    eps: &'a [f64],
    eps_old: &'a [f64],
    /// gas u and v after the momentum predictor
    u: &'a [f64],
    v: &'a [f64],
    /// d_g of the u and v nodes
    d_u: &'a [f64],
    d_v: &'a [f64],
    /// gas velocity into the domain through each face of each wall side (empty: none)
    inflow: &'a Sides<Vec<f64>>,
    /// convection scheme of the face εg
    scheme: Scheme,
    /// P' fixed at cell 0 (no open side)
    pinned: bool,
}

/// The P' equations `a` and the gas mass imbalance b of every cell (module doc); returns
/// Σ|b|.
fn assemble(
    grid: &Grid,
    gas: &GasContinuity<'_>,
    dt: f64,
    imbalance: &mut [f64],
    a: &mut Stencil5,
) -> f64 {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let (eps, scheme) = (gas.eps, gas.scheme);
    // a constant density factors out of the balance (MFIX's incompressible form)
    let constant = match gas.law {
        GasLaw::Constant(rho) => Some(rho),
        GasLaw::IdealGas { .. } => None,
    };
    let compressibility = gas.law.compressibility();
    // ρ_g on a face from the upwind cell, the inside cell on the boundary
    let upwind_rho = |vel: f64, lo: Option<usize>, hi: Option<usize>| match (lo, hi) {
        (Some(l), Some(h)) => gas.rho[if vel >= 0.0 { l } else { h }],
        (Some(c), None) | (None, Some(c)) => gas.rho[c],
        (None, None) => 0.0,
    };
    // face εg (MFIX `DISCRETIZE(1)`, docs/model.md §4.2): upwind or Superbee between the
    // cells lo and hi, `stride` apart; the inside cell's on the domain boundary
    let face = |vel: f64, lo: Option<usize>, hi: Option<usize>, stride: usize| -> f64 {
        match (lo, hi) {
            (Some(l), Some(h)) => face_value(
                scheme,
                eps,
                l.checked_sub(stride)
                    .filter(|&x| same_line(x, l, stride, nx)),
                l,
                h,
                Some(h + stride).filter(|&x| x < eps.len() && same_line(h, x, stride, nx)),
                vel,
            ),
            (Some(c), None) | (None, Some(c)) => eps[c],
            (None, None) => 0.0,
        }
    };
    // gas entering through a distributor is pure gas (MFIX BC_EP_G = 1)
    let inlet = |at_side: bool, faces: &[f64], along: usize, value: f64| {
        if at_side && faces.get(along).is_some_and(|&v| v != 0.0) {
            1.0
        } else {
            value
        }
    };
    let (u, v, f) = (gas.u, gas.v, gas.inflow);
    // rows in parallel (each cell's row is its own); b goes to the row first
    a.par_fill_rows(|j, row| {
        for i in 0..nx {
            let k = i + nx * j;
            let (kw, ke) = (i + (nx + 1) * j, i + 1 + (nx + 1) * j);
            let (ks, kn) = (i + nx * j, i + nx * (j + 1));
            let west = (i > 0).then(|| k - 1);
            let east = (i + 1 < nx).then_some(k + 1);
            let south = (j > 0).then(|| k - nx);
            let north = (j + 1 < ny).then_some(k + nx);
            let ew = inlet(i == 0, &f.west, j, face(u[kw], west, Some(k), 1));
            let ee = inlet(i + 1 == nx, &f.east, j, face(u[ke], Some(k), east, 1));
            let es = inlet(j == 0, &f.south, i, face(v[ks], south, Some(k), nx));
            let en = inlet(j + 1 == ny, &f.north, i, face(v[kn], Some(k), north, nx));
            let volume = dx[i] * dy[j];
            let (ce, cw, cn, cs);
            if let Some(rho) = constant {
                row.b[i] = rho
                    * (-(eps[k] - gas.eps_old[k]) * volume / dt + ew * u[kw] * dy[j]
                        - ee * u[ke] * dy[j]
                        + es * v[ks] * dx[i]
                        - en * v[kn] * dx[i]);
                ce = rho * ee * gas.d_u[ke] * dy[j];
                cw = rho * ew * gas.d_u[kw] * dy[j];
                cn = rho * en * gas.d_v[kn] * dx[i];
                cs = rho * es * gas.d_v[ks] * dx[i];
                row.a_p[i] = ce + cw + cn + cs;
            } else {
                // face ρ_g εg: the upwind cell's ρ_g times the scheme's εg (module doc)
                let mw = upwind_rho(u[kw], west, Some(k)) * ew;
                let me = upwind_rho(u[ke], Some(k), east) * ee;
                let ms = upwind_rho(v[ks], south, Some(k)) * es;
                let mn = upwind_rho(v[kn], Some(k), north) * en;
                row.b[i] = -(gas.bulk[k] - gas.bulk_old[k]) * volume / dt + mw * u[kw] * dy[j]
                    - me * u[ke] * dy[j]
                    + ms * v[ks] * dx[i]
                    - mn * v[kn] * dx[i];
                ce = me * gas.d_u[ke] * dy[j];
                cw = mw * gas.d_u[kw] * dy[j];
                cn = mn * gas.d_v[kn] * dx[i];
                cs = ms * gas.d_v[ks] * dx[i];
                row.a_p[i] =
                    ce + cw + cn + cs + gas.relax_pressure * compressibility * eps[k] * volume / dt;
            }
            row.a_e[i] = if east.is_some() { ce } else { 0.0 };
            row.a_w[i] = if west.is_some() { cw } else { 0.0 };
            row.a_n[i] = if north.is_some() { cn } else { 0.0 };
            row.a_s[i] = if south.is_some() { cs } else { 0.0 };
        }
    });
    imbalance.copy_from_slice(&a.b);
    // Σ|b| in cell order, as one sequential pass would add it
    let total = imbalance.iter().fold(0.0, |sum, b| sum + b.abs());
    if gas.pinned {
        fixed_row(a, 0, 0.0);
    }
    total
}

/// Whether cells `a` < `b`, `stride` apart, lie on one grid line (x lines: stride 1 within
/// a row of `nx`; y lines: stride `nx`, always).
fn same_line(a: usize, b: usize, stride: usize, nx: usize) -> bool {
    stride != 1 || a / nx == b / nx
}
