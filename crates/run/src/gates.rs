//! The case's gates on the grid (`gates`, issue 57 item 2): each stands on the interior u
//! face nearest to its x and closes the rows whose centres it covers at the time
//! ([`runout_case::Gate::blocks`]); the run hands the closed faces to the solver before each
//! step ([`runout_solver::two_fluid::TwoFluid::set_gate_faces`]) and lands a step on each
//! gate's opening time.

use runout_case::Gate;
use runout_mesh::Grid;

use crate::case_solver::at_or_after;

/// The gates of a case on its grid, and the faces they closed at the last step.
#[derive(Clone, Debug, Default)]
pub(crate) struct GateSchedule {
    /// each gate with the index of its u face
    gates: Vec<(Gate, usize)>,
    /// the rows' centres [m]
    rows: Vec<f64>,
    /// u faces per row, nx + 1
    faces_per_row: usize,
    /// the faces closed at the last call of [`GateSchedule::faces_if_changed`]
    last: Option<Vec<bool>>,
}

impl GateSchedule {
    /// `gates` on `grid`.
    pub(crate) fn new(gates: &[Gate], grid: &Grid) -> Self {
        let faces = grid.x.faces();
        let nearest = |x: f64| {
            (1..grid.nx())
                .min_by(|&a, &b| (faces[a] - x).abs().total_cmp(&(faces[b] - x).abs()))
                .unwrap_or(1)
        };
        Self {
            gates: gates.iter().map(|g| (*g, nearest(g.x))).collect(),
            rows: grid.y.centres().to_vec(),
            faces_per_row: grid.nx() + 1,
            last: None,
        }
    }

    /// The u faces closed at time `t`, (nx + 1) × ny flags; empty without gates.
    pub(crate) fn faces_at(&self, t: f64) -> Vec<bool> {
        if self.gates.is_empty() {
            return Vec::new();
        }
        let mut closed = vec![false; self.faces_per_row * self.rows.len()];
        for (gate, i) in &self.gates {
            for (j, &y) in self.rows.iter().enumerate() {
                if gate.blocks(y, t) {
                    closed[i + self.faces_per_row * j] = true;
                }
            }
        }
        closed
    }

    /// The faces closed at `t` when they differ from the last call's, else `None`.
    pub(crate) fn faces_if_changed(&mut self, t: f64) -> Option<Vec<bool>> {
        let now = self.faces_at(t);
        if self.last.as_ref() == Some(&now) {
            return None;
        }
        self.last = Some(now.clone());
        Some(now)
    }

    /// The earliest opening time not yet reached at `time` [s].
    pub(crate) fn next_opening(&self, time: f64) -> Option<f64> {
        self.gates
            .iter()
            .map(|(g, _)| g.opens_at())
            .filter(|&t| !at_or_after(time, t))
            .min_by(f64::total_cmp)
    }
}
