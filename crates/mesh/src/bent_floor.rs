//! A floor of straight pieces joined by circular arcs: gravity and the centrifugal force in
//! bed-following coordinates (docs/model.md §9; issue 43 item 5, issue 57 item 1).
//!
//! runout's slopes are a tilted gravity over one plane floor. A floor whose slope changes
//! needs the coordinates to follow it: x is the distance along the floor, y the distance
//! from it. The floor is a path of pieces k = 0, 1, …, each starting at x = s_k with the
//! angle α_k (positive downhill towards +x), the elevation z_k and the horizontal distance
//! h_k: a straight keeps its angle,
//!
//!   α(x) = α_k,
//!
//! an arc of signed radius R_k (> 0 concave, the floor turning flatter with the centre above
//! it; < 0 convex) turns it,
//!
//!   α(x) = α_k − (x − s_k)/R_k,
//!
//! with curvature κ = −dα/dx = 1/R_k on the arc and 0 on a straight. The first piece is a
//! straight through x = 0 (Bend) or the domain's west end (a path) and runs back without
//! end; the last runs on without end.
//!
//! A point (x, y) of the flow lies at the elevation z = z_b(x) + y cos α(x), with
//! z_b(x) = −∫ sin α dx the floor's elevation (the thin-layer map of Savage & Hutter 1991,
//! Acta Mech. 86, §2; it neglects the metric factor 1 − κ y):
//!
//!   z_b(x) = z_k − (x − s_k) sin α_k                  on a straight,
//!   z_b(x) = z_k − R_k (cos α(x) − cos α_k)             on an arc,
//!
//! and its horizontal distance ∫ cos α dx is h_k + (x − s_k) cos α_k on a straight,
//! h_k + R_k (sin α_k − sin α(x)) on an arc.
//!
//! Gravity is −∇Φ of the potential Φ = g z taken in these coordinates,
//!
//!   f_x = g sin α (1 − κ y),   f_y = −g cos α,
//!
//! so it stays conservative: a gas at rest under the hydrostatic p = p_ref − ρ_g (Φ − Φ_ref)
//! stays at rest on every bend. On the straight pieces it is the tilted gravity of a plane
//! floor, (g sin α, −g cos α). The discrete momentum equations take the x component as the
//! potential's difference between the two cells beside a u node, so the balance with the
//! hydrostatic pressure holds to round-off on any grid ([`BentFloor::force_x_between`]).
//!
//! A grain following the floor at speed u needs the centripetal acceleration κ u² towards
//! the arc's centre; in the floor's frame it is the centrifugal body force −κ u² along y,
//! pressing the flow onto a concave floor and lifting it from a convex one (Savage & Hutter
//! 1991, the curvature term of the normal momentum). Left out, and stated as the validity:
//! the metric factor 1/(1 − κ y) of the derivatives along x and the term κ u v of the x
//! momentum, both of order κ h for a flow of thickness h: the map holds for h ≪ |R|. Above
//! the flow, the gas sees the same map; at rest it is exact, in motion its error is of order
//! κ y. Where a concave arc's radius is no larger than the domain's height the normals cross
//! inside the domain (the map folds); a case refuses that ([`BentFloor::tightest_concave_radius`]).

use std::sync::Arc;

/// One arc of a floor's path: where it starts along the floor, its radius and the angle it
/// turns the floor to; the floor is straight between arcs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArcSpec {
    /// where the arc starts, along the floor [m]
    pub start: f64,
    /// its radius R [m], > 0
    pub radius: f64,
    /// the floor's angle after it [deg], downhill positive, in (−90°, 90°)
    pub to_slope_deg: f64,
}

/// One piece of the path (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Piece {
    /// s_k [m]
    start: f64,
    /// α_k [rad]
    angle: f64,
    /// R_k [m], signed (module doc); `None` on a straight
    radius: Option<f64>,
    /// z_k [m]
    elevation: f64,
    /// h_k [m]
    horizontal: f64,
}

