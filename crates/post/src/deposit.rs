//! Where a flow stops: whether and when the solids came to rest, the deposit's extent, its
//! maximum thickness and its profile along x (issue 43 item 4; `runout post RUN_DIR`).
//!
//! Definitions (docs/reference/deposit.md):
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
//!   volume per unit floor area);
//! - **cells across** a column's dense deposit: the cells from the floor to its highest cell
//!   with εs ≥ 0.3. Where a deposit is nowhere [`DEFAULT_MIN_CELLS`] cells thick its shape
//!   and its edge are the grid's more than the flow's (docs/studies/collapse-floor.md, docs/studies/foot.md):
//!   `runout post` warns; it notes the thin edge every deposit has ([`ThinDeposit`]).

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
/// The fewest cells across a dense deposit below which `runout post` warns (issue 57 item 3).
pub const DEFAULT_MIN_CELLS: usize = 5;

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
    /// cells across the dense deposit where H∞ is
    pub max_thickness_cells: usize,
    /// the deposit's centre along the floor: the solids-height-weighted x of its columns [m]
    pub centre_x: f64,
    /// where the dense deposit is fewer than [`DEFAULT_MIN_CELLS`] cells thick, if anywhere
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thin: Option<ThinDeposit>,
    /// on a floor that bends (`bed: Bend`, docs/model.md §9): where the deposit lies on it
    #[serde(skip_serializing_if = "Option::is_none")]
    pub on_the_run_out: Option<RunOut>,
}

/// Where a deposit lies on a floor whose foot turns onto a run-out (docs/reference/deposit.md): x runs
/// along the floor, so the distances below are measured along it, and the drop and the
/// horizontal distance come from the floor's shape (docs/model.md §9).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct RunOut {
    /// where the arc ends and the run-out begins, x_e [m along the floor]
    pub foot_x: f64,
    /// the grain edge past the foot, distal_edge_grain − x_e [m] (negative: it stopped
    /// before the run-out)
    pub grain_edge_past_foot: f64,
    /// the rear edge of the release, x_r (the smallest x0 of the initial blocks with solids) [m]
    pub release_rear_x: f64,
    /// the floor's drop from x_r to the grain edge, H [m]
    pub drop: f64,
    /// the horizontal distance from x_r to the grain edge, L [m]
    pub horizontal: f64,
    /// H/L: the tangent of the travel angle (Heim's ratio, the "Fahrböschung")
    pub heim_ratio: f64,
    /// the released solids' centre along the floor (the blocks' area-weighted centre) [m]
    pub release_centre_x: f64,
    /// the deposit's centre along the floor (solids-height-weighted) [m]
    pub deposit_centre_x: f64,
    /// the floor's drop over its horizontal distance between the two centres: the slope of
    /// the centre of mass's energy line, the effective friction coefficient of a block
    /// sliding from rest the same way (Legros 2002, Eng. Geol. 63, 301)
    pub centre_ratio: f64,
}

/// Where a dense deposit is fewer than `min_cells` cells thick (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ThinDeposit {
    /// the fewest cells asked for
    pub min_cells: usize,
    /// the columns of the dense deposit thinner than that, of all its columns
    pub columns: (usize, usize),
    /// the westmost and eastmost of them, cell-centre x [m]
    pub x_range: (f64, f64),
    /// their share of the dense deposit's solids volume Σ εs Δy Δx [-]
    pub solids_share: f64,
}

impl ThinDeposit {
    /// What `runout post` prints: a warning when even the thickest column, `max_cells`
    /// across, is thinner than `min_cells` (the deposit is nowhere resolved), else a note on
    /// its thin edge (every deposit thins to nothing at its edges).
    pub fn message(&self, max_cells: usize) -> String {
        let columns = format!(
            "{} of its {} columns, from x = {:.4} to {:.4} m, {:.0} % of its solids",
            self.columns.0,
            self.columns.1,
            self.x_range.0,
            self.x_range.1,
            100.0 * self.solids_share
        );
        if max_cells < self.min_cells {
            format!(
                "warning: the dense deposit is at most {max_cells} cells thick, fewer than {} ({columns}): its thickness and its edge are the grid's; refine the grid toward the floor (docs/reference/deposit.md)",
                self.min_cells
            )
        } else {
            format!(
                "note: the dense deposit is fewer than {} cells thick in {columns} (its thin edge)",
                self.min_cells
            )
        }
    }
}

