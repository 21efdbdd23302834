//! Steady, fully developed granular flow down an inclined plane: a 1-D boundary-value solve
//! of the two-fluid model's solids equations with the closures and wall conditions the 2-D
//! solver uses (issue 7, third check; `docs/studies/chute1d.md`).
//!
//! Coordinates: x along the slope (downhill), y normal to the floor (floor at y = 0, a lid at
//! y = H); gravity g = (g sin α, −g cos α). Fully developed: ∂/∂x = 0, v_s = 0. Dry: ρ_g = 0
//! (no gas phase, no drag, μ* = μ₀, κ* = κ₀; docs/model.md §2.2). Unknowns per cell: εs, u_s, θ.
//!
//! Equations (docs/model.md §1.2–1.3 reduced to 1-D):
//! - y-momentum: d(P_s + P*)/dy = −εs ρs g cos α, with P_s = P_kin + P_fric (§2.3);
//! - x-momentum: d/dy(μ_s du/dy) + εs ρs g sin α = 0, μ_s = μ_kin + μ_fric (§2.3);
//! - granular energy: d/dy(κ_s dθ/dy) + Π − γ = 0 with Π = −P_kin tr D + 2μ_kin tr(D²) +
//!   λ_kin (tr D)² (§1.3). Here tr D = 0, D_xy = ½ du/dy, so tr(D²) = 2 D_xy² = ½ (du/dy)²,
//!   S:S = tr(D²) − (tr D)²/3 = ½ (du/dy)² and Π = μ_kin (du/dy)²: only the kinetic viscosity
//!   produces granular energy;
//! - the holdup ∫₀ᴴ εs dy = M (the solids mass per floor area divided by ρs), which the 2-D
//!   solver conserves on a periodic strip.
//!
//! Boundaries: the floor takes any [`SolidsWallModel`] (Johnson–Jackson in issue 7), applied
//! through [`RobinFace::implicit_parts`] exactly as the 2-D solver does (docs/model.md §3.2), with
//! the near-wall states gathered as docs/model.md §3.5–3.6 prescribe; the lid at y = H is a
//! free-slip wall with zero θ flux (MFIX FSW, runout's [`SolidsWallModel::FreeSlip`]). The
//! lid carries no equation for εs: as in the staggered 2-D solver, y-momentum holds on the
//! N − 1 interior faces and the holdup closes the system; the lid's load is a diagnostic
//! ([`ChuteProfile::lid_pressure`]). A strip of height H with holdup M on a periodic 2-D grid
//! with the same floor and an FSW lid has exactly these equations.
//!
//! Discretisation (docs/model.md §4.1): finite volumes on the cell centres of a stretched
//! [`Axis`]; face transport coefficients are the harmonic means MFIX uses (AVG_H with the
//! AVG_X weights); the cell-centred strain rate is the difference of the two face velocities
//! over the cell width (face values linearly interpolated, the wall-face value from the
//! Robin closure); the body force on a y-momentum face is the volume-weighted mean of the two
//! cells, so Σ faces gives P_s(0) − P_lid = ρs g cos α Σ εs Δy exactly. The floor closure takes
//! the fluid cell's μ_s, κ_s and εs ([`WallTreatment::FluidCell`], docs/model.md §3.1, §3.5–3.6),
//! which is first-order accurate where they vary at the wall; [`WallTreatment::Extrapolated`]
//! is the second-order variant used to verify the rest of the scheme.
//!
//! Solver: Newton's method on all 3N unknowns (ln εs, u_s, ln θ: positive by construction,
//! and the dilute layer decays exponentially) with a finite-difference Jacobian, coloured five
//! cells apart as every row involves cells j − 2 … j + 2; the y-momentum rows are
//! differentiated through the two cell pressures separately, so that a dilute cell's tiny
//! pressure is not lost beside a dense one's. Pseudo-transient continuation on the u_s and θ
//! rows (ρs εs ∂u/∂t, (3/2) ρs εs ∂θ/∂t with switched evolution relaxation) makes it robust
//! from a poor start; steps are limited to one decade in εs and θ and to 90 % of the distance
//! to εs = 1. The banded Jacobian plus the dense holdup row is solved by faer's sparse LU with
//! partial pivoting and a Sherman–Morrison correction.
//!
//! Limits (`docs/studies/chute1d.md` §3): a free surface with a dilute layer above the bed is not
//! resolved (the discrete hydrostatic balance has no positive solution once g cos α Δy/2
//! exceeds θ there); gas is not implemented ([`Chute1dError::GasNotSupported`]).

