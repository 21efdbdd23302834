//! The paper's slide with a Johnson–Jackson floor, S-JJ-phi with φ = 0.1 (issue 7, last
//! check), run through the driver ([`runout_run::run_case`]): the block falls, gravity
//! tilts on impact, and the flow slides to the paper's t = 1.25 s (1.25 s after the tilt,
//! docs/studies/impact.md §4). The check wants no NaN, εs ≤ εs,max + 0.02 everywhere at every step,
//! and the solids mass conserved within 1e-8 relative. The smoke grid (10× coarser than the
//! paper's) is run to 1.25 s instead of the preset's 0.4 s.

use anyhow::Result;
use runout_case::Fidelity;
use runout_output::RunSummary;

use super::case_copy::sweep_member;

/// The case file of the sensitivity family S-JJ-phi, relative to the workspace root.
pub const CASE_FILE: &str = "cases/sensitivity/S-JJ-phi.ron";
/// The member of the family that is run.
pub const CASE_NAME: &str = "S-JJ-phi_phi=0.1";
/// The end time every fidelity is run to [s].
pub const END_TIME: f64 = 1.25;

/// A finished run: its summary, the end time it had to reach and whether every monitor value
/// in its `bulk.csv` is finite.
#[derive(Clone, Debug)]
pub struct SlideRun {
    /// the driver's summary
    pub summary: RunSummary,
    /// the end time it had to reach [s]
    pub end_time: f64,
    /// no NaN or inf in bulk.csv
    pub finite_monitors: bool,
}

/// Runs S-JJ-phi φ = 0.1 at `fidelity` to 1.25 s in a temporary directory.
pub fn run(fidelity: Fidelity) -> Result<SlideRun> {
    let mut case = sweep_member(CASE_FILE, CASE_NAME)?;
    case.fidelity.smoke.end_time = END_TIME;
    let end_time = case.at_fidelity(fidelity).run.end_time;
    let out = std::env::temp_dir().join(format!(
        "runout-sjjphi-{}-{}",
        fidelity.name(),
        std::process::id()
    ));
    let summary = runout_run::run_case(&case, fidelity, &out, |_| {})?;
    let bulk = std::fs::read_to_string(out.join("bulk.csv"))?;
    let finite_monitors = !bulk.to_ascii_lowercase().contains("nan") && !bulk.contains("inf");
    Ok(SlideRun {
        summary,
        end_time,
        finite_monitors,
    })
}
