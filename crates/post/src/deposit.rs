//! Where a flow stops: whether and when the solids came to rest, the deposit's extent, its
//! maximum thickness and its profile along x (issue 43 item 4; `runout post RUN_DIR`).
//!
//! Definitions (docs/deposit.md):
//! - **at rest** from time t_rest: the εs-weighted mean u_s of `bulk.csv` is at most
//!   v_rest at every sample from t_rest on, and the front of `bulk.csv` does not move after
//!   t_rest; v_rest = `rest_fraction` · √(g H∞) (default 1 %, the collapse check's
//!   threshold). A run whose last sample is above v_rest is not at rest.
//! - **distal edge** at a threshold εs*: the east face of the easternmost floor cell with
//!   εs ≥ εs* in the last field file (εs* = 0.01, the bulk front's, and 0.3, the dense
//!   deposit's);
//! - **grain edge**: the east face of the easternmost column whose solids height Σ εs Δy is
//!   at least one grain diameter d (a layer about two grains deep at εs = 0.6): an edge
//!   that does not depend on the cell height, unlike a threshold on the cells' εs (a cell
//!   with εs = 0.01 holds 0.1 d of grains in a 5 mm cell of 0.5 mm grains, half that in a
//!   2.5 mm one);
//! - **L∞** (the runout): the distal edge minus the east edge of the release (the largest
//!   x1 of the initial blocks holding solids);
//! - **thickness** of a column: the top face of its highest cell with εs ≥ εs*; **H∞**:
//!   the largest dense (εs ≥ 0.3) thickness; **solids height**: Σ εs Δy (the column's solids
//!   volume per unit floor area).

use std::path::Path;

use runout_case::{Case, Gravity};
use serde::Serialize;

use crate::fields::field_files;
use crate::table::Table;

/// εs of the dilute edge (the bulk monitor's front threshold).
pub const DILUTE_EPS_S: f64 = 0.01;
/// εs of the dense deposit.
pub const DENSE_EPS_S: f64 = 0.3;
/// Solids height Σ εs Δy of the grain edge, in grain diameters.
pub const GRAIN_EDGE_DIAMETERS: f64 = 1.0;
/// Default v_rest as a fraction of √(g H∞).
pub const DEFAULT_REST_FRACTION: f64 = 0.01;

/// The deposit of one run (module doc for the definitions).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Deposit {
    /// time of the field file read [s] (the last)
    pub time: f64,
    /// speed below which the solids count as at rest, v_rest [m/s]
    pub rest_speed: f64,
    /// the solids are at rest at the end of the run
    pub at_rest: bool,
    /// the earliest bulk sample from which they stayed at rest [s]
    pub rest_time: Option<f64>,
    /// εs-weighted mean u_s at the last bulk sample [m/s]
    pub final_mean_u_s: f64,
    /// east edge of the release [m]
    pub release_edge_x: f64,
    /// distal edge at εs ≥ 0.01 [m]
    pub distal_edge_dilute: f64,
    /// distal edge at εs ≥ 0.3 [m]
    pub distal_edge_dense: f64,
    /// L∞ at εs ≥ 0.01: distal edge − release edge [m]
    pub runout_dilute: f64,
    /// distal edge where the solids height reaches [`GRAIN_EDGE_DIAMETERS`] grains [m]
    pub distal_edge_grain: f64,
    /// L∞ at the grain edge [m]
    pub runout_grain: f64,
    /// L∞ at εs ≥ 0.3 [m]
    pub runout_dense: f64,
    /// H∞: largest thickness at εs ≥ 0.3 [m]
    pub max_thickness: f64,
    /// x of the column where H∞ is [m]
    pub max_thickness_x: f64,
}

/// One column of the deposit profile.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct DepositColumn {
    /// cell-centre x [m]
    pub x: f64,
    /// thickness at εs ≥ 0.3 [m]
    pub thickness_dense: f64,
    /// thickness at εs ≥ 0.01 [m]
    pub thickness_dilute: f64,
    /// Σ εs Δy [m]
    pub solids_height: f64,
}

