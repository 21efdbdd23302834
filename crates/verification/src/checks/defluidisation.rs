//! The `defluidisation` check (issue 60 item 3): a packed bed of 80 µm beads aerated through
//! the floor, the floor then closed ([`crate::problems::defluidisation`]), through the
//! driver. At 1 kPa the basal excess gas pressure halves within 15 % of the rigid bed's
//! pore-pressure diffusion, t½ = τ½ H²/D with D = P εg/β from the run's own bed and drag law
//! ([`crate::references::pore_pressure`]); over three heights t½ scales as H² (the
//! least-squares exponent within 15 % of 2); the aerated profile is steady before the
//! shut-off and the bed neither expands nor compacts (its mean εs within 1 %). At 1 kPa and
//! at 1 atm, where the bed compacts as it drains and the decay is several times slower than
//! the rigid bed's, t½ is within 15 % of the 1-D nonlinear consolidation of the run's bed
//! ([`crate::references::consolidation`]).
//!
//! - fast: H = 0.025 m at 1 kPa (10 cells in the bed), about a minute;
//! - full: H = 0.025, 0.035 and 0.05 m at 1 kPa and 0.05 m at 1 atm (`cargo xtask verify
//!   defluidisation`, ~10 min).

use runout_case::Fidelity;

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::defluidisation::{at, run, shipped_case};

/// The gas's absolute pressure [Pa]: low enough for the gas to store several times more per
/// pascal than the bed's frictional compaction, so that the bed is nearly rigid.
pub const PRESSURE: f64 = 1000.0;
/// The compacting bed's absolute pressure [Pa] (full size).
pub const ATMOSPHERE: f64 = 101_325.0;
/// The compacting bed's height [m] (full size; ~160 s on one thread).
pub const ATMOSPHERE_HEIGHT: f64 = 0.05;
/// Largest |t½/t½_rigid − 1| (1 kPa).
pub const HALF_TIME_TOLERANCE: f64 = 0.15;
/// Largest |t½/t½_consolidation − 1|.
pub const CONSOLIDATION_TOLERANCE: f64 = 0.15;
/// Largest |n/2 − 1| of the exponent n of t½ ∝ Hⁿ.
pub const SCALING_TOLERANCE: f64 = 0.15;

/// Defluidisation of a bed aerated through the floor.
pub struct Defluidisation;

impl Check for Defluidisation {
    fn name(&self) -> &'static str {
        "defluidisation"
    }

    fn description(&self) -> &'static str {
        "a bed aerated through the floor, then shut off: the basal excess pressure halves as pore-pressure diffusion in a rigid bed at 1 kPa, t½ ∝ H², and as the bed's consolidation at 1 kPa and 1 atm"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        let beds: &[(f64, f64)] = match size {
            Size::Fast => &[(PRESSURE, 0.025)],
            Size::Full => &[
                (PRESSURE, 0.025),
                (PRESSURE, 0.035),
                (PRESSURE, 0.05),
                (ATMOSPHERE, ATMOSPHERE_HEIGHT),
            ],
        };
        let base = shipped_case()?;
        let mut points = Vec::new();
        for &(pressure, height) in beds {
            let (case, off) = at(&base, pressure, height)?;
            let r = run(&case, Fidelity::Coarse, off)?;
            let ratio = r.half_time / r.rigid_half_time;
            let consolidation = r.half_time / r.consolidation_half_time;
            println!(
                "  P {pressure} Pa, H {height} m: bed {:.4} m, εs {:.4} (end {:.4}), P {:.1} Pa, \
                 D {:.4e} m²/s; excess {:.2} Pa ({:.4} of it a tenth of the inflow earlier); \
                 t½ {:.2} ms against the rigid bed's {:.2} ms (ratio {ratio:.3}) and the \
                 consolidation's {:.2} ms (ratio {consolidation:.3}); {} steps, {} outer \
                 iterations, {:.1} s",
                r.height,
                r.eps_s.0,
                r.eps_s.1,
                r.pressure,
                r.diffusivity,
                r.excess,
                r.steadiness,
                1e3 * r.half_time,
                1e3 * r.rigid_half_time,
                1e3 * r.consolidation_half_time,
                r.steps,
                r.outer_iterations,
                r.wall_time
            );
            let label = format!("P {pressure} Pa, H {height} m");
            let rigid = pressure == PRESSURE;
            if rigid {
                outcome.measure(
                    format!("{label}: |t½/t½_rigid − 1|"),
                    (ratio - 1.0).abs(),
                    Limit::AtMost(HALF_TIME_TOLERANCE),
                );
            }
            outcome.measure(
                format!("{label}: |t½/t½_consolidation − 1|"),
                (consolidation - 1.0).abs(),
                Limit::AtMost(CONSOLIDATION_TOLERANCE),
            );
            outcome.measure(
                format!("{label}: the excess a tenth of the inflow before the shut-off, over it"),
                r.steadiness,
                Limit::AtLeast(0.98),
            );
            if rigid {
                outcome.measure(
                    format!("{label}: |εs(end)/εs(shut-off) − 1|"),
                    (r.eps_s.1 / r.eps_s.0 - 1.0).abs(),
                    Limit::AtMost(0.01),
                );
                points.push((r.height.ln(), r.half_time.ln()));
            }
        }
        if points.len() >= 3 {
            let n = points.len() as f64;
            let (mx, my) = points
                .iter()
                .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
            let slope = points.iter().map(|(x, y)| (x - mx) * (y - my)).sum::<f64>()
                / points.iter().map(|(x, _)| (x - mx).powi(2)).sum::<f64>();
            println!("  t½ ∝ H^{slope:.3} over the three heights at {PRESSURE} Pa");
            outcome.measure(
                "|n/2 − 1| of t½ ∝ Hⁿ",
                (slope / 2.0 - 1.0).abs(),
                Limit::AtMost(SCALING_TOLERANCE),
            );
        }
        Ok(outcome)
    }
}
