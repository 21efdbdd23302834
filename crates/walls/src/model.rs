//! The solids wall models of the paper as Robin coefficients (docs/model.md §3.2–3.8).
//!
//! Per wall face, each outer iteration, the solver calls
//! - [`SolidsWallModel::momentum`] with a [`MomentumWallState`] for each solids tangential
//!   velocity component: it returns the [`RobinFace`] (g = 1, h = h_w^u, c = h_w^u U_w) and the
//!   diagnostics (h_w^u, φ, COL, FRI, slip);
//! - [`SolidsWallModel::granular_temperature`] with a [`ThetaWallState`]: the [`RobinFace`]
//!   (g, h_θ, c_θ) of κ ∂θ/∂n + h_θ θ = c_θ (JJ, Jenkins) or dθ/dn + h_θ(θ − θ_w) = c (user).
//!
//! Closure parameters (particles, gas, εs,max, εs,min, φ, g0 model, friction model) come from
//! [`ClosureParams`]; its drag law is not used: the wall routines estimate the drag in μ*, κ*
//! with Wen–Yu (docs/model.md §2.6 last bullet).

use crate::coefficients::{
    c_theta_jenkins, c_theta_johnson_jackson, collisional_jenkins, collisional_johnson_jackson,
    frictional, h_theta_jenkins, h_theta_johnson_jackson,
};
use crate::coulomb::{coulomb_momentum, CoulombWall};
use crate::error::{Checks, WallError};
use crate::face::RobinFace;
use crate::specularity::LiBenyahia;
use crate::state::{wall_theta, MomentumWallState, ThetaWallState, WALL_S_DDOT_S_FLOOR};
use runout_closures::drag::{dga_wall_wen_yu, DragInputs};
use runout_closures::guards::DIL_EP_S;
use runout_closures::kinetic::{lun_1984, GasCoupling, KineticStress, SolidsState};
use runout_closures::{ClosureParams, FrictionalStress, KineticJoin};
use serde::Serialize;

/// Particle–wall contact parameters shared by the Johnson–Jackson and Jenkins models.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct WallContact {
    /// particle–wall restitution e_w [-] (MFIX `E_W`; paper Table 3: 0.7)
    pub wall_restitution: f64,
    /// wall friction angle δ_w \[deg\] (MFIX `PHI_W`; paper Table 3: 11°)
    pub wall_friction_angle: f64,
    /// tan δ_w [-], converted once (style A6.13)
    pub tan_wall_friction: f64,
    /// wall velocity U_w [m/s] (MFIX `BC_UW_S`; 0 in the paper)
    pub wall_velocity: f64,
}

impl WallContact {
    /// Validated contact parameters: e_w ∈ [0, 1], δ_w ∈ [0, 90) degrees, U_w finite.
    pub fn new(
        wall_restitution: f64,
        wall_friction_angle: f64,
        wall_velocity: f64,
    ) -> Result<Self, WallError> {
        let mut checks = Checks::default();
        let wall_restitution = checks.check("wall_restitution", wall_restitution, "[0, 1]", |v| {
            (0.0..=1.0).contains(&v)
        });
        let wall_friction_angle = checks.check(
            "wall_friction_angle",
            wall_friction_angle,
            "[0, 90) degrees",
            |v| (0.0..90.0).contains(&v),
        );
        let wall_velocity = checks.check("u_w", wall_velocity, "(-inf, inf)", f64::is_finite);
        checks.finish(Some(Self {
            wall_restitution,
            wall_friction_angle,
            tan_wall_friction: wall_friction_angle.to_radians().tan(),
            wall_velocity,
        }))
    }
}

impl Default for WallContact {
    /// The paper's sensitivity values (paper Table 3): e_w = 0.7, δ_w = 11°, U_w = 0.
    fn default() -> Self {
        Self::new(0.7, 11.0, 0.0).expect("paper values are valid")
    }
}

