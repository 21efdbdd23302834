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
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let (xc, yc) = (grid.x.centres(), grid.y.centres());
    let (x_faces, y_faces) = (grid.x.faces(), grid.y.faces());
    let x_face = |i: usize| x_faces[i];
    let y_face = |j: usize| y_faces[j];
    // cell-centred velocities: the mean of the two faces (MFIX AVG_X_E, docs/model.md §4.1)
    let uc = |i: usize, j: usize| 0.5 * (u[i + (nx + 1) * j] + u[i + 1 + (nx + 1) * j]);
    let vc = |i: usize, j: usize| 0.5 * (v[i + nx * j] + v[i + nx * (j + 1)]);
    // each cell from its own faces and neighbours, rows in parallel
    for_each_row(out, nx, |j, row| {
        for i in 0..nx {
            let du_dx = (u[i + 1 + (nx + 1) * j] - u[i + (nx + 1) * j]) / dx[i];
            let dv_dy = (v[i + nx * (j + 1)] - v[i + nx * j]) / dy[j];
            // ∂u/∂y = (u_n − u_s)/Δy with u on the cell's south and north faces interpolated
            // between row centres (AVG_Y, docs/model.md §4.4 GET_FACE_VEL_SOLIDS), the wall face
            // value at a wall (MFIX's ghost/fluid mean, §3.2); one-sided at an outlet
            let du_dy = {
                let face = |jf: usize| -> Option<f64> {
                    if jf == 0 {
                        walls.south.map(|w| w[i])
                    } else if jf == ny {
                        walls.north.map(|w| w[i])
                    } else {
                        let w = grid.y.interpolation_weight(jf - 1);
                        Some(w * uc(i, jf - 1) + (1.0 - w) * uc(i, jf))
                    }
                };
                match (face(j), face(j + 1)) {
                    (Some(s), Some(n)) => (n - s) / dy[j],
                    // one-sided across the missing face: centre to the other face
                    (None, Some(n)) => (n - uc(i, j)) / (y_face(j + 1) - yc[j]),
                    (Some(s), None) => (uc(i, j) - s) / (yc[j] - y_face(j)),
                    (None, None) => 0.0,
                }
            };
            let dv_dx = {
                let face = |i_f: usize| -> Option<f64> {
                    if i_f == 0 {
                        walls.west.map(|w| w[j])
                    } else if i_f == nx {
                        walls.east.map(|w| w[j])
                    } else {
                        let w = grid.x.interpolation_weight(i_f - 1);
                        Some(w * vc(i_f - 1, j) + (1.0 - w) * vc(i_f, j))
                    }
                };
                match (face(i), face(i + 1)) {
                    (Some(w), Some(e)) => (e - w) / dx[i],
                    (None, Some(e)) => (e - vc(i, j)) / (x_face(i + 1) - xc[i]),
                    (Some(w), None) => (vc(i, j) - w) / (xc[i] - x_face(i)),
                    (None, None) => 0.0,
                }
            };
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