use runout_closures::{evaluate, CellState, ClosureParams};
use runout_mesh::{Axis, Beyond};
use runout_walls::state::{corner_theta, face_theta};
use runout_walls::{
    MomentumDiagnostics, MomentumWallState, RobinFace, SolidsWallModel, ThetaDiagnostics,
    ThetaWallState, WallStrain,
};

mod equations;
mod newton;
mod sidewalls;

pub use sidewalls::ChuteSidewalls;

use equations::*;
use newton::*;

/// Unknowns per cell: εs, u_s, θ.
const VARS: usize = 3;
/// Index of εs in a cell's block.
const EPS: usize = 0;
/// Index of u_s in a cell's block.
const U: usize = 1;
/// Index of θ in a cell's block.
const THETA: usize = 2;
/// Every residual row of cell j depends on cells j − 2 … j + 2 (the face viscosities use the
/// cell strain rates, which use the neighbours' velocities).
const STENCIL_REACH: usize = 2;
/// Relative finite-difference step of the Jacobian, √(machine ε).
const FD_STEP: f64 = 1.4901161193847656e-8;
/// MFIX's floor in the harmonic mean's denominator (`fun_avg.inc`, docs/model.md §4.1).
const HARMONIC_FLOOR: f64 = 1e-15;
/// Fraction-to-boundary factor: a Newton step may consume at most this share of the distance
/// to εs = 1 (interior-point convention; εs > 0 and θ > 0 hold by the logarithmic unknowns).
const FRACTION_TO_BOUNDARY: f64 = 0.9;
/// Largest change of ln εs or ln θ in one Newton step: one decade, so that a step far from
/// the solution cannot overflow the closures.
const MAX_LOG_STEP: f64 = std::f64::consts::LN_10;
/// Switched evolution relaxation: the pseudo-time step grows at most by this factor per
/// accepted step (Mulder & van Leer 1985).
const SER_MAX_GROWTH: f64 = 10.0;
/// A rejected step (non-finite or a residual grown by more than [`REJECT_GROWTH`]) divides the
/// pseudo-time step by this factor.
const REJECT_SHRINK: f64 = 4.0;
/// A trial step whose progress residual (`global_norm`) exceeds the current one by this factor
/// is rejected.
const REJECT_GROWTH: f64 = 10.0;
/// The floor wall's own fixed point (face values from coefficients that depend on the face
/// values) is iterated to this relative change.
const WALL_FIXED_POINT_TOL: f64 = 1e-14;
/// Maximum iterations of the floor fixed point.
const WALL_FIXED_POINT_MAX: usize = 200;
/// Bisection steps of the hydrostatic initial guess (interval halved to 2⁻⁶⁰ of its length).
const BISECTION_STEPS: usize = 60;
/// Upper end of the εs bracket of the initial guess: below 1, where the Carnahan–Starling g0
/// is singular (docs/model.md §2.1).
const EPS_S_BRACKET_TOP: f64 = 0.99;

/// Where the floor closure takes its bulk values (the transport coefficient Γ on the wall face,
/// and εs of the near-wall states).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum WallTreatment {
    /// As MFIX and the 2-D solver: the fluid cell's own values (docs/model.md §3.1 for Γ, §3.5–3.6
    /// for εs). They sit half a cell from the wall, so where Γ or εs vary at the wall the
    /// closure is first-order accurate.
    #[default]
    FluidCell,
    /// Second order: Γ and εs extrapolated to y = 0 from the first two cell centres,
    /// log-linearly (positive, exact for exponential profiles):
    /// f_w = f₁ (f₁/f₂)^{Δ₁/(2 δ)}, δ the distance between the two centres.
    Extrapolated,
}

impl WallTreatment {
    /// The wall value of a positive cell-centred field `values` on `grid`.
    pub fn wall_value(self, grid: &Axis, values: &[f64]) -> f64 {
        match self {
            Self::FluidCell => values[0],
            Self::Extrapolated => {
                let reach = 0.5 * grid.widths()[0] / grid.face_spacing()[1];
                values[0] * (values[0] / values[1]).powf(reach)
            }
        }
    }
}