/// User-set partial slip (paper Eqs. 12–13; MFIX PSW with `BC_JJ_PS = 0`) in MFIX's manual
/// units (docs/model.md §3.3): du/dn + h_u (u − U_w) = 0 and dθ/dn + h_θ (θ − θ_w) = c, with h in
/// m⁻¹ and c in m s⁻² — no conductivity factor, unlike the JJ flux form whose units the
/// paper's Table 1 prints (docs/model.md §3.10.6).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct UserPartialSlip {
    /// h_w^u [m⁻¹] (MFIX `BC_HW_S`)
    pub h_u: f64,
    /// U_w [m/s] (MFIX `BC_UW_S`)
    pub u_w: f64,
    /// h_w^θ [m⁻¹] (MFIX `BC_HW_THETA_M`)
    pub h_theta: f64,
    /// θ_w [m²/s²] (MFIX `BC_THETAW_M`)
    pub theta_w: f64,
    /// c_w [m s⁻²] (MFIX `BC_C_THETA_M`)
    pub c: f64,
}

impl UserPartialSlip {
    /// Validated user coefficients: h_u, h_θ ≥ 0, θ_w ≥ 0, U_w and c finite.
    pub fn new(h_u: f64, u_w: f64, h_theta: f64, theta_w: f64, c: f64) -> Result<Self, WallError> {
        let non_negative = |v: f64| v >= 0.0 && v.is_finite();
        let mut checks = Checks::default();
        let user = Self {
            h_u: checks.check("h_u", h_u, "[0, inf)", non_negative),
            u_w: checks.check("u_w", u_w, "(-inf, inf)", f64::is_finite),
            h_theta: checks.check("h_theta", h_theta, "[0, inf)", non_negative),
            theta_w: checks.check("theta_w", theta_w, "[0, inf)", non_negative),
            c: checks.check("c", c, "(-inf, inf)", f64::is_finite),
        };
        checks.finish(Some(user))
    }
}

/// How the specularity φ of a Johnson–Jackson wall is obtained.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum Specularity {
    /// a constant φ ∈ [0, 1] (MFIX `PHIP`)
    Constant(f64),
    /// Li & Benyahia's φ(r), r = |u_sl|/√(3θ) (MFIX `BC_JJ_M`, docs/model.md §3.7)
    LiBenyahia(LiBenyahia),
}

impl Specularity {
    /// φ at slip speed |u_sl| and (floored) θ > 0.
    #[inline]
    pub fn at(&self, slip: f64, theta: f64) -> f64 {
        match self {
            Self::Constant(phi) => *phi,
            Self::LiBenyahia(law) => law.specularity_at(slip, theta),
        }
    }
}

/// A solids wall condition (paper §2.2; docs/model.md §3), parameters validated.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum SolidsWallModel {
    /// MFIX NSW with `BC_JJ_PS = 0`: face velocity 0 (the wall velocity is ignored,
    /// docs/model.md §3.2 table); zero θ gradient (runout's case schema: zero granular-energy
    /// flux)
    NoSlip,
    /// MFIX FSW with `BC_JJ_PS = 0`: zero tangential stress, zero θ gradient
    FreeSlip,
    /// user-set partial slip, paper Eqs. 12–13 (docs/model.md §3.3)
    PartialSlip(UserPartialSlip),
    /// Johnson & Jackson (1987), `BC_JJ_PS = 1`, constant or Li–Benyahia specularity
    /// (docs/model.md §3.5–3.7)
    JohnsonJackson {
        /// φ or φ(r)
        specularity: Specularity,
        /// e_w, δ_w, U_w
        contact: WallContact,
    },
    /// Jenkins (1992) small-friction, all-sliding limit, `JENKINS = .TRUE.` (docs/model.md §3.8)
    Jenkins {
        /// e_w, δ_w, U_w
        contact: WallContact,
    },
    /// A Coulomb wall τ_w = μ_w P, regularised at zero slip (docs/model.md §3.11; not in MFIX)
    Coulomb(CoulombWall),
}

impl SolidsWallModel {
    /// User partial slip (paper Eqs. 12–13, MFIX manual units of docs/model.md §3.3).
    pub fn partial_slip(
        h_u: f64,
        u_w: f64,
        h_theta: f64,
        theta_w: f64,
        c: f64,
    ) -> Result<Self, WallError> {
        UserPartialSlip::new(h_u, u_w, h_theta, theta_w, c).map(Self::PartialSlip)
    }

    /// Johnson–Jackson with a constant specularity φ ∈ [0, 1] (paper Eqs. 14, 18–19).
    pub fn johnson_jackson(
        specularity: f64,
        wall_restitution: f64,
        wall_friction_angle: f64,
        u_w: f64,
    ) -> Result<Self, WallError> {
        let mut checks = Checks::default();
        let phi = checks.check("specularity", specularity, "[0, 1]", |v| {
            (0.0..=1.0).contains(&v)
        });
        let contact = checks.take(WallContact::new(wall_restitution, wall_friction_angle, u_w));
        checks.finish(contact.map(|contact| Self::JohnsonJackson {
            specularity: Specularity::Constant(phi),
            contact,
        }))
    }

