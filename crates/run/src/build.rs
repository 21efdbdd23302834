//! From a case to a solver: the single-phase core for a gas-only case, the two-fluid model
//! for a case with solids, with their initial state and boundary conditions.

use runout_case::{
    Block, Boundary, Case, Convection, Fill, GasWall, Gravity, InitialPressure, KineticTheory,
    OutletPressure,
};
use runout_closures::{ClosureParams, FrictionParams, Gas, Particles};
use runout_mesh::{Grid, Sides};
use runout_walls::{RobinFace, SolidsWallModel};

use crate::RunError;
use runout_solver::bent_floor::BentFloor;
use runout_solver::momentum::MomentumForm;

use crate::polygon;
use runout_solver::single_phase::{Fluid, Settings, SideBc, SinglePhase};
use runout_solver::transport::Scheme;
use runout_solver::two_fluid::{RelaxationBase, SolidsSpec, TwoFluid, TwoFluidSettings};

fn wall_closure(gas: &GasWall) -> RobinFace {
    match *gas {
        GasWall::NoSlip => RobinFace::dirichlet(0.0),
        GasWall::FreeSlip => RobinFace::ZERO_GRADIENT,
        GasWall::Moving { u_w } => RobinFace::dirichlet(u_w),
        GasWall::PartialSlip { h_u, u_w } => RobinFace::partial_slip(h_u, u_w),
    }
}

/// The gas condition of a boundary: the wall's closure of the tangential velocity, or the
/// outlet's (hydrostatic) pressure.
fn outlet_bc(b: &Boundary, gas: &runout_case::Gas) -> SideBc {
    match b {
        Boundary::Wall { gas: wall, .. } => SideBc::Wall(wall_closure(wall)),
        Boundary::PressureOutlet {
            pressure: OutletPressure::Uniform(p),
        } => SideBc::Outlet(*p),
        Boundary::PressureOutlet {
            pressure: OutletPressure::Hydrostatic(p0),
        } => SideBc::HydrostaticOutlet {
            p0: *p0,
            density: gas.density,
        },
    }
}

/// The gas conditions of the four sides of a case.
fn gas_sides(case: &Case, gas: &runout_case::Gas) -> Sides<SideBc> {
    let b = &case.boundaries;
    Sides {
        west: outlet_bc(&b.west, gas),
        east: outlet_bc(&b.east, gas),
        south: outlet_bc(&b.south, gas),
        north: outlet_bc(&b.north, gas),
    }
}

/// Initial gas pressure of cell centre (x, y): hydrostatic from the top-left corner,
/// p = p_ref + ρ_g g·(r − r_top-left), under a bent floor p_ref + ρ_g (Φ(r_top-left) − Φ(r))
/// (docs/model.md §9), or the case's uniform value.
fn initial_gas_pressure(
    case: &Case,
    gas: &runout_case::Gas,
    gravity: (f64, f64),
    bent: Option<&BentFloor>,
    grid: &Grid,
    (x, y): (f64, f64),
) -> f64 {
    let top_left = (grid.x.start(), grid.y.end());
    match (&case.initial.gas_pressure, bent, gas.law.is_constant()) {
        (InitialPressure::Hydrostatic, None, true) => {
            gas.reference_pressure
                + gas.density * (gravity.0 * (x - top_left.0) + gravity.1 * (y - top_left.1))
        }
        (InitialPressure::Hydrostatic, Some(b), true) => {
            gas.reference_pressure + gas.density * b.work(top_left, (x, y))
        }
        // an ideal gas's isothermal column (docs/model.md §1.4)
        (InitialPressure::Hydrostatic, _, false) => {
            let work = match bent {
                Some(b) => b.work(top_left, (x, y)),
                None => gravity.0 * (x - top_left.0) + gravity.1 * (y - top_left.1),
            };
            gas.equation_of_state()
                .hydrostatic(gas.reference_pressure, work)
        }
        (InitialPressure::Uniform(p), _, _) => *p,
    }
}

/// The bent floor of a case with `bed: Bend(..)` (docs/model.md §9), acting under its final
/// (tilted) gravity; `None` on a plane floor.
pub(super) fn bent_floor(case: &Case) -> Result<Option<BentFloor>, RunError> {
    case.bent_floor().map_err(|e| RunError::Unsupported {
        case: case.name.clone(),
        reason: e.to_string(),
    })
}

/// Gravity (g_x, g_y) [m s⁻²].
type GravityVector = (f64, f64);

/// Gravity vector of a slope α: g = (g sin α, −g cos α) (architecture.md conventions).
pub(super) fn gravity_vector(magnitude: f64, slope_deg: f64) -> (f64, f64) {
    let a = slope_deg.to_radians();
    (magnitude * a.sin(), -magnitude * a.cos())
}

