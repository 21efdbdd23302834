//! Momentum equations of one phase on the staggered grid (docs/model.md §4.4), with
//! variable bulk density ρε, volume fraction ε and viscosity μ per cell, so that the same
//! assembly serves the single-phase core (ε = 1, uniform ρ and μ) and every phase of the
//! two-fluid model.
//!
//! u control volumes span from cell centre i−1 to i (half a cell at the domain ends), v
//! control volumes from row j−1 to j. Per face of a control volume:
//! - mass flux: the mean of the two adjacent scalar-cell face fluxes (docs/model.md §4.2), each
//!   ρε_face u A with ρε_face from the convection scheme (upwind or Superbee, as MFIX's
//!   continuity face densities, [`face_value`]);
//! - conductance: μ A/δ, with μ of the cell at x-faces of u-cells and the harmonic mean of
//!   the four surrounding cells at their y-faces (MFIX AVG_X_H of AVG_Y_H, §4.1);
//! - transient: a_P⁰ = ½ (V_W ρε_W⁰ + V_E ρε_E⁰)/Δt (old bulk density averaged by cell
//!   volumes to the momentum cell, §4.4); body force likewise with the current ρε;
//! - pressure: −ε̄ (P_E − P_W) A with ε̄ distance-interpolated (AVG_X), plus −(P_s,E − P_s,W) A
//!   for a solids phase and −(P*_E − P*_W) A where the Schaeffer plastic pressure is given
//!   (§1.2, §4.4);
//! - walls: the eliminated Robin closure of the tangential component (§3.2) with the fluid
//!   cells' viscosity (§3.1).
//!
//! The explicit stress terms of docs/model.md §4.4 come in as a per-node source
//! ([`PhaseFields::explicit_source`], computed by [`crate::stress`]); the interphase drag is
//! added by the partial elimination of the two-fluid model.

use runout_closures::FaceMean;
use runout_linsolve::{RowMut, Stencil5};
use runout_mesh::{Grid, Sides};
use runout_walls::RobinFace;

use crate::bent_floor::BentFloor;
use crate::momentum_form::add_continuity_remainder;
pub use crate::momentum_form::MomentumForm;
use crate::side::{outlet_pressure, OutletPoint, SideBc};
use crate::staggered::{mean_u_at_v_node, Component};
use crate::transport::{assemble_masked, face_value, FaceData, Scheme};

/// Cell-centred coefficient fields of one phase (index i + nx j).
#[derive(Clone, Copy, Debug)]
pub struct PhaseFields<'a> {
    /// bulk density ρε at the current iterate [kg m⁻³]
    pub bulk_density: &'a [f64],
    /// bulk density at the old time level [kg m⁻³]
    pub bulk_density_old: &'a [f64],
    /// volume fraction ε, multiplying the gas-pressure gradient [-]
    pub volume_fraction: &'a [f64],
    /// dynamic viscosity [Pa s]
    pub viscosity: &'a [f64],
    /// how `viscosity` is averaged to the corners (harmonic but for μ(I), [`FaceMean`])
    pub viscosity_mean: FaceMean,
    /// the solids pressure P_s of a solids phase [Pa]; `None` for the gas
    pub solids_pressure: Option<&'a [f64]>,
    /// the Schaeffer plastic pressure P* of a solids phase [Pa], its own gradient −∇P*
    /// (docs/model.md §2.4.1, §4.4); `None` for the gas and without Schaeffer friction (P* ≡ 0)
    pub plastic_pressure: Option<&'a [f64]>,
    /// explicit stress source per node of the component being assembled, already integrated
    /// over the control volume [N per m depth] (docs/model.md §4.4, [`crate::stress`]); `None`
    /// where the viscosity is uniform and the flow incompressible (it vanishes)
    pub explicit_source: Option<&'a [f64]>,
    /// nodes of the component being assembled whose rows the caller replaces (dilute solids
    /// faces, docs/model.md §2.7): their rows and the faces between two of them are skipped
    pub skip: Option<&'a [bool]>,
    /// the phase's velocity along x at the u nodes, for the centrifugal force of a bent floor
    /// in its v equations ([`Context::bent_floor`]); `None` without one
    pub velocity_along: Option<&'a [f64]>,
}

