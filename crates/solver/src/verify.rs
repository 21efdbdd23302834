//! Verification problems of the single-phase core (issue 6), shared by the fast tests and
//! `cargo xtask verify`.
//!
//! Each problem sets up a [`SinglePhase`], runs it and returns a structured result: errors
//! against the reference, observed orders, outer iterations and wall time. The tests in
//! `crates/solver/tests/` call them at small sizes; `cargo xtask verify` runs full sizes.
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

use std::f64::consts::PI;
use std::time::Instant;

use runout_linsolve::LinearSolverKind;
use runout_mesh::{Axis, Grid, MeshError, Segment, Sides};
use runout_walls::RobinFace;

use crate::single_phase::{Fluid, Settings, SideBc, SinglePhase, SolverError, SteadyReport};
use crate::transport::Scheme;

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

// ---------------------------------------------------------------------------------------
// Reference data
// ---------------------------------------------------------------------------------------

/// Centreline velocities of the lid-driven unit cavity (unit lid speed): u(0.5, y) at the
/// heights `y` and v(x, 0.5) at the abscissae `x`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CentrelineReference {
    /// citation
    pub source: &'static str,
    /// Reynolds number U L/ν
    pub reynolds: f64,
    /// heights of the u samples on the vertical centreline x = 0.5
    pub y: &'static [f64],
    /// u(0.5, y)
    pub u: &'static [f64],
    /// abscissae of the v samples on the horizontal centreline y = 0.5
    pub x: &'static [f64],
    /// v(x, 0.5)
    pub v: &'static [f64],
}

/// y of Ghia, Ghia & Shin's u samples (their 129-point grid lines), top to bottom.
pub const GHIA_Y: [f64; 17] = [
    1.0, 0.9766, 0.9688, 0.9609, 0.9531, 0.8516, 0.7344, 0.6172, 0.5, 0.4531, 0.2813, 0.1719,
    0.1016, 0.0703, 0.0625, 0.0547, 0.0,
];

/// x of Ghia, Ghia & Shin's v samples, right to left.
pub const GHIA_X: [f64; 17] = [
    1.0, 0.9688, 0.9609, 0.9531, 0.9453, 0.9063, 0.8594, 0.8047, 0.5, 0.2344, 0.2266, 0.1563,
    0.0938, 0.0781, 0.0703, 0.0625, 0.0,
];

const GHIA_CITATION: &str = "Ghia, Ghia & Shin (1982), J. Comput. Phys. 48, 387-411, Tables I-II";

/// Ghia, Ghia & Shin (1982), J. Comput. Phys. 48, 387–411, Tables I and II, Re = 100.
pub const GHIA_RE100: CentrelineReference = CentrelineReference {
    source: GHIA_CITATION,
    reynolds: 100.0,
    y: &GHIA_Y,
    u: &[
        1.0, 0.84123, 0.78871, 0.73722, 0.68717, 0.23151, 0.00332, -0.13641, -0.20581, -0.21090,
        -0.15662, -0.10150, -0.06434, -0.04775, -0.04192, -0.03717, 0.0,
    ],
    x: &GHIA_X,
    v: &[
        0.0, -0.05906, -0.07391, -0.08864, -0.10313, -0.16914, -0.22445, -0.24533, 0.05454,
        0.17527, 0.17507, 0.16077, 0.12317, 0.10890, 0.10091, 0.09233, 0.0,
    ],
};

/// Ghia, Ghia & Shin (1982), Tables I and II, Re = 1000.
pub const GHIA_RE1000: CentrelineReference = CentrelineReference {
    source: GHIA_CITATION,
    reynolds: 1000.0,
    y: &GHIA_Y,
    u: &[
        1.0, 0.65928, 0.57492, 0.51117, 0.46604, 0.33304, 0.18719, 0.05702, -0.06080, -0.10648,
        -0.27805, -0.38289, -0.29730, -0.22220, -0.20196, -0.18109, 0.0,
    ],
    x: &GHIA_X,
    v: &[
        0.0, -0.21388, -0.27669, -0.33714, -0.39188, -0.51550, -0.42665, -0.31966, 0.02526,
        0.32235, 0.33075, 0.37095, 0.32627, 0.30353, 0.29012, 0.27485, 0.0,
    ],
};

