//! The `haff` check (issue 7, homogeneous cooling of the energy equation alone): the
//! assembled granular-energy equation in a closed box at rest against Haff's law
//! ([`crate::problems::haff_energy`], [`crate::references::haff`]). To t = 2 t0 with 100,
//! 200 and 400 implicit-Euler steps: no spatial variation (spread ≤ 1e-12 θ), the finest
//! within 1 % of the law, and the observed order in Δt in [0.9, 1.1). One size: it takes
//! well under a second.

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::haff_energy::{cool, t0, THETA0};
use crate::references::haff_theta;

/// Haff's law through the granular-energy equation.
pub struct Haff;

impl Check for Haff {
    fn name(&self) -> &'static str {
        "haff"
    }

    fn description(&self) -> &'static str {
        "granular-energy equation in a box at rest against Haff's law"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        let t_end = 2.0 * t0();
        let exact = haff_theta(THETA0, t_end, t0());
        let mut errors = Vec::new();
        for steps in [100, 200, 400] {
            let theta = cool(t_end, steps)?;
            // no spatial variation appears in a uniform closed box
            let spread = theta.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
                - theta.iter().cloned().fold(f64::INFINITY, f64::min);
            outcome.measure(
                format!("{steps} steps: spread of θ [m²/s²]"),
                spread,
                Limit::AtMost(1e-12 * exact),
            );
            errors.push((theta[0] - exact).abs() / exact);
        }
        let order = (errors[1] / errors[2]).log2();
        println!("Haff cooling to t = 2 t0: relative errors {errors:?}, order in dt {order:.3}");
        outcome.measure("400 steps: relative error", errors[2], Limit::Below(0.01));
        outcome.measure("order in dt", order, Limit::Within(0.9, 1.1));
        Ok(outcome)
    }
}