    /// Revisited Johnson–Jackson: Li & Benyahia's φ(r) (paper Eqs. 16–17 in MFIX's continuous
    /// form, docs/model.md §3.7), φ₀ from k unless `phi0` is given (MFIX `PHIP0`).
    pub fn revisited_johnson_jackson(
        wall_restitution: f64,
        wall_friction_angle: f64,
        phi0: Option<f64>,
        u_w: f64,
    ) -> Result<Self, WallError> {
        let mut checks = Checks::default();
        let Some(contact) =
            checks.take(WallContact::new(wall_restitution, wall_friction_angle, u_w))
        else {
            // k needs a valid contact; the override is checked on its own
            checks.take(phi0.map_or(Ok(()), |v| LiBenyahia::check_override(v).map(|_| ())));
            return checks.finish(None);
        };
        let law = checks.take(LiBenyahia::new(
            contact.wall_restitution,
            contact.tan_wall_friction,
            phi0,
        ));
        checks.finish(law.map(|law| Self::JohnsonJackson {
            specularity: Specularity::LiBenyahia(law),
            contact,
        }))
    }

    /// Jenkins' small-friction, all-sliding limit (paper Eq. 20, docs/model.md §3.8).
    pub fn jenkins(
        wall_restitution: f64,
        wall_friction_angle: f64,
        u_w: f64,
    ) -> Result<Self, WallError> {
        Ok(Self::Jenkins {
            contact: WallContact::new(wall_restitution, wall_friction_angle, u_w)?,
        })
    }

    /// A Coulomb wall of friction coefficient μ_w with slip regularisation u_min [m s⁻¹]
    /// (docs/model.md §3.11).
    pub fn coulomb(friction: f64, slip_floor: f64) -> Result<Self, WallError> {
        CoulombWall::new(friction, slip_floor).map(Self::Coulomb)
    }

    /// The (momentum, θ) face closures of a state-independent condition (no-slip,
    /// free-slip, user partial slip: the faces [`SolidsWallModel::momentum`] and
    /// [`SolidsWallModel::granular_temperature`] return at any state); `None` for the
    /// state-dependent ones (Johnson–Jackson, revisited JJ, Jenkins), evaluated per face.
    pub fn fixed_faces(&self) -> Option<(RobinFace, RobinFace)> {
        match self {
            Self::NoSlip => Some((RobinFace::dirichlet(0.0), RobinFace::ZERO_GRADIENT)),
            Self::FreeSlip => Some((RobinFace::ZERO_GRADIENT, RobinFace::ZERO_GRADIENT)),
            Self::PartialSlip(user) => Some((
                RobinFace::partial_slip(user.h_u, user.u_w),
                RobinFace::user_theta(user.h_theta, user.theta_w, user.c),
            )),
            Self::JohnsonJackson { .. } | Self::Jenkins { .. } | Self::Coulomb(_) => None,
        }
    }

    /// A one-line description of the condition for the run's scene (`runout check
    /// --explain`), e.g. `Johnson–Jackson (φ = 0.1)`.
    pub fn describe(&self) -> String {
        match self {
            Self::NoSlip => "no-slip".into(),
            Self::FreeSlip => "free-slip".into(),
            Self::PartialSlip(p) => format!(
                "user partial slip (h_w^u = {} m⁻¹, h_w^θ = {} m⁻¹)",
                p.h_u, p.h_theta
            ),
            Self::JohnsonJackson {
                specularity: Specularity::Constant(phi),
                ..
            } => format!("Johnson–Jackson (φ = {phi})"),
            Self::JohnsonJackson {
                specularity: Specularity::LiBenyahia(_),
                ..
            } => "Johnson–Jackson revisited (Li–Benyahia φ(r))".into(),
            Self::Jenkins { .. } => "Jenkins".into(),
            Self::Coulomb(wall) => format!("Coulomb (μ_w = {})", wall.friction),
        }
    }

