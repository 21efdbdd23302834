//! Diagnostics of the two-fluid solver: where the wall time of the outer iteration goes
//! ([`Profile`], [`LinearIterations`]) and where the residuals of the last outer iteration
//! (docs/model.md §4.11) were largest ([`TwoFluid::residual_locations`]), for the diagnosis
//! of a step that fails. Nothing here changes the iteration.

use std::time::Instant;

use runout_mesh::{Side, Sides};

use super::TwoFluid;

/// How often each optional piece of the outer iteration was evaluated since the solver was
/// built: a piece the scene ([`super::Scene`]) leaves out stays at zero.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Counters {
    /// per-cell closure evaluations (cells with solids, summed over phases and iterations)
    pub cell_closures: u64,
    /// per-face wall closures of the state-dependent walls (JJ, revisited JJ, Jenkins) on
    /// each side, summed over phases and iterations
    pub wall_closure_faces: Sides<u64>,
    /// cells whose Schaeffer plastic pressure P* was recomputed after the εs correction
    pub plastic_pressure_cells: u64,
}

impl Counters {
    /// Per-face wall closures on every side together.
    pub fn wall_closure_faces_total(&self) -> u64 {
        Side::ALL
            .iter()
            .map(|&s| *self.wall_closure_faces.get(s))
            .sum()
    }
}

/// Wall time spent in each part of the outer iteration since the solver was built \[s\]
/// (issue 9: where the time goes). Timers are `Instant`s around whole loops, a few tens of
/// nanoseconds per call.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Profile {
    /// closures per cell (KT, friction, drag), strain rates, wall face velocities
    pub closures: f64,
    /// state-dependent wall closures (JJ, revisited JJ, Jenkins)
    pub walls: f64,
    /// explicit stress sources (once per step)
    pub stress: f64,
    /// momentum assembly of every phase and the partial elimination
    pub momentum_assembly: f64,
    /// momentum linear solves
    pub momentum_solve: f64,
    /// ε-correction assembly and update
    pub eps_assembly: f64,
    /// ε-correction linear solves
    pub eps_solve: f64,
    /// gas pressure-correction assembly and update
    pub pressure_assembly: f64,
    /// gas pressure-correction linear solves
    pub pressure_solve: f64,
    /// granular-energy assembly
    pub theta_assembly: f64,
    /// granular-energy linear solves
    pub theta_solve: f64,
    /// linear-solver iterations of each equation's solves
    pub iterations: LinearIterations,
}

/// Linear-solver iterations summed over every solve since the solver was built, per
/// equation (issue 22: where the cost per cell grows with the grid).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LinearIterations {
    /// momentum (every phase, u and v)
    pub momentum: u64,
    /// solids volume-fraction corrections
    pub eps: u64,
    /// gas pressure corrections
    pub pressure: u64,
    /// granular energy
    pub theta: u64,
}

impl LinearIterations {
    /// The counts by equation name.
    pub fn parts(&self) -> [(&'static str, u64); 4] {
        [
            ("momentum", self.momentum),
            ("eps", self.eps),
            ("pressure", self.pressure),
            ("theta", self.theta),
        ]
    }
}

impl Profile {
    /// The parts by name, in the order of the outer iteration.
    pub fn parts(&self) -> [(&'static str, f64); 11] {
        [
            ("closures", self.closures),
            ("walls", self.walls),
            ("stress", self.stress),
            ("momentum_assembly", self.momentum_assembly),
            ("momentum_solve", self.momentum_solve),
            ("eps_assembly", self.eps_assembly),
            ("eps_solve", self.eps_solve),
            ("pressure_assembly", self.pressure_assembly),
            ("pressure_solve", self.pressure_solve),
            ("theta_assembly", self.theta_assembly),
            ("theta_solve", self.theta_solve),
        ]
    }

    /// Sum of all parts \[s\].
    pub fn total(&self) -> f64 {
        self.closures
            + self.walls
            + self.stress
            + self.momentum_assembly
            + self.momentum_solve
            + self.eps_assembly
            + self.eps_solve
            + self.pressure_assembly
            + self.pressure_solve
            + self.theta_assembly
            + self.theta_solve
    }
}

/// Seconds since `t`.
pub(super) fn since(t: Instant) -> f64 {
    t.elapsed().as_secs_f64()
}

/// What the solver records about itself: where the time went, how often each optional piece
/// ran, and where the residuals of the last outer iteration were largest.
#[derive(Clone, Debug, Default)]
pub(super) struct Diagnostics {
    /// where the time went
    pub(super) profile: Profile,
    /// how often each optional piece ran
    pub(super) counters: Counters,
    /// where the residuals of the last outer iteration were largest
    pub(super) worst: Worst,
}

/// Locations of the largest residuals of the last outer iteration (for diagnoses).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Worst {
    /// |residual|, phase (0 gas, m solids m), component (0 u, 1 v), node i, j
    pub momentum: (f64, usize, usize, usize, usize),
    /// |residual|, cell
    pub theta: (f64, usize),
}

impl TwoFluid {
    /// Where the residuals of the last outer iteration were largest: momentum (phase,
    /// component, node), gas and solids continuity (cell) and granular energy (cell), with
    /// grid indices and coordinates, for the diagnosis of a step that fails.
    pub fn residual_locations(&self) -> String {
        let g = &self.model.grid;
        let nx = g.nx();
        let cell = |k: usize| {
            let (i, j) = (k % nx, k / nx);
            let (x, y) = g.cell_centre(i, j);
            format!("cell ({i}, {j}) at x = {x:.4} m, y = {y:.4} m")
        };
        let largest = |v: &[f64]| {
            v.iter().enumerate().fold(
                (0.0_f64, 0),
                |m, (k, r)| if r.abs() > m.0 { (r.abs(), k) } else { m },
            )
        };
        let mut out = Vec::new();
        let (r, p, dir, i, j) = self.diagnostics.worst.momentum;
        if r > 0.0 {
            let phase = if p == 0 {
                "gas".to_string()
            } else {
                format!("solids {p}")
            };
            let (comp, (x, y)) = if dir == 0 {
                ("u", g.u_face_position(i, j))
            } else {
                ("v", g.v_face_position(i, j))
            };
            out.push(format!(
                "momentum: largest residual {r:.3e} in {phase} {comp} at node ({i}, {j}), x = {x:.4} m, y = {y:.4} m"
            ));
        }
        let (r, k) = largest(&self.workspace.imbalance);
        if r > 0.0 {
            out.push(format!(
                "gas continuity: largest imbalance {r:.3e} kg/s per m in {}",
                cell(k)
            ));
        }
        for (m, s) in self.workspace.solids.iter().enumerate() {
            let (r, k) = largest(&s.imbalance);
            if r > 0.0 {
                out.push(format!(
                    "solids {} continuity: largest imbalance {r:.3e} kg/s per m in {}",
                    m + 1,
                    cell(k)
                ));
            }
        }
        let (r, k) = self.diagnostics.worst.theta;
        if r > 0.0 {
            out.push(format!(
                "granular energy: largest residual {r:.3e} in {}",
                cell(k)
            ));
        }
        out.join("; ")
    }
}
