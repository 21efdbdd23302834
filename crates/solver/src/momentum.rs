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

use std::marker::PhantomData;

use runout_closures::FaceMean;
use runout_linsolve::{RowMut, Stencil5};
use runout_mesh::{Grid, Sides};
use runout_walls::RobinFace;

use crate::bent_floor::BentFloor;
use crate::direction::{Direction, X, Y};
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

impl WallFaces {
    /// The per-node closures of each side, `None` where the side's [`SideBc`] holds.
    fn sides(&self) -> Sides<Option<&Vec<RobinFace>>> {
        Sides {
            west: self.west.as_ref(),
            east: self.east.as_ref(),
            south: self.south.as_ref(),
            north: self.north.as_ref(),
        }
    }
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
/// u and v are one equation, written once in the component's own coordinates
/// (`control_volume_faces`, `sources`) and compiled once per direction (`Direction`,
/// direction.rs).
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
    let phi = c.pick(u, v);
    if c.dir == 0 {
        control_volume_faces::<X>(ctx, phase, fluxes, faces);
        assemble_masked(faces, phi, ctx.scheme, phase.skip, a);
        sources::<X>(ctx, phase, old, a);
    } else {
        control_volume_faces::<Y>(ctx, phase, fluxes, faces);
        assemble_masked(faces, phi, ctx.scheme, phase.skip, a);
        sources::<Y>(ctx, phase, old, a);
    }
    if ctx.form == MomentumForm::Conservative && ctx.dt.is_finite() {
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
    out.x.resize((nx + 1) * ny, 0.0);
    out.y.resize(nx * (ny + 1), 0.0);
    face_mass_fluxes::<X>(grid, scheme, rho_eps, u, &mut out.x);
    face_mass_fluxes::<Y>(grid, scheme, rho_eps, v, &mut out.y);
}

/// [`mass_fluxes`] through the faces normal to direction `D`, of the velocity `phi` on
/// them: on face (a, b) ρε of the scheme between cells a − 1 and a, the inside cell's at an
/// end, times φ and the face area.
fn face_mass_fluxes<D: Direction>(
    grid: &Grid,
    scheme: Scheme,
    rho_eps: &[f64],
    phi: &[f64],
    out: &mut [f64],
) {
    let nx = grid.nx();
    let (n_a, n_b) = (D::along(grid).len(), D::across(grid).len());
    let d_b = D::across(grid).widths();
    let cell = |c: usize, b: usize| D::cell(c, b, nx);
    D::for_each(0..n_a + 1, 0..n_b, |a, b| {
        let k = D::node(a, b, nx);
        let vel = phi[k];
        let re = if a == 0 {
            rho_eps[cell(0, b)]
        } else if a == n_a {
            rho_eps[cell(n_a - 1, b)]
        } else {
            face_value(
                scheme,
                rho_eps,
                (a >= 2).then(|| cell(a - 2, b)),
                cell(a - 1, b),
                cell(a, b),
                (a + 1 < n_a).then(|| cell(a + 1, b)),
                vel,
            )
        };
        out[k] = re * vel * d_b[b];
    });
}

/// The nodes of component `D` on a grid: the cells beside each node, the distance weights
/// between them and the widths of the control volumes (a periodic column's node 0 lies
/// between cell nx − 1 and cell 0 and spans a whole cell).
struct Nodes<'a, D> {
    grid: &'a Grid,
    periodic: bool,
    direction: PhantomData<D>,
}

impl<'a, D: Direction> Nodes<'a, D> {
    #[inline]
    fn of(grid: &'a Grid) -> Self {
        Nodes {
            grid,
            periodic: D::periodic(grid),
            direction: PhantomData,
        }
    }

    /// The cells before and after node a along the direction: one at an end, unless the
    /// column is periodic, where node 0 lies between cell nx − 1 (= 0) and cell 0.
    #[inline]
    fn cells_beside(&self, a: usize) -> (Option<usize>, Option<usize>) {
        let n = D::along(self.grid).len();
        if self.periodic && a == 0 {
            (Some(n - 1), Some(0))
        } else {
            (a.checked_sub(1), (a < n).then_some(a))
        }
    }

    /// Distance weight of cell `lo` at the face between cells `lo` and `hi` (½ across the
    /// wrap).
    #[inline]
    fn weight(&self, lo: usize, hi: usize) -> f64 {
        if lo < hi {
            D::along(self.grid).interpolation_weight(lo)
        } else {
            0.5
        }
    }

    /// Width of the control volume of node a: the whole cell for a periodic column's node 0.
    #[inline]
    fn width(&self, a: usize) -> f64 {
        let widths = D::along(self.grid).widths();
        if self.periodic && a == 0 {
            0.5 * (widths[widths.len() - 1] + widths[0])
        } else {
            cv_width(widths, a)
        }
    }
}

