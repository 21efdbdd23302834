//! The discrete equations of the 1-D chute (docs/model.md §1.2–1.3 reduced to 1-D, the
//! floor's Robin closures of docs/model.md §3.5–3.6): the residual of every row at given
//! unknowns, with the floor's own fixed point ([`floor_closure`]), and the hydrostatic
//! initial guess's bisection.

use super::*;

/// The floor closure at one state: both Robin faces and their face values, consistent with
/// each other (docs/model.md §3.5–3.6).
#[derive(Clone, Copy, Debug)]
pub(super) struct FloorClosure {
    pub(super) momentum: runout_walls::MomentumWall,
    pub(super) theta: runout_walls::ThetaWall,
    pub(super) u_face: f64,
    pub(super) theta_face: f64,
}

/// Evaluates the floor's momentum and θ conditions from the wall εs ([`WallTreatment`]), the
/// first cell's u, θ and width Δ, with the near-wall states of docs/model.md §3.5–3.6 in 1-D: εs
/// interpolated along x is the cell's own (MFIX); θ at the corner point is the mean of ghost and fluid θ (`corner_theta`), θ on
/// the face `face_theta`; the slip is |u_face − U_w|; the wall strain rate is
/// du/dy = (u₁ − u_G)/Δ with tr D = 0, S_nn = 0 (`WallStrain::planar_floor`). The ghost
/// values depend on the coefficients, which depend on the ghost values: MFIX lags them over
/// its outer iterations; at a steady state they are this fixed point.
pub(super) fn floor_closure(
    model: &SolidsWallModel,
    params: &ClosureParams,
    eps_s: f64,
    u: f64,
    theta: f64,
    delta: f64,
) -> FloorClosure {
    let u_wall = model.wall_velocity();
    let mut u_face = u;
    let mut theta_face = theta;
    let mut closure = None;
    for _ in 0..WALL_FIXED_POINT_MAX {
        let slip = (u_face - u_wall).abs();
        let u_ghost = 2.0 * u_face - u;
        let theta_ghost = 2.0 * theta_face - theta;
        let strain = WallStrain::planar_floor(0.0, (u - u_ghost) / delta, 0.0, 0.0);
        let momentum = model.momentum(
            &MomentumWallState {
                eps_s_fluid: eps_s,
                eps_s,
                theta: corner_theta(theta_ghost, theta),
                slip,
                gas_slip: 0.0,
                tr_d: strain.tr_d,
                s_ddot_s: strain.s_ddot_s,
                s_nn: strain.s_nn,
                extra_normal_load: 0.0,
            },
            params,
        );
        let theta_wall = model.granular_temperature(
            &ThetaWallState {
                eps_s,
                theta: face_theta(theta_ghost, theta),
                slip,
                gas_slip: 0.0,
            },
            params,
        );
        let new_u = momentum.face.face_value(u, delta);
        let new_theta = theta_wall.face.face_value(theta, delta);
        let change = ((new_u - u_face).abs() / (u.abs() + u_wall.abs()).max(f64::MIN_POSITIVE))
            .max((new_theta - theta_face).abs() / theta.abs().max(f64::MIN_POSITIVE));
        u_face = new_u;
        theta_face = new_theta;
        closure = Some((momentum, theta_wall));
        if change <= WALL_FIXED_POINT_TOL {
            break;
        }
    }
    let (momentum, theta) = closure.expect("at least one iteration");
    FloorClosure {
        momentum,
        theta,
        u_face,
        theta_face,
    }
}

/// Everything one residual evaluation computes.
pub(super) struct Evaluation {
    pub(super) residual: Vec<f64>,
    /// Σ|terms| of each row, for the normalised residual
    pub(super) scale: Vec<f64>,
    pub(super) floor: FloorClosure,
    pub(super) pressure: Vec<f64>,
    pub(super) mu_s: Vec<f64>,
    pub(super) production: Vec<f64>,
    pub(super) dissipation: Vec<f64>,
    pub(super) shear_rate: Vec<f64>,
    pub(super) shear_flux: Vec<f64>,
    pub(super) energy_flux: Vec<f64>,
}