    /// K = τ_w/|u_sl| [Pa s m⁻¹] of this condition on the side walls of a channel of width
    /// `width`, with the solids profile flat across it (docs/model.md §8): free slip 0; user
    /// partial slip μ_s h_w^u; JJ, revisited JJ and Jenkins COL (+ FRI on the frictional
    /// branch) at `state`; Coulomb μ_w P/√(|u_sl|² + u_min²) at `state`; no slip, which a
    /// flat profile cannot meet, its parabolic limit 6 μ_s/W. Jenkins' COL overflows as
    /// |u_sl| → 0: the caller bounds K.
    pub fn side_wall_stress_per_slip(
        &self,
        state: &MomentumWallState,
        mu_s: f64,
        width: f64,
        params: &ClosureParams,
    ) -> f64 {
        match self {
            Self::FreeSlip => 0.0,
            Self::NoSlip => 6.0 * mu_s / width,
            Self::PartialSlip(user) => mu_s * user.h_u,
            Self::JohnsonJackson { .. } | Self::Jenkins { .. } | Self::Coulomb(_) => {
                let d = self.momentum(state, params).diagnostics;
                match d.branch {
                    MomentumBranch::Kinetic | MomentumBranch::Coulomb => d.col,
                    MomentumBranch::KineticFrictional => d.col + d.fri,
                    _ => 0.0,
                }
            }
        }
    }

    /// The factor from the θ face coefficients of [`SolidsWallModel::granular_temperature`]
    /// (h, c) to the wall's granular-energy flux q_w = factor (c − h θ): κ_s for the user
    /// partial slip, written in MFIX's manual units (docs/model.md §3.3); 1 for the flux
    /// form of JJ and Jenkins (§3.6, §3.8) and for the zero-flux walls.
    pub fn theta_flux_factor(&self, kappa_s: f64) -> f64 {
        match self {
            Self::PartialSlip(_) => kappa_s,
            _ => 1.0,
        }
    }

    /// Whether the wall's stress reads the solids' normal load beyond their pressure
    /// ([`MomentumWallState::extra_normal_load`]): the Coulomb wall (docs/model.md §3.11).
    /// MFIX's JJ and Jenkins read the pressure (their FRI's P_f − 2 μ_f S_nn, §3.5).
    pub fn reads_normal_traction(&self) -> bool {
        matches!(self, Self::Coulomb(_))
    }

    /// The solids wall velocity U_w [m/s] the slip speed is measured against (0 for no-slip
    /// and free-slip walls: MFIX NSW ignores it).
    pub fn wall_velocity(&self) -> f64 {
        match self {
            Self::NoSlip | Self::FreeSlip | Self::Coulomb(_) => 0.0,
            Self::PartialSlip(user) => user.u_w,
            Self::JohnsonJackson { contact, .. } | Self::Jenkins { contact } => {
                contact.wall_velocity
            }
        }
    }

    /// Robin coefficients of one solids tangential velocity on a wall face, g du/dn +
    /// h u_face = c (docs/model.md §3.2), and the diagnostics the paper plots.
    ///
    /// JJ and Jenkins follow docs/model.md §3.5 (MFIX `calc_grbdry.f` CALC_GRBDRY):
    /// 0. εs of the fluid cell ≤ `DIL_EP_S` (1e-4): free slip (step 6);
    /// 1. θ ≤ 0 → 1e-8; μ_k, P_k from Lun (1984) at the interpolated εs, θ with the Wen–Yu
    ///    DgA in μ* (dry if ρ_g = 0);
    /// 2. COL: JJ φ √(3θ) π ρs εs g0/(6 εs,max), φ = PHIP or φ(r); Jenkins tan δ_w P_k/|u_sl|;
    /// 3. Princeton friction and fluid-cell εs > εs,min: if the interpolated εs > εs,min too,
    ///    P_f, μ_f from docs/model.md §2.4.2 with S:S ≥ 1e-10 and FRI = tan δ_w (P_f − 2 μ_f S_nn),
    ///    else FRI = μ_f = 0; then h = 0 if |u_sl| = 0 (or ζ = 0), else
    ///    h = (COL + FRI)/(μ_k + μ_f) — FRI not divided by |u_sl|, as coded in MFIX;
    /// 4. otherwise h = COL/μ_k;
    /// 5. g = 1, c = h U_w.
    ///
    /// A state with μ_k + μ_f = 0 (no solids: εs = 0 with gas) returns h = 0, never 0/0. If
    /// Jenkins' COL overflows (|u_sl| ≲ 1e-290 P_k), h_w^u = +∞ and the face is the exact
    /// h → ∞ limit, u_face = U_w; the face coefficients are always finite.
    pub fn momentum(&self, state: &MomentumWallState, params: &ClosureParams) -> MomentumWall {
        match self {
            Self::NoSlip => {
                MomentumWall::fixed(RobinFace::dirichlet(0.0), MomentumBranch::NoSlip, state)
            }
            Self::FreeSlip => {
                MomentumWall::fixed(RobinFace::ZERO_GRADIENT, MomentumBranch::FreeSlip, state)
            }
            Self::PartialSlip(user) => MomentumWall::fixed(
                RobinFace::partial_slip(user.h_u, user.u_w),
                MomentumBranch::User,
                state,
            ),
            Self::JohnsonJackson {
                specularity,
                contact,
            } => kinetic_momentum(
                Collision::JohnsonJackson(*specularity),
                contact,
                state,
                params,
            ),
            Self::Jenkins { contact } => {
                kinetic_momentum(Collision::Jenkins, contact, state, params)
            }
            Self::Coulomb(wall) => coulomb_momentum(wall, state, params),
        }
    }