/// The chute problem: material, slope, holdup, floor and grid.
#[derive(Clone, Debug)]
pub struct ChuteParams {
    /// closures (particles, friction model and parameters, g0); `gas.density` must be 0
    pub closures: ClosureParams,
    /// slope α \[deg\], 0 < α < 90
    pub slope_deg: f64,
    /// |g| [m/s²]
    pub gravity: f64,
    /// solids holdup M = ∫₀ᴴ εs dy \[m\] (bed depth at εs = 1), 0 < M < H
    pub holdup: f64,
    /// floor wall condition at y = 0 (docs/model.md §3)
    pub floor: SolidsWallModel,
    /// cells across the layer, faces from y = 0 (floor) to y = H (free-slip lid)
    pub grid: Axis,
    /// bulk values of the floor closure: MFIX's fluid-cell values (default) or second-order
    /// extrapolated ones
    pub wall_treatment: WallTreatment,
    /// side walls a width apart (docs/model.md §8); none: a plane flow
    pub sidewalls: Option<ChuteSidewalls>,
}

/// Starting point of the iteration.
#[derive(Clone, Debug)]
pub enum InitialGuess {
    /// uniform u_s and θ, with εs in hydrostatic balance for that θ and the holdup
    Uniform {
        /// u_s [m/s]
        velocity: f64,
        /// θ [m²/s²] > 0
        theta: f64,
    },
    /// a previous solution, linearly interpolated onto this grid (grid sequencing,
    /// continuation in a parameter)
    Profile(Box<ChuteProfile>),
}

/// Iteration controls.
#[derive(Clone, Debug)]
pub struct SolverSettings {
    /// converged when the root-mean-square residual, each row divided by its equation's fixed
    /// reference (the floor-normal and floor-parallel weights of the holdup, the holdup, the
    /// weight's power at the free-fall speed), is below this
    pub tolerance: f64,
    /// Newton iterations allowed (accepted and rejected)
    pub max_iterations: usize,
    /// first pseudo-time step \[s\]; grows by switched evolution relaxation
    pub initial_pseudo_time_step: f64,
    /// starting point
    pub initial: InitialGuess,
}

impl Default for SolverSettings {
    /// Tolerance 1e-10, 400 iterations, Δτ₀ = 1e-3 s, start from u_s = 1 m/s,
    /// θ = 0.1 m²/s².
    fn default() -> Self {
        Self {
            tolerance: 1e-10,
            max_iterations: 400,
            initial_pseudo_time_step: 1e-3,
            initial: InitialGuess::Uniform {
                velocity: 1.0,
                theta: 0.1,
            },
        }
    }
}

/// Floor values of the converged solution (docs/model.md §3.5–3.6).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FloorDiagnostics {
    /// h_w^u [m⁻¹ as MFIX codes it] and the other momentum-wall quantities
    pub momentum: MomentumDiagnostics,
    /// h_θ, c_θ, κ of the θ wall condition
    pub theta: ThetaDiagnostics,
    /// u_s on the floor face (mean of ghost and fluid values) [m/s]
    pub face_velocity: f64,
    /// slip |u_s,face − U_w| [m/s]
    pub slip: f64,
    /// θ on the floor face [m²/s²]
    pub face_theta: f64,
    /// εs of the near-wall states (the first cell's, or extrapolated: [`WallTreatment`]) [-]
    pub eps_s: f64,
    /// μ_s on the floor face (the Γ of the momentum closure) [Pa s]
    pub viscosity: f64,
    /// wall shear stress μ_s du/dy at y = 0 \[Pa\] (= μ_s,face h_w^u (u_face − U_w))
    pub shear_stress: f64,
    /// P_s + P* at y = 0 \[Pa\], the first cell's value plus the weight of its lower half
    pub pressure: f64,
    /// granular-energy flux into the flow through the floor, −κ_s,1 (θ₁ − θ_G)/Δ \[W/m²\]:
    /// (κ_s,1/g)(c_θ − h_θ θ_face) with g the wall routine's κ (docs/model.md §3.2 note)
    pub energy_flux_into_flow: f64,
}

