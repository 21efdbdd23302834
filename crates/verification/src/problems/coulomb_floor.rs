//! Issue 61's check of the Coulomb wall (docs/model.md §3.11): a granular block sliding on
//! a Coulomb floor, and a layer sliding between Coulomb side walls, against the law every
//! landslide model is judged by.
//!
//! **The sliding block.** Whatever happens inside a block that slides as a whole, its centre
//! of mass accelerates at
//!
//!   a = g (sin θ − μ_w cos θ)                                                         (1)
//!
//! because the floor's friction is μ_w times its normal load, and the normal load is the
//! block's weight g cos θ per unit mass once its motion across the floor has settled. The
//! set-up is a copy of cases/collapse/CM-a1.ron (glass beads with μ(I), Jop et al. 2005): a
//! block 0.10 m long and 0.02 m thick at εs = 0.57 (P_c(0.57) = 75 Pa, about half the
//! weight at its base, so that it neither springs up nor sinks much), on a 20° slope
//! (tan θ = 0.364, just below the beads' μ_s = 0.382), in a box 0.6 × 0.04 m, released
//! sliding at 1 m/s so that every part of its base slides forward throughout: a granular
//! block released at rest collapses on itself, and where its rear stops the floor holds it
//! by static friction below μ_w N, so that Eq. (1) does not apply (docs/model.md §3.11 has
//! the numbers). The acceleration is the least-squares slope of the εs-weighted mean u_s
//! (bulk.csv, every 5 ms) between 0.05 and 0.2 s. Released at εs 0.57, below the packing
//! its weight holds, the block settles and rebounds across the floor; the finer the grid,
//! the less that rebound is damped (at 240 × 32 the μ_w Eq. (1) implies swings by ±4 %
//! between successive 50 ms windows), which Eq. (1) does not count.
//!
//! **The pore gas.** Eq. (1) is the law of a block in vacuum. In air the block is a
//! two-fluid body: as it spreads and settles it expels
//! the gas in its pores, and the gas's drag carries part of its weight, so the floor's load
//! and its friction are smaller than Eq. (1) assumes. At 120 × 16, μ_w = 0.2, the μ_w Eq. (1)
//! implies is 0.1984 in air and 0.1997 with the gas's viscosity a hundredth of air's
//! (docs/model.md §3.11). The check therefore judges the wall law on the block in a thin gas
//! ([`PoreGas::Thin`]: air's density, a hundredth of its viscosity, so a hundredth of its
//! drag) and prints the block in air ([`PoreGas::Air`]) beside it as a measurement of the
//! cushion, without a limit.
//!
//! **The layer between side walls.** A layer uniform along the slope (the periodic column of
//! [`crate::problems::chute_column`], packed as [`crate::problems::incline::packed_layer`])
//! slides as a plug on a Coulomb floor μ_f between Coulomb side walls μ_sw a width W apart.
//! Its stresses are hydrostatic (no strain), P(y) = ρs g cos θ ∫_y^h εs dy', so the floor
//! carries the weight and each side wall ∫P dy = ρs g cos θ ∫ εs y dy (by parts): per unit
//! mass
//!
//!   a = g sin θ − μ_f g cos θ − (2 μ_sw/W) g cos θ y_c                                 (2)
//!
//! with y_c the height of the layer's centre of mass.
//!
//! **The energy line.** A block released at rest on a 30° slope that turns onto a flat floor
//! ([`run_energy_line`]) stops on the flat; the drop of its centre of mass over the centre's
//! horizontal travel is at least μ_w.

use anyhow::{bail, Context, Result};
use runout_case::{Boundary, Case, Fidelity, Gravity, MomentumForm, SolidsWall};
use runout_mesh::Segment;
use runout_solver::two_fluid::{RelaxationBase, TwoFluid};
use runout_walls::SolidsWallModel;

