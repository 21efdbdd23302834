//! The granular-energy equation of one solids phase (docs/model.md §1.3, §4.8):
//!
//! (3/2)[∂(εs ρs θ)/∂t + ∇·(εs ρs θ us)] = ∇·(κs ∇θ) + Π − γ − J_vis + J_slip,
//!
//! on the cell-centred grid, in MFIX's continuity-subtracted implicit-Euler form: convection
//! with the flux (3/2)·(solids mass flux) and upwind bulk density; conduction through
//! harmonic face conductivities (§4.1); the transient with the old bulk density; the
//! dissipation γ and the viscous damping J_vis = 3 F_gs θ implicit (γ/θ and 3 F_gs in the
//! diagonal); the production Π = −P_kin tr D + 2 μ_kin tr(D²) + λ_kin (tr D)² split by sign
//! (a negative part goes to the diagonal as a multiple of θ, a positive part to the source);
//! J_slip as a source. Walls close the flux with [`RobinFace`] (docs/model.md §3.2, §3.3, §3.6).

use runout_linsolve::Stencil5;
use runout_mesh::{Grid, Sides};
use runout_walls::RobinFace;

use crate::direction::{Direction, X, Y};
use crate::momentum::WallFaces;
use crate::transport::{assemble_masked, FaceData, Scheme};
use runout_linsolve::for_each_row;

/// Per-cell inputs of the granular-energy equation, evaluated by the caller from the
/// closures at the current iterate (cell index i + nx j).
#[derive(Clone, Copy, Debug)]
pub struct EnergyInputs<'a> {
    /// solids bulk density ρs εs, current [kg m⁻³]
    pub bulk_density: &'a [f64],
    /// solids bulk density at the old time level [kg m⁻³]
    pub bulk_density_old: &'a [f64],
    /// granular conductivity κs [kg m⁻¹ s⁻¹]
    pub conductivity: &'a [f64],
    /// P_kin/θ [kg m⁻³] (the kinetic pressure is linear in θ, docs/model.md §2.2)
    pub p_kin_over_theta: &'a [f64],
    /// μ_kin [Pa s]
    pub mu_kin: &'a [f64],
    /// λ_kin [Pa s]
    pub lambda_kin: &'a [f64],
    /// γ/θ at the current θ [kg m⁻³ s⁻¹]
    pub dissipation_over_theta: &'a [f64],
    /// interphase drag coefficient F_gs [kg m⁻³ s⁻¹] (0 without gas)
    pub drag: &'a [f64],
    /// J_slip, Koch–Sangani slip production [W m⁻³]
    pub slip_production: &'a [f64],
    /// tr D of the solids [s⁻¹]
    pub tr_d: &'a [f64],
    /// tr(D²) of the solids [s⁻²]
    pub tr_d2: &'a [f64],
    /// cells whose rows the caller replaces (the dilute cells of the two-fluid model,
    /// docs/model.md §4.8): their rows are left as they are; `None`: every row
    pub skip: Option<&'a [bool]>,
}

