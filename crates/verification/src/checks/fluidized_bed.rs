//! The `fluidized-bed` check (issue 7, settling column, the gas pressure drop): a bed
//! fluidized by gas at twice the minimum fluidization velocity hangs on the gas
//! ([`crate::problems::fluidized_bed`]). Averaged over 1.5–3 s: the gas pressure drop equals
//! the bed's buoyant weight within 1 %, and the floor's solids pressure carries under 1 % of
//! it; the solids mass is conserved to 1e-10 and the gas pressure stays finite. One size.

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::fluidized_bed::{run, AVERAGE_FROM, END, INFLOW};

/// The fluidized bed.
pub struct FluidizedBed;

impl Check for FluidizedBed {
    fn name(&self) -> &'static str {
        "fluidized-bed"
    }

    fn description(&self) -> &'static str {
        "fluidized bed: gas pressure drop equals the bed's buoyant weight"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        let b = run(std::env::var("RUNOUT_VERBOSE").is_ok())?;
        let (drop, weight, p_s, mass, max_eps, steps) =
            (b.drop, b.weight, b.p_s, b.mass_change, b.max_eps, b.steps);
        println!(
            "fluidized bed, U = {INFLOW} m/s, mean over {AVERAGE_FROM}–{END} s: gas pressure drop {drop:.2} Pa, buoyant weight {weight:.2} Pa ({:+.3} %), P_s at the floor {p_s:.3} Pa, max eps {max_eps:.3}, mass change {mass:.2e}, {steps} steps",
            100.0 * (drop / weight - 1.0)
        );
        outcome.holds("p_g finite", b.finite);
        outcome.measure(
            "|drop / weight − 1|",
            (drop / weight - 1.0).abs(),
            Limit::Below(0.01),
        );
        outcome.measure("|relative mass change|", mass.abs(), Limit::Below(1e-10));
        // fluidized (the 1-D bed oscillates with rising voids): the floor's solids pressure
        // carries under 1 % of the weight on average
        outcome.measure(
            "P_s at the floor / weight",
            p_s / weight,
            Limit::Below(0.01),
        );
        Ok(outcome)
    }
}
