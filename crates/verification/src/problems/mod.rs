//! The verification problems: each sets up a solver, runs it and returns a structured
//! result (errors against the reference, observed orders, outer iterations, wall time). The
//! checks of [`crate::checks`] run them at a fast size (the tests of
//! `crates/verification/tests/`) and a full size (`cargo xtask verify`).
//!
//! Single-phase core (issue 6):
//!
//! - [`cavity`]: lid-driven cavity against the centreline velocities of Ghia, Ghia & Shin
//!   (1982) ([`GHIA_RE100`], [`GHIA_RE1000`]); [`BOTELLA_PEYRET_RE1000`] and
//!   [`BOTELLA_PEYRET_RE1000_EXTREMA`] are the spectral reference of Botella & Peyret (1998)
//!   at the same sample points, for judging Ghia's own accuracy at Re = 1000.
//! - [`poiseuille_order`]: plane Poiseuille flow between partial-slip walls against its
//!   closed form ([`poiseuille_exact`]), observed order on uniform and stretched grids.
//! - [`taylor_green_space_order`], [`taylor_green_time_order`]: the decaying Taylor–Green
//!   vortex in a free-slip box as a manufactured unsteady solution.
//! - [`mass_conservation`]: the net continuity imbalance after every converged step,
//!   relative to the flow through the domain ([`section_flow`]).
//!
//! Two-fluid model (issue 7):
//!
//! - [`chute_column`]: steady chute flow on a periodic column against the 1-D reference
//!   ([`crate::chute1d`]);
//! - [`haff_energy`]: the assembled granular-energy equation against Haff's law;
//! - [`cooling_box`]: homogeneous cooling through the whole two-fluid step;
//! - [`settling_column`]: a suspension settling into a packed bed that carries its weight;
//! - [`fluidized_bed`]: a bed hanging on the gas pressure drop;
//! - [`gas_inlet`]: the same through the driver, the floor's inlet opened and shut by the
//!   case's schedule (issue 60);
//! - [`s_jj_phi`]: the paper's slide with a Johnson–Jackson floor through the driver;
//! - [`relaxation`]: the paper's slide with two under-relaxations, the same flow (issue 58).
//!
//! Where a flow stops (issue 43):
//!
//! - [`incline`]: the μ(I) law on a rough incline, flowing against the Bagnold profile and
//!   at rest below μ_s against the creep of its regularisation;
//! - [`coulomb_floor`]: a block sliding on a Coulomb floor and a layer between Coulomb side
//!   walls against the sliding-block law (issue 61).

use std::f64::consts::PI;
use std::time::Instant;

use runout_linsolve::LinearSolverKind;
use runout_mesh::{Axis, Grid, MeshError, Segment, Sides};
use runout_walls::RobinFace;

use runout_solver::{Fluid, Scheme, Settings, SideBc, SinglePhase, SolverError, SteadyReport};

pub use crate::references::{
    ghia, CentrelineExtrema, CentrelineReference, BOTELLA_PEYRET_RE1000,
    BOTELLA_PEYRET_RE1000_EXTREMA, GHIA_RE100, GHIA_RE1000, GHIA_X, GHIA_Y,
};

/// Largest allowed net continuity imbalance of a converged step relative to the flow
/// through the domain (issue 6).
pub const MASS_TOLERANCE: f64 = 1e-10;