/// The face fluxes and conductances of component `D`'s control volumes (module doc).
fn control_volume_faces<D: Direction>(
    ctx: &Context<'_>,
    phase: &PhaseFields<'_>,
    fluxes: &MassFluxes,
    faces: &mut FaceData,
) {
    let grid = ctx.grid;
    let nx = grid.nx();
    let (n_a, n_b) = (D::along(grid).len(), D::across(grid).len());
    let (d_a, d_b) = (D::along(grid).widths(), D::across(grid).widths());
    let across_spacing = D::across(grid).face_spacing();
    let mu = phase.viscosity;
    let nodes = Nodes::<D>::of(grid);
    // scalar-cell mass fluxes normal to the direction at node (a, b), and across it at the
    // face b of cell a ([`MassFluxes`])
    let (along_flux, across_flux) = D::mass_fluxes(fluxes);
    let along_flux = |a: usize, b: usize| along_flux[D::node(a, b, nx)];
    let across_flux = |a: usize, b: usize| across_flux[D::cross_node(a, b, nx)];
    D::for_each(1..n_a + 1, 0..n_b, |a, b| {
        // the face through cell centre a − 1, between nodes a − 1 and a
        let k = D::along_face(faces, a, b);
        let (flux, cond) = D::along_faces(faces);
        // periodic column: the face couples node 0 to its own copy, and its flux and
        // diffusion cancel those of the wrapped face on the other side
        if nodes.periodic || both_skipped(phase.skip, D::node(a - 1, b, nx), D::node(a, b, nx)) {
            (flux[k], cond[k]) = (0.0, 0.0);
            return;
        }
        flux[k] = 0.5 * (along_flux(a - 1, b) + along_flux(a, b));
        cond[k] = mu[D::cell(a - 1, b, nx)] * d_b[b] / d_a[a - 1];
    });
    D::for_each(0..n_a + 1, 1..n_b, |a, b| {
        // the face between nodes (a, b − 1) and (a, b): halves of the fluxes of the cells
        // beside the node
        let k = D::across_face(faces, a, b);
        let (flux, cond) = D::across_faces(faces);
        if both_skipped(phase.skip, D::node(a, b - 1, nx), D::node(a, b, nx)) {
            (flux[k], cond[k]) = (0.0, 0.0);
            return;
        }
        let (lo, hi) = nodes.cells_beside(a);
        flux[k] = [lo, hi]
            .into_iter()
            .flatten()
            .map(|c| 0.5 * across_flux(c, b))
            .sum();
        // viscosity at the corner: harmonic (μ(I): arithmetic) across, then along (MFIX
        // AVG_X_H of AVG_Y_H for u, AVG_Y_H of AVG_X_H for v; docs/model.md §4.1)
        let mean = phase.viscosity_mean;
        let line = |c: usize| {
            face_mean(
                mean,
                mu[D::cell(c, b - 1, nx)],
                mu[D::cell(c, b, nx)],
                D::across(grid).interpolation_weight(b - 1),
            )
        };
        let mu_corner = match (lo, hi) {
            (Some(l), Some(h)) => face_mean(mean, line(l), line(h), nodes.weight(l, h)),
            (Some(c), None) | (None, Some(c)) => line(c),
            (None, None) => 0.0,
        };
        cond[k] = mu_corner * nodes.width(a) / across_spacing[b];
    });
}

/// The body force per unit mass at node (a, b) between cells `lo` and `hi` along the
/// direction: gravity's component, or a bent floor's field, whose v equations gain the
/// centrifugal force of the phase's u (docs/model.md §9).
fn body_force<D: Direction>(
    ctx: &Context<'_>,
    phase: &PhaseFields<'_>,
    a: usize,
    b: usize,
    (lo, hi): (Option<usize>, Option<usize>),
) -> f64 {
    let grid = ctx.grid;
    let Some(floor) = ctx.bent_floor else {
        return D::pick(ctx.gravity.0, ctx.gravity.1);
    };
    let (xc, yc) = (grid.x.centres(), grid.y.centres());
    if D::DIR == 0 {
        match (lo, hi) {
            (Some(w), Some(e)) => floor.force_x_between(xc[w], xc[e], yc[b]),
            _ => floor.force(grid.x.faces()[a], yc[b]).0,
        }
    } else {
        let u = phase
            .velocity_along
            .map_or(0.0, |u| mean_u_at_v_node(u, grid.nx(), b, lo, hi));
        floor.force(xc[b], 0.0).1 + floor.centrifugal(xc[b], u)
    }
}

/// The gas pressure an outlet at the `high` (else low) end of component `D`'s line b holds
/// (docs/model.md §4.1, §9); 0 at a wall.
fn end_pressure<D: Direction>(ctx: &Context<'_>, b: usize, high: bool) -> f64 {
    let (along, across) = (D::along(ctx.grid), D::across(ctx.grid));
    let (low_end, high_end) = D::ends(ctx.bcs);
    let (bc, a_end) = if high {
        (high_end, along.end())
    } else {
        (low_end, along.start())
    };
    let corner = D::pick((a_end, across.start()), (across.start(), a_end));
    let point = D::pick((a_end, across.centres()[b]), (across.centres()[b], a_end));
    let g_across = D::pick(ctx.gravity.1, ctx.gravity.0);
    let at = OutletPoint::on_side(corner, point, g_across);
    outlet_pressure(ctx.bent_floor, bc, at).unwrap_or(0.0)
}