impl Piece {
    fn angle_at(&self, x: f64) -> f64 {
        match self.radius {
            None => self.angle,
            Some(r) => self.angle - (x - self.start) / r,
        }
    }

    fn elevation_at(&self, x: f64) -> f64 {
        match self.radius {
            None => self.elevation - (x - self.start) * self.angle.sin(),
            Some(r) => self.elevation - r * (self.angle_at(x).cos() - self.angle.cos()),
        }
    }

    fn horizontal_at(&self, x: f64) -> f64 {
        match self.radius {
            None => self.horizontal + (x - self.start) * self.angle.cos(),
            Some(r) => self.horizontal + r * (self.angle.sin() - self.angle_at(x).sin()),
        }
    }
}

/// A floor of straight pieces joined by circular arcs under gravity of a given magnitude
/// (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct BentFloor {
    /// |g| [m s⁻²]
    gravity: f64,
    /// the path's pieces, in order along x
    pieces: Arc<[Piece]>,
}

/// Why a bent floor was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum BentFloorError {
    /// the numbers cannot make a concave foot
    #[error("a bent floor needs |g| ≥ 0, 0 ≤ slope_after < slope < 90°, R > 0 and a finite start (got |g| = {gravity:?}, slope {slope:?}°, slope_after {slope_after:?}°, R = {radius:?} m, start {start:?} m)")]
    Invalid {
        /// |g|
        gravity: f64,
        /// α₀ [deg]
        slope: f64,
        /// α₁ [deg]
        slope_after: f64,
        /// R [m]
        radius: f64,
        /// x_b [m]
        start: f64,
    },
    /// one arc of a path cannot be built
    #[error("arc {index} of the floor's path: {reason}")]
    Arc {
        /// the arc's index from 0
        index: usize,
        /// why
        reason: String,
    },
}

impl BentFloor {
    /// The floor of slope `slope_deg` that turns at x = `start` on an arc of `radius` onto
    /// `slope_after_deg`, under gravity of magnitude `gravity` (`bed: Bend`): a concave
    /// foot, its first straight through x = 0 at elevation 0.
    pub fn new(
        gravity: f64,
        slope_deg: f64,
        slope_after_deg: f64,
        start: f64,
        radius: f64,
    ) -> Result<Self, BentFloorError> {
        let valid = gravity.is_finite()
            && gravity >= 0.0
            && (0.0..90.0).contains(&slope_deg)
            && (0.0..slope_deg).contains(&slope_after_deg)
            && radius.is_finite()
            && radius > 0.0
            && start.is_finite();
        if !valid {
            return Err(BentFloorError::Invalid {
                gravity,
                slope: slope_deg,
                slope_after: slope_after_deg,
                radius,
                start,
            });
        }
        let arc = ArcSpec {
            start,
            radius,
            to_slope_deg: slope_after_deg,
        };
        Self::path(gravity, 0.0, slope_deg, &[arc])
    }

