//! The solids wall condition as a case file writes it (`solids: JohnsonJackson(...)`), the one
//! wall type from the RON file to the face coefficients: the case crate reads and writes it,
//! `runout wall` builds it from its options, and [`SolidsWall::model`] turns it into the
//! [`SolidsWallModel`] the solver evaluates — through the validated constructors, the only
//! validation of its parameters.

use runout_mesh::short;
use serde::{Deserialize, Serialize};

use crate::coulomb::DEFAULT_SLIP_FLOOR;
use crate::error::WallError;
use crate::model::SolidsWallModel;

/// Solids condition on a wall: the paper's subject (paper §2.2, docs/model.md §3).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum SolidsWall {
    /// Zero solids velocity on the wall; zero granular-energy flux (MFIX NSW, `BC_JJ_PS = 0`).
    NoSlip,
    /// Zero tangential stress; zero granular-energy flux (MFIX FSW, `BC_JJ_PS = 0`).
    FreeSlip,
    /// User-set partial slip (paper Eqs. 12–13, MFIX PSW with `BC_JJ_PS = 0`):
    /// du/dn + h_u (u − u_w) = 0 and dθ/dn + h_θ (θ − θ_w) = c, both in MFIX's manual
    /// units (docs/model.md §3.3): h in m⁻¹, c in m s⁻² (no conductivity factor).
    PartialSlip {
        /// h_w^u [m⁻¹] (MFIX `BC_HW_S`)
        h_u: f64,
        /// wall velocity U_w [m s⁻¹] (MFIX `BC_UW_S`)
        #[serde(default)]
        u_w: f64,
        /// h_w^θ [m⁻¹] (MFIX `BC_HW_THETA_M`)
        h_theta: f64,
        /// θ_w [m² s⁻²] (MFIX `BC_THETAW_M`)
        theta_w: f64,
        /// c_w [m s⁻²] (MFIX `BC_C_THETA_M`)
        c: f64,
    },
    /// Johnson & Jackson (1987) with a constant specularity (paper Eqs. 14, 18–19;
    /// docs/model.md §3.5–3.6).
    JohnsonJackson {
        /// specularity coefficient φ [-] (MFIX `PHIP`)
        specularity: f64,
        /// particle–wall restitution e_w [-] (MFIX `E_W`)
        wall_restitution: f64,
        /// wall friction angle δ_w [deg] (MFIX `PHI_W`)
        wall_friction_angle: f64,
        /// wall velocity [m s⁻¹] (MFIX `BC_UW_S`)
        #[serde(default)]
        u_w: f64,
    },
    /// Johnson–Jackson with Li & Benyahia's (2012) specularity φ(r), the paper's
    /// "revisited JJ" (paper Eqs. 16–17 as MFIX codes them, docs/model.md §3.7).
    RevisitedJohnsonJackson {
        /// particle–wall restitution e_w [-]
        wall_restitution: f64,
        /// wall friction angle δ_w [deg]
        wall_friction_angle: f64,
        /// φ₀ override (MFIX `PHIP0`); computed from k when absent
        #[serde(default)]
        phi0: Option<f64>,
        /// wall velocity [m s⁻¹]
        #[serde(default)]
        u_w: f64,
    },
    /// Jenkins (1992) small-friction, all-sliding limit (paper Eq. 20, docs/model.md §3.8).
    Jenkins {
        /// particle–wall restitution e_w [-]
        wall_restitution: f64,
        /// wall friction angle δ_w [deg]
        wall_friction_angle: f64,
        /// wall velocity [m s⁻¹]
        #[serde(default)]
        u_w: f64,
    },
    /// A Coulomb wall τ_w = μ_w P at rest, regularised at zero slip (docs/model.md §3.11; not
    /// in MFIX): the side walls of a glass channel (Jop, Forterre & Pouliquen 2005).
    Coulomb {
        /// grain–wall friction coefficient μ_w = tan δ_w [-]
        friction: f64,
        /// slip-speed regularisation u_min [m s⁻¹]; 1e-4 when absent
        #[serde(default)]
        slip_floor: Option<f64>,
    },
}

impl SolidsWall {
    /// The wall model, its parameters checked by the validated constructors (every
    /// out-of-range field in the error, named as in the case file).
    pub fn model(&self) -> Result<SolidsWallModel, WallError> {
        match *self {
            Self::NoSlip => Ok(SolidsWallModel::NoSlip),
            Self::FreeSlip => Ok(SolidsWallModel::FreeSlip),
            Self::PartialSlip {
                h_u,
                u_w,
                h_theta,
                theta_w,
                c,
            } => SolidsWallModel::partial_slip(h_u, u_w, h_theta, theta_w, c),
            Self::JohnsonJackson {
                specularity,
                wall_restitution,
                wall_friction_angle,
                u_w,
            } => SolidsWallModel::johnson_jackson(
                specularity,
                wall_restitution,
                wall_friction_angle,
                u_w,
            ),
            Self::RevisitedJohnsonJackson {
                wall_restitution,
                wall_friction_angle,
                phi0,
                u_w,
            } => SolidsWallModel::revisited_johnson_jackson(
                wall_restitution,
                wall_friction_angle,
                phi0,
                u_w,
            ),
            Self::Jenkins {
                wall_restitution,
                wall_friction_angle,
                u_w,
            } => SolidsWallModel::jenkins(wall_restitution, wall_friction_angle, u_w),
            Self::Coulomb {
                friction,
                slip_floor,
            } => SolidsWallModel::coulomb(friction, slip_floor.unwrap_or(DEFAULT_SLIP_FLOOR)),
        }
    }

