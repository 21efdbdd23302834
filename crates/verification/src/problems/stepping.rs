//! Stepping a two-fluid solver from a problem, as the driver would, for the checks that
//! sample the solver's state between steps (the driver writes only its monitors).

use anyhow::{bail, Result};
use runout_case::Case;
use runout_solver::two_fluid::TwoFluid;

/// How a problem steps a solver itself, as the driver would: Δt from `dt.0`, growing by 1.2
/// to `dt.2` while steps converge, halved when one does not, and given up below `dt.1`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Stepping {
    /// residual, θ residual and divergence tolerances, largest outer iterations
    pub(crate) tolerances: (f64, f64, f64, usize),
    /// initial, smallest and largest Δt [s]
    pub(crate) dt: (f64, f64, f64),
}

impl Stepping {
    /// The case's own controls (`run.tolerances`, `run.dt`).
    pub(crate) fn of(case: &Case) -> Self {
        let (tol, dt) = (&case.run.tolerances, &case.run.dt);
        Stepping {
            tolerances: (
                tol.residual,
                tol.theta_residual,
                tol.diverge,
                tol.max_iterations as usize,
            ),
            dt: (dt.initial, dt.min, dt.max),
        }
    }

    /// Steps `tf` from `*time` to `until`, calling `sample` after every converged step; `dt`
    /// carries the time step from one call to the next.
    pub(crate) fn march(
        self,
        tf: &mut TwoFluid,
        (time, dt): (&mut f64, &mut f64),
        until: f64,
        mut sample: impl FnMut(f64, &TwoFluid),
    ) -> Result<()> {
        let (residual, theta_residual, diverge, iterations) = self.tolerances;
        while *time < until - 1e-12 {
            let this = dt.min(until - *time);
            let step = tf.step(this, residual, theta_residual, diverge, iterations)?;
            if !step.converged {
                *dt *= 0.5;
                if *dt < self.dt.1 {
                    bail!("the step at t = {time} s did not converge: {step:?}");
                }
                continue;
            }
            *time += this;
            sample(*time, tf);
            *dt = (*dt * 1.2).min(self.dt.2);
        }
        Ok(())
    }
}
