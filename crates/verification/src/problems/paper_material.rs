//! The paper's material in air, shared by the two-fluid problems: paper Table 3
//! (d = 0.5 mm, ρs = 2000 kg/m³, e = 0.9; ρg = 1.2 kg/m³, μg = 1.8e-5 Pa s; δ_int = 35°,
//! εs,min = 0.5) with Carnahan–Starling g0 and Gidaspow drag (docs/model.md §2).

use runout_closures::{
    ClosureParams, Drag, FrictionModel, FrictionParams, Gas, Particles, RadialDistribution,
};

/// The paper's particles in air with the given friction model and packing limit εs,max.
pub fn paper_particles_in_air(friction_model: FrictionModel, eps_max: f64) -> ClosureParams {
    ClosureParams {
        particles: Particles {
            diameter: 5e-4,
            density: 2000.0,
            restitution: 0.9,
        },
        gas: Gas {
            density: 1.2,
            viscosity: 1.8e-5,
        },
        friction: FrictionParams::new(eps_max, 0.5, 35.0),
        radial: RadialDistribution::CarnahanStarling,
        friction_model,
        drag: Drag::Gidaspow,
    }
}