/// Per-node wall closures that replace a side's single [`SideBc`] (wall models whose
/// coefficients depend on the local state: Johnson–Jackson, Jenkins, docs/model.md §3.5). For
/// momentum: `south`/`north` hold one closure per u-node (nx + 1), `west`/`east` one per
/// v-node (ny + 1); for granular energy one per boundary cell (nx or ny).
#[derive(Clone, Debug, Default)]
pub struct WallFaces {
    /// closures along the west side
    pub west: Option<Vec<RobinFace>>,
    /// closures along the east side
    pub east: Option<Vec<RobinFace>>,
    /// closures along the south side (the floor)
    pub south: Option<Vec<RobinFace>>,
    /// closures along the north side
    pub north: Option<Vec<RobinFace>>,
}

/// The closure at position `k` along `side`: the per-node one if given, else the side's.
fn side_closure(bc: &SideBc, faces: Option<&Vec<RobinFace>>, k: usize) -> SideBc {
    match faces {
        Some(f) => SideBc::Wall(f[k]),
        None => *bc,
    }
}

/// What every phase's momentum assembly shares.
#[derive(Clone, Copy, Debug)]
pub struct Context<'a> {
    /// the grid
    pub grid: &'a Grid,
    /// the condition on each side for this phase's tangential velocity
    pub bcs: &'a Sides<SideBc>,
    /// gravity (g_x, g_y) [m s⁻²]
    pub gravity: (f64, f64),
    /// a floor that bends (docs/model.md §9): when set, gravity is its field, not `gravity`,
    /// and the v equations gain the centrifugal force of `PhaseFields::velocity_along`
    pub bent_floor: Option<&'a BentFloor>,
    /// time step [s] (`f64::INFINITY` for a steady iteration)
    pub dt: f64,
    /// convection scheme
    pub scheme: Scheme,
    /// gas pressure at cell centres [Pa]
    pub gas_pressure: &'a [f64],
    /// per-node wall closures overriding `bcs` on the sides they cover
    pub wall_faces: Option<&'a WallFaces>,
    /// the form of the transient and convection terms
    pub form: MomentumForm,
}

/// Width of the u control volume at x-face i: centre to centre inside, half a cell at the
/// two ends (docs/model.md §4.1).
pub fn cv_width(widths: &[f64], i: usize) -> f64 {
    let n = widths.len();
    if i == 0 {
        0.5 * widths[0]
    } else if i == n {
        0.5 * widths[n - 1]
    } else {
        0.5 * (widths[i - 1] + widths[i])
    }
}

/// Harmonic mean with MFIX's guard against a zero denominator (docs/model.md §4.1, AVG_X_H).
pub(crate) fn harmonic(a: f64, b: f64, weight_a: f64) -> f64 {
    a * b / (weight_a * a + (1.0 - weight_a) * b).max(1e-15)
}

/// The mean of two cell values at the face between them, `weight_a` the distance weight of
/// `a`: [`harmonic`] or arithmetic (docs/model.md §4.1, §2.4.4).
pub(crate) fn face_mean(mean: FaceMean, a: f64, b: f64, weight_a: f64) -> f64 {
    match mean {
        FaceMean::Harmonic => harmonic(a, b, weight_a),
        FaceMean::Arithmetic => weight_a * a + (1.0 - weight_a) * b,
    }
}

/// Distance-weighted interpolation of a cell field to x-face i (1 ≤ i < nx; AVG_X).
fn interp_x(grid: &Grid, field: &[f64], i: usize, j: usize) -> f64 {
    let nx = grid.nx();
    let w = grid.x.interpolation_weight(i - 1);
    w * field[i - 1 + nx * j] + (1.0 - w) * field[i + nx * j]
}

/// Distance-weighted interpolation of a cell field to y-face j (1 ≤ j < ny; AVG_Y).
fn interp_y(grid: &Grid, field: &[f64], i: usize, j: usize) -> f64 {
    let nx = grid.nx();
    let w = grid.y.interpolation_weight(j - 1);
    w * field[i + nx * (j - 1)] + (1.0 - w) * field[i + nx * j]
}

/// Σ a_nb φ_nb + b of row k: the right-hand side with the current neighbour values (used
/// for residuals, docs/model.md §4.11, and the partial elimination, §4.5).
pub(crate) fn neighbour_sum(a: &Stencil5, phi: &[f64], k: usize) -> f64 {
    let row = RowCoefficients::of(a, k);
    row.neighbour_sum(phi, k, a.pattern().nx())
}

