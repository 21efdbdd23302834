//! The wall closures of one solids phase between outer iterations (docs/model.md §3.2,
//! §3.5–3.8): the per-face closures of the state-dependent walls ([`super::walls`]), their
//! cycle watch, the tangential velocity on the wall faces, and the floor probe.

use runout_mesh::Sides;

use super::dilute::ClosureCycle;
use crate::momentum::WallFaces;

/// The wall closure caches of one solids phase (module doc).
#[derive(Clone, Debug)]
pub(crate) struct PhaseWallClosures {
    /// tangential velocity on the wall faces of the south/north rows (per column) and the
    /// west/east columns (per row), from the wall closures (docs/model.md §3.2): what MFIX's
    /// ghost cells put into the strain rates of the wall cells (§4.4)
    pub wall_face_velocity: Sides<Vec<f64>>,
    /// per-node momentum closures of the state-dependent walls
    pub wall_velocity: WallFaces,
    /// per node of each side, the cycle watch of its momentum closure (for
    /// [`super::TwoFluidSettings::relax_wall_closures_oscillating_only`]; empty until used)
    pub wall_velocity_cycle: Sides<Vec<ClosureCycle>>,
    /// per-cell θ closures of the state-dependent walls
    pub wall_theta: WallFaces,
    /// h_w^u of the last floor evaluation per u-node (the wall probe of paper Fig. 9)
    pub floor_h_u: Vec<f64>,
    /// the normal load N_w a Coulomb floor read at its last evaluation per u-node
    /// (docs/model.md §3.11) [Pa]; 0 elsewhere. Recomputed every outer iteration (not in a
    /// checkpoint)
    pub floor_normal_load: Vec<f64>,
}

impl PhaseWallClosures {
    /// No per-face closures yet, zero wall face velocities, on an nx × ny grid.
    pub fn new((nx, ny): (usize, usize)) -> Self {
        PhaseWallClosures {
            wall_face_velocity: Sides {
                west: vec![0.0; ny],
                east: vec![0.0; ny],
                south: vec![0.0; nx],
                north: vec![0.0; nx],
            },
            wall_velocity: WallFaces::default(),
            wall_velocity_cycle: Sides::all(Vec::new()),
            wall_theta: WallFaces::default(),
            floor_h_u: vec![0.0; nx + 1],
            floor_normal_load: vec![0.0; nx + 1],
        }
    }
}
