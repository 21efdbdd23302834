//! The form of the momentum equations' transient and convection terms (docs/model.md §4.3):
//! MFIX's continuity-subtracted form, or the conservative form, which adds back the control
//! volume's continuity remainder r φ_P that the subtracted form drops.

use runout_linsolve::Stencil5;
use runout_mesh::Grid;

use crate::momentum::PhaseFields;
use crate::staggered::Component;
use crate::transport::FaceData;

/// The form of the transient and convection terms of the momentum equations (docs/model.md
/// §4.3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MomentumForm {
    /// MFIX's continuity-subtracted form ([NUM] §3.2): a_P = Σ a_nb + a_P⁰, the momentum
    /// cell's continuity taken as satisfied
    #[default]
    ContinuitySubtracted,
    /// the conservative form: the continuity-subtracted one plus r φ_P
    /// ([`add_continuity_remainder`])
    Conservative,
}

/// Turns a continuity-subtracted row into the conservative one (docs/model.md §4.3).
///
/// The conservative discrete momentum balance of a control volume with mass m (½ V ρε of
/// each cell it spans) and face mass fluxes F (upwind face values φ_f) is
///
///   (m φ_P − m⁰ φ_P⁰)/Δt + Σ_f F_f φ_f = S.
///
/// Subtracting φ_P times the control volume's continuity remainder
/// r = (m − m⁰)/Δt + Σ_f F_f gives the continuity-subtracted form that MFIX assembles,
/// m⁰ (φ_P − φ_P⁰)/Δt + Σ_f F_f (φ_f − φ_P) = S, whose a_P = Σ a_nb + m⁰/Δt. The two agree
/// only where continuity holds; where the outer iterations leave r ≠ 0, Σ_P r φ_P is a
/// momentum the subtracted form creates (its sum over a sheared block does not vanish,
/// docs/model.md §3.11). This adds r φ_P back: implicitly (a_P += r) where r > 0, with
/// the current φ_P on the right-hand side where r < 0, so that a_P never drops below
/// Σ a_nb + a_P⁰ and the converged row is the conservative balance.
pub(crate) fn add_continuity_remainder(
    grid: &Grid,
    phase: &PhaseFields<'_>,
    c: Component,
    phi: &[f64],
    faces: &FaceData,
    dt: f64,
    a: &mut Stencil5,
) {
    let nx = grid.nx();
    // periodic as the grid is, like the rest of the assembly
    let c = Component {
        periodic: c.dir == 0 && grid.periodic_x(),
        ..c
    };
    let (mx, my) = (faces.mx, faces.my);
    for j in 0..my {
        for i in 0..mx {
            let k = i + mx * j;
            if a.pattern().fixed_mask()[k] || phase.skip.is_some_and(|s| s[k]) {
                continue;
            }
            // the cells whose halves make up the control volume
            let cells = c.cells(i, j, true);
            let mass = |rho_eps: &[f64]| -> f64 {
                cells
                    .iter()
                    .flatten()
                    .map(|&(ci, cj)| 0.5 * grid.cell_volume(ci, cj) * rho_eps[ci + nx * cj])
                    .sum()
            };
            let storage = (mass(phase.bulk_density) - mass(phase.bulk_density_old)) / dt;
            let (w, e) = (faces.xf(i, j), faces.xf(i + 1, j));
            let (s, n) = (faces.yf(i, j), faces.yf(i, j + 1));
            let net_outflow = faces.flux_x[e] - faces.flux_x[w] + faces.flux_y[n] - faces.flux_y[s];
            let remainder = storage + net_outflow;
            if remainder > 0.0 {
                a.a_p[k] += remainder;
            } else {
                a.b[k] -= remainder * phi[k];
            }
        }
    }
}