    /// Robin coefficients of θ on a wall face, g ∂θ/∂n + h θ_face = c (docs/model.md §3.2),
    /// and diagnostics.
    ///
    /// - no-slip, free-slip: zero gradient (g = 1, h = c = 0);
    /// - user partial slip: g = 1, h = h_θ, c = c_w + h_θ θ_w (docs/model.md §3.3, manual units);
    /// - JJ, Jenkins (docs/model.md §3.6, §3.8; MFIX `bc_theta.f`): zero gradient if the fluid
    ///   cell's εs ≤ `DIL_EP_S`; else, with θ ≤ 0 → 1e-8 and the fluid cell's εs, g0:
    ///   g = κ_s (Lun, Wen–Yu DgA in κ*), and
    ///   JJ h_θ = (π√3/(4 εs,max))(1 − e_w²) ρs εs g0 √θ,
    ///   c_θ = (π√3/(6 εs,max)) φ ρs εs g0 √θ |u_sl|² (φ(r) evaluated with this state's slip
    ///   and θ for the revisited model);
    ///   Jenkins h_θ = (3/8)√(3θ)(1 − e_w) P_k/θ, c_θ = (21/16) tan²δ_w (1 + e_w) √(3θ) P_k.
    ///   Units: h_θ in kg m⁻² s⁻¹, c_θ in kg s⁻³ (the paper's Table 1 units).
    pub fn granular_temperature(
        &self,
        state: &ThetaWallState,
        params: &ClosureParams,
    ) -> ThetaWall {
        let zero_gradient = |branch| ThetaWall {
            face: RobinFace::ZERO_GRADIENT,
            diagnostics: ThetaDiagnostics {
                branch,
                slip: state.slip,
                ..ThetaDiagnostics::default()
            },
        };
        let contact = match self {
            Self::NoSlip | Self::FreeSlip | Self::Coulomb(_) => {
                return zero_gradient(ThetaBranch::ZeroFlux)
            }
            Self::PartialSlip(user) => {
                return ThetaWall {
                    face: RobinFace::user_theta(user.h_theta, user.theta_w, user.c),
                    diagnostics: ThetaDiagnostics {
                        branch: ThetaBranch::User,
                        h_theta: user.h_theta,
                        c_theta: user.c,
                        slip: state.slip,
                        ..ThetaDiagnostics::default()
                    },
                }
            }
            Self::JohnsonJackson { contact, .. } | Self::Jenkins { contact } => contact,
        };
        if state.eps_s <= DIL_EP_S {
            return zero_gradient(ThetaBranch::DiluteZeroGradient);
        }
        let theta = wall_theta(state.theta);
        let solids = SolidsState::new(state.eps_s, theta, &params.particles, params.radial);
        let kinetic = lun_1984(
            &solids,
            wall_gas_coupling(state.eps_s, state.gas_slip, params),
        );
        let eps_s_max = params.friction.eps_s_max;
        let (h_theta, c_theta, specularity, branch) = match self {
            Self::JohnsonJackson { specularity, .. } => {
                let phi = specularity.at(state.slip, theta);
                (
                    h_theta_johnson_jackson(contact.wall_restitution, &solids, eps_s_max),
                    c_theta_johnson_jackson(phi, &solids, state.slip, eps_s_max),
                    Some(phi),
                    ThetaBranch::JohnsonJackson,
                )
            }
            _ => (
                h_theta_jenkins(contact.wall_restitution, theta, kinetic.p_kin),
                c_theta_jenkins(
                    contact.tan_wall_friction,
                    contact.wall_restitution,
                    theta,
                    kinetic.p_kin,
                ),
                None,
                ThetaBranch::Jenkins,
            ),
        };
        ThetaWall {
            face: RobinFace {
                g: kinetic.kappa_kin,
                h: h_theta,
                c: c_theta,
            },
            diagnostics: ThetaDiagnostics {
                branch,
                theta,
                kappa: kinetic.kappa_kin,
                h_theta,
                c_theta,
                specularity,
                slip: state.slip,
                p_kin: kinetic.p_kin,
            },
        }
    }
}

