//! The wall-normal station profile a run writes (`profile_x<x>_t<t>.csv`: y, εs, u_s, θ).

use std::path::Path;

use crate::chosen::Run;
use crate::folder::csv_files;
use crate::metrics::{profile_metrics, FlowMetrics};
use crate::table::Table;

/// Wall-normal profile at the station: distance from the floor y (the domains start at
/// y = 0) and εs, u_s, θ.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    /// cell-centre heights [m]
    pub y: Vec<f64>,
    /// solids volume fraction [-]
    pub eps_s: Vec<f64>,
    /// solids x-velocity [m/s]
    pub u_s: Vec<f64>,
    /// granular temperature [m²/s²]
    pub theta: Vec<f64>,
}

impl Profile {
    /// Reads a profile file (columns y, eps_s, u_s, theta).
    pub fn read(path: &Path) -> Result<Profile, String> {
        let t = Table::read(path)?;
        Ok(Profile {
            y: t.column("y")?,
            eps_s: t.column("eps_s")?,
            u_s: t.column("u_s")?,
            theta: t.column("theta")?,
        })
    }

    /// The summary.csv metrics of this profile ([`crate::metrics`] definitions).
    pub fn metrics(&self) -> FlowMetrics {
        let rows: Vec<Vec<f64>> = (0..self.y.len())
            .map(|k| vec![self.y[k], self.eps_s[k], self.u_s[k], self.theta[k]])
            .collect();
        profile_metrics(&rows)
    }
}

/// The time in a profile file name `profile_x<x>_t<t>.csv`.
pub fn profile_file_time(name: &str) -> Option<f64> {
    name.strip_prefix("profile_x")?
        .strip_suffix(".csv")?
        .rsplit_once("_t")?
        .1
        .parse()
        .ok()
}

/// The station profile of a run at `time`; the error says why it is missing.
pub fn station_profile(run: &Run, time: f64) -> Result<Profile, String> {
    let file = csv_files(&run.dir, "profile_x").into_iter().find(|p| {
        p.file_name()
            .and_then(|n| n.to_str())
            .and_then(profile_file_time)
            .is_some_and(|t| (t - time).abs() <= 1e-9 * time.max(1.0))
    });
    let Some(file) = file else {
        return Err(run.ended_before(time).unwrap_or_else(|| {
            format!(
                "the {} run has no profile_x*_t{time}.csv (no profile monitor at t = {time} s)",
                run.fidelity
            )
        }));
    };
    Profile::read(&file)
}