use crate::chute1d::ChuteSidewalls;
use crate::problems::case_copy::{ending_at, template_on_grid, thin_gas, validated};
use crate::problems::chute_column::{sliding_column, ChuteCheckSetup};
use crate::problems::incline::{glass_beads, packed_layer, HEIGHT, HOLDUP};
use crate::problems::stepping::Stepping;

/// The gas in the block's pores (module doc).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PoreGas {
    /// the template's air
    Air,
    /// air's density with [`THIN_GAS_VISCOSITY_FRACTION`] of its viscosity
    Thin,
}

/// The form of the momentum equations the check judges the law in (docs/model.md §4.3): in
/// MFIX's continuity-subtracted form the outer iterations' continuity remainder creates
/// momentum where the block is sheared (module doc).
pub const JUDGED_FORM: MomentumForm = MomentumForm::Conservative;

/// The thin gas's viscosity over air's [-]: the drag of the Stokes regime scales with it.
pub const THIN_GAS_VISCOSITY_FRACTION: f64 = 0.01;

/// The case the block is copied from, relative to the workspace root.
pub const TEMPLATE: &str = "cases/collapse/CM-a1.ron";
/// The slope [deg].
pub const SLOPE_DEG: f64 = 20.0;
/// The block's starting εs [-].
pub const BLOCK_EPS_S: f64 = 0.57;
/// The block's starting speed along the slope [m s⁻¹].
pub const BLOCK_SPEED: f64 = 1.0;
/// The window of the fit of Eq. (1) [s].
pub const FIT_WINDOW: (f64, f64) = (0.05, 0.2);
/// Standard gravity of CM-a1.ron [m s⁻²].
pub const GRAVITY: f64 = 9.81;

/// Eq. (1): a = g (sin θ − μ_w cos θ) [m s⁻²].
pub fn sliding_acceleration(slope_deg: f64, mu_w: f64) -> f64 {
    let theta = slope_deg.to_radians();
    GRAVITY * (theta.sin() - mu_w * theta.cos())
}

/// The friction coefficient a measured acceleration implies through Eq. (1).
pub fn effective_friction(slope_deg: f64, acceleration: f64) -> f64 {
    let theta = slope_deg.to_radians();
    (GRAVITY * theta.sin() - acceleration) / (GRAVITY * theta.cos())
}

/// The least-squares slope of `values` against `times` over the samples in `window`.
pub fn fitted_slope(times: &[f64], values: &[f64], window: (f64, f64)) -> Option<f64> {
    let points: Vec<(f64, f64)> = times
        .iter()
        .zip(values)
        .filter(|(t, _)| (window.0..=window.1).contains(*t))
        .map(|(&t, &v)| (t, v))
        .collect();
    if points.len() < 3 {
        return None;
    }
    let n = points.len() as f64;
    let (t_mean, v_mean) = (
        points.iter().map(|p| p.0).sum::<f64>() / n,
        points.iter().map(|p| p.1).sum::<f64>() / n,
    );
    let (num, den) = points.iter().fold((0.0, 0.0), |(num, den), (t, v)| {
        (
            num + (t - t_mean) * (v - v_mean),
            den + (t - t_mean) * (t - t_mean),
        )
    });
    Some(num / den)
}

/// The block case on `cells_x` × `cells_y` cells with floor friction `mu_w`, `pore_gas` and
/// the momentum equations in `form` (module doc).
pub fn block_case(
    cells_x: usize,
    cells_y: usize,
    mu_w: f64,
    pore_gas: PoreGas,
    form: MomentumForm,
) -> Result<Case> {
    let mut case = template_on_grid(
        TEMPLATE,
        format!("coulomb-block-mu{mu_w}-{cells_x}x{cells_y}-{pore_gas:?}"),
        (0.6, 0.04),
        (cells_x, cells_y),
        Gravity::Constant {
            magnitude: GRAVITY,
            slope: SLOPE_DEG,
        },
    )?;
    if pore_gas == PoreGas::Thin {
        case = thin_gas(case, THIN_GAS_VISCOSITY_FRACTION)?;
    }
    let Boundary::Wall { solids, .. } = &mut case.boundaries.south else {
        bail!("{TEMPLATE}: the floor is not a wall");
    };
    *solids = SolidsWall::Coulomb {
        friction: mu_w,
        slip_floor: None,
    };
    case.numerics.momentum_form = form;
    let block = &mut case.initial.regions[0];
    block.x = (0.05, 0.15);
    block.y = (0.0, 0.02);
    block.solids[0].eps_s = BLOCK_EPS_S;
    block.solids[0].velocity = (BLOCK_SPEED, 0.0);
    validated(ending_at(case, FIT_WINDOW.1), "block")
}