/// Assembles the θ equation (without relaxation) into `a`, given the solids face velocities
/// `u` ((nx+1) × ny) and `v` (nx × (ny+1)), the old θ, the wall closures per side (with
/// per-cell overrides in `wall_cells`, e.g. Johnson–Jackson, docs/model.md §3.6) and Δt.
#[allow(clippy::too_many_arguments)]
pub fn assemble_theta(
    grid: &Grid,
    inputs: &EnergyInputs<'_>,
    walls: &Sides<Option<RobinFace>>,
    wall_cells: Option<&WallFaces>,
    u: &[f64],
    v: &[f64],
    theta_old: &[f64],
    dt: f64,
    scheme: Scheme,
    theta: &[f64],
    faces: &mut FaceData,
    a: &mut Stencil5,
) {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let kappa = inputs.conductivity;
    face_fluxes_and_conductances(grid, inputs, u, v, faces);
    assemble_masked(faces, theta, scheme, inputs.skip, a);
    // the sources of each cell's own row, rows in parallel
    a.par_fill_rows(|j, row| {
        for i in 0..nx {
            let k = i + nx * j;
            if inputs.skip.is_some_and(|s| s[k]) {
                continue;
            }
            let volume = dx[i] * dy[j];
            // wall faces: θ closure with the fluid cell's conductivity (docs/model.md §3.1)
            let cell_face =
                |side: &Option<RobinFace>, over: Option<&Vec<RobinFace>>, pos: usize| {
                    over.map(|f| f[pos]).or(*side)
                };
            let over = wall_cells;
            for (present, face, delta, area) in [
                (
                    i == 0,
                    cell_face(&walls.west, over.and_then(|w| w.west.as_ref()), j),
                    dx[i],
                    dy[j],
                ),
                (
                    i == nx - 1,
                    cell_face(&walls.east, over.and_then(|w| w.east.as_ref()), j),
                    dx[i],
                    dy[j],
                ),
                (
                    j == 0,
                    cell_face(&walls.south, over.and_then(|w| w.south.as_ref()), i),
                    dy[j],
                    dx[i],
                ),
                (
                    j == ny - 1,
                    cell_face(&walls.north, over.and_then(|w| w.north.as_ref()), i),
                    dy[j],
                    dx[i],
                ),
            ] {
                if let (true, Some(face)) = (present, face) {
                    let (ap, b) = face.implicit_parts(kappa[k], delta);
                    row.a_p[i] += ap * area;
                    row.b[i] += b * area;
                }
            }
            // transient with the old bulk density (docs/model.md §1.3, §4.3)
            let a0 = 1.5 * inputs.bulk_density_old[k] * volume / dt;
            row.a_p[i] += a0;
            row.b[i] += a0 * theta_old[k];
            // dissipation and viscous damping, implicit
            row.a_p[i] += (inputs.dissipation_over_theta[k] + 3.0 * inputs.drag[k]) * volume;
            // production split by sign (docs/model.md §4.8)
            let tr_d = inputs.tr_d[k];
            let compression = -inputs.p_kin_over_theta[k] * tr_d; // coefficient of θ in −P_kin tr D
            if compression >= 0.0 {
                row.b[i] += compression * theta[k] * volume;
            } else {
                row.a_p[i] += -compression * volume;
            }
            let bulk = inputs.lambda_kin[k] * tr_d * tr_d;
            if bulk >= 0.0 {
                row.b[i] += bulk * volume;
            } else {
                row.a_p[i] += -bulk / theta[k].max(runout_closures::guards::THETA_SMALL) * volume;
            }
            row.b[i] +=
                (2.0 * inputs.mu_kin[k] * inputs.tr_d2[k] + inputs.slip_production[k]) * volume;
        }
    });
}

/// The θ convection flux (3/2)·(solids mass flux, upwind bulk density) and the harmonic
/// face conductance of every interior face (docs/model.md §4.1, §4.8), rows in parallel
/// (each face's value is its own).
fn face_fluxes_and_conductances(
    grid: &Grid,
    inputs: &EnergyInputs<'_>,
    u: &[f64],
    v: &[f64],
    faces: &mut FaceData,
) {
    theta_faces::<X>(grid, inputs, u, faces);
    theta_faces::<Y>(grid, inputs, v, faces);
}

/// [`face_fluxes_and_conductances`] of the interior faces normal to direction `D`, with
/// the solids velocity `phi` on them: face (a, b) between cells a − 1 and a.
fn theta_faces<D: Direction>(
    grid: &Grid,
    inputs: &EnergyInputs<'_>,
    phi: &[f64],
    faces: &mut FaceData,
) {
    let nx = grid.nx();
    let (along, mx) = (D::along(grid), D::row_len(nx));
    let (n_a, spacing, d_b) = (along.len(), along.face_spacing(), D::across(grid).widths());
    let rho_eps = inputs.bulk_density;
    let kappa = inputs.conductivity;
    let harmonic = |a: f64, b: f64, w: f64| a * b / (w * a + (1.0 - w) * b).max(1e-15);
    let upwind =
        |vel: f64, lo: usize, hi: usize| if vel >= 0.0 { rho_eps[lo] } else { rho_eps[hi] };
    // (b, cell a − 1, cell a) of the face at (i, j); `None` on the domain ends
    let interior = |i: usize, j: usize| {
        let (a, b) = D::ab(i, j);
        (a > 0 && a < n_a).then(|| (a, b, D::cell(a - 1, b, nx), D::cell(a, b, nx)))
    };
    let (flux, cond) = D::along_faces(faces);
    for_each_row(flux, mx, |j, row| {
        for (i, flux) in row.iter_mut().enumerate() {
            if let Some((_, b, lo, hi)) = interior(i, j) {
                let vel = phi[i + mx * j];
                *flux = 1.5 * upwind(vel, lo, hi) * vel * d_b[b];
            }
        }
    });
    for_each_row(cond, mx, |j, row| {
        for (i, cond) in row.iter_mut().enumerate() {
            if let Some((a, b, lo, hi)) = interior(i, j) {
                *cond = harmonic(kappa[lo], kappa[hi], along.interpolation_weight(a - 1)) * d_b[b]
                    / spacing[a];
            }
        }
    });
}
