//! `runout wall`: the wall-condition calculator (issue 4). Evaluates one solids wall model of
//! docs/model.md §3 (runout-walls) at one near-wall state and prints the Robin coefficients of
//! the solids tangential velocity and of θ, with the diagnostics the paper plots
//! (h_w^u, φ, COL, FRI, slip), as pretty JSON.

use anyhow::{anyhow, ensure};
use clap::builder::PossibleValuesParser;
use runout_closures::{ClosureParams, Drag};
use runout_walls::{
    MissingParameter, MomentumWall, MomentumWallState, SolidsWall, SolidsWallModel, ThetaWall,
    ThetaWallState,
};
use serde::Serialize;
use std::io::Write;

use crate::material::MaterialArgs;

/// θ_w assumed for the user partial-slip θ condition when `--theta-w` is not given
/// [m²/s²]: the value of the paper's Fig. 1 (shared/docs/cases.md, units note).
const DEFAULT_THETA_W: f64 = 0.01;

/// Field names of the JSON output, shown by `runout wall --help`.
const OUTPUT_FIELDS: &str = "\
OUTPUT (JSON, SI units):
  inputs                     the near-wall state and parameters used (echo of the options)
  model                      the wall model with its validated parameters
  momentum.face.{g,h,c}      g du/dn + h u_face = c for the solids tangential velocity
                             (n from the fluid into the wall; g = 1, c = h U_w)
  momentum.diagnostics       branch, h_u [1/m] (null = infinite: no-slip), specularity [-],
                             col [Pa s/m], fri [Pa], slip [m/s], theta (after the floor),
                             mu_kin, mu_fric [Pa s], p_kin, p_fric [Pa], zeta [1/s]
  granular_temperature.face.{g,h,c}
                             g dtheta/dn + h theta_face = c: JJ/Jenkins g = kappa [kg/(m s)],
                             h [kg/(m2 s)], c [kg/s3]; user partial slip g = 1, h [1/m],
                             c = c_w + h theta_w
  granular_temperature.diagnostics
                             branch, theta, kappa, h_theta, c_theta, specularity, slip, p_kin
The momentum condition uses --eps-s (interpolated at the velocity face) and --eps-s-fluid
(the fluid cell: dilute skip and friction test); the theta condition uses --eps-s-fluid.
Sources: docs/model.md §3; rustdoc of runout-walls.";

/// Print the Robin coefficients and diagnostics of one solids wall model at one near-wall
/// state as JSON. Material defaults are the paper's sensitivity-analysis values (paper
/// Table 3: d = 0.5 mm, rho_s = 2000, e = 0.9, e_w = 0.7, wall friction 11 deg, internal
/// friction 35 deg, eps_s,max = 0.65, air).
#[derive(clap::Args, Debug, Clone)]
#[command(after_help = OUTPUT_FIELDS)]
pub struct WallArgs {
    /// solids wall condition (paper §2.2, docs/model.md §3): no-slip, free-slip (zero theta
    /// flux), partial-slip (paper Eqs. 12-13: --h-u, --h-theta, --c-theta, --theta-w),
    /// johnson-jackson (constant --specularity), revisited-jj (Li & Benyahia's phi(r),
    /// optional --phi0), jenkins (small-friction, all-sliding limit), coulomb (tau_w =
    /// --coulomb-friction P, regularised by --slip-floor; not in MFIX)
    #[arg(long, value_parser = PossibleValuesParser::new(SolidsWall::KINDS))]
    pub model: String,
    /// specularity coefficient phi [-] (johnson-jackson; MFIX PHIP)
    #[arg(long)]
    pub specularity: Option<f64>,
    /// phi0 override for revisited-jj (MFIX PHIP0); computed from k when absent
    #[arg(long)]
    pub phi0: Option<f64>,
    /// Coulomb wall friction coefficient mu_w = tan delta_w [-] (coulomb; the case file's
    /// `friction`)
    #[arg(long)]
    pub coulomb_friction: Option<f64>,
    /// Coulomb wall slip regularisation u_min [m/s] (coulomb; default 1e-4)
    #[arg(long)]
    pub slip_floor: Option<f64>,
    /// particle-wall restitution e_w [-]
    #[arg(long, default_value_t = 0.7)]
    pub wall_restitution: f64,
    /// wall friction angle delta_w [degrees]
    #[arg(long, default_value_t = 11.0)]
    pub wall_friction_angle: f64,
    /// wall velocity U_w [m/s] (slip is measured against it)
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub u_w: f64,
    /// partial-slip h_w^u [1/m] (MFIX BC_HW_S)
    #[arg(long)]
    pub h_u: Option<f64>,
    /// partial-slip h_w^theta [1/m] (MFIX BC_HW_THETA_M, manual units)
    #[arg(long)]
    pub h_theta: Option<f64>,
    /// partial-slip c_w [m/s2] (MFIX BC_C_THETA_M, manual units)
    #[arg(long, allow_negative_numbers = true)]
    pub c_theta: Option<f64>,
    /// partial-slip theta_w [m2/s2] (MFIX BC_THETAW_M; default 0.01, assumed in cases.md)
    #[arg(long)]
    pub theta_w: Option<f64>,
    /// solids fraction at the wall velocity face (interpolated) [-]
    #[arg(long)]
    pub eps_s: f64,
    /// solids fraction of the fluid cell next to the wall [-] (default: --eps-s)
    #[arg(long)]
    pub eps_s_fluid: Option<f64>,
    /// granular temperature at the wall [m2/s2] (values <= 0 become 1e-8, as in MFIX)
    #[arg(long, allow_negative_numbers = true)]
    pub theta: f64,
    /// solids slip speed |u_s - U_w| at the wall face [m/s]
    #[arg(long, default_value_t = 0.0)]
    pub slip: f64,
    /// gas-solids relative speed |u_g - u_s| at the wall face [m/s] (Wen-Yu drag in mu*,
    /// kappa*). Default: |--slip + --u-w|, the gas at rest on the wall (gas no-slip, as on
    /// the paper's floor). Exactly 0 triggers MFIX's DgA = 1e32, i.e. mu* = kappa* = 0
    #[arg(long)]
    pub gas_slip: Option<f64>,
    /// solids dilatation tr D at the wall [1/s]
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub tr_d: f64,
    /// S:S = tr(D^2) - (tr D)^2/3 at the wall [1/s2] (floored at 1e-10 inside, as in MFIX)
    #[arg(long, default_value_t = 0.0)]
    pub s_ddot_s: f64,
    /// normal-normal deviatoric strain rate S_nn = D_nn - tr D/3 at the wall [1/s]
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub s_nn: f64,
    /// particle, gas and closure options (the frictional wall term FRI needs princeton)
    #[command(flatten)]
    pub material: MaterialArgs,
}

