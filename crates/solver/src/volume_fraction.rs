//! The solids volume-fraction correction of Syamlal (1998), as MFIX applies it to one
//! close-packed solids phase (docs/model.md §4.7).
//!
//! The solids face velocities respond to a change ε' of the volume fraction through the
//! solids pressure: u'_f = −e_f (K_cp,nb ε'_nb − K_cp,P ε'_P) in the direction from P to nb,
//! with e_f = A_f / a_P,s (the solids momentum centre coefficient before partial
//! elimination) and K_cp = dP_s/dεs (docs/model.md §2.5). Linearising the discrete solids
//! continuity with upwind face values around the predicted velocities u* gives, per face of
//! cell P with outward flux u*·n A:
//! - outflow: a_nb = ρs εs,P e_f A K_cp,nb; a_P += ρs εs,P e_f A K_cp,P + ρs u*·n A;
//! - inflow:  a_nb = ρs εs,nb e_f A K_cp,nb + ρs |u*·n| A; a_P += ρs εs,nb e_f A K_cp,P;
//!
//! plus a_P += ρs V/Δt and b = −(the mass imbalance of ρs εs with u*). With K_cp = 0 the
//! correction is a pure kinematic continuity correction and exact.

use std::ops::Range;

use runout_linsolve::Stencil5;
use runout_mesh::Grid;

use crate::direction::{Direction, X, Y};
use crate::transport::{face_value, Scheme};
use rayon::prelude::*;
use runout_linsolve::for_each_row;

/// Inputs of the correction equation of one solids phase.
#[derive(Clone, Copy, Debug)]
pub struct CorrectionInputs<'a> {
    /// solids material density ρs [kg m⁻³]
    pub density: f64,
    /// current volume fraction εs per cell [-]
    pub eps: &'a [f64],
    /// volume fraction at the old time level [-]
    pub eps_old: &'a [f64],
    /// predicted solids u on x-faces ((nx+1) × ny) [m s⁻¹]
    pub u: &'a [f64],
    /// predicted solids v on y-faces (nx × (ny+1)) [m s⁻¹]
    pub v: &'a [f64],
    /// e = A/a_P of each u-face (0 on walls, where the velocity is fixed) [m² s kg⁻¹ per m depth]
    pub e_u: &'a [f64],
    /// e = A/a_P of each v-face
    pub e_v: &'a [f64],
    /// K_cp = dP_s/dεs per cell [Pa]
    pub k_cp: &'a [f64],
    /// time step [s]
    pub dt: f64,
    /// scheme of the face volume fractions in the mass imbalance (MFIX `DISCRETIZE(2)`)
    pub scheme: Scheme,
}

/// Net solids mass imbalance of every cell with the given velocities, ρs [(εs − εs⁰) V/Δt +
/// Σ εs,face u·n A] [kg s⁻¹ per m depth], into `out`; the face values follow `x.scheme`
/// ([`face_value`]; on an outlet face the inside cell's for outflow and zero for inflow).
/// Blocks of rows in parallel, two per thread: a y-face between two blocks is evaluated by
/// both (the same value), and every cell sums its terms in the same order (storage, west,
/// east, south, north face), so the result does not depend on the blocks.
pub fn mass_imbalance(grid: &Grid, x: &CorrectionInputs<'_>, out: &mut [f64]) {
    let (nx, ny) = (grid.nx(), grid.ny());
    let blocks = if nx * ny < PAR_MIN_CELLS {
        1
    } else {
        2 * rayon::current_num_threads()
    };
    let rows_per_block = ny.div_ceil(blocks).max(1);
    out.par_chunks_mut(nx * rows_per_block)
        .enumerate()
        .for_each(|(b, block)| imbalance_of_rows(grid, x, b * rows_per_block, block));
}

/// Grids with fewer cells than this compute [`mass_imbalance`] in one block.
const PAR_MIN_CELLS: usize = 1 << 13;

