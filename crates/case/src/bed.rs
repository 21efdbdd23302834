//! The `bed` option of a case: the floor's shape in bed-following coordinates (docs/model.md
//! §9) — one plane, a slope whose foot turns (`Bend`), a path of straight pieces joined by
//! circular arcs (`Path`), or a transect of (horizontal, elevation) points turned into such
//! a path (`Transect`) — and its validation.

use serde::{Deserialize, Serialize};

use runout_mesh::bent_floor::{ArcSpec, BentFloor, BentFloorError};

use crate::checker::{Checker, B};
use crate::schema::{Case, Gravity};

/// The floor's shape. `Plane` (the default): one plane floor under the case's uniform
/// (tilted) gravity. The others make x run along the floor and y normal to it, with gravity
/// following the floor's angle and the flow feeling the centrifugal force −κ u² on each arc
/// (docs/model.md §9; valid for flows much thinner than the arcs' radii).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Bed {
    /// one plane floor
    #[default]
    Plane,
    /// a slope (the gravity's) whose foot turns onto a run-out
    Bend {
        /// where the arc starts, along the floor [m], inside the domain
        at: f64,
        /// arc radius R [m], > 0
        radius: f64,
        /// the run-out's slope after the arc [deg], 0 ≤ slope_after < the gravity's slope
        #[serde(default)]
        slope_after: f64,
    },
    /// straight pieces joined by arcs, from the domain's west end: `Straight`, `Arc`,
    /// `Straight`, …, `Straight`, each arc turning the floor from the straight before it to
    /// the straight after it; the gravity's slope is 0 (the path gives every angle)
    Path(Vec<BedPiece>),
    /// a cut through a terrain model: (horizontal distance, elevation) points [m], x rising,
    /// from the domain's west end, the straight lines between them joined by arcs of
    /// `radius` at every point where the slope changes; the gravity's slope is 0
    Transect {
        /// (x, z) points [m], at least two, x strictly rising
        points: Vec<(f64, f64)>,
        /// the arcs' radius R [m], > 0, small enough for each arc to fit its two lines
        radius: f64,
    },
}

/// One piece of a `bed: Path`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum BedPiece {
    /// a straight floor
    Straight {
        /// its length along the floor [m], > 0
        length: f64,
        /// its slope [deg], downhill towards +x positive, in (−90°, 90°)
        slope: f64,
    },
    /// a circular arc from the slope of the straight before to that of the straight after
    Arc {
        /// its radius R [m], > 0 (larger than the domain's height where the floor turns
        /// flatter)
        radius: f64,
    },
}

impl Bed {
    /// Whether this is the default plane floor (then not written to resolved cases, so
    /// that cases and run folders from before the option existed are unchanged).
    pub fn is_plane(&self) -> bool {
        *self == Bed::Plane
    }
}

/// A path's first slope [deg] and its arcs, laid from x = `origin` along the floor;
/// `Err((index, reason))` names the piece that breaks the order Straight, Arc, …, Straight
/// or whose numbers are out of range.
pub fn path_arcs(
    pieces: &[BedPiece],
    origin: f64,
) -> Result<(f64, Vec<ArcSpec>, f64), (usize, String)> {
    let straight = |k: usize| match pieces.get(k) {
        Some(BedPiece::Straight { length, slope }) => Ok((*length, *slope)),
        Some(BedPiece::Arc { .. }) => Err((
            k,
            String::from("a Straight (pieces alternate Straight, Arc, Straight, …)"),
        )),
        None => Err((
            k,
            String::from("a Straight after the last Arc (a path ends on a Straight)"),
        )),
    };
    let (first_length, first_slope) = straight(0)?;
    let mut arcs = Vec::new();
    let (mut x, mut slope, mut length) = (origin, first_slope, first_length);
    let mut k = 0;
    loop {
        if !(length.is_finite() && length > 0.0) {
            return Err((
                k,
                format!("a length > 0 (got {})", runout_mesh::short(length)),
            ));
        }
        if !(slope.is_finite() && slope.abs() < 90.0) {
            return Err((
                k,
                format!(
                    "a slope in (−90°, 90°) (got {}°: beyond vertical)",
                    runout_mesh::short(slope)
                ),
            ));
        }
        x += length;
        let Some(piece) = pieces.get(k + 1) else {
            return Ok((first_slope, arcs, x));
        };
        let BedPiece::Arc { radius } = *piece else {
            return Err((
                k + 1,
                String::from(
                    "an Arc between two Straights (a kink has no bed-following coordinates)",
                ),
            ));
        };
        if !(radius.is_finite() && radius > 0.0) {
            return Err((
                k + 1,
                format!("a radius > 0 (got {})", runout_mesh::short(radius)),
            ));
        }
        let (next_length, next_slope) = straight(k + 2)?;
        if next_slope == slope {
            return Err((
                k + 1,
                format!(
                    "an arc that turns (the straights on both sides have slope {}°)",
                    runout_mesh::short(slope)
                ),
            ));
        }
        arcs.push(ArcSpec {
            start: x,
            radius,
            to_slope_deg: next_slope,
        });
        x += radius * (slope - next_slope).abs().to_radians();
        (slope, length) = (next_slope, next_length);
        k += 2;
    }
}