/// Builds the single-phase solver of a gas-only case, or says why it cannot.
pub fn single_phase_solver(case: &Case) -> Result<SinglePhase, RunError> {
    let unsupported = |reason: &str| RunError::Unsupported {
        case: case.name.clone(),
        reason: reason.into(),
    };
    if !case.solids.is_empty() {
        return Err(unsupported(
            "has solids phases: the two-fluid model is not implemented yet (issue 7); only \
             single-phase gas cases run today",
        ));
    }
    let gas = case
        .gas
        .as_ref()
        .ok_or_else(|| unsupported("has neither gas nor solids"))?;
    if case.sidewalls.is_some() {
        return Err(unsupported(
            "has sidewalls, which act on solids (docs/model.md §8): two-fluid cases only",
        ));
    }
    if !gas.law.is_constant() {
        return Err(unsupported(
            "has an ideal gas (gas.law), which the two-fluid solver carries: the single-phase \
             solver's gas has a constant density",
        ));
    }
    let gravity = match case.gravity {
        Gravity::Constant { magnitude, slope } => gravity_vector(magnitude, slope),
        Gravity::TiltOnImpact { .. } => {
            return Err(unsupported(
                "tilts gravity on solids impact, which needs a solids phase",
            ));
        }
    };
    let grid = case.grid().map_err(|source| RunError::Mesh {
        case: case.name.clone(),
        source,
    })?;
    let b = &case.boundaries;
    let bcs = gas_sides(case, gas);
    let r = &case.numerics.relaxation;
    let settings = Settings {
        scheme: match case.numerics.convection {
            Convection::Upwind => Scheme::Upwind,
            Convection::Superbee => Scheme::Superbee,
        },
        relax_velocity: r.velocity,
        relax_pressure: r.pressure,
        ..Settings::default()
    };
    let fluid = Fluid {
        density: gas.density,
        viscosity: gas.viscosity,
    };
    let mut s = SinglePhase::new(grid, fluid, bcs, gravity, settings).map_err(|source| {
        RunError::Solver {
            case: case.name.clone(),
            source,
        }
    })?;
    // Initial state: uniform gas velocity; hydrostatic or uniform pressure.
    let (u0, v0) = case.initial.gas_velocity;
    s.u.iter_mut().for_each(|u| *u = u0);
    s.v.iter_mut().for_each(|v| *v = v0);
    let g = s.grid().clone();
    for j in 0..g.ny() {
        for i in 0..g.nx() {
            let (x, y) = g.cell_centre(i, j);
            s.p[g.cell_index(i, j)] = initial_gas_pressure(case, gas, gravity, None, &g, (x, y));
        }
    }
    zero_normal_velocity_on_walls(b, &g, &mut s.u, &mut s.v);
    Ok(s)
}

/// Zero normal velocity on the wall faces of one phase's face fields (u on x-faces, v on
/// y-faces); outlets keep theirs.
fn zero_normal_velocity_on_walls(b: &Sides<Boundary>, grid: &Grid, u: &mut [f64], v: &mut [f64]) {
    let (nx, ny) = (grid.nx(), grid.ny());
    let wall = |side: &Boundary| matches!(side, Boundary::Wall { .. });
    for j in 0..ny {
        for (i, side) in [(0, &b.west), (nx, &b.east)] {
            if wall(side) {
                u[i + (nx + 1) * j] = 0.0;
            }
        }
    }
    for i in 0..nx {
        for (j, side) in [(0, &b.south), (ny, &b.north)] {
            if wall(side) {
                v[i + nx * j] = 0.0;
            }
        }
    }
}

/// The fraction of the area of cell (i, j) inside `block` [-] (exact rectangle overlap).
pub(super) fn covered_fraction(grid: &Grid, i: usize, j: usize, block: &Block) -> f64 {
    let overlap = |faces: &[f64], k: usize, (lo, hi): (f64, f64)| {
        (faces[k + 1].min(hi) - faces[k].max(lo)).max(0.0) / (faces[k + 1] - faces[k])
    };
    overlap(grid.x.faces(), i, block.x) * overlap(grid.y.faces(), j, block.y)
}