/// Reads the deposit of the run in `dir` from its resolved case, `bulk.csv` and its last
/// field file; `rest_fraction` sets v_rest = rest_fraction · √(g H∞).
pub fn read_deposit(
    dir: &Path,
    case: &Case,
    rest_fraction: f64,
) -> Result<(Deposit, Vec<DepositColumn>), String> {
    let grid = case.grid().map_err(|e| format!("{}: {e}", dir.display()))?;
    let (xf, yf) = (grid.x.faces().to_vec(), grid.y.faces().to_vec());
    let (time, eps) = last_eps_s(dir, xf.len() - 1, yf.len() - 1)?;
    let profile = profile(&eps, &xf, &yf);
    let bulk = Table::read(&dir.join("bulk.csv"))
        .map_err(|e| format!("{}: {e}", dir.join("bulk.csv").display()))?;
    let times = bulk.column("t").map_err(|e| format!("bulk.csv: {e}"))?;
    let fronts = bulk
        .column("front_x")
        .map_err(|e| format!("bulk.csv: {e}"))?;
    let speeds = bulk
        .column("mean_u_s")
        .map_err(|e| format!("bulk.csv: {e}"))?;
    let (max_thickness, max_thickness_x) = profile
        .iter()
        .map(|c| (c.thickness_dense, c.x))
        .fold((0.0, xf[0]), |best, c| if c.0 > best.0 { c } else { best });
    let rest_speed = rest_fraction * (gravity_magnitude(case) * max_thickness).sqrt();
    let rest_time = rest_time(&times, &fronts, &speeds, rest_speed);
    let release_edge_x = release_edge(case).unwrap_or(xf[0]);
    let floor = &eps[..xf.len() - 1];
    let distal_edge_dilute = distal_edge(floor, &xf, DILUTE_EPS_S);
    let distal_edge_dense = distal_edge(floor, &xf, DENSE_EPS_S);
    let diameter = case.solids.first().map_or(0.0, |s| s.diameter);
    let distal_edge_grain = grain_edge(&profile, &xf, GRAIN_EDGE_DIAMETERS * diameter);
    Ok((
        Deposit {
            time,
            rest_speed,
            at_rest: rest_time.is_some(),
            rest_time,
            final_mean_u_s: speeds.last().copied().unwrap_or(f64::NAN),
            release_edge_x,
            distal_edge_dilute,
            distal_edge_dense,
            runout_dilute: distal_edge_dilute - release_edge_x,
            runout_dense: distal_edge_dense - release_edge_x,
            distal_edge_grain,
            runout_grain: distal_edge_grain - release_edge_x,
            max_thickness,
            max_thickness_x,
        },
        profile,
    ))
}

/// The profile as CSV text: `x,thickness_dense,thickness_dilute,solids_height` (m).
pub fn profile_csv(profile: &[DepositColumn]) -> String {
    let mut s = String::from("x,thickness_dense,thickness_dilute,solids_height\n");
    for c in profile {
        s.push_str(&format!(
            "{:e},{:e},{:e},{:e}\n",
            c.x, c.thickness_dense, c.thickness_dilute, c.solids_height
        ));
    }
    s
}

/// The earliest sample from which every later mean speed is ≤ `rest_speed` and the front
/// no longer moves; `None` if the last sample is above it or the still stretch has fewer
/// than two samples (one sample cannot show a still front).
pub fn rest_time(times: &[f64], fronts: &[f64], speeds: &[f64], rest_speed: f64) -> Option<f64> {
    let last_front = *fronts.last()?;
    let still = (0..times.len())
        .rev()
        .take_while(|&k| speeds[k].abs() <= rest_speed && fronts[k] == last_front)
        .last()?;
    (still + 1 < times.len()).then(|| times[still])
}

/// East face of the easternmost floor cell with εs ≥ `threshold` (the west face if none).
pub fn distal_edge(floor_eps: &[f64], x_faces: &[f64], threshold: f64) -> f64 {
    floor_eps
        .iter()
        .rposition(|&e| e >= threshold)
        .map_or(x_faces[0], |i| x_faces[i + 1])
}

/// East face of the easternmost column whose solids height is at least `height` (the west
/// face if none).
pub fn grain_edge(profile: &[DepositColumn], x_faces: &[f64], height: f64) -> f64 {
    profile
        .iter()
        .rposition(|c| c.solids_height >= height)
        .map_or(x_faces[0], |i| x_faces[i + 1])
}

/// Each column's thicknesses and solids height from row-major εs (floor row first), on the
/// grid with faces `xf`, `yf`.
pub fn profile(eps: &[f64], xf: &[f64], yf: &[f64]) -> Vec<DepositColumn> {
    let (nx, ny) = (xf.len() - 1, yf.len() - 1);
    (0..nx)
        .map(|i| {
            let column = |j: usize| eps[j * nx + i];
            let top = |threshold: f64| {
                (0..ny)
                    .rev()
                    .find(|&j| column(j) >= threshold)
                    .map_or(0.0, |j| yf[j + 1] - yf[0])
            };
            DepositColumn {
                x: 0.5 * (xf[i] + xf[i + 1]),
                thickness_dense: top(DENSE_EPS_S),
                thickness_dilute: top(DILUTE_EPS_S),
                solids_height: (0..ny).map(|j| column(j) * (yf[j + 1] - yf[j])).sum(),
            }
        })
        .collect()
}