/// Which collisional term a kinetic wall model uses.
#[derive(Clone, Copy, Debug)]
enum Collision {
    JohnsonJackson(Specularity),
    Jenkins,
}

/// The gas coupling of μ*, κ* at a wall: dry if ρ_g = 0, else the Wen–Yu DgA at the wall
/// face with εg = 1 − εs (1e32 at zero relative speed) (docs/model.md §2.6 last bullet, §3.5
/// step 1; MFIX CALC_MU_SV_BDRY).
pub fn wall_gas_coupling(eps_s: f64, gas_slip: f64, params: &ClosureParams) -> GasCoupling {
    if params.gas.density == 0.0 {
        GasCoupling::Dry
    } else {
        GasCoupling::Drag(dga_wall_wen_yu(&DragInputs {
            eps_g: 1.0 - eps_s,
            rho_g: params.gas.density,
            mu_g: params.gas.viscosity,
            slip: gas_slip,
            d_p: params.particles.diameter,
        }))
    }
}

/// JJ / Jenkins momentum coefficient (docs/model.md §3.5 steps 1–6, §3.8).
fn kinetic_momentum(
    collision: Collision,
    contact: &WallContact,
    state: &MomentumWallState,
    params: &ClosureParams,
) -> MomentumWall {
    if state.eps_s_fluid <= DIL_EP_S {
        return MomentumWall {
            face: RobinFace::ZERO_GRADIENT,
            diagnostics: MomentumDiagnostics {
                branch: MomentumBranch::DiluteFreeSlip,
                slip: state.slip,
                ..MomentumDiagnostics::default()
            },
        };
    }
    let (theta, solids, kinetic) = wall_kinetics(state, params);
    let (col, specularity) = match collision {
        Collision::JohnsonJackson(law) => {
            let phi = law.at(state.slip, theta);
            let col = collisional_johnson_jackson(phi, &solids, params.friction.eps_s_max);
            (col, Some(phi))
        }
        Collision::Jenkins => (
            collisional_jenkins(contact.tan_wall_friction, kinetic.p_kin, state.slip),
            None,
        ),
    };
    let friction_acts = |eps_s| {
        params
            .friction_model
            .wall_friction_acts_at(eps_s, &params.friction)
    };
    let frictional_branch = friction_acts(state.eps_s_fluid);
    let mut diagnostics = MomentumDiagnostics {
        theta,
        specularity,
        col,
        slip: state.slip,
        mu_kin: kinetic.mu_kin,
        p_kin: kinetic.p_kin,
        ..MomentumDiagnostics::default()
    };
    let h = if frictional_branch {
        if friction_acts(state.eps_s) {
            // the Princeton or μ(I) stress: the models with wall friction
            let stress = diagnostics.add_wall_friction(state, params);
            diagnostics.fri = frictional(
                contact.tan_wall_friction,
                stress.p_fric,
                stress.mu_fric,
                state.s_nn,
            );
        }
        // ζ is only evaluated (and > 0 by the closures' θ floor) when friction is; MFIX's
        // "ζ = 0" test cannot fire then
        if state.slip == 0.0 {
            diagnostics.branch = MomentumBranch::ZeroSlip;
            0.0
        } else {
            diagnostics.branch = MomentumBranch::KineticFrictional;
            ratio_or_zero(diagnostics.col + diagnostics.fri, diagnostics.viscosity())
        }
    } else {
        diagnostics.branch = MomentumBranch::Kinetic;
        ratio_or_zero(col, kinetic.mu_kin)
    };
    diagnostics.h_u = h;
    // Jenkins' COL = tan δ_w P_k/|u_sl| overflows for |u_sl| ≲ 1e-290 P_k: h = +∞ is the
    // no-slip limit of the Robin face (relative to the wall), taken exactly
    let face = if h.is_finite() {
        RobinFace::partial_slip(h, contact.wall_velocity)
    } else {
        RobinFace::dirichlet(contact.wall_velocity)
    };
    MomentumWall { face, diagnostics }
}