/// Makes row k read φ = `value` with no neighbour links.
pub(crate) fn fixed_row(a: &mut Stencil5, k: usize, value: f64) {
    RowCoefficients::fixed(value).put(a, k);
}

/// The coefficients and right-hand side of one row, a_P φ_P = Σ a_nb φ_nb + b.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct RowCoefficients {
    pub a_p: f64,
    pub a_e: f64,
    pub a_w: f64,
    pub a_n: f64,
    pub a_s: f64,
    pub b: f64,
}

impl RowCoefficients {
    /// φ = `value` with no neighbour links.
    pub fn fixed(value: f64) -> Self {
        RowCoefficients {
            a_p: 1.0,
            a_e: 0.0,
            a_w: 0.0,
            a_n: 0.0,
            a_s: 0.0,
            b: value,
        }
    }

    /// Row k of `a`.
    #[inline]
    pub fn of(a: &Stencil5, k: usize) -> Self {
        RowCoefficients {
            a_p: a.a_p[k],
            a_e: a.a_e[k],
            a_w: a.a_w[k],
            a_n: a.a_n[k],
            a_s: a.a_s[k],
            b: a.b[k],
        }
    }

    /// Entry i of the row `row`.
    #[inline]
    pub fn of_entry(row: &RowMut<'_>, i: usize) -> Self {
        RowCoefficients {
            a_p: row.a_p[i],
            a_e: row.a_e[i],
            a_w: row.a_w[i],
            a_n: row.a_n[i],
            a_s: row.a_s[i],
            b: row.b[i],
        }
    }

    /// Writes these into row k of `a`.
    #[inline]
    pub fn put(self, a: &mut Stencil5, k: usize) {
        a.a_p[k] = self.a_p;
        a.b[k] = self.b;
        a.a_e[k] = self.a_e;
        a.a_w[k] = self.a_w;
        a.a_n[k] = self.a_n;
        a.a_s[k] = self.a_s;
    }

    /// Writes these into entry i of `row`.
    #[inline]
    pub fn put_in(self, row: &mut RowMut<'_>, i: usize) {
        row.a_p[i] = self.a_p;
        row.b[i] = self.b;
        row.a_e[i] = self.a_e;
        row.a_w[i] = self.a_w;
        row.a_n[i] = self.a_n;
        row.a_s[i] = self.a_s;
    }

    /// Σ a_nb φ_nb + b of this row of cell k in an `nx`-wide block ([`neighbour_sum`]).
    #[inline]
    pub fn neighbour_sum(&self, phi: &[f64], k: usize, nx: usize) -> f64 {
        let mut r = self.b;
        if self.a_e != 0.0 {
            r += self.a_e * phi[k + 1];
        }
        if self.a_w != 0.0 {
            r += self.a_w * phi[k - 1];
        }
        if self.a_n != 0.0 {
            r += self.a_n * phi[k + nx];
        }
        if self.a_s != 0.0 {
            r += self.a_s * phi[k - nx];
        }
        r
    }
}

/// Adds the eliminated wall-face closure (docs/model.md §3.2) of a tangential component to row
/// k: Γ h/(g + hΔ/2) to a_P and Γ c/(g + hΔ/2) to b, times the face area. Nothing on an
/// outlet (zero normal gradient).
pub(crate) fn add_wall_face(
    a: &mut Stencil5,
    k: usize,
    bc: &SideBc,
    gamma: f64,
    delta: f64,
    area: f64,
) {
    if let SideBc::Wall(face) = bc {
        let (ap, b) = face.implicit_parts(gamma, delta);
        a.a_p[k] += ap * area;
        a.b[k] += b * area;
    }
}

/// Whether both momentum nodes `k0` and `k1` are skipped (their shared face is not needed).
#[inline]
fn both_skipped(skip: Option<&[bool]>, k0: usize, k1: usize) -> bool {
    skip.is_some_and(|s| s[k0] && s[k1])
}

