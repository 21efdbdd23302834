//! Cell-centred strain rates of a phase from its staggered velocities (model-spec §4.4,
//! "cell-centred strain rate for μ, P_f and production"), as the closures need them:
//! tr D = ∂u/∂x + ∂v/∂y, tr(D²) = D11² + D22² + 2 D12², and S:S = tr(D²) − (tr D)²/3
//! (model-spec §0.3, §2.4.2). D12 = ½(∂u/∂y + ∂v/∂x) uses the velocities interpolated to
//! the cell centre's neighbours: ∂u/∂y from the cell-centred u of the rows above and below
//! (one-sided at the domain's first and last rows, where the wall ghost would enter in MFIX;
//! the caller's wall closure supplies the face value there), likewise ∂v/∂x.

use runout_mesh::Grid;

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
/// the first and last rows/columns (from the wall closures, model-spec §3.2). `None` means
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
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let (xc, yc) = (grid.x.centres(), grid.y.centres());
    let (x0, x1, y0, y1) = (grid.x.start(), grid.x.end(), grid.y.start(), grid.y.end());
    // cell-centred velocities: the mean of the two faces (MFIX AVG_X_E, model-spec §4.1)
    let uc = |i: usize, j: usize| 0.5 * (u[i + (nx + 1) * j] + u[i + 1 + (nx + 1) * j]);
    let vc = |i: usize, j: usize| 0.5 * (v[i + nx * j] + v[i + nx * (j + 1)]);
    for j in 0..ny {
        for i in 0..nx {
            let du_dx = (u[i + 1 + (nx + 1) * j] - u[i + (nx + 1) * j]) / dx[i];
            let dv_dy = (v[i + nx * (j + 1)] - v[i + nx * j]) / dy[j];
            // ∂u/∂y: centred difference of cell-centred u between the neighbouring rows, the
            // wall face value standing in for the missing row
            let (y_lo, u_lo) = if j > 0 {
                (yc[j - 1], uc(i, j - 1))
            } else {
                walls.south.map_or((yc[j], uc(i, j)), |w| (y0, w[i]))
            };
            let (y_hi, u_hi) = if j + 1 < ny {
                (yc[j + 1], uc(i, j + 1))
            } else {
                walls.north.map_or((yc[j], uc(i, j)), |w| (y1, w[i]))
            };
            let du_dy = if y_hi > y_lo {
                (u_hi - u_lo) / (y_hi - y_lo)
            } else {
                0.0
            };
            let (x_lo, v_lo) = if i > 0 {
                (xc[i - 1], vc(i - 1, j))
            } else {
                walls.west.map_or((xc[i], vc(i, j)), |w| (x0, w[j]))
            };
            let (x_hi, v_hi) = if i + 1 < nx {
                (xc[i + 1], vc(i + 1, j))
            } else {
                walls.east.map_or((xc[i], vc(i, j)), |w| (x1, w[j]))
            };
            let dv_dx = if x_hi > x_lo {
                (v_hi - v_lo) / (x_hi - x_lo)
            } else {
                0.0
            };
            let d12 = 0.5 * (du_dy + dv_dx);
            let tr_d = du_dx + dv_dy;
            // 2-D: D33 = 0 (model-spec §0.3)
            let tr_d2 = du_dx * du_dx + dv_dy * dv_dy + 2.0 * d12 * d12;
            out[i + nx * j] = Strain {
                tr_d,
                tr_d2,
                s_ddot_s: (tr_d2 - tr_d * tr_d / 3.0).max(0.0),
            };
        }
    }
}
