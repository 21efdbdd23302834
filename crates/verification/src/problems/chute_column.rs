//! Issue 7's inclined-plane check: steady, fully developed flow down a slope with a
//! Johnson–Jackson floor, computed by the 2-D two-fluid solver on a periodic column (a
//! periodic x axis, [`runout_mesh::Axis::periodic`]) marched in time to a steady state,
//! against the 1-D steady boundary-value solve of the same equations and closures ([`crate::chute1d`]),
//! on the same y grid. Run by the `chute` check ([`crate::checks::chute`]): fast in
//! `crates/verification/tests/chute_column.rs`, full by `cargo xtask verify chute`
//! (docs/reports/chute.md).
//!
//! The reference is dry (ρ_g = 0, docs/studies/chute1d.md §1) and the two-fluid solver always carries
//! a gas, so the column's gas is made negligible rather than absent: ρ_g and μ_g are tiny
//! (defaults 1e-3 kg m⁻³ and 1e-8 Pa s). The check measures what that leaves: the largest
//! drag force on the solids relative to their weight along the slope, and the buoyancy
//! ρ_g/ρ_s, both reported in [`ChuteCheck`].
//!
//! The setup is the confined strip of docs/studies/chute1d.md §3: H = 8.7 mm, holdup 5 mm (mean
//! εs 0.575), 25°, the paper's material (d = 0.5 mm, ρs = 2000 kg m⁻³, e = 0.9, Princeton
//! friction φ = 35°, εs,max = 0.65, εs,min = 0.5), JJ floor φ' = 0.1, e_w = 0.7, δ_w = 11°,
//! free-slip lid with zero θ flux.

use std::time::Instant;

use runout_closures::{ClosureParams, Gas};
use runout_mesh::{Axis, Grid, Sides};
use runout_walls::{RobinFace, SolidsWallModel};

use runout_solver::two_fluid::{RelaxationBase, Sidewalls, SolidsSpec, TwoFluid, TwoFluidSettings};
use runout_solver::{Fluid, Scheme, SideBc};

use crate::chute1d::{
    self, ChuteParams, ChuteProfile, ChuteSidewalls, SolverSettings, WallTreatment,
};

/// What to run.
#[derive(Clone, Debug)]
pub struct ChuteCheckSetup {
    /// cells across the layer (uniform)
    pub cells: usize,
    /// layer height H between floor and lid \[m\]
    pub height: f64,
    /// holdup ∫ εs dy \[m\]
    pub holdup: f64,
    /// slope α \[deg\]
    pub slope_deg: f64,
    /// floor condition
    pub floor: SolidsWallModel,
    /// side walls a width apart (docs/model.md §8; the gas slips freely on them); none: a
    /// plane flow
    pub sidewalls: Option<ChuteSidewalls>,
    /// ρ_g of the negligible gas [kg m⁻³]
    pub gas_density: f64,
    /// μ_g of the negligible gas [Pa s]
    pub gas_viscosity: f64,
    /// simulated time allowed to reach the steady state \[s\]
    pub end_time: f64,
    /// steady when the largest relative rate of change of εs, u_s and θ (each relative to
    /// its largest magnitude) is below this [s⁻¹]
    pub steady_rate: f64,
    /// largest time step \[s\]
    pub dt_max: f64,
    /// print progress to stderr
    pub verbose: bool,
    /// the dry material and closures of both solvers (the 2-D column adds the negligible gas)
    pub closures: ClosureParams,
    /// the 2-D column's starting u_s and u_g \[m/s\]
    pub initial_velocity: f64,
    /// the starting εs of each cell (its holdup should be the setup's); none: εs = holdup/H
    /// in the whole strip
    pub initial_eps_s: Option<Vec<f64>>,
    /// the starting u_s of each row (the gas starts at `initial_velocity`); none: all
    /// `initial_velocity`
    pub initial_u_s: Option<Vec<f64>>,
    /// the 2-D column's starting θ \[m²/s²\]
    pub initial_theta: f64,
    /// the 2-D column's momentum under-relaxation (MFIX's UR_FAC; default 0.5, the
    /// solver's)
    pub relax_velocity: f64,
    /// what the solids rows' relaxation is proportional to (default: the friction model's)
    pub solids_relaxation_base: Option<RelaxationBase>,
    /// the 1-D reference's iteration controls and starting point
    pub reference_settings: SolverSettings,
}

