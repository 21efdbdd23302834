//! The `settling` check (issue 7, second check): 0.4 s of a suspension settling in a closed
//! box ([`crate::problems::settling_column`]): solids mass conserved to 1e-10, εs ≤
//! εs,max + 0.01, the fields finite, the top empty (εs < 1e-3) and the bottom packed
//! (εs > 0.55), and the settled bed's weight above the bottom cells' centres carried by the
//! solids pressure there within 1 % (the vertical momentum balance of the bed at rest). One
//! size (400 steps of 1 ms).

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::settling_column::column;

/// The settling column.
pub struct Settling;

impl Check for Settling {
    fn name(&self) -> &'static str {
        "settling"
    }

    fn description(&self) -> &'static str {
        "settling column: packed bed carries its weight by the solids pressure"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        let (tf, mass0) = column(400, 1e-3, std::env::var("RUNOUT_VERBOSE").is_ok())?;
        let grid = tf.grid();
        let (nx, ny) = (grid.nx(), grid.ny());
        let mass = tf.solids_mass(0);
        outcome.measure(
            "|relative mass change|",
            (mass / mass0 - 1.0).abs(),
            Limit::AtMost(1e-10),
        );
        let max_eps = tf.solids(0).eps().iter().cloned().fold(0.0, f64::max);
        outcome.measure("max εs", max_eps, Limit::AtMost(0.65 + 0.01));
        outcome.holds(
            "εs and p_g finite",
            tf.solids(0)
                .eps()
                .iter()
                .chain(tf.p_g())
                .all(|x| x.is_finite()),
        );
        // the bed has settled: the top of the domain is empty, the bottom packed
        outcome.measure(
            "εs in the top cell",
            tf.solids(0).eps()[nx * (ny - 1)],
            Limit::Below(1e-3),
        );
        outcome.measure(
            "εs in the bottom cell",
            tf.solids(0).eps()[0],
            Limit::Above(0.55),
        );
        // weight per area above the bottom cells' centres, carried by P_s there
        let (width, dy, g) = (grid.x.length(), grid.y.widths()[0], 9.81);
        let rho_s = 2000.0;
        let eps_bottom: f64 = (0..nx).map(|i| tf.solids(0).eps()[i]).sum::<f64>() / nx as f64;
        let weight = mass0 * g / width - rho_s * eps_bottom * g * 0.5 * dy;
        let p_s_bottom: f64 = (0..nx).map(|i| tf.p_s(0)[i]).sum::<f64>() / nx as f64;
        println!("settled bed: P_s at the bottom centres {p_s_bottom:.2} Pa, weight above them {weight:.2} Pa, max eps {max_eps:.4}");
        outcome.measure(
            "|P_s at the floor / weight − 1|",
            (p_s_bottom / weight - 1.0).abs(),
            Limit::Below(0.01),
        );
        Ok(outcome)
    }
}