/// The kinetic state at a wall (docs/model.md §3.5 step 1): θ ≤ 0 → 1e-8, the solids state
/// at the interpolated εs and Lun's (1984) stresses with the Wen–Yu DgA in μ* (dry if
/// ρ_g = 0).
pub(crate) fn wall_kinetics(
    state: &MomentumWallState,
    params: &ClosureParams,
) -> (f64, SolidsState, KineticStress) {
    let theta = wall_theta(state.theta);
    let solids = SolidsState::new(state.eps_s, theta, &params.particles, params.radial);
    let kinetic = lun_1984(
        &solids,
        wall_gas_coupling(state.eps_s, state.gas_slip, params),
    );
    (theta, solids, kinetic)
}

/// numerator/denominator, or 0 when the denominator is 0 (a viscosity that vanishes only
/// with the solids themselves: no wall stress).
#[inline]
pub(crate) fn ratio_or_zero(numerator: f64, denominator: f64) -> f64 {
    if denominator == 0.0 {
        0.0
    } else {
        numerator / denominator
    }
}

/// Which rule produced a momentum coefficient.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub enum MomentumBranch {
    /// no-slip wall: face value 0
    NoSlip,
    /// free-slip wall
    #[default]
    FreeSlip,
    /// user partial slip
    User,
    /// JJ/Jenkins next to a cell with εs ≤ `DIL_EP_S`: free slip (docs/model.md §3.5 step 6)
    DiluteFreeSlip,
    /// h = COL/μ_k (no Princeton friction, or fluid-cell εs ≤ εs,min)
    Kinetic,
    /// h = (COL + FRI)/μ_s, μ_s the joined viscosity (μ_k + μ_f but for μ(I))
    KineticFrictional,
    /// frictional branch at zero slip: h = 0 (docs/model.md §3.5 step 4)
    ZeroSlip,
    /// Coulomb wall: h = K/μ_s, K = μ_w P/√(|u_sl|² + u_min²) reported in `col`
    /// (docs/model.md §3.11)
    Coulomb,
}

/// Diagnostics of a momentum wall condition (the quantities of the paper's Table 2 and
/// Fig. 9). Zero where a model does not evaluate them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct MomentumDiagnostics {
    /// the rule applied
    pub branch: MomentumBranch,
    /// h_w^u [m⁻¹ for COL/μ; MFIX mixes in s⁻¹ through FRI]; +∞ for a no-slip wall (a
    /// Dirichlet face, printed as `null` in JSON)
    pub h_u: f64,
    /// specularity φ used [-] (JJ, revisited JJ); None otherwise
    pub specularity: Option<f64>,
    /// COL [Pa s/m]
    pub col: f64,
    /// FRI \[Pa\]
    pub fri: f64,
    /// slip speed |u_sl| [m/s]
    pub slip: f64,
    /// θ used, after the 1e-8 floor [m²/s²]
    pub theta: f64,
    /// μ_k at the wall (Wen–Yu μ*) [Pa s]
    pub mu_kin: f64,
    /// μ_f at the wall [Pa s]
    pub mu_fric: f64,
    /// P_k at the wall \[Pa\]
    pub p_kin: f64,
    /// P_f at the wall \[Pa\]
    pub p_fric: f64,
    /// N_w, the normal load a Coulomb wall's friction is proportional to (P_k + P_f and the
    /// load beyond them, docs/model.md §3.11) \[Pa\]; 0 for the other conditions
    pub normal_load: f64,
    /// Princeton strain scale ζ [1/s] (0 if friction was not evaluated)
    pub zeta: f64,
    /// how μ_k joins μ_f in the viscosity h divides by (the frictional model's)
    pub kinetic_join: KineticJoin,
}