    /// The floor that starts at x = `origin` (elevation and horizontal distance 0 there) with
    /// the angle `first_slope_deg` and turns on each of `arcs` in turn, straight between
    /// them, under gravity of magnitude `gravity`. Refused: a non-finite or negative |g|, an
    /// angle outside (−90°, 90°) (a slope beyond vertical), a radius not > 0, an arc that
    /// does not turn, or one that starts before the previous arc ends.
    pub fn path(
        gravity: f64,
        origin: f64,
        first_slope_deg: f64,
        arcs: &[ArcSpec],
    ) -> Result<Self, BentFloorError> {
        let invalid = |index: usize, reason: String| BentFloorError::Arc { index, reason };
        let upright = |deg: f64| deg.is_finite() && deg.abs() < 90.0;
        if !(gravity.is_finite() && gravity >= 0.0 && origin.is_finite()) {
            return Err(invalid(
                0,
                format!(
                    "|g| = {}, origin {}: both finite, |g| ≥ 0",
                    crate::short(gravity),
                    crate::short(origin)
                ),
            ));
        }
        if !upright(first_slope_deg) {
            return Err(invalid(
                0,
                format!(
                    "the first slope {}° is not in (−90°, 90°)",
                    crate::short(first_slope_deg)
                ),
            ));
        }
        let mut pieces = vec![Piece {
            start: origin,
            angle: first_slope_deg.to_radians(),
            radius: None,
            elevation: 0.0,
            horizontal: 0.0,
        }];
        for (index, arc) in arcs.iter().enumerate() {
            let before = *pieces.last().expect("the first straight");
            if !(arc.radius.is_finite() && arc.radius > 0.0) {
                return Err(invalid(
                    index,
                    format!("radius {} m is not > 0", crate::short(arc.radius)),
                ));
            }
            if !upright(arc.to_slope_deg) {
                return Err(invalid(
                    index,
                    format!(
                        "slope {}° is not in (−90°, 90°): beyond vertical",
                        crate::short(arc.to_slope_deg)
                    ),
                ));
            }
            let to = arc.to_slope_deg.to_radians();
            if to == before.angle {
                return Err(invalid(
                    index,
                    format!(
                        "it does not turn (slope {}° before and after)",
                        crate::short(arc.to_slope_deg)
                    ),
                ));
            }
            if !(arc.start.is_finite() && arc.start >= before.start) {
                return Err(invalid(
                    index,
                    format!(
                        "it starts at x = {} m, before the straight it leaves (x = {} m)",
                        crate::short(arc.start),
                        crate::short(before.start)
                    ),
                ));
            }
            // concave (turning flatter, the centre above the floor): R > 0; convex: R < 0
            let radius = if to < before.angle {
                arc.radius
            } else {
                -arc.radius
            };
            let on_arc = Piece {
                start: arc.start,
                angle: before.angle,
                radius: Some(radius),
                elevation: before.elevation_at(arc.start),
                horizontal: before.horizontal_at(arc.start),
            };
            let end = arc.start + radius * (before.angle - to);
            pieces.push(on_arc);
            pieces.push(Piece {
                start: end,
                angle: to,
                radius: None,
                elevation: on_arc.elevation - radius * (to.cos() - on_arc.angle.cos()),
                horizontal: on_arc.horizontal + radius * (on_arc.angle.sin() - to.sin()),
            });
        }
        Ok(Self {
            gravity,
            pieces: pieces.into(),
        })
    }

    /// The piece that holds x: an arc holds the open interval between its ends, a straight
    /// its start and what follows up to the next arc.
    fn piece(&self, x: f64) -> &Piece {
        let after = self.pieces.partition_point(|p| p.start < x);
        match self.pieces.get(after) {
            Some(p) if p.start == x && p.radius.is_none() => p,
            _ => &self.pieces[after.saturating_sub(1)],
        }
    }

    /// Where the first arc starts [m] (+∞ on a path without arcs).
    pub fn start(&self) -> f64 {
        self.pieces.get(1).map_or(f64::INFINITY, |p| p.start)
    }

    /// Where the last arc ends [m]: the foot of the last bend (−∞ without arcs).
    pub fn end(&self) -> f64 {
        if self.pieces.len() > 1 {
            self.pieces[self.pieces.len() - 1].start
        } else {
            f64::NEG_INFINITY
        }
    }

    /// The floor's angle α(x) [rad].
    pub fn angle(&self, x: f64) -> f64 {
        self.piece(x).angle_at(x)
    }

    /// The floor's curvature κ(x) = −dα/dx [m⁻¹]: 1/R on an arc (negative on a convex one),
    /// 0 on a straight.
    pub fn curvature(&self, x: f64) -> f64 {
        self.piece(x).radius.map_or(0.0, |r| 1.0 / r)
    }

    /// The smallest radius of the path's concave arcs [m] (+∞ without one): a domain at
    /// least this high folds (module doc).
    pub fn tightest_concave_radius(&self) -> f64 {
        self.pieces
            .iter()
            .filter_map(|p| p.radius)
            .filter(|&r| r > 0.0)
            .fold(f64::INFINITY, f64::min)
    }

