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
//! is the mirror image: both are written once in the component's own coordinates and
//! compiled per direction (direction.rs).

use runout_mesh::Grid;

use runout_closures::FaceMean;

use crate::direction::{Direction, X, Y};
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
    let fields = (mu, mean, lambda, tr_d);
    component_stress::<X>(grid, u, v, fields, fixed_u, tau_u);
    component_stress::<Y>(grid, v, u, fields, fixed_v, tau_v);
}

/// [`explicit_stress`] of component `D` with velocity `phi` and the other component
/// `other`, in the component's own coordinates (a along, b across; direction.rs): on node
/// (a, b) the normal part (μ ∂φ/∂a + λ tr D) differenced between cells a − 1 and a times
/// the face, the shear part μ ∂φ_other/∂a differenced between the corners b and b + 1 times
/// the control-volume width.
fn component_stress<D: Direction>(
    grid: &Grid,
    phi: &[f64],
    other: &[f64],
    (mu, mean, lambda, tr_d): (&[f64], FaceMean, &[f64], &[f64]),
    fixed: &[bool],
    tau: &mut [f64],
) {
    let nx = grid.nx();
    let (n_a, n_b) = (D::along(grid).len(), D::across(grid).len());
    let (d_a, d_b) = (D::along(grid).widths(), D::across(grid).widths());
    let along_spacing = D::along(grid).face_spacing();
    // the normal stress beyond the implicit part at the centre of cell (c, b)
    let normal_stress = |c: usize, b: usize| {
        let k = D::cell(c, b, nx);
        mu[k] * (phi[D::node(c + 1, b, nx)] - phi[D::node(c, b, nx)]) / d_a[c] + lambda[k] * tr_d[k]
    };
    // ∂φ_other/∂a at the corner (a, b), 1 ≤ a < n_a: ∂v/∂x for u, ∂u/∂y for v (zero on the
    // walls at the ends, where the other component is zero)
    let cross = |a: usize, b: usize| {
        (other[D::cross_node(a, b, nx)] - other[D::cross_node(a - 1, b, nx)]) / along_spacing[a]
    };
    D::for_each(0..n_a + 1, 0..n_b, |a, b| {
        let k = D::node(a, b, nx);
        if fixed[k] || a == 0 || a == n_a {
            tau[k] = 0.0;
            return;
        }
        let normal = (normal_stress(a, b) - normal_stress(a - 1, b)) * d_b[b];
        // corners at b and b + 1 across: the other component on a wall face is zero, so
        // its derivative is as well; on an outlet face it exists and is used
        let shear_at = |bf: usize| {
            let (i, j) = D::xy(a, bf);
            corner_viscosity(grid, mu, mean, i, j) * cross(a, bf)
        };
        let shear = (shear_at(b + 1) - shear_at(b)) * cv_width(d_a, a);
        tau[k] = normal + shear;
    });
}
