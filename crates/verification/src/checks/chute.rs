//! The `chute` check (issue 7, inclined plane): steady, fully developed flow down a slope
//! with a Johnson–Jackson floor; the 2-D two-fluid solver on a periodic column against the
//! 1-D steady solve of the same equations ([`crate::problems::chute_column`],
//! [`crate::chute1d`], docs/reports/chute.md). εs, u_s and θ must agree within
//! [`CHUTE_TOLERANCE`] of their largest value once the column is steady.
//!
//! - fast: 40 cells at 25°, plane (also: solids mass conserved to 1e-10, drag below 1e-4 of
//!   the weight) and with side walls (docs/model.md §8, issue 23 item 1: the walls must
//!   change the 1-D u_s by more than 0.2 of its largest value, and the two solvers agree
//!   on the changed profile);
//! - full: 80 cells at 15°, 25° and 35°, and at 25° with side walls
//!   ([`Chute::run_full`], which `cargo xtask verify chute` also turns into docs/reports/chute.md).

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::chute_column::{reference, run, ChuteCheck, ChuteCheckSetup, SIDEWALL_WIDTH};

/// Acceptance: largest difference relative to the largest value (issue 7).
pub const CHUTE_TOLERANCE: f64 = 0.02;
/// Smallest relative change of u_s the side walls must make at the fast size.
pub const SIDEWALL_MIN_CHANGE: f64 = 0.2;

/// The full size's runs: slope [deg] and side-wall width [m] (docs/model.md §8), none for a
/// plane flow.
pub const FULL_RUNS: [(f64, Option<f64>); 4] = [
    (15.0, None),
    (25.0, None),
    (35.0, None),
    (25.0, Some(SIDEWALL_WIDTH)),
];

/// One finished run of the full size.
#[derive(Clone, Debug)]
pub struct ChuteRun {
    /// slope [deg]
    pub slope_deg: f64,
    /// side-wall width [m], none for a plane flow
    pub sidewalls: Option<f64>,
    /// the comparison
    pub check: ChuteCheck,
}

/// Steady chute flow: 2-D column against the 1-D reference.
pub struct Chute;

/// Largest change of the 1-D u_s of `c` from `plane_u_s`, relative to the plane's largest
/// |u_s|.
pub fn relative_change(c: &ChuteCheck, plane_u_s: &[f64]) -> f64 {
    let largest = plane_u_s.iter().fold(0.0_f64, |m, u| m.max(u.abs()));
    c.reference
        .u_s
        .iter()
        .zip(plane_u_s)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
        / largest
}

/// The profile agreement of one run: steady, εs, u_s and θ within the tolerance.
fn agreement(outcome: &mut Outcome, label: &str, c: &ChuteCheck) {
    outcome.holds(format!("{label}: steady"), c.column.steady);
    for (what, value) in [
        ("eps error", c.eps_error),
        ("u_s error", c.velocity_error),
        ("theta error", c.theta_error),
    ] {
        outcome.measure(
            format!("{label}: {what}"),
            value,
            Limit::Below(CHUTE_TOLERANCE),
        );
    }
}

impl Chute {
    /// The full size's runs with their outcome (`cargo xtask verify chute` writes the runs
    /// into docs/reports/chute.md).
    pub fn run_full(&self) -> anyhow::Result<(Outcome, Vec<ChuteRun>)> {
        let mut outcome = Outcome::new(self.name(), Size::Full);
        let mut runs = Vec::new();
        for (slope, sidewalls) in FULL_RUNS {
            println!("chute at {slope}°, side walls {sidewalls:?}…");
            let mut setup = ChuteCheckSetup {
                slope_deg: slope,
                ..ChuteCheckSetup::default()
            };
            if let Some(width) = sidewalls {
                setup = setup.with_floor_sidewalls(width);
            }
            let c = run(&setup).map_err(|e| anyhow::anyhow!("chute check at {slope}°: {e}"))?;
            println!(
                "  errors eps {:.2e}, u {:.2e}, theta {:.2e}; {} steps, {:.1} s wall",
                c.eps_error, c.velocity_error, c.theta_error, c.column.steps, c.column.wall_time
            );
            agreement(
                &mut outcome,
                &format!("{slope}° side walls {sidewalls:?}"),
                &c,
            );
            runs.push(ChuteRun {
                slope_deg: slope,
                sidewalls,
                check: c,
            });
        }
        Ok((outcome, runs))
    }

    fn fast(&self, outcome: &mut Outcome) -> anyhow::Result<()> {
        let plane = ChuteCheckSetup {
            cells: 40,
            verbose: std::env::var("RUNOUT_VERBOSE").is_ok(),
            ..ChuteCheckSetup::default()
        };
        let c = run(&plane)?;
        println!(
            "40 cells: t = {:.3} s, {} steps ({} rejected), rate {:.2e}/s, errors: eps {:.2e}, u {:.2e}, theta {:.2e} (pointwise {:.2e}), mass {:.2e}, drag/weight {:.2e}, {:.1} s wall",
            c.column.time,
            c.column.steps,
            c.column.rejected,
            c.column.final_rate,
            c.eps_error,
            c.velocity_error,
            c.theta_error,
            c.theta_pointwise_error,
            c.column.mass_change,
            c.column.drag_to_weight,
            c.column.wall_time
        );
        agreement(outcome, "40 cells 25°", &c);
        outcome.measure(
            "40 cells 25°: |mass change|",
            c.column.mass_change.abs(),
            Limit::Below(1e-10),
        );
        outcome.measure(
            "40 cells 25°: drag/weight",
            c.column.drag_to_weight,
            Limit::Below(1e-4),
        );
        // side walls: the plane reference alone (the 1-D solve takes well under a second)
        let c = run(&plane.clone().with_floor_sidewalls(SIDEWALL_WIDTH))?;
        let plane_reference = reference(&plane)?;
        let change = relative_change(&c, &plane_reference.u_s);
        println!(
            "side walls W = {SIDEWALL_WIDTH} m: u_s changed by {change:.2} of the plane's largest; t = {:.3} s, {} steps, errors eps {:.2e}, u {:.2e}, theta {:.2e}",
            c.column.time, c.column.steps, c.eps_error, c.velocity_error, c.theta_error
        );
        outcome.measure(
            "40 cells 25° side walls: u_s change",
            change,
            Limit::Above(SIDEWALL_MIN_CHANGE),
        );
        agreement(outcome, "40 cells 25° side walls", &c);
        Ok(())
    }
}

impl Check for Chute {
    fn name(&self) -> &'static str {
        "chute"
    }

    fn description(&self) -> &'static str {
        "steady chute flow: 2-D periodic column against the 1-D reference solver"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        match size {
            Size::Fast => {
                let mut outcome = Outcome::new(self.name(), size);
                self.fast(&mut outcome)?;
                Ok(outcome)
            }
            Size::Full => Ok(self.run_full()?.0),
        }
    }
}