/// The echoed inputs of the JSON output.
#[derive(Serialize)]
struct Inputs<'a> {
    model: &'a str,
    momentum_state: MomentumWallState,
    theta_state: ThetaWallState,
    material: &'a MaterialArgs,
}

#[derive(Serialize)]
struct Output<'a> {
    inputs: Inputs<'a>,
    model: SolidsWallModel,
    momentum: MomentumWall,
    granular_temperature: ThetaWall,
}

impl WallArgs {
    /// Reject states and parameters outside the models' validity ranges.
    fn validate(&self) -> anyhow::Result<()> {
        for (name, eps) in [
            ("--eps-s", self.eps_s),
            ("--eps-s-fluid", self.eps_s_fluid()),
        ] {
            ensure!(
                (0.0..1.0).contains(&eps),
                "{name} must be in [0, 1), got {eps}"
            );
        }
        ensure!(self.theta.is_finite(), "--theta must be finite");
        for (name, v) in [
            ("--slip", self.slip),
            ("--gas-slip", self.gas_slip()),
            ("--s-ddot-s", self.s_ddot_s),
        ] {
            ensure!(v >= 0.0 && v.is_finite(), "{name} must be >= 0, got {v}");
        }
        ensure!(
            self.tr_d.is_finite() && self.s_nn.is_finite(),
            "--tr-d, --s-nn must be finite"
        );
        self.material.validate()
    }

    fn eps_s_fluid(&self) -> f64 {
        self.eps_s_fluid.unwrap_or(self.eps_s)
    }

    /// |u_g − u_s| at the wall face; with the gas at rest on the wall (u_g,face = 0) and the
    /// solids face velocity U_w + slip (one tangential component) it is |slip + U_w|.
    fn gas_slip(&self) -> f64 {
        self.gas_slip.unwrap_or((self.slip + self.u_w).abs())
    }

    /// The wall condition of `--model` with its options, as a case file would write it.
    fn spec(&self) -> anyhow::Result<SolidsWall> {
        SolidsWall::from_parameters(&self.model, |name| self.parameter(name)).map_err(|e| match e {
            MissingParameter::Field(name) => {
                anyhow!("--model {} needs {}", self.model, option_of(name))
            }
            kind => anyhow!("--model: {kind}"),
        })
    }

    /// The option of a wall parameter ([`SolidsWall::parameters`] names), with its default.
    fn parameter(&self, name: &str) -> Option<f64> {
        match name {
            "specularity" => self.specularity,
            "phi0" => self.phi0,
            "wall_restitution" => Some(self.wall_restitution),
            "wall_friction_angle" => Some(self.wall_friction_angle),
            "u_w" => Some(self.u_w),
            "h_u" => self.h_u,
            "h_theta" => self.h_theta,
            "theta_w" => Some(self.theta_w.unwrap_or(DEFAULT_THETA_W)),
            "c" => self.c_theta,
            "friction" => self.coulomb_friction,
            "slip_floor" => self.slip_floor,
            _ => None,
        }
    }

