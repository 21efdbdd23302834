//! The `release` check (issue 57 item 2): a pile given as a polygon in world coordinates
//! and held by a gate ([`crate::problems::release`]): the released mass is the polygon's to
//! 1e-10, the pile is at rest once settled until the gate opens and flows past it after, and
//! the solids mass is conserved.
//!
//! - fast: 100 × 30 cells (5 mm);
//! - full: 100 × 30 and 200 × 60.

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::release::{run_pile, GATE, MASS_DRIFT, REST_SPEED, SETTLED};

/// The gated pile on a slope.
pub struct Release;

impl Check for Release {
    fn name(&self) -> &'static str {
        "release"
    }

    fn description(&self) -> &'static str {
        "a polygon pile behind a gate on a 30° slope: its mass, at rest until the gate opens, then flowing"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        let grids: &[(usize, usize)] = match size {
            Size::Fast => &[(100, 30)],
            Size::Full => &[(100, 30), (200, 60)],
        };
        let (_, _, opens) = GATE;
        for &(nx, ny) in grids {
            let r = run_pile((nx, ny))?;
            println!(
                "  {nx} × {ny}: mass/(area εs ρs) − 1 = {:.2e}, drift {:.2e}; {SETTLED}–{opens} s: mean speed ≤ {:.2e} m/s, \
                 front ≤ {:.4} m (gate face {:.4} m); 0.2 s after: front {:.4} m",
                r.mass_error, r.mass_drift, r.rest_speed, r.front_before, r.gate_face, r.front_after
            );
            let at = format!("{nx} × {ny}");
            outcome.measure(
                format!("{at}: |released mass/(area εs ρs) − 1|"),
                r.mass_error.abs(),
                Limit::AtMost(1e-10),
            );
            outcome.measure(
                format!("{at}: |solids mass drift|"),
                r.mass_drift,
                Limit::AtMost(MASS_DRIFT),
            );
            outcome.measure(
                format!("{at}: mean speed from {SETTLED} s until the gate opens [m/s]"),
                r.rest_speed,
                Limit::AtMost(REST_SPEED),
            );
            outcome.measure(
                format!("{at}: front before the gate opens − gate face [m]"),
                r.front_before - r.gate_face,
                Limit::AtMost(1e-9),
            );
            outcome.measure(
                format!("{at}: front 0.2 s after the gate opens − gate face [m]"),
                r.front_after - r.gate_face,
                Limit::AtLeast(0.05),
            );
        }
        Ok(outcome)
    }
}