/// A transect's first slope [deg] and its arcs from x = `origin` along the floor (module
/// doc): the straight lines between successive points, each corner rounded by an arc of
/// `radius` tangent to both lines, which cuts t = R tan(|Δα|/2) off each; also the path's
/// length to the last point. `Err((index, reason))` names the point at fault.
pub fn transect_arcs(
    points: &[(f64, f64)],
    radius: f64,
    origin: f64,
) -> Result<(f64, Vec<ArcSpec>, f64), (usize, String)> {
    if points.len() < 2 {
        return Err((points.len(), String::from("at least two points")));
    }
    if let Some(k) = points
        .iter()
        .position(|(x, z)| !(x.is_finite() && z.is_finite()))
    {
        return Err((k, String::from("finite coordinates")));
    }
    if let Some(k) = (1..points.len()).find(|&k| points[k].0 <= points[k - 1].0) {
        return Err((k, format!("x above the previous point's {} m (a vertical or overhanging step is beyond vertical)", runout_mesh::short(points[k - 1].0))));
    }
    // each line's length and slope (downhill positive) [m, rad]
    let lines: Vec<(f64, f64)> = points
        .windows(2)
        .map(|w| {
            let (dx, dz) = (w[1].0 - w[0].0, w[1].1 - w[0].1);
            (dx.hypot(dz), (-dz).atan2(dx))
        })
        .collect();
    // the length each corner's arc cuts off its two lines; 0 at the ends
    let cut: Vec<f64> = (0..=lines.len())
        .map(|k| {
            if k == 0 || k == lines.len() {
                0.0
            } else {
                radius * (0.5 * (lines[k - 1].1 - lines[k].1).abs()).tan()
            }
        })
        .collect();
    if !(radius.is_finite() && radius > 0.0) {
        return Err((
            0,
            format!("radius > 0 (got {})", runout_mesh::short(radius)),
        ));
    }
    let mut arcs = Vec::new();
    let mut x = origin;
    for (k, &(length, slope)) in lines.iter().enumerate() {
        let straight = length - cut[k] - cut[k + 1];
        if straight < 0.0 {
            return Err((
                k + 1,
                format!(
                    "room for the arcs at both ends of the line to it ({} m long; the arcs of radius {} m cut {} m and {} m off it): a smaller radius or fewer points",
                    runout_mesh::short(length),
                    runout_mesh::short(radius),
                    runout_mesh::short(cut[k]),
                    runout_mesh::short(cut[k + 1])
                ),
            ));
        }
        x += straight;
        if let Some(&(_, next)) = lines.get(k + 1) {
            if next != slope {
                arcs.push(ArcSpec {
                    start: x,
                    radius,
                    to_slope_deg: next.to_degrees(),
                });
                x += radius * (slope - next).abs();
            }
        }
    }
    Ok((lines[0].1.to_degrees(), arcs, x))
}

impl Case {
    /// The bent floor of a case with `bed: Bend`, `Path` or `Transect` under its final
    /// (tilted) gravity (docs/model.md §9), `Ok(None)` on a plane floor; an error only for a
    /// case that did not pass validation.
    pub fn bent_floor(&self) -> Result<Option<BentFloor>, BentFloorError> {
        let magnitude = match self.gravity {
            Gravity::Constant { magnitude, .. } | Gravity::TiltOnImpact { magnitude, .. } => {
                magnitude
            }
        };
        let origin = self.domain.x.origin;
        let refused = |(index, reason): (usize, String)| BentFloorError::Arc { index, reason };
        match &self.bed {
            Bed::Plane => Ok(None),
            Bed::Bend {
                at,
                radius,
                slope_after,
            } => BentFloor::new(magnitude, self.gravity.slope(), *slope_after, *at, *radius)
                .map(Some),
            Bed::Path(pieces) => {
                let (first, arcs, _) = path_arcs(pieces, origin).map_err(refused)?;
                BentFloor::path(magnitude, origin, first, &arcs).map(Some)
            }
            Bed::Transect { points, radius } => {
                let (first, arcs, _) = transect_arcs(points, *radius, origin).map_err(refused)?;
                BentFloor::path(magnitude, origin, first, &arcs).map(Some)
            }
        }
    }
}