    /// The floor's elevation z_b(x) [m] (module doc), 0 at the path's origin.
    pub fn floor_elevation(&self, x: f64) -> f64 {
        self.piece(x).elevation_at(x)
    }

    /// The horizontal distance of floor point x from the path's origin, ∫ cos α dx' [m].
    pub fn floor_horizontal(&self, x: f64) -> f64 {
        self.piece(x).horizontal_at(x)
    }

    /// The potential Φ = g (z_b(x) + y cos α(x)) [m² s⁻²] whose gradient gravity is.
    pub fn potential(&self, x: f64, y: f64) -> f64 {
        self.gravity * (self.floor_elevation(x) + y * self.angle(x).cos())
    }

    /// Gravity (f_x, f_y) = (g sin α (1 − κ y), −g cos α) at (x, y) [m s⁻²].
    pub fn force(&self, x: f64, y: f64) -> (f64, f64) {
        let a = self.angle(x);
        (
            self.gravity * a.sin() * (1.0 - self.curvature(x) * y),
            -self.gravity * a.cos(),
        )
    }

    /// The x component between two points at the same y, −(Φ(x_e, y) − Φ(x_w, y))/(x_e − x_w):
    /// the u node's body force, in balance with a hydrostatic pressure to round-off.
    pub fn force_x_between(&self, x_w: f64, x_e: f64, y: f64) -> f64 {
        -(self.potential(x_e, y) - self.potential(x_w, y)) / (x_e - x_w)
    }

    /// The work of gravity per unit mass from `from` to `to`, Φ(from) − Φ(to) [m² s⁻²]: a
    /// hydrostatic pressure rises by ρ times it.
    pub fn work(&self, from: (f64, f64), to: (f64, f64)) -> f64 {
        self.potential(from.0, from.1) - self.potential(to.0, to.1)
    }

    /// The centrifugal body force along y of a flow moving at `u` along the floor,
    /// −κ(x) u² [m s⁻²] (module doc).
    pub fn centrifugal(&self, x: f64, u: f64) -> f64 {
        -self.curvature(x) * u * u
    }

