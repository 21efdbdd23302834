//! The explicit parts of a phase's viscous stress (docs/model.md §4.4, MFIX `calc_trd_s.f`,
//! `tau_u_s.f`, `tau_v_s.f`).
//!
//! The momentum assembly treats μ ∂u_i/∂x_j implicitly (through a_nb); the rest of
//! ∇·τ, τ = μ(∇u + ∇uᵀ) + λ (tr D) I, is a source: for the u equation
//! ∂/∂x(μ ∂u/∂x) + ∂/∂y(μ ∂v/∂x) + ∂/∂x(λ tr D), for the v equation
//! ∂/∂x(μ ∂u/∂y) + ∂/∂y(μ ∂v/∂y) + ∂/∂y(λ tr D). MFIX evaluates these once per time step, at
//! its start, with that moment's velocities and coefficients (CALC_TRD_AND_TAU in
//! `time_step.f`), and keeps them through the outer iterations.
//!
//! Discretisation on a u control volume (x-face i, row j): the normal part as the difference
//! of (μ ∂u/∂x + λ tr D) between the cell centres i and i−1, times the face height; the shear
//! part as the difference of μ ∂v/∂x between the corners (i, j+1) and (i, j), times the
//! control-volume width, with μ at a corner the mean the caller names (the two-fluid step:
//! harmonic, MFIX's, as the implicit shear conductance but for μ(I), whose implicit corner is
//! arithmetic; docs/model.md §4.1, §2.4.4). On a wall the tangential
//! derivative of the normal velocity is zero (v = 0 along a floor), so the corner term
//! vanishes there; on an outlet the corner values of the fluid row are used. The v equation
//! is the mirror image.

use runout_mesh::Grid;

use runout_closures::FaceMean;

use crate::momentum::{cv_width, face_mean};

/// μ at the corner (x-face i, y-face j) from the (up to four) cells around it, by `mean`.
fn corner_viscosity(grid: &Grid, mu: &[f64], mean: FaceMean, i: usize, j: usize) -> f64 {
    let (nx, ny) = (grid.nx(), grid.ny());
    let rows = [j.checked_sub(1), (j < ny).then_some(j)];
    let cols = [i.checked_sub(1), (i < nx).then_some(i)];
    let column = |c: usize| match (rows[0], rows[1]) {
        (Some(s), Some(n)) => face_mean(
            mean,
            mu[c + nx * s],
            mu[c + nx * n],
            grid.y.interpolation_weight(s),
        ),
        (Some(r), None) | (None, Some(r)) => mu[c + nx * r],
        (None, None) => 0.0,
    };
    match (cols[0], cols[1]) {
        (Some(w), Some(e)) => face_mean(mean, column(w), column(e), grid.x.interpolation_weight(w)),
        (Some(c), None) | (None, Some(c)) => column(c),
        (None, None) => 0.0,
    }
}

/// Fills `tau_u` ((nx+1) × ny) and `tau_v` (nx × (ny+1)) with the explicit stress sources of
/// one phase, integrated over each momentum control volume [N per m depth]. `mu`, `lambda`
/// and `tr_d` are cell fields; `fixed_u`/`fixed_v` mark the nodes whose rows are fixed (wall
/// normal velocities), which get zero. Nodes whose two neighbouring cells both fall outside
/// the domain do not exist; an outlet end node (one cell) gets zero as well (zero normal
/// gradient there).
#[allow(clippy::too_many_arguments)]
pub fn explicit_stress(
    grid: &Grid,
    u: &[f64],
    v: &[f64],
    mu: &[f64],
    mean: FaceMean,
    lambda: &[f64],
    tr_d: &[f64],
    fixed_u: &[bool],
    fixed_v: &[bool],
    tau_u: &mut [f64],
    tau_v: &mut [f64],
) {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let (dxc, dyc) = (grid.x.face_spacing(), grid.y.face_spacing());
    let mx = nx + 1;
    // the normal stress beyond the implicit part at a cell centre
    let normal_x = |c: usize, r: usize| {
        let k = c + nx * r;
        mu[k] * (u[c + 1 + mx * r] - u[c + mx * r]) / dx[c] + lambda[k] * tr_d[k]
    };
    let normal_y = |c: usize, r: usize| {
        let k = c + nx * r;
        mu[k] * (v[c + nx * (r + 1)] - v[c + nx * r]) / dy[r] + lambda[k] * tr_d[k]
    };
    // ∂v/∂x at corner (x-face i, y-face j), 1 ≤ i < nx (zero on the west/east walls)
    let dv_dx = |i: usize, j: usize| (v[i + nx * j] - v[i - 1 + nx * j]) / dxc[i];
    // ∂u/∂y at corner (x-face i, y-face j), 1 ≤ j < ny; on the floor/lid the wall closure
    // is implicit already, and ∂v/∂x vanishes there, so only interior corners carry this
    let du_dy = |i: usize, j: usize| (u[i + mx * j] - u[i + mx * (j - 1)]) / dyc[j];
    for j in 0..ny {
        for i in 0..mx {
            let k = i + mx * j;
            if fixed_u[k] || i == 0 || i == nx {
                tau_u[k] = 0.0;
                continue;
            }
            let normal = (normal_x(i, j) - normal_x(i - 1, j)) * dy[j];
            // corners at y-faces j (south) and j+1 (north); v on a wall face is zero, so
            // ∂v/∂x there is zero as well; on an outlet face v exists and is used
            let shear_at = |jf: usize| corner_viscosity(grid, mu, mean, i, jf) * dv_dx(i, jf);
            let shear = (shear_at(j + 1) - shear_at(j)) * cv_width(dx, i);
            tau_u[k] = normal + shear;
        }
    }
    for j in 0..=ny {
        for i in 0..nx {
            let k = i + nx * j;
            if fixed_v[k] || j == 0 || j == ny {
                tau_v[k] = 0.0;
                continue;
            }
            let normal = (normal_y(i, j) - normal_y(i, j - 1)) * dx[i];
            // corners at x-faces i (west) and i+1 (east); u on a west/east wall is zero
            let shear_at = |i_f: usize| corner_viscosity(grid, mu, mean, i_f, j) * du_dy(i_f, j);
            let shear = (shear_at(i + 1) - shear_at(i)) * cv_width(dy, j);
            tau_v[k] = normal + shear;
        }
    }
}