impl Default for ChuteCheckSetup {
    /// The reference case of docs/studies/chute1d.md §3 on 80 cells.
    fn default() -> Self {
        Self {
            cells: 80,
            height: 0.0087,
            holdup: 0.005,
            slope_deg: 25.0,
            floor: SolidsWallModel::johnson_jackson(0.1, 0.7, 11.0, 0.0)
                .expect("valid JJ parameters"),
            sidewalls: None,
            gas_density: 1e-3,
            gas_viscosity: 1e-8,
            end_time: 20.0,
            steady_rate: 1e-4,
            dt_max: 2e-2,
            verbose: false,
            closures: dry_closures(),
            initial_velocity: 0.3,
            initial_eps_s: None,
            initial_u_s: None,
            initial_theta: 1e-3,
            relax_velocity: TwoFluidSettings::default().relax_velocity,
            solids_relaxation_base: TwoFluidSettings::default().solids_relaxation_base,
            reference_settings: SolverSettings::default(),
        }
    }
}

/// Width of the side walls of the check with side walls [m]: narrow enough for them to
/// carry a large share of the weight along the slope (docs/model.md §8).
pub const SIDEWALL_WIDTH: f64 = 0.02;

impl ChuteCheckSetup {
    /// This setup with side walls `width` apart that have the floor's solids condition
    /// (docs/model.md §8).
    pub fn with_floor_sidewalls(self, width: f64) -> Self {
        Self {
            sidewalls: Some(ChuteSidewalls {
                width,
                solids: self.floor,
            }),
            ..self
        }
    }
}

/// The comparison.
#[derive(Clone, Debug)]
pub struct ChuteCheck {
    /// the 1-D steady solution
    pub reference: ChuteProfile,
    /// the 2-D column at the end of its march (its cell centres are the reference's)
    pub column: SteadyColumn,
    /// max |εs − εs,ref| / max εs,ref
    pub eps_error: f64,
    /// max |u_s − u_s,ref| / max u_s,ref
    pub velocity_error: f64,
    /// max |θ − θ_ref| / max θ_ref
    pub theta_error: f64,
    /// max |θ − θ_ref| / θ_ref, pointwise (θ spans three decades)
    pub theta_pointwise_error: f64,
    /// ρ_g/ρ_s: the buoyancy left by the negligible gas
    pub buoyancy: f64,
}

