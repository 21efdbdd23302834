//! Set-up of the two-fluid solver: the sparsity patterns of its equations (wall nodes fixed,
//! docs/model.md §3.1; a periodic column, the pressure pinned where no side is open,
//! docs/model.md §4.6), its linear solvers and their tolerances (docs/model.md §4.13), and
//! the work storage of every phase, allocated once.

use runout_linsolve::{
    build, ActiveBox, LinearSolver, LinearSolverKind, MultigridParams, Pattern, Stencil5,
};
use runout_mesh::{Grid, Sides};

use super::diagnostics::Diagnostics;
use super::model::Model;
use super::{
    lin, IterationFlags, PhaseCoefficients, PhaseWallClosures, PhaseWork, Scene, SolidsSpec,
    Solvers, State, TwoFluid, TwoFluidError, TwoFluidSettings, Workspace, MAX_SOLIDS_PHASES,
    PRESSURE_COARSEST_CELLS, PRESSURE_RTOL, THETA_SMALL,
};
use crate::direction::{X, Y};
use crate::node_block::{pressure_pattern, wall_pattern};
use crate::single_phase::{Fluid, SideBc};
use crate::transport::FaceData;
use runout_closures::GasLaw;

impl TwoFluid {
    /// Sets up the solver: gas at rest, εs = 0, θ = θ_small, zero pressure; the caller fills
    /// the initial fields. Refuses a phase whose sides are not walls exactly where the gas's
    /// are ([`TwoFluidError::SolidsSideMismatch`]).
    pub fn new(
        grid: Grid,
        gas: Fluid,
        gas_walls: Sides<SideBc>,
        solids_specs: Vec<SolidsSpec>,
        gravity: (f64, f64),
        settings: TwoFluidSettings,
    ) -> Result<Self, TwoFluidError> {
        if solids_specs.len() > MAX_SOLIDS_PHASES {
            return Err(TwoFluidError::TooManyPhases(solids_specs.len()));
        }
        check_solids_sides(&gas_walls, &solids_specs)?;
        let (nx, ny) = (grid.nx(), grid.ny());
        let scene = Scene::of(&grid, &solids_specs, &settings, None);
        let n = nx * ny;
        let outlet = |b: &SideBc| !matches!(b, SideBc::Wall(_));
        if grid.y.is_periodic() {
            return Err(TwoFluidError::PeriodicY);
        }
        let periodic = grid.periodic_x();
        if periodic && (nx != 1 || outlet(&gas_walls.west) || outlet(&gas_walls.east)) {
            return Err(TwoFluidError::PeriodicColumn(nx));
        }
        let (pu, pv, pp, pressure_pinned) = gas_patterns(&grid, &gas_walls)?;
        let pc = Pattern::new(nx, ny).map_err(lin("cell pattern"))?;
        let [solver_u, solver_v, solver_p, solver_eps, solver_eps_fallback, solver_theta] =
            linear_solvers([&pu, &pv, &pp, &pc])?;
        let m = solids_specs.len();
        let coefficients = vec![PhaseCoefficients::new((nx, ny)); m];
        let wall_closures = vec![PhaseWallClosures::new((nx, ny)); m];
        let work = vec![PhaseWork::new((nx, ny), &pu, &pv, &pc); m];
        let densities = solids_specs.iter().map(|s| s.params.particles.density);
        Ok(TwoFluid {
            state: State::new((nx, ny), gas.density, densities, THETA_SMALL),
            coefficients,
            wall_closures,
            workspace: Workspace {
                d_u: vec![0.0; (nx + 1) * ny],
                d_v: vec![0.0; nx * (ny + 1)],
                p_corr: vec![0.0; n],
                imbalance: vec![0.0; n],
                u_faces: FaceData::zeros(nx + 1, ny),
                v_faces: FaceData::zeros(nx, ny + 1),
                c_faces: FaceData::zeros(nx, ny),
                gas_fluxes: Default::default(),
                a_ug: Stencil5::new(pu),
                a_vg: Stencil5::new(pv),
                a_p: Stencil5::new(pp),
                solids: work,
                solvers: Solvers {
                    u: solver_u,
                    v: solver_v,
                    p: solver_p,
                    eps: solver_eps,
                    eps_fallback: solver_eps_fallback,
                    theta: solver_theta,
                },
                flags: IterationFlags {
                    pressure_pinned,
                    rebuild_preconditioners: true,
                    closures_fresh: false,
                    theta_class_fresh: true,
                },
            },
            diagnostics: Diagnostics::default(),
            model: Model {
                gas_viscosity: vec![gas.viscosity; n],
                grid,
                gas,
                gas_walls,
                gas_inflow: Sides::all(Vec::new()),
                solids_specs,
                gravity,
                bent_floor: None,
                gate_faces: Vec::new(),
                settings,
                scene,
                sidewalls: None,
            },
        })
    }
}

