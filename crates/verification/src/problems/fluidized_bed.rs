//! Issue 7, settling-column check, the gas pressure drop: the settled bed of a column is
//! fluidized by gas entering through a distributor in the floor
//! ([`TwoFluid::set_gas_inflow`]) at about twice the minimum fluidization velocity and
//! leaving through a pressure outlet at the top. Once the bed is fluidized its weight hangs
//! on the gas, so the time-averaged gas pressure drop across it equals the bed's buoyant
//! weight per area (the column's momentum balance with the solids pressure negligible at
//! the floor). Checks: within 1 %, solids mass conserved to 1e-10, no solids leave.
//!
//! (The closed-box settling column of [`super::settling_column`] has no gas flow through its
//! packed bed: there the bed's weight is carried by the solids pressure, checked within
//! 1 %.)

use runout_closures::{
    ClosureParams, Drag, FrictionModel, FrictionParams, Gas, Particles, RadialDistribution,
};
use runout_mesh::{Axis, Grid, Sides};
use runout_solver::two_fluid::{SolidsSpec, TwoFluid, TwoFluidSettings};
use runout_solver::{Fluid, SideBc};
use runout_walls::{RobinFace, SolidsWallModel};

/// Solids density [kg m⁻³].
pub const RHO_S: f64 = 2000.0;
/// Gas density [kg m⁻³].
pub const RHO_G: f64 = 1.2;
/// Gravity [m s⁻²].
pub const G: f64 = 9.81;
/// Superficial gas velocity [m/s]: twice the minimum fluidization velocity of the initial
/// bed (εs = 0.55, d = 0.5 mm, ρs = 2000 kg m⁻³ in air) by Gidaspow's Ergun branch, where
/// the drag per volume, 150 εs² μ U/(εg³ d²) + 1.75 εs ρ U²/(εg³ d), reaches the bed's
/// weight ρs εs g at U ≈ 0.25 m/s.
pub const INFLOW: f64 = 0.5;
/// End of the run [s].
pub const END: f64 = 3.0;
/// Start of the averaging [s].
pub const AVERAGE_FROM: f64 = 1.5;

/// Averages and end state of the fluidized-bed run.
#[derive(Clone, Copy, Debug)]
pub struct FluidizedBed {
    /// time-averaged gas pressure drop across the bed, less the gas's own column [Pa]
    pub drop: f64,
    /// time-averaged buoyant weight of the bed per area [Pa]
    pub weight: f64,
    /// time-averaged solids pressure at the floor [Pa]
    pub p_s: f64,
    /// relative change of the solids mass
    pub mass_change: f64,
    /// largest εs at the end
    pub max_eps: f64,
    /// accepted steps
    pub steps: usize,
    /// every gas pressure finite at the end
    pub finite: bool,
}

/// Cells of the column.
const CELLS: usize = 60;

/// The bed's solver: one column of [`CELLS`] cells between free-slip walls, 0.3 m high, the
/// lowest 0.1 m at εs = 0.55, gas entering through the floor at [`INFLOW`].
fn bed_solver() -> anyhow::Result<TwoFluid> {
    let (ny, height, bed) = (CELLS, 0.3, 0.1);
    // one column between free-slip walls: a 1-D bed
    let grid = Grid::new(
        Axis::uniform(0.0, 0.005, 1)?,
        Axis::uniform(0.0, height, ny)?,
    );
    let gas = Fluid {
        density: RHO_G,
        viscosity: 1.8e-5,
    };
    let free_slip = SideBc::Wall(RobinFace::ZERO_GRADIENT);
    let no_slip = SideBc::Wall(RobinFace::dirichlet(0.0));
    let outlet = SideBc::Outlet(0.0);
    let params = ClosureParams {
        particles: Particles {
            diameter: 5e-4,
            density: RHO_S,
            restitution: 0.9,
        },
        gas: Gas {
            density: RHO_G,
            viscosity: 1.8e-5,
        },
        friction: FrictionParams::new(0.65, 0.5, 35.0),
        radial: RadialDistribution::CarnahanStarling,
        friction_model: FrictionModel::princeton(),
        drag: Drag::Gidaspow,
    };
    let spec = SolidsSpec {
        params,
        eps_max: 0.65,
        walls: Sides {
            west: Some(SolidsWallModel::FreeSlip),
            east: Some(SolidsWallModel::FreeSlip),
            south: Some(SolidsWallModel::NoSlip),
            north: None,
        },
    };
    let gas_walls = Sides {
        west: free_slip,
        east: free_slip,
        south: no_slip,
        north: outlet,
    };
    let mut tf = TwoFluid::new(
        grid.clone(),
        gas,
        gas_walls,
        vec![spec],
        (0.0, -G),
        TwoFluidSettings::default(),
    )?;
    tf.set_gas_inflow(Sides {
        west: 0.0,
        east: 0.0,
        south: INFLOW,
        north: 0.0,
    })?;
    let state = tf.state_mut();
    state.update_solids(0, |s| {
        for j in 0..ny {
            if grid.y.centres()[j] < bed {
                s.eps[j] = 0.55;
            }
            s.theta[j] = 1e-4;
        }
    });
    state.gas_mut().v.iter_mut().for_each(|v| *v = INFLOW);
    Ok(tf)
}