/// The steady profile and how it was obtained.
#[derive(Clone, Debug, PartialEq)]
pub struct ChuteProfile {
    /// cell-centre heights above the floor \[m\]
    pub y: Vec<f64>,
    /// cell widths \[m\]
    pub dy: Vec<f64>,
    /// εs [-]
    pub eps_s: Vec<f64>,
    /// u_s [m/s]
    pub u_s: Vec<f64>,
    /// θ [m²/s²]
    pub theta: Vec<f64>,
    /// P_s + P* \[Pa\] at the cell centres
    pub pressure: Vec<f64>,
    /// μ_s [Pa s] at the cell centres
    pub mu_s: Vec<f64>,
    /// du_s/dy [1/s] at the cell centres (the strain rate fed to the closures)
    pub shear_rate: Vec<f64>,
    /// shear production Π = μ_kin (du/dy)² [W/m³]
    pub production: Vec<f64>,
    /// collisional dissipation γ [W/m³]
    pub dissipation: Vec<f64>,
    /// floor diagnostics
    pub floor: FloorDiagnostics,
    /// load on the lid: P at the last centre minus the weight of its upper half \[Pa\]
    pub lid_pressure: f64,
    /// ∫ εs dy = Σ εs Δy \[m\]
    pub holdup: f64,
    /// Newton iterations used
    pub iterations: usize,
    /// final residual: root mean square over rows, each divided by its equation's fixed
    /// reference (weights W_n, W_t, the holdup M, the power W_t √(g cos α M))
    pub residual: f64,
    /// final max over rows of |residual|/Σ|terms| (limited by round-off where all terms of
    /// a row are small, e.g. the shear under the free-slip lid)
    pub normalised_residual: f64,
}

/// Why a solve failed.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Chute1dError {
    /// A parameter outside its range.
    #[error("chute1d: `{field}` = {value} is outside {allowed}")]
    InvalidParameter {
        /// parameter name
        field: &'static str,
        /// the value given
        value: f64,
        /// the allowed range
        allowed: &'static str,
    },
    /// Only the dry case is implemented.
    #[error("chute1d: only the dry case (gas density 0) is implemented, got ρ_g = {0}")]
    GasNotSupported(f64),
    /// The Newton iteration stopped without converging (no steady state near the path, or
    /// too few iterations).
    #[error(
        "chute1d: not converged after {iterations} iterations (residual {residual:e}, worst \
         row {worst_row} = {equation} of cell {cell}, pseudo-time step {pseudo_time_step:e} s)"
    )]
    NotConverged {
        /// iterations used
        iterations: usize,
        /// last residual (as [`ChuteProfile::residual`])
        residual: f64,
        /// row index with the largest |residual|/Σ|terms|
        worst_row: usize,
        /// equation of that row
        equation: &'static str,
        /// cell of that row
        cell: usize,
        /// last pseudo-time step \[s\]
        pseudo_time_step: f64,
    },
    /// The Jacobian was singular.
    #[error("chute1d: singular Jacobian at row {0}")]
    Singular(usize),
}

/// Name of a residual row's equation.
fn equation_name(row: usize, n: usize) -> &'static str {
    match row % VARS {
        EPS if row / VARS + 1 == n => "holdup",
        EPS => "y-momentum",
        U => "x-momentum",
        _ => "granular energy",
    }
}

/// Harmonic face mean Γ_f = Γ_a Γ_b / max(1e-15, w Γ_a + (1 − w) Γ_b), with w the AVG_X
/// weight of the lower cell (docs/model.md §4.1, MFIX AVG_X_H).
#[inline]
pub fn harmonic_face_mean(gamma_lower: f64, gamma_upper: f64, weight_lower: f64) -> f64 {
    gamma_lower * gamma_upper
        / (weight_lower * gamma_lower + (1.0 - weight_lower) * gamma_upper).max(HARMONIC_FLOOR)
}

