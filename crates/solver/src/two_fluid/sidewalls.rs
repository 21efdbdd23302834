//! Friction of the two side walls of a quasi-2-D channel (docs/model.md §8; not in MFIX).
//!
//! A 2-D slice of a channel of width W leaves out its two side walls, both parallel to the
//! slice. Averaged over the width, with the solids profile across it flat, their stress acts
//! on every cell as a volumetric sink −(2/W) τ_w in the solids momentum (u and v both lie in
//! the walls' plane), τ_w = K u_s from the floor's wall models (runout-walls) evaluated with
//! the cell's own state (the walls are at rest, so the slip is the cell's velocity):
//! - free slip: K = 0;
//! - user partial slip (docs/model.md §3.3): K = μ_s h_w^u;
//! - Johnson–Jackson, revisited JJ, Jenkins (§3.5, §3.7, §3.8): K = COL (+ FRI on the
//!   frictional branch), the model's stress per unit slip (h_w^u (μ_k + μ_f) of MFIX's rule);
//! - no slip: a flat profile cannot meet it; its parabolic limit K = 6 μ_s/W.
//!
//! The granular energy gains the walls' flux (2/W) q_w, q_w = c_θ − h_θ θ (JJ: generation by
//! slip minus collisional dissipation; Jenkins likewise; user: κ_s (c − h_θ θ) in MFIX's
//! manual units). Both are implicit: (2/W) K V on the diagonal of each u/v row, (2/W) h_θ V
//! on the diagonal of each θ row and (2/W) c_θ V in its source, with K, h_θ, c_θ lagged one
//! outer iteration, as the floor's closures are. A gas no-slip wall adds the width-averaged
//! plane-Poiseuille drag 12 μ_g/W² (docs/model.md §8).

use runout_closures::ClosureParams;
use runout_mesh::Grid;
use runout_walls::{MomentumWallState, SolidsWallModel, ThetaWallState};

use super::momentum_pea::SolidsComponent;
use super::wall_load::side_wall_extra_load;
use super::{PhaseCoefficients, SolidsSpec, State};
use crate::staggered::Component;

/// Largest K [Pa s m⁻¹]: Jenkins' COL = tan δ_w P_k/|u_s| overflows as |u_s| → 0; far below
/// this bound a cell's velocity is already zero to rounding.
const MAX_STRESS_PER_SLIP: f64 = 1e30;

/// The side walls of a quasi-2-D channel (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sidewalls {
    /// channel width W between the walls [m]; `f64::INFINITY` is the plane limit (no term)
    pub width: f64,
    /// the solids condition on both walls (at rest)
    pub solids: SolidsWallModel,
    /// the gas sticks to the walls (plane-Poiseuille drag); else it slips freely
    pub gas_no_slip: bool,
}

/// What the side-wall terms of one cell are evaluated with: the cell's own state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SidewallCell {
    /// εs [-]
    pub eps_s: f64,
    /// θ [m² s⁻²]
    pub theta: f64,
    /// |u_s| at the cell centre, the slip on the resting walls [m s⁻¹]
    pub speed: f64,
    /// |u_g − u_s| at the cell centre [m s⁻¹] (Wen–Yu drag in μ*, κ*)
    pub gas_slip: f64,
    /// tr D in the plane [s⁻¹]
    pub tr_d: f64,
    /// S:S in the plane [s⁻²] (the flat profile adds no shear across the width)
    pub s_ddot_s: f64,
    /// μ_s of the cell [Pa s]
    pub mu_s: f64,
    /// λ_s of the cell [Pa s] (the walls' normal load, [`side_wall_extra_load`])
    pub lambda_s: f64,
    /// κ_s of the cell [kg m⁻¹ s⁻¹]
    pub kappa_s: f64,
}

/// The width-averaged side-wall terms of one cell, per unit volume.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SidewallTerms {
    /// (2/W) K: momentum sink per unit velocity [kg m⁻³ s⁻¹]
    pub drag: f64,
    /// (2/W) h_θ: θ sink per unit θ [kg m⁻³ s⁻¹]
    pub theta_sink: f64,
    /// (2/W) c_θ: θ source [W m⁻³]
    pub theta_source: f64,
    /// the walls' normal load beyond the pressure, −λ_s tr D, where they read it (a Coulomb
    /// wall, docs/model.md §3.11), else 0 \[Pa\]
    pub extra_normal_load: f64,
}

impl Sidewalls {
    /// τ_w/u_s = K of the solids at one cell [Pa s m⁻¹] (module doc).
    pub fn stress_per_slip(&self, cell: &SidewallCell, params: &ClosureParams) -> f64 {
        let state = MomentumWallState {
            eps_s_fluid: cell.eps_s,
            eps_s: cell.eps_s,
            theta: cell.theta,
            slip: cell.speed,
            gas_slip: cell.gas_slip,
            tr_d: cell.tr_d,
            s_ddot_s: cell.s_ddot_s,
            // the wall normal z: D_zz = 0
            s_nn: -cell.tr_d / 3.0,
            extra_normal_load: side_wall_extra_load(cell.lambda_s, cell.tr_d),
        };
        let k = self
            .solids
            .side_wall_stress_per_slip(&state, cell.mu_s, self.width, params);
        k.min(MAX_STRESS_PER_SLIP)
    }