/// Runs the bed ([`bed_solver`]) to 3 s with an adaptive step, averaging from 1.5 s. With
/// `verbose`, prints progress every 200 steps.
pub fn run(verbose: bool) -> anyhow::Result<FluidizedBed> {
    let mut tf = bed_solver()?;
    let ny = CELLS;
    let grid = tf.grid().clone();
    let dy = grid.y.widths()[0];
    let mass0 = tf.solids_mass(0);
    // buoyant weight of the bed per area above the bottom cell's centre, and the gas
    // column between the bottom and top cell centres
    let weight = |tf: &TwoFluid| -> f64 {
        let s = &tf.solids(0).eps();
        (RHO_S - RHO_G) * G * (s.iter().sum::<f64>() - 0.5 * s[0]) * dy
    };
    let (mut time, mut dt): (f64, f64) = (0.0, 2e-4);
    let (end, average_from) = (END, AVERAGE_FROM);
    let (mut drop_integral, mut weight_integral, mut p_s_integral, mut span) = (0.0, 0.0, 0.0, 0.0);
    let mut steps = 0;
    while time < end - 1e-12 {
        let step_dt = dt.min(end - time);
        let out = tf.step(step_dt, 1e-3, 1e-4, 1e4, 50)?;
        if !out.converged {
            dt *= 0.5;
            anyhow::ensure!(dt > 1e-7, "time step collapsed at t = {time}: {out:?}");
            continue;
        }
        time += step_dt;
        steps += 1;
        if out.iterations < 10 {
            dt = (dt * 1.1).min(2e-3);
        }
        // gas pressure drop between the bottom and top cell centres, less the gas's own
        // column (εg ρg g between them)
        let p = tf.p_g();
        let gas_column: f64 = RHO_G * G * dy * (0.5 * tf.eps_g()[0] + 0.5 * tf.eps_g()[ny - 1])
            + RHO_G * G * dy * tf.eps_g()[1..ny - 1].iter().sum::<f64>();
        let drop = p[0] - p[ny - 1] - gas_column;
        if time > average_from {
            drop_integral += drop * step_dt;
            weight_integral += weight(&tf) * step_dt;
            p_s_integral += tf.p_s(0)[0] * step_dt;
            span += step_dt;
        }
        if verbose && steps % 200 == 0 {
            let top = (0..ny)
                .rev()
                .find(|&j| tf.solids(0).eps()[j] > 0.1)
                .unwrap_or(0);
            eprintln!(
                "t = {time:.3} s, dt {dt:.1e}, {} its, drop {drop:.1} Pa, weight {:.1} Pa, eps bottom {:.3}, P_s bottom {:.2}, bed top {:.3} m",
                out.iterations,
                weight(&tf),
                tf.solids(0).eps()[0],
                tf.p_s(0)[0],
                grid.y.centres()[top]
            );
        }
    }
    let (drop, weight, p_s) = (
        drop_integral / span,
        weight_integral / span,
        p_s_integral / span,
    );
    let mass = tf.solids_mass(0) / mass0 - 1.0;
    let max_eps = tf.solids(0).eps().iter().cloned().fold(0.0, f64::max);
    Ok(FluidizedBed {
        drop,
        weight,
        p_s,
        mass_change: mass,
        max_eps,
        steps,
        finite: tf.p_g().iter().all(|x| x.is_finite()),
    })
}