/// Builds the two-fluid solver of a case with solids, or says what it still lacks.
pub fn two_fluid_solver(case: &Case) -> Result<TwoFluid, RunError> {
    let unsupported = |reason: String| RunError::Unsupported {
        case: case.name.clone(),
        reason,
    };
    let gas = case.gas.as_ref().ok_or_else(|| {
        unsupported("a dry case (no gas) is not supported by the two-fluid solver yet".into())
    })?;
    if !matches!(case.models.kinetic_theory, KineticTheory::Lun1984 { .. }) {
        return Err(unsupported(
            "only the Lun 1984 kinetic theory with the θ PDE is implemented".into(),
        ));
    }
    // e.g. Schaeffer: one phase only (docs/model.md §2.4.1)
    if let Some(max) = case.models.friction.max_solids_phases() {
        if case.solids.len() > max {
            return Err(unsupported(format!(
                "{} friction with more than {max} solids phase(s) is not implemented",
                case.models.friction.name()
            )));
        }
    }
    let grid = case.grid().map_err(|source| RunError::Mesh {
        case: case.name.clone(),
        source,
    })?;
    let b = &case.boundaries;
    let gas_walls = gas_sides(case, gas);
    let walls = Sides {
        west: solids_side(case, &b.west)?,
        east: solids_side(case, &b.east)?,
        south: solids_side(case, &b.south)?,
        north: solids_side(case, &b.north)?,
    };
    let specs = solids_specs(case, gas, &walls);
    let gravity = match case.gravity {
        Gravity::Constant { magnitude, slope } => gravity_vector(magnitude, slope),
        Gravity::TiltOnImpact { magnitude, .. } => gravity_vector(magnitude, 0.0),
    };
    let settings = two_fluid_settings(case);
    let fluid = Fluid {
        density: gas.density,
        viscosity: gas.viscosity,
    };
    let mut tf = TwoFluid::new(grid.clone(), fluid, gas_walls, specs, gravity, settings)
        .map_err(|e| unsupported(format!("setting up the two-fluid solver: {e}")))?;
    if !gas.law.is_constant() {
        tf.set_gas_law(gas.equation_of_state())
            .map_err(|e| unsupported(format!("gas.law: {e}")))?;
    }
    tf.set_sidewalls(super::sidewalls::sidewalls(case)?);
    // a bent floor acts with the tilted gravity: from the start under a constant one, at
    // the tilt otherwise (`PendingTilt`)
    let bent = bent_floor(case)?.filter(|_| matches!(case.gravity, Gravity::Constant { .. }));
    fill_initial_state(&mut tf, case, gas, (gravity, bent.as_ref()), &grid);
    tf.set_bent_floor(bent);
    let gas = tf.state_mut().gas_mut();
    zero_normal_velocity_on_walls(b, &grid, &mut gas.u, &mut gas.v);
    for s in tf.state_mut().phases_mut() {
        zero_normal_velocity_on_walls(b, &grid, &mut s.u, &mut s.v);
    }
    Ok(tf)
}

/// The solids wall model of boundary `b`, `None` on an outlet (the solids then see the gas's
/// outlet, [`SolidsSpec::walls`]).
fn solids_side(case: &Case, b: &Boundary) -> Result<Option<SolidsWallModel>, RunError> {
    match b {
        Boundary::PressureOutlet { .. } => Ok(None),
        Boundary::Wall { solids, .. } => {
            solids.model().map(Some).map_err(|e| RunError::Unsupported {
                case: case.name.clone(),
                reason: format!("{e}"),
            })
        }
    }
}

/// The solids phases of a two-fluid case with the solids wall models `walls` of its sides.
fn solids_specs(
    case: &Case,
    gas: &runout_case::Gas,
    walls: &Sides<Option<SolidsWallModel>>,
) -> Vec<SolidsSpec> {
    case.solids
        .iter()
        .map(|m| SolidsSpec {
            params: ClosureParams {
                particles: Particles {
                    diameter: m.diameter,
                    density: m.density,
                    restitution: m.restitution,
                },
                gas: Gas {
                    density: gas.density,
                    viscosity: gas.viscosity,
                },
                friction: FrictionParams::new(
                    m.max_packing,
                    m.friction_min_packing,
                    m.internal_friction_angle,
                ),
                radial: case.models.radial_distribution,
                friction_model: case.models.friction,
                drag: case.models.drag,
            },
            eps_max: m.max_packing,
            walls: walls.clone(),
        })
        .collect()
}