/// One block run: its measured acceleration against Eq. (1).
#[derive(Clone, Debug)]
pub struct BlockRun {
    /// cells along and across the slope
    pub cells: (usize, usize),
    /// μ_w of the floor
    pub mu_w: f64,
    /// the fitted acceleration [m s⁻²]
    pub acceleration: f64,
    /// Eq. (1) [m s⁻²]
    pub expected: f64,
    /// μ_w implied by the fitted acceleration
    pub effective_mu_w: f64,
    /// wall time [s]
    pub wall_time: f64,
}

/// Runs the block (module doc) through the driver in a temporary directory.
pub fn run_block(
    cells_x: usize,
    cells_y: usize,
    mu_w: f64,
    pore_gas: PoreGas,
    form: MomentumForm,
) -> Result<BlockRun> {
    let case = block_case(cells_x, cells_y, mu_w, pore_gas, form)?;
    let out = std::env::temp_dir().join(format!("runout-{}-{}", case.name, std::process::id()));
    let summary = runout_run::run_case(&case, Fidelity::Paper, &out, |_| {})?;
    let bulk = runout_post::table::Table::read(&out.join("bulk.csv"))
        .map_err(|e| anyhow::anyhow!("{}: {e}", out.display()))?;
    let times = bulk.column("t").map_err(anyhow::Error::msg)?;
    let speeds = bulk.column("mean_u_s").map_err(anyhow::Error::msg)?;
    let acceleration =
        fitted_slope(&times, &speeds, FIT_WINDOW).context("too few bulk.csv samples")?;
    let _ = std::fs::remove_dir_all(&out);
    Ok(BlockRun {
        cells: (cells_x, cells_y),
        mu_w,
        acceleration,
        expected: sliding_acceleration(SLOPE_DEG, mu_w),
        effective_mu_w: effective_friction(SLOPE_DEG, acceleration),
        wall_time: summary.wall_time,
    })
}

/// The packed layer of the glass beads on `cells` cells across its strip, sliding at `speed`
/// on a Coulomb floor of friction `mu_f`, between `sidewalls` if any.
fn layer_setup(
    cells: usize,
    mu_f: f64,
    sidewalls: Option<ChuteSidewalls>,
    speed: f64,
) -> Result<ChuteCheckSetup> {
    Ok(ChuteCheckSetup {
        cells,
        height: HEIGHT,
        holdup: HOLDUP,
        slope_deg: SLOPE_DEG,
        floor: SolidsWallModel::coulomb(mu_f, runout_walls::coulomb::DEFAULT_SLIP_FLOOR)?,
        sidewalls,
        closures: glass_beads(),
        initial_velocity: speed,
        initial_eps_s: Some(packed_layer(cells, SLOPE_DEG)),
        initial_theta: 1e-6,
        ..ChuteCheckSetup::default()
    })
}

