//! The `cooling` check (issue 7, first check): homogeneous cooling through the whole
//! two-fluid step ([`crate::problems::cooling_box`]). To t = 5 ms (about three Haff times)
//! with 400 and 800 steps: θ uniform (every cell within 1e-6 of the mean), the finer within
//! 1 % of the cooling law with viscous damping ([`crate::references::damped_cooling_theta`]),
//! first order in Δt (|order − 1| < 0.15), and no motion: every velocity below 1e-8 m/s
//! and εs unchanged to 1e-9. One size (about a second).

use runout_solver::two_fluid::TwoFluid;

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::cooling_box::{cool, exact, EPS_S, THETA0};

/// Homogeneous cooling through the two-fluid step.
pub struct Cooling;

/// The mean θ of the box and the largest deviation of a cell from it, relative to the mean.
fn mean_theta(tf: &TwoFluid) -> (f64, f64) {
    let th = &tf.solids(0).theta;
    let mean = th.iter().sum::<f64>() / th.len() as f64;
    let spread = th.iter().fold(0.0_f64, |m, t| m.max((t - mean).abs()));
    (mean, spread / mean)
}

/// Largest velocity of either phase and largest εs drift of a run.
fn at_rest(outcome: &mut Outcome, label: &str, tf: &TwoFluid) {
    let s = tf.solids(0);
    let speed =
        s.u.iter()
            .chain(&s.v)
            .chain(tf.u_g())
            .chain(tf.v_g())
            .fold(0.0_f64, |m, x| m.max(x.abs()));
    // the linear solvers' round-off only: 1e-8 m/s against a fluctuation speed √θ ≥ 0.2 m/s
    outcome.measure(
        format!("{label}: largest velocity [m/s]"),
        speed,
        Limit::Below(1e-8),
    );
    let drift = s
        .eps()
        .iter()
        .fold(0.0_f64, |m, e| m.max((e - EPS_S).abs()));
    outcome.measure(format!("{label}: εs drift"), drift, Limit::Below(1e-9));
}

impl Check for Cooling {
    fn name(&self) -> &'static str {
        "cooling"
    }

    fn description(&self) -> &'static str {
        "homogeneous cooling through the two-fluid step against the damped Haff law"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        // about three Haff times t0 = 2/(a √θ0)
        let t_end = 0.005;
        let (coarse, fine) = (cool(t_end, 400)?, cool(t_end, 800)?);
        let want = exact(t_end);
        let (t1, spread1) = mean_theta(&coarse);
        let (t2, spread2) = mean_theta(&fine);
        // uniform: every cell the same to the linear solvers' tolerance
        for (label, spread) in [("400 steps", spread1), ("800 steps", spread2)] {
            outcome.measure(
                format!("{label}: largest |θ − mean|/mean"),
                spread,
                Limit::AtMost(1e-6),
            );
        }
        let (e1, e2) = ((t1 - want) / want, (t2 - want) / want);
        println!(
            "θ(t_end): exact {want:.6e} (θ0 = {THETA0}); 400 steps {t1:.6e} ({:+.3} %), 800 steps {t2:.6e} ({:+.3} %); order {:.2}",
            e1 * 100.0,
            e2 * 100.0,
            (e1 / e2).log2()
        );
        outcome.measure("800 steps: |relative error|", e2.abs(), Limit::Below(0.01));
        // implicit Euler: first order in Δt
        let order = (e1 / e2).log2();
        outcome.measure("|order in dt − 1|", (order - 1.0).abs(), Limit::Below(0.15));
        // no motion, no change of εs or gas pressure gradient
        at_rest(&mut outcome, "400 steps", &coarse);
        at_rest(&mut outcome, "800 steps", &fine);
        Ok(outcome)
    }
}