impl MomentumDiagnostics {
    /// Evaluates the friction model's stress at the wall state (docs/model.md §3.5 step 3:
    /// S:S ≥ 1e-10, with this state's θ and P_k) and records μ_f, P_f, ζ and the join.
    pub(crate) fn add_wall_friction(
        &mut self,
        state: &MomentumWallState,
        params: &ClosureParams,
    ) -> FrictionalStress {
        let stress = params.friction_model.stress(
            state.eps_s,
            self.theta,
            params.particles.diameter,
            params.particles.density,
            state.tr_d,
            state.s_ddot_s.max(WALL_S_DDOT_S_FLOOR),
            self.p_kin,
            &params.friction,
        );
        self.mu_fric = stress.mu_fric;
        self.p_fric = stress.p_fric;
        self.zeta = stress.zeta;
        self.kinetic_join = stress.kinetic_join;
        stress
    }

    /// The solids viscosity the wall stress is expressed with, μ_k + μ_f (the μ(I) law's
    /// larger-of join, docs/model.md §2.4.4) [Pa s].
    pub fn viscosity(&self) -> f64 {
        self.kinetic_join.viscosity(self.mu_kin, self.mu_fric)
    }
}

/// A momentum wall condition: the face closure and its diagnostics.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MomentumWall {
    /// g du/dn + h u_face = c for the solids tangential velocity
    pub face: RobinFace,
    /// what the paper plots
    pub diagnostics: MomentumDiagnostics,
}

impl MomentumWall {
    /// The face with the solver's face viscosity Γ (the one its momentum assembly multiplies
    /// h by, docs/model.md §3.2): a Coulomb wall's h = K/Γ, so that the stress the face
    /// imposes is K u_face = μ_w P (docs/model.md §3.11); every other condition unchanged
    /// (MFIX forms JJ's and Jenkins' h with the wall routine's viscosity, §3.5 step 4).
    pub fn with_face_viscosity(mut self, gamma: f64) -> Self {
        if self.diagnostics.branch == MomentumBranch::Coulomb {
            let h = ratio_or_zero(self.diagnostics.col, gamma);
            self.diagnostics.h_u = h;
            self.face = RobinFace::partial_slip(h, 0.0);
        }
        self
    }

    /// A state-independent face (no-slip, free-slip, user), with the state's slip echoed.
    fn fixed(face: RobinFace, branch: MomentumBranch, state: &MomentumWallState) -> Self {
        Self {
            face,
            diagnostics: MomentumDiagnostics {
                branch,
                slip: state.slip,
                h_u: if face.g == 0.0 { f64::INFINITY } else { face.h },
                ..MomentumDiagnostics::default()
            },
        }
    }
}

/// Which rule produced a θ coefficient.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub enum ThetaBranch {
    /// no-slip or free-slip wall: zero flux
    #[default]
    ZeroFlux,
    /// user partial slip (manual units)
    User,
    /// JJ/Jenkins next to a cell with εs ≤ `DIL_EP_S`: θ_G = θ_F
    DiluteZeroGradient,
    /// Johnson–Jackson flux form
    JohnsonJackson,
    /// Jenkins flux form
    Jenkins,
}

/// Diagnostics of a θ wall condition. Zero where a model does not evaluate them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct ThetaDiagnostics {
    /// the rule applied
    pub branch: ThetaBranch,
    /// θ used, after the 1e-8 floor [m²/s²]
    pub theta: f64,
    /// g = κ_s of the BC routine [kg m⁻¹ s⁻¹] (JJ, Jenkins)
    pub kappa: f64,
    /// h_θ [kg m⁻² s⁻¹] (JJ, Jenkins) or [m⁻¹] (user)
    pub h_theta: f64,
    /// c_θ [kg s⁻³] (JJ, Jenkins) or c_w [m s⁻²] (user)
    pub c_theta: f64,
    /// specularity φ used [-] (JJ, revisited JJ)
    pub specularity: Option<f64>,
    /// slip speed |u_sl| [m/s]
    pub slip: f64,
    /// P_k of the fluid cell state \[Pa\]
    pub p_kin: f64,
}

/// A θ wall condition: the face closure and its diagnostics.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ThetaWall {
    /// g ∂θ/∂n + h θ_face = c
    pub face: RobinFace,
    /// coefficients in the paper's terms
    pub diagnostics: ThetaDiagnostics,
}