/// A packed layer released at rest on a Coulomb floor of friction `mu_f` (the layer of
/// [`run_layer`] without side walls, uniform along the slope, so with no face to slump):
/// the largest |mean u_s| over [`LAYER_RUN`]'s time [m s⁻¹]. Above tan θ it stays at rest
/// (but for the regularisation's creep, u_min r/√(1 − r²), 1.1e-4 m/s at μ_f = 0.5);
/// below, it slides.
pub fn layer_at_rest(cells: usize, mu_f: f64) -> Result<f64> {
    let (_, end, dt) = LAYER_RUN;
    let setup = layer_setup(cells, mu_f, None, 0.0)?;
    let mut tf = sliding_column(&setup, GRAVITY)?;
    let mut largest: f64 = 0.0;
    let stepping = Stepping {
        tolerances: (1e-3, 1e-4, 1e4, 100),
        dt: (1e-4, 1e-7, dt),
    };
    stepping.march(&mut tf, (&mut 0.0, &mut 1e-4), end, |_, tf| {
        largest = largest.max(mean_speed(tf).abs());
    })?;
    Ok(largest)
}

/// The largest mean speed of a layer at rest [m s⁻¹] (20 × the creep at μ_f = 0.5) and the
/// least of one that slides (μ_f = 0.3, below tan θ: it gains g (sin θ − μ_f cos θ) t =
/// 0.06 m/s in 0.1 s).
pub const REST_SPEEDS: (f64, f64) = (2e-3, 0.03);

/// One run of the layer between side walls: its acceleration against Eq. (2).
#[derive(Clone, Debug)]
pub struct LayerRun {
    /// cells across the layer's strip
    pub cells: usize,
    /// the fitted acceleration [m s⁻²]
    pub acceleration: f64,
    /// Eq. (2) [m s⁻²]
    pub expected: f64,
    /// the side walls' share of Eq. (2)'s friction, measured over expected
    pub friction_ratio: f64,
}

/// The layer's floor friction μ_f, side-wall friction μ_sw and channel width W \[m\].
pub const LAYER_WALLS: (f64, f64, f64) = (0.1, 0.1, 0.02);
/// The layer's starting speed [m s⁻¹] and its simulated time and time step [s].
pub const LAYER_RUN: (f64, f64, f64) = (1.0, 0.1, 1e-3);

/// Runs the layer (module doc) on `cells` cells across the strip.
pub fn run_layer(cells: usize) -> Result<LayerRun> {
    let (mu_f, mu_sw, width) = LAYER_WALLS;
    let (speed, end, dt) = LAYER_RUN;
    let sidewalls = ChuteSidewalls {
        width,
        solids: SolidsWallModel::coulomb(mu_sw, runout_walls::coulomb::DEFAULT_SLIP_FLOOR)?,
    };
    let setup = layer_setup(cells, mu_f, Some(sidewalls), speed)?;
    let mut tf = sliding_column(&setup, GRAVITY)?;
    let (mut times, mut speeds) = (vec![0.0], vec![mean_speed(&tf)]);
    let stepping = Stepping {
        tolerances: (1e-3, 1e-4, 1e4, 100),
        dt: (1e-4, 1e-7, dt),
    };
    stepping.march(&mut tf, (&mut 0.0, &mut 1e-4), end, |time, tf| {
        times.push(time);
        speeds.push(mean_speed(tf));
    })?;
    let acceleration = fitted_slope(&times, &speeds, (0.0, end)).context("no samples")?;
    let theta = SLOPE_DEG.to_radians();
    let y_c = centre_height(&tf);
    let side = 2.0 * mu_sw / width * GRAVITY * theta.cos() * y_c;
    let expected = GRAVITY * (theta.sin() - mu_f * theta.cos()) - side;
    Ok(LayerRun {
        cells,
        acceleration,
        expected,
        friction_ratio: (GRAVITY * theta.sin() - acceleration) / (GRAVITY * theta.sin() - expected),
    })
}