    /// The numeric parameters as written, by their case-file names (for the case's
    /// plausibility bands, docs/reference/input-validation.md); an absent `phi0` is left out.
    pub fn parameters(&self) -> Vec<(&'static str, f64)> {
        match *self {
            Self::NoSlip | Self::FreeSlip => vec![],
            Self::PartialSlip {
                h_u,
                u_w,
                h_theta,
                theta_w,
                c,
            } => vec![
                ("h_u", h_u),
                ("u_w", u_w),
                ("h_theta", h_theta),
                ("theta_w", theta_w),
                ("c", c),
            ],
            Self::JohnsonJackson {
                specularity,
                wall_restitution,
                wall_friction_angle,
                u_w,
            } => vec![
                ("specularity", specularity),
                ("wall_restitution", wall_restitution),
                ("wall_friction_angle", wall_friction_angle),
                ("u_w", u_w),
            ],
            Self::RevisitedJohnsonJackson {
                wall_restitution,
                wall_friction_angle,
                phi0,
                u_w,
            } => [
                ("wall_restitution", Some(wall_restitution)),
                ("wall_friction_angle", Some(wall_friction_angle)),
                ("phi0", phi0),
                ("u_w", Some(u_w)),
            ]
            .into_iter()
            .filter_map(|(name, v)| v.map(|v| (name, v)))
            .collect(),
            Self::Jenkins {
                wall_restitution,
                wall_friction_angle,
                u_w,
            } => vec![
                ("wall_restitution", wall_restitution),
                ("wall_friction_angle", wall_friction_angle),
                ("u_w", u_w),
            ],
            Self::Coulomb {
                friction,
                slip_floor,
            } => [("friction", Some(friction)), ("slip_floor", slip_floor)]
                .into_iter()
                .filter_map(|(name, v)| v.map(|v| (name, v)))
                .collect(),
        }
    }

    /// The wall velocity U_w as written [m s⁻¹] (0 for no-slip and free-slip walls).
    pub fn wall_velocity(&self) -> f64 {
        self.parameters()
            .into_iter()
            .find_map(|(name, v)| (name == "u_w").then_some(v))
            .unwrap_or(0.0)
    }

    /// A short label for case names and messages, e.g. `jj-phi0.1`, `jenkins`.
    pub fn label(&self) -> String {
        match self {
            Self::NoSlip => "noslip".into(),
            Self::FreeSlip => "freeslip".into(),
            Self::PartialSlip {
                h_u, h_theta, c, ..
            } => {
                format!(
                    "ps-hu{}-htheta{}-c{}",
                    short(*h_u),
                    short(*h_theta),
                    short(*c)
                )
            }
            Self::JohnsonJackson { specularity, .. } => {
                format!("jj-phi{}", short(*specularity))
            }
            Self::RevisitedJohnsonJackson { .. } => "rjj".into(),
            Self::Jenkins { .. } => "jenkins".into(),
            Self::Coulomb { friction, .. } => format!("coulomb-mu{}", short(*friction)),
        }
    }

    /// The kinds of condition by their `runout wall --model` names, and a condition of
    /// each kind built from named parameters ([`SolidsWall::parameters`] names).
    pub const KINDS: [&'static str; 7] = [
        "no-slip",
        "free-slip",
        "partial-slip",
        "johnson-jackson",
        "revisited-jj",
        "jenkins",
        "coulomb",
    ];

    /// The condition of kind `kind` (one of [`SolidsWall::KINDS`]) with its parameters from
    /// `param` (case-file names, [`SolidsWall::parameters`]); `Err` names the first required
    /// parameter that `param` lacks, or says the kind is unknown.
    pub fn from_parameters(
        kind: &str,
        param: impl Fn(&'static str) -> Option<f64>,
    ) -> Result<Self, MissingParameter> {
        let need = |name: &'static str| param(name).ok_or(MissingParameter::Field(name));
        Ok(match kind {
            "no-slip" => Self::NoSlip,
            "free-slip" => Self::FreeSlip,
            "partial-slip" => Self::PartialSlip {
                h_u: need("h_u")?,
                u_w: need("u_w")?,
                h_theta: need("h_theta")?,
                theta_w: need("theta_w")?,
                c: need("c")?,
            },
            "johnson-jackson" => Self::JohnsonJackson {
                specularity: need("specularity")?,
                wall_restitution: need("wall_restitution")?,
                wall_friction_angle: need("wall_friction_angle")?,
                u_w: need("u_w")?,
            },
            "revisited-jj" => Self::RevisitedJohnsonJackson {
                wall_restitution: need("wall_restitution")?,
                wall_friction_angle: need("wall_friction_angle")?,
                phi0: param("phi0"),
                u_w: need("u_w")?,
            },
            "jenkins" => Self::Jenkins {
                wall_restitution: need("wall_restitution")?,
                wall_friction_angle: need("wall_friction_angle")?,
                u_w: need("u_w")?,
            },
            "coulomb" => Self::Coulomb {
                friction: need("friction")?,
                slip_floor: param("slip_floor"),
            },
            other => return Err(MissingParameter::Kind(other.to_string())),
        })
    }
}

/// What [`SolidsWall::from_parameters`] lacks.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum MissingParameter {
    /// a required parameter (case-file name) was not given
    #[error("needs `{0}`")]
    Field(&'static str),
    /// not one of [`SolidsWall::KINDS`]
    #[error("unknown wall condition `{0}`")]
    Kind(String),
}
