//! The `bed-path` check (issue 57 item 1): a floor of several bends in bed-following
//! coordinates ([`crate::problems::bed_path`]):
//! - a thin block sliding down a path of four slopes on a free-slip floor has the speed its
//!   centre's drop gives, ū = √(2 g Δz_c), within 2 % at every sample once it has dropped
//!   1 cm (energy neither made nor lost beyond the grains' own dissipation);
//! - a layer on a path whose every piece is flatter than the beads' friction angle stays put
//!   (its largest speed below 1e-4 m/s), and the same layer with its first piece at 30° flows
//!   (above 0.05 m/s).
//!
//! - fast: the slide on 240 × 8 cells, the layers on 120 × 4;
//! - full: the slide on 240 × 8 and 480 × 16, the layers on 120 × 4 and 240 × 8.

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::bed_path::{run_rest, run_slide, SLIDE_SETTLED_DROP};

/// The largest |ū/√(2 g Δz_c) − 1| of the slide [-].
pub const SLIDE_TOLERANCE: f64 = 0.02;
/// The largest speed of the layer at rest [m s⁻¹]: 0.03 % of √(g h) for h = 1 cm.
pub const REST_SPEED: f64 = 1e-4;
/// The least speed of the contrast's layer on a 30° piece [m s⁻¹].
pub const FLOWING_SPEED: f64 = 0.05;

/// The slide and the layers on paths of bends.
pub struct BedPath;

impl Check for BedPath {
    fn name(&self) -> &'static str {
        "bed-path"
    }

    fn description(&self) -> &'static str {
        "a floor of several bends: a frictionless slide's speed √(2 g Δz), a layer at rest on slopes below its friction angle"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        type Grids = &'static [(usize, usize)];
        let (slides, layers): (Grids, Grids) = match size {
            Size::Fast => (&[(240, 8)], &[(120, 4)]),
            Size::Full => (&[(240, 8), (480, 16)], &[(120, 4), (240, 8)]),
        };
        println!("a block sliding on a free-slip path of 30°, 10°, 20° and 0°:");
        for &(nx, ny) in slides {
            let samples = run_slide((nx, ny))?;
            let judged: Vec<_> = samples
                .iter()
                .filter(|s| s.drop >= SLIDE_SETTLED_DROP)
                .collect();
            let worst = judged
                .iter()
                .map(|s| s.speed / s.law - 1.0)
                .fold(0.0f64, |w, e| if e.abs() > w.abs() { e } else { w });
            for s in samples.iter().step_by(5) {
                println!(
                    "  {nx:>3} × {ny:<2} t {:.2} s: centre at x {:.3} m, dropped {:.4} m, ū {:.4} m/s, √(2 g Δz) {:.4} m/s ({:+.2} %)",
                    s.time,
                    s.x,
                    s.drop,
                    s.speed,
                    s.law,
                    100.0 * (s.speed / s.law - 1.0)
                );
            }
            outcome.measure(
                format!(
                    "slide on {nx} × {ny}: largest |ū/√(2 g Δz_c) − 1| ({} samples)",
                    judged.len()
                ),
                worst.abs(),
                Limit::AtMost(SLIDE_TOLERANCE),
            );
            let last = samples.last().map_or(0.0, |s| s.x);
            outcome.holds(
                format!(
                    "slide on {nx} × {ny}: the centre reaches the run-out (x {last:.3} m > 0.9 m)"
                ),
                last > 0.9,
            );
        }
        println!(
            "a layer wall to wall on a no-slip path, first piece 15° (then 5°, 12°, 0°) and 30°:"
        );
        for &(nx, ny) in layers {
            for (first, limit) in [
                (15.0, Limit::AtMost(REST_SPEED)),
                (30.0, Limit::AtLeast(FLOWING_SPEED)),
            ] {
                let r = run_rest((nx, ny), first)?;
                println!(
                    "  {nx:>3} × {ny:<2} first piece {first}°: largest speed {:.2e} m/s, centre moved {:.2e} m, \
                     floor P_s over the weight above the cell centre {:.3}–{:.3} (not judged)",
                    r.largest_speed, r.centre_moved, r.pressure_ratio.0, r.pressure_ratio.1
                );
                outcome.measure(
                    format!("layer on {nx} × {ny}, first piece {first}°: largest speed [m/s]"),
                    r.largest_speed,
                    limit,
                );
            }
        }
        Ok(outcome)
    }
}