/// Assembles the momentum system of component `c` (u or v) of one phase on its node block,
/// without relaxation (module doc); `old` is the component's velocity at the old time level.
/// Rows of fixed nodes (wall normal velocities) read 0.
///
/// u and v are one equation, written twice as mirror images (`u_faces`/`u_sources` and
/// `v_faces`/`v_sources`; the test `v_of_the_transposed_problem_is_u` holds them to it): one
/// assembly over the staggered [`Component`] view gave the same results bit for bit but
/// cost 6–7 % more CPU on family M (docs/studies/performance.md, session 14), where the issue's
/// constraint allows 3 %.
#[allow(clippy::too_many_arguments)]
pub fn assemble(
    ctx: &Context<'_>,
    phase: &PhaseFields<'_>,
    c: Component,
    u: &[f64],
    v: &[f64],
    old: &[f64],
    faces: &mut FaceData,
    a: &mut Stencil5,
) {
    let mut fluxes = MassFluxes::default();
    mass_fluxes(ctx.grid, ctx.scheme, phase.bulk_density, u, v, &mut fluxes);
    assemble_with_fluxes(ctx, phase, c, u, v, old, &fluxes, faces, a);
}

/// [`assemble`] with the phase's scalar-cell mass fluxes `fluxes` of [`mass_fluxes`] at
/// the same u, v and bulk density, computed once for the u and the v system.
#[allow(clippy::too_many_arguments)]
pub fn assemble_with_fluxes(
    ctx: &Context<'_>,
    phase: &PhaseFields<'_>,
    c: Component,
    u: &[f64],
    v: &[f64],
    old: &[f64],
    fluxes: &MassFluxes,
    faces: &mut FaceData,
    a: &mut Stencil5,
) {
    if c.dir == 0 {
        u_faces(ctx, phase, fluxes, faces);
        assemble_masked(faces, u, ctx.scheme, phase.skip, a);
        u_sources(ctx, phase, old, a);
    } else {
        v_faces(ctx, phase, fluxes, faces);
        assemble_masked(faces, v, ctx.scheme, phase.skip, a);
        v_sources(ctx, phase, old, a);
    }
    if ctx.form == MomentumForm::Conservative && ctx.dt.is_finite() {
        let phi = if c.dir == 0 { u } else { v };
        add_continuity_remainder(ctx.grid, phase, c, phi, faces, ctx.dt, a);
    }
}

/// The mass fluxes ρε u A of one phase through every face of the scalar cells, ρε at an
/// inner face from the convection scheme (docs/model.md §4.2, [`face_value`]) and at a
/// domain end the inside cell's (an outlet's inflow). A momentum control volume's face
/// flux is the mean of two of them (module doc): computed once per phase, they serve the
/// u and the v system, where each is read four times.
#[derive(Clone, Debug, Default)]
pub struct MassFluxes {
    /// through the x-faces, index i + (nx + 1) j (the u-nodes) [kg s⁻¹ per m depth]
    pub x: Vec<f64>,
    /// through the y-faces, index i + nx j (the v-nodes) [kg s⁻¹ per m depth]
    pub y: Vec<f64>,
}

/// Fills `out` with the mass fluxes of bulk density `rho_eps` and velocities u, v
/// ([`MassFluxes`]).
pub fn mass_fluxes(
    grid: &Grid,
    scheme: Scheme,
    rho_eps: &[f64],
    u: &[f64],
    v: &[f64],
    out: &mut MassFluxes,
) {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let mx = nx + 1;
    out.x.resize(mx * ny, 0.0);
    out.y.resize(nx * (ny + 1), 0.0);
    for j in 0..ny {
        let row = nx * j;
        for i in 0..mx {
            let vel = u[i + mx * j];
            let re = if i == 0 {
                rho_eps[row]
            } else if i == nx {
                rho_eps[nx - 1 + row]
            } else {
                face_value(
                    scheme,
                    rho_eps,
                    (i >= 2).then(|| i - 2 + row),
                    i - 1 + row,
                    i + row,
                    (i + 1 < nx).then(|| i + 1 + row),
                    vel,
                )
            };
            out.x[i + mx * j] = re * vel * dy[j];
        }
    }
    for j in 0..=ny {
        for i in 0..nx {
            let vel = v[i + nx * j];
            let re = if j == 0 {
                rho_eps[i]
            } else if j == ny {
                rho_eps[i + nx * (ny - 1)]
            } else {
                face_value(
                    scheme,
                    rho_eps,
                    (j >= 2).then(|| i + nx * (j - 2)),
                    i + nx * (j - 1),
                    i + nx * j,
                    (j + 1 < ny).then(|| i + nx * (j + 1)),
                    vel,
                )
            };
            out.y[i + nx * j] = re * vel * dx[i];
        }
    }
}

