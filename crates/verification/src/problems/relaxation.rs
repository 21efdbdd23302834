//! Issue 58's two-relaxation problem: an under-relaxation factor changes the path of a
//! step's outer iterations, not the converged step, so one case run with two sets of factors
//! must give the same flow. The case is the paper's slide on a Jenkins floor, S-JEN-d with
//! d = 0.5 mm (cases/sensitivity/S-JEN-d.ron), run once with family S's factors (velocity
//! 0.7, θ 1.0, pressure 1.0) and once with MFIX's (0.5, 0.5, 0.8), everything else as
//! shipped. With the momentum residual pooled over every node as MFIX's `calc_resid.f`
//! does, the two parted at the head of the slide: at `wall` fidelity the floor front at the
//! station time was 13.12 m with family S's factors and 13.76 m with MFIX's, eight cells
//! apart, while max u_s agreed within 0.5 % — the packed body's large a_P hid the head's
//! residual (docs/model.md §4.11). The comparison: the interpolated front at every sample
//! of the first run from the impact on against the second's interpolated in time, the
//! whole-cell front and
//! the flow thickness at the station (one cell each), and max u_s, mean u_s and the floor
//! cell's εs at the station (relative).

use anyhow::{bail, Result};
use runout_case::{Case, Fidelity};
use runout_mesh::{interpolate, Beyond};
use runout_post::front::front_series;
use runout_post::metrics::PROFILE_TIME;
use runout_post::run::{run_metrics, RunMetrics};

use super::case_copy::sweep_member;

/// The sweep file, relative to the workspace root.
pub const CASE_FILE: &str = "cases/sensitivity/S-JEN-d.ron";
/// The member of the sweep that is run.
pub const CASE_NAME: &str = "S-JEN-d_d=0.0005";
/// MFIX's factors (velocity, θ, pressure: `UR_FAC(3..5)`, `UR_FAC(8)`, `UR_FAC(1)`).
pub const MFIX_FACTORS: Factors = Factors {
    velocity: 0.5,
    theta: 0.5,
    pressure: 0.8,
};
/// Largest relative difference of a station number between the two runs (issue 58).
pub const STATION_TOLERANCE: f64 = 0.005;

/// Under-relaxation factors of velocity, θ and the gas pressure correction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Factors {
    /// momentum of every phase
    pub velocity: f64,
    /// granular energy
    pub theta: f64,
    /// gas pressure correction
    pub pressure: f64,
}

/// One run of the case.
#[derive(Clone, Debug)]
pub struct RelaxationRun {
    /// the factors it ran with
    pub factors: Factors,
    /// the interpolated front against time, (t, x)
    pub front: Vec<(f64, f64)>,
    /// what `runout post` reads at the station
    pub metrics: RunMetrics,
    /// the floor cells' width and the first row's height at the station [m]
    pub cell: (f64, f64),
    /// converged steps
    pub steps: u64,
    /// wall time [s]
    pub wall_time: f64,
}

/// The shipped case (every fidelity).
pub fn shipped_case() -> Result<Case> {
    sweep_member(CASE_FILE, CASE_NAME)
}

/// The shipped case's own factors.
pub fn shipped_factors(case: &Case) -> Factors {
    let r = &case.numerics.relaxation;
    Factors {
        velocity: r.velocity,
        theta: r.theta,
        pressure: r.pressure,
    }
}

/// Runs the shipped case at `fidelity` with `factors` in a temporary directory.
pub fn run(fidelity: Fidelity, factors: Factors) -> Result<RelaxationRun> {
    let mut case = shipped_case()?;
    let r = &mut case.numerics.relaxation;
    (r.velocity, r.theta, r.pressure) = (factors.velocity, factors.theta, factors.pressure);
    let resolved = case.at_fidelity(fidelity);
    let grid = resolved.grid()?;
    let out = std::env::temp_dir().join(format!(
        "runout-relaxation-{}-{}-{}",
        fidelity.name(),
        factors.velocity,
        std::process::id()
    ));
    let summary = runout_run::run_case(&case, fidelity, &out, |_| {})?;
    let (_, front) = front_series(&out).map_err(anyhow::Error::msg)?;
    let metrics = run_metrics(&out, &[]).map_err(anyhow::Error::msg)?;
    let at = metrics.front_x.unwrap_or(grid.x.start());
    let column = grid
        .x
        .faces()
        .partition_point(|&f| f < at)
        .clamp(1, grid.nx());
    let cell = (grid.x.widths()[column - 1], grid.y.widths()[0]);
    let _ = std::fs::remove_dir_all(&out);
    Ok(RelaxationRun {
        factors,
        front,
        metrics,
        cell,
        steps: summary.steps,
        wall_time: summary.wall_time,
    })
}

/// The two runs compared (module doc).
#[derive(Clone, Debug)]
pub struct Comparison {
    /// the largest |front difference| over the first run's samples from the impact on where
    /// both have a front [m], and the time it is at [s]
    pub front_gap: (f64, f64),
    /// |whole-cell front difference| at the station [m]
    pub station_front_gap: f64,
    /// |flow thickness difference| at the station [m]
    pub thickness_gap: f64,
    /// (name, first, second, |relative difference|) of max u_s, mean u_s, floor εs
    pub station: Vec<(&'static str, f64, f64, f64)>,
}

/// Reads one station number of a run.
type StationNumber = fn(&RunMetrics) -> Option<f64>;

/// Compares run `b` with run `a` (module doc); a number missing from either is an error.
pub fn compare(a: &RelaxationRun, b: &RelaxationRun) -> Result<Comparison> {
    // from the impact (the paper's clock's zero): before it the block falls, and the floor
    // front appears in one jump of several metres when its lowest grains reach the floor
    let impact = a.metrics.station_time - PROFILE_TIME;
    let mut front_gap = (0.0, 0.0);
    let (b_times, b_fronts): (Vec<f64>, Vec<f64>) = b.front.iter().copied().unzip();
    for &(t, x) in a.front.iter().filter(|(t, _)| *t >= impact) {
        if let Some(y) = interpolate(&b_times, &b_fronts, t, Beyond::Missing) {
            if (x - y).abs() > front_gap.0 {
                front_gap = ((x - y).abs(), t);
            }
        }
    }
    let both = |name: &str, f: StationNumber| -> Result<(f64, f64)> {
        match (f(&a.metrics), f(&b.metrics)) {
            (Some(x), Some(y)) => Ok((x, y)),
            _ => bail!("{name} is missing from a run"),
        }
    };
    let front = both("the station front", |m| m.front_x)?;
    let thickness = both("the flow thickness", |m| m.flow.flow_thickness)?;
    let mut station = Vec::new();
    let numbers: [(&'static str, StationNumber); 3] = [
        ("max u_s", |m| m.flow.max_u_s),
        ("mean u_s", |m| m.mean_u_s),
        ("floor εs", |m| m.flow.floor_eps_s),
    ];
    for (name, f) in numbers {
        let (x, y) = both(name, f)?;
        station.push((name, x, y, ((y - x) / x).abs()));
    }
    Ok(Comparison {
        front_gap,
        station_front_gap: (front.1 - front.0).abs(),
        thickness_gap: (thickness.1 - thickness.0).abs(),
        station,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shipped_case_is_family_s_with_its_own_factors() {
        let case = shipped_case().expect("the sweep loads");
        let f = shipped_factors(&case);
        assert_eq!((f.velocity, f.theta, f.pressure), (0.7, 1.0, 1.0));
        assert_ne!(f, MFIX_FACTORS);
    }
}
