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

use runout_linsolve::Stencil5;
use runout_mesh::Grid;

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

/// [`mass_imbalance`] of the rows j0.. that `out` holds.
fn imbalance_of_rows(grid: &Grid, x: &CorrectionInputs<'_>, j0: usize, out: &mut [f64]) {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let rows = out.len() / nx;
    for (r, row) in out.chunks_mut(nx).enumerate() {
        let j = j0 + r;
        let cells = nx * j;
        for i in 0..nx {
            row[i] = (x.eps[i + cells] - x.eps_old[i + cells]) * dx[i] * dy[j] / x.dt;
        }
        for i in 0..=nx {
            let vel = x.u[i + (nx + 1) * j];
            // a periodic column of one cell (nx = 1): the fluxes through its west and east
            // faces are the same flux and cancel, so both are left out
            if vel == 0.0 || (grid.periodic_x() && (i == 0 || i == nx)) {
                continue;
            }
            let eps_face = if i == 0 || i == nx {
                boundary_face(x.eps[i.min(nx - 1) + cells], vel, i == 0)
            } else {
                face_value(
                    x.scheme,
                    x.eps,
                    (i >= 2).then(|| i - 2 + cells),
                    i - 1 + cells,
                    i + cells,
                    (i + 1 < nx).then(|| i + 1 + cells),
                    vel,
                )
            };
            let flux = eps_face * vel * dy[j];
            if i > 0 {
                row[i - 1] += flux;
            }
            if i < nx {
                row[i] -= flux;
            }
        }
    }
    // the y-faces from the block's bottom to its top, each adding to the cell below and
    // taking from the cell above where those are in the block
    for j in j0..=j0 + rows {
        for i in 0..nx {
            let vel = x.v[i + nx * j];
            if vel == 0.0 {
                continue;
            }
            let eps_face = if j == 0 || j == ny {
                boundary_face(x.eps[i + nx * j.min(ny - 1)], vel, j == 0)
            } else {
                face_value(
                    x.scheme,
                    x.eps,
                    (j >= 2).then(|| i + nx * (j - 2)),
                    i + nx * (j - 1),
                    i + nx * j,
                    (j + 1 < ny).then(|| i + nx * (j + 1)),
                    vel,
                )
            };
            let flux = eps_face * vel * dx[i];
            if j > j0 {
                out[i + nx * (j - 1 - j0)] += flux;
            }
            if j < j0 + rows {
                out[i + nx * (j - j0)] -= flux;
            }
        }
    }
    out.iter_mut().for_each(|m| *m *= x.density);
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
    let (nx, ny) = (grid.nx(), grid.ny());
    for k in 0..eps.len() {
        if eps[k] + eps_prime[k] > eps_max && eps_prime[k] > 0.0 {
            eps_prime[k] *= relax;
        }
        eps[k] = (eps[k] + eps_prime[k]).max(0.0);
    }
    let eps_prime = &*eps_prime;
    // face by face, rows in parallel (interior faces; walls have e = 0 anyway)
    for_each_row(u, nx + 1, |j, row| {
        for i in 1..nx {
            let (w, e, f) = (i - 1 + nx * j, i + nx * j, i + (nx + 1) * j);
            row[i] -= e_u[f] * (k_cp[e] * eps_prime[e] - k_cp[w] * eps_prime[w]);
        }
    });
    for_each_row(v, nx, |j, row| {
        if j == 0 || j == ny {
            return;
        }
        for (i, v) in row.iter_mut().enumerate() {
            let (s, n, f) = (i + nx * (j - 1), i + nx * j, i + nx * j);
            *v -= e_v[f] * (k_cp[n] * eps_prime[n] - k_cp[s] * eps_prime[s]);
        }
    });
}
