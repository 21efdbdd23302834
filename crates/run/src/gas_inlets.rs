//! The case's gas inlets on the grid (`gas_inlets`, issue 60 item 2): the velocity into the
//! domain on each wall face, the covered fraction of an inlet's rate where a face is covered
//! in part, summed over the inlets open at the time ([`runout_case::GasInlet::open_at`]); the
//! run hands them to the solver before each step when they change
//! ([`runout_solver::two_fluid::TwoFluid::set_gas_inflow_faces`]) and lands a step on each
//! inlet's opening and closing.

use runout_case::GasInlet;
use runout_mesh::{Grid, Sides};

use crate::case_solver::at_or_after;

/// An inlet with its velocity [m s⁻¹] and the covered fraction of each face along its side
/// (index, fraction).
type PlacedInlet = (GasInlet, f64, Vec<(usize, f64)>);

/// The inlets of a case on its grid, and the faces' velocities at the last step.
#[derive(Clone, Debug, Default)]
pub(crate) struct InletSchedule {
    /// each inlet placed on its side's faces
    inlets: Vec<PlacedInlet>,
    /// faces along the floor and top (nx), along the west and east sides (ny)
    faces: (usize, usize),
    /// the velocities handed over at the last call of [`InletSchedule::faces_if_changed`]
    last: Option<Sides<Vec<f64>>>,
}

/// The fraction of each cell of `faces` (an axis's face coordinates) that `(start, end)`
/// covers, where it is > 0.
fn covered(faces: &[f64], (start, end): (f64, f64)) -> Vec<(usize, f64)> {
    faces
        .windows(2)
        .enumerate()
        .filter_map(|(i, w)| {
            let overlap = end.min(w[1]) - start.max(w[0]);
            (overlap > 0.0).then(|| (i, overlap / (w[1] - w[0])))
        })
        .collect()
}

impl InletSchedule {
    /// `inlets` of gas of `density` [kg m⁻³] on `grid`.
    pub(crate) fn new(inlets: &[GasInlet], density: f64, grid: &Grid) -> Self {
        Self {
            inlets: inlets
                .iter()
                .map(|g| {
                    let axis = if g.side.is_horizontal() {
                        &grid.x
                    } else {
                        &grid.y
                    };
                    (*g, g.velocity(density), covered(axis.faces(), g.along))
                })
                .collect(),
            faces: (grid.nx(), grid.ny()),
            last: None,
        }
    }

    /// The velocity into the domain on each face of each side at time `t`; empty lists on
    /// the sides without an open inlet.
    pub(crate) fn faces_at(&self, t: f64) -> Sides<Vec<f64>> {
        let mut out: Sides<Vec<f64>> = Sides::all(Vec::new());
        for (inlet, velocity, cover) in self.inlets.iter().filter(|g| g.0.open_at(t)) {
            let n = if inlet.side.is_horizontal() {
                self.faces.0
            } else {
                self.faces.1
            };
            let side = out.get_mut(inlet.side);
            if side.is_empty() {
                *side = vec![0.0; n];
            }
            for &(i, fraction) in cover {
                side[i] += velocity * fraction;
            }
        }
        out
    }

    /// The velocities at `t` when they differ from the last call's, else `None`.
    pub(crate) fn faces_if_changed(&mut self, t: f64) -> Option<Sides<Vec<f64>>> {
        if self.inlets.is_empty() {
            return None;
        }
        let now = self.faces_at(t);
        if self.last.as_ref() == Some(&now) {
            return None;
        }
        self.last = Some(now.clone());
        Some(now)
    }

    /// The earliest opening or closing not yet reached at `time` [s].
    pub(crate) fn next_change(&self, time: f64) -> Option<f64> {
        self.inlets
            .iter()
            .flat_map(|(g, ..)| g.events())
            .filter(|&t| !at_or_after(time, t))
            .min_by(f64::total_cmp)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_case::InletRate;
    use runout_mesh::{AxisSpec, Segment, Side};

    fn grid() -> Grid {
        let axis = |length, cells| AxisSpec {
            origin: 0.0,
            segments: vec![Segment::Uniform { length, cells }],
        };
        Grid::from_specs(&axis(1.0, 10), &axis(0.5, 5)).unwrap()
    }

    /// A segment from 0.25 to 0.6 m on the floor covers half of face 2, faces 3–5 whole:
    /// the gas let in is the rate times the segment's length.
    #[test]
    fn a_face_covered_in_part_lets_in_its_share() {
        let inlet = GasInlet {
            side: Side::South,
            along: (0.25, 0.6),
            rate: InletRate::MassFlux(0.24),
            from: 0.1,
            until: Some(0.3),
        };
        let mut s = InletSchedule::new(&[inlet], 1.2, &grid());
        assert!(s.faces_at(0.0).south.is_empty());
        let on = s.faces_at(0.2);
        let expected = [0.0, 0.0, 0.1, 0.2, 0.2, 0.2, 0.0, 0.0, 0.0, 0.0];
        assert_eq!(on.south.len(), 10);
        for (v, e) in on.south.iter().zip(expected) {
            assert!((v - e).abs() < 1e-12, "{:?}", on.south);
        }
        let total: f64 = on.south.iter().map(|v| v * 0.1).sum();
        assert!((total - 0.2 * 0.35).abs() < 1e-12);
        assert!(on.west.is_empty() && on.north.is_empty());
        assert!(s.faces_at(0.3).south.is_empty());
        // the run is told once per change, and lands steps on the opening and the closing
        assert!(s.faces_if_changed(0.2).is_some());
        assert!(s.faces_if_changed(0.25).is_none());
        assert_eq!(s.next_change(0.0), Some(0.1));
        assert_eq!(s.next_change(0.1), Some(0.3));
        assert_eq!(s.next_change(0.3), None);
    }
}