/// The εs-weighted mean u_s of the column [m s⁻¹].
fn mean_speed(tf: &TwoFluid) -> f64 {
    let s = tf.solids(0);
    let dy = tf.grid().y.widths();
    let (num, den) =
        s.eps()
            .iter()
            .zip(dy)
            .enumerate()
            .fold((0.0, 0.0), |(num, den), (j, (e, h))| {
                // one cell across: u nodes 2j (west) and 2j + 1 (east) of row j
                let u = 0.5 * (s.u[2 * j] + s.u[2 * j + 1]);
                (num + e * h * u, den + e * h)
            });
    num / den
}

/// The height of the column's centre of mass above the floor [m].
fn centre_height(tf: &TwoFluid) -> f64 {
    let s = tf.solids(0);
    let (dy, yc) = (tf.grid().y.widths(), tf.grid().y.centres());
    let (num, den) = s
        .eps()
        .iter()
        .zip(dy.iter().zip(yc))
        .fold((0.0, 0.0), |(num, den), (e, (h, y))| {
            (num + e * h * y, den + e * h)
        });
    num / den
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fit_recovers_a_straight_line() {
        let times: Vec<f64> = (0..50).map(|k| f64::from(k) * 0.005).collect();
        let values: Vec<f64> = times.iter().map(|t| 1.0 + 1.5 * t).collect();
        let slope = fitted_slope(&times, &values, FIT_WINDOW).unwrap();
        assert!((slope - 1.5).abs() < 1e-12, "{slope}");
        assert!(
            (effective_friction(SLOPE_DEG, sliding_acceleration(SLOPE_DEG, 0.3)) - 0.3).abs()
                < 1e-12
        );
    }
}

/// The first step of the packed layer on a frictionless floor without side walls, started
/// at rest, at momentum relaxation `relax_velocity` with the solids rows relaxed in
/// proportion to `base` (`None`: μ(I)'s own part): its mean speed gain over g sin θ Δt,
/// which is 1 for any converged step (a plug with no wall friction accelerates at g sin θ).
/// With μ(I) the plug's regularised viscosity μ_s P/γ̇_min makes its links about 1e4 times
/// its inertia, and Patankar's relaxation, which adds (1 − ω)/ω a_P to the diagonal with
/// a_P counting those links, moves the rigid motion by about a_0/a_P per outer iteration
/// while the normalised residual Σ|r|/Σ|a_P u| is already below its tolerance: the step
/// "converges" with the layer still (docs/model.md §4.10).
pub fn plug_first_step(
    cells: usize,
    relax_velocity: f64,
    solids_relaxation_base: Option<RelaxationBase>,
) -> Result<f64> {
    let dt = 1e-3;
    let setup = ChuteCheckSetup {
        cells,
        height: HEIGHT,
        holdup: HOLDUP,
        slope_deg: SLOPE_DEG,
        floor: SolidsWallModel::FreeSlip,
        closures: glass_beads(),
        initial_velocity: 0.0,
        initial_eps_s: Some(packed_layer(cells, SLOPE_DEG)),
        initial_theta: 1e-6,
        relax_velocity,
        solids_relaxation_base,
        ..ChuteCheckSetup::default()
    };
    let mut tf = sliding_column(&setup, GRAVITY)?;
    // residual 1e-2: at the cases' 1e-3 the relaxed step stalls (and a run retries it
    // with a smaller Δt, whose larger inertia a_0 lets it through)
    let step = tf.step(dt, 1e-2, 1e-4, 1e4, 200)?;
    if !step.converged {
        bail!("the plug's first step did not converge: {step:?}");
    }
    Ok(mean_speed(&tf) / (GRAVITY * SLOPE_DEG.to_radians().sin() * dt))
}

#[cfg(test)]
mod plug {
    use super::*;

    /// With μ(I)'s relaxation (its rows' own part) the plug's first step is converged at
    /// every ω, as it is unrelaxed.
    #[test]
    fn a_mu_i_plug_accelerates_at_g_sin_theta() {
        for relax in [0.5, 0.7, 1.0] {
            let gain = plug_first_step(12, relax, None).unwrap();
            assert!((gain - 1.0).abs() < 1e-3, "relaxation {relax}: {gain}");
        }
    }

