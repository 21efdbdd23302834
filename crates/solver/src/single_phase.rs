//! Incompressible single-phase SIMPLE on a stretched staggered grid (docs/model.md §4).
//!
//! u lives on x-faces ((nx+1) × ny, faces i = 0 and nx on the domain ends), v on y-faces
//! (nx × (ny+1)), p at cell centres. Each outer iteration: momentum predictor with the
//! current pressure (upwind or Superbee by deferred correction, implicit Euler, Patankar
//! under-relaxation, docs/model.md §4.2–4.4, §4.10), pressure correction from discrete
//! continuity (§4.6 with one phase), velocity and pressure correction, residuals (§4.11).
//!
//! Walls impose zero normal velocity and, for the tangential component, the eliminated
//! Robin closure of docs/model.md §3.2 ([`runout_walls::RobinFace`]) with the distance from the fluid
//! centre to its ghost (the first cell's width, §3.1). An outlet holds the pressure on its
//! face and has zero normal gradient of both velocity components.

use runout_closures::FaceMean;
use runout_linsolve::{build, LinSolveError, LinearSolver, LinearSolverKind, Stencil5};
use runout_mesh::{Beyond, Grid, Sides};

use crate::direction::{Direction, X, Y};
use crate::momentum::{assemble, fixed_row, neighbour_sum, Context, MomentumForm, PhaseFields};
use crate::node_block::{correct_velocity, pressure_pattern, wall_pattern};
pub use crate::side::SideBc;
use crate::staggered::Component;
use crate::transport::{FaceData, Scheme};

/// Constant fluid properties.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fluid {
    /// density ρ [kg m⁻³]
    pub density: f64,
    /// dynamic viscosity μ [Pa s]
    pub viscosity: f64,
}

/// Iteration settings (MFIX defaults, docs/model.md §4.10–4.11).
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// convection scheme
    pub scheme: Scheme,
    /// momentum under-relaxation (`UR_FAC(3..4)`)
    pub relax_velocity: f64,
    /// pressure under-relaxation (`UR_FAC(1)`)
    pub relax_pressure: f64,
    /// linear solver for the momentum equations
    pub momentum_solver: LinearSolverKind,
    /// linear solver for the pressure correction
    pub pressure_solver: LinearSolverKind,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            scheme: Scheme::Upwind,
            relax_velocity: 0.5,
            relax_pressure: 0.8,
            momentum_solver: LinearSolverKind::transport_default(1e-8, 200),
            pressure_solver: LinearSolverKind::pressure_default(),
        }
    }
}

/// Errors of the single-phase solver.
#[derive(Debug, thiserror::Error)]
pub enum SolverError {
    /// A linear solve failed.
    #[error("{equation}: {source}")]
    Linear {
        /// which equation
        equation: &'static str,
        /// the solver error
        source: LinSolveError,
    },
    /// A periodic axis: the single-phase solver has walls or outlets on every side.
    #[error("the single-phase solver has no periodic axis")]
    Periodic,
    /// A non-finite value appeared.
    #[error("{equation}: non-finite value at node {node} after outer iteration {iteration}")]
    NonFinite {
        /// which equation
        equation: &'static str,
        /// linear node index
        node: usize,
        /// outer iteration
        iteration: usize,
    },
}

/// Normalised residuals of one outer iteration (docs/model.md §4.11).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Residuals {
    /// u momentum: Σ|b + Σ a_nb u_nb − a_P u_P| / Σ|a_P u_P| (before relaxation)
    pub u: f64,
    /// v momentum, same form
    pub v: f64,
    /// mean |mass imbalance| of the predicted velocities over the cells [kg s⁻¹ per m depth]
    pub mass: f64,
    /// u-face index (i + (nx+1) j) with the largest |u-momentum imbalance|
    pub worst_u: usize,
    /// v-face index (i + nx j) with the largest |v-momentum imbalance|
    pub worst_v: usize,
    /// cell index (i + nx j) with the largest |mass imbalance|
    pub worst_mass: usize,
}

/// Outcome of [`SinglePhase::step`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepOutcome {
    /// outer iterations used
    pub iterations: usize,
    /// whether the step converged (if not, the fields were restored)
    pub converged: bool,
    /// the last residual sum
    pub residual: f64,
    /// the residuals of the last outer iteration
    pub last: Residuals,
    /// the residual sums of the last (up to) [`HISTORY`] outer iterations, oldest first,
    /// unused slots NaN
    pub history: [f64; HISTORY],
}