/// Checks `bed`: a Bend's arc starts inside the domain and ends before its east end, its
/// radius is > 0 and its run-out shallower than the slope (a concave foot); a Path's pieces
/// alternate Straight, Arc, …, Straight and a Transect's points rise in x with room for
/// their arcs, each covering the domain, with every concave arc's radius above the domain's
/// height (else the floor's normals cross inside it) and the gravity's slope 0; a bed needs
/// solids (the two-fluid model).
pub(crate) fn check_bed(c: &mut Checker, case: &Case) {
    match &case.bed {
        Bed::Plane => return,
        Bed::Bend { .. } => check_bend(c, case),
        Bed::Path(pieces) => {
            let laid = path_arcs(pieces, case.domain.x.origin);
            check_path(
                c,
                case,
                "bed.Path",
                laid.map_err(|(k, why)| (format!("bed.Path[{k}]"), why)),
            );
        }
        Bed::Transect { points, radius } => {
            let laid = transect_arcs(points, *radius, case.domain.x.origin);
            let field = |k: usize| {
                if k < points.len() {
                    format!("bed.Transect.points[{k}]")
                } else {
                    String::from("bed.Transect.points")
                }
            };
            check_path(
                c,
                case,
                "bed.Transect",
                laid.map_err(|(k, why)| (field(k), why)),
            );
        }
    }
    if case.solids.is_empty() {
        c.fail(
            "bed",
            "not Plane",
            "Plane for a gas-only case (a bent floor is a two-fluid option)",
        );
    }
}

/// A laid-out path (first slope, arcs, end along the floor) or the field at fault.
type Laid = Result<(f64, Vec<ArcSpec>, f64), (String, String)>;

/// The checks a Path and a Transect share (the doc of [`check_bed`]).
fn check_path(c: &mut Checker, case: &Case, field: &str, laid: Laid) {
    let (first, arcs, end) = match laid {
        Ok(laid) => laid,
        Err((field, why)) => {
            c.fail(field, "as given", why);
            return;
        }
    };
    let slope = case.gravity.slope();
    if !matches!(case.gravity, Gravity::Constant { .. }) || slope != 0.0 {
        c.fail(
            "gravity",
            format!("{:?} with slope {}°", case.gravity, runout_mesh::short(slope)),
            format!("Constant(magnitude: …, slope: 0.0) with {field} (the bed gives the floor's angle everywhere; gravity points down)"),
        );
    }
    let (x0, x1) = (case.domain.x.origin, case.domain.x.end());
    if end < x1 {
        c.fail(
            field,
            format!("a path to x = {} m", runout_mesh::short(end)),
            format!(
                "a path that covers the domain to its east end, x = {} m",
                runout_mesh::short(x1)
            ),
        );
    }
    let height = case.domain.y.end() - case.domain.y.origin;
    let mut angle = first;
    for (k, arc) in arcs.iter().enumerate() {
        if arc.to_slope_deg < angle && arc.radius <= height && arc.start < x1 {
            c.fail(
                format!("{field}: arc {k} at x = {} m", runout_mesh::short(arc.start)),
                format!("R = {} m", runout_mesh::short(arc.radius)),
                format!(
                    "R > the domain's height {} m where the floor turns flatter (else the floor's normals cross inside the domain: a fold)",
                    runout_mesh::short(height)
                ),
            );
        }
        angle = arc.to_slope_deg;
    }
    if let Err(e) = BentFloor::path(1.0, x0, first, &arcs) {
        c.fail(field, "as given", e.to_string());
    }
}

