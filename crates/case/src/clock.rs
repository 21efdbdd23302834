//! A case's clock (docs/studies/impact.md §4): the times of a case whose gravity tilts at a time
//! known in advance may count from the tilt; a run counts them from the start.
//!
//! The tilt time t_i of the time criteria: `FreeFall`, t_i = sqrt(2 h / g) with h the
//! height of the lowest initial region holding solids above the floor (the free fall of the
//! block's bottom, docs/studies/impact.md §1); `At(time)`, t_i = time. A field criterion (`FloorCell`,
//! `DenseContact`, `CentroidDrop`) is known only when it fires, so a clock from the impact
//! is refused with it (validate.rs).

use crate::schema::{Case, Clock, Gravity, ImpactCriterion};

impl Case {
    /// Height of the lowest initial region holding solids above the floor [m] (0 without
    /// one, or for one below the domain's origin).
    pub fn release_height(&self) -> f64 {
        self.initial
            .regions
            .iter()
            .filter(|b| b.solids.iter().any(|s| s.eps_s > 0.0))
            .map(|b| b.y.0 - self.domain.y.origin)
            .reduce(f64::min)
            .unwrap_or(0.0)
            .max(0.0)
    }

    /// The time of a tilt fixed in advance [s]: sqrt(2 h / g) for `FreeFall`, the given time
    /// for `At`; `None` for constant gravity and the field criteria.
    pub fn scheduled_tilt_time(&self) -> Option<f64> {
        match &self.gravity {
            Gravity::TiltOnImpact {
                magnitude,
                criterion,
                ..
            } => match criterion {
                ImpactCriterion::FreeFall => Some((2.0 * self.release_height() / magnitude).sqrt()),
                ImpactCriterion::At { time } => Some(*time),
                _ => None,
            },
            Gravity::Constant { .. } => None,
        }
    }

    /// The case with its times counted from the start: with `clock: Impact`, the tilt time
    /// added to the end time and to every profile time, and the clock set to `Start` (so a
    /// resolved case read again is not shifted twice). A case validated with a clock from
    /// the impact has a scheduled tilt; without one the times are left as they are.
    pub fn with_start_clock(mut self) -> Case {
        let shift = self.scheduled_tilt_time();
        let Gravity::TiltOnImpact { clock, .. } = &mut self.gravity else {
            return self;
        };
        if *clock == Clock::Start {
            return self;
        }
        *clock = Clock::Start;
        let Some(t_i) = shift else {
            return self;
        };
        self.run.end_time += t_i;
        for p in &mut self.monitors.profiles {
            p.times.iter_mut().for_each(|t| *t += t_i);
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use crate::schema::{Clock, Gravity, ImpactCriterion};

    fn base() -> crate::Case {
        let file = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../cases/sensitivity/base.ron");
        crate::load_case(&file).unwrap()
    }

    fn set_clock(case: &mut crate::Case, to: Clock) {
        if let Gravity::TiltOnImpact { clock, .. } = &mut case.gravity {
            *clock = to;
        }
    }

    #[test]
    fn a_clock_from_the_impact_shifts_the_end_and_the_profiles_by_the_free_fall() {
        let mut case = base();
        set_clock(&mut case, Clock::Impact);
        let free_fall = (2.0 * 0.40 / 9.80665_f64).sqrt();
        assert_eq!(case.scheduled_tilt_time(), Some(free_fall));
        let resolved = case.at_fidelity(crate::Fidelity::Coarse);
        assert_eq!(resolved.run.end_time, 1.25 + free_fall);
        assert_eq!(resolved.monitors.profiles[0].times, [1.25 + free_fall]);
        // resolved once: the clock is the start's, so resolving again changes nothing
        assert_eq!(resolved.clone().with_start_clock(), resolved);
        let text = ron::ser::to_string(&resolved).unwrap();
        assert!(!text.contains("clock"), "{text}");
    }

    #[test]
    fn a_clock_from_the_start_changes_nothing() {
        let mut case = base();
        set_clock(&mut case, Clock::Start);
        assert_eq!(case.clone().with_start_clock(), case);
        let mut at = case.clone();
        if let Gravity::TiltOnImpact { criterion, .. } = &mut at.gravity {
            *criterion = ImpactCriterion::At { time: 0.3 };
        }
        set_clock(&mut at, Clock::Impact);
        let resolved = at.at_fidelity(crate::Fidelity::Paper);
        assert_eq!(resolved.run.end_time, 1.25 + 0.3);
    }
}