/// Outer iterations kept in [`StepOutcome::history`].
pub const HISTORY: usize = 8;

/// Outcome of [`SinglePhase::solve_steady`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadyReport {
    /// outer iterations done
    pub iterations: usize,
    /// residuals of the last iteration
    pub residuals: Residuals,
    /// whether the tolerance was met
    pub converged: bool,
}

/// The single-phase solver with all its work storage (allocated once).
pub struct SinglePhase {
    grid: Grid,
    fluid: Fluid,
    bcs: Sides<SideBc>,
    gravity: (f64, f64),
    settings: Settings,
    /// u on x-faces, index i + (nx+1) j
    pub u: Vec<f64>,
    /// v on y-faces, index i + nx j
    pub v: Vec<f64>,
    /// pressure at cell centres, index i + nx j [Pa]
    pub p: Vec<f64>,
    u_old: Vec<f64>,
    v_old: Vec<f64>,
    d_u: Vec<f64>,
    d_v: Vec<f64>,
    p_corr: Vec<f64>,
    /// ρ, 1 and μ per cell: the phase fields of a single incompressible phase
    density_cells: Vec<f64>,
    ones: Vec<f64>,
    viscosity_cells: Vec<f64>,
    u_faces: FaceData,
    v_faces: FaceData,
    a_u: Stencil5,
    a_v: Stencil5,
    a_p: Stencil5,
    solver_u: Box<dyn LinearSolver>,
    solver_v: Box<dyn LinearSolver>,
    solver_p: Box<dyn LinearSolver>,
    pressure_pinned: bool,
}

impl SinglePhase {
    /// Sets up the solver for `grid` with fluid at rest and zero pressure.
    pub fn new(
        grid: Grid,
        fluid: Fluid,
        bcs: Sides<SideBc>,
        gravity: (f64, f64),
        settings: Settings,
    ) -> Result<Self, SolverError> {
        if grid.x.is_periodic() || grid.y.is_periodic() {
            return Err(SolverError::Periodic);
        }
        let (nx, ny) = (grid.nx(), grid.ny());
        let lin = |equation| move |source| SolverError::Linear { equation, source };
        let pu = wall_pattern::<X>(&grid, &bcs).map_err(lin("u"))?;
        let pv = wall_pattern::<Y>(&grid, &bcs).map_err(lin("v"))?;
        let (pp, pressure_pinned) = pressure_pattern(&grid, &bcs).map_err(lin("p'"))?;
        let mut solver_u = build(&settings.momentum_solver);
        let mut solver_v = build(&settings.momentum_solver);
        let mut solver_p = build(&settings.pressure_solver);
        solver_u.set_pattern(&pu).map_err(lin("u"))?;
        solver_v.set_pattern(&pv).map_err(lin("v"))?;
        solver_p.set_pattern(&pp).map_err(lin("p'"))?;
        Ok(SinglePhase {
            u: vec![0.0; (nx + 1) * ny],
            v: vec![0.0; nx * (ny + 1)],
            p: vec![0.0; nx * ny],
            u_old: vec![0.0; (nx + 1) * ny],
            v_old: vec![0.0; nx * (ny + 1)],
            d_u: vec![0.0; (nx + 1) * ny],
            d_v: vec![0.0; nx * (ny + 1)],
            p_corr: vec![0.0; nx * ny],
            density_cells: vec![fluid.density; nx * ny],
            ones: vec![1.0; nx * ny],
            viscosity_cells: vec![fluid.viscosity; nx * ny],
            u_faces: FaceData::zeros(nx + 1, ny),
            v_faces: FaceData::zeros(nx, ny + 1),
            a_u: Stencil5::new(pu),
            a_v: Stencil5::new(pv),
            a_p: Stencil5::new(pp),
            solver_u,
            solver_v,
            solver_p,
            pressure_pinned,
            grid,
            fluid,
            bcs,
            gravity,
            settings,
        })
    }

    /// The grid.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// Gravity (g_x, g_y) [m s⁻²].
    pub fn gravity(&self) -> (f64, f64) {
        self.gravity
    }

