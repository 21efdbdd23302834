//! The full closure set of one cell state (docs/model.md §1.3 and §2), evaluated by one
//! allocation-free function, [`evaluate`]. Used by the solver, the `runout closures`
//! calculator and the bench.

use crate::drag::{dga_single_particle, Drag, DragInputs};
use crate::energy::{shear_production, slip_production, viscous_damping};
use crate::friction::{FrictionModel, FrictionParams, FrictionalStress};
use crate::guards::DIL_EP_S;
use crate::kinetic::{lun_1984, GasCoupling, KineticStress, SolidsState};
use crate::radial::RadialDistribution;
use crate::stress::{assemble, SolidsStress};
use serde::Serialize;

/// Particle properties of one solids phase (style A6.13).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Particles {
    /// particle diameter d \[m\] (`D_P0`)
    pub diameter: f64,
    /// material density ρs [kg/m³] (`RO_S0`)
    pub density: f64,
    /// particle–particle restitution coefficient e [-] (`C_E`)
    pub restitution: f64,
}

impl Default for Particles {
    /// Paper Table 3, sensitivity analysis: d = 0.5 mm, ρs = 2000 kg/m³, e = 0.9.
    fn default() -> Self {
        Self {
            diameter: 5e-4,
            density: 2000.0,
            restitution: 0.9,
        }
    }
}

/// Gas properties (constant `RO_G0`, `MU_G0`; docs/model.md §1.1–1.2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Gas {
    /// gas density ρ_g [kg/m³]; 0 means a dry granular flow (no drag, μ* = μ₀, κ* = κ₀)
    pub density: f64,
    /// gas viscosity μ_g [Pa s]
    pub viscosity: f64,
}

impl Default for Gas {
    /// Paper Table 3: ρ_g = 1.2 kg/m³, μ_g = 1.8e-5 Pa s (constants assumed, docs/model.md §5).
    fn default() -> Self {
        Self {
            density: 1.2,
            viscosity: 1.8e-5,
        }
    }
}

/// Every parameter and model choice of the closure set.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ClosureParams {
    /// particle properties
    pub particles: Particles,
    /// gas properties
    pub gas: Gas,
    /// εs,max, εs,min and φ of the frictional closures
    pub friction: FrictionParams,
    /// g0 model (default Carnahan–Starling)
    pub radial: RadialDistribution,
    /// frictional model with its code constants (default Princeton, the paper's)
    pub friction_model: FrictionModel,
    /// drag law (default Syamlal–O'Brien 0.8/2.65)
    pub drag: Drag,
}

/// The local state of one cell (cell-centred values).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CellState {
    /// solids volume fraction εs [-], 0 ≤ εs < 1
    pub eps_s: f64,
    /// granular temperature θ [m²/s²], ≥ 0
    pub theta: f64,
    /// relative speed |u_g − u_s| [m/s] (drag and Koch–Sangani slip production)
    pub slip: f64,
    /// tr D_s = ∇·u_s [1/s]
    pub tr_d: f64,
    /// S:S = tr(D_s²) − (tr D_s)²/3 [1/s²], ≥ 0
    pub s_ddot_s: f64,
}

impl Default for CellState {
    /// The second check state of docs/model.md §2.2 (εs = 0.55, θ = 0.1 m²/s²), at rest.
    fn default() -> Self {
        Self {
            eps_s: 0.55,
            theta: 0.1,
            slip: 0.0,
            tr_d: 0.0,
            s_ddot_s: 0.0,
        }
    }
}

/// Every closure value at one cell state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct ClosureSet {
    /// εg = 1 − εs [-]
    pub eps_g: f64,
    /// g0 [-] (docs/model.md §2.1)
    pub g0: f64,
    /// dg0/dεs [-] (docs/model.md §2.1)
    pub dg0_deps: f64,
    /// η = (1 + e)/2 [-]
    pub eta: f64,
    /// DgA of the bulk drag law [kg m⁻³ s⁻¹] (docs/model.md §2.6)
    pub dga: f64,
    /// F_gs = εs DgA [kg m⁻³ s⁻¹] (docs/model.md §2.6)
    pub f_gs: f64,
    /// drag per unit solids fraction used in μ*, κ* [kg m⁻³ s⁻¹]: DgA, or the single-particle
    /// value below `DIL_EP_S` (docs/model.md §2.2); 0 without gas
    pub dga_kinetic: f64,
    /// kinetic-theory values (docs/model.md §2.2)
    pub kinetic: KineticStress,
    /// frictional values (docs/model.md §2.4)
    pub friction: FrictionalStress,
    /// summed stress coefficients (docs/model.md §2.3)
    pub stress: SolidsStress,
    /// K_cp = dP_s/dεs \[Pa\] (docs/model.md §2.5; the solver zeroes it in wall cells)
    pub k_cp: f64,
    /// shear production Π [W m⁻³] (docs/model.md §1.3)
    pub production: f64,
    /// viscous damping J_vis = 3 F_gs θ [W m⁻³] (docs/model.md §1.3)
    pub j_vis: f64,
    /// slip production J_slip [W m⁻³] (docs/model.md §1.3)
    pub j_slip: f64,
}