    /// (h_θ, c_θ) of the walls' granular-energy flux q_w = c_θ − h_θ θ at one cell
    /// [kg m⁻² s⁻¹, kg s⁻³] (module doc).
    pub fn theta_flux(&self, cell: &SidewallCell, params: &ClosureParams) -> (f64, f64) {
        let state = ThetaWallState {
            eps_s: cell.eps_s,
            theta: cell.theta,
            slip: cell.speed,
            gas_slip: cell.gas_slip,
        };
        let face = self.solids.granular_temperature(&state, params).face;
        let factor = self.solids.theta_flux_factor(cell.kappa_s);
        (factor * face.h, factor * face.c)
    }

    /// The cell's width-averaged terms (module doc).
    pub fn solids_terms(&self, cell: &SidewallCell, params: &ClosureParams) -> SidewallTerms {
        let per_width = 2.0 / self.width;
        let (h_theta, c_theta) = self.theta_flux(cell, params);
        SidewallTerms {
            drag: per_width * self.stress_per_slip(cell, params),
            theta_sink: per_width * h_theta,
            theta_source: per_width * c_theta,
            extra_normal_load: if self.solids.reads_normal_traction() {
                side_wall_extra_load(cell.lambda_s, cell.tr_d)
            } else {
                0.0
            },
        }
    }

    /// The gas's width-averaged drag per unit velocity [kg m⁻³ s⁻¹]: plane Poiseuille flow
    /// between no-slip walls, −12 μ_g ū/W² (docs/model.md §8), or 0 for free-slip walls.
    pub fn gas_drag(&self, mu_g: f64) -> f64 {
        if self.gas_no_slip {
            12.0 * mu_g / (self.width * self.width)
        } else {
            0.0
        }
    }
}

/// Step 1, side walls: the terms of every cell and solids phase from the current iterate
/// (after the closures, whose μ_s, κ_s and strain rates they read).
pub(super) fn update_sidewalls(
    grid: &Grid,
    sidewalls: &Sidewalls,
    state: &State,
    coefficients: &mut [PhaseCoefficients],
    specs: &[SolidsSpec],
) {
    let nx = grid.nx();
    let (u_g, v_g) = (&state.gas().u, &state.gas().v);
    for ((s, p), spec) in coefficients.iter_mut().zip(state.phases()).zip(specs) {
        let eps = p.eps();
        for k in 0..eps.len() {
            if eps[k] == 0.0 {
                s.sidewall[k] = SidewallTerms::default();
                continue;
            }
            let (i, j) = (k % nx, k / nx);
            let (w, e) = (i + (nx + 1) * j, i + 1 + (nx + 1) * j);
            let (us, vs) = (0.5 * (p.u[w] + p.u[e]), 0.5 * (p.v[k] + p.v[k + nx]));
            let (ug, vg) = (0.5 * (u_g[w] + u_g[e]), 0.5 * (v_g[k] + v_g[k + nx]));
            let cell = SidewallCell {
                eps_s: eps[k],
                theta: p.theta[k],
                speed: us.hypot(vs),
                gas_slip: (ug - us).hypot(vg - vs),
                tr_d: s.strain[k].tr_d,
                s_ddot_s: s.strain[k].s_ddot_s,
                mu_s: s.mu[k],
                lambda_s: s.lambda[k],
                kappa_s: s.kappa[k],
            };
            s.sidewall[k] = sidewalls.solids_terms(&cell, &spec.params);
        }
    }
}

