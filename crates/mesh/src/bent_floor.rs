//! A floor whose slope turns onto a shallower run-out: gravity and the centrifugal force in
//! bed-following coordinates (docs/model.md §9, issue 43 item 5).
//!
//! runout's slopes are a tilted gravity over one plane floor. A foot that turns needs the
//! coordinates to follow the floor: x is the distance along it, y the distance from it. The
//! floor's angle (positive downhill towards +x) is
//!
//!   α(x) = α₀                     for x ≤ x_b,
//!   α(x) = α₀ − (x − x_b)/R       on the arc x_b ≤ x ≤ x_e = x_b + R (α₀ − α₁),
//!   α(x) = α₁                     beyond,
//!
//! a circular arc of radius R joining the slope α₀ to the run-out α₁ < α₀, with curvature
//! κ = −dα/dx = 1/R on the arc (concave: the centre lies above the floor) and 0 elsewhere.
//!
//! A point (x, y) of the flow lies at the elevation z = z_b(x) + y cos α(x), with
//! z_b(x) = −∫ sin α dx the floor's elevation (the thin-layer map of Savage & Hutter 1991,
//! Acta Mech. 86, §2; it neglects the metric factor 1 − κ y):
//!
//!   z_b(x) = −x sin α₀                                   for x ≤ x_b,
//!   z_b(x) = −x_b sin α₀ − R (cos α(x) − cos α₀)           on the arc,
//!   z_b(x) = z_b(x_e) − (x − x_e) sin α₁                   beyond.
//!
//! Gravity is −∇Φ of the potential Φ = g z taken in these coordinates,
//!
//!   f_x = g sin α (1 − κ y),   f_y = −g cos α,
//!
//! so it stays conservative: a gas at rest under the hydrostatic p = p_ref − ρ_g (Φ − Φ_ref)
//! stays at rest on the bend. On the straight parts it is the tilted gravity of a plane
//! floor, (g sin α, −g cos α). The discrete momentum equations take the x component as the
//! potential's difference between the two cells beside a u node, so the balance with the
//! hydrostatic pressure holds to round-off on any grid ([`BentFloor::force_x_between`]).
//!
//! A grain following the concave floor at speed u needs the centripetal acceleration κ u²
//! towards the centre; in the floor's frame it is the centrifugal body force −κ u² along y,
//! pressing the flow onto the floor (Savage & Hutter 1991, the curvature term of the normal
//! momentum). Left out, and stated as the validity: the metric factor 1/(1 − κ y) of the
//! derivatives along x and the term κ u v of the x momentum, both of order κ h for a flow of
//! thickness h: the map holds for h ≪ R. Above the flow, the gas sees the same map; at rest
//! it is exact, in motion its error is of order κ y.

/// A slope of angle α₀ whose foot turns on an arc of radius R onto the run-out angle α₁.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BentFloor {
    /// |g| [m s⁻²]
    gravity: f64,
    /// slope before the bend α₀ [rad]
    slope: f64,
    /// slope after the bend α₁ [rad], 0 ≤ α₁ < α₀
    slope_after: f64,
    /// where the arc starts, x_b [m along the floor]
    start: f64,
    /// arc radius R [m]
    radius: f64,
}

/// Why a bent floor was refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum BentFloorError {
    /// the numbers cannot make a concave foot
    #[error("a bent floor needs |g| ≥ 0, 0 ≤ slope_after < slope < 90°, R > 0 and a finite start (got |g| = {gravity}, slope {slope}°, slope_after {slope_after}°, R = {radius} m, start {start} m)")]
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
}

impl BentFloor {
    /// The floor of slope `slope_deg` that turns at x = `start` on an arc of `radius` onto
    /// `slope_after_deg`, under gravity of magnitude `gravity`.
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
        Ok(Self {
            gravity,
            slope: slope_deg.to_radians(),
            slope_after: slope_after_deg.to_radians(),
            start,
            radius,
        })
    }

    /// Where the arc starts, x_b [m].
    pub fn start(&self) -> f64 {
        self.start
    }

    /// Where the arc ends, x_e = x_b + R (α₀ − α₁) [m].
    pub fn end(&self) -> f64 {
        self.start + self.radius * (self.slope - self.slope_after)
    }

    /// The floor's angle α(x) [rad].
    pub fn angle(&self, x: f64) -> f64 {
        if x <= self.start {
            self.slope
        } else if x >= self.end() {
            self.slope_after
        } else {
            self.slope - (x - self.start) / self.radius
        }
    }

    /// The floor's curvature κ(x) = −dα/dx [m⁻¹]: 1/R on the arc, 0 elsewhere.
    pub fn curvature(&self, x: f64) -> f64 {
        if x > self.start && x < self.end() {
            1.0 / self.radius
        } else {
            0.0
        }
    }

    /// The floor's elevation z_b(x) [m] (module doc), 0 at x = 0.
    pub fn floor_elevation(&self, x: f64) -> f64 {
        let before = |x: f64| -x * self.slope.sin();
        if x <= self.start {
            return before(x);
        }
        let on_arc =
            |x: f64| before(self.start) - self.radius * (self.angle(x).cos() - self.slope.cos());
        let end = self.end();
        if x < end {
            on_arc(x)
        } else {
            on_arc(end) - (x - end) * self.slope_after.sin()
        }
    }

    /// The horizontal distance of floor point x from x = 0, ∫₀ˣ cos α dx' [m]: x cos α₀
    /// before the arc, + R (sin α₀ − sin α(x)) on it, + (x − x_e) cos α₁ beyond.
    pub fn floor_horizontal(&self, x: f64) -> f64 {
        let before = |x: f64| x * self.slope.cos();
        if x <= self.start {
            return before(x);
        }
        let on_arc =
            |x: f64| before(self.start) + self.radius * (self.slope.sin() - self.angle(x).sin());
        let end = self.end();
        if x < end {
            on_arc(x)
        } else {
            on_arc(end) + (x - end) * self.slope_after.cos()
        }
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
        let drop = f.floor_elevation(f.start) - f.floor_elevation(f.end());
        assert!((drop - 2.0 * (1.0 - a.cos())).abs() < 1e-14);
        // horizontal run of the arc: ∫ cos α dx = R (sin α₀ − sin α₁)
        let run = 2.0 * a.sin();
        let chord = (drop * drop + run * run).sqrt();
        assert!((chord - 2.0 * 2.0 * (a / 2.0).sin()).abs() < 1e-13);
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