/// Why the check could not run.
#[derive(Debug, thiserror::Error)]
pub enum ChuteCheckError {
    /// the 1-D reference failed
    #[error("1-D reference: {0}")]
    Reference(#[from] chute1d::Chute1dError),
    /// the 2-D solver could not be set up or failed
    #[error("2-D column: {0}")]
    Column(String),
}

fn max_abs(values: &[f64]) -> f64 {
    values.iter().fold(0.0, |m: f64, v| m.max(v.abs()))
}

fn relative_error(values: &[f64], reference: &[f64]) -> f64 {
    values
        .iter()
        .zip(reference)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
        / max_abs(reference)
}

/// |g| of the check [m s⁻²].
const GRAVITY: f64 = 9.81;

/// The paper's material, dry (the 1-D reference's closures).
pub fn dry_closures() -> ClosureParams {
    ClosureParams {
        gas: Gas {
            density: 0.0,
            ..Gas::default()
        },
        ..ClosureParams::default()
    }
}

/// The 1-D steady reference of a setup (`chute1d`), on its y grid.
pub fn reference(setup: &ChuteCheckSetup) -> Result<ChuteProfile, ChuteCheckError> {
    let axis = Axis::uniform(0.0, setup.height, setup.cells)
        .map_err(|e| ChuteCheckError::Column(e.to_string()))?;
    Ok(chute1d::solve(
        &ChuteParams {
            closures: setup.closures,
            slope_deg: setup.slope_deg,
            gravity: GRAVITY,
            holdup: setup.holdup,
            floor: setup.floor,
            grid: axis,
            wall_treatment: WallTreatment::FluidCell,
            sidewalls: setup.sidewalls,
        },
        &setup.reference_settings,
    )?)
}

/// The 2-D column marched to its steady state (or its end time).
#[derive(Clone, Debug)]
pub struct SteadyColumn {
    /// cell-centre heights \[m\]
    pub y: Vec<f64>,
    /// εs [-]
    pub eps_s: Vec<f64>,
    /// u_s at the cell centres' height (the row's u-node) [m/s]
    pub u_s: Vec<f64>,
    /// θ [m²/s²]
    pub theta: Vec<f64>,
    /// simulated time reached \[s\]
    pub time: f64,
    /// accepted steps
    pub steps: usize,
    /// steps retried with half the time step
    pub rejected: usize,
    /// the largest relative rate of change at the end [s⁻¹]
    pub final_rate: f64,
    /// whether `final_rate` fell below the setup's `steady_rate`
    pub steady: bool,
    /// relative change of the solids mass over the run
    pub mass_change: f64,
    /// largest |F_gs (u_g − u_s)| relative to εs ρs g sin α over the cells
    pub drag_to_weight: f64,
    /// wall time of the march \[s\]
    pub wall_time: f64,
}

/// The 2-D column of `setup` on its `cells` uniform cells under gravity `g` [m s⁻²], started
/// as the setup says, for a caller that marches it itself (a transient).
pub fn sliding_column(setup: &ChuteCheckSetup, g: f64) -> Result<TwoFluid, ChuteCheckError> {
    let axis = Axis::uniform(0.0, setup.height, setup.cells)
        .map_err(|e| ChuteCheckError::Column(e.to_string()))?;
    column(setup, axis, setup.closures, g)
}

/// Marches the 2-D column of `setup` to its steady state.
pub fn steady_column(setup: &ChuteCheckSetup) -> Result<SteadyColumn, ChuteCheckError> {
    let axis = Axis::uniform(0.0, setup.height, setup.cells)
        .map_err(|e| ChuteCheckError::Column(e.to_string()))?;
    let y = axis.centres().to_vec();
    let (dry, g) = (setup.closures, GRAVITY);
    let ny = setup.cells;
    let mut tf = column(setup, axis, dry, g)?;
    let rho_s = tf.solids_density(0);
    let alpha = setup.slope_deg.to_radians();
    let mass0 = tf.solids_mass(0);
    let start = Instant::now();
    let March {
        time,
        steps,
        rejected,
        rate,
    } = march(&mut tf, setup)?;
    let wall_time = start.elapsed().as_secs_f64();
    let u_s = u_rows(&tf);
    let s = tf.solids(0);
    let mut drag_to_weight: f64 = 0.0;
    for j in 0..ny {
        let weight = s.eps()[j] * rho_s * g * alpha.sin();
        if weight > 0.0 {
            drag_to_weight =
                drag_to_weight.max((tf.drag(0)[j] * (tf.u_g()[2 * j] - u_s[j])).abs() / weight);
        }
    }
    Ok(SteadyColumn {
        y,
        eps_s: s.eps().to_vec(),
        theta: s.theta.clone(),
        u_s,
        time,
        steps,
        rejected,
        final_rate: rate,
        steady: rate < setup.steady_rate,
        mass_change: tf.solids_mass(0) / mass0 - 1.0,
        drag_to_weight,
        wall_time,
    })
}

/// Runs the 1-D reference and the 2-D column and compares them.
pub fn run(setup: &ChuteCheckSetup) -> Result<ChuteCheck, ChuteCheckError> {
    let reference = reference(setup)?;
    let column = steady_column(setup)?;
    let theta_pointwise_error = column
        .theta
        .iter()
        .zip(&reference.theta)
        .map(|(a, b)| (a / b - 1.0).abs())
        .fold(0.0, f64::max);
    Ok(ChuteCheck {
        eps_error: relative_error(&column.eps_s, &reference.eps_s),
        velocity_error: relative_error(&column.u_s, &reference.u_s),
        theta_error: relative_error(&column.theta, &reference.theta),
        theta_pointwise_error,
        buoyancy: setup.gas_density / setup.closures.particles.density,
        column,
        reference,
    })
}

/// The 2-D column of the check on the 1-D reference's y grid `axis`: one cell across (its
/// width drops out), periodic in x, dry closures `dry` with the setup's gas, gravity `g`
/// along the slope; started at uniform εs = holdup/H, gas and solids sliding at the setup's
/// initial velocity and θ (defaults 0.3 m/s, 1e-3 m²/s²).
fn column(
    setup: &ChuteCheckSetup,
    axis: Axis,
    dry: ClosureParams,
    g: f64,
) -> Result<TwoFluid, ChuteCheckError> {
    // the 2-D column: one cell across (its width drops out), the same y grid
    let grid = Grid::new(
        Axis::uniform(0.0, setup.height, 1)
            .map_err(|e| ChuteCheckError::Column(e.to_string()))?
            .periodic(),
        axis,
    );
    let params = ClosureParams {
        gas: Gas {
            density: setup.gas_density,
            viscosity: setup.gas_viscosity,
        },
        ..dry
    };
    let free_slip = SideBc::Wall(RobinFace::ZERO_GRADIENT);
    let spec = SolidsSpec {
        eps_max: params.friction.eps_s_max,
        params,
        // x sides: free slip (periodic column); floor: the wall model; lid: MFIX's FSW
        walls: Sides {
            west: Some(SolidsWallModel::FreeSlip),
            east: Some(SolidsWallModel::FreeSlip),
            south: Some(setup.floor),
            north: Some(SolidsWallModel::FreeSlip),
        },
    };
    let gas_walls = Sides {
        west: free_slip,
        east: free_slip,
        south: SideBc::Wall(RobinFace::dirichlet(0.0)),
        north: free_slip,
    };
    let alpha = setup.slope_deg.to_radians();
    let gravity = (g * alpha.sin(), -g * alpha.cos());
    let settings = TwoFluidSettings {
        scheme: Scheme::Upwind,
        relax_velocity: setup.relax_velocity,
        solids_relaxation_base: setup.solids_relaxation_base,
        ..TwoFluidSettings::default()
    };
    let gas = Fluid {
        density: setup.gas_density,
        viscosity: setup.gas_viscosity,
    };
    let mut tf = TwoFluid::new(grid, gas, gas_walls, vec![spec], gravity, settings)
        .map_err(|e| ChuteCheckError::Column(e.to_string()))?;
    tf.set_sidewalls(setup.sidewalls.map(|w| Sidewalls {
        width: w.width,
        solids: w.solids,
        gas_no_slip: false,
    }));
    // start: the given εs or a uniform one, gas and solids sliding together
    let eps0 = setup.holdup / setup.height;
    let (u0, theta0) = (setup.initial_velocity, setup.initial_theta);
    let state = tf.state_mut();
    state.update_solids(0, |s| {
        match &setup.initial_eps_s {
            Some(profile) => s.eps.copy_from_slice(profile),
            None => s.eps.iter_mut().for_each(|e| *e = eps0),
        }
        s.theta.iter_mut().for_each(|t| *t = theta0);
        s.u.iter_mut().for_each(|u| *u = u0);
        if let Some(rows) = &setup.initial_u_s {
            // u-nodes row by row: nx + 1 per row
            let per_row = s.u.len() / rows.len();
            for (k, u) in s.u.iter_mut().enumerate() {
                *u = rows[k / per_row];
            }
        }
    });
    state.gas_mut().u.iter_mut().for_each(|u| *u = u0);
    Ok(tf)
}

/// How the march to the steady state ended.
struct March {
    /// simulated time [s]
    time: f64,
    /// accepted and rejected steps
    steps: usize,
    rejected: usize,
    /// the largest relative rate of change at the end [s⁻¹]
    rate: f64,
}

/// u of each row of the column (node 0 of the periodic column).
fn u_rows(tf: &TwoFluid) -> Vec<f64> {
    let ny = tf.grid().ny();
    (0..ny).map(|j| tf.solids(0).u[2 * j]).collect()
}

/// Marches the column in time until its relative rate of change falls below the setup's
/// `steady_rate` or its end time, growing Δt while the outer iteration copes and halving it
/// on a failed step.
fn march(tf: &mut TwoFluid, setup: &ChuteCheckSetup) -> Result<March, ChuteCheckError> {
    let (mut time, mut dt) = (0.0, 1e-4);
    let (mut steps, mut rejected) = (0, 0);
    let mut rate = f64::INFINITY;
    while time < setup.end_time {
        let before = (
            tf.solids(0).eps().to_vec(),
            u_rows(tf),
            tf.solids(0).theta.clone(),
        );
        let out = tf
            .step(dt, 1e-3, 1e-4, 1e4, 50)
            .map_err(|e| ChuteCheckError::Column(e.to_string()))?;
        if !out.converged {
            rejected += 1;
            dt *= 0.5;
            if dt < 1e-8 {
                return Err(ChuteCheckError::Column(format!(
                    "time step below 1e-8 s at t = {time:.4} s: {}",
                    tf.residual_locations()
                )));
            }
            continue;
        }
        time += dt;
        steps += 1;
        let change = |a: &[f64], b: &[f64]| relative_error(b, a) / dt;
        rate = change(&before.0, tf.solids(0).eps())
            .max(change(&before.1, &u_rows(tf)))
            .max(change(&before.2, &tf.solids(0).theta));
        if setup.verbose && steps % 200 == 0 {
            eprintln!(
                "t = {time:.3} s, dt = {dt:.2e}, {} its, rate {rate:.2e}/s, slip row 0 {:.4}",
                out.iterations,
                tf.solids(0).u[0]
            );
        }
        if rate < setup.steady_rate {
            break;
        }
        // a steady state is sought: grow the step while the outer iteration copes
        if out.iterations <= 20 {
            dt = (dt * 1.2).min(setup.dt_max);
        }
    }
    Ok(March {
        time,
        steps,
        rejected,
        rate,
    })
}