    /// Sets gravity (a schedule may tilt it during a run).
    pub fn set_gravity(&mut self, gravity: (f64, f64)) {
        self.gravity = gravity;
    }

    /// The fluid.
    pub fn fluid(&self) -> Fluid {
        self.fluid
    }

    /// Cell-centred velocities (u, v) interleaved, the mean of the two faces of each cell
    /// (MFIX AVG_X_E, docs/model.md §4.1), into `out` (length 2 · cells).
    pub fn centre_velocities(&self, out: &mut [f64]) {
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        for j in 0..ny {
            for i in 0..nx {
                let k = i + nx * j;
                out[2 * k] = 0.5 * (self.u[i + (nx + 1) * j] + self.u[i + 1 + (nx + 1) * j]);
                out[2 * k + 1] = 0.5 * (self.v[k] + self.v[k + nx]);
            }
        }
    }

    /// Stores the current fields as the old time level.
    pub fn begin_step(&mut self) {
        self.u_old.copy_from_slice(&self.u);
        self.v_old.copy_from_slice(&self.v);
    }

    /// The state the next step reads: u, v, p and the last d coefficients and pressure
    /// correction (issue 21's checkpoints; see [`crate::state`]).
    pub fn save_state(&self) -> crate::state::SolverState {
        let mut st = crate::state::SolverState::default();
        for (name, values) in [
            ("u", &self.u),
            ("v", &self.v),
            ("p", &self.p),
            ("d_u", &self.d_u),
            ("d_v", &self.d_v),
            ("p_corr", &self.p_corr),
        ] {
            st.put(name, values);
        }
        st
    }

    /// Puts back a state saved by [`SinglePhase::save_state`] on the same grid.
    pub fn load_state(
        &mut self,
        st: &crate::state::SolverState,
    ) -> Result<(), crate::state::StateError> {
        for (name, values) in [
            ("u", &mut self.u),
            ("v", &mut self.v),
            ("p", &mut self.p),
            ("d_u", &mut self.d_u),
            ("d_v", &mut self.d_v),
            ("p_corr", &mut self.p_corr),
        ] {
            st.take(name, values)?;
        }
        Ok(())
    }

    /// Restores the fields of the start of the step (after a failed step).
    pub fn restore_step(&mut self) {
        self.u.copy_from_slice(&self.u_old);
        self.v.copy_from_slice(&self.v_old);
    }

    /// One SIMPLE outer iteration with time step `dt` (`f64::INFINITY` for a steady
    /// iteration). Returns the residuals of the momentum predictor and of continuity.
    pub fn outer_iteration(&mut self, dt: f64, iteration: usize) -> Result<Residuals, SolverError> {
        let [cu, cv] = Component::of_grid(&self.grid);
        let (ru, worst_u) = self.momentum(cu, dt)?;
        let (rv, worst_v) = self.momentum(cv, dt)?;
        let (mass, worst_mass) = self.pressure_correction()?;
        for (name, field) in [("u", &self.u), ("v", &self.v), ("p", &self.p)] {
            if let Some(node) = field.iter().position(|x| !x.is_finite()) {
                return Err(SolverError::NonFinite {
                    equation: name,
                    node,
                    iteration,
                });
            }
        }
        Ok(Residuals {
            u: ru,
            v: rv,
            mass,
            worst_u,
            worst_v,
            worst_mass,
        })
    }

    /// Relaxes the assembled system and returns the pre-relaxation residual normalised as
    /// MFIX does (docs/model.md §4.11): Σ|b + Σ a_nb φ_nb − a_P φ_P| / Σ|a_P| |vel_P|, where
    /// |vel_P| is the speed from both staggered components stored at the same (i, j).
    fn finish_momentum(
        a: &mut Stencil5,
        phi: &[f64],
        speed: impl Fn(usize) -> f64,
        relax: f64,
    ) -> (f64, usize) {
        let mut num = 0.0;
        let mut den = 0.0;
        let (mut worst, mut worst_abs) = (0, -1.0);
        for k in 0..phi.len() {
            if a.pattern().fixed_mask()[k] {
                continue;
            }
            let r = (neighbour_sum(a, phi, k) - a.a_p[k] * phi[k]).abs();
            if r > worst_abs {
                (worst, worst_abs) = (k, r);
            }
            num += r;
            den += a.a_p[k].abs() * speed(k);
            // Patankar under-relaxation (docs/model.md §4.10)
            let ap = a.a_p[k] / relax;
            a.b[k] += (1.0 - relax) * ap * phi[k];
            a.a_p[k] = ap;
        }
        (if den > 0.0 { num / den } else { num }, worst)
    }