/// Checks `bed.Bend.*` (the doc of [`check_bed`]).
fn check_bend(c: &mut Checker, case: &Case) {
    let Bed::Bend {
        at,
        radius,
        slope_after,
    } = case.bed
    else {
        return;
    };
    let (x0, x1) = (case.domain.x.origin, case.domain.x.end());
    let p = "bed.Bend";
    c.range(format!("{p}.at"), at, B::Open(x0), B::Open(x1));
    c.range(format!("{p}.radius"), radius, B::Open(0.0), B::Inf);
    let slope = case.gravity.slope();
    c.range(
        format!("{p}.slope_after"),
        slope_after,
        B::Closed(0.0),
        B::Open(slope),
    );
    let arc_end = at + radius * (slope - slope_after).to_radians();
    if at > x0 && at < x1 && radius > 0.0 && arc_end >= x1 {
        c.fail(
            format!("{p}.radius"),
            runout_mesh::short(radius),
            format!(
                "an arc that ends before the domain's east end (x = {}): R (slope − slope_after) < {} m",
                runout_mesh::short(x1),
                runout_mesh::short(x1 - at)
            ),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn floor(first: f64, arcs: &[ArcSpec], origin: f64) -> BentFloor {
        BentFloor::path(9.81, origin, first, arcs).unwrap()
    }

    /// A transect's floor leaves its first point along its first line and, past its last
    /// arc, runs along its last line: at the path's length it is at the last point (to
    /// 1e-12 m), though the arcs cut every corner between.
    #[test]
    fn a_transect_ends_on_its_last_point() {
        let points = [
            (0.0, 100.0),
            (40.0, 75.0),
            (70.0, 66.0),
            (90.0, 66.0),
            (130.0, 70.0),
        ];
        let (first, arcs, end) = transect_arcs(&points, 12.0, 5.0).unwrap();
        let f = floor(first, &arcs, 5.0);
        assert_eq!(arcs.len(), 3);
        assert!((first - (25f64).atan2(40.0).to_degrees()).abs() < 1e-12);
        let (x1, z1) = (points[4].0 - points[0].0, points[4].1 - points[0].1);
        assert!(
            (f.floor_horizontal(end) - x1).abs() < 1e-12,
            "{}",
            f.floor_horizontal(end)
        );
        assert!(
            (f.floor_elevation(end) - z1).abs() < 1e-12,
            "{}",
            f.floor_elevation(end)
        );
        // the first arc starts where it cuts R tan(Δα/2) off the first line
        let delta = (25f64).atan2(40.0) - (9f64).atan2(30.0);
        let first_line = 40f64.hypot(25.0);
        assert!((arcs[0].start - (5.0 + first_line - 12.0 * (0.5 * delta).tan())).abs() < 1e-12);
        // the last line climbs: its slope is negative
        assert!(f.angle(end) < 0.0);
    }

    /// A path's pieces laid end to end: its arcs start after each straight, and it ends at
    /// the sum of the straights and the arcs' lengths R |Δα|.
    #[test]
    fn a_path_lays_its_pieces_end_to_end() {
        let pieces = [
            BedPiece::Straight {
                length: 2.0,
                slope: 30.0,
            },
            BedPiece::Arc { radius: 1.0 },
            BedPiece::Straight {
                length: 1.5,
                slope: 10.0,
            },
            BedPiece::Arc { radius: 2.0 },
            BedPiece::Straight {
                length: 3.0,
                slope: 20.0,
            },
        ];
        let (first, arcs, end) = path_arcs(&pieces, -0.5).unwrap();
        assert_eq!(first, 30.0);
        assert_eq!(arcs[0].start, 1.5);
        let second = 1.5 + 20f64.to_radians() + 1.5;
        assert!((arcs[1].start - second).abs() < 1e-15);
        assert!((end - (second + 2.0 * 10f64.to_radians() + 3.0)).abs() < 1e-14);
        let f = floor(first, &arcs, -0.5);
        assert!((f.angle(end) - 20f64.to_radians()).abs() < 1e-15);
    }

    #[test]
    fn broken_paths_and_transects_name_the_piece() {
        let s = |length, slope| BedPiece::Straight { length, slope };
        let a = |radius| BedPiece::Arc { radius };
        assert_eq!(path_arcs(&[a(1.0)], 0.0).unwrap_err().0, 0);
        assert_eq!(
            path_arcs(&[s(1.0, 30.0), s(1.0, 10.0)], 0.0).unwrap_err().0,
            1
        );
        assert_eq!(path_arcs(&[s(1.0, 30.0), a(1.0)], 0.0).unwrap_err().0, 2);
        assert_eq!(
            path_arcs(&[s(1.0, 30.0), a(1.0), s(0.0, 10.0)], 0.0)
                .unwrap_err()
                .0,
            2
        );
        assert_eq!(
            path_arcs(&[s(1.0, 30.0), a(-1.0), s(1.0, 10.0)], 0.0)
                .unwrap_err()
                .0,
            1
        );
        assert_eq!(
            path_arcs(&[s(1.0, 30.0), a(1.0), s(1.0, 30.0)], 0.0)
                .unwrap_err()
                .0,
            1
        );
        assert_eq!(path_arcs(&[s(1.0, 95.0)], 0.0).unwrap_err().0, 0);
        assert_eq!(transect_arcs(&[(0.0, 1.0)], 1.0, 0.0).unwrap_err().0, 1);
        assert_eq!(
            transect_arcs(&[(0.0, 1.0), (1.0, 0.0), (1.0, -1.0)], 0.1, 0.0)
                .unwrap_err()
                .0,
            2
        );
        assert_eq!(
            transect_arcs(&[(0.0, 1.0), (1.0, 0.0), (0.5, -1.0)], 0.1, 0.0)
                .unwrap_err()
                .0,
            2
        );
        // a 1 m line cannot hold two arcs of 10 m turning by 45°
        let corners = [(0.0, 2.0), (1.0, 1.0), (2.0, 1.0), (3.0, 0.0)];
        assert_eq!(transect_arcs(&corners, 10.0, 0.0).unwrap_err().0, 1);
        assert!(transect_arcs(&corners, 0.5, 0.0).is_ok());
    }
}