    /// MFIX's Patankar form freezes it: the speed gain is below 1 % of g sin θ Δt at
    /// ω = 0.5, 0.7, 0.9 (docs/model.md §4.10). `cargo test --release -p
    /// runout-verification --lib plug -- --nocapture` prints them.
    #[test]
    fn patankar_relaxation_freezes_a_mu_i_plug() {
        for relax in [0.5, 0.7, 0.9] {
            let gain = plug_first_step(12, relax, Some(RelaxationBase::Centre)).unwrap();
            println!("Patankar, ω = {relax}: speed gain / (g sin θ Δt) = {gain:.3e}");
            assert!(gain < 1e-2, "relaxation {relax}: {gain}");
        }
    }
}

/// The energy line's slope [deg], bend (start along the floor, radius) [m] and run-out end
/// time [s]: a block released at rest 0.10 m up a 30° slope that turns on a 0.1 m arc onto a
/// flat floor at x = 0.3 m (tan 30° = 0.577 above μ_w, so it slides; the flat stops it).
pub const ENERGY_LINE_BED: (f64, f64, f64, f64) = (30.0, 0.3, 0.1, 1.5);

/// The last stretch of the energy-line run over which the deposit must be at rest [s].
pub const LATE_WINDOW: f64 = 0.5;

/// The energy line of a block that slides down a slope onto a flat floor and stops there:
/// the drop of its centre over the centre's horizontal travel (runout_post's
/// `centre_ratio`), which is at least μ_w because the floor's friction μ_w N, with N the
/// weight plus the centrifugal load on the arc, does work μ_w g cos α ds or more per unit
/// mass over every stretch ds, and the grains' own shearing only adds to it; whether it is
/// at rest by the end: its εs-weighted mean speed over the last [`LATE_WINDOW`] below
/// `runout post`'s rest speed. (`runout post`'s rest time also needs the whole-cell front
/// still, which the deposit's tip can cross late as it creeps at the regularisation's
/// speed: on 120 × 16 the front cell at 0.64 m filled at 1.5 s with the mean speed at
/// 1.6e-4 m/s.)
#[derive(Clone, Debug)]
pub struct EnergyLineRun {
    /// cells along and across the floor
    pub cells: (usize, usize),
    /// μ_w of the floor
    pub mu_w: f64,
    /// drop of the centre over its horizontal travel [-]
    pub centre_ratio: f64,
    /// the same of the rear of the release to the grain edge (Heim's ratio) [-]
    pub heim_ratio: f64,
    /// when the deposit came to rest [s], if it did (`runout post`'s rest time)
    pub rest_time: Option<f64>,
    /// the largest |εs-weighted mean u_s| over the last [`LATE_WINDOW`] [m s⁻¹]
    pub late_speed: f64,
    /// `runout post`'s rest speed, 1 % of √(g H∞) [m s⁻¹]
    pub rest_speed: f64,
    /// the grain edge past the foot [m]
    pub past_foot: f64,
}

/// The energy-line case (module doc of [`EnergyLineRun`]) with the momentum equations in
/// `form`.
pub fn energy_line_case(
    cells_x: usize,
    cells_y: usize,
    mu_w: f64,
    form: MomentumForm,
) -> Result<Case> {
    let (slope, at, radius, end) = ENERGY_LINE_BED;
    let mut case = block_case(cells_x, cells_y, mu_w, PoreGas::Thin, form)?;
    case.name = format!("coulomb-energy-line-mu{mu_w}-{cells_x}x{cells_y}");
    case.domain.x.segments = vec![Segment::Uniform {
        length: 0.8,
        cells: cells_x,
    }];
    case.gravity = Gravity::Constant {
        magnitude: GRAVITY,
        slope,
    };
    case.bed = runout_case::Bed::Bend {
        at,
        radius,
        slope_after: 0.0,
    };
    let block = &mut case.initial.regions[0];
    block.solids[0].velocity = (0.0, 0.0);
    validated(ending_at(case, end), "energy-line")
}