/// [`mass_imbalance`] of the rows j0.. that `out` holds: per cell the storage, then the
/// faces normal to x (west, east), then those normal to y (south, north).
fn imbalance_of_rows(grid: &Grid, x: &CorrectionInputs<'_>, j0: usize, out: &mut [f64]) {
    let nx = grid.nx();
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    for (r, row) in out.chunks_mut(nx).enumerate() {
        let cells = nx * (j0 + r);
        for i in 0..nx {
            row[i] = (x.eps[i + cells] - x.eps_old[i + cells]) * dx[i] * dy[j0 + r] / x.dt;
        }
    }
    let rows = j0..j0 + out.len() / nx;
    face_imbalance::<X>(grid, x, x.u, rows.clone(), out);
    face_imbalance::<Y>(grid, x, x.v, rows, out);
    out.iter_mut().for_each(|m| *m *= x.density);
}

/// Adds the flux εs,f φ A through each face (a, b) normal to direction `D` that bounds a cell
/// of the block of rows `rows` (`out`) to the cell before it and takes it from the cell
/// after it; εs,f from the scheme, on the domain boundary the inside cell's for outflow and
/// 0 for inflow. A y-face between two blocks is evaluated by both (the same value).
fn face_imbalance<D: Direction>(
    grid: &Grid,
    x: &CorrectionInputs<'_>,
    phi: &[f64],
    rows: Range<usize>,
    out: &mut [f64],
) {
    let nx = grid.nx();
    let (n_a, n_b) = (D::along(grid).len(), D::across(grid).len());
    let d_b = D::across(grid).widths();
    let cell = |c: usize, b: usize| D::cell(c, b, nx);
    // cell (c, b)'s index in `out`, if the block holds it
    let in_block = |c: usize, b: usize| {
        let (i, j) = D::xy(c, b);
        rows.contains(&j).then(|| i + nx * (j - rows.start))
    };
    // x: the rows' faces; y: the faces from the block's bottom to its top
    let (along, across) = D::pick(
        (0..n_a + 1, rows.clone()),
        (rows.start..rows.end + 1, 0..n_b),
    );
    D::for_each(along, across, |a, b| {
        let vel = phi[D::node(a, b, nx)];
        // a periodic column of one cell (nx = 1): the fluxes through its west and east
        // faces are the same flux and cancel, so both are left out
        if vel == 0.0 || (D::periodic(grid) && (a == 0 || a == n_a)) {
            return;
        }
        let eps_face = if a == 0 || a == n_a {
            boundary_face(x.eps[cell(a.min(n_a - 1), b)], vel, a == 0)
        } else {
            face_value(
                x.scheme,
                x.eps,
                (a >= 2).then(|| cell(a - 2, b)),
                cell(a - 1, b),
                cell(a, b),
                (a + 1 < n_a).then(|| cell(a + 1, b)),
                vel,
            )
        };
        let flux = eps_face * vel * d_b[b];
        if let Some(k) = a.checked_sub(1).and_then(|c| in_block(c, b)) {
            out[k] += flux;
        }
        if let Some(k) = (a < n_a).then(|| in_block(a, b)).flatten() {
            out[k] -= flux;
        }
    });
}

/// εs on a domain-boundary face (an outlet; walls carry no normal velocity): the inside
/// cell's value for outflow, zero for inflow (the gas outside carries no solids). `low` is
/// true on the west/south side, where inflow is a positive velocity.
fn boundary_face(inside: f64, vel: f64, low: bool) -> f64 {
    let inflow = if low { vel > 0.0 } else { vel < 0.0 };
    if inflow {
        0.0
    } else {
        inside
    }
}

/// The four faces of cell (i, j): (normal velocity in +x/+y, area, sign of the outward
/// normal, neighbour cell across the face if any).
fn faces(
    grid: &Grid,
    u: &[f64],
    v: &[f64],
    i: usize,
    j: usize,
) -> [(f64, f64, f64, Option<usize>); 4] {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    [
        (
            u[i + 1 + (nx + 1) * j],
            dy[j],
            1.0,
            (i + 1 < nx).then(|| i + 1 + nx * j),
        ),
        (
            u[i + (nx + 1) * j],
            dy[j],
            -1.0,
            (i > 0).then(|| i - 1 + nx * j),
        ),
        (
            v[i + nx * (j + 1)],
            dx[i],
            1.0,
            (j + 1 < ny).then(|| i + nx * (j + 1)),
        ),
        (
            v[i + nx * j],
            dx[i],
            -1.0,
            (j > 0).then(|| i + nx * (j - 1)),
        ),
    ]
}