    /// The wall model, its parameters validated by runout-walls.
    fn model(&self) -> anyhow::Result<SolidsWallModel> {
        Ok(self.spec()?.model()?)
    }

    fn params(&self) -> ClosureParams {
        // the drag law is not used by the wall models (they estimate drag with Wen-Yu,
        // docs/model.md §2.6)
        self.material.params(Drag::default())
    }
}

/// The option that sets a wall parameter ([`SolidsWall::parameters`] names).
fn option_of(name: &str) -> String {
    match name {
        "c" => "--c-theta".into(),
        "friction" => "--coulomb-friction".into(),
        other => format!("--{}", other.replace('_', "-")),
    }
}

/// Run `runout wall`: validate the options, evaluate the wall model's momentum and
/// granular-temperature conditions and print them to stdout as pretty JSON (field names in
/// the `--help` text).
pub fn run(args: &WallArgs) -> anyhow::Result<()> {
    args.validate()?;
    let model = args.model()?;
    let params = args.params();
    let momentum_state = MomentumWallState {
        eps_s_fluid: args.eps_s_fluid(),
        eps_s: args.eps_s,
        theta: args.theta,
        slip: args.slip,
        gas_slip: args.gas_slip(),
        tr_d: args.tr_d,
        s_ddot_s: args.s_ddot_s,
        s_nn: args.s_nn,
        extra_normal_load: 0.0,
    };
    let theta_state = ThetaWallState {
        eps_s: args.eps_s_fluid(),
        theta: args.theta,
        slip: args.slip,
        gas_slip: args.gas_slip(),
    };
    let output = Output {
        inputs: Inputs {
            model: &args.model,
            momentum_state,
            theta_state,
            material: &args.material,
        },
        model,
        momentum: model.momentum(&momentum_state, &params),
        granular_temperature: model.granular_temperature(&theta_state, &params),
    };
    let mut out = std::io::stdout().lock();
    serde_json::to_writer_pretty(&mut out, &output)?;
    writeln!(out)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        args: WallArgs,
    }

    fn parse(options: &[&str]) -> Result<WallArgs, clap::Error> {
        Cli::try_parse_from(std::iter::once("wall").chain(options.iter().copied())).map(|c| c.args)
    }

    #[test]
    fn johnson_jackson_evaluates_the_library_model_with_paper_defaults() {
        let args = parse(&[
            "--model",
            "johnson-jackson",
            "--specularity",
            "0.1",
            "--eps-s",
            "0.55",
            "--theta",
            "0.01",
            "--slip",
            "5",
            "--s-ddot-s",
            "5000",
        ])
        .unwrap();
        args.validate().unwrap();
        let model = args.model().unwrap();
        // paper Table 3 wall: e_w = 0.7, δ_w = 11°; gas at rest on the wall
        assert_eq!(
            model,
            SolidsWallModel::johnson_jackson(0.1, 0.7, 11.0, 0.0).unwrap()
        );
        assert_eq!(args.gas_slip(), 5.0);
        let state = MomentumWallState {
            eps_s_fluid: 0.55,
            eps_s: 0.55,
            theta: 0.01,
            slip: 5.0,
            gas_slip: 5.0,
            tr_d: 0.0,
            s_ddot_s: 5000.0,
            s_nn: 0.0,
            extra_normal_load: 0.0,
        };
        let want = model.momentum(&state, &ClosureParams::default());
        assert_eq!(model.momentum(&state, &args.params()), want);
    }

    #[test]
    fn missing_or_invalid_model_parameters_are_errors() {
        let jj = parse(&[
            "--model",
            "johnson-jackson",
            "--eps-s",
            "0.5",
            "--theta",
            "0.1",
        ]);
        let err = jj.unwrap().model().unwrap_err().to_string();
        assert!(err.contains("--specularity"), "{err}");
        let ps = parse(&[
            "--model",
            "partial-slip",
            "--eps-s",
            "0.5",
            "--theta",
            "0.1",
        ]);
        assert!(ps.unwrap().model().is_err());
        let bad = parse(&[
            "--model",
            "johnson-jackson",
            "--specularity",
            "2",
            "--eps-s",
            "0.5",
            "--theta",
            "0.1",
        ]);
        let err = bad.unwrap().model().unwrap_err().to_string();
        assert!(
            err.contains("specularity") && err.contains("[0, 1]"),
            "{err}"
        );
        let eps = parse(&["--model", "jenkins", "--eps-s", "1.2", "--theta", "0.1"]);
        assert!(eps.unwrap().validate().is_err());
        assert!(parse(&["--model", "nonsense", "--eps-s", "0.5", "--theta", "0.1"]).is_err());
    }
}
