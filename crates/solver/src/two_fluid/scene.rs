//! The scene: what a two-fluid solver built from a case computes, derived once when the
//! solver is built ([`Scene::of`]) from its phases, walls and settings. The outer iteration
//! runs the stages the scene lists and nothing else: a stage or term that is not in the
//! scene is not evaluated (its counters in [`super::Counters`] stay at zero), and
//! `runout check --explain` prints the scene with the case's cost.
//!
//! What the scene decides (docs/model.md §4.9 for the stages):
//! - per-cell closures of a phase only where it has solids (εs > 0); none at all without
//!   solids phases (a single-phase case builds no two-fluid solver);
//! - per-face wall closures only on the sides whose solids condition depends on the
//!   near-wall state (Johnson–Jackson, its Li–Benyahia revision, Jenkins: §3.5–3.8); no-slip,
//!   free-slip and user partial slip are fixed Robin faces set once (§3.2–3.3);
//! - Schaeffer's plastic pressure P* (its update after the εs correction and its gradient
//!   in the solids momentum, §2.4.1, §4.4) only where the friction model has one, and θ
//!   pinned only where the model pins it (§1.3);
//! - the side-wall terms only for a quasi-2-D channel (§8).

use std::fmt;

use runout_mesh::{Grid, Side, Sides};

use super::{SolidsSpec, TwoFluidSettings};

/// How one side's solids wall closure is computed.
#[derive(Clone, Debug, PartialEq)]
pub enum WallClosure {
    /// an outlet: no wall closure
    Outlet,
    /// a fixed Robin face set when the solver is built (no-slip, free-slip, partial slip)
    Fixed(String),
    /// per face, from the near-wall state, at every outer iteration
    PerFace(String),
}

/// What one solids phase computes.
#[derive(Clone, Debug, PartialEq)]
pub struct PhaseScene {
    /// the closure models of its cells (radial distribution, drag, friction)
    pub closures: String,
    /// Schaeffer's plastic pressure P* is updated and enters the solids momentum
    pub plastic_pressure: bool,
    /// θ is pinned to θ_small where εg < this εg* (a fixed row of the θ equation)
    pub theta_pinned_below: Option<f64>,
    /// the solids wall closure of each side
    pub walls: Sides<WallClosure>,
}

/// What a two-fluid solver computes (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// cells (nx, ny)
    pub cells: (usize, usize),
    /// the solids phases
    pub phases: Vec<PhaseScene>,
    /// the convection scheme of momentum and θ
    pub scheme: String,
    /// the side-wall terms of a quasi-2-D channel, if any (width [m])
    pub sidewalls: Option<f64>,
    /// one periodic column (MFIX CYCLIC_X on one cell)
    pub periodic_x: bool,
    /// each converged step ends with exact discrete solids continuity
    pub exact_solids_continuity: bool,
}

/// The closure of one side of one phase.
fn side_closure(spec: &SolidsSpec, side: Side) -> WallClosure {
    match spec.wall(side) {
        None => WallClosure::Outlet,
        Some(model) if model.fixed_faces().is_some() => WallClosure::Fixed(model.describe()),
        Some(model) => WallClosure::PerFace(model.describe()),
    }
}

impl PhaseScene {
    /// What the phase of `spec` computes.
    pub fn of(spec: &SolidsSpec) -> PhaseScene {
        let p = &spec.params;
        PhaseScene {
            closures: format!(
                "kinetic theory, {:?} g₀, {:?} drag, {} friction",
                p.radial,
                p.drag,
                p.friction_model.name()
            ),
            plastic_pressure: p.friction_model.has_plastic_pressure(),
            theta_pinned_below: p.friction_model.pins_theta_below(&p.friction),
            walls: Sides::from_fn(|side| side_closure(spec, side)),
        }
    }
}

impl Scene {
    /// The scene of a solver with these phases and settings on `grid`.
    pub fn of(
        grid: &Grid,
        specs: &[SolidsSpec],
        settings: &TwoFluidSettings,
        sidewall_width: Option<f64>,
    ) -> Scene {
        Scene {
            cells: (grid.nx(), grid.ny()),
            phases: specs.iter().map(PhaseScene::of).collect(),
            scheme: format!("{:?}", settings.scheme),
            sidewalls: sidewall_width,
            periodic_x: grid.periodic_x(),
            exact_solids_continuity: settings.exact_solids_continuity,
        }
    }

    /// Whether any side of any phase has per-face wall closures (the walls stage runs).
    pub fn has_per_face_walls(&self) -> bool {
        self.phases.iter().any(|p| {
            Side::ALL
                .iter()
                .any(|&s| matches!(p.walls.get(s), WallClosure::PerFace(_)))
        })
    }

    /// Unknowns per outer iteration: gas u, v, P'; per phase u, v, εs, θ.
    pub fn unknowns(&self) -> usize {
        let n = self.cells.0 * self.cells.1;
        n * (3 + 4 * self.phases.len())
    }
}

impl fmt::Display for Scene {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let m = self.phases.len();
        writeln!(
            f,
            "two-fluid model, gas + {m} solids phase(s), {} × {} cells, {} convection",
            self.cells.0, self.cells.1, self.scheme
        )?;
        writeln!(f, "each outer iteration (docs/model.md §4.9):")?;
        for (k, p) in self.phases.iter().enumerate() {
            writeln!(
                f,
                "  1. closures of phase {}: {} (cells with solids only)",
                k + 1,
                p.closures
            )?;
        }
        for (k, p) in self.phases.iter().enumerate() {
            for side in Side::ALL {
                let how = match p.walls.get(side) {
                    WallClosure::Outlet => "outlet, no wall closure".to_string(),
                    WallClosure::Fixed(name) => {
                        format!("{name}, fixed faces (no per-face closure)")
                    }
                    WallClosure::PerFace(name) => format!("{name}, per face every iteration"),
                };
                writeln!(f, "     walls of phase {} {side:?}: {how}", k + 1)?;
            }
        }
        match self.sidewalls {
            Some(w) => writeln!(
                f,
                "     side-wall terms: channel width {w} m (docs/model.md §8)"
            )?,
            None => writeln!(f, "     side-wall terms: none (plane flow)")?,
        }
        let star = self.phases.iter().any(|p| p.plastic_pressure);
        writeln!(f, "  2. momentum: gas u, v and {m} solids u, v; drag by partial elimination of {} phases{}", m + 1,
            if star { "; Schaeffer's −∇P* in the solids momentum" } else { "; no P* term" })?;
        writeln!(
            f,
            "  3. solids volume-fraction correction of {m} phase(s){}",
            if star {
                ", then P* from the corrected εs"
            } else {
                ""
            }
        )?;
        writeln!(f, "  4. gas pressure correction")?;
        let pinned = self
            .phases
            .iter()
            .filter_map(|p| p.theta_pinned_below)
            .next();
        match pinned {
            Some(e) => writeln!(
                f,
                "  5. granular energy of {m} phase(s), θ pinned where εg < {e}"
            )?,
            None => writeln!(f, "  5. granular energy of {m} phase(s)")?,
        }
        writeln!(f, "  6. residuals")?;
        writeln!(
            f,
            "each step: explicit stress terms (docs/model.md §4.4){}{}",
            if self.exact_solids_continuity {
                "; exact solids continuity at the end"
            } else {
                ""
            },
            if self.periodic_x {
                "; periodic in x (one column)"
            } else {
                ""
            }
        )
    }
}
