//! The decaying Taylor–Green vortex in a free-slip box as a manufactured unsteady solution
//! (orders in space and time), and the mass conservation of every converged step.

use super::*;

/// Density of the Taylor–Green runs [kg m⁻³].
pub const TG_DENSITY: f64 = 1.0;
/// Viscosity of the Taylor–Green runs [Pa s].
pub const TG_VISCOSITY: f64 = 0.05;
/// End time of the Taylor–Green runs [s].
pub const TG_END_TIME: f64 = 0.2;
/// Convergence tolerance of every Taylor–Green step (sum of the normalised residuals,
/// docs/model.md §4.11). Far below the differences the orders are measured from (≥ 1e-5);
/// 1e-11 stalls at the round-off floor of the continuity residual once Δt ≤ 0.005 on 32².
pub const TG_STEP_TOLERANCE: f64 = 1e-10;

/// The decaying Taylor–Green vortex on [0, 1]², an exact Navier–Stokes solution:
/// u = sin(πx) cos(πy) F, v = −cos(πx) sin(πy) F, p = −ρF²/4 (cos 2πx + cos 2πy),
/// F = exp(−2π²νt). Normal velocity and tangential stress vanish on all sides, so
/// free-slip walls (zero-gradient Robin closure, docs/model.md §3.2) are exact. Returns (u, v, p).
pub fn taylor_green_exact(x: f64, y: f64, t: f64) -> (f64, f64, f64) {
    let f = (-2.0 * PI * PI * TG_VISCOSITY / TG_DENSITY * t).exp();
    (
        (PI * x).sin() * (PI * y).cos() * f,
        -(PI * x).cos() * (PI * y).sin() * f,
        -TG_DENSITY * f * f / 4.0 * ((2.0 * PI * x).cos() + (2.0 * PI * y).cos()),
    )
}

/// One Taylor–Green integration to [`TG_END_TIME`].
#[derive(Clone, Debug, PartialEq)]
pub struct TaylorGreenRun {
    /// the grid
    pub grid: Grid,
    /// time steps
    pub steps: usize,
    /// u on the x-faces at the end, index i + (n+1) j
    pub u: Vec<f64>,
    /// outer iterations over all steps
    pub outer_iterations: usize,
    /// wall time [s]
    pub wall_time: f64,
    /// net continuity imbalance after each converged step relative to the flow through
    /// the domain ([`mass_ratio`])
    pub mass_ratios: Vec<f64>,
}

impl TaylorGreenRun {
    /// max |u − u_exact(T)| over the x-faces of a field on this run's grid.
    pub fn max_error(&self, u: &[f64]) -> f64 {
        let n = self.grid.nx();
        let mut e: f64 = 0.0;
        for (j, &y) in self.grid.y.centres().iter().enumerate() {
            for (i, &x) in self.grid.x.faces().iter().enumerate() {
                let exact = taylor_green_exact(x, y, TG_END_TIME).0;
                e = e.max((u[i + (n + 1) * j] - exact).abs());
            }
        }
        e
    }
}

/// Integrates the Taylor–Green vortex on an n × n grid with `steps` implicit-Euler steps
/// (Superbee, direct linear solves, [`TG_STEP_TOLERANCE`]), from the exact fields at t = 0.
pub fn taylor_green(n: usize, steps: usize) -> Result<TaylorGreenRun, VerifyError> {
    let grid = Grid::new(Axis::uniform(0.0, 1.0, n)?, Axis::uniform(0.0, 1.0, n)?);
    let slip = SideBc::Wall(RobinFace::ZERO_GRADIENT);
    let bcs = Sides {
        west: slip,
        east: slip,
        south: slip,
        north: slip,
    };
    let settings = Settings {
        scheme: Scheme::Superbee,
        relax_velocity: 0.9,
        relax_pressure: 0.1,
        momentum_solver: LinearSolverKind::SparseLu,
        pressure_solver: LinearSolverKind::SparseLu,
    };
    let fluid = Fluid {
        density: TG_DENSITY,
        viscosity: TG_VISCOSITY,
    };
    let t = Instant::now();
    let mut s = SinglePhase::new(grid.clone(), fluid, bcs, (0.0, 0.0), settings)?;
    let (xf, yc) = (grid.x.faces(), grid.y.centres());
    let (xc, yf) = (grid.x.centres(), grid.y.faces());
    for (j, &y) in yc.iter().enumerate() {
        for (i, &x) in xf.iter().enumerate() {
            s.u[i + (n + 1) * j] = taylor_green_exact(x, y, 0.0).0;
        }
    }
    for (j, &y) in yf.iter().enumerate() {
        for (i, &x) in xc.iter().enumerate() {
            s.v[i + n * j] = taylor_green_exact(x, y, 0.0).1;
        }
    }
    for (j, &y) in yc.iter().enumerate() {
        for (i, &x) in xc.iter().enumerate() {
            s.p[i + n * j] = taylor_green_exact(x, y, 0.0).2;
        }
    }
    let dt = TG_END_TIME / steps as f64;
    let mut outer_iterations = 0;
    let mut mass_ratios = Vec::with_capacity(steps);
    for step in 0..steps {
        let out = s.step(dt, TG_STEP_TOLERANCE, 1e4, 400)?;
        outer_iterations += out.iterations;
        if !out.converged {
            return Err(VerifyError::StepNotConverged {
                step,
                steps,
                cells: n,
                residual: out.residual,
            });
        }
        mass_ratios.push(mass_ratio(&s, TG_DENSITY));
    }
    Ok(TaylorGreenRun {
        grid,
        steps,
        u: s.u,
        outer_iterations,
        wall_time: t.elapsed().as_secs_f64(),
        mass_ratios,
    })
}