/// The iteration settings of a two-fluid case.
fn two_fluid_settings(case: &Case) -> TwoFluidSettings {
    let r = &case.numerics.relaxation;
    TwoFluidSettings {
        scheme: match case.numerics.convection {
            Convection::Upwind => Scheme::Upwind,
            Convection::Superbee => Scheme::Superbee,
        },
        relax_velocity: r.velocity,
        solids_relaxation_base: r.solids_velocity_base.map(|base| match base {
            runout_case::SolidsRelaxationBase::Centre => RelaxationBase::Centre,
            runout_case::SolidsRelaxationBase::OwnPart => RelaxationBase::OwnPart,
        }),
        relax_pressure: r.pressure,
        relax_eps: r.eps_s,
        relax_theta: r.theta,
        relax_wall_closures: r.wall_closures,
        relax_wall_closures_oscillating_only: r.wall_closures_at
            == runout_case::WallRelaxationScope::Oscillating,
        freeze_cycling_dilute_class: case.numerics.dilute_cells
            == runout_case::DiluteCellClass::FrozenWhenCycling,
        exact_solids_continuity: case.numerics.exact_solids_mass,
        detect_stall: case.run.tolerances.detect_stall,
        pooled_momentum_residual: case.run.tolerances.momentum_residual
            == runout_case::MomentumResidual::Pooled,
        momentum_form: match case.numerics.momentum_form {
            runout_case::MomentumForm::ContinuitySubtracted => MomentumForm::ContinuitySubtracted,
            runout_case::MomentumForm::Conservative => MomentumForm::Conservative,
        },
    }
}

/// The initial state of a two-fluid case: the gas velocity and pressure, the background θ,
/// then each block in order (cells filled by their centre or by their covered fraction).
fn fill_initial_state(
    tf: &mut TwoFluid,
    case: &Case,
    gas: &runout_case::Gas,
    (gravity, bent): (GravityVector, Option<&BentFloor>),
    grid: &Grid,
) {
    let (nx, ny) = (grid.nx(), grid.ny());
    // each polygon's corners in the solver's (x, y), as validation found them
    let polygons: Vec<_> = case
        .initial
        .polygons
        .iter()
        .filter_map(|p| case.polygon_in_domain(p).ok().map(|corners| (p, corners)))
        .collect();
    let (u0, v0) = case.initial.gas_velocity;
    let state = tf.state_mut();
    state.gas_mut().u.iter_mut().for_each(|u| *u = u0);
    state.gas_mut().v.iter_mut().for_each(|v| *v = v0);
    for s in state.phases_mut() {
        s.theta
            .iter_mut()
            .for_each(|t| *t = case.initial.theta.max(runout_closures::guards::THETA_SMALL));
    }
    for j in 0..ny {
        for i in 0..nx {
            let (x, y) = grid.cell_centre(i, j);
            let k = i + nx * j;
            state.gas_mut().p[k] = initial_gas_pressure(case, gas, gravity, bent, grid, (x, y));
            for block in &case.initial.regions {
                // the part of the cell the block fills: all or nothing by the centre, or
                // the covered fraction of its area
                let covered = match block.fill {
                    Fill::CellCentre => {
                        let inside =
                            x >= block.x.0 && x <= block.x.1 && y >= block.y.0 && y <= block.y.1;
                        if inside {
                            1.0
                        } else {
                            0.0
                        }
                    }
                    Fill::CoveredFraction => covered_fraction(grid, i, j, block),
                };
                fill_cell(state, (i, j, nx), covered, &block.solids);
            }
            for (polygon, corners) in polygons.iter() {
                let (xf, yf) = (grid.x.faces(), grid.y.faces());
                let area = (xf[i + 1] - xf[i]) * (yf[j + 1] - yf[j]);
                let covered =
                    polygon::area_inside(corners, (xf[i], xf[i + 1]), (yf[j], yf[j + 1])) / area;
                fill_cell(state, (i, j, nx), covered, &polygon.solids);
            }
        }
    }
}

/// Cell (i, j) of a grid `nx` wide takes the solids state `solids` over the fraction
/// `covered` of its area: all of it where it is covered whole, else the covered part of
/// what it held replaced (θ weighted by εs); the faces of a cell it covers at all take its
/// velocity.
fn fill_cell(
    state: &mut runout_solver::two_fluid::State,
    (i, j, nx): (usize, usize, usize),
    covered: f64,
    solids: &[runout_case::BlockSolids],
) {
    if covered <= 0.0 {
        return;
    }
    let k = i + nx * j;
    for (m, bs) in solids.iter().enumerate() {
        let theta_b = bs.theta.max(runout_closures::guards::THETA_SMALL);
        let eps = if covered >= 1.0 {
            state.solids_mut(m).theta[k] = theta_b;
            bs.eps_s
        } else {
            // the region replaces the covered part of what the cell held
            let s = state.solids_mut(m);
            let kept = s.eps()[k] * (1.0 - covered);
            let added = bs.eps_s * covered;
            if kept + added > 0.0 {
                s.theta[k] = (kept * s.theta[k] + added * theta_b) / (kept + added);
            }
            kept + added
        };
        state.set_solids_fraction(m, k, eps);
        let s = state.solids_mut(m);
        for f in [i + (nx + 1) * j, i + 1 + (nx + 1) * j] {
            s.u[f] = bs.velocity.0;
        }
        for f in [k, k + nx] {
            s.v[f] = bs.velocity.1;
        }
    }
}