impl TwoFluid {
    /// Sets the gas's equation of state (docs/model.md §1.4; a constant density, the one the
    /// solver is built with, unless this is called). A compressible gas's pressure level is
    /// set by its mass, so P' is no longer pinned in a closed domain (docs/model.md §4.6).
    /// Refused: a density of the law that is not finite and positive at the reference
    /// pressure of 1 bar.
    pub fn set_gas_law(&mut self, law: GasLaw) -> Result<(), TwoFluidError> {
        let rho = law.density(1e5);
        if !(rho.is_finite() && rho > 0.0) {
            return Err(TwoFluidError::Shape(format!(
                "gas law {law:?}: density {rho} kg/m³ at 1 bar"
            )));
        }
        if law.is_compressible() && self.workspace.flags.pressure_pinned {
            let (nx, ny) = (self.model.grid.nx(), self.model.grid.ny());
            let pp = Pattern::new(nx, ny).map_err(lin("p' pattern"))?;
            self.workspace
                .solvers
                .p
                .set_pattern(&pp)
                .map_err(lin("p'"))?;
            self.workspace.a_p = Stencil5::new(pp);
            self.workspace.flags.pressure_pinned = false;
            self.workspace.flags.rebuild_preconditioners = true;
        }
        self.state.set_gas_law(law);
        Ok(())
    }
}

/// Each phase's solids side is a wall exactly where the gas's is ([`SolidsSpec::walls`]).
fn check_solids_sides(
    gas_walls: &Sides<SideBc>,
    solids_specs: &[SolidsSpec],
) -> Result<(), TwoFluidError> {
    let kind = |wall: bool| if wall { "a wall" } else { "an outlet" };
    for (m, spec) in solids_specs.iter().enumerate() {
        for (side, gas) in gas_walls.iter() {
            let (solids_wall, gas_wall) =
                (spec.wall(side).is_some(), matches!(gas, SideBc::Wall(_)));
            if solids_wall != gas_wall {
                return Err(TwoFluidError::SolidsSideMismatch {
                    phase: m + 1,
                    side: side.name(),
                    solids: kind(solids_wall),
                    gas: kind(gas_wall),
                });
            }
        }
    }
    Ok(())
}

/// The gas's u, v and P' patterns ([`wall_pattern`], [`pressure_pattern`]) and whether P'
/// is pinned.
fn gas_patterns(
    grid: &Grid,
    gas_walls: &Sides<SideBc>,
) -> Result<(Pattern, Pattern, Pattern, bool), TwoFluidError> {
    let pu = wall_pattern::<X>(grid, gas_walls).map_err(lin("u pattern"))?;
    let pv = wall_pattern::<Y>(grid, gas_walls).map_err(lin("v pattern"))?;
    let (pp, pressure_pinned) = pressure_pattern(grid, gas_walls).map_err(lin("p' pattern"))?;
    Ok((pu, pv, pp, pressure_pinned))
}

/// The linear solvers of u, v, P', ε', ε' (fallback) and θ on the u, v, P' and cell
/// patterns.
fn linear_solvers(
    [pu, pv, pp, pc]: [&Pattern; 4],
) -> Result<[Box<dyn LinearSolver>; 6], TwoFluidError> {
    // Momentum and θ are solved tighter than MFIX's LEQ_TOL = 1e-4 (docs/model.md §4.13):
    // with 1e-4 the normalised residuals of the outer iteration stall near 1e-4, the
    // size of the linear solves' own error, and θ's tolerance (1e-4) is never met.
    let transport = LinearSolverKind::transport_default(1e-8, 100);
    // Each solver of u, v, ε' and θ solves the rectangle of rows with links only
    // (`ActiveBox`): the dilute solids rows outside it read a_P φ = b (docs/model.md §2.7,
    // §4.8) and are solved exactly; the gas's rows are linked everywhere and solved whole.
    let active =
        |kind: &LinearSolverKind| -> Box<dyn LinearSolver> { Box::new(ActiveBox::new(kind)) };
    let mut solver_u = active(&transport);
    let mut solver_v = active(&transport);
    // The gas pressure correction is solved to 1e-2: its error is removed by the next outer
    // iteration like any other, and on family M (coarse) the results agree with a 1e-4
    // solve to 6 digits at the same outer-iteration count while the solve costs half
    // (docs/history/performance-log.md, "Two-fluid model: family M against MFIX's cost"). MFIX's
    // own pressure solves stop near 1e-1 (20 line-relaxed BiCGSTAB iterations,
    // docs/model.md §4.13).
    let mut solver_p = build(&LinearSolverKind::MultigridCg(MultigridParams {
        rtol: PRESSURE_RTOL,
        max_iter: 20,
        coarsest_max_cells: PRESSURE_COARSEST_CELLS,
        ..MultigridParams::default()
    }));
    let mut solver_eps = active(&LinearSolverKind::volume_fraction_default());
    let mut solver_eps_fallback = active(&LinearSolverKind::transport_default(1e-4, 20));
    let mut solver_theta = active(&transport);
    solver_u.set_pattern(pu).map_err(lin("u"))?;
    solver_v.set_pattern(pv).map_err(lin("v"))?;
    solver_p.set_pattern(pp).map_err(lin("p'"))?;
    solver_eps.set_pattern(pc).map_err(lin("eps'"))?;
    solver_eps_fallback
        .set_pattern(pc)
        .map_err(lin("eps' (fallback)"))?;
    solver_theta.set_pattern(pc).map_err(lin("theta"))?;
    Ok([
        solver_u,
        solver_v,
        solver_p,
        solver_eps,
        solver_eps_fallback,
        solver_theta,
    ])
}
