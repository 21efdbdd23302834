//! The `cavity` check (issue 6): the lid-driven cavity with Superbee against the centreline
//! velocities of Ghia, Ghia & Shin (1982) ([`crate::problems::cavity`]).
//!
//! - fast: 32 × 32 at Re = 100 with both schemes, largest centreline deviation < 0.05;
//! - full: 129 × 129 (Ghia's grid) with Superbee at Re = 100 and 1000, largest deviation
//!   < 1 % of the lid speed (the acceptance target of issue 6).
//!
//! Both want a converged steady state and a continuity imbalance ≤ [`MASS_TOLERANCE`] of
//! the flow through the domain.

use runout_solver::Scheme;

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::{cavity, CavitySetup, MASS_TOLERANCE};

/// Cells per side of the acceptance cavity (Ghia's grid has 129 lines).
pub const CAVITY_CELLS: usize = 129;
/// Largest centreline deviation allowed at 129 × 129 (issue 6): 1% of the lid speed.
pub const CAVITY_TARGET: f64 = 0.01;
/// Largest centreline deviation allowed at the fast size (32 × 32, Re = 100).
pub const CAVITY_FAST_TARGET: f64 = 0.05;

/// The lid-driven cavity against Ghia.
pub struct Cavity;

impl Check for Cavity {
    fn name(&self) -> &'static str {
        "cavity"
    }

    fn description(&self) -> &'static str {
        "lid-driven cavity against Ghia, Ghia & Shin (1982)"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        match size {
            Size::Fast => fast(&mut outcome)?,
            Size::Full => full(&mut outcome)?,
        }
        Ok(outcome)
    }
}

fn fast(outcome: &mut Outcome) -> anyhow::Result<()> {
    for scheme in [Scheme::Upwind, Scheme::Superbee] {
        let r = cavity(&CavitySetup::new(32, 100.0, scheme))?;
        println!(
            "32x32 Re=100 {scheme:?}: max centreline error {:.4} after {} iterations, mass ratio {:.1e}",
            r.max_error, r.outer_iterations, r.mass_ratio
        );
        let label = format!("32x32 Re=100 {scheme:?}");
        outcome.holds(format!("{label}: converged"), r.converged);
        outcome.measure(
            format!("{label}: max centreline error"),
            r.max_error,
            Limit::Below(CAVITY_FAST_TARGET),
        );
        outcome.measure(
            format!("{label}: mass ratio"),
            r.mass_ratio,
            Limit::AtMost(MASS_TOLERANCE),
        );
    }
    Ok(())
}

fn full(outcome: &mut Outcome) -> anyhow::Result<()> {
    println!("lid-driven cavity, {CAVITY_CELLS} x {CAVITY_CELLS}, Superbee, against Ghia, Ghia & Shin (1982)");
    for re in [100.0, 1000.0] {
        let r = cavity(&CavitySetup::new(CAVITY_CELLS, re, Scheme::Superbee))?;
        let (which, worst) = r.ghia.worst();
        let ok = r.converged && r.max_error < CAVITY_TARGET && r.mass_ratio <= MASS_TOLERANCE;
        println!(
            "  Re = {re:>4}: max |error| {:.5} ({which} at {:.4}: ours {:.5}, Ghia {:.5}); \
             {} outer iterations, {:.1} s, mass ratio {:.1e}  {}",
            r.max_error,
            worst.position,
            worst.computed,
            worst.reference,
            r.outer_iterations,
            r.wall_time,
            r.mass_ratio,
            super::verdict(ok)
        );
        let label = format!("{CAVITY_CELLS}x{CAVITY_CELLS} Re={re}");
        outcome.holds(format!("{label}: converged"), r.converged);
        outcome.measure(
            format!("{label}: max centreline error"),
            r.max_error,
            Limit::Below(CAVITY_TARGET),
        );
        outcome.measure(
            format!("{label}: mass ratio"),
            r.mass_ratio,
            Limit::AtMost(MASS_TOLERANCE),
        );
    }
    Ok(())
}
