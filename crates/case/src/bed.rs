//! The `bed` option of a case: a floor whose slope turns at its foot onto a shallower run-out,
//! in bed-following coordinates (docs/model.md §9), and its validation.

use serde::{Deserialize, Serialize};

use runout_mesh::bent_floor::{BentFloor, BentFloorError};

use crate::checker::{Checker, B};
use crate::schema::{Case, Gravity};

/// The floor's shape. `Plane` (the default): one plane floor under the case's uniform
/// (tilted) gravity. `Bend`: x runs along the floor and y normal to it; the floor keeps the
/// gravity's slope up to x = `at`, turns on a circular arc of `radius` onto `slope_after`
/// and keeps that to the end of the domain (docs/model.md §9: gravity follows the floor's
/// angle and the flow feels the centrifugal force −κ u² on the arc; valid for flows much
/// thinner than the radius).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Bed {
    /// one plane floor
    #[default]
    Plane,
    /// a slope whose foot turns onto a run-out
    Bend {
        /// where the arc starts, along the floor [m], inside the domain
        at: f64,
        /// arc radius R [m], > 0
        radius: f64,
        /// the run-out's slope after the arc [deg], 0 ≤ slope_after < the gravity's slope
        #[serde(default)]
        slope_after: f64,
    },
}

impl Bed {
    /// Whether this is the default plane floor (then not written to resolved cases, so
    /// that cases and run folders from before the option existed are unchanged).
    pub fn is_plane(&self) -> bool {
        *self == Bed::Plane
    }
}

impl Case {
    /// The bent floor of a case with `bed: Bend(..)` under its final (tilted) gravity
    /// (docs/model.md §9), `Ok(None)` on a plane floor; an error only for a case that did
    /// not pass validation.
    pub fn bent_floor(&self) -> Result<Option<BentFloor>, BentFloorError> {
        let Bed::Bend {
            at,
            radius,
            slope_after,
        } = self.bed
        else {
            return Ok(None);
        };
        let magnitude = match self.gravity {
            Gravity::Constant { magnitude, .. } | Gravity::TiltOnImpact { magnitude, .. } => {
                magnitude
            }
        };
        BentFloor::new(magnitude, self.gravity.slope(), slope_after, at, radius).map(Some)
    }
}

/// Checks `bed.Bend.*`: the arc starts inside the domain and ends before its east end, the
/// radius is > 0 and the run-out is shallower than the slope (a concave foot); a bend needs
/// solids (the two-fluid model) and a tilted gravity.
pub(crate) fn check_bed(c: &mut Checker, case: &Case) {
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
    if case.solids.is_empty() {
        c.fail(
            "bed",
            "Bend",
            "Plane for a gas-only case (a bent floor is a two-fluid option)",
        );
    }
}