    /// The bed-following (x, y) of the world point (`horizontal`, `elevation`) on this
    /// floor's scale (∫ cos α dx and z_b from the path's origin): the x in `range` whose
    /// normal passes through the point, found by bisection of the tangential offset
    /// (X − h(x)) cos α − (Z − z_b(x)) sin α, which falls with x where the map does not fold;
    /// `None` when no normal from `range` reaches it.
    pub fn to_floor_coordinates(
        &self,
        (horizontal, elevation): (f64, f64),
        range: (f64, f64),
    ) -> Option<(f64, f64)> {
        let offset = |x: f64| {
            let a = self.angle(x);
            (horizontal - self.floor_horizontal(x)) * a.cos()
                - (elevation - self.floor_elevation(x)) * a.sin()
        };
        let (mut lo, mut hi) = range;
        let (f_lo, f_hi) = (offset(lo), offset(hi));
        if f_lo < 0.0 || f_hi > 0.0 {
            return None;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if offset(mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let x = 0.5 * (lo + hi);
        let a = self.angle(x);
        let y = (horizontal - self.floor_horizontal(x)) * a.sin()
            + (elevation - self.floor_elevation(x)) * a.cos();
        Some((x, y))
    }

    /// The path as rows (from x, to x, what, angle at the start and end [deg], elevation and
    /// horizontal distance at the start [m]) for `runout mesh` and `runout check --explain`,
    /// between `from` and `to` (the domain's ends).
    pub fn describe(&self, from: f64, to: f64) -> String {
        let mut out =
            String::from("  floor path (x along the floor; z elevation, h horizontal distance):\n");
        for (k, p) in self.pieces.iter().enumerate() {
            let (a, b) = (
                p.start.max(from),
                self.pieces.get(k + 1).map_or(to, |n| n.start.min(to)),
            );
            if b <= a && !(k == 0 && a == b) {
                continue;
            }
            let what = match p.radius {
                None => String::from("straight"),
                Some(r) if r > 0.0 => format!("concave arc R = {} m", crate::short(r)),
                Some(r) => format!("convex arc R = {} m", crate::short(-r)),
            };
            out.push_str(&format!(
                "    x {a:>9.3} … {b:<9.3} m  {what:<22} slope {:>7.3}° → {:>7.3}°   z {:>9.4} m  h {:>9.4} m\n",
                self.angle(a).to_degrees(),
                p.angle_at(b).to_degrees(),
                self.floor_elevation(a),
                self.floor_horizontal(a),
            ));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn foot() -> BentFloor {
        BentFloor::new(9.81, 40.0, 0.0, 10.0, 2.0).unwrap()
    }

    /// The floor's elevation against a direct quadrature of −∫ sin α dx (midpoint rule,
    /// 200 000 intervals, second order: agreement to 1e-9 m).
    #[test]
    fn elevation_is_the_integral_of_the_slope() {
        let f = foot();
        let n = 200_000;
        let x_end = 20.0;
        let h = x_end / n as f64;
        let mut z = 0.0;
        for k in 0..n {
            let x = (k as f64 + 0.5) * h;
            z -= f.angle(x).sin() * h;
            let xk = (k + 1) as f64 * h;
            if (k + 1) % 10_000 == 0 {
                assert!((z - f.floor_elevation(xk)).abs() < 1e-9, "x = {xk}");
            }
        }
    }

    /// f = −∇Φ: each component against a central difference of the potential (1e-6), in the
    /// arc and on both straight parts.
    #[test]
    fn force_is_the_gradient_of_the_potential() {
        let f = foot();
        let h = 1e-5;
        for &(x, y) in &[(5.0, 0.3), (10.7, 0.05), (11.2, 1.5), (15.0, 0.8)] {
            let (fx, fy) = f.force(x, y);
            let dx = -(f.potential(x + h, y) - f.potential(x - h, y)) / (2.0 * h);
            let dy = -(f.potential(x, y + h) - f.potential(x, y - h)) / (2.0 * h);
            assert!((fx - dx).abs() < 1e-6, "f_x at ({x}, {y}): {fx} vs {dx}");
            assert!((fy - dy).abs() < 1e-6, "f_y at ({x}, {y}): {fy} vs {dy}");
        }
    }

    /// On the straight parts the field is the tilted gravity of a plane floor, and the arc
    /// turns the floor by α₀ − α₁ over R (α₀ − α₁) of floor.
    #[test]
    fn straight_parts_are_the_tilted_gravity() {
        let f = foot();
        let a = 40f64.to_radians();
        let (fx, fy) = f.force(3.0, 0.4);
        assert!((fx - 9.81 * a.sin()).abs() < 1e-14 && (fy + 9.81 * a.cos()).abs() < 1e-14);
        let (fx, fy) = f.force(18.0, 0.4);
        assert!(fx.abs() < 1e-14 && (fy + 9.81).abs() < 1e-14);
        assert!((f.end() - (10.0 + 2.0 * a)).abs() < 1e-14);
        assert_eq!(f.curvature(11.0), 0.5);
        assert_eq!(f.centrifugal(11.0, 4.0), -8.0);
        assert_eq!(f.centrifugal(9.0, 4.0), 0.0);
    }

    /// The horizontal distance is ∫ cos α dx (the midpoint quadrature as for the elevation).
    #[test]
    fn horizontal_distance_is_the_integral_of_the_cosine() {
        let f = foot();
        let n = 200_000;
        let h = 20.0 / n as f64;
        let mut run = 0.0;
        for k in 0..n {
            run += f.angle((k as f64 + 0.5) * h).cos() * h;
            let xk = (k + 1) as f64 * h;
            if (k + 1) % 10_000 == 0 {
                assert!((run - f.floor_horizontal(xk)).abs() < 1e-9, "x = {xk}");
            }
        }
    }

    /// The floor's elevation is the true geometry's: the arc's chord from x_b to x_e drops by
    /// R (cos α₁ − cos α₀) and runs 2 R sin((α₀ − α₁)/2) (a circle's chord).
    #[test]
    fn the_arc_is_a_circle() {
        let f = foot();
        let a = 40f64.to_radians();
        let drop = f.floor_elevation(f.start()) - f.floor_elevation(f.end());
        assert!((drop - 2.0 * (1.0 - a.cos())).abs() < 1e-14);
        // horizontal run of the arc: ∫ cos α dx = R (sin α₀ − sin α₁)
        let run = 2.0 * a.sin();
        let chord = (drop * drop + run * run).sqrt();
        assert!((chord - 2.0 * 2.0 * (a / 2.0).sin()).abs() < 1e-13);
    }

    /// A path with a concave and a convex arc, an uphill counter-slope and two straights: the
    /// elevation and horizontal distance against a midpoint quadrature of the angle (1e-9 m),
    /// the curvature's sign, and f = −∇Φ on every piece.
    fn hills() -> BentFloor {
        let arcs = [
            ArcSpec {
                start: 4.0,
                radius: 3.0,
                to_slope_deg: 10.0,
            },
            ArcSpec {
                start: 8.0,
                radius: 2.0,
                to_slope_deg: 25.0,
            },
            ArcSpec {
                start: 10.0,
                radius: 4.0,
                to_slope_deg: -5.0,
            },
        ];
        BentFloor::path(9.81, -1.0, 35.0, &arcs).unwrap()
    }

    #[test]
    fn a_path_is_the_integral_of_its_angle() {
        let f = hills();
        let (x0, x1, n) = (-1.0, 20.0, 210_000);
        let h = (x1 - x0) / n as f64;
        let (mut z, mut run) = (0.0, 0.0);
        for k in 0..n {
            let a = f.angle(x0 + (k as f64 + 0.5) * h);
            z -= a.sin() * h;
            run += a.cos() * h;
            let xk = x0 + (k + 1) as f64 * h;
            if (k + 1) % 10_000 == 0 {
                assert!((z - f.floor_elevation(xk)).abs() < 1e-9, "z at x = {xk}");
                assert!((run - f.floor_horizontal(xk)).abs() < 1e-9, "h at x = {xk}");
            }
        }
        assert_eq!(f.floor_elevation(-1.0), 0.0);
        let first_end = 4.0 + 3.0 * 25f64.to_radians();
        assert!((f.angle(first_end + 0.1) - 10f64.to_radians()).abs() < 1e-15);
        assert_eq!(f.curvature(5.0), 1.0 / 3.0);
        assert_eq!(f.curvature(8.1), -0.5, "convex");
        assert_eq!(f.curvature(9.0), 0.0, "the straight between");
        assert!(
            f.curvature(11.0) > 0.0 && f.angle(30.0) < 0.0,
            "concave onto a counter-slope"
        );
        assert_eq!(f.tightest_concave_radius(), 3.0);
        let e = 1e-5;
        for &(x, y) in &[
            (0.0, 0.2),
            (5.0, 0.3),
            (8.2, 0.1),
            (9.5, 0.4),
            (11.0, 0.2),
            (19.0, 0.5),
        ] {
            let (fx, fy) = f.force(x, y);
            let dx = -(f.potential(x + e, y) - f.potential(x - e, y)) / (2.0 * e);
            let dy = -(f.potential(x, y + e) - f.potential(x, y - e)) / (2.0 * e);
            assert!(
                (fx - dx).abs() < 1e-6 && (fy - dy).abs() < 1e-6,
                "({x}, {y})"
            );
        }
    }

    /// World points mapped back to the floor's coordinates land where they came from (1e-9
    /// m), on straights, concave and convex arcs; a point beyond the range is refused.
    #[test]
    fn world_points_map_back_to_the_floor() {
        let f = hills();
        for &(x, y) in &[
            (0.5, 0.3),
            (5.0, 0.8),
            (8.3, 0.05),
            (9.5, 1.2),
            (11.0, 0.4),
            (18.0, 1.0),
        ] {
            let a = f.angle(x);
            let world = (
                f.floor_horizontal(x) + y * a.sin(),
                f.floor_elevation(x) + y * a.cos(),
            );
            let (xb, yb) = f.to_floor_coordinates(world, (-1.0, 20.0)).unwrap();
            assert!(
                (xb - x).abs() < 1e-9 && (yb - y).abs() < 1e-9,
                "({x}, {y}) → ({xb}, {yb})"
            );
        }
        let beyond = (f.floor_horizontal(20.0) + 1.0, f.floor_elevation(20.0));
        assert_eq!(f.to_floor_coordinates(beyond, (-1.0, 20.0)), None);
    }

    /// `bed: Bend` is the path with one arc from x = 0, and that path's numbers are those of
    /// the closed forms the single bend was written with before paths existed, exactly (the
    /// one difference: z_b(0) is +0 where they gave −0).
    #[test]
    fn a_bend_is_the_closed_form_bit_for_bit() {
        let f = foot();
        let (a0, a1, xb, r) = (40f64.to_radians(), 0.0f64, 10.0, 2.0);
        let xe = xb + r * (a0 - a1);
        let angle = |x: f64| {
            if x <= xb {
                a0
            } else if x >= xe {
                a1
            } else {
                a0 - (x - xb) / r
            }
        };
        let z = |x: f64| {
            let arc = |x: f64| -xb * a0.sin() - r * (angle(x).cos() - a0.cos());
            if x <= xb {
                -x * a0.sin()
            } else if x < xe {
                arc(x)
            } else {
                arc(xe) - (x - xe) * a1.sin()
            }
        };
        for k in 0..=4000 {
            let x = -3.0 + k as f64 * 0.006;
            assert_eq!(f.angle(x).to_bits(), angle(x).to_bits(), "α at {x}");
            assert_eq!(f.floor_elevation(x), z(x), "z at {x}");
        }
        for x in [xb, xe] {
            assert_eq!(f.angle(x).to_bits(), angle(x).to_bits());
            assert_eq!(f.curvature(x), 0.0, "the arc is open at its ends");
        }
    }

    #[test]
    fn paths_beyond_vertical_or_out_of_order_are_refused() {
        let arc = |start, radius, to| ArcSpec {
            start,
            radius,
            to_slope_deg: to,
        };
        assert!(BentFloor::path(9.81, 0.0, 95.0, &[]).is_err());
        assert!(BentFloor::path(9.81, 0.0, 30.0, &[arc(1.0, 1.0, -90.0)]).is_err());
        assert!(BentFloor::path(9.81, 0.0, 30.0, &[arc(1.0, 0.0, 10.0)]).is_err());
        assert!(BentFloor::path(9.81, 0.0, 30.0, &[arc(1.0, 1.0, 30.0)]).is_err());
        assert!(
            BentFloor::path(9.81, 0.0, 30.0, &[arc(1.0, 1.0, 10.0), arc(1.2, 1.0, 0.0)]).is_err()
        );
        assert!(BentFloor::path(9.81, 2.0, 30.0, &[arc(1.0, 1.0, 10.0)]).is_err());
        assert!(BentFloor::path(
            9.81,
            0.0,
            30.0,
            &[arc(1.0, 1.0, 10.0), arc(1.0 + 20f64.to_radians(), 1.0, 0.0)]
        )
        .is_ok());
    }

    #[test]
    fn convex_or_degenerate_floors_are_refused() {
        assert!(BentFloor::new(9.81, 30.0, 35.0, 10.0, 2.0).is_err());
        assert!(BentFloor::new(9.81, 30.0, 30.0, 10.0, 2.0).is_err());
        assert!(BentFloor::new(9.81, 30.0, 0.0, 10.0, 0.0).is_err());
        assert!(BentFloor::new(9.81, 30.0, 0.0, f64::NAN, 2.0).is_err());
        assert!(BentFloor::new(9.81, 30.0, -1.0, 10.0, 2.0).is_err());
    }
}
