//! Material and model options shared by the calculators (`runout closures`, `runout wall`):
//! one definition of the particle, gas and closure choices, their validation and their
//! mapping to `runout_closures::ClosureParams`. Defaults are the paper's sensitivity values
//! (paper Table 3).

use anyhow::ensure;
use clap::ValueEnum;
use runout_closures::{
    ClosureParams, Drag, FrictionModel, FrictionParams, Gas, Particles, RadialDistribution,
};
use serde::Serialize;

/// Frictional model (MFIX `FRICTION_MODEL`, docs/model.md §2.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum FrictionChoice {
    /// Srivastava & Sundaresan (2003), the paper's model
    Princeton,
    /// Schaeffer (1987) with the plastic pressure P*
    Schaeffer,
    /// kinetic theory only
    None,
}

/// Radial distribution function (MFIX `RDF_TYPE`, docs/model.md §2.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum RadialChoice {
    /// Carnahan–Starling as MFIX codes it
    CarnahanStarling,
    /// Ma–Ahmadi
    MaAhmadi,
}

/// Particle, gas and closure options (echoed in the JSON output as `inputs.material`).
#[derive(clap::Args, Debug, Clone, Serialize)]
pub struct MaterialArgs {
    /// particle diameter d [m]
    #[arg(long, default_value_t = 5e-4)]
    pub diameter: f64,
    /// solids material density rho_s [kg/m3]
    #[arg(long, default_value_t = 2000.0)]
    pub density: f64,
    /// particle-particle restitution coefficient e [-]
    #[arg(long, default_value_t = 0.9)]
    pub restitution: f64,
    /// maximum packing eps_s,max = 1 - EP_STAR [-]
    #[arg(long, default_value_t = 0.65)]
    pub eps_s_max: f64,
    /// onset of Princeton friction eps_s,min = EPS_F_MIN [-]
    #[arg(long, default_value_t = 0.5)]
    pub eps_s_min: f64,
    /// internal friction angle phi [degrees]
    #[arg(long, default_value_t = 35.0)]
    pub phi_internal: f64,
    /// gas density rho_g [kg/m3]; 0 = dry granular flow (no drag, mu* = mu0, kappa* = kappa0)
    #[arg(long, default_value_t = 1.2)]
    pub gas_density: f64,
    /// gas viscosity mu_g [Pa s]
    #[arg(long, default_value_t = 1.8e-5)]
    pub gas_viscosity: f64,
    /// frictional model
    #[arg(long, value_enum, default_value_t = FrictionChoice::Princeton)]
    pub friction: FrictionChoice,
    /// radial distribution function
    #[arg(long, value_enum, default_value_t = RadialChoice::CarnahanStarling)]
    pub radial: RadialChoice,
}

impl MaterialArgs {
    /// Rejects parameters outside the closures' validity ranges.
    pub fn validate(&self) -> anyhow::Result<()> {
        ensure!(
            self.diameter > 0.0,
            "--diameter must be > 0, got {}",
            self.diameter
        );
        ensure!(
            self.density > 0.0,
            "--density must be > 0, got {}",
            self.density
        );
        ensure!(
            self.restitution > 0.0 && self.restitution <= 1.0,
            "--restitution must be in (0, 1], got {}",
            self.restitution
        );
        ensure!(
            0.0 < self.eps_s_min && self.eps_s_min < self.eps_s_max && self.eps_s_max < 1.0,
            "need 0 < --eps-s-min < --eps-s-max < 1, got {} and {}",
            self.eps_s_min,
            self.eps_s_max
        );
        // n = sqrt(3)/(2 sin phi) must exceed 1 in dilatation (docs/model.md §2.4.2)
        ensure!(
            self.phi_internal > 0.0 && self.phi_internal < 60.0,
            "--phi-internal must be in (0, 60) degrees, got {}",
            self.phi_internal
        );
        ensure!(
            self.gas_density >= 0.0,
            "--gas-density must be >= 0, got {}",
            self.gas_density
        );
        ensure!(
            self.gas_viscosity > 0.0,
            "--gas-viscosity must be > 0, got {}",
            self.gas_viscosity
        );
        Ok(())
    }

    /// The closure parameters, with the given drag law.
    pub fn params(&self, drag: Drag) -> ClosureParams {
        ClosureParams {
            particles: Particles {
                diameter: self.diameter,
                density: self.density,
                restitution: self.restitution,
            },
            gas: Gas {
                density: self.gas_density,
                viscosity: self.gas_viscosity,
            },
            friction: FrictionParams::new(self.eps_s_max, self.eps_s_min, self.phi_internal),
            radial: match self.radial {
                RadialChoice::CarnahanStarling => RadialDistribution::CarnahanStarling,
                RadialChoice::MaAhmadi => RadialDistribution::MaAhmadi,
            },
            friction_model: match self.friction {
                FrictionChoice::Princeton => FrictionModel::princeton(),
                FrictionChoice::Schaeffer => FrictionModel::schaeffer(),
                FrictionChoice::None => FrictionModel::None,
            },
            drag,
        }
    }
}
