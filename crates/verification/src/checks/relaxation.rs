//! The `relaxation` check (issue 58): the paper's slide on a Jenkins floor run with family
//! S's under-relaxation and with MFIX's gives the same flow
//! ([`crate::problems::relaxation`]): the interpolated front within one floor cell at every
//! sample, the whole-cell front and the flow thickness at the station within one cell, and
//! max u_s, mean u_s and the floor cell's εs at the station within 0.5 %.
//!
//! - fast: `wall` fidelity (250 × 90 cells, where the pooled momentum residual put the two
//!   fronts eight cells apart; at coarse, 250 × 23, they were one cell apart with it too),
//!   about three minutes for both runs;
//! - full: coarse, `wall` and the paper's grid (1000 × 90, about 20 min).

use runout_case::Fidelity;

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::relaxation::{
    compare, run, shipped_case, shipped_factors, MFIX_FACTORS, STATION_TOLERANCE,
};

/// One case, two relaxations.
pub struct Relaxation;

impl Check for Relaxation {
    fn name(&self) -> &'static str {
        "relaxation"
    }

    fn description(&self) -> &'static str {
        "the paper's slide with family S's and MFIX's under-relaxation: the same front and station numbers"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        let fidelities: &[Fidelity] = match size {
            Size::Fast => &[Fidelity::Wall],
            Size::Full => &[Fidelity::Coarse, Fidelity::Wall, Fidelity::Paper],
        };
        let shipped = shipped_factors(&shipped_case()?);
        for &fidelity in fidelities {
            let label = fidelity.name();
            let a = run(fidelity, shipped)?;
            let b = run(fidelity, MFIX_FACTORS)?;
            for r in [&a, &b] {
                println!(
                    "  {label}, factors {:?}: front at the station {:.3} m, {} steps, {:.1} s wall",
                    r.factors,
                    r.metrics.front_x.unwrap_or(f64::NAN),
                    r.steps,
                    r.wall_time
                );
            }
            let c = compare(&a, &b)?;
            let (dx, dy) = a.cell;
            println!(
                "  {label}: largest front gap {:.4} m at t = {:.3} s (cell {dx:.4} m); at the station: \
                 front gap {:.4} m, thickness gap {:.4} m (row {dy:.4} m)",
                c.front_gap.0, c.front_gap.1, c.station_front_gap, c.thickness_gap
            );
            // a whole-cell quantity one cell apart differs by the cell's width to round-off
            let one_cell = |w: f64| Limit::AtMost(w * (1.0 + 1e-9));
            outcome.measure(
                format!("{label}: largest |front gap| over time [m]"),
                c.front_gap.0,
                one_cell(dx),
            );
            outcome.measure(
                format!("{label}: |whole-cell front gap| at the station [m]"),
                c.station_front_gap,
                one_cell(dx),
            );
            outcome.measure(
                format!("{label}: |flow thickness gap| at the station [m]"),
                c.thickness_gap,
                one_cell(dy),
            );
            for (name, x, y, rel) in c.station {
                println!(
                    "  {label}: {name} {x:.5} against {y:.5} ({:.2} %)",
                    100.0 * rel
                );
                outcome.measure(
                    format!("{label}: {name} at the station, relative difference"),
                    rel,
                    Limit::AtMost(STATION_TOLERANCE),
                );
            }
        }
        Ok(outcome)
    }
}