/// The u-nodes of a grid: the cells beside each node, the distance weights between them and
/// the widths of the control volumes (a periodic column's node 0 lies between cell nx − 1 and
/// cell 0 and spans a whole cell).
#[derive(Clone, Copy)]
struct UNodes<'a> {
    grid: &'a Grid,
    periodic: bool,
}

impl UNodes<'_> {
    /// The cells west and east of u-node i: one at an end, unless the column is periodic,
    /// where node 0 lies between cell nx − 1 (= 0) and cell 0.
    fn cells_beside(self, i: usize) -> (Option<usize>, Option<usize>) {
        let nx = self.grid.nx();
        if self.periodic && i == 0 {
            (Some(nx - 1), Some(0))
        } else {
            (i.checked_sub(1), (i < nx).then_some(i))
        }
    }

    /// Distance weight of cell w at the face between cells w and e (½ across the wrap).
    fn x_weight(self, w: usize, e: usize) -> f64 {
        if w < e {
            self.grid.x.interpolation_weight(w)
        } else {
            0.5
        }
    }

    /// Width of the u control volume: the whole cell for a periodic column's node 0.
    fn width(self, i: usize) -> f64 {
        let (nx, dx) = (self.grid.nx(), self.grid.x.widths());
        if self.periodic && i == 0 {
            0.5 * (dx[nx - 1] + dx[0])
        } else {
            cv_width(dx, i)
        }
    }
}

/// The face fluxes and conductances of the u control volumes (module doc).
fn u_faces(ctx: &Context<'_>, phase: &PhaseFields<'_>, fluxes: &MassFluxes, faces: &mut FaceData) {
    let grid = ctx.grid;
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let dyc = grid.y.face_spacing();
    let mx = nx + 1;
    let mu = phase.viscosity;
    // scalar-cell x-face mass flux at u-node (i, j)
    let x_face_flux = |i: usize, j: usize| fluxes.x[i + mx * j];
    let nodes = UNodes {
        grid,
        periodic: ctx.grid.periodic_x(),
    };
    let cells_beside = |i: usize| nodes.cells_beside(i);
    let x_weight = |w: usize, e: usize| nodes.x_weight(w, e);
    let width = |i: usize| nodes.width(i);
    // scalar-cell y-face mass flux at v-node (i, j), 1 ≤ j < ny
    let y_face_flux = |i: usize, j: usize| fluxes.y[i + nx * j];
    for j in 0..ny {
        for i in 1..=nx {
            // u-CV x-face at cell centre i−1, between u-nodes i−1 and i
            let k = faces.xf(i, j);
            // periodic column: the face couples node 0 to its own copy, and its flux and
            // diffusion cancel those of the wrapped face on the other side
            if ctx.grid.periodic_x() || both_skipped(phase.skip, i - 1 + mx * j, i + mx * j) {
                (faces.flux_x[k], faces.cond_x[k]) = (0.0, 0.0);
                continue;
            }
            faces.flux_x[k] = 0.5 * (x_face_flux(i - 1, j) + x_face_flux(i, j));
            faces.cond_x[k] = mu[i - 1 + nx * j] * dy[j] / dx[i - 1];
        }
    }
    for j in 1..ny {
        for i in 0..mx {
            // u-CV y-face at y-face j: halves of the two adjacent cells' v-face fluxes
            if both_skipped(phase.skip, i + mx * (j - 1), i + mx * j) {
                let k = faces.yf(i, j);
                (faces.flux_y[k], faces.cond_y[k]) = (0.0, 0.0);
                continue;
            }
            let (west, east) = cells_beside(i);
            let flux: f64 = [west, east]
                .into_iter()
                .flatten()
                .map(|c| 0.5 * y_face_flux(c, j))
                .sum();
            // viscosity at the corner: harmonic (μ(I): arithmetic) in y per column, then in
            // x (AVG_X_H of AVG_Y_H)
            let mean = phase.viscosity_mean;
            let column = |c: usize| {
                face_mean(
                    mean,
                    mu[c + nx * (j - 1)],
                    mu[c + nx * j],
                    grid.y.interpolation_weight(j - 1),
                )
            };
            let mu_corner = match (west, east) {
                (Some(w), Some(e)) => face_mean(mean, column(w), column(e), x_weight(w, e)),
                (Some(c), None) | (None, Some(c)) => column(c),
                (None, None) => 0.0,
            };
            let k = faces.yf(i, j);
            faces.flux_y[k] = flux;
            faces.cond_y[k] = mu_corner * width(i) / dyc[j];
        }
    }
}

