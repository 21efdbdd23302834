//! The `ideal-gas` check (issue 60 item 1): air as an ideal gas in a closed box while a bed
//! of sand settles ([`crate::problems::ideal_gas`]), through the driver. The gas's mass stays
//! the initial one (to the outer iterations' continuity remainder, below 1e-9 of it); the
//! clear gas above the settled bed is the isothermal column P0 exp(−M g z/(R T)) to 1e-11
//! (round-off on 1e5 Pa); and in the same box without the bed, where the gas relaxes from a
//! uniform pressure to its column, the column's level is the one the gas's mass fixes, to
//! 1e-8.
//!
//! - fast: the smoke fidelity (5 × 25 cells), with and without the bed;
//! - full: besides, both at coarse fidelity (10 × 50). (The bed at 10 × 50 needs the
//!   momentum residual's floor speed, docs/model.md §4.11: without it, once the bed is at
//!   rest its residual, normalised by its own vanishing speeds, stalled at 1.03e-3 and steps
//!   were rejected until Δt was 8e-7 s.)

use runout_case::Fidelity;

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::ideal_gas::{run, shipped_case, without_bed};

/// Largest |m(t)/m(0) − 1| of the gas.
pub const MASS_TOLERANCE: f64 = 1e-9;
/// Largest |P/P_column − 1| in the clear gas at the end.
pub const COLUMN_TOLERANCE: f64 = 1e-11;
/// Largest |P_top/P_top(mass) − 1| at the end.
pub const LEVEL_TOLERANCE: f64 = 1e-8;

/// A bed settling in a closed box of air as an ideal gas.
pub struct IdealGas;

impl Check for IdealGas {
    fn name(&self) -> &'static str {
        "ideal-gas"
    }

    fn description(&self) -> &'static str {
        "air as an ideal gas in a closed box while a bed settles: its mass kept, the isothermal column, the level its mass fixes"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        let fidelities: &[Fidelity] = match size {
            Size::Fast => &[Fidelity::Smoke],
            Size::Full => &[Fidelity::Smoke, Fidelity::Coarse],
        };
        let bed = shipped_case()?;
        let empty = without_bed(&bed);
        for &fidelity in fidelities {
            for (case, what) in [(&bed, "bed"), (&empty, "no bed")] {
                let label = format!("{}, {what}", fidelity.name());
                let r = run(case, fidelity)?;
                println!(
                    "  {label}: gas mass change {:.2e}; clear rows {}, column error {:.2e}; top \
                     pressure {:.3} Pa, against the mass's {:+.2e}; {} steps, {} outer \
                     iterations, {:.1} s",
                    r.mass_change,
                    r.clear_rows,
                    r.column_error,
                    r.top_pressure,
                    r.level_error,
                    r.steps,
                    r.outer_iterations,
                    r.wall_time
                );
                outcome.measure(
                    format!("{label}: |gas mass change|"),
                    r.mass_change,
                    Limit::AtMost(MASS_TOLERANCE),
                );
                outcome.measure(
                    format!("{label}: clear rows"),
                    r.clear_rows as f64,
                    Limit::AtLeast(5.0),
                );
                outcome.measure(
                    format!("{label}: |P/P_column − 1| in the clear gas"),
                    r.column_error,
                    Limit::AtMost(COLUMN_TOLERANCE),
                );
                if case.initial.regions.is_empty() {
                    outcome.measure(
                        format!("{label}: |P_top/P_top(mass) − 1|"),
                        r.level_error.abs(),
                        Limit::AtMost(LEVEL_TOLERANCE),
                    );
                }
            }
        }
        Ok(outcome)
    }
}