/// The time and εs of the run's last field file.
fn last_eps_s(dir: &Path, nx: usize, ny: usize) -> Result<(f64, Vec<f64>), String> {
    let (time, name) = field_files(dir)
        .map_err(|e| format!("{}: {e}", dir.join("fields.pvd").display()))?
        .pop()
        .ok_or_else(|| format!("{}: fields.pvd lists no file", dir.display()))?;
    let path = dir.join(&name);
    let xml = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let eps = runout_output::read_vtr_array(&xml, "eps_s")
        .ok_or_else(|| format!("{}: no eps_s array", path.display()))?;
    if eps.len() != nx * ny {
        return Err(format!(
            "{}: {} εs values for a {nx} × {ny} grid",
            path.display(),
            eps.len()
        ));
    }
    Ok((time, eps))
}

/// |g| of the case.
fn gravity_magnitude(case: &Case) -> f64 {
    match case.gravity {
        Gravity::Constant { magnitude, .. } | Gravity::TiltOnImpact { magnitude, .. } => magnitude,
    }
}

/// The largest x1 of the initial blocks that hold solids.
fn release_edge(case: &Case) -> Option<f64> {
    case.initial
        .regions
        .iter()
        .filter(|b| b.solids.iter().any(|s| s.eps_s > 0.0))
        .map(|b| b.x.1)
        .reduce(f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rest time is the first sample of the final still stretch; a front that moves or a
    /// speed above v_rest at the end means no rest.
    #[test]
    fn rest_starts_where_speed_and_front_stay_still() {
        let t = [0.0, 0.1, 0.2, 0.3, 0.4];
        let front = [0.1, 0.2, 0.3, 0.3, 0.3];
        let speed = [1.0, 0.5, 0.005, 0.001, 0.0];
        assert_eq!(rest_time(&t, &front, &speed, 0.01), Some(0.2));
        assert_eq!(rest_time(&t, &front, &speed, 2e-3), Some(0.3));
        assert_eq!(rest_time(&t, &front, &speed, 1e-4), None);
        let moving = [0.1, 0.2, 0.3, 0.3, 0.35];
        assert_eq!(rest_time(&t, &moving, &speed, 0.01), None);
        assert_eq!(
            rest_time(&t, &front, &[1.0, 1.0, 1.0, 1.0, 0.02], 0.01),
            None
        );
        assert_eq!(rest_time(&[], &[], &[], 0.01), None);
    }

    /// A 3 × 2 grid: thicknesses from the top cell above each threshold, Σ εs Δy, edges.
    #[test]
    fn profile_and_edges_of_a_small_deposit() {
        let xf = [0.0, 1.0, 2.0, 3.0];
        let yf = [0.0, 0.5, 1.5];
        // floor row, then the row above
        let eps = [0.6, 0.2, 0.005, 0.5, 0.0, 0.0];
        let p = profile(&eps, &xf, &yf);
        assert_eq!(p[0].thickness_dense, 1.5);
        assert_eq!(p[1].thickness_dense, 0.0);
        assert_eq!(p[1].thickness_dilute, 0.5);
        assert_eq!(p[2].thickness_dilute, 0.0);
        assert!((p[0].solids_height - (0.6 * 0.5 + 0.5 * 1.0)).abs() < 1e-15);
        assert_eq!(distal_edge(&eps[..3], &xf, DILUTE_EPS_S), 2.0);
        assert_eq!(distal_edge(&eps[..3], &xf, DENSE_EPS_S), 1.0);
        assert_eq!(distal_edge(&eps[..3], &xf, 0.9), 0.0);
        // only the floor row counts: the dense row above does not move the edge
        let two_rows = [0.6, 0.4, 0.005, 0.0, 0.6, 0.6, 0.6, 0.6];
        let faces = [0.0, 0.1, 0.2, 0.3, 0.4];
        assert_eq!(distal_edge(&two_rows[..4], &faces, DILUTE_EPS_S), 0.2);
        assert_eq!(distal_edge(&two_rows[..4], &faces, 0.5), 0.1);
        assert!(
            profile_csv(&p).starts_with("x,thickness_dense,thickness_dilute,solids_height\n5e-1,")
        );
        // the grain edge: the last column holding at least this solids height
        assert_eq!(grain_edge(&p, &xf, 0.1), 2.0);
        assert_eq!(grain_edge(&p, &xf, 0.5), 1.0);
        assert_eq!(grain_edge(&p, &xf, 1.0), 0.0);
    }
}
