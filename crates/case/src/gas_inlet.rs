//! Gas let in through walls (issue 60 item 2): a segment of one wall side through which gas
//! enters the domain at a superficial velocity or a mass flux, from a time until a time — a
//! porous floor or distributor plate, a vent — as MFIX's mass inflow with BC_EP_G = 1 (the
//! gas crosses the face as pure gas; the solids still see the wall and its condition), with
//! its validation.
//!
//! The segment runs along its side in the domain's coordinates: x for the floor (south) and
//! the top (north), y for the west and east sides. A face the segment covers in part lets in
//! the covered fraction of the rate, so the gas entering is the rate times the segment's
//! length whatever the grid.

use serde::{Deserialize, Serialize};

use runout_mesh::Side;

use crate::checker::{Checker, B};
use crate::schema::{Boundary, Case};

/// One segment of a wall side that lets gas in (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GasInlet {
    /// the wall side it is on
    pub side: Side,
    /// where along the side (start, end) [m]: x on the floor and the top, y on the west and
    /// east sides, inside the side's extent, start < end
    pub along: (f64, f64),
    /// how much gas enters
    pub rate: InletRate,
    /// when it opens [s], ≥ 0 (default 0: from the start)
    #[serde(default)]
    pub from: f64,
    /// when it closes [s], after `from` (default: never)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub until: Option<f64>,
}

/// How much gas an inlet lets in.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum InletRate {
    /// superficial velocity normal to the wall into the domain [m s⁻¹], > 0
    Velocity(f64),
    /// mass flux into the domain [kg m⁻² s⁻¹], > 0: the velocity is it over the gas's
    /// density
    MassFlux(f64),
}

impl InletRate {
    /// The same kind of rate, `factor` times as large.
    pub fn scaled(self, factor: f64) -> Self {
        match self {
            InletRate::Velocity(v) => InletRate::Velocity(factor * v),
            InletRate::MassFlux(g) => InletRate::MassFlux(factor * g),
        }
    }
}

impl GasInlet {
    /// The superficial velocity into the domain [m s⁻¹] for gas of `density` [kg m⁻³].
    pub fn velocity(&self, density: f64) -> f64 {
        match self.rate {
            InletRate::Velocity(v) => v,
            InletRate::MassFlux(g) => g / density,
        }
    }

    /// Whether it lets gas in at time `t` [s]: from `from` until `until`.
    pub fn open_at(&self, t: f64) -> bool {
        t >= self.from && self.until.is_none_or(|end| t < end)
    }

    /// The times it opens and closes [s].
    pub fn events(&self) -> impl Iterator<Item = f64> {
        std::iter::once(self.from).chain(self.until)
    }

    /// Whether it and `other` overlap along the same side at some time.
    fn overlaps(&self, other: &GasInlet) -> bool {
        let apart_in_space = self.along.1 <= other.along.0 || other.along.1 <= self.along.0;
        let ends = |g: &GasInlet| g.until.unwrap_or(f64::INFINITY);
        let apart_in_time = ends(self) <= other.from || ends(other) <= self.from;
        self.side == other.side && !apart_in_space && !apart_in_time
    }
}

/// Checks `gas_inlets` (module doc): each on a side whose gas and solids are a wall (not an
/// outlet, not periodic), within the side's extent with start < end, a finite rate > 0, from
/// ≥ 0 and until > from; no two on one side overlapping in place and time; a case with gas
/// and solids (the two-fluid solver's option).
pub(crate) fn check_gas_inlets(c: &mut Checker, case: &Case) {
    for (k, inlet) in case.gas_inlets.iter().enumerate() {
        let p = format!("gas_inlets[{k}]");
        if !matches!(case.boundaries.get(inlet.side), Boundary::Wall { .. }) {
            c.fail(
                format!("{p}.side"),
                format!("{}, which is not a wall", inlet.side.name()),
                "a side whose boundary is a Wall (gas let in through an outlet or a periodic side is refused)",
            );
        }
        let axis = if inlet.side.is_horizontal() {
            &case.domain.x
        } else {
            &case.domain.y
        };
        let (lo, hi) = (axis.origin, axis.end());
        let (start, end) = inlet.along;
        c.range(format!("{p}.along.0"), start, B::Closed(lo), B::Open(hi));
        c.range(format!("{p}.along.1"), end, B::Open(start), B::Closed(hi));
        match inlet.rate {
            InletRate::Velocity(v) => {
                c.range(format!("{p}.rate.Velocity"), v, B::Open(0.0), B::Inf)
            }
            InletRate::MassFlux(g) => {
                c.range(format!("{p}.rate.MassFlux"), g, B::Open(0.0), B::Inf)
            }
        }
        c.range(format!("{p}.from"), inlet.from, B::Closed(0.0), B::Inf);
        if let Some(until) = inlet.until {
            c.range(format!("{p}.until"), until, B::Open(inlet.from), B::Inf);
        }
        if let Some(other) = case.gas_inlets[..k].iter().position(|o| o.overlaps(inlet)) {
            c.fail(
                format!("{p}.along"),
                format!(
                    "overlaps gas_inlets[{other}] on the {} side while both are open",
                    inlet.side.name()
                ),
                "segments of one side apart in place or in time",
            );
        }
    }
    if !case.gas_inlets.is_empty() && (case.gas.is_none() || case.solids.is_empty()) {
        c.fail(
            "gas_inlets",
            "a gas inlet in a case without gas or without solids",
            "none (gas inlets are a two-fluid option: a case with gas and solids)",
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn inlet(along: (f64, f64), from: f64, until: Option<f64>) -> GasInlet {
        GasInlet {
            side: Side::South,
            along,
            rate: InletRate::Velocity(0.1),
            from,
            until,
        }
    }

    #[test]
    fn an_inlet_is_open_from_its_start_until_its_end() {
        let g = inlet((0.0, 1.0), 0.5, Some(2.0));
        assert!(!g.open_at(0.49) && g.open_at(0.5) && g.open_at(1.99) && !g.open_at(2.0));
        assert!(inlet((0.0, 1.0), 0.0, None).open_at(1e9));
        assert_eq!(g.events().collect::<Vec<_>>(), vec![0.5, 2.0]);
        let flux = GasInlet {
            rate: InletRate::MassFlux(0.6),
            ..g
        };
        assert!((flux.velocity(1.2) - 0.5).abs() < 1e-15);
    }

    #[test]
    fn inlets_overlap_only_in_place_and_time_on_one_side() {
        let a = inlet((0.0, 1.0), 0.0, Some(1.0));
        assert!(a.overlaps(&inlet((0.5, 2.0), 0.5, None)));
        // end to end, or one after the other, or on another side
        assert!(!a.overlaps(&inlet((1.0, 2.0), 0.0, None)));
        assert!(!a.overlaps(&inlet((0.0, 1.0), 1.0, None)));
        let west = GasInlet {
            side: Side::West,
            ..inlet((0.0, 1.0), 0.0, None)
        };
        assert!(!a.overlaps(&west));
    }
}