/// The sources of the u equations (walls, transient, gravity, pressure gradients, the
/// explicit stress) and the rows of fixed nodes.
fn u_sources(ctx: &Context<'_>, phase: &PhaseFields<'_>, u_old: &[f64], a: &mut Stencil5) {
    let grid = ctx.grid;
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let mx = nx + 1;
    let rho_eps = phase.bulk_density;
    let mu = phase.viscosity;
    let nodes = UNodes {
        grid,
        periodic: ctx.grid.periodic_x(),
    };
    let cells_beside = |i: usize| nodes.cells_beside(i);
    let x_weight = |w: usize, e: usize| nodes.x_weight(w, e);
    let width = |i: usize| nodes.width(i);
    let y0 = grid.y.start();
    let yc = grid.y.centres();
    let (x0, x1) = (grid.x.start(), grid.x.end());
    let xc = grid.x.centres();
    for j in 0..ny {
        let west_point = OutletPoint::on_side((x0, y0), (x0, yc[j]), ctx.gravity.1);
        let p_west = outlet_pressure(ctx.bent_floor, &ctx.bcs.west, west_point).unwrap_or(0.0);
        let east_point = OutletPoint::on_side((x1, y0), (x1, yc[j]), ctx.gravity.1);
        let p_east = outlet_pressure(ctx.bent_floor, &ctx.bcs.east, east_point).unwrap_or(0.0);
        for i in 0..mx {
            let k = i + mx * j;
            if a.pattern().fixed_mask()[k] {
                fixed_row(a, k, 0.0);
                continue;
            }
            if phase.skip.is_some_and(|s| s[k]) {
                continue;
            }
            let width = width(i);
            // cells on either side (the inside cell only at an outlet end)
            let (west, east) = cells_beside(i);
            let half_volume = |c: Option<usize>, field: &[f64]| {
                c.map_or(0.0, |c| 0.5 * dx[c] * dy[j] * field[c + nx * j])
            };
            // walls below and above: the fluid cells' viscosity (docs/model.md §3.1)
            let mu_wall = |row: usize| -> f64 {
                match (west, east) {
                    (Some(w), Some(e)) => {
                        harmonic(mu[w + nx * row], mu[e + nx * row], x_weight(w, e))
                    }
                    (Some(c), None) | (None, Some(c)) => mu[c + nx * row],
                    (None, None) => 0.0,
                }
            };
            let over = ctx.wall_faces;
            if j == 0 {
                let bc = side_closure(&ctx.bcs.south, over.and_then(|w| w.south.as_ref()), i);
                add_wall_face(a, k, &bc, mu_wall(0), dy[0], width);
            }
            if j == ny - 1 {
                let bc = side_closure(&ctx.bcs.north, over.and_then(|w| w.north.as_ref()), i);
                add_wall_face(a, k, &bc, mu_wall(ny - 1), dy[ny - 1], width);
            }
            // transient (implicit Euler, docs/model.md §4.3–4.4)
            let a0 = (half_volume(west, phase.bulk_density_old)
                + half_volume(east, phase.bulk_density_old))
                / ctx.dt;
            a.a_p[k] += a0;
            a.b[k] += a0 * u_old[k];
            // body force with the current bulk density
            let g_x = match (ctx.bent_floor, west, east) {
                (None, ..) => ctx.gravity.0,
                (Some(b), Some(w), Some(e)) => b.force_x_between(xc[w], xc[e], yc[j]),
                (Some(b), ..) => b.force(grid.x.faces()[i], yc[j]).0,
            };
            a.b[k] += (half_volume(west, rho_eps) + half_volume(east, rho_eps)) * g_x;
            // gas pressure, −ε̄ ΔP A; solids pressure, −ΔP_s A
            let eps_face = match (west, east) {
                (Some(w), Some(e)) if w >= e => {
                    let f = phase.volume_fraction;
                    0.5 * (f[w + nx * j] + f[e + nx * j])
                }
                (Some(_), Some(_)) => interp_x(grid, phase.volume_fraction, i, j),
                (Some(c), None) | (None, Some(c)) => phase.volume_fraction[c + nx * j],
                (None, None) => 0.0,
            };
            let p_w = west.map_or(p_west, |c| ctx.gas_pressure[c + nx * j]);
            let p_e = east.map_or(p_east, |c| ctx.gas_pressure[c + nx * j]);
            a.b[k] += eps_face * (p_w - p_e) * dy[j];
            if let (Some(ps), Some(w), Some(e)) = (phase.solids_pressure, west, east) {
                a.b[k] += (ps[w + nx * j] - ps[e + nx * j]) * dy[j];
            }
            // −(P*_E − P*_W) A, MFIX's SDPS (docs/model.md §4.4, §2.4.1)
            if let (Some(pp), Some(w), Some(e)) = (phase.plastic_pressure, west, east) {
                a.b[k] += (pp[w + nx * j] - pp[e + nx * j]) * dy[j];
            }
            if let Some(tau) = phase.explicit_source {
                a.b[k] += tau[k];
            }
        }
    }
}

