//! The laboratory's release (issue 57 item 2): a pile given as a polygon in world
//! coordinates (`initial.polygons`), and gates that hold it until they are removed or lifted
//! (`gates`), with their validation.
//!
//! World coordinates are the horizontal distance X and the elevation Z of a point, measured
//! from the floor at the domain's west end, under the case's final gravity: on a plane floor
//! tilted by α, X = (x − x0) cos α + y sin α and Z = −(x − x0) sin α + y cos α; on a bed
//! (docs/model.md §9) X = h(x) + y sin α(x) and Z = z_b(x) + y cos α(x), less their values
//! at (x0, 0). A pile with a horizontal free surface is then a polygon with a horizontal top
//! edge, whatever the slope.

use serde::{Deserialize, Serialize};

use runout_mesh::bent_floor::BentFloor;

use crate::checker::{Checker, B};
use crate::schema::{BlockSolids, Case, Gravity};

/// How far beyond an end of the domain, relative to its length, a polygon's corner is taken
/// on the end wall [-] (a corner written to six digits on the wall falls up to ~1e-7 off it).
pub const CORNER_SLACK: f64 = 1e-5;

/// A region of solids bounded by a polygon in world coordinates (module doc), filled by the
/// exact fraction of each cell it covers, after the rectangular blocks.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Polygon {
    /// its corners (X, Z) [m] in order (either sense), at least three, the edges not crossing
    pub points: Vec<(f64, f64)>,
    /// one entry per solids phase
    pub solids: Vec<BlockSolids>,
}

/// A wall across the flow at `x` (along the floor), from the floor to `height` (normal to
/// it), which holds the solids and the gas until it opens.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Gate {
    /// where it stands along the floor [m], inside the domain (the u face nearest to it)
    pub x: f64,
    /// how high it reaches from the floor [m], in (0, the domain's height]
    pub height: f64,
    /// how it opens
    pub open: GateOpening,
}

/// How a gate opens.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum GateOpening {
    /// removed whole at time `at` [s]
    Removed {
        /// when [s], ≥ 0
        at: f64,
    },
    /// lifted from time `at` [s] at `speed` [m/s]: its lower edge rises from the floor
    Lifted {
        /// when it starts to rise [s], ≥ 0
        at: f64,
        /// how fast [m s⁻¹], > 0
        speed: f64,
    },
}

impl Gate {
    /// Whether the gate blocks the point at height `y` [m] at time `t` [s]: below its top,
    /// and above its lower edge once it is lifted; nowhere once removed.
    pub fn blocks(&self, y: f64, t: f64) -> bool {
        if y >= self.height {
            return false;
        }
        match self.open {
            GateOpening::Removed { at } => t < at,
            GateOpening::Lifted { at, speed } => y >= speed * (t - at).max(0.0),
        }
    }

    /// When the gate starts to open [s].
    pub fn opens_at(&self) -> f64 {
        match self.open {
            GateOpening::Removed { at } | GateOpening::Lifted { at, .. } => at,
        }
    }
}

impl Case {
    /// The floor under the final gravity as bed-following coordinates: the bed's path, or on
    /// a plane floor one straight at the gravity's slope from x = 0 (module doc); an error
    /// only for a case that did not pass validation.
    pub fn floor_map(&self) -> Result<BentFloor, runout_mesh::bent_floor::BentFloorError> {
        if let Some(floor) = self.bent_floor()? {
            return Ok(floor);
        }
        let magnitude = match self.gravity {
            Gravity::Constant { magnitude, .. } | Gravity::TiltOnImpact { magnitude, .. } => {
                magnitude
            }
        };
        BentFloor::path(magnitude, 0.0, self.gravity.slope(), &[])
    }

    /// A polygon's corners in the solver's (x, y), or the index of the first corner the
    /// floor's coordinates cannot reach within the domain's length.
    pub fn polygon_in_domain(&self, polygon: &Polygon) -> Result<Vec<(f64, f64)>, usize> {
        let floor = self.floor_map().map_err(|_| 0usize)?;
        let x = &self.domain.x;
        let origin = (
            floor.floor_horizontal(x.origin),
            floor.floor_elevation(x.origin),
        );
        polygon
            .points
            .iter()
            .enumerate()
            .map(|(k, &(px, pz))| {
                // a corner on an end wall, as written to a few digits, may fall a hair outside
                let slack = CORNER_SLACK * (x.end() - x.origin);
                let range = (x.origin - slack, x.end() + slack);
                floor
                    .to_floor_coordinates((origin.0 + px, origin.1 + pz), range)
                    .map(|(along, y)| (along.clamp(x.origin, x.end()), y))
                    .ok_or(k)
            })
            .collect()
    }
}

