//! The `defluidisation` check (issue 60 item 3): a packed bed of 80 µm beads aerated through
//! the floor at 1 kPa, the floor then closed ([`crate::problems::defluidisation`]), through
//! the driver. The basal excess gas pressure halves within 15 % of the rigid bed's
//! pore-pressure diffusion, t½ = τ½ H²/D with D = P εg/β from the run's own bed and drag law
//! ([`crate::references::pore_pressure`]); over three heights t½ scales as H² (the
//! least-squares exponent within 15 % of 2); the aerated profile is steady before the
//! shut-off and the bed neither expands nor compacts (its mean εs within 1 %).
//!
//! - fast: H = 0.025 m (10 cells in the bed), about a minute;
//! - full: H = 0.025, 0.035 and 0.05 m (`cargo xtask verify defluidisation`, ~10 min).

use runout_case::Fidelity;

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::defluidisation::{at, run, shipped_case};

/// The gas's absolute pressure [Pa]: low enough for the gas to store ~10× more per pascal
/// than the bed's frictional compaction, so that the bed is nearly rigid.
pub const PRESSURE: f64 = 1000.0;
/// Largest |t½/t½_rigid − 1|.
pub const HALF_TIME_TOLERANCE: f64 = 0.15;
/// Largest |n/2 − 1| of the exponent n of t½ ∝ Hⁿ.
pub const SCALING_TOLERANCE: f64 = 0.15;

/// Defluidisation of a bed aerated through the floor.
pub struct Defluidisation;

impl Check for Defluidisation {
    fn name(&self) -> &'static str {
        "defluidisation"
    }

    fn description(&self) -> &'static str {
        "a bed aerated through the floor, then shut off: the basal excess pressure halves as pore-pressure diffusion in a rigid bed, t½ ∝ H²"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        let heights: &[f64] = match size {
            Size::Fast => &[0.025],
            Size::Full => &[0.025, 0.035, 0.05],
        };
        let base = shipped_case()?;
        let mut points = Vec::new();
        for &height in heights {
            let (case, off) = at(&base, PRESSURE, height)?;
            let r = run(&case, Fidelity::Coarse, off)?;
            let ratio = r.half_time / r.rigid_half_time;
            println!(
                "  H {height} m: bed {:.4} m, εs {:.4} (end {:.4}), P {:.1} Pa, D {:.4e} m²/s; \
                 excess {:.2} Pa ({:.4} of it a tenth of the inflow earlier); t½ {:.2} ms \
                 against the rigid bed's {:.2} ms (ratio {ratio:.3}); {} steps, {} outer \
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
                r.steps,
                r.outer_iterations,
                r.wall_time
            );
            let label = format!("H {height} m");
            outcome.measure(
                format!("{label}: |t½/t½_rigid − 1|"),
                (ratio - 1.0).abs(),
                Limit::AtMost(HALF_TIME_TOLERANCE),
            );
            outcome.measure(
                format!("{label}: the excess a tenth of the inflow before the shut-off, over it"),
                r.steadiness,
                Limit::AtLeast(0.98),
            );
            outcome.measure(
                format!("{label}: |εs(end)/εs(shut-off) − 1|"),
                (r.eps_s.1 / r.eps_s.0 - 1.0).abs(),
                Limit::AtMost(0.01),
            );
            points.push((r.height.ln(), r.half_time.ln()));
        }
        if points.len() >= 3 {
            let n = points.len() as f64;
            let (mx, my) = points
                .iter()
                .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
            let slope = points.iter().map(|(x, y)| (x - mx) * (y - my)).sum::<f64>()
                / points.iter().map(|(x, _)| (x - mx).powi(2)).sum::<f64>();
            println!("  t½ ∝ H^{slope:.3} over the three heights");
            outcome.measure(
                "|n/2 − 1| of t½ ∝ Hⁿ",
                (slope / 2.0 - 1.0).abs(),
                Limit::AtMost(SCALING_TOLERANCE),
            );
        }
        Ok(outcome)
    }
}
