//! The `sidewalls` option of a case: the two side walls of a channel of width W that a 2-D
//! slice leaves out, as a width-averaged friction (docs/model.md §8), and its validation.

use serde::{Deserialize, Serialize};

use crate::checker::{Checker, B};
use crate::schema::SolidsWall;

/// Two parallel side walls a distance `width` apart, both in the x–y plane of the slice
/// (docs/model.md §8). Their stress, averaged over the width, enters the solids momentum
/// (and, for the gas, the plane-Poiseuille drag of a no-slip wall) as a volumetric sink.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sidewalls {
    /// channel width W between the two walls [m], finite and > 0
    pub width: f64,
    /// the solids condition on both walls (any the floor accepts; the walls are at rest, so
    /// a wall velocity `u_w` must be 0)
    pub solids: SolidsWall,
    /// the gas condition on both walls
    pub gas: GasSidewall,
}

/// The gas condition on the side walls.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum GasSidewall {
    /// zero velocity on the walls: the width-averaged plane-Poiseuille drag −12 μ_g u/W²
    NoSlip,
    /// zero stress: nothing
    FreeSlip,
}

/// Checks `sidewalls.*`: the width finite and > 0, the solids condition as a floor's
/// (`check_solids_wall`), and the walls at rest.
pub(crate) fn check_sidewalls(
    c: &mut Checker,
    s: &Sidewalls,
    check_solids_wall: impl Fn(&mut Checker, &str, &SolidsWall),
) {
    c.range("sidewalls.width", s.width, B::Open(0.0), B::Inf);
    check_solids_wall(c, "sidewalls.solids", &s.solids);
    let u_w = s.solids.wall_velocity();
    if u_w != 0.0 {
        c.fail(
            "sidewalls.solids.u_w",
            runout_mesh::short(u_w),
            "0 (the side walls are at rest)",
        );
    }
}