/// Diffusive fluxes Γ dφ/dy (in +y) on the N + 1 faces of `grid` (docs/model.md §3.2, §4.1): the
/// floor face from the eliminated Robin closure, `RobinFace::implicit_parts` with the wall
/// value of Γ (`treatment`; MFIX: the first cell's), flux = a φ₁ − b; interior faces from the
/// harmonic-mean Γ and the centre difference; the lid face zero (zero gradient). This is the
/// operator of both the x-momentum and the granular-energy rows of [`solve`].
pub fn diffusive_fluxes(
    grid: &Axis,
    gamma: &[f64],
    phi: &[f64],
    floor: &RobinFace,
    treatment: WallTreatment,
) -> Vec<f64> {
    let n = grid.len();
    let dy = grid.widths();
    let spacing = grid.face_spacing();
    let mut flux = vec![0.0; n + 1];
    let (a, b) = floor.implicit_parts(treatment.wall_value(grid, gamma), dy[0]);
    // flux out of cell 0 through the floor is a φ₀ − b; in +y it is Γ (φ₀ − φ_G)/Δ
    flux[0] = a * phi[0] - b;
    for f in 1..n {
        let w = grid.interpolation_weight(f - 1);
        let gamma_face = harmonic_face_mean(gamma[f - 1], gamma[f], w);
        flux[f] = gamma_face * (phi[f] - phi[f - 1]) / spacing[f];
    }
    flux
}

/// Solves d/dy(Γ dφ/dy) + S = 0 on `grid` with the Robin `floor` at y = 0 and zero gradient at
/// the top, Γ and S given per cell: the same discrete operator as [`diffusive_fluxes`]
/// (for the discretisation check against closed forms, `docs/studies/chute1d.md` §4).
pub fn solve_linear_diffusion(
    grid: &Axis,
    gamma: &[f64],
    source: &[f64],
    floor: &RobinFace,
    treatment: WallTreatment,
) -> Result<Vec<f64>, Chute1dError> {
    let n = grid.len();
    let dy = grid.widths();
    let spacing = grid.face_spacing();
    // tridiagonal rows: −lower φ_{j−1} + diag φ_j − upper φ_{j+1} = rhs
    let mut lower = vec![0.0; n];
    let mut diag = vec![0.0; n];
    let mut upper = vec![0.0; n];
    let mut rhs: Vec<f64> = (0..n).map(|j| source[j] * dy[j]).collect();
    let (a, b) = floor.implicit_parts(treatment.wall_value(grid, gamma), dy[0]);
    diag[0] += a;
    rhs[0] += b;
    for f in 1..n {
        let w = grid.interpolation_weight(f - 1);
        let c = harmonic_face_mean(gamma[f - 1], gamma[f], w) / spacing[f];
        diag[f - 1] += c;
        upper[f - 1] = c;
        diag[f] += c;
        lower[f] = c;
    }
    // Thomas algorithm
    for j in 1..n {
        if diag[j - 1] == 0.0 {
            return Err(Chute1dError::Singular(j - 1));
        }
        let m = lower[j] / diag[j - 1];
        diag[j] -= m * upper[j - 1];
        rhs[j] += m * rhs[j - 1];
    }
    if diag[n - 1] == 0.0 {
        return Err(Chute1dError::Singular(n - 1));
    }
    let mut phi = vec![0.0; n];
    phi[n - 1] = rhs[n - 1] / diag[n - 1];
    for j in (0..n - 1).rev() {
        phi[j] = (rhs[j] + upper[j] * phi[j + 1]) / diag[j];
    }
    Ok(phi)
}

fn check_parameters(p: &ChuteParams) -> Result<(), Chute1dError> {
    let invalid = |field, value, allowed| {
        Err(Chute1dError::InvalidParameter {
            field,
            value,
            allowed,
        })
    };
    if p.closures.gas.density != 0.0 {
        return Err(Chute1dError::GasNotSupported(p.closures.gas.density));
    }
    if !(p.slope_deg > 0.0 && p.slope_deg < 90.0) {
        return invalid("slope_deg", p.slope_deg, "(0, 90)");
    }
    if !(p.gravity > 0.0 && p.gravity.is_finite()) {
        return invalid("gravity", p.gravity, "(0, inf)");
    }
    let height = p.grid.length();
    if !(p.holdup > 0.0 && p.holdup < height * EPS_S_BRACKET_TOP) {
        return invalid("holdup", p.holdup, "(0, 0.99 H)");
    }
    if p.grid.len() < 2 {
        return invalid("grid cells", p.grid.len() as f64, "[2, inf)");
    }
    if let Some(w) = p.sidewalls {
        if w.width.is_nan() || w.width <= 0.0 {
            return invalid("sidewalls.width", w.width, "(0, inf]");
        }
    }
    Ok(())
}