/// Botella & Peyret (1998), "Benchmark spectral results on the lid-driven cavity flow",
/// Computers & Fluids 27(4), 421–433, Tables 9 and 10 (Chebyshev collocation, N = 160),
/// Re = 1000, at Ghia's sample points. Transcribed from public benchmark scripts that
/// quote these tables (several independent copies agree to all digits).
pub const BOTELLA_PEYRET_RE1000: CentrelineReference = CentrelineReference {
    source: "Botella & Peyret (1998), Comput. Fluids 27, 421-433, Tables 9-10",
    reynolds: 1000.0,
    y: &GHIA_Y,
    u: &[
        1.0, 0.6644227, 0.5808359, 0.5169277, 0.4723329, 0.3372212, 0.1886747, 0.0570178,
        -0.0620561, -0.1081999, -0.2803696, -0.3885691, -0.3004561, -0.2228955, -0.2023300,
        -0.1812881, 0.0,
    ],
    x: &GHIA_X,
    v: &[
        0.0, -0.2279225, -0.2936869, -0.3553213, -0.4103754, -0.5264392, -0.4264545, -0.3202137,
        0.0257995, 0.3253592, 0.3339924, 0.3769189, 0.3330442, 0.3099097, 0.2962703, 0.2807056,
        0.0,
    ],
};

/// Extrema of the centreline velocities.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CentrelineExtrema {
    /// minimum of u(0.5, y)
    pub u_min: f64,
    /// where it is
    pub y_u_min: f64,
    /// maximum of v(x, 0.5)
    pub v_max: f64,
    /// where it is
    pub x_v_max: f64,
    /// minimum of v(x, 0.5)
    pub v_min: f64,
    /// where it is
    pub x_v_min: f64,
}

/// Botella & Peyret (1998), Table 7, Re = 1000 (N = 160).
pub const BOTELLA_PEYRET_RE1000_EXTREMA: CentrelineExtrema = CentrelineExtrema {
    u_min: -0.3885698,
    y_u_min: 0.1717,
    v_max: 0.3769447,
    x_v_max: 0.1578,
    v_min: -0.5270771,
    x_v_min: 0.9092,
};

/// Ghia's table for `reynolds` (100 or 1000).
pub fn ghia(reynolds: f64) -> Option<&'static CentrelineReference> {
    [&GHIA_RE100, &GHIA_RE1000]
        .into_iter()
        .find(|r| r.reynolds == reynolds)
}

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

/// Observed orders log(e_k/e_{k+1}) / log(r_k) with r_k the refinement ratio.
pub fn observed_orders(errors: &[f64], ratios: &[f64]) -> Vec<f64> {
    errors
        .windows(2)
        .zip(ratios)
        .map(|(e, r)| (e[0] / e[1]).ln() / r.ln())
        .collect()
}

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

// ---------------------------------------------------------------------------------------
// Lid-driven cavity
// ---------------------------------------------------------------------------------------

/// A lid-driven cavity run: unit square, unit lid speed, ρ = 1, μ = 1/Re.
#[derive(Clone, Debug, PartialEq)]
pub struct CavitySetup {
    /// cells per side
    pub cells: usize,
    /// Reynolds number
    pub reynolds: f64,
    /// convection scheme
    pub scheme: Scheme,
    /// steady convergence: Σ of the normalised momentum residuals ≤ `tolerance` …
    pub tolerance: f64,
    /// … and mean |mass imbalance| per cell ≤ `mass_tolerance` [kg s⁻¹ per m depth]
    pub mass_tolerance: f64,
    /// outer-iteration cap
    pub max_iterations: usize,
}

impl CavitySetup {
    /// The setup of the issue-6 check: momentum tolerance 1e-7, mass 1e-14 per cell, at
    /// most 20 000 outer iterations.
    pub fn new(cells: usize, reynolds: f64, scheme: Scheme) -> Self {
        CavitySetup {
            cells,
            reynolds,
            scheme,
            tolerance: 1e-7,
            mass_tolerance: 1e-14,
            max_iterations: 20_000,
        }
    }
}

/// A converged (or not) cavity solution.
pub struct CavityRun {
    /// the setup
    pub setup: CavitySetup,
    /// the solver with its fields
    pub solver: SinglePhase,
    /// the steady iteration report
    pub report: SteadyReport,
    /// wall time of the solve [s]
    pub wall_time: f64,
}

