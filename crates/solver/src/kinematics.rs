//! Cell-centred strain rates of a phase from its staggered velocities (docs/model.md §4.4,
//! "cell-centred strain rate for μ, P_f and production"), as the closures need them:
//! tr D = ∂u/∂x + ∂v/∂y, tr(D²) = D11² + D22² + 2 D12², and S:S = tr(D²) − (tr D)²/3
//! (docs/model.md §0.3, §2.4.2). D12 = ½(∂u/∂y + ∂v/∂x): ∂u/∂y is the difference of u on the
//! cell's north and south faces (cell-centred u interpolated between rows), and at a wall
//! the wall face value that MFIX's ghost cell implies (the caller's wall closure supplies
//! it, docs/model.md §3.2, §4.4); likewise ∂v/∂x. Without a face value (an outlet) the
//! difference is one-sided.

use runout_mesh::Grid;

use runout_linsolve::for_each_row;

use crate::direction::{Direction, X, Y};

/// Strain-rate invariants of one cell.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Strain {
    /// tr D = ∇·u [s⁻¹]
    pub tr_d: f64,
    /// tr(D²) [s⁻²]
    pub tr_d2: f64,
    /// S:S = tr(D²) − (tr D)²/3 ≥ 0 [s⁻²]
    pub s_ddot_s: f64,
}

/// Face values of the tangential velocity on the four walls, per row or column, used at
/// the first and last rows/columns (from the wall closures, docs/model.md §3.2). `None` means
/// a one-sided difference inside the domain (an outlet).
#[derive(Clone, Copy, Debug, Default)]
pub struct WallVelocities<'a> {
    /// u on the floor face of each column (length nx), cell-centred in x
    pub south: Option<&'a [f64]>,
    /// u on the top face of each column
    pub north: Option<&'a [f64]>,
    /// v on the west face of each row (length ny), cell-centred in y
    pub west: Option<&'a [f64]>,
    /// v on the east face of each row
    pub east: Option<&'a [f64]>,
}

/// Fills `out` (one entry per cell, index i + nx j) with the strain invariants of the
/// velocity field u ((nx+1) × ny x-faces), v (nx × (ny+1) y-faces).
pub fn strain_rates(
    grid: &Grid,
    u: &[f64],
    v: &[f64],
    walls: &WallVelocities<'_>,
    out: &mut [Strain],
) {
    let nx = grid.nx();
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    // each cell from its own faces and neighbours, rows in parallel
    for_each_row(out, nx, |j, row| {
        for i in 0..nx {
            let du_dx = (u[i + 1 + (nx + 1) * j] - u[i + (nx + 1) * j]) / dx[i];
            let dv_dy = (v[i + nx * (j + 1)] - v[i + nx * j]) / dy[j];
            let du_dy = across_derivative::<X>(grid, u, (walls.south, walls.north), (i, j));
            let dv_dx = across_derivative::<Y>(grid, v, (walls.west, walls.east), (j, i));
            let d12 = 0.5 * (du_dy + dv_dx);
            let tr_d = du_dx + dv_dy;
            // 2-D: D33 = 0 (docs/model.md §0.3)
            let tr_d2 = du_dx * du_dx + dv_dy * dv_dy + 2.0 * d12 * d12;
            row[i] = Strain {
                tr_d,
                tr_d2,
                s_ddot_s: (tr_d2 - tr_d * tr_d / 3.0).max(0.0),
            };
        }
    });
}

/// ∂φ/∂b in cell (a, b) for component `D` (∂u/∂y, ∂v/∂x): (φ_hi − φ_lo)/Δb with φ on the
/// cell's two faces across the direction interpolated between the cell centres (AVG_Y,
/// docs/model.md §4.4 GET_FACE_VEL_SOLIDS) of the cell-centred φ (the mean of its two nodes,
/// MFIX AVG_X_E, §4.1), at a wall the wall face value of `walls` (low, high; MFIX's
/// ghost/fluid mean, §3.2); one-sided at an outlet (centre to the other face).
#[inline]
fn across_derivative<D: Direction>(
    grid: &Grid,
    phi: &[f64],
    (low, high): (Option<&[f64]>, Option<&[f64]>),
    (a, b): (usize, usize),
) -> f64 {
    let nx = grid.nx();
    let across = D::across(grid);
    let n_b = across.len();
    let centre = |b: usize| 0.5 * (phi[D::node(a, b, nx)] + phi[D::node(a + 1, b, nx)]);
    let face = |bf: usize| -> Option<f64> {
        if bf == 0 {
            low.map(|w| w[a])
        } else if bf == n_b {
            high.map(|w| w[a])
        } else {
            let w = across.interpolation_weight(bf - 1);
            Some(w * centre(bf - 1) + (1.0 - w) * centre(bf))
        }
    };
    let (faces, centres) = (across.faces(), across.centres());
    match (face(b), face(b + 1)) {
        (Some(lo), Some(hi)) => (hi - lo) / across.widths()[b],
        (None, Some(hi)) => (hi - centre(b)) / (faces[b + 1] - centres[b]),
        (Some(lo), None) => (centre(b) - lo) / (centres[b] - faces[b]),
        (None, None) => 0.0,
    }
}