/// The sources of component `D`'s equations (walls, transient, gravity, pressure
/// gradients, the explicit stress) and the rows of fixed nodes.
fn sources<D: Direction>(
    ctx: &Context<'_>,
    phase: &PhaseFields<'_>,
    old: &[f64],
    a: &mut Stencil5,
) {
    let grid = ctx.grid;
    let nx = grid.nx();
    let (n_a, n_b) = (D::along(grid).len(), D::across(grid).len());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let d_b = D::across(grid).widths();
    let (rho_eps, mu, eps) = (phase.bulk_density, phase.viscosity, phase.volume_fraction);
    let nodes = Nodes::<D>::of(grid);
    let cell = |c: usize, b: usize| D::cell(c, b, nx);
    let over = ctx.wall_faces.map_or(Sides::all(None), WallFaces::sides);
    let (low_wall, high_wall) = D::walls(ctx.bcs);
    let (low_faces, high_faces) = D::walls(&over);
    D::for_each(0..n_a + 1, 0..n_b, |a_node, b| {
        let k = D::node(a_node, b, nx);
        if a.pattern().fixed_mask()[k] {
            fixed_row(a, k, 0.0);
            return;
        }
        if phase.skip.is_some_and(|s| s[k]) {
            return;
        }
        let width = nodes.width(a_node);
        // cells on either side along the component (the inside cell only at an outlet end)
        let (lo, hi) = nodes.cells_beside(a_node);
        let half_volume = |c: Option<usize>, field: &[f64]| {
            c.map_or(0.0, |c| {
                let (i, j) = D::xy(c, b);
                0.5 * dx[i] * dy[j] * field[i + nx * j]
            })
        };
        // walls across the line: the fluid cells' viscosity (docs/model.md §3.1)
        let mu_wall = |row: usize| -> f64 {
            match (lo, hi) {
                (Some(l), Some(h)) => {
                    harmonic(mu[cell(l, row)], mu[cell(h, row)], nodes.weight(l, h))
                }
                (Some(c), None) | (None, Some(c)) => mu[cell(c, row)],
                (None, None) => 0.0,
            }
        };
        if b == 0 {
            let bc = side_closure(low_wall, *low_faces, a_node);
            add_wall_face(a, k, &bc, mu_wall(0), d_b[0], width);
        }
        if b == n_b - 1 {
            let bc = side_closure(high_wall, *high_faces, a_node);
            add_wall_face(a, k, &bc, mu_wall(n_b - 1), d_b[n_b - 1], width);
        }
        // transient (implicit Euler, docs/model.md §4.3–4.4)
        let a0 = (half_volume(lo, phase.bulk_density_old)
            + half_volume(hi, phase.bulk_density_old))
            / ctx.dt;
        a.a_p[k] += a0;
        a.b[k] += a0 * old[k];
        // body force with the current bulk density
        let mass = half_volume(lo, rho_eps) + half_volume(hi, rho_eps);
        a.b[k] += mass * body_force::<D>(ctx, phase, a_node, b, (lo, hi));
        // gas pressure, −ε̄ ΔP A (ε̄ distance-interpolated, AVG_X / AVG_Y); solids pressure,
        // −ΔP_s A
        let eps_face = match (lo, hi) {
            // across a periodic wrap
            (Some(l), Some(h)) if l >= h => 0.5 * (eps[cell(l, b)] + eps[cell(h, b)]),
            (Some(l), Some(h)) => {
                let w = D::along(grid).interpolation_weight(l);
                w * eps[cell(l, b)] + (1.0 - w) * eps[cell(h, b)]
            }
            (Some(c), None) | (None, Some(c)) => eps[cell(c, b)],
            (None, None) => 0.0,
        };
        let p_lo = lo.map_or_else(
            || end_pressure::<D>(ctx, b, false),
            |c| ctx.gas_pressure[cell(c, b)],
        );
        let p_hi = hi.map_or_else(
            || end_pressure::<D>(ctx, b, true),
            |c| ctx.gas_pressure[cell(c, b)],
        );
        a.b[k] += eps_face * (p_lo - p_hi) * d_b[b];
        if let (Some(ps), Some(l), Some(h)) = (phase.solids_pressure, lo, hi) {
            a.b[k] += (ps[cell(l, b)] - ps[cell(h, b)]) * d_b[b];
        }
        // −ΔP* A, MFIX's SDPS (docs/model.md §4.4, §2.4.1)
        if let (Some(pp), Some(l), Some(h)) = (phase.plastic_pressure, lo, hi) {
            a.b[k] += (pp[cell(l, b)] - pp[cell(h, b)]) * d_b[b];
        }
        if let Some(tau) = phase.explicit_source {
            a.b[k] += tau[k];
        }
    });
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
