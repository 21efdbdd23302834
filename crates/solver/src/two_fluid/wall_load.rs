//! The solids' normal load on a wall beyond their pressure (docs/model.md §3.11): what a
//! Coulomb wall adds to P_s to press with N_w, the normal traction of the solids on the wall.
//!
//! The solids press on a wall with N_w = −n·σ_s·n, σ_s = −P_s I + τ_s, n the wall's normal
//! into the fluid. The pressure alone misses the normal viscous stress
//! τ_nn = 2 μ_s ∂u_n/∂n + λ_s tr D (Eq. 1's stress, docs/model.md §2.3), which a flow that
//! spreads or compacts carries. A μ(I) block spreading down a slope is in Rankine's active
//! state: stretched along the floor, shortened across it, τ_yy ≈ −μ(I) P (the whole
//! deviatoric stress lies along the stretching), so that the floor carries the weight as
//! P (1 + μ(I)) and P is only about 1/1.38 of it (docs/model.md §3.11 has the numbers).
//!
//! The wall cell's traction is carried to the wall across the half cell between its centre
//! and the wall by that half cell's momentum balance along n, its normal acceleration
//! neglected:
//!
//!   N_w = P_s,c − τ_nn,c − (Δ/2) εs,c (ρs g·n − ∇P_g·n)                           (1)
//!
//! with g the body force at the cell centre (gravity, or a bent floor's field with its
//! centrifugal part, docs/model.md §9), ∇P_g·n the gas pressure's gradient between the wall
//! cell and the next cell inward (the buoyancy −εs ∇P_g of the solids momentum), Δ the wall
//! cell's width across the wall. The normal drag is left out (it matters only where gas
//! flows through the layer across the wall). Returned per wall cell: N_w − P_s,c, which the
//! wall adds to its own pressure ([`runout_walls::MomentumWallState::extra_normal_load`]).
//! The same balance on the side walls of a channel (docs/model.md §8), whose normal z the
//! plane flow does not strain (D_zz = 0), is N_w − P_s = −λ_s tr D ([`side_wall_extra_load`]).

use runout_mesh::{Grid, Side};

use crate::bent_floor::BentFloor;

/// The body force per unit mass on the solids: uniform gravity, or a bent floor's field.
#[derive(Clone, Copy, Debug)]
pub(super) struct BodyForce<'a> {
    /// gravity (g_x, g_y) [m s⁻²] of a plane floor
    pub gravity: (f64, f64),
    /// a bent floor's field replaces `gravity` when set
    pub bent_floor: Option<&'a BentFloor>,
}

impl BodyForce<'_> {
    /// (f_x, f_y) [m s⁻²] at (x, y) for solids moving at `u` along the floor (the bent floor's
    /// centrifugal force −κ u² joins f_y, docs/model.md §9).
    fn at(&self, x: f64, y: f64, u: f64) -> (f64, f64) {
        match self.bent_floor {
            None => self.gravity,
            Some(b) => {
                let (f_x, f_y) = b.force(x, y);
                (f_x, f_y + b.centrifugal(x, u))
            }
        }
    }
}

/// What Eq. (1) reads of one solids phase.
#[derive(Clone, Copy, Debug)]
pub(super) struct PhaseLoad<'a> {
    /// εs per cell
    pub eps: &'a [f64],
    /// u on the x-faces, v on the y-faces [m s⁻¹]
    pub u: &'a [f64],
    pub v: &'a [f64],
    /// μ_s, λ_s [Pa s] and tr D [s⁻¹] per cell
    pub mu: &'a [f64],
    pub lambda: &'a [f64],
    pub tr_d: &'a [f64],
    /// ρs [kg m⁻³]
    pub density: f64,
}

/// N_w − P_s,c of Eq. (1) for every cell of the wall row on `side`, in order along the wall
/// [Pa]. `gas_pressure` is P_g per cell.
pub(super) fn extra_normal_load(
    grid: &Grid,
    side: Side,
    phase: &PhaseLoad<'_>,
    gas_pressure: &[f64],
    body: &BodyForce<'_>,
) -> Vec<f64> {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let (xc, yc) = (grid.x.centres(), grid.y.centres());
    let (dxc, dyc) = (grid.x.face_spacing(), grid.y.face_spacing());
    let horizontal = matches!(side, Side::South | Side::North);
    // n into the fluid: +1 along the axis from a south or west wall
    let n_sign = if matches!(side, Side::South | Side::West) {
        1.0
    } else {
        -1.0
    };
    let n_cells = if horizontal { nx } else { ny };
    (0..n_cells)
        .map(|a| {
            let (i, j) = match side {
                Side::South => (a, 0),
                Side::North => (a, ny - 1),
                Side::West => (0, a),
                Side::East => (nx - 1, a),
            };
            let c = i + nx * j;
            let u_centre = 0.5 * (phase.u[i + (nx + 1) * j] + phase.u[i + 1 + (nx + 1) * j]);
            let (f_x, f_y) = body.at(xc[i], yc[j], u_centre);
            // the next cell inward along an axis of `len` cells, and the face between them
            // (whose spacing is the centres' distance)
            let inward = |k: usize, len: usize| {
                if n_sign > 0.0 {
                    (k + 1 < len).then_some((k + 1, k + 1))
                } else {
                    k.checked_sub(1).map(|m| (m, k))
                }
            };
            // ∂u_n/∂n (sign-free), the body force along n, ∇P_g·n to the next cell inward
            let (dun_dn, f_n, dp_n, delta) = if horizontal {
                let dv = (phase.v[i + nx * (j + 1)] - phase.v[c]) / dy[j];
                let dp = inward(j, ny).map_or(0.0, |(m, face)| {
                    (gas_pressure[i + nx * m] - gas_pressure[c]) / dyc[face]
                });
                (dv, n_sign * f_y, dp, dy[j])
            } else {
                let du = (phase.u[i + 1 + (nx + 1) * j] - phase.u[i + (nx + 1) * j]) / dx[i];
                let dp = inward(i, nx).map_or(0.0, |(m, face)| {
                    (gas_pressure[m + nx * j] - gas_pressure[c]) / dxc[face]
                });
                (du, n_sign * f_x, dp, dx[i])
            };
            let tau_nn = 2.0 * phase.mu[c] * dun_dn + phase.lambda[c] * phase.tr_d[c];
            let eps = phase.eps[c];
            // Eq. (1) less P_s,c
            -tau_nn - 0.5 * delta * eps * (phase.density * f_n - dp_n)
        })
        .collect()
}

