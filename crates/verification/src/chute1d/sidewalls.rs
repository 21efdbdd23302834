//! Side walls of the 1-D chute (docs/model.md §8), written from the equations apart from the
//! 2-D solver's: two walls a width W apart, parallel to the (x, y) plane, with the solids
//! profile across the width flat, remove (2/W) τ_w from the x-momentum of every cell and add
//! (2/W) q_w to its granular energy; τ_w and q_w come from the floor's wall models at the
//! cell's own state (the walls are at rest: the slip is u_s; the wall normal is z, so
//! S_nn = D_zz − tr D/3 = 0 with tr D = 0; dry, so no gas slip).

use runout_closures::ClosureParams;
use runout_walls::{MomentumWallState, SolidsWallModel, ThetaWallState};

/// Two side walls of the chute, a width apart (docs/model.md §8).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChuteSidewalls {
    /// width W between the walls [m], > 0
    pub width: f64,
    /// the solids condition on both walls (at rest)
    pub solids: SolidsWallModel,
}

/// What one cell's side walls contribute per unit volume.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct SidewallLoad {
    /// x-momentum sink (2/W) τ_w [N m⁻³]
    pub(super) momentum: f64,
    /// granular-energy gain (2/W) c_θ [W m⁻³]
    pub(super) generation: f64,
    /// granular-energy loss (2/W) h_θ θ [W m⁻³]
    pub(super) dissipation: f64,
}

impl ChuteSidewalls {
    /// The load of a cell at (εs, u_s, θ) with shear rate du/dy, μ_s and κ_s.
    pub(super) fn load(
        &self,
        params: &ClosureParams,
        (eps_s, u, theta): (f64, f64, f64),
        shear_rate: f64,
        (mu_s, kappa_s): (f64, f64),
    ) -> SidewallLoad {
        let per_width = 2.0 / self.width;
        let slip = u.abs();
        // τ_w: the wall model's Robin coefficient h_w^u times the viscosity it was formed
        // with (μ_k + μ_f of the wall routine: h = (COL + FRI)/(μ_k + μ_f), docs/model.md §3.5)
        let stress = match self.solids {
            SolidsWallModel::FreeSlip => 0.0,
            SolidsWallModel::NoSlip => 6.0 * mu_s / self.width * u,
            SolidsWallModel::PartialSlip(user) => mu_s * user.h_u * u,
            SolidsWallModel::JohnsonJackson { .. }
            | SolidsWallModel::Jenkins { .. }
            | SolidsWallModel::Coulomb(_) => {
                let wall = self.solids.momentum(
                    &MomentumWallState {
                        eps_s_fluid: eps_s,
                        eps_s,
                        theta,
                        slip,
                        gas_slip: 0.0,
                        tr_d: 0.0,
                        s_ddot_s: 0.5 * shear_rate * shear_rate,
                        s_nn: 0.0,
                        extra_normal_load: 0.0,
                    },
                    params,
                );
                let d = wall.diagnostics;
                d.h_u * d.viscosity() * u
            }
        };
        let face = self
            .solids
            .granular_temperature(
                &ThetaWallState {
                    eps_s,
                    theta,
                    slip,
                    gas_slip: 0.0,
                },
                params,
            )
            .face;
        // JJ and Jenkins: κ ∂θ/∂n + h_θ θ = c_θ, the flux into the flow c_θ − h_θ θ; the
        // user form is in MFIX's manual units (times κ_s); no-/free-slip: zero flux
        let scale = self.solids.theta_flux_factor(kappa_s);
        SidewallLoad {
            momentum: per_width * stress,
            generation: per_width * scale * face.c,
            dissipation: per_width * scale * face.h * theta,
        }
    }
}
