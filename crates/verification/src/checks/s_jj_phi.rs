//! The `s-jj-phi` check (issue 7, last check): the paper's slide with a Johnson–Jackson
//! floor, φ = 0.1, through the driver to t = 1.25 s ([`crate::problems::s_jj_phi`]): the run
//! completes, reaches 1.25 s, has no NaN or inf in its monitors, conserves the solids mass
//! within 1e-8 and keeps εs ≤ εs,max + 0.02.
//!
//! - fast: the smoke fidelity (10× coarser than the paper's grid);
//! - full: smoke and coarse (several minutes).

use runout_case::Fidelity;
use runout_output::RunStatus;

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::s_jj_phi::{run, SlideRun};

/// S-JJ-phi φ = 0.1 to 1.25 s.
pub struct SJjPhi;

fn judge(outcome: &mut Outcome, fidelity: Fidelity, r: &SlideRun) {
    let s = &r.summary;
    println!(
        "S-JJ-phi φ = 0.1 at {}: {:?}, t = {} s, {} steps ({} rejected), {:.1} outer it./step, \
         mass change {:.2e}, max εs {:.4}, {:.1} s wall, {:.1} s wall per simulated second",
        fidelity.name(),
        s.status,
        s.simulated_time,
        s.steps,
        s.rejected_steps,
        s.outer_iterations as f64 / s.steps.max(1) as f64,
        s.solids_mass_change,
        s.max_eps_s,
        s.wall_time,
        s.wall_time / s.simulated_time
    );
    let label = fidelity.name();
    outcome.holds(format!("{label}: monitors finite"), r.finite_monitors);
    outcome.holds(
        format!("{label}: completed"),
        s.status == RunStatus::Completed,
    );
    outcome.measure(
        format!("{label}: |t_end − {}| [s]", r.end_time),
        (s.simulated_time - r.end_time).abs(),
        Limit::Below(1e-9),
    );
    outcome.measure(
        format!("{label}: |solids mass change|"),
        s.solids_mass_change.abs(),
        Limit::AtMost(1e-8),
    );
    outcome.measure(
        format!("{label}: max εs"),
        s.max_eps_s,
        Limit::AtMost(0.65 + 0.02),
    );
}

impl Check for SJjPhi {
    fn name(&self) -> &'static str {
        "s-jj-phi"
    }

    fn description(&self) -> &'static str {
        "S-JJ-phi φ = 0.1 through the driver to 1.25 s: finite, mass, packing"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        let fidelities: &[Fidelity] = match size {
            Size::Fast => &[Fidelity::Smoke],
            Size::Full => &[Fidelity::Smoke, Fidelity::Coarse],
        };
        for &fidelity in fidelities {
            let r = run(fidelity)?;
            judge(&mut outcome, fidelity, &r);
        }
        Ok(outcome)
    }
}