/// Errors of a verification run.
#[derive(Debug, thiserror::Error)]
pub enum VerifyError {
    /// The solver failed.
    #[error(transparent)]
    Solver(#[from] SolverError),
    /// The grid could not be built.
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// A time step did not converge.
    #[error("step {step} of {steps} (n = {cells}) did not converge: residual {residual:e}")]
    StepNotConverged {
        /// the step (0-based)
        step: usize,
        /// steps of the run
        steps: usize,
        /// cells per side
        cells: usize,
        /// the residual sum at the end of the step
        residual: f64,
    },
    /// A steady run did not converge.
    #[error("{problem}: no convergence after {iterations} outer iterations")]
    SteadyNotConverged {
        /// which problem
        problem: &'static str,
        /// outer iterations done
        iterations: usize,
    },
    /// The requested study is not defined.
    #[error("{0}")]
    Setup(String),
}

pub mod bed_path;
pub(crate) mod case_copy;
mod channel;
pub mod chute_column;
pub mod cooling_box;
pub mod coulomb_floor;
pub mod defluidisation;
pub mod fluidized_bed;
pub mod gas_inlet;
pub mod haff_energy;
pub mod ideal_gas;
pub mod incline;
mod lid_driven;
pub mod paper_material;
pub mod relaxation;
pub mod release;
pub mod s_jj_phi;
pub mod settling_column;
pub(crate) mod stepping;
mod vortex;

pub use channel::*;
pub use lid_driven::*;
pub use vortex::*;

// ---------------------------------------------------------------------------------------
// Shared measures
// ---------------------------------------------------------------------------------------

/// The flow through the domain [kg s⁻¹ per m depth]: the largest one-way mass flow across
/// any grid section (a column of x-faces or a row of y-faces), max(Σ F⁺, Σ |F⁻|). For a
/// channel it is the flow rate; for a closed box, the circulating flow.
pub fn section_flow(s: &SinglePhase, density: f64) -> f64 {
    let g = s.grid();
    let (nx, ny) = (g.nx(), g.ny());
    let (dx, dy) = (g.x.widths(), g.y.widths());
    let mut best: f64 = 0.0;
    for i in 0..=nx {
        let (mut pos, mut neg) = (0.0, 0.0);
        for j in 0..ny {
            let f = density * s.u[i + (nx + 1) * j] * dy[j];
            if f > 0.0 {
                pos += f;
            } else {
                neg -= f;
            }
        }
        best = best.max(pos).max(neg);
    }
    for j in 0..=ny {
        let (mut pos, mut neg) = (0.0, 0.0);
        for i in 0..nx {
            let f = density * s.v[i + nx * j] * dx[i];
            if f > 0.0 {
                pos += f;
            } else {
                neg -= f;
            }
        }
        best = best.max(pos).max(neg);
    }
    best
}

/// Net continuity imbalance (Σ over cells of |imbalance|, [`SinglePhase::mass_imbalance`])
/// relative to [`section_flow`].
pub fn mass_ratio(s: &SinglePhase, density: f64) -> f64 {
    s.mass_imbalance() / section_flow(s, density).max(f64::MIN_POSITIVE)
}

/// Observed orders log(e_k/e_{k+1}) / log(r_k): the post-processing library's one definition.
pub use runout_post::convergence::observed_orders;

/// One level of a convergence study.
#[derive(Clone, Debug, PartialEq)]
pub struct Level {
    /// cells across the refined direction (per side for square grids)
    pub cells: usize,
    /// time steps (0 for steady problems)
    pub steps: usize,
    /// outer iterations over all runs of the level
    pub outer_iterations: usize,
    /// wall time over all runs of the level [s]
    pub wall_time: f64,
    /// largest net continuity imbalance of a converged step (or the steady state) relative
    /// to the flow through the domain
    pub mass_ratio: f64,
}

/// A convergence study: levels, the measured errors and the observed orders.
#[derive(Clone, Debug, PartialEq)]
pub struct OrderStudy {
    /// what was measured
    pub label: String,
    /// the levels, coarse to fine (or large Δt to small)
    pub levels: Vec<Level>,
    /// errors: against the exact solution, one per level; for a self-convergence study the
    /// differences between consecutive levels, one per pair
    pub errors: Vec<f64>,
    /// observed orders between consecutive errors
    pub orders: Vec<f64>,
}

impl OrderStudy {
    /// Largest mass ratio over the levels.
    pub fn worst_mass_ratio(&self) -> f64 {
        self.levels.iter().map(|l| l.mass_ratio).fold(0.0, f64::max)
    }

    /// Smallest observed order.
    pub fn min_order(&self) -> f64 {
        self.orders.iter().copied().fold(f64::INFINITY, f64::min)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orders_of_exact_power_law() {
        let e = [1.0, 0.25, 0.0625];
        let p = observed_orders(&e, &[2.0, 2.0]);
        assert!(p.iter().all(|o| (o - 2.0).abs() < 1e-12));
    }
}
