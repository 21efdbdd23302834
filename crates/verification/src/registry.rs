//! The registry of checks: what `cargo xtask verify <name>` and the tests of
//! `crates/verification/tests/` iterate.
//!
//! | name | problem | reference |
//! |---|---|---|
//! | `cavity` | lid-driven cavity | Ghia, Ghia & Shin (1982) |
//! | `poiseuille` | partial-slip channel | closed form |
//! | `taylor-green` | decaying vortex, mass of every step | closed form |
//! | `chute` | steady chute on a periodic column | the 1-D chute solver |
//! | `incline` | μ(I) on a rough incline, flowing and at rest | Bagnold profile, creep closed form |
//! | `coulomb-floor` | a block on a Coulomb floor, a layer between Coulomb side walls | the sliding-block law |
//! | `release` | a polygon pile behind a gate on a slope | its mass, at rest until the gate opens |
//! | `bed-path` | a block sliding down a path of bends, a layer at rest on one | ū = √(2 g Δz), rest below the friction angle |
//! | `haff` | energy equation in a box at rest | Haff (1983) |
//! | `cooling` | cooling through the two-fluid step | Haff with viscous damping |
//! | `settling` | settling column | the bed's weight |
//! | `fluidized-bed` | fluidized bed | the bed's buoyant weight |
//! | `gas-inlet` | a bed fluidised through a floor inlet on a schedule, through the driver | the bed's buoyant weight while open, none while shut |
//! | `ideal-gas` | air as an ideal gas in a closed box while a bed settles | its mass, the isothermal column |
//! | `defluidisation` | a bed aerated through the floor at 1 kPa (and 1 atm, full size), then shut off | pore-pressure diffusion in a rigid bed, t½ ∝ H² (1 kPa); the bed's 1-D nonlinear consolidation |
//! | `s-jj-phi` | the paper's slide through the driver | bounds and conservation |
//! | `relaxation` | the paper's slide with two under-relaxations | the same front and station numbers |
//!
//! Not here, and why: the granular column collapse (`cargo xtask verify collapse`, against
//! the laboratory runout laws of [`crate::references::runout_laws`]) and family M against
//! MFIX (`cargo xtask verify mfix-slope`, against [`crate::references::mfix_family_m`]).
//! Both are studies of the whole program rather than pass/fail checks of the solver: they
//! run cases through the driver into run directories that they reuse between invocations,
//! take fidelity presets, thread counts and reuse flags, time the runs (getrusage) and
//! write their pages (docs/reports/collapse.md, docs/reports/mfix-slope.md) with figures from the VTK
//! output. They stay in xtask with their options, and take their reference numbers from
//! this crate. The Re = 1000 cavity investigation (`cargo xtask verify cavity-re1000`) is a
//! study without a limit and stays in xtask too.

use crate::check::Check;
use crate::checks::{
    BedPath, Cavity, Chute, Cooling, CoulombFloor, Defluidisation, FluidizedBed, GasInlet, Haff,
    IdealGas, Incline, Poiseuille, Relaxation, Release, SJjPhi, Settling, TaylorGreen,
};

/// Every check, in the order `cargo xtask verify all` runs them.
pub fn registry() -> Vec<Box<dyn Check>> {
    vec![
        Box::new(Cavity),
        Box::new(Poiseuille),
        Box::new(TaylorGreen),
        Box::new(Chute),
        Box::new(Incline),
        Box::new(CoulombFloor),
        Box::new(BedPath),
        Box::new(Release),
        Box::new(Haff),
        Box::new(Cooling),
        Box::new(Settling),
        Box::new(FluidizedBed),
        Box::new(GasInlet),
        Box::new(IdealGas),
        Box::new(Defluidisation),
        Box::new(SJjPhi),
        Box::new(Relaxation),
    ]
}

/// The check called `name`.
pub fn find(name: &str) -> Option<Box<dyn Check>> {
    registry().into_iter().find(|c| c.name() == name)
}

/// Named groups of checks: `single-phase` (issue 6's core: cavity, poiseuille,
/// taylor-green), `two-fluid` (issue 7's cooling, settling, fluidized bed and S-JJ-phi)
/// and `all` (the whole registry).
pub fn group(name: &str) -> Option<Vec<&'static str>> {
    match name {
        "single-phase" => Some(vec!["cavity", "poiseuille", "taylor-green"]),
        "two-fluid" => Some(vec![
            "haff",
            "cooling",
            "settling",
            "fluidized-bed",
            "s-jj-phi",
        ]),
        "all" => Some(registry().iter().map(|c| c.name()).collect()),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_and_groups_resolve() {
        let names: Vec<_> = registry().iter().map(|c| c.name()).collect();
        let mut sorted = names.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(sorted.len(), names.len(), "{names:?}");
        for g in ["single-phase", "two-fluid", "all"] {
            for n in group(g).unwrap() {
                assert!(find(n).is_some(), "{g}: {n}");
            }
        }
    }
}