/// N_w − P_s on a side wall of a channel (module doc): −λ_s tr D, the plane flow's τ_zz with
/// D_zz = 0 [Pa].
pub(super) fn side_wall_extra_load(lambda_s: f64, tr_d: f64) -> f64 {
    -lambda_s * tr_d
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_mesh::Axis;

    fn grid() -> Grid {
        Grid::new(
            Axis::uniform(0.0, 0.3, 3).unwrap(),
            Axis::uniform(0.0, 0.2, 4).unwrap(),
        )
    }

    /// A layer at rest under gravity with hydrostatic gas: the floor carries the wall cell's
    /// pressure and the half cell's buoyant weight εs (ρs − ρg) g Δ/2; the lid, with no cell
    /// inward beyond the top row's neighbour, its half cell's weight pulling off it.
    #[test]
    fn at_rest_the_half_cell_weight_joins_the_pressure() {
        let grid = grid();
        let (nx, ny) = (3, 4);
        let (rho_s, rho_g, g, eps) = (2500.0, 1.2, 9.81, 0.55);
        let zeros_c = vec![0.0; nx * ny];
        let u = vec![0.0; (nx + 1) * ny];
        let v = vec![0.0; nx * (ny + 1)];
        let eps_field = vec![eps; nx * ny];
        let yc = grid.y.centres().to_vec();
        let p_g: Vec<f64> = (0..nx * ny).map(|k| 1e5 - rho_g * g * yc[k / nx]).collect();
        let phase = PhaseLoad {
            eps: &eps_field,
            u: &u,
            v: &v,
            mu: &zeros_c,
            lambda: &zeros_c,
            tr_d: &zeros_c,
            density: rho_s,
        };
        let body = BodyForce {
            gravity: (0.0, -g),
            bent_floor: None,
        };
        let floor = extra_normal_load(&grid, Side::South, &phase, &p_g, &body);
        let expected = 0.5 * 0.05 * eps * (rho_s - rho_g) * g;
        for load in floor {
            assert!((load / expected - 1.0).abs() < 1e-12, "{load} {expected}");
        }
        let lid = extra_normal_load(&grid, Side::North, &phase, &p_g, &body);
        for load in lid {
            assert!((load / -expected - 1.0).abs() < 1e-12, "{load} {expected}");
        }
        // the side walls feel no body force across them
        for load in extra_normal_load(&grid, Side::West, &phase, &p_g, &body) {
            assert!(load.abs() < 1e-12, "{load}");
        }
    }

    /// A cell shortened across the floor at rate e (v falls by e Δ over the wall cell) with
    /// μ_s, λ_s = −2μ_s/3: τ_yy = 2 μ_s (−e) + λ_s (−e) = −(4/3) μ_s e, a load beyond P of
    /// (4/3) μ_s e (no gravity); on a side wall −λ_s tr D = −(2/3) μ_s e, pulling off it.
    #[test]
    fn a_shortened_cell_presses_on_the_floor_with_its_viscous_stress() {
        let grid = grid();
        let (nx, ny) = (3, 4);
        let (mu, e) = (2.0e3, 1e-3);
        let u = vec![0.0; (nx + 1) * ny];
        // v = −e y on the y-faces
        let v: Vec<f64> = (0..nx * (ny + 1))
            .map(|k| -e * grid.y.faces()[k / nx])
            .collect();
        let mu_field = vec![mu; nx * ny];
        let lambda = vec![-2.0 / 3.0 * mu; nx * ny];
        let tr_d = vec![-e; nx * ny];
        let eps_field = vec![0.5; nx * ny];
        let phase = PhaseLoad {
            eps: &eps_field,
            u: &u,
            v: &v,
            mu: &mu_field,
            lambda: &lambda,
            tr_d: &tr_d,
            density: 2500.0,
        };
        let body = BodyForce {
            gravity: (0.0, 0.0),
            bent_floor: None,
        };
        let floor = extra_normal_load(&grid, Side::South, &phase, &[1e5; 12], &body);
        for load in floor {
            assert!((load / (4.0 / 3.0 * mu * e) - 1.0).abs() < 1e-12, "{load}");
        }
        let side = side_wall_extra_load(-2.0 / 3.0 * mu, -e);
        assert!((side / (-2.0 / 3.0 * mu * e) - 1.0).abs() < 1e-12, "{side}");
    }
}