/// The unknown vector of an initial guess.
fn initial_unknowns(problem: &Problem, initial: &InitialGuess) -> Vec<f64> {
    let n = problem.n();
    let y = problem.p.grid.centres();
    let y0 = problem.p.grid.start();
    let mut x = vec![0.0; VARS * n];
    match initial {
        InitialGuess::Uniform { velocity, theta } => {
            let theta = vec![*theta; n];
            let eps = problem.hydrostatic_eps(&theta, &vec![0.0; n]);
            for j in 0..n {
                x[VARS * j + EPS] = eps[j];
                x[VARS * j + U] = *velocity;
                x[VARS * j + THETA] = theta[j];
            }
        }
        InitialGuess::Profile(profile) => {
            for j in 0..n {
                let at = y[j] - y0;
                x[VARS * j + EPS] = interpolate(&profile.y, &profile.eps_s, at);
                x[VARS * j + U] = interpolate(&profile.y, &profile.u_s, at);
                x[VARS * j + THETA] = interpolate(&profile.y, &profile.theta, at);
            }
            // restore the holdup exactly by scaling εs
            let dy = problem.p.grid.widths();
            let holdup: f64 = (0..n).map(|j| x[VARS * j + EPS] * dy[j]).sum();
            let factor = problem.p.holdup / holdup;
            for j in 0..n {
                x[VARS * j + EPS] *= factor;
            }
        }
    }
    // the iteration works in ln εs and ln θ (positivity; the dilute layer decays
    // exponentially with height)
    for j in 0..n {
        x[VARS * j + EPS] = x[VARS * j + EPS].ln();
        x[VARS * j + THETA] = x[VARS * j + THETA].ln();
    }
    x
}

/// Piecewise-linear interpolation in increasing abscissae, constant beyond the ends
/// ([`runout_mesh::interpolate`] with [`Beyond::Clamp`]; a profile has samples).
pub fn interpolate(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    runout_mesh::interpolate(xs, ys, x, Beyond::Clamp).expect("a profile has samples")
}

/// Solves the steady, fully developed chute flow (module docs): Newton with pseudo-transient
/// continuation from `settings.initial`.
pub fn solve(
    params: &ChuteParams,
    settings: &SolverSettings,
) -> Result<ChuteProfile, Chute1dError> {
    check_parameters(params)?;
    let problem = Problem::new(params);
    let n = problem.n();
    let mut x = initial_unknowns(&problem, &settings.initial);
    let mut current = problem.evaluate(&x);
    let (mut norm, mut worst) = normalised_residual(&current);
    let mut progress = global_norm(&problem, &current);
    let mut pseudo_dt = settings.initial_pseudo_time_step;
    let dy = params.grid.widths();
    let mut iterations = 0;
    while progress > settings.tolerance {
        if iterations == settings.max_iterations {
            return Err(Chute1dError::NotConverged {
                iterations,
                residual: progress,
                worst_row: worst,
                equation: equation_name(worst, n),
                cell: worst / VARS,
                pseudo_time_step: pseudo_dt,
            });
        }
        iterations += 1;
        let mut matrix = jacobian(&problem, &x, &current);
        // pseudo-transient terms of the momentum and granular-energy rows (docs/model.md §1.2,
        // §1.3: ρs εs ∂u/∂t and (3/2) ρs εs ∂θ/∂t per unit area)
        for j in 0..n {
            // (the θ row's unknown is ln θ: ∂θ/∂ln θ = θ)
            let mass = problem.rho_s * x[VARS * j + EPS].exp() * dy[j] / pseudo_dt;
            matrix.add(VARS * j + U, VARS * j + U, -mass);
            let theta = x[VARS * j + THETA].exp();
            matrix.add(VARS * j + THETA, VARS * j + THETA, -1.5 * mass * theta);
        }
        let delta = newton_step(&problem, &x, matrix, &current.residual)?;
        let lambda = step_length(&x, &delta);
        let trial: Vec<f64> = x.iter().zip(&delta).map(|(a, d)| a + lambda * d).collect();
        let evaluation = problem.evaluate(&trial);
        let (trial_norm, trial_worst) = normalised_residual(&evaluation);
        let trial_progress = global_norm(&problem, &evaluation);
        if !trial_progress.is_finite() || trial_progress > REJECT_GROWTH * progress {
            pseudo_dt /= REJECT_SHRINK;
            continue;
        }
        pseudo_dt *= (progress / trial_progress).min(SER_MAX_GROWTH);
        progress = trial_progress;
        x = trial;
        current = evaluation;
        norm = trial_norm;
        worst = trial_worst;
        tracing::debug!(iterations, norm, lambda, pseudo_dt, "chute1d Newton step");
    }
    Ok(profile(&problem, &x, &current, iterations, progress, norm))
}

