//! MFIX's adaptive time-step controller (docs/model.md §4.12).

use serde::{Deserialize, Serialize};

/// The adaptive time-step controller of MFIX (docs/model.md §4.12): after every block of
/// `steps_per_change` converged steps (MFIX `STEPS_MIN` = 5) it compares the outer iterations per simulated second with the previous block and
/// keeps or reverses the direction of change; a failed step shrinks Δt and resets.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DtController {
    dt: f64,
    min: f64,
    max: f64,
    factor: f64,
    direction: f64,
    iterations: usize,
    steps: usize,
    steps_per_change: usize,
    failure_factor: f64,
    cost_old: f64,
}

impl DtController {
    /// Starts at `initial`, bounded by [min, max], changing by `factor` (MFIX `DT_FAC`) after
    /// every `steps_per_change` converged steps (MFIX `STEPS_MIN` = 5; at least 1). A failed
    /// step multiplies Δt by `factor` (MFIX) or by [`DtController::with_failure_factor`]'s.
    pub fn new(initial: f64, min: f64, max: f64, factor: f64, steps_per_change: usize) -> Self {
        DtController {
            failure_factor: factor,
            dt: initial,
            min,
            max,
            factor,
            direction: -1.0,
            iterations: 0,
            steps: 0,
            steps_per_change: steps_per_change.max(1),
            cost_old: 0.0,
        }
    }

    /// The controller with `failure_factor` instead of `factor` after a failed step.
    pub fn with_failure_factor(mut self, failure_factor: f64) -> Self {
        self.failure_factor = failure_factor;
        self
    }

    /// The Δt to try next [s].
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Records a converged step of `dt` that took `iterations` outer iterations (`hit_cap`:
    /// the iteration limit was reached).
    pub fn converged(&mut self, dt: f64, iterations: usize, hit_cap: bool) {
        if self.factor >= 1.0 {
            return;
        }
        self.iterations += iterations;
        self.steps += 1;
        if self.steps < self.steps_per_change {
            return;
        }
        let cost = self.iterations as f64 / (self.steps as f64 * dt);
        if cost > self.cost_old {
            self.direction = -self.direction;
        }
        if self.direction > 0.0 {
            if !hit_cap {
                self.dt = (self.dt / self.factor).min(self.max);
            }
        } else {
            self.dt *= self.factor;
        }
        self.iterations = 0;
        self.steps = 0;
        self.cost_old = cost;
    }

    /// Takes `dt` as the Δt just tried when it was shorter than the controller's (a step
    /// cut to land on the end time), so that a failure shrinks from it.
    pub fn shorten_to(&mut self, dt: f64) {
        self.dt = self.dt.min(dt);
    }

    /// Records a failed step; returns `false` if Δt fell below the minimum (the run stops).
    pub fn failed(&mut self) -> bool {
        self.direction = -1.0;
        self.iterations = 0;
        self.steps = 0;
        self.cost_old = 0.0;
        self.dt *= self.failure_factor.min(0.999_999);
        self.dt >= self.min
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dt_controller_follows_mfix_rules() {
        let mut c = DtController::new(1e-3, 1e-6, 1e-2, 0.9, 5);
        // first block of 5: cost > 0 = old → direction flips from − to +: Δt grows
        for _ in 0..5 {
            c.converged(1e-3, 10, false);
        }
        assert!((c.dt() - 1e-3 / 0.9).abs() < 1e-15);
        // a failure shrinks Δt and resets the direction
        assert!(c.failed());
        assert!((c.dt() - 1e-3).abs() < 1e-15);
        let mut c = DtController::new(2e-6, 1e-6, 1e-2, 0.5, 5);
        assert!(c.failed());
        assert!(!c.failed(), "below dt_min the run must stop");
    }

    #[test]
    fn dt_controller_changes_after_every_block_of_steps_per_change() {
        // one step per change: Δt grows at every converged step while the iterations per
        // simulated second fall (same iterations at a larger Δt)
        let mut c = DtController::new(1e-4, 1e-6, 1e-3, 0.9, 1);
        for n in 1..=10 {
            c.converged(c.dt(), 8, false);
            assert!((c.dt() - 1e-4 / 0.9_f64.powi(n)).abs() < 1e-15, "step {n}");
        }
        // a step that costs more per simulated second turns the direction: Δt shrinks
        let before = c.dt();
        c.converged(before, 40, false);
        assert!((c.dt() - before * 0.9).abs() < 1e-15);
        // at the cap it stays
        let mut c = DtController::new(1e-3, 1e-6, 1e-3, 0.9, 1);
        c.converged(1e-3, 8, false);
        assert_eq!(c.dt(), 1e-3);
        // a failure factor of its own
        let mut c = DtController::new(1e-3, 1e-6, 1e-3, 0.9, 5).with_failure_factor(0.5);
        assert!(c.failed());
        assert!((c.dt() - 5e-4).abs() < 1e-15);
    }
}