/// Solves the cavity of `setup` (SIMPLE relaxation 0.7/0.3, default linear solvers).
pub fn cavity_solve(setup: &CavitySetup) -> Result<CavityRun, VerifyError> {
    let n = setup.cells;
    let grid = Grid::new(Axis::uniform(0.0, 1.0, n)?, Axis::uniform(0.0, 1.0, n)?);
    let still = SideBc::Wall(RobinFace::dirichlet(0.0));
    let bcs = Sides {
        west: still,
        east: still,
        south: still,
        north: SideBc::Wall(RobinFace::dirichlet(1.0)),
    };
    let fluid = Fluid {
        density: 1.0,
        viscosity: 1.0 / setup.reynolds,
    };
    let settings = Settings {
        scheme: setup.scheme,
        relax_velocity: 0.7,
        relax_pressure: 0.3,
        ..Settings::default()
    };
    let t = Instant::now();
    let mut solver = SinglePhase::new(grid, fluid, bcs, (0.0, 0.0), settings)?;
    let report = solver.solve_steady(
        setup.max_iterations,
        setup.tolerance,
        setup.mass_tolerance / setup.tolerance,
    )?;
    Ok(CavityRun {
        setup: setup.clone(),
        solver,
        report,
        wall_time: t.elapsed().as_secs_f64(),
    })
}

/// One centreline sample.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// y (u samples) or x (v samples)
    pub position: f64,
    /// our value (bilinear interpolation of the staggered nodes, [`SinglePhase::u_at`])
    pub computed: f64,
    /// the reference value
    pub reference: f64,
}

impl Sample {
    /// |computed − reference|
    pub fn error(&self) -> f64 {
        (self.computed - self.reference).abs()
    }
}

/// A solution against a [`CentrelineReference`].
#[derive(Clone, Debug, PartialEq)]
pub struct CentrelineComparison {
    /// the reference's citation
    pub source: &'static str,
    /// u(0.5, y) samples
    pub u: Vec<Sample>,
    /// v(x, 0.5) samples
    pub v: Vec<Sample>,
}

impl CentrelineComparison {
    /// Largest |computed − reference| over all samples.
    pub fn max_error(&self) -> f64 {
        self.u
            .iter()
            .chain(&self.v)
            .map(Sample::error)
            .fold(0.0, f64::max)
    }

    /// The sample with the largest error, with "u" or "v".
    pub fn worst(&self) -> (&'static str, Sample) {
        let u = self.u.iter().map(|s| ("u", *s));
        let v = self.v.iter().map(|s| ("v", *s));
        u.chain(v)
            .fold(None, |best: Option<(&'static str, Sample)>, c| match best {
                Some(b) if b.1.error() >= c.1.error() => Some(b),
                _ => Some(c),
            })
            .expect("references have samples")
    }
}

/// Compares the centrelines of a cavity solution with `reference`.
pub fn compare_centrelines(
    s: &SinglePhase,
    reference: &CentrelineReference,
) -> CentrelineComparison {
    CentrelineComparison {
        source: reference.source,
        u: reference
            .y
            .iter()
            .zip(reference.u)
            .map(|(&y, &r)| Sample {
                position: y,
                computed: s.u_at(0.5, y),
                reference: r,
            })
            .collect(),
        v: reference
            .x
            .iter()
            .zip(reference.v)
            .map(|(&x, &r)| Sample {
                position: x,
                computed: s.v_at(x, 0.5),
                reference: r,
            })
            .collect(),
    }
}

/// Extremum of a sampled curve: the vertex of the parabola through the extreme sample and
/// its two neighbours (the sample itself at an end). `sign` = 1 for a maximum, −1 for a minimum.
fn extremum(xs: &[f64], ys: &[f64], sign: f64) -> (f64, f64) {
    let k = (0..ys.len())
        .max_by(|&a, &b| (sign * ys[a]).total_cmp(&(sign * ys[b])))
        .expect("samples");
    if k == 0 || k + 1 == ys.len() {
        return (ys[k], xs[k]);
    }
    let (x0, x1, x2) = (xs[k - 1], xs[k], xs[k + 1]);
    let (y0, y1, y2) = (ys[k - 1], ys[k], ys[k + 1]);
    // Newton form: y = y0 + d1 (x − x0) + d2 (x − x0)(x − x1)
    let d1 = (y1 - y0) / (x1 - x0);
    let d2 = ((y2 - y1) / (x2 - x1) - d1) / (x2 - x0);
    if d2 == 0.0 {
        return (y1, x1);
    }
    let xv = 0.5 * (x0 + x1) - d1 / (2.0 * d2);
    (y0 + d1 * (xv - x0) + d2 * (xv - x0) * (xv - x1), xv)
}