/// The discrete problem: parameters plus derived constants.
pub(super) struct Problem<'a> {
    pub(super) p: &'a ChuteParams,
    pub(super) rho_s: f64,
    pub(super) g_normal: f64,
    pub(super) g_tangential: f64,
}

impl<'a> Problem<'a> {
    pub(super) fn new(p: &'a ChuteParams) -> Self {
        let alpha = p.slope_deg.to_radians();
        Self {
            p,
            rho_s: p.closures.particles.density,
            g_normal: p.gravity * alpha.cos(),
            g_tangential: p.gravity * alpha.sin(),
        }
    }

    pub(super) fn n(&self) -> usize {
        self.p.grid.len()
    }

    /// Closures of one cell at (εs, θ) and shear rate du/dy: tr D = 0, S:S = ½ (du/dy)²
    /// (module docs). Returns (P_s + P*, μ_s, κ_s, Π, γ).
    pub(super) fn cell(
        &self,
        eps_s: f64,
        theta: f64,
        shear_rate: f64,
    ) -> (f64, f64, f64, f64, f64) {
        let set = evaluate(
            &CellState {
                eps_s,
                theta,
                slip: 0.0,
                tr_d: 0.0,
                s_ddot_s: 0.5 * shear_rate * shear_rate,
            },
            &self.p.closures,
        );
        (
            set.stress.p_s + set.stress.p_star,
            set.stress.mu_s,
            set.kinetic.kappa_kin,
            set.production,
            set.kinetic.dissipation,
        )
    }

    /// Residuals of every row at the unknowns `x` = (ln εs, u, ln θ) per cell (module docs):
    /// y-momentum on face j + ½ in row (j, εs) for j < N − 1 and the holdup in row (N − 1, εs);
    /// x-momentum and granular energy of cell j in rows (j, u), (j, θ).
    pub(super) fn evaluate(&self, x: &[f64]) -> Evaluation {
        let n = self.n();
        let grid = &self.p.grid;
        let dy = grid.widths();
        let eps_s: Vec<f64> = (0..n).map(|j| x[VARS * j + EPS].exp()).collect();
        let eps = |j: usize| eps_s[j];
        let u: Vec<f64> = (0..n).map(|j| x[VARS * j + U]).collect();
        let theta: Vec<f64> = (0..n).map(|j| x[VARS * j + THETA].exp()).collect();

        let treatment = self.p.wall_treatment;
        let floor = floor_closure(
            &self.p.floor,
            &self.p.closures,
            treatment.wall_value(grid, &eps_s),
            u[0],
            theta[0],
            dy[0],
        );
        // face velocities: floor from the Robin closure, interior AVG_Y, lid zero gradient
        let mut u_face = vec![0.0; n + 1];
        u_face[0] = floor.u_face;
        for f in 1..n {
            let w = grid.interpolation_weight(f - 1);
            u_face[f] = w * u[f - 1] + (1.0 - w) * u[f];
        }
        u_face[n] = u[n - 1];

        let mut pressure = vec![0.0; n];
        let mut mu_s = vec![0.0; n];
        let mut kappa = vec![0.0; n];
        let mut production = vec![0.0; n];
        let mut dissipation = vec![0.0; n];
        let mut shear_rate = vec![0.0; n];
        for j in 0..n {
            shear_rate[j] = (u_face[j + 1] - u_face[j]) / dy[j];
            let (p, mu, k, pi, gamma) = self.cell(eps(j), theta[j], shear_rate[j]);
            pressure[j] = p;
            mu_s[j] = mu;
            kappa[j] = k;
            production[j] = pi;
            dissipation[j] = gamma;
        }
        let shear_flux = diffusive_fluxes(grid, &mu_s, &u, &floor.momentum.face, treatment);
        let energy_flux = diffusive_fluxes(grid, &kappa, &theta, &floor.theta.face, treatment);

        let mut residual = vec![0.0; VARS * n];
        let mut scale = vec![0.0; VARS * n];
        let rho = self.rho_s;
        for j in 0..n {
            let row = VARS * j;
            if j + 1 < n {
                let weight = 0.5 * rho * self.g_normal * (eps(j) * dy[j] + eps(j + 1) * dy[j + 1]);
                residual[row + EPS] = pressure[j] - pressure[j + 1] - weight;
                scale[row + EPS] = pressure[j].abs() + pressure[j + 1].abs() + weight.abs();
            } else {
                let holdup: f64 = (0..n).map(|k| eps(k) * dy[k]).sum();
                residual[row + EPS] = holdup - self.p.holdup;
                scale[row + EPS] = self.p.holdup;
            }
            let body = rho * eps(j) * self.g_tangential * dy[j];
            // the side walls' width-averaged friction and θ flux (docs/model.md §8)
            let side = self.p.sidewalls.map(|w| {
                w.load(
                    &self.p.closures,
                    (eps(j), u[j], theta[j]),
                    shear_rate[j],
                    (mu_s[j], kappa[j]),
                )
            });
            let (side_drag, side_gain, side_loss) = side.map_or((0.0, 0.0, 0.0), |s| {
                (s.momentum, s.generation, s.dissipation)
            });
            residual[row + U] = shear_flux[j + 1] - shear_flux[j] + body - side_drag * dy[j];
            scale[row + U] = shear_flux[j + 1].abs()
                + shear_flux[j].abs()
                + body.abs()
                + side_drag.abs() * dy[j];
            let net_source = (production[j] - dissipation[j] + side_gain - side_loss) * dy[j];
            residual[row + THETA] = energy_flux[j + 1] - energy_flux[j] + net_source;
            scale[row + THETA] = energy_flux[j + 1].abs()
                + energy_flux[j].abs()
                + (production[j] + dissipation[j] + side_gain + side_loss) * dy[j];
        }
        Evaluation {
            residual,
            scale,
            floor,
            pressure,
            mu_s,
            production,
            dissipation,
            shear_rate,
            shear_flux,
            energy_flux,
        }
    }