    /// The momentum predictor of component `c` (u or v) with the current pressure: the
    /// assembly (docs/model.md §4.4), the residual and Patankar relaxation (§4.10–4.11), the
    /// d coefficients of the pressure correction (§4.6) and the solve.
    fn momentum(&mut self, c: Component, dt: f64) -> Result<(f64, usize), SolverError> {
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        let (dx, dy) = (self.grid.x.widths(), self.grid.y.widths());
        let ctx = Context {
            grid: &self.grid,
            bcs: &self.bcs,
            gravity: self.gravity,
            bent_floor: None,
            dt,
            scheme: self.settings.scheme,
            gas_pressure: &self.p,
            wall_faces: None,
            form: MomentumForm::ContinuitySubtracted,
        };
        let phase = PhaseFields {
            bulk_density: &self.density_cells,
            bulk_density_old: &self.density_cells,
            volume_fraction: &self.ones,
            viscosity: &self.viscosity_cells,
            viscosity_mean: FaceMean::Harmonic,
            solids_pressure: None,
            plastic_pressure: None,
            explicit_source: None,
            skip: None,
            velocity_along: None,
        };
        let (old, faces, a) = c.pick(
            (&self.u_old, &mut self.u_faces, &mut self.a_u),
            (&self.v_old, &mut self.v_faces, &mut self.a_v),
        );
        assemble(&ctx, &phase, c, &self.u, &self.v, old, faces, a);
        // the speed from both components stored at the same (i, j), the other one's node
        // clamped to its block (docs/model.md §4.11)
        let (phi, other) = c.pick((&self.u, &self.v), (&self.v, &self.u));
        let speed = |k: usize| {
            let (i, j) = (k % c.mx, k / c.mx);
            let (i, j, other_mx) = c.pick((i.min(nx - 1), j, nx), (i, j.min(ny - 1), nx + 1));
            phi[k].hypot(other[i + other_mx * j])
        };
        let r = Self::finish_momentum(a, phi, speed, self.settings.relax_velocity);
        let d = c.pick(&mut self.d_u, &mut self.d_v);
        for k in 0..d.len() {
            d[k] = if a.pattern().fixed_mask()[k] {
                0.0
            } else {
                c.face_area(k % c.mx, k / c.mx, dx, dy) / a.a_p[k]
            };
        }
        let (phi, solver) = c.pick(
            (&mut self.u, &mut self.solver_u),
            (&mut self.v, &mut self.solver_v),
        );
        solver
            .setup_and_solve(a, phi)
            .map_err(|source| SolverError::Linear {
                equation: c.pick("u momentum", "v momentum"),
                source,
            })?;
        Ok(r)
    }

