//! What a two-fluid solver is built with and keeps through its steps: the grid, the gas and
//! its walls, the solids phases, gravity, the iteration settings, the scene derived from
//! them and the side walls of a channel. The stages of the outer iteration read it (an
//! explicit `&Model` beside the state they change); only the set-up and the run's schedules
//! (gravity, inflow, side walls) write it, through [`super::TwoFluid`]'s setters.

use runout_mesh::{Grid, Sides};

use super::{Scene, Sidewalls, SolidsSpec, TwoFluidSettings};
use crate::bent_floor::BentFloor;
use crate::single_phase::{Fluid, SideBc};

/// The fixed description of a two-fluid problem (module doc).
pub(super) struct Model {
    /// the grid (x may be periodic: a fully developed column)
    pub grid: Grid,
    /// gas density and viscosity
    pub gas: Fluid,
    /// the gas viscosity per cell [Pa s] (uniform: μ_g of `gas`), the viscosity field of
    /// the gas momentum assembly
    pub gas_viscosity: Vec<f64>,
    /// the gas's condition on each side (wall closure of its tangential velocity or outlet)
    pub gas_walls: Sides<SideBc>,
    /// gas velocity into the domain through each wall side [m s⁻¹] (a distributor: gas
    /// enters with εg = 1, solids see the wall; MFIX's mass inlet with BC_EP_G = 1), 0 on
    /// impermeable walls
    pub gas_inflow: Sides<Vec<f64>>,
    /// the solids phases: closure parameters, packing and walls
    pub solids_specs: Vec<SolidsSpec>,
    /// gravity (g_x, g_y) [m s⁻²]
    pub gravity: (f64, f64),
    /// a floor that bends (docs/model.md §9): when set, its field replaces `gravity` and the
    /// v equations gain the centrifugal force; none on a plane floor
    pub bent_floor: Option<BentFloor>,
    /// the u faces a gate closes at present, (nx + 1) × ny flags (empty: none), where the gas
    /// and every solids phase hold u = 0 as at a wall ([`super::TwoFluid::set_gate_faces`])
    pub gate_faces: Vec<bool>,
    /// iteration settings
    pub settings: TwoFluidSettings,
    /// what this solver computes (derived when built, and when the side walls are set)
    pub scene: Scene,
    /// the side walls of a quasi-2-D channel (docs/model.md §8), none in a plane flow
    pub sidewalls: Option<Sidewalls>,
}

/// The momentum residual's floor speed as a fraction of the free-fall speed over the domain's
/// height √(|g| L_y) ([`Model::momentum_speed_floor`]).
const MOMENTUM_SPEED_FLOOR: f64 = 1e-6;

impl Model {
    /// The speed [m/s] below which a class of momentum nodes counts as at rest for its
    /// residual (docs/model.md §4.11, [`super::residuals::ClassedResidual`]):
    /// [`MOMENTUM_SPEED_FLOOR`] √(|g| L_y), about 2 µm/s on a half-metre domain; with the
    /// 1e-3 tolerance a class at rest is converged when its velocity error is below ~2 nm/s.
    /// Zero without gravity.
    pub fn momentum_speed_floor(&self) -> f64 {
        let g = self.gravity.0.hypot(self.gravity.1);
        MOMENTUM_SPEED_FLOOR * (g * self.grid.y.length()).sqrt()
    }
}