fn profile(
    problem: &Problem,
    x: &[f64],
    e: &Evaluation,
    iterations: usize,
    residual: f64,
    normalised_residual: f64,
) -> ChuteProfile {
    let n = problem.n();
    let grid = &problem.p.grid;
    let dy = grid.widths().to_vec();
    let column = |v: usize| (0..n).map(|j| x[VARS * j + v]).collect::<Vec<f64>>();
    let exp_column = |v: usize| column(v).iter().map(|z| z.exp()).collect::<Vec<f64>>();
    let eps_s = exp_column(EPS);
    let floor = &e.floor;
    let half_weight = |j: usize| 0.5 * problem.rho_s * problem.g_normal * eps_s[j] * dy[j];
    let u_wall = problem.p.floor.wall_velocity();
    ChuteProfile {
        y: grid.centres().iter().map(|c| c - grid.start()).collect(),
        floor: FloorDiagnostics {
            momentum: floor.momentum.diagnostics,
            theta: floor.theta.diagnostics,
            face_velocity: floor.u_face,
            slip: (floor.u_face - u_wall).abs(),
            face_theta: floor.theta_face,
            eps_s: problem.p.wall_treatment.wall_value(grid, &eps_s),
            viscosity: problem.p.wall_treatment.wall_value(grid, &e.mu_s),
            shear_stress: e.shear_flux[0],
            pressure: e.pressure[0] + half_weight(0),
            energy_flux_into_flow: -e.energy_flux[0],
        },
        lid_pressure: e.pressure[n - 1] - half_weight(n - 1),
        holdup: (0..n).map(|j| eps_s[j] * dy[j]).sum(),
        eps_s,
        u_s: column(U),
        theta: exp_column(THETA),
        pressure: e.pressure.clone(),
        mu_s: e.mu_s.clone(),
        shear_rate: e.shear_rate.clone(),
        production: e.production.clone(),
        dissipation: e.dissipation.clone(),
        dy,
        iterations,
        residual,
        normalised_residual,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn band_solver_matches_a_dense_solution() {
        // a 7×7 tridiagonal-plus system with a known solution, pivoting forced by a zero
        // diagonal entry
        let n = 7;
        let mut m = BandMatrix::new(n, 2, 2);
        let mut dense = vec![vec![0.0; n]; n];
        for i in 0..n {
            for j in i.saturating_sub(2)..=(i + 2).min(n - 1) {
                let value = if i == j && i == 3 {
                    0.0
                } else {
                    1.0 + (i * 3 + j * 5) as f64 % 7.0
                };
                m.add(i, j, value);
                dense[i][j] = value;
            }
        }
        let exact: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
        let rhs: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| dense[i][j] * exact[j]).sum())
            .collect();
        let mut systems = vec![rhs];
        m.solve_in_place(&mut systems).unwrap();
        for i in 0..n {
            assert!((systems[0][i] - exact[i]).abs() < 1e-12, "{:?}", systems[0]);
        }
    }

    #[test]
    fn harmonic_mean_of_equal_values_is_the_value() {
        assert!((harmonic_face_mean(2.5, 2.5, 0.3) - 2.5).abs() < 1e-15);
        // series resistances: Δ/Γ_f = Δ_a/Γ_a + Δ_b/Γ_b with w = Δ_b/(Δ_a + Δ_b)
        let (da, db, ga, gb) = (1.0, 3.0, 2.0, 5.0);
        let w = db / (da + db);
        let expected = (da + db) / (da / ga + db / gb);
        assert!((harmonic_face_mean(ga, gb, w) - expected).abs() < 1e-14);
    }
}