    /// Pressure correction from cell continuity (docs/model.md §4.6 for one incompressible
    /// phase); corrects u, v and p. Returns the mean |mass imbalance| before correction.
    fn pressure_correction(&mut self) -> Result<(f64, usize), SolverError> {
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        let rho = self.fluid.density;
        let dx = self.grid.x.widths();
        let dy = self.grid.y.widths();
        let a = &mut self.a_p;
        let mut imbalance = 0.0;
        let (mut worst, mut worst_abs) = (0, -1.0);
        for j in 0..ny {
            for i in 0..nx {
                let k = i + nx * j;
                let (kw, ke) = (i + (nx + 1) * j, i + 1 + (nx + 1) * j);
                let (ks, kn) = (i + nx * j, i + nx * (j + 1));
                let b =
                    rho * ((self.u[kw] - self.u[ke]) * dy[j] + (self.v[ks] - self.v[kn]) * dx[i]);
                imbalance += b.abs();
                if b.abs() > worst_abs {
                    (worst, worst_abs) = (k, b.abs());
                }
                if self.pressure_pinned && k == 0 {
                    fixed_row(a, k, 0.0);
                    continue;
                }
                let ce = rho * self.d_u[ke] * dy[j];
                let cw = rho * self.d_u[kw] * dy[j];
                let cn = rho * self.d_v[kn] * dx[i];
                let cs = rho * self.d_v[ks] * dx[i];
                // links to neighbour cells; a boundary face with a velocity unknown (an
                // outlet, where p' = 0 on the face) contributes only to a_P
                a.a_e[k] = if i + 1 < nx { ce } else { 0.0 };
                a.a_w[k] = if i > 0 { cw } else { 0.0 };
                a.a_n[k] = if j + 1 < ny { cn } else { 0.0 };
                a.a_s[k] = if j > 0 { cs } else { 0.0 };
                a.a_p[k] = ce + cw + cn + cs;
                a.b[k] = b;
            }
        }
        self.p_corr.iter_mut().for_each(|x| *x = 0.0);
        self.solver_p
            .setup_and_solve(a, &mut self.p_corr)
            .map_err(|source| SolverError::Linear {
                equation: "pressure correction",
                source,
            })?;
        // velocity correction with the full p', pressure with ω_p (docs/model.md §4.6)
        let pc = &self.p_corr;
        correct_velocity::<X>((nx, ny), pc, &self.d_u, &mut self.u);
        correct_velocity::<Y>((nx, ny), pc, &self.d_v, &mut self.v);
        let w = self.settings.relax_pressure;
        self.p.iter_mut().zip(pc).for_each(|(p, c)| *p += w * c);
        Ok((imbalance / (nx * ny) as f64, worst))
    }

    /// One implicit-Euler time step of size `dt`: outer iterations until the sum of the
    /// normalised residuals (momentum as in [`Residuals`], continuity relative to the first
    /// iteration's imbalance, docs/model.md §4.11) is at most `tol`, after at least two
    /// iterations. A step that does not converge within `max_iterations`, or whose sum
    /// exceeds `diverge`, is undone (fields restored) and reported as not converged, so the
    /// caller can retry with a smaller Δt (docs/model.md §4.12).
    pub fn step(
        &mut self,
        dt: f64,
        tol: f64,
        diverge: f64,
        max_iterations: usize,
    ) -> Result<StepOutcome, SolverError> {
        self.begin_step();
        let mut first_mass = None;
        let mut out = StepOutcome {
            iterations: 0,
            converged: false,
            residual: f64::INFINITY,
            last: Residuals::default(),
            history: [f64::NAN; HISTORY],
        };
        for it in 0..max_iterations {
            out.iterations = it + 1;
            let r = match self.outer_iteration(dt, it) {
                Ok(r) => r,
                Err(SolverError::NonFinite { .. }) => {
                    self.restore_step();
                    out.residual = f64::INFINITY;
                    return Ok(out);
                }
                Err(e) => return Err(e),
            };
            let norm = *first_mass.get_or_insert(if r.mass > f64::MIN_POSITIVE {
                r.mass
            } else {
                1.0
            });
            out.residual = r.u + r.v + r.mass / norm;
            out.last = r;
            out.history.rotate_left(1);
            out.history[HISTORY - 1] = out.residual;
            if it >= 1 && out.residual <= tol {
                out.converged = true;
                return Ok(out);
            }
            if it >= 1 && out.residual >= diverge {
                break;
            }
        }
        self.restore_step();
        Ok(out)
    }

