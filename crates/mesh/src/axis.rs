//! One-dimensional stretched axes built from MFIX-style segments.
//!
//! [`Axis`] stores the faces as the truth and caches everything derived from them
//! (docs/model.md §4.1); it is built from faces or from consecutive [`Segment`]s.

use crate::segment::{total_cells, Segment};
use crate::MeshError;

/// A 1-D axis: faces are the truth; centres, widths and centre distances are cached.
#[derive(Clone, Debug, PartialEq)]
pub struct Axis {
    faces: Vec<f64>,
    centres: Vec<f64>,
    widths: Vec<f64>,
    face_spacing: Vec<f64>,
    /// the two end faces are one face ([`Axis::periodic`])
    periodic: bool,
}

impl Axis {
    /// Builds an axis from strictly increasing face coordinates (at least two).
    pub fn from_faces(faces: Vec<f64>) -> Result<Axis, MeshError> {
        if faces.len() < 2 {
            return Err(MeshError::Unsolvable(
                "an axis needs at least two faces".into(),
            ));
        }
        if let Some(k) = (1..faces.len()).find(|&k| faces[k] <= faces[k - 1] || faces[k].is_nan()) {
            return Err(MeshError::Unsolvable(format!(
                "faces are not strictly increasing at index {k}: {} then {}",
                faces[k - 1],
                faces[k]
            )));
        }
        if faces.iter().any(|f| !f.is_finite()) {
            return Err(MeshError::Unsolvable("non-finite face coordinate".into()));
        }
        let n = faces.len() - 1;
        let widths: Vec<f64> = (0..n).map(|i| faces[i + 1] - faces[i]).collect();
        let centres: Vec<f64> = (0..n).map(|i| 0.5 * (faces[i] + faces[i + 1])).collect();
        // Centre-to-centre distance across each face (docs/model.md §4.1, ODX_E); at the two
        // domain faces MFIX's ghost cell has the width of the adjacent fluid cell
        // (docs/model.md §3.1), so the distance is that cell's width.
        let mut face_spacing = Vec::with_capacity(n + 1);
        face_spacing.push(widths[0]);
        face_spacing.extend((1..n).map(|i| 0.5 * (widths[i - 1] + widths[i])));
        face_spacing.push(widths[n - 1]);
        Ok(Axis {
            faces,
            centres,
            widths,
            face_spacing,
            periodic: false,
        })
    }

    /// Builds an axis starting at `origin` from consecutive segments.
    pub fn from_segments(origin: f64, segments: &[Segment]) -> Result<Axis, MeshError> {
        if segments.is_empty() {
            return Err(MeshError::Unsolvable(
                "an axis needs at least one segment".into(),
            ));
        }
        // bounded before anything is allocated
        let cells = total_cells(segments)?;
        let mut faces = Vec::with_capacity(cells + 1);
        faces.push(origin);
        let mut start = origin;
        for seg in segments {
            let widths = seg.widths()?;
            let mut x = start;
            let n = widths.len();
            for (m, w) in widths.iter().enumerate() {
                // The segment's last face is placed at its exact end so that segment
                // boundaries (control points, MFIX `CPX`) do not drift with round-off.
                x = if m + 1 == n {
                    start + seg.length()
                } else {
                    x + w
                };
                faces.push(x);
            }
            start += seg.length();
        }
        Axis::from_faces(faces)
    }

    /// `n` equal cells on [x0, x1].
    pub fn uniform(x0: f64, x1: f64, n: usize) -> Result<Axis, MeshError> {
        Axis::from_segments(
            x0,
            &[Segment::Uniform {
                length: x1 - x0,
                cells: n,
            }],
        )
    }

    /// The same axis made periodic: its last face is its first (MFIX `CYCLIC_X`). The
    /// geometry is unchanged; what a periodic axis admits (the two-fluid solver: the x axis,
    /// one cell) is the solver's to check.
    pub fn periodic(mut self) -> Axis {
        self.periodic = true;
        self
    }

    /// Whether the axis is periodic ([`Axis::periodic`]).
    pub fn is_periodic(&self) -> bool {
        self.periodic
    }

    /// Number of cells.
    pub fn len(&self) -> usize {
        self.widths.len()
    }

    /// Always false: an axis has at least one cell.
    pub fn is_empty(&self) -> bool {
        self.widths.is_empty()
    }

    /// Face coordinates, `len() + 1` values, strictly increasing [m].
    pub fn faces(&self) -> &[f64] {
        &self.faces
    }

    /// Cell-centre coordinates [m].
    pub fn centres(&self) -> &[f64] {
        &self.centres
    }

    /// Cell widths Δx_i [m] (MFIX `DX`).
    pub fn widths(&self) -> &[f64] {
        &self.widths
    }

    /// Distance between the centres on either side of face k (k = 0..=len()) [m]:
    /// (Δx_{k−1} + Δx_k)/2 inside, the adjacent cell's width at the two ends (MFIX ghost
    /// cells have the width of their fluid neighbour, docs/model.md §3.1).
    pub fn face_spacing(&self) -> &[f64] {
        &self.face_spacing
    }

    /// Lower end of the axis [m].
    pub fn start(&self) -> f64 {
        self.faces[0]
    }

    /// Upper end of the axis [m].
    pub fn end(&self) -> f64 {
        self.faces[self.faces.len() - 1]
    }

    /// Total length [m].
    pub fn length(&self) -> f64 {
        self.end() - self.start()
    }

    /// Linear-interpolation weight of cell i at its upper face i+½ (MFIX AVG_X,
    /// docs/model.md §4.1): f = w φ_i + (1 − w) φ_{i+1} with w = Δx_{i+1}/(Δx_i + Δx_{i+1}).
    /// Valid for i + 1 < len().
    pub fn interpolation_weight(&self, i: usize) -> f64 {
        self.widths[i + 1] / (self.widths[i] + self.widths[i + 1])
    }

    /// The cell that contains `x`: faces[i] ≤ x < faces[i+1], and the last cell for
    /// x = end(). `None` outside the axis or for NaN.
    pub fn locate(&self, x: f64) -> Option<usize> {
        if !(x >= self.start() && x <= self.end()) {
            return None;
        }
        let k = self.faces.partition_point(|&f| f <= x);
        Some(k.saturating_sub(1).min(self.len() - 1))
    }

    /// Smallest and largest cell width [m].
    pub fn width_range(&self) -> (f64, f64) {
        self.widths
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |(lo, hi), &w| {
                (lo.min(w), hi.max(w))
            })
    }

    /// Largest ratio of adjacent widths, max over i of max(w_{i+1}/w_i, w_i/w_{i+1}) (1 for a
    /// single cell).
    pub fn max_adjacent_ratio(&self) -> f64 {
        self.widths
            .windows(2)
            .map(|p| (p[1] / p[0]).max(p[0] / p[1]))
            .fold(1.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_periodic_axis_keeps_its_geometry() {
        let axis = Axis::uniform(0.0, 1.0, 4).unwrap();
        assert!(!axis.is_periodic());
        let periodic = axis.clone().periodic();
        assert!(periodic.is_periodic());
        assert_eq!(periodic.faces(), axis.faces());
        assert_eq!(periodic.face_spacing(), axis.face_spacing());
        assert_ne!(periodic, axis);
    }
}