    /// Hydrostatic εs profile for given θ and zero shear (the initial guess): εs of the top
    /// cell is bisected until Σ εs Δy = M, each lower cell's εs bisected so that its y-momentum
    /// face balances (docs/model.md §1.2 with ∂/∂x = 0).
    pub(super) fn hydrostatic_eps(&self, theta: &[f64], shear_rate: &[f64]) -> Vec<f64> {
        let n = self.n();
        let dy = self.p.grid.widths();
        let half_weight = |j: usize, e: f64| 0.5 * self.rho_s * self.g_normal * e * dy[j];
        let march = |top: f64| -> Vec<f64> {
            let mut eps = vec![0.0; n];
            eps[n - 1] = top;
            for j in (0..n - 1).rev() {
                let above = self.cell(eps[j + 1], theta[j + 1], shear_rate[j + 1]).0
                    + half_weight(j + 1, eps[j + 1]);
                let balance =
                    |e: f64| self.cell(e, theta[j], shear_rate[j]).0 - half_weight(j, e) - above;
                eps[j] = bisect(balance, 0.0, EPS_S_BRACKET_TOP);
            }
            eps
        };
        let holdup = |eps: &[f64]| (0..n).map(|j| eps[j] * dy[j]).sum::<f64>();
        let top = bisect(
            |t| holdup(&march(t)) - self.p.holdup,
            0.0,
            EPS_S_BRACKET_TOP,
        );
        march(top)
    }
}

/// Root of an increasing-at-the-root function on [lo, hi] by bisection ([`BISECTION_STEPS`]);
/// returns the end nearest the sign change if there is none.
pub(super) fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    for _ in 0..BISECTION_STEPS {
        let mid = 0.5 * (lo + hi);
        if f(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}