/// The signed area of a polygon (shoelace) [m²]: positive anticlockwise.
pub fn signed_area(points: &[(f64, f64)]) -> f64 {
    let n = points.len();
    0.5 * (0..n)
        .map(|k| {
            let (a, b) = (points[k], points[(k + 1) % n]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum::<f64>()
}

/// Whether two closed segments cross or touch.
fn segments_meet(a: ((f64, f64), (f64, f64)), b: ((f64, f64), (f64, f64))) -> bool {
    let cross = |o: (f64, f64), p: (f64, f64), q: (f64, f64)| {
        (p.0 - o.0) * (q.1 - o.1) - (p.1 - o.1) * (q.0 - o.0)
    };
    let (d1, d2) = (cross(b.0, b.1, a.0), cross(b.0, b.1, a.1));
    let (d3, d4) = (cross(a.0, a.1, b.0), cross(a.0, a.1, b.1));
    let within = |o: (f64, f64), p: (f64, f64), q: (f64, f64)| {
        q.0 >= o.0.min(p.0) && q.0 <= o.0.max(p.0) && q.1 >= o.1.min(p.1) && q.1 <= o.1.max(p.1)
    };
    ((d1 > 0.0) != (d2 > 0.0) && (d3 > 0.0) != (d4 > 0.0) && d1 != 0.0 && d2 != 0.0)
        || (d1 == 0.0 && within(b.0, b.1, a.0))
        || (d2 == 0.0 && within(b.0, b.1, a.1))
        || (d3 == 0.0 && within(a.0, a.1, b.0))
        || (d4 == 0.0 && within(a.0, a.1, b.1))
}

/// The index of an edge that meets an edge not next to it (a polygon that crosses itself).
pub fn self_crossing(points: &[(f64, f64)]) -> Option<usize> {
    let n = points.len();
    let edge = |k: usize| (points[k], points[(k + 1) % n]);
    (0..n).find(|&a| {
        (a + 2..n)
            .filter(|&b| (b + 1) % n != a)
            .any(|b| segments_meet(edge(a), edge(b)))
    })
}

/// Checks `initial.polygons` and `gates` (module doc): a polygon has three corners or more,
/// finite, its edges not crossing, an area > 0, all inside the domain in the floor's
/// coordinates, one solids entry per phase; a gate stands inside the domain, reaches no
/// higher than it, opens at t ≥ 0 and rises at a speed > 0; both need solids.
pub(crate) fn check_release(c: &mut Checker, case: &Case) {
    for (k, polygon) in case.initial.polygons.iter().enumerate() {
        let p = format!("initial.polygons[{k}]");
        let points = &polygon.points;
        if points.len() < 3 {
            c.fail(
                format!("{p}.points"),
                format!("{} corners", points.len()),
                "at least 3",
            );
            continue;
        }
        if let Some(i) = points
            .iter()
            .position(|(x, z)| !(x.is_finite() && z.is_finite()))
        {
            c.fail(
                format!("{p}.points[{i}]"),
                "not finite",
                "finite (X, Z) in m",
            );
            continue;
        }
        if let Some(i) = self_crossing(points) {
            c.fail(
                format!("{p}.points[{i}]"),
                "an edge that crosses another",
                "a simple polygon (its edges meet only at shared corners)",
            );
            continue;
        }
        if signed_area(points).abs() <= 0.0 {
            c.fail(
                format!("{p}.points"),
                "zero area",
                "a polygon with an area > 0",
            );
            continue;
        }
        match case.polygon_in_domain(polygon) {
            Err(i) => c.fail(
                format!("{p}.points[{i}]"),
                format!("{:?}", points[i]),
                "a point above the floor within the domain's length (world X, Z from the floor at the domain's west end)",
            ),
            Ok(corners) => {
                let (y0, y1) = (case.domain.y.origin, case.domain.y.end());
                if let Some(i) = corners.iter().position(|&(_, y)| y < y0 - 1e-12 || y > y1 + 1e-12) {
                    c.fail(
                        format!("{p}.points[{i}]"),
                        format!("{:?}, at y = {} m from the floor", points[i], runout_mesh::short(corners[i].1)),
                        format!("inside the domain: 0 ≤ y ≤ {} m", runout_mesh::short(y1)),
                    );
                }
            }
        }
        if polygon.solids.len() != case.solids.len() {
            c.fail(
                format!("{p}.solids"),
                format!("{} entries", polygon.solids.len()),
                format!("one entry per solids phase ({})", case.solids.len()),
            );
        }
    }
    let (x0, x1) = (case.domain.x.origin, case.domain.x.end());
    let height = case.domain.y.end() - case.domain.y.origin;
    for (k, gate) in case.gates.iter().enumerate() {
        let p = format!("gates[{k}]");
        c.range(format!("{p}.x"), gate.x, B::Open(x0), B::Open(x1));
        c.range(
            format!("{p}.height"),
            gate.height,
            B::Open(0.0),
            B::Closed(height),
        );
        match gate.open {
            GateOpening::Removed { at } => {
                c.range(format!("{p}.open.Removed.at"), at, B::Closed(0.0), B::Inf)
            }
            GateOpening::Lifted { at, speed } => {
                c.range(format!("{p}.open.Lifted.at"), at, B::Closed(0.0), B::Inf);
                c.range(
                    format!("{p}.open.Lifted.speed"),
                    speed,
                    B::Open(0.0),
                    B::Inf,
                );
            }
        }
    }
    if case.solids.is_empty() && !(case.gates.is_empty() && case.initial.polygons.is_empty()) {
        c.fail(
            "gates",
            "a gate or polygon in a gas-only case",
            "none (gates and polygons are two-fluid options)",
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crossing_polygons_are_found() {
        let square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        assert_eq!(self_crossing(&square), None);
        assert_eq!(signed_area(&square), 1.0);
        let bow_tie = [(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)];
        assert!(self_crossing(&bow_tie).is_some());
        let wedge = [(0.0, 0.0), (2.0, -1.0), (2.0, 0.5)];
        assert_eq!(self_crossing(&wedge), None);
        assert!(signed_area(&wedge) > 0.0);
    }

    #[test]
    fn a_lifted_gate_opens_from_the_floor() {
        let gate = Gate {
            x: 1.0,
            height: 0.2,
            open: GateOpening::Lifted {
                at: 0.5,
                speed: 0.1,
            },
        };
        assert!(gate.blocks(0.0, 0.4) && gate.blocks(0.19, 0.4) && !gate.blocks(0.2, 0.4));
        assert!(!gate.blocks(0.04, 1.0) && gate.blocks(0.06, 1.0));
        let removed = Gate {
            open: GateOpening::Removed { at: 0.5 },
            ..gate
        };
        assert!(removed.blocks(0.1, 0.49) && !removed.blocks(0.1, 0.5));
    }
}