/// Centreline extrema of a cavity solution: u(0.5, y) at the u-node heights and v(x, 0.5)
/// at the v-node abscissae, each extremum refined by a parabola through three nodes.
pub fn centreline_extrema(s: &SinglePhase) -> CentrelineExtrema {
    let g = s.grid();
    let yc = g.y.centres();
    let xc = g.x.centres();
    let us: Vec<f64> = yc.iter().map(|&y| s.u_at(0.5, y)).collect();
    let vs: Vec<f64> = xc.iter().map(|&x| s.v_at(x, 0.5)).collect();
    let (u_min, y_u_min) = extremum(yc, &us, -1.0);
    let (v_max, x_v_max) = extremum(xc, &vs, 1.0);
    let (v_min, x_v_min) = extremum(xc, &vs, -1.0);
    CentrelineExtrema {
        u_min,
        y_u_min,
        v_max,
        x_v_max,
        v_min,
        x_v_min,
    }
}

/// Result of [`cavity`].
#[derive(Clone, Debug, PartialEq)]
pub struct CavityResult {
    /// the setup
    pub setup: CavitySetup,
    /// against Ghia, Ghia & Shin (1982)
    pub ghia: CentrelineComparison,
    /// largest centreline deviation from Ghia (lid speed 1)
    pub max_error: f64,
    /// outer iterations
    pub outer_iterations: usize,
    /// whether the steady tolerance was met
    pub converged: bool,
    /// net continuity imbalance relative to the circulating flow ([`mass_ratio`])
    pub mass_ratio: f64,
    /// wall time [s]
    pub wall_time: f64,
}

/// The cavity of `setup` against Ghia, Ghia & Shin (1982) (Re = 100 or 1000).
pub fn cavity(setup: &CavitySetup) -> Result<CavityResult, VerifyError> {
    let reference = ghia(setup.reynolds).ok_or_else(|| {
        VerifyError::Setup(format!(
            "no Ghia table at Re = {} (have 100, 1000)",
            setup.reynolds
        ))
    })?;
    let run = cavity_solve(setup)?;
    let ghia = compare_centrelines(&run.solver, reference);
    Ok(CavityResult {
        setup: setup.clone(),
        max_error: ghia.max_error(),
        ghia,
        outer_iterations: run.report.iterations,
        converged: run.report.converged,
        mass_ratio: mass_ratio(&run.solver, 1.0),
        wall_time: run.wall_time,
    })
}

// ---------------------------------------------------------------------------------------
// Plane Poiseuille flow with partial-slip walls
// ---------------------------------------------------------------------------------------

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

// ---------------------------------------------------------------------------------------
// Taylor–Green vortex (manufactured unsteady solution)
// ---------------------------------------------------------------------------------------

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_are_consistent() {
        for r in [&GHIA_RE100, &GHIA_RE1000, &BOTELLA_PEYRET_RE1000] {
            assert_eq!(r.y.len(), r.u.len());
            assert_eq!(r.x.len(), r.v.len());
            // ordered from the lid (or right wall) down, no-slip walls and unit lid
            assert!(r.y.windows(2).all(|w| w[0] > w[1]));
            assert!(r.x.windows(2).all(|w| w[0] > w[1]));
            assert_eq!((r.u[0], r.u[16], r.v[0], r.v[16]), (1.0, 0.0, 0.0, 0.0));
        }
        // The spectral values differ from Ghia's by at most 0.011 (at x = 0.9063), which
        // is why Ghia is not a 1e-3 reference at Re = 1000.
        let d = (GHIA_RE1000.v[5] - BOTELLA_PEYRET_RE1000.v[5]).abs();
        assert!((0.0109..0.0110).contains(&d), "{d}");
    }

    #[test]
    fn parabola_vertex() {
        let xs = [0.0, 1.0, 2.0, 3.0];
        let ys: Vec<f64> = xs.iter().map(|x: &f64| (x - 1.3).powi(2) - 2.0).collect();
        let (y, x) = extremum(&xs, &ys, -1.0);
        assert!((x - 1.3).abs() < 1e-12 && (y + 2.0).abs() < 1e-12);
    }

    #[test]
    fn orders_of_exact_power_law() {
        let e = [1.0, 0.25, 0.0625];
        let p = observed_orders(&e, &[2.0, 2.0]);
        assert!(p.iter().all(|o| (o - 2.0).abs() < 1e-12));
    }
}
