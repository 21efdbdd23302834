//! The `gas-inlet` check (issue 60 item 2): a bed fluidised through a gas inlet in the floor
//! from 0.2 s until 2.0 s ([`crate::problems::gas_inlet`]), through the driver: the gas
//! pressure drop across the bed is its buoyant weight while the inlet is open (time-averaged,
//! within 3 %: the drop fluctuates by ±10 % as the bed bubbles, and about 50 snapshots
//! average it), and below 2 % of it before the inlet opens and once it has closed (the solids
//! carry the bed); the solids mass is conserved.
//!
//! - fast: the smoke fidelity (5 × 30 cells);
//! - full: smoke and coarse (10 × 60).

use runout_case::Fidelity;

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::gas_inlet::{run, WINDOWS};

/// Largest |drop/weight − 1| while the inlet is open.
pub const OPEN_TOLERANCE: f64 = 0.03;
/// Largest |drop/weight| while it is shut.
pub const SHUT_TOLERANCE: f64 = 0.02;

/// A bed fluidised through the floor, then shut off.
pub struct GasInlet;

impl Check for GasInlet {
    fn name(&self) -> &'static str {
        "gas-inlet"
    }

    fn description(&self) -> &'static str {
        "a bed fluidised through a floor inlet on a schedule: the gas carries its weight while the inlet is open, the solids before and after"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        let fidelities: &[Fidelity] = match size {
            Size::Fast => &[Fidelity::Smoke],
            Size::Full => &[Fidelity::Smoke, Fidelity::Coarse],
        };
        for &fidelity in fidelities {
            let label = fidelity.name();
            let r = run(fidelity)?;
            let [before, open, after] = r.drop_over_weight;
            println!(
                "  {label}: inflow {} m/s; gas pressure drop / buoyant weight: {:.4} before ({} snapshots, {:?} s), \
                 {:.4} open ({}, {:?} s), {:.4} after ({}, {:?} s); mass change {:.1e}; {} steps, {:.1} s",
                r.inflow, before.0, before.1, WINDOWS[0], open.0, open.1, WINDOWS[1], after.0, after.1, WINDOWS[2],
                r.mass_change, r.steps, r.wall_time
            );
            outcome.measure(
                format!("{label}: |drop/weight| before the inlet opens"),
                before.0.abs(),
                Limit::AtMost(SHUT_TOLERANCE),
            );
            outcome.measure(
                format!("{label}: |drop/weight − 1| while it is open"),
                (open.0 - 1.0).abs(),
                Limit::AtMost(OPEN_TOLERANCE),
            );
            outcome.measure(
                format!("{label}: |drop/weight| after it closed"),
                after.0.abs(),
                Limit::AtMost(SHUT_TOLERANCE),
            );
            for (name, n) in [("before", before.1), ("open", open.1), ("after", after.1)] {
                outcome.measure(
                    format!("{label}: snapshots averaged {name}"),
                    n as f64,
                    Limit::AtLeast(5.0),
                );
            }
            outcome.measure(
                format!("{label}: |solids mass change|"),
                r.mass_change.abs(),
                Limit::AtMost(1e-8),
            );
        }
        Ok(outcome)
    }
}