/// Adds the side walls' momentum sinks to the assembled rows of component `c`: at each
/// coupled node the cells' (2/W) K by half volumes (as the drag, docs/model.md §4.5) times
/// the node's volume on the solids diagonal (dilute and fixed nodes skipped: their rows are
/// replaced), and the gas's Poiseuille drag on the gas diagonal.
pub(super) fn add_momentum_sinks(
    grid: &Grid,
    c: Component,
    (gas_rows, gas_drag): (&mut runout_linsolve::Stencil5, f64),
    solids: &mut [SolidsComponent<'_>],
) {
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    for j in 0..c.my {
        for i in 0..c.mx {
            let k = i + c.mx * j;
            if gas_rows.pattern().fixed_mask()[k] {
                continue;
            }
            let [lo, hi] = c.cells(i, j, true);
            let half = |x: Option<(usize, usize)>| {
                x.map(|(ci, cj)| (ci + c.nx * cj, 0.5 * dx[ci] * dy[cj]))
            };
            let (lo, hi) = (half(lo), half(hi));
            let volume = lo.map_or(0.0, |x| x.1) + hi.map_or(0.0, |x| x.1);
            gas_rows.a_p[k] += gas_drag * volume;
            for s in solids.iter_mut() {
                if s.dilute[k] {
                    continue;
                }
                let terms = &s.coefficients.sidewall;
                let sink = lo.map_or(0.0, |(cell, v)| terms[cell].drag * v)
                    + hi.map_or(0.0, |(cell, v)| terms[cell].drag * v);
                s.a.a_p[k] += sink;
            }
        }
    }
}

/// Adds the side walls' θ flux to the assembled θ rows of one phase: (2/W) h_θ V on the
/// diagonal, (2/W) c_θ V to the source.
pub(super) fn add_theta_flux(
    grid: &Grid,
    sidewall: &[SidewallTerms],
    a_theta: &mut runout_linsolve::Stencil5,
) {
    let nx = grid.nx();
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    for (k, terms) in sidewall.iter().enumerate() {
        let volume = dx[k % nx] * dy[k / nx];
        a_theta.a_p[k] += terms.theta_sink * volume;
        a_theta.b[k] += terms.theta_source * volume;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_walls::coefficients::{c_theta_johnson_jackson, h_theta_johnson_jackson};

    fn cell() -> SidewallCell {
        SidewallCell {
            eps_s: 0.3,
            theta: 0.05,
            speed: 2.0,
            gas_slip: 0.0,
            tr_d: 0.0,
            s_ddot_s: 0.0,
            mu_s: 0.2,
            lambda_s: -0.2 * 2.0 / 3.0,
            kappa_s: 0.4,
        }
    }

    /// Below εs,min the JJ wall stress per unit slip is COL = φ √(3θ) π ρs εs g0/(6 εs,max)
    /// (docs/model.md §3.5), and the θ flux JJ's (§3.6), both times 2/W.
    #[test]
    fn johnson_jackson_terms_are_col_and_the_jj_flux_over_half_the_width() {
        let params = ClosureParams::default();
        let phi = 0.1;
        let walls = Sidewalls {
            width: 0.3,
            solids: SolidsWallModel::johnson_jackson(phi, 0.7, 11.0, 0.0).unwrap(),
            gas_no_slip: true,
        };
        let c = cell();
        let eps_max = params.friction.eps_s_max;
        let g0 = params.radial.g0(c.eps_s);
        let col = phi
            * (3.0 * c.theta).sqrt()
            * std::f64::consts::PI
            * params.particles.density
            * c.eps_s
            * g0
            / (6.0 * eps_max);
        let t = walls.solids_terms(&c, &params);
        assert!(
            (t.drag - col / 0.15).abs() < 1e-12 * t.drag,
            "{} {}",
            t.drag,
            col
        );
        let state = runout_closures::kinetic::SolidsState::new(
            c.eps_s,
            c.theta,
            &params.particles,
            params.radial,
        );
        let h = h_theta_johnson_jackson(0.7, &state, eps_max);
        let cth = c_theta_johnson_jackson(phi, &state, c.speed, eps_max);
        assert!((t.theta_sink - h / 0.15).abs() < 1e-12 * t.theta_sink);
        assert!((t.theta_source - cth / 0.15).abs() < 1e-12 * t.theta_source);
        // the gas: 12 μ_g/W²
        assert_eq!(walls.gas_drag(1.8e-5), 12.0 * 1.8e-5 / 0.09);
    }

    #[test]
    fn simple_walls_give_their_closed_forms() {
        let params = ClosureParams::default();
        let c = cell();
        let with = |solids| Sidewalls {
            width: 0.5,
            solids,
            gas_no_slip: false,
        };
        let free = with(SolidsWallModel::FreeSlip).solids_terms(&c, &params);
        assert_eq!(free, SidewallTerms::default());
        let stick = with(SolidsWallModel::NoSlip);
        assert_eq!(stick.solids_terms(&c, &params).drag, 4.0 * 6.0 * 0.2 / 0.5);
        let user = with(SolidsWallModel::partial_slip(50.0, 0.0, 3.0, 0.01, 0.5).unwrap());
        let t = user.solids_terms(&c, &params);
        assert_eq!(t.drag, 4.0 * 0.2 * 50.0);
        assert_eq!(t.theta_sink, 4.0 * 0.4 * 3.0);
        assert!((t.theta_source - 4.0 * 0.4 * (0.5 + 3.0 * 0.01)).abs() < 1e-15);
        assert_eq!(stick.gas_drag(1.0), 0.0);
    }

    /// The plane limit W → ∞ adds exactly nothing.
    #[test]
    fn an_infinite_width_adds_nothing() {
        let params = ClosureParams::default();
        let walls = Sidewalls {
            width: f64::INFINITY,
            solids: SolidsWallModel::jenkins(0.7, 11.0, 0.0).unwrap(),
            gas_no_slip: true,
        };
        assert_eq!(
            walls.solids_terms(&cell(), &params),
            SidewallTerms::default()
        );
        assert_eq!(walls.gas_drag(1.8e-5), 0.0);
    }
}