/// The face fluxes and conductances of the v control volumes (module doc).
fn v_faces(ctx: &Context<'_>, phase: &PhaseFields<'_>, fluxes: &MassFluxes, faces: &mut FaceData) {
    let grid = ctx.grid;
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let dxc = grid.x.face_spacing();
    let my = ny + 1;
    let mu = phase.viscosity;
    // scalar-cell y-face and x-face mass fluxes ([`MassFluxes`])
    let y_face_flux = |i: usize, j: usize| fluxes.y[i + nx * j];
    let x_face_flux = |i: usize, j: usize| fluxes.x[i + (nx + 1) * j];
    for j in 0..my {
        for i in 1..nx {
            // v-CV x-face at x-face i: halves of the two adjacent rows' u-face fluxes
            if both_skipped(phase.skip, i - 1 + nx * j, i + nx * j) {
                let k = faces.xf(i, j);
                (faces.flux_x[k], faces.cond_x[k]) = (0.0, 0.0);
                continue;
            }
            let (south, north) = (j.checked_sub(1), (j < ny).then_some(j));
            let flux: f64 = [south, north]
                .into_iter()
                .flatten()
                .map(|r| 0.5 * x_face_flux(i, r))
                .sum();
            let mean = phase.viscosity_mean;
            let row = |r: usize| {
                face_mean(
                    mean,
                    mu[i - 1 + nx * r],
                    mu[i + nx * r],
                    grid.x.interpolation_weight(i - 1),
                )
            };
            let mu_corner = match (south, north) {
                (Some(s), Some(n)) => {
                    face_mean(mean, row(s), row(n), grid.y.interpolation_weight(s))
                }
                (Some(r), None) | (None, Some(r)) => row(r),
                (None, None) => 0.0,
            };
            let k = faces.xf(i, j);
            faces.flux_x[k] = flux;
            faces.cond_x[k] = mu_corner * cv_width(dy, j) / dxc[i];
        }
    }
    for j in 1..my {
        for i in 0..nx {
            let k = faces.yf(i, j);
            if both_skipped(phase.skip, i + nx * (j - 1), i + nx * j) {
                (faces.flux_y[k], faces.cond_y[k]) = (0.0, 0.0);
                continue;
            }
            faces.flux_y[k] = 0.5 * (y_face_flux(i, j - 1) + y_face_flux(i, j));
            faces.cond_y[k] = mu[i + nx * (j - 1)] * dx[i] / dy[j - 1];
        }
    }
}