fn tg_level(runs: &[&TaylorGreenRun]) -> Level {
    Level {
        cells: runs[0].grid.nx(),
        steps: runs[0].steps,
        outer_iterations: runs.iter().map(|r| r.outer_iterations).sum(),
        wall_time: runs.iter().map(|r| r.wall_time).sum(),
        mass_ratio: runs
            .iter()
            .flat_map(|r| r.mass_ratios.iter().copied())
            .fold(0.0, f64::max),
    }
}

/// Spatial order: on each grid of `levels` (cells per side, increasing), the first-order
/// time error of implicit Euler is removed by Richardson extrapolation in time,
/// 2 u(Δt/2) − u(Δt), and the result compared with the exact solution. Δt is refined with
/// the grid (T/`steps` on the first level, steps ∝ cells), so that the O(Δt²) remainder of
/// the extrapolation shrinks like h² and cannot mask the spatial order on fine grids.
pub fn taylor_green_space_order(levels: &[usize], steps: usize) -> Result<OrderStudy, VerifyError> {
    let first = *levels
        .first()
        .ok_or_else(|| VerifyError::Setup("no levels".into()))?;
    let mut out = Vec::new();
    let mut errors = Vec::new();
    for &n in levels {
        let k = steps * n / first;
        let coarse = taylor_green(n, k)?;
        let fine = taylor_green(n, 2 * k)?;
        let extrapolated: Vec<f64> = fine
            .u
            .iter()
            .zip(&coarse.u)
            .map(|(f, c)| 2.0 * f - c)
            .collect();
        errors.push(coarse.max_error(&extrapolated));
        out.push(tg_level(&[&coarse, &fine]));
    }
    let ratios: Vec<f64> = levels
        .windows(2)
        .map(|w| w[1] as f64 / w[0] as f64)
        .collect();
    Ok(OrderStudy {
        label: format!(
            "Taylor-Green space (Richardson in time, {steps} and {} steps on n = {first}, \
             steps proportional to n)",
            2 * steps
        ),
        orders: observed_orders(&errors, &ratios),
        levels: out,
        errors,
    })
}

/// Temporal order on one n × n grid by self-convergence over `steps` (increasing): the
/// differences max |u_k − u_{k+1}| of consecutive runs, in which the spatial error cancels.
pub fn taylor_green_time_order(n: usize, steps: &[usize]) -> Result<OrderStudy, VerifyError> {
    let runs = steps
        .iter()
        .map(|&k| taylor_green(n, k))
        .collect::<Result<Vec<_>, _>>()?;
    let errors: Vec<f64> = runs
        .windows(2)
        .map(|w| {
            w[0].u
                .iter()
                .zip(&w[1].u)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max)
        })
        .collect();
    let ratios: Vec<f64> = steps
        .windows(2)
        .map(|w| w[1] as f64 / w[0] as f64)
        .collect();
    Ok(OrderStudy {
        label: format!("Taylor-Green time (self-convergence, n = {n})"),
        orders: observed_orders(&errors, &ratios[..errors.len().saturating_sub(1)]),
        levels: runs.iter().map(|r| tg_level(&[r])).collect(),
        errors,
    })
}

/// Per-step mass conservation on the Taylor–Green run (n × n, `steps` steps).
#[derive(Clone, Debug, PartialEq)]
pub struct MassCheck {
    /// net continuity imbalance after each converged step relative to the flow through
    /// the domain
    pub ratios: Vec<f64>,
    /// the largest of them
    pub worst: f64,
}

impl MassCheck {
    /// Whether every step is within [`MASS_TOLERANCE`].
    pub fn passed(&self) -> bool {
        self.ratios.iter().all(|&r| r <= MASS_TOLERANCE)
    }
}

/// Checks the mass balance of every converged step of a Taylor–Green run.
pub fn mass_conservation(n: usize, steps: usize) -> Result<MassCheck, VerifyError> {
    let run = taylor_green(n, steps)?;
    let worst = run.mass_ratios.iter().copied().fold(0.0, f64::max);
    Ok(MassCheck {
        ratios: run.mass_ratios,
        worst,
    })
}
