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

use runout_linsolve::Stencil5;
use runout_mesh::{Grid, Side, Sides};
use runout_walls::RobinFace;

use crate::single_phase::SideBc;
use crate::staggered::Component;
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
    /// The per-node closures of `side`, if given.
    pub fn side(&self, side: Side) -> Option<&Vec<RobinFace>> {
        match side {
            Side::West => self.west.as_ref(),
            Side::East => self.east.as_ref(),
            Side::South => self.south.as_ref(),
            Side::North => self.north.as_ref(),
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
    /// time step [s] (`f64::INFINITY` for a steady iteration)
    pub dt: f64,
    /// convection scheme
    pub scheme: Scheme,
    /// gas pressure at cell centres [Pa]
    pub gas_pressure: &'a [f64],
    /// per-node wall closures overriding `bcs` on the sides they cover
    pub wall_faces: Option<&'a WallFaces>,
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

/// Σ a_nb φ_nb + b of row k: the right-hand side with the current neighbour values (used
/// for residuals, docs/model.md §4.11, and the partial elimination, §4.5).
pub(crate) fn neighbour_sum(a: &Stencil5, phi: &[f64], k: usize) -> f64 {
    let nx = a.pattern().nx();
    let mut r = a.b[k];
    if a.a_e[k] != 0.0 {
        r += a.a_e[k] * phi[k + 1];
    }
    if a.a_w[k] != 0.0 {
        r += a.a_w[k] * phi[k - 1];
    }
    if a.a_n[k] != 0.0 {
        r += a.a_n[k] * phi[k + nx];
    }
    if a.a_s[k] != 0.0 {
        r += a.a_s[k] * phi[k - nx];
    }
    r
}

/// Makes row k read φ = `value` with no neighbour links.
pub(crate) fn fixed_row(a: &mut Stencil5, k: usize, value: f64) {
    a.a_p[k] = 1.0;
    a.b[k] = value;
    a.a_e[k] = 0.0;
    a.a_w[k] = 0.0;
    a.a_n[k] = 0.0;
    a.a_s[k] = 0.0;
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
/// without relaxation (module doc): u on the (nx+1) × ny x-faces, v on the nx × (ny+1)
/// y-faces. `old` is the component's velocity at the old time level. Rows of fixed nodes
/// (wall normal velocities) read 0.
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
    // one compiled copy per direction, so that the index arithmetic of the component view
    // folds to that of u or v (as fast as the hand-written u and v assemblies were)
    if c.dir == 0 {
        control_volume_faces::<0>(ctx, phase, c, u, v, faces);
    } else {
        control_volume_faces::<1>(ctx, phase, c, u, v, faces);
    }
    assemble_masked(faces, c.pick(u, v), ctx.scheme, phase.skip, a);
    if c.dir == 0 {
        sources::<0>(ctx, phase, c, old, a);
    } else {
        sources::<1>(ctx, phase, c, old, a);
    }
}

/// The face fluxes and conductances of component `c`'s control volumes (module doc), in
/// the component's coordinates (a along, b across; [`Component`]); `DIR` is `c.dir`.
fn control_volume_faces<const DIR: usize>(
    ctx: &Context<'_>,
    phase: &PhaseFields<'_>,
    c: Component,
    u: &[f64],
    v: &[f64],
    faces: &mut FaceData,
) {
    let c = Component { dir: DIR, ..c };
    let grid = ctx.grid;
    let (n_a, n_b) = c.cells_along_across();
    let (along, across) = (c.axis(grid), c.across_axis(grid));
    let (d_a, d_b) = (along.widths(), across.widths());
    let across_spacing = across.face_spacing();
    let (rho_eps, mu) = (phase.bulk_density, phase.viscosity);
    let (own, other) = c.pick((u, v), (v, u));
    // scalar-cell face mass flux at the component's node (a, b), ρε from the scheme (at a
    // domain end, where only an outlet has a flux, the inside cell supplies ρε)
    let along_face_flux = |a: usize, b: usize| -> f64 {
        let vel = own[c.node(a, b)];
        let re = if a == 0 {
            rho_eps[c.cell(0, b)]
        } else if a == n_a {
            rho_eps[c.cell(n_a - 1, b)]
        } else {
            face_value(
                ctx.scheme,
                rho_eps,
                (a >= 2).then(|| c.cell(a - 2, b)),
                c.cell(a - 1, b),
                c.cell(a, b),
                (a + 1 < n_a).then(|| c.cell(a + 1, b)),
                vel,
            )
        };
        re * vel * d_b[b]
    };
    // scalar-cell face mass flux at the other component's node (a, b), 1 ≤ b < n_b
    let across_face_flux = |a: usize, b: usize| -> f64 {
        let vel = other[c.cross_node(a, b)];
        face_value(
            ctx.scheme,
            rho_eps,
            (b >= 2).then(|| c.cell(a, b - 2)),
            c.cell(a, b - 1),
            c.cell(a, b),
            (b + 1 < n_b).then(|| c.cell(a, b + 1)),
            vel,
        ) * vel
            * d_a[a]
    };
    for b in 0..n_b {
        for a in 1..=n_a {
            // the face through cell centre a − 1, between nodes a − 1 and a
            let k = c.along_face(faces, a, b);
            let (flux, cond) = c.pick(
                (&mut faces.flux_x, &mut faces.cond_x),
                (&mut faces.flux_y, &mut faces.cond_y),
            );
            // periodic column: the face couples node 0 to its own copy, and its flux and
            // diffusion cancel those of the wrapped face on the other side
            if c.periodic || both_skipped(phase.skip, c.node(a - 1, b), c.node(a, b)) {
                (flux[k], cond[k]) = (0.0, 0.0);
                continue;
            }
            flux[k] = 0.5 * (along_face_flux(a - 1, b) + along_face_flux(a, b));
            cond[k] = mu[c.cell(a - 1, b)] * d_b[b] / d_a[a - 1];
        }
    }
    for b in 1..n_b {
        for a in 0..=n_a {
            // the face between nodes (a, b − 1) and (a, b): halves of the fluxes of the
            // cells beside the node
            let k = c.across_face(faces, a, b);
            let (flux, cond) = c.pick(
                (&mut faces.flux_y, &mut faces.cond_y),
                (&mut faces.flux_x, &mut faces.cond_x),
            );
            if both_skipped(phase.skip, c.node(a, b - 1), c.node(a, b)) {
                (flux[k], cond[k]) = (0.0, 0.0);
                continue;
            }
            let (lo, hi) = c.cells_beside(a);
            flux[k] = [lo, hi]
                .into_iter()
                .flatten()
                .map(|ca| 0.5 * across_face_flux(ca, b))
                .sum();
            // viscosity at the corner: harmonic across, then along (MFIX AVG_X_H of AVG_Y_H
            // for u, AVG_Y_H of AVG_X_H for v; docs/model.md §4.1)
            let line = |ca: usize| {
                harmonic(
                    mu[c.cell(ca, b - 1)],
                    mu[c.cell(ca, b)],
                    across.interpolation_weight(b - 1),
                )
            };
            let mu_corner = match (lo, hi) {
                (Some(l), Some(h)) => harmonic(line(l), line(h), c.along_weight(grid, l, h)),
                (Some(x), None) | (None, Some(x)) => line(x),
                (None, None) => 0.0,
            };
            cond[k] = mu_corner * c.control_width(grid, a) / across_spacing[b];
        }
    }
}

/// The sources of component `c`'s equations (walls, transient, gravity, pressure
/// gradients, the explicit stress) and the rows of fixed nodes; `DIR` is `c.dir`.
fn sources<const DIR: usize>(
    ctx: &Context<'_>,
    phase: &PhaseFields<'_>,
    c: Component,
    old: &[f64],
    a: &mut Stencil5,
) {
    let c = Component { dir: DIR, ..c };
    let grid = ctx.grid;
    let (n_a, n_b) = c.cells_along_across();
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let (along, across) = (c.axis(grid), c.across_axis(grid));
    let d_b = across.widths();
    let (rho_eps, mu, eps) = (phase.bulk_density, phase.viscosity, phase.volume_fraction);
    let (g_along, g_across) = c.pick(ctx.gravity, (ctx.gravity.1, ctx.gravity.0));
    let (low_end, high_end) = c.end_sides();
    let (low_wall, high_wall) = c.wall_sides();
    let wall_closure = |side: Side, a: usize| {
        side_closure(
            ctx.bcs.get(side),
            ctx.wall_faces.and_then(|w| w.side(side)),
            a,
        )
    };
    for b in 0..n_b {
        // the pressure an outlet end holds at this line's height
        let end_pressure = |side: Side| {
            let position = across.centres()[b] - across.start();
            ctx.bcs
                .get(side)
                .pressure(position, g_across)
                .unwrap_or(0.0)
        };
        let (p_low_end, p_high_end) = (end_pressure(low_end), end_pressure(high_end));
        for a_node in 0..=n_a {
            let k = c.node(a_node, b);
            if a.pattern().fixed_mask()[k] {
                fixed_row(a, k, 0.0);
                continue;
            }
            if phase.skip.is_some_and(|s| s[k]) {
                continue;
            }
            let width = c.control_width(grid, a_node);
            // cells on either side along the component (one at an outlet end)
            let (lo, hi) = c.cells_beside(a_node);
            let half_volume = |ca: Option<usize>, field: &[f64]| {
                ca.map_or(0.0, |ca| {
                    let (i, j) = c.xy(ca, b);
                    0.5 * dx[i] * dy[j] * field[c.cell(ca, b)]
                })
            };
            // walls across the line: the fluid cells' viscosity (docs/model.md §3.1)
            let mu_wall = |row: usize| -> f64 {
                match (lo, hi) {
                    (Some(l), Some(h)) => harmonic(
                        mu[c.cell(l, row)],
                        mu[c.cell(h, row)],
                        c.along_weight(grid, l, h),
                    ),
                    (Some(x), None) | (None, Some(x)) => mu[c.cell(x, row)],
                    (None, None) => 0.0,
                }
            };
            if b == 0 {
                let bc = wall_closure(low_wall, a_node);
                add_wall_face(a, k, &bc, mu_wall(0), d_b[0], width);
            }
            if b == n_b - 1 {
                let bc = wall_closure(high_wall, a_node);
                add_wall_face(a, k, &bc, mu_wall(n_b - 1), d_b[n_b - 1], width);
            }
            // transient (implicit Euler, docs/model.md §4.3–4.4)
            let a0 = (half_volume(lo, phase.bulk_density_old)
                + half_volume(hi, phase.bulk_density_old))
                / ctx.dt;
            a.a_p[k] += a0;
            a.b[k] += a0 * old[k];
            // body force with the current bulk density
            a.b[k] += (half_volume(lo, rho_eps) + half_volume(hi, rho_eps)) * g_along;
            // gas pressure, −ε̄ ΔP A (ε̄ distance-interpolated, AVG_X / AVG_Y)
            let eps_face = match (lo, hi) {
                // across a periodic wrap
                (Some(l), Some(h)) if l >= h => 0.5 * (eps[c.cell(l, b)] + eps[c.cell(h, b)]),
                (Some(l), Some(h)) => {
                    let w = along.interpolation_weight(l);
                    w * eps[c.cell(l, b)] + (1.0 - w) * eps[c.cell(h, b)]
                }
                (Some(x), None) | (None, Some(x)) => eps[c.cell(x, b)],
                (None, None) => 0.0,
            };
            let p_lo = lo.map_or(p_low_end, |x| ctx.gas_pressure[c.cell(x, b)]);
            let p_hi = hi.map_or(p_high_end, |x| ctx.gas_pressure[c.cell(x, b)]);
            a.b[k] += eps_face * (p_lo - p_hi) * d_b[b];
            // solids pressure, −ΔP_s A
            if let (Some(ps), Some(l), Some(h)) = (phase.solids_pressure, lo, hi) {
                a.b[k] += (ps[c.cell(l, b)] - ps[c.cell(h, b)]) * d_b[b];
            }
            // −ΔP* A, MFIX's SDPS (docs/model.md §4.4, §2.4.1)
            if let (Some(pp), Some(l), Some(h)) = (phase.plastic_pressure, lo, hi) {
                a.b[k] += (pp[c.cell(l, b)] - pp[c.cell(h, b)]) * d_b[b];
            }
            if let Some(tau) = phase.explicit_source {
                a.b[k] += tau[k];
            }
        }
    }
}