/// The sources of the v equations (walls, transient, gravity, pressure gradients, the
/// explicit stress) and the rows of fixed nodes.
fn v_sources(ctx: &Context<'_>, phase: &PhaseFields<'_>, v_old: &[f64], a: &mut Stencil5) {
    let grid = ctx.grid;
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let my = ny + 1;
    let rho_eps = phase.bulk_density;
    let mu = phase.viscosity;
    let x0 = grid.x.start();
    let (y0, y1) = (grid.y.start(), grid.y.end());
    let xc = grid.x.centres();
    for j in 0..my {
        for i in 0..nx {
            let k = i + nx * j;
            if a.pattern().fixed_mask()[k] {
                fixed_row(a, k, 0.0);
                continue;
            }
            if phase.skip.is_some_and(|s| s[k]) {
                continue;
            }
            let height = cv_width(dy, j);
            let (south, north) = (j.checked_sub(1), (j < ny).then_some(j));
            let half_volume = |r: Option<usize>, field: &[f64]| {
                r.map_or(0.0, |r| 0.5 * dx[i] * dy[r] * field[i + nx * r])
            };
            let mu_wall = |col: usize| -> f64 {
                match (south, north) {
                    (Some(s), Some(n)) => harmonic(
                        mu[col + nx * s],
                        mu[col + nx * n],
                        grid.y.interpolation_weight(s),
                    ),
                    (Some(r), None) | (None, Some(r)) => mu[col + nx * r],
                    (None, None) => 0.0,
                }
            };
            let over = ctx.wall_faces;
            if i == 0 {
                let bc = side_closure(&ctx.bcs.west, over.and_then(|w| w.west.as_ref()), j);
                add_wall_face(a, k, &bc, mu_wall(0), dx[0], height);
            }
            if i == nx - 1 {
                let bc = side_closure(&ctx.bcs.east, over.and_then(|w| w.east.as_ref()), j);
                add_wall_face(a, k, &bc, mu_wall(nx - 1), dx[nx - 1], height);
            }
            let a0 = (half_volume(south, phase.bulk_density_old)
                + half_volume(north, phase.bulk_density_old))
                / ctx.dt;
            a.a_p[k] += a0;
            a.b[k] += a0 * v_old[k];
            let mass = half_volume(south, rho_eps) + half_volume(north, rho_eps);
            match ctx.bent_floor {
                None => a.b[k] += mass * ctx.gravity.1,
                Some(b) => {
                    let u = phase
                        .velocity_along
                        .map_or(0.0, |u| mean_u_at_v_node(u, nx, i, south, north));
                    a.b[k] += mass * (b.force(xc[i], 0.0).1 + b.centrifugal(xc[i], u));
                }
            }
            let eps_face = match (south, north) {
                (Some(_), Some(_)) => interp_y(grid, phase.volume_fraction, i, j),
                (Some(r), None) | (None, Some(r)) => phase.volume_fraction[i + nx * r],
                (None, None) => 0.0,
            };
            let south_point = OutletPoint::on_side((x0, y0), (xc[i], y0), ctx.gravity.0);
            let p_south =
                outlet_pressure(ctx.bent_floor, &ctx.bcs.south, south_point).unwrap_or(0.0);
            let north_point = OutletPoint::on_side((x0, y1), (xc[i], y1), ctx.gravity.0);
            let p_north =
                outlet_pressure(ctx.bent_floor, &ctx.bcs.north, north_point).unwrap_or(0.0);
            let p_s = south.map_or(p_south, |r| ctx.gas_pressure[i + nx * r]);
            let p_n = north.map_or(p_north, |r| ctx.gas_pressure[i + nx * r]);
            a.b[k] += eps_face * (p_s - p_n) * dx[i];
            if let (Some(ps), Some(s), Some(n)) = (phase.solids_pressure, south, north) {
                a.b[k] += (ps[i + nx * s] - ps[i + nx * n]) * dx[i];
            }
            // −(P*_N − P*_S) A, MFIX's SDPS (docs/model.md §4.4, §2.4.1)
            if let (Some(pp), Some(s), Some(n)) = (phase.plastic_pressure, south, north) {
                a.b[k] += (pp[i + nx * s] - pp[i + nx * n]) * dx[i];
            }
            if let Some(tau) = phase.explicit_source {
                a.b[k] += tau[k];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The corner means of a Coulomb viscosity beside a free surface (docs/model.md §2.4.4):
    /// with cell strengths 1 and q, the harmonic mean is 4q/(1 + q)² of the arithmetic one.
    #[test]
    fn face_means_weight_as_stated() {
        let (a, b) = (1.0, 0.1);
        let arithmetic = face_mean(FaceMean::Arithmetic, a, b, 0.5);
        let harmonic_mean = face_mean(FaceMean::Harmonic, a, b, 0.5);
        assert!((arithmetic - 0.55).abs() < 1e-15);
        assert!((harmonic_mean - 2.0 * a * b / (a + b)).abs() < 1e-15);
        assert!((harmonic_mean / arithmetic - 4.0 * b / (1.0 + b).powi(2)).abs() < 1e-15);
        // distance weights: the nearer cell counts more
        assert!((face_mean(FaceMean::Arithmetic, a, b, 0.75) - 0.775).abs() < 1e-15);
        assert_eq!(
            face_mean(FaceMean::Harmonic, 0.3, 0.7, 0.25),
            harmonic(0.3, 0.7, 0.25)
        );
    }
}