/// Runs the energy-line block (module doc of [`EnergyLineRun`]) through the driver.
pub fn run_energy_line(cells_x: usize, cells_y: usize, mu_w: f64) -> Result<EnergyLineRun> {
    let case = energy_line_case(cells_x, cells_y, mu_w, JUDGED_FORM)?;
    let out = std::env::temp_dir().join(format!("runout-{}-{}", case.name, std::process::id()));
    runout_run::run_case(&case, Fidelity::Paper, &out, |_| {})?;
    let resolved = case.at_fidelity(Fidelity::Paper);
    let (deposit, _) = runout_post::deposit::read_deposit(
        &out,
        &resolved,
        runout_post::deposit::DEFAULT_REST_FRACTION,
    )
    .map_err(anyhow::Error::msg)?;
    let bulk = runout_post::table::Table::read(&out.join("bulk.csv"))
        .map_err(|e| anyhow::anyhow!("{}: {e}", out.display()))?;
    let times = bulk.column("t").map_err(anyhow::Error::msg)?;
    let speeds = bulk.column("mean_u_s").map_err(anyhow::Error::msg)?;
    let end = ENERGY_LINE_BED.3;
    let late_speed = times
        .iter()
        .zip(&speeds)
        .filter(|(t, _)| **t >= end - LATE_WINDOW)
        .map(|(_, u)| u.abs())
        .fold(0.0, f64::max);
    let _ = std::fs::remove_dir_all(&out);
    let run_out = deposit
        .on_the_run_out
        .context("a bent floor's deposit has its place on the run-out")?;
    Ok(EnergyLineRun {
        cells: (cells_x, cells_y),
        mu_w,
        centre_ratio: run_out.centre_ratio,
        heim_ratio: run_out.heim_ratio,
        rest_time: deposit.rest_time,
        late_speed,
        rest_speed: deposit.rest_speed,
        past_foot: run_out.grain_edge_past_foot,
    })
}

/// The block's floor load over its weight normal to the floor, Σ N_w w over the floor's u
/// nodes against M g cos θ, at each of `times` [s] (the block of [`block_case`] stepped as
/// the driver would): the load the Coulomb wall reads, against the weight it should carry
/// once the block's motion across the floor has settled.
pub fn floor_load_ratios(
    cells_x: usize,
    cells_y: usize,
    mu_w: f64,
    times: &[f64],
) -> Result<Vec<f64>> {
    let case = block_case(cells_x, cells_y, mu_w, PoreGas::Thin, JUDGED_FORM)?
        .at_fidelity(Fidelity::Paper);
    let mut tf = runout_run::two_fluid_solver(&case)?;
    let stepping = Stepping::of(&case);
    let (mut time, mut dt) = (0.0, stepping.dt.0);
    let mut ratios = Vec::with_capacity(times.len());
    for &until in times {
        stepping.march(&mut tf, (&mut time, &mut dt), until, |_, _| {})?;
        let grid = tf.grid();
        let weight = tf.solids_mass(0) * GRAVITY * SLOPE_DEG.to_radians().cos();
        let spacing = grid.x.face_spacing();
        let load: f64 = (1..grid.nx())
            .map(|k| tf.floor_normal_load(0)[k] * spacing[k])
            .sum();
        ratios.push(load / weight);
    }
    Ok(ratios)
}

/// The block's momentum budget along the slope over [`FIT_WINDOW`], per unit mass
/// [m s⁻²]: what its momentum did against what its forces add up to.
#[derive(Clone, Debug)]
pub struct MomentumBudget {
    /// the least-squares slope of the εs-weighted mean u_s, sampled every step
    pub acceleration: f64,
    /// the time mean of gravity, the floor's friction Σ μ_w N_w w (the load the wall read),
    /// the drag and the buoyancy −εs ∂P_g/∂x, over the solids' mass
    pub forces: f64,
    /// μ_w implied by each through Eq. (1)
    pub effective_mu_w: (f64, f64),
}

