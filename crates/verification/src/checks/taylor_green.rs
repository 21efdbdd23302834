//! The `taylor-green` check (issue 6): the decaying Taylor–Green vortex in a free-slip box,
//! a manufactured unsteady solution ([`crate::problems::taylor_green_exact`]), and the
//! per-step mass check.
//!
//! - space order (Richardson in time) ≥ 1.8: fast 8, 16 cells; full 8, 16, 32 (8 steps);
//! - time order (self-convergence, implicit Euler) in [0.9, 1.2): fast 16 cells with 5, 10,
//!   20 steps; full 32 cells with 5 … 40;
//! - the net continuity imbalance of every converged step ≤ [`MASS_TOLERANCE`] of the flow
//!   through the domain: fast 16 cells, 10 steps; full 32 cells, 20 steps (and every run of
//!   the order studies).

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::{
    mass_conservation, taylor_green_space_order, taylor_green_time_order, MASS_TOLERANCE,
};

/// Smallest observed space order.
pub const MIN_SPACE_ORDER: f64 = 1.8;
/// Range of the observed time orders [lo, hi).
pub const TIME_ORDER_RANGE: (f64, f64) = (0.9, 1.2);

/// The Taylor–Green vortex: orders in space and time, mass of every step.
pub struct TaylorGreen;

impl Check for TaylorGreen {
    fn name(&self) -> &'static str {
        "taylor-green"
    }

    fn description(&self) -> &'static str {
        "Taylor-Green vortex: space and time orders, mass of every step"
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
    let space = taylor_green_space_order(&[8, 16], 8)?;
    println!(
        "{}: errors {:?}, orders {:?}",
        space.label, space.errors, space.orders
    );
    outcome.measure(
        format!("{}: smallest order", space.label),
        space.min_order(),
        Limit::AtLeast(MIN_SPACE_ORDER),
    );
    let time = taylor_green_time_order(16, &[5, 10, 20])?;
    println!(
        "{}: differences {:?}, orders {:?}",
        time.label, time.errors, time.orders
    );
    time_orders(outcome, &time);
    let (n, steps) = (16, 10);
    let check = mass_conservation(n, steps)?;
    println!(
        "worst per-step mass ratio {:.2e} over {} steps",
        check.worst,
        check.ratios.len()
    );
    outcome.measure(
        "mass: steps checked",
        check.ratios.len() as f64,
        Limit::Equals(steps as f64),
    );
    outcome.holds("mass: every step within the tolerance", check.passed());
    outcome.measure(
        "mass: worst per-step ratio",
        check.worst,
        Limit::AtMost(MASS_TOLERANCE),
    );
    Ok(())
}

fn time_orders(outcome: &mut Outcome, time: &crate::problems::OrderStudy) {
    let (lo, hi) = TIME_ORDER_RANGE;
    for (k, p) in time.orders.iter().enumerate() {
        outcome.measure(
            format!("{}: order {}", time.label, k + 1),
            *p,
            Limit::Within(lo, hi),
        );
    }
}

fn full(outcome: &mut Outcome) -> anyhow::Result<()> {
    println!("Taylor-Green vortex in a free-slip box (manufactured unsteady solution)");
    let space = taylor_green_space_order(&[8, 16, 32], 8)?;
    super::print_study(&space);
    let ok = space.min_order() >= MIN_SPACE_ORDER;
    println!(
        "    smallest space order {:.3} (expect 2)  {}",
        space.min_order(),
        super::verdict(ok)
    );
    outcome.measure(
        format!("{}: smallest order", space.label),
        space.min_order(),
        Limit::AtLeast(MIN_SPACE_ORDER),
    );
    let time = taylor_green_time_order(32, &[5, 10, 20, 40])?;
    super::print_study(&time);
    let (lo, hi) = TIME_ORDER_RANGE;
    let ok = time.orders.iter().all(|p| (lo..hi).contains(p));
    println!(
        "    time orders {:?} (expect 1)  {}",
        time.orders,
        super::verdict(ok)
    );
    time_orders(outcome, &time);
    let mass = mass_conservation(32, 20)?;
    let worst = mass
        .worst
        .max(space.worst_mass_ratio())
        .max(time.worst_mass_ratio());
    let ok = mass.passed() && worst <= MASS_TOLERANCE;
    println!(
        "  mass: net continuity imbalance of every converged step / flow through the domain: \
         worst {worst:.2e} over all runs above (limit {MASS_TOLERANCE:e})  {}",
        super::verdict(ok)
    );
    outcome.holds("mass: every step within the tolerance", mass.passed());
    outcome.measure(
        "mass: worst ratio over all runs",
        worst,
        Limit::AtMost(MASS_TOLERANCE),
    );
    Ok(())
}
