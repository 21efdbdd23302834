//! Plane Poiseuille flow between partial-slip walls against its closed form, and its observed
//! order on uniform and stretched grids.

use super::*;

/// Channel height H [m].
pub const POISEUILLE_HEIGHT: f64 = 1.0;
/// Channel length L [m].
pub const POISEUILLE_LENGTH: f64 = 2.0;
/// Viscosity μ [Pa s].
pub const POISEUILLE_VISCOSITY: f64 = 0.5;
/// Density ρ [kg m⁻³].
pub const POISEUILLE_DENSITY: f64 = 1.0;
/// Pressure drop p_in − p_out [Pa].
pub const POISEUILLE_PRESSURE_DROP: f64 = 1.0;
/// Slip coefficient h_u of both walls (paper Eq. 12) [m⁻¹].
pub const POISEUILLE_SLIP: f64 = 4.0;

/// Closed form between partial-slip walls du/dn + h u = 0 (n into the wall), G = Δp/L:
/// u(y) = G/(2μ) [y (H − y) + H/h] (so u'(0) = G H/(2μ) = h u(0)).
pub fn poiseuille_exact(y: f64) -> f64 {
    let (h, g) = (
        POISEUILLE_HEIGHT,
        POISEUILLE_PRESSURE_DROP / POISEUILLE_LENGTH,
    );
    g / (2.0 * POISEUILLE_VISCOSITY) * (y * (h - y) + h / POISEUILLE_SLIP)
}

/// Wall-normal grid of a Poiseuille study.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ChannelGrid {
    /// uniform cells; a level is the number of cells across
    Uniform,
    /// symmetric geometric stretching, cells growing by `growth` from each wall to the
    /// middle on the coarsest level; a level is the number of cells per half. Refining by
    /// r splits every cell into r with growth^(1/r), so the levels are nested.
    Stretched {
        /// growth factor on the coarsest level
        growth: f64,
    },
}

/// One Poiseuille solve.
#[derive(Clone, Debug, PartialEq)]
pub struct PoiseuilleRun {
    /// cells across the channel
    pub cells: usize,
    /// max |u − exact| over the cell centres of the middle column and the wall face value
    pub error: f64,
    /// outer iterations
    pub outer_iterations: usize,
    /// net continuity imbalance relative to the flow rate
    pub mass_ratio: f64,
    /// wall time [s]
    pub wall_time: f64,
}

/// The fully developed channel: pressure inlet and outlet at the ends, partial-slip walls
/// at y = 0 and H, 4 cells along. Direct linear solves, so that the outer iterations
/// converge to round-off; with ω_p = 1 − ω_u (Patankar 1980 §6.7).
pub fn poiseuille(y: Axis, scheme: Scheme) -> Result<PoiseuilleRun, VerifyError> {
    let grid = Grid::new(Axis::uniform(0.0, POISEUILLE_LENGTH, 4)?, y);
    let face = RobinFace::partial_slip(POISEUILLE_SLIP, 0.0);
    let wall = SideBc::Wall(face);
    let bcs = Sides {
        west: SideBc::Outlet(POISEUILLE_PRESSURE_DROP),
        east: SideBc::Outlet(0.0),
        south: wall,
        north: wall,
    };
    let settings = Settings {
        scheme,
        relax_velocity: 0.9,
        relax_pressure: 0.1,
        momentum_solver: LinearSolverKind::SparseLu,
        pressure_solver: LinearSolverKind::SparseLu,
    };
    let fluid = Fluid {
        density: POISEUILLE_DENSITY,
        viscosity: POISEUILLE_VISCOSITY,
    };
    let t = Instant::now();
    let mut s = SinglePhase::new(grid, fluid, bcs, (0.0, 0.0), settings)?;
    let report = s.solve_steady(20_000, 1e-9, 1.0)?;
    let wall_time = t.elapsed().as_secs_f64();
    if !report.converged {
        return Err(VerifyError::SteadyNotConverged {
            problem: "Poiseuille",
            iterations: report.iterations,
        });
    }
    let g = s.grid();
    let i = 2; // the middle x-face
    let mut error: f64 = 0.0;
    for (j, &y) in g.y.centres().iter().enumerate() {
        error = error.max((s.u[i + (g.nx() + 1) * j] - poiseuille_exact(y)).abs());
    }
    // the wall face value of the closure, too
    let u0 = face.face_value(s.u[i], g.y.widths()[0]);
    error = error.max((u0 - poiseuille_exact(0.0)).abs());
    Ok(PoiseuilleRun {
        cells: g.ny(),
        error,
        outer_iterations: report.iterations,
        mass_ratio: mass_ratio(&s, POISEUILLE_DENSITY),
        wall_time,
    })
}

/// The wall-normal axis of `grid` at `level` (see [`ChannelGrid`]); `coarsest` is the first
/// level of the study.
pub fn channel_axis(grid: ChannelGrid, level: usize, coarsest: usize) -> Result<Axis, MeshError> {
    match grid {
        ChannelGrid::Uniform => Axis::uniform(0.0, POISEUILLE_HEIGHT, level),
        ChannelGrid::Stretched { growth } => {
            let g = growth.powf(coarsest as f64 / level as f64);
            let half = 0.5 * POISEUILLE_HEIGHT;
            Axis::from_segments(
                0.0,
                &[
                    Segment::Geometric {
                        length: half,
                        cells: level,
                        growth: g,
                    },
                    Segment::Geometric {
                        length: half,
                        cells: level,
                        growth: 1.0 / g,
                    },
                ],
            )
        }
    }
}

/// Poiseuille errors over `levels` (increasing; see [`ChannelGrid`]) and observed orders.
pub fn poiseuille_order(
    grid: ChannelGrid,
    levels: &[usize],
    scheme: Scheme,
) -> Result<OrderStudy, VerifyError> {
    let coarsest = *levels
        .first()
        .ok_or_else(|| VerifyError::Setup("no levels".into()))?;
    let mut out = Vec::new();
    let mut errors = Vec::new();
    for &level in levels {
        let run = poiseuille(channel_axis(grid, level, coarsest)?, scheme)?;
        errors.push(run.error);
        out.push(Level {
            cells: run.cells,
            steps: 0,
            outer_iterations: run.outer_iterations,
            wall_time: run.wall_time,
            mass_ratio: run.mass_ratio,
        });
    }
    let ratios: Vec<f64> = levels
        .windows(2)
        .map(|w| w[1] as f64 / w[0] as f64)
        .collect();
    Ok(OrderStudy {
        label: format!("Poiseuille, partial slip h_u = {POISEUILLE_SLIP}, {grid:?}, {scheme:?}"),
        orders: observed_orders(&errors, &ratios),
        levels: out,
        errors,
    })
}