/// Where the dense deposit of `profile` is fewer than `min_cells` cells thick, `None` where
/// it is not (or there is no dense deposit).
pub fn thin_deposit(profile: &[DepositColumn], min_cells: usize) -> Option<ThinDeposit> {
    let dense: Vec<&DepositColumn> = profile.iter().filter(|c| c.cells_dense > 0).collect();
    let thin: Vec<&&DepositColumn> = dense.iter().filter(|c| c.cells_dense < min_cells).collect();
    if thin.is_empty() {
        return None;
    }
    let volume = |cs: &mut dyn Iterator<Item = &DepositColumn>| -> f64 {
        cs.map(|c| c.solids_height * c.width).sum()
    };
    let total = volume(&mut dense.iter().copied());
    let share = volume(&mut thin.iter().map(|c| **c));
    Some(ThinDeposit {
        min_cells,
        columns: (thin.len(), dense.len()),
        x_range: (thin[0].x, thin[thin.len() - 1].x),
        solids_share: if total > 0.0 { share / total } else { 0.0 },
    })
}

/// One column of the deposit profile.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct DepositColumn {
    /// cell-centre x [m]
    pub x: f64,
    /// the column's width [m]
    pub width: f64,
    /// thickness at εs ≥ 0.3 [m]
    pub thickness_dense: f64,
    /// cells across the dense deposit (module doc)
    pub cells_dense: usize,
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
    let (max_thickness, max_thickness_x, max_thickness_cells) = profile
        .iter()
        .map(|c| (c.thickness_dense, c.x, c.cells_dense))
        .fold(
            (0.0, xf[0], 0),
            |best, c| if c.0 > best.0 { c } else { best },
        );
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
            max_thickness_cells,
            thin: thin_deposit(&profile, DEFAULT_MIN_CELLS),
            centre_x: centre_x(&profile, &xf),
            on_the_run_out: run_out(case, distal_edge_grain, centre_x(&profile, &xf))?,
        },
        profile,
    ))
}

/// The deposit's place on a bent floor (`RunOut`), `None` on a plane floor; `deposit_centre`
/// is the deposit's solids-height-weighted x.
fn run_out(case: &Case, grain_edge: f64, deposit_centre: f64) -> Result<Option<RunOut>, String> {
    let Some(floor) = case.bent_floor().map_err(|e| e.to_string())? else {
        return Ok(None);
    };
    // the floor's drop and horizontal distance from a to b
    let path = |a: f64, b: f64| {
        (
            floor.floor_elevation(a) - floor.floor_elevation(b),
            floor.floor_horizontal(b) - floor.floor_horizontal(a),
        )
    };
    let rear = release_rear(case).unwrap_or(0.0);
    let (drop, horizontal) = path(rear, grain_edge);
    let release_centre = release_centre(case).unwrap_or(rear);
    let (drop_centre, horizontal_centre) = path(release_centre, deposit_centre);
    Ok(Some(RunOut {
        foot_x: floor.end(),
        grain_edge_past_foot: grain_edge - floor.end(),
        release_rear_x: rear,
        drop,
        horizontal,
        heim_ratio: drop / horizontal,
        release_centre_x: release_centre,
        deposit_centre_x: deposit_centre,
        centre_ratio: drop_centre / horizontal_centre,
    }))
}

/// The solids-height-weighted x of a deposit profile (columns of widths from `xf`).
fn centre_x(profile: &[DepositColumn], xf: &[f64]) -> f64 {
    let (moment, volume) = profile
        .iter()
        .zip(xf.windows(2))
        .fold((0.0, 0.0), |(m, v), (c, w)| {
            let a = c.solids_height * (w[1] - w[0]);
            (m + c.x * a, v + a)
        });
    moment / volume
}

/// The area-weighted centre x of the released regions.
fn release_centre(case: &Case) -> Option<f64> {
    let (moment, area) = released(case).iter().fold((0.0, 0.0), |(m, a), r| {
        (m + r.centre_x * r.area, a + r.area)
    });
    (area > 0.0).then(|| moment / area)
}