/// Evaluate every closure of docs/model.md §2 and the granular-energy sources of §1.3 at one
/// cell state: g0 → drag F_gs → Lun KT (gas-modified μ*, κ*) → friction → additive stress →
/// K_cp → Π, J_vis, J_slip. Pure and allocation-free. A dry flow (ρ_g = 0) has no drag, no
/// J_vis and no J_slip, and μ* = μ₀, κ* = κ₀ (docs/model.md §6, last row).
#[inline]
pub fn evaluate(state: &CellState, params: &ClosureParams) -> ClosureSet {
    evaluate_in_gas(state, params, &params.gas)
}

/// [`evaluate`] in the gas `fluid` instead of `params.gas`: a compressible gas's density of
/// the cell (docs/model.md §1.4).
#[inline]
pub fn evaluate_in_gas(state: &CellState, params: &ClosureParams, fluid: &Gas) -> ClosureSet {
    let particles = &params.particles;
    let eps_s = state.eps_s;
    let eps_g = 1.0 - eps_s;
    let solids = SolidsState::new(eps_s, state.theta, particles, params.radial);
    let g0 = solids.g0;

    let has_gas = fluid.density != 0.0;
    let drag_inputs = DragInputs {
        eps_g,
        rho_g: fluid.density,
        mu_g: fluid.viscosity,
        slip: state.slip,
        d_p: particles.diameter,
    };
    let (dga, dga_kinetic, gas) = if has_gas {
        let dga = params.drag.dga(eps_s, &drag_inputs);
        // MFIX GT_PDE_LUN: single-particle drag below DIL_EP_S, F_gs/εs = DgA otherwise
        let dga_kinetic = if eps_s < DIL_EP_S {
            dga_single_particle(&drag_inputs)
        } else {
            dga
        };
        (dga, dga_kinetic, GasCoupling::Drag(dga_kinetic))
    } else {
        (0.0, 0.0, GasCoupling::Dry)
    };
    let f_gs = eps_s * dga;

    let kinetic = lun_1984(&solids, gas);
    let friction = params.friction_model.stress(
        eps_s,
        state.theta,
        particles.diameter,
        particles.density,
        state.tr_d,
        state.s_ddot_s,
        kinetic.p_kin,
        &params.friction,
    );
    // K_cp (docs/model.md §2.5), reusing the Princeton P_f/P_c just computed
    let k_cp = match params.friction_model {
        FrictionModel::Princeton(c) => c.k_cp_from_stress(eps_s, &friction, &params.friction),
        model => model.k_cp(
            eps_s,
            state.theta,
            particles.diameter,
            state.tr_d,
            state.s_ddot_s,
            &params.friction,
        ),
    };
    let (j_vis, j_slip) = if has_gas {
        (
            viscous_damping(f_gs, state.theta),
            slip_production(
                eps_s,
                state.theta,
                g0,
                particles.diameter,
                particles.density,
                fluid.viscosity,
                state.slip,
            ),
        )
    } else {
        (0.0, 0.0)
    };

    ClosureSet {
        eps_g,
        g0,
        dg0_deps: params.radial.dg0_deps(eps_s),
        eta: solids.eta(),
        dga,
        f_gs,
        dga_kinetic,
        kinetic,
        friction,
        stress: assemble(&kinetic, &friction),
        k_cp,
        production: shear_production(
            kinetic.p_kin,
            kinetic.mu_kin,
            kinetic.lambda_kin,
            state.tr_d,
            state.s_ddot_s,
        ),
        j_vis,
        j_slip,
    }
}