/// The block of [`block_case`] stepped as the driver would, its momentum against its
/// forces (docs/model.md §4.3): in a discretisation that conserves momentum the two agree
/// whatever the outer iterations leave of continuity.
pub fn block_momentum_budget(
    cells: (usize, usize),
    mu_w: f64,
    form: MomentumForm,
) -> Result<MomentumBudget> {
    let case =
        block_case(cells.0, cells.1, mu_w, PoreGas::Thin, form)?.at_fidelity(Fidelity::Paper);
    let mut tf = runout_run::two_fluid_solver(&case)?;
    let stepping = Stepping::of(&case);
    let (mut time, mut dt) = (0.0, stepping.dt.0);
    let (mut times, mut speeds, mut forces) = (Vec::new(), Vec::new(), Vec::new());
    let gravity = GRAVITY * SLOPE_DEG.to_radians().sin();
    stepping.march(&mut tf, (&mut time, &mut dt), FIT_WINDOW.1, |t, tf| {
        let (speed, force) = speed_and_force(tf, mu_w);
        times.push(t);
        speeds.push(speed);
        forces.push(gravity + force);
    })?;
    let acceleration = fitted_slope(&times, &speeds, FIT_WINDOW).context("too few steps")?;
    // the trapezoid mean of the force over the window
    let (mut impulse, mut span) = (0.0, 0.0);
    for k in 1..times.len() {
        if times[k - 1] >= FIT_WINDOW.0 {
            let h = times[k] - times[k - 1];
            impulse += 0.5 * h * (forces[k] + forces[k - 1]);
            span += h;
        }
    }
    let forces = impulse / span;
    Ok(MomentumBudget {
        acceleration,
        forces,
        effective_mu_w: (
            effective_friction(SLOPE_DEG, acceleration),
            effective_friction(SLOPE_DEG, forces),
        ),
    })
}

/// The εs-weighted mean u_s [m s⁻¹] (bulk.csv's `mean_u_s`) and the force along the slope
/// other than gravity per unit solids mass [m s⁻²]: the floor's friction −μ_w N_w w
/// summed over its u nodes, the drag F_gs (u_g − u_s) V and the buoyancy −εs ∂P_g/∂x V
/// summed over the cells (centred differences; the block is clear of the end walls).
fn speed_and_force(tf: &TwoFluid, mu_w: f64) -> (f64, f64) {
    let grid = tf.grid();
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, s) = (grid.x.widths(), tf.solids(0));
    let (u_g, p_g, drag) = (tf.u_g(), tf.p_g(), tf.drag(0));
    let centre =
        |u: &[f64], i: usize, j: usize| 0.5 * (u[i + (nx + 1) * j] + u[i + 1 + (nx + 1) * j]);
    let (mut momentum, mut volume, mut force) = (0.0, 0.0, 0.0);
    for j in 0..ny {
        for i in 0..nx {
            let k = i + nx * j;
            let (cell, eps) = (grid.cell_volume(i, j), s.eps()[k]);
            let u_s = centre(&s.u, i, j);
            momentum += eps * cell * u_s;
            volume += eps * cell;
            force += drag[k] * (centre(u_g, i, j) - u_s) * cell;
            if i > 0 && i + 1 < nx {
                let spacing = 0.5 * (dx[i - 1] + dx[i + 1]) + dx[i];
                force -= eps * (p_g[k + 1] - p_g[k - 1]) / spacing * cell;
            }
        }
    }
    let spacing = grid.x.face_spacing();
    let friction: f64 = (1..nx)
        .map(|k| mu_w * tf.floor_normal_load(0)[k] * s.u[k].signum() * spacing[k])
        .sum();
    (momentum / volume, (force - friction) / tf.solids_mass(0))
}
