//! The registry of checks and studies: what `cargo xtask verify <name>` and the tests of
//! `crates/verification/tests/` iterate.
//!
//! The checks ([`Check`], [`crate::checks`]): a problem judged against its reference at
//! the fast size (the tests, CI) and the full size (`cargo xtask verify`).
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
//! The studies ([`Study`], [`mod@crate::studies`]): the whole program run with options into run
//! folders that they reuse between invocations, timed, their pages written to
//! docs/reports/ (or runs/) with figures; `cargo xtask verify <name> [options]`, never the
//! test suite.
//!
//! | name | study | reference | options | page |
//! |---|---|---|---|---|
//! | `cavity-re1000` | lid-driven cavity at Re = 1000 on three grids and three tolerances | Ghia, Ghia & Shin (1982); Botella & Peyret (1998) | none | none: it prints its numbers |
//! | `collapse` | granular column collapse, Princeton and μ(I) | laboratory runout laws ([`crate::references::runout_laws`]) | `--fidelity`, `--friction`, `--aspect`, `--sidewalls`, `--reuse` | docs/reports/collapse*.md at coarse, else runs/collapse-report/ |
//! | `mfix-slope` | family M: the paper's slide on four floors, timed | MFIX 21.3.2 ([`crate::references::mfix_family_m`]) | `--fidelity`, `--threads`, `--skip-variants` | docs/reports/mfix-slope.md |

use crate::check::Check;
use crate::checks::{
    BedPath, Cavity, Chute, Cooling, CoulombFloor, Defluidisation, FluidizedBed, GasInlet, Haff,
    IdealGas, Incline, Poiseuille, Relaxation, Release, SJjPhi, Settling, TaylorGreen,
};
use crate::studies::{CavityRe1000, Collapse, MfixSlope};
use crate::study::Study;

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

/// Every study, by name.
pub fn studies() -> Vec<Box<dyn Study>> {
    vec![
        Box::new(CavityRe1000),
        Box::new(Collapse),
        Box::new(MfixSlope),
    ]
}

/// The study called `name`.
pub fn find_study(name: &str) -> Option<Box<dyn Study>> {
    studies().into_iter().find(|s| s.name() == name)
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
        let mut names: Vec<_> = registry().iter().map(|c| c.name()).collect();
        names.extend(studies().iter().map(|s| s.name()));
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