/// Assembles the ε' equation into `a` (cells, x fastest). `imbalance` receives the mass
/// imbalance of the predicted state (its mean magnitude is the residual, docs/model.md §4.11).
pub fn assemble_correction(
    grid: &Grid,
    x: &CorrectionInputs<'_>,
    imbalance: &mut [f64],
    a: &mut Stencil5,
) {
    let nx = grid.nx();
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    mass_imbalance(grid, x, imbalance);
    let rho = x.density;
    let imbalance = &*imbalance;
    // each cell's row from its own faces, rows in parallel
    a.par_fill_rows(|j, row| {
        for i in 0..nx {
            let k = i + nx * j;
            let mut a_p = rho * dx[i] * dy[j] / x.dt;
            let mut links = [0.0; 4]; // e, w, n, s
            let e_faces = [
                x.e_u[i + 1 + (nx + 1) * j],
                x.e_u[i + (nx + 1) * j],
                x.e_v[i + nx * (j + 1)],
                x.e_v[i + nx * j],
            ];
            for (slot, ((vel, area, sign, nb), e_f)) in faces(grid, x.u, x.v, i, j)
                .into_iter()
                .zip(e_faces)
                .enumerate()
            {
                let flux = sign * vel * area;
                if grid.periodic_x() && slot < 2 {
                    continue;
                }
                let Some(n) = nb else {
                    // domain boundary: a wall (no flux, no correction) or an outlet face
                    // whose outflow carries ε'_P
                    if flux > 0.0 {
                        a_p += rho * flux;
                    }
                    continue;
                };
                if flux >= 0.0 {
                    links[slot] = rho * x.eps[k] * e_f * area * x.k_cp[n];
                    a_p += rho * x.eps[k] * e_f * area * x.k_cp[k] + rho * flux;
                } else {
                    links[slot] = rho * x.eps[n] * e_f * area * x.k_cp[n] + rho * flux.abs();
                    a_p += rho * x.eps[n] * e_f * area * x.k_cp[k];
                }
            }
            row.a_e[i] = links[0];
            row.a_w[i] = links[1];
            row.a_n[i] = links[2];
            row.a_s[i] = links[3];
            row.a_p[i] = a_p;
            row.b[i] = -imbalance[k];
        }
    });
}

/// Applies the correction ε' (docs/model.md §4.7): selective under-relaxation where the new
/// value would exceed `eps_max` with ε' > 0, εs ≥ 0, and the solids face velocities
/// u ← u − e_f (K_cp,nb ε'_nb − K_cp,P ε'_P). Walls (e = 0) are untouched.
#[allow(clippy::too_many_arguments)]
pub fn apply_correction(
    grid: &Grid,
    eps_prime: &mut [f64],
    eps: &mut [f64],
    eps_max: f64,
    relax: f64,
    u: &mut [f64],
    v: &mut [f64],
    e_u: &[f64],
    e_v: &[f64],
    k_cp: &[f64],
) {
    for k in 0..eps.len() {
        if eps[k] + eps_prime[k] > eps_max && eps_prime[k] > 0.0 {
            eps_prime[k] *= relax;
        }
        eps[k] = (eps[k] + eps_prime[k]).max(0.0);
    }
    let eps_prime = &*eps_prime;
    correct_face_velocities::<X>(grid, eps_prime, k_cp, e_u, u);
    correct_face_velocities::<Y>(grid, eps_prime, k_cp, e_v, v);
}

/// φ −= e_f (K_cp,high ε'_high − K_cp,low ε'_low) on the nodes of component `D` between two
/// cells (docs/model.md §4.7), rows in parallel (walls have e = 0 anyway; a periodic
/// column's node 0 has no gradient of K_cp ε').
fn correct_face_velocities<D: Direction>(
    grid: &Grid,
    eps_prime: &[f64],
    k_cp: &[f64],
    e: &[f64],
    phi: &mut [f64],
) {
    let nx = grid.nx();
    let (n_a, mx) = (D::along(grid).len(), D::row_len(nx));
    for_each_row(phi, mx, |j, row| {
        for (i, phi) in row.iter_mut().enumerate() {
            let (a, b) = D::ab(i, j);
            if a == 0 || a == n_a {
                continue;
            }
            let (lo, hi) = (D::cell(a - 1, b, nx), D::cell(a, b, nx));
            *phi -= e[i + mx * j] * (k_cp[hi] * eps_prime[hi] - k_cp[lo] * eps_prime[lo]);
        }
    });
}