    /// Where the largest residual of each equation lies: (equation, normalised residual,
    /// x, y of the node).
    pub fn locate_residual(&self, r: &Residuals) -> [(&'static str, f64, f64, f64); 3] {
        let nx = self.grid.nx();
        let (iu, ju) = (r.worst_u % (nx + 1), r.worst_u / (nx + 1));
        let (iv, jv) = (r.worst_v % nx, r.worst_v / nx);
        let (ic, jc) = (r.worst_mass % nx, r.worst_mass / nx);
        let (xu, yu) = self.grid.u_face_position(iu, ju);
        let (xv, yv) = self.grid.v_face_position(iv, jv);
        let (xc, yc) = self.grid.cell_centre(ic, jc);
        [
            ("u momentum", r.u, xu, yu),
            ("v momentum", r.v, xv, yv),
            ("continuity", r.mass, xc, yc),
        ]
    }

    /// Steady SIMPLE iterations (no transient term) until the momentum residuals sum to at
    /// most `tol` and the mean mass imbalance is at most `tol · mass_scale`.
    pub fn solve_steady(
        &mut self,
        max_iterations: usize,
        tol: f64,
        mass_scale: f64,
    ) -> Result<SteadyReport, SolverError> {
        self.begin_step();
        let mut last = Residuals::default();
        for it in 0..max_iterations {
            last = self.outer_iteration(f64::INFINITY, it)?;
            if it > 0 && last.u + last.v <= tol && last.mass <= tol * mass_scale {
                return Ok(SteadyReport {
                    iterations: it + 1,
                    residuals: last,
                    converged: true,
                });
            }
        }
        Ok(SteadyReport {
            iterations: max_iterations,
            residuals: last,
            converged: false,
        })
    }

    /// Net continuity imbalance of the current velocities, Σ over cells of
    /// |ρ (inflow − outflow)| [kg s⁻¹ per m depth].
    pub fn mass_imbalance(&self) -> f64 {
        let (nx, ny) = (self.grid.nx(), self.grid.ny());
        let dx = self.grid.x.widths();
        let dy = self.grid.y.widths();
        let mut total = 0.0;
        for j in 0..ny {
            for i in 0..nx {
                let (kw, ke) = (i + (nx + 1) * j, i + 1 + (nx + 1) * j);
                let (ks, kn) = (i + nx * j, i + nx * (j + 1));
                total += (self.fluid.density
                    * ((self.u[kw] - self.u[ke]) * dy[j] + (self.v[ks] - self.v[kn]) * dx[i]))
                    .abs();
            }
        }
        total
    }

    /// u interpolated bilinearly at (x, y) from its staggered nodes, with the wall face
    /// values of the Robin closure below the first and above the last row.
    pub fn u_at(&self, x: f64, y: f64) -> f64 {
        self.interpolate::<X>(&self.u, (x, y))
    }

    /// v interpolated bilinearly at (x, y), with wall face values at the two ends.
    pub fn v_at(&self, x: f64, y: f64) -> f64 {
        self.interpolate::<Y>(&self.v, (x, y))
    }

    /// Component `D`'s `phi` at point `xy`: linear along each node line across the
    /// direction (the wall face values at its two ends, docs/model.md §3.2), then linear
    /// between the two lines around the point.
    fn interpolate<D: Direction>(&self, phi: &[f64], xy: (f64, f64)) -> f64 {
        let nx = self.grid.nx();
        let (along, across) = (D::along(&self.grid), D::across(&self.grid));
        let (low_wall, high_wall) = D::walls(&self.bcs);
        let (n_a, n_b) = (along.len(), across.len());
        let widths = across.widths();
        // the positions across and the values on the node line a, walls included
        let line = |a: usize| -> (Vec<f64>, Vec<f64>) {
            let mut bs = vec![across.start()];
            let mut values = vec![face_value(low_wall, phi[D::node(a, 0, nx)], widths[0])];
            for (b, &c) in across.centres().iter().enumerate() {
                bs.push(c);
                values.push(phi[D::node(a, b, nx)]);
            }
            let last = phi[D::node(a, n_b - 1, nx)];
            bs.push(across.end());
            values.push(face_value(high_wall, last, widths[n_b - 1]));
            (bs, values)
        };
        let (pa, pb) = D::pick(xy, (xy.1, xy.0));
        let faces = along.faces();
        let a = faces.partition_point(|&f| f <= pa).clamp(1, n_a) - 1;
        let t = (pa - faces[a]) / (faces[a + 1] - faces[a]);
        let (bs, lo) = line(a);
        let (_, hi) = line(a + 1);
        (1.0 - t) * interp(&bs, &lo, pb) + t * interp(&bs, &hi, pb)
    }
}

fn face_value(bc: &SideBc, fluid_value: f64, delta: f64) -> f64 {
    match bc {
        SideBc::Wall(face) => face.face_value(fluid_value, delta),
        SideBc::Outlet(_) | SideBc::HydrostaticOutlet { .. } => fluid_value,
    }
}

/// Piecewise-linear interpolation in increasing abscissae, clamped at the ends
/// ([`runout_mesh::interpolate`] with [`Beyond::Clamp`]; a node line has its two walls).
fn interp(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    runout_mesh::interpolate(xs, ys, x, Beyond::Clamp).expect("a node line has samples")
}