/// The profile as CSV text: `x,thickness_dense,thickness_dilute,solids_height` (m) and
/// `cells_dense`.
pub fn profile_csv(profile: &[DepositColumn]) -> String {
    let mut s = String::from("x,thickness_dense,thickness_dilute,solids_height,cells_dense\n");
    for c in profile {
        s.push_str(&format!(
            "{:e},{:e},{:e},{:e},{}\n",
            c.x, c.thickness_dense, c.thickness_dilute, c.solids_height, c.cells_dense
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
            let highest = |threshold: f64| (0..ny).rev().find(|&j| column(j) >= threshold);
            let top = |threshold: f64| highest(threshold).map_or(0.0, |j| yf[j + 1] - yf[0]);
            DepositColumn {
                x: 0.5 * (xf[i] + xf[i + 1]),
                width: xf[i + 1] - xf[i],
                thickness_dense: top(DENSE_EPS_S),
                cells_dense: highest(DENSE_EPS_S).map_or(0, |j| j + 1),
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

/// The smallest x of the released regions.
fn release_rear(case: &Case) -> Option<f64> {
    released(case).iter().map(|r| r.x.0).reduce(f64::min)
}

/// The largest x of the released regions.
fn release_edge(case: &Case) -> Option<f64> {
    released(case).iter().map(|r| r.x.1).reduce(f64::max)
}

/// One released region in the solver's coordinates: its x extent, area and centre x.
struct Released {
    x: (f64, f64),
    area: f64,
    centre_x: f64,
}

/// The initial blocks and polygons that hold solids (a polygon by its corners in the
/// solver's (x, y), as the run fills it).
fn released(case: &Case) -> Vec<Released> {
    let holds = |solids: &[runout_case::BlockSolids]| solids.iter().any(|s| s.eps_s > 0.0);
    let blocks = case
        .initial
        .regions
        .iter()
        .filter(|b| holds(&b.solids))
        .map(|b| Released {
            x: b.x,
            area: (b.x.1 - b.x.0) * (b.y.1 - b.y.0),
            centre_x: 0.5 * (b.x.0 + b.x.1),
        });
    let polygons = case
        .initial
        .polygons
        .iter()
        .filter(|p| holds(&p.solids))
        .filter_map(|p| case.polygon_in_domain(p).ok())
        .map(|corners| {
            let n = corners.len();
            // the centroid's x: Σ (x_k + x_k+1) c_k / (6 A), c_k the shoelace term
            let (mut twice_area, mut moment) = (0.0, 0.0);
            for k in 0..n {
                let (a, b) = (corners[k], corners[(k + 1) % n]);
                let c = a.0 * b.1 - b.0 * a.1;
                twice_area += c;
                moment += (a.0 + b.0) * c;
            }
            let xs = corners.iter().map(|c| c.0);
            Released {
                x: (
                    xs.clone().fold(f64::INFINITY, f64::min),
                    xs.fold(f64::NEG_INFINITY, f64::max),
                ),
                area: 0.5 * twice_area.abs(),
                centre_x: moment / (3.0 * twice_area),
            }
        });
    blocks.chain(polygons).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On the family-FS slide (40° onto a flat run-out, arc 12 m to 12 + 2 · 40° m): a grain
    /// edge still on the slope travels at the slope's own angle (H/L = tan 40°); at the
    /// foot's end it is 0 m past the foot; far out on the flat H is the slope's and the arc's
    /// drop, (12 − 5) sin 40° + 2 (1 − cos 40°), and H/L falls.
    #[test]
    fn a_deposit_on_a_bent_floor_has_its_travel_angle() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let case = runout_case::load_case(&root.join("cases/foot/mu-i/base.ron")).unwrap();
        let a = 40f64.to_radians();
        let on_slope = run_out(&case, 10.0, 10.0).unwrap().unwrap();
        assert_eq!(on_slope.release_rear_x, 5.0);
        assert!((on_slope.heim_ratio - a.tan()).abs() < 1e-12);
        assert!((on_slope.drop - 5.0 * a.sin()).abs() < 1e-12);
        // the centres: the block's 5.25 m; on the straight slope, its slope's tangent too
        assert_eq!(on_slope.release_centre_x, 5.25);
        assert!((on_slope.centre_ratio - a.tan()).abs() < 1e-12);
        let foot = 12.0 + 2.0 * a;
        let at_foot = run_out(&case, foot, foot).unwrap().unwrap();
        assert!(at_foot.grain_edge_past_foot.abs() < 1e-12);
        let far = run_out(&case, 30.0, 20.0).unwrap().unwrap();
        let drop = 7.0 * a.sin() + 2.0 * (1.0 - a.cos());
        assert!((far.drop - drop).abs() < 1e-12);
        let horizontal = 7.0 * a.cos() + 2.0 * a.sin() + (30.0 - foot);
        assert!((far.horizontal - horizontal).abs() < 1e-12);
        assert!(far.heim_ratio < at_foot.heim_ratio && at_foot.heim_ratio < a.tan());
        // the deposit's centre weighs each column's solids height by its width
        let column = |x: f64, h: f64| DepositColumn {
            x,
            width: 1.0,
            thickness_dense: h,
            cells_dense: 1,
            thickness_dilute: h,
            solids_height: h,
        };
        let profile = [column(0.5, 1.0), column(2.0, 1.0)];
        assert!((centre_x(&profile, &[0.0, 1.0, 3.0]) - (0.5 + 2.0 * 2.0) / 3.0).abs() < 1e-15);
        let plane = runout_case::load_case(&root.join("cases/sensitivity/base.ron")).unwrap();
        assert_eq!(run_out(&plane, 10.0, 10.0).unwrap(), None);
    }

    /// A polygon release (cases/slopes/gated-pile.ron: a trapezoid in the floor's
    /// coordinates from the back wall, 2.309 cm high, to the gate at 0.1 m, 8.083 cm high)
    /// has its rear, edge and centre: the trapezoid's centroid L (h0 + 2 h1)/(3 (h0 + h1)).
    #[test]
    fn a_polygon_release_has_its_edges_and_centre() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let case = runout_case::load_case(&root.join("cases/slopes/gated-pile.ron")).unwrap();
        let (h0, h1) = (
            0.02 / 30f64.to_radians().cos(),
            (0.02 + 0.05) / 30f64.to_radians().cos(),
        );
        assert!(release_rear(&case).unwrap().abs() < 1e-9);
        assert!((release_edge(&case).unwrap() - 0.1).abs() < 1e-5);
        let centroid = 0.1 * (h0 + 2.0 * h1) / (3.0 * (h0 + h1));
        assert!(
            (release_centre(&case).unwrap() - centroid).abs() < 1e-5,
            "{:?}",
            release_centre(&case)
        );
    }

    /// A deposit of 2 × 2 cells rising to 6 over 4 columns of a grid whose cells thicken
    /// upward: its cells across, and the columns thinner than 5 with their share of its
    /// solids.
    #[test]
    fn a_thin_deposit_is_found_and_said() {
        let xf = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        let yf: Vec<f64> = (0..=8).map(|j| 0.1 * (j * j) as f64).collect();
        let (nx, ny) = (5, 8);
        let heights = [2, 6, 4, 2, 0];
        let mut eps = vec![0.0; nx * ny];
        for (i, &h) in heights.iter().enumerate() {
            for j in 0..h {
                eps[i + nx * j] = 0.6;
            }
        }
        let p = profile(&eps, &xf, &yf);
        let cells: Vec<usize> = p.iter().map(|c| c.cells_dense).collect();
        assert_eq!(cells, [2, 6, 4, 2, 0]);
        assert!((p[1].thickness_dense - 3.6).abs() < 1e-12);
        let thin = thin_deposit(&p, 5).unwrap();
        assert_eq!(thin.columns, (3, 4));
        assert_eq!(thin.x_range, (0.5, 3.5));
        // solids heights 0.6 × (0.4, 3.6, 1.6, 0.4): the thin ones hold 2.4 of 6.0
        assert!(
            (thin.solids_share - 0.4).abs() < 1e-12,
            "{}",
            thin.solids_share
        );
        assert!(thin.message(6).starts_with(
            "note: the dense deposit is fewer than 5 cells thick in 3 of its 4 columns"
        ));
        assert!(thin
            .message(4)
            .starts_with("warning: the dense deposit is at most 4 cells thick"));
        assert_eq!(thin_deposit(&p, 2), None);
    }

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
        assert!(profile_csv(&p)
            .starts_with("x,thickness_dense,thickness_dilute,solids_height,cells_dense\n5e-1,"));
        // the grain edge: the last column holding at least this solids height
        assert_eq!(grain_edge(&p, &xf, 0.1), 2.0);
        assert_eq!(grain_edge(&p, &xf, 0.5), 1.0);
        assert_eq!(grain_edge(&p, &xf, 1.0), 0.0);
    }
}
