//! A side of the domain: its condition ([`SideBc`]: a wall's closure or an outlet's
//! pressure) and the hydrostatic pressure of an outlet at a point of it, under a uniform
//! gravity or a bent floor (docs/model.md §4.1, §9; cases.md "Top outlet under tilted
//! gravity").

use runout_walls::RobinFace;

use crate::bent_floor::BentFloor;

/// Condition on one side of the domain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SideBc {
    /// Impermeable wall; the closure of the tangential velocity component.
    Wall(RobinFace),
    /// Pressure outlet (or inlet) holding this pressure on the boundary face [Pa].
    Outlet(f64),
    /// Pressure outlet holding the fluid's hydrostatic pressure along it,
    /// p(s) = p0 + ρ g_s s, with s the distance from the side's first corner (south end of
    /// a west/east side, west end of a south/north side) and g_s the gravity component
    /// along the side; it follows the gravity of the moment (cases.md "Top outlet under
    /// tilted gravity").
    HydrostaticOutlet {
        /// pressure at the first corner [Pa]
        p0: f64,
        /// density of the column [kg m⁻³]
        density: f64,
    },
}

impl SideBc {
    /// Whether the side is an outlet (not a wall).
    pub(crate) fn is_outlet(&self) -> bool {
        !matches!(self, SideBc::Wall(_))
    }

    /// Pressure on the outlet at distance `s` from its first corner, with `g_along` the
    /// gravity component along the side; `None` for a wall.
    pub(crate) fn pressure(&self, s: f64, g_along: f64) -> Option<f64> {
        match *self {
            SideBc::Wall(_) => None,
            SideBc::Outlet(p) => Some(p),
            SideBc::HydrostaticOutlet { p0, density } => Some(p0 + density * g_along * s),
        }
    }

    /// Pressure on the outlet where gravity has done `work` per unit mass since its first
    /// corner (a bent floor's potential drop, [`crate::bent_floor::BentFloor::work`]);
    /// `None` for a wall.
    pub(crate) fn pressure_with_work(&self, work: f64) -> Option<f64> {
        match *self {
            SideBc::Wall(_) => None,
            SideBc::Outlet(p) => Some(p),
            SideBc::HydrostaticOutlet { p0, density } => Some(p0 + density * work),
        }
    }
}

/// A point on a side of the domain, for its outlet's hydrostatic pressure.
#[derive(Clone, Copy)]
pub(crate) struct OutletPoint {
    /// the side's first corner (south end of a west/east side, west end of a south/north one)
    corner: (f64, f64),
    /// the point
    point: (f64, f64),
    /// uniform gravity's component along the side [m s⁻²]
    g_along: f64,
}

impl OutletPoint {
    pub(crate) fn on_side(corner: (f64, f64), point: (f64, f64), g_along: f64) -> Self {
        Self {
            corner,
            point,
            g_along,
        }
    }

    /// The distance from the corner along the side (one coordinate differs) [m].
    fn distance(&self) -> f64 {
        (self.point.0 - self.corner.0) + (self.point.1 - self.corner.1)
    }
}

/// A side's outlet pressure at a point: under a bent floor the hydrostatic pressure follows
/// its potential, p0 + ρ (Φ(corner) − Φ(point)); else p0 + ρ g_s s ([`SideBc`]).
pub(crate) fn outlet_pressure(
    bent_floor: Option<&BentFloor>,
    bc: &SideBc,
    at: OutletPoint,
) -> Option<f64> {
    match bent_floor {
        None => bc.pressure(at.distance(), at.g_along),
        Some(b) => bc.pressure_with_work(b.work(at.corner, at.point)),
    }
}
