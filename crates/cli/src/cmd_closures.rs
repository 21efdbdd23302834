//! `runout closures`: the closure calculator (issue 3). Evaluates every closure of
//! docs/model.md §2 (and the granular-energy sources of §1.3) at one state with
//! `runout_closures::evaluate` and prints the result as pretty JSON.

use anyhow::ensure;
use clap::ValueEnum;
use runout_closures::{evaluate, CellState, ClosureParams, Drag};

use crate::material::MaterialArgs;
use serde::Serialize;
use std::io::Write;

/// Field names of the JSON output, shown by `runout closures --help`.
const OUTPUT_FIELDS: &str = "\
OUTPUT (JSON, SI units):
  inputs            the state and parameters used (echo of the options)
  closures.eps_g    gas fraction 1 - eps_s [-]
  closures.g0, .dg0_deps   radial distribution at contact and its eps_s-derivative [-]
  closures.eta      (1 + e)/2 [-]
  closures.dga      drag coefficient per unit solids fraction DgA [kg m-3 s-1]
  closures.f_gs     interphase drag coefficient F_gs = eps_s DgA [kg m-3 s-1]
  closures.dga_kinetic     drag used in mu*, kappa* (single-particle below eps_s = 1e-4)
  closures.kinetic.p_kin   kinetic pressure (paper Eq. 6) [Pa]
  closures.kinetic.mu_dilute, .mu_bulk, .mu_star, .mu_kin, .lambda_kin   viscosities [Pa s]
  closures.kinetic.kappa_dilute, .kappa_star, .kappa_kin   conductivities [kg m-1 s-1]
  closures.kinetic.dissipation   collisional dissipation gamma [W m-3]
  closures.friction.p_fric, .mu_fric, .lambda_fric   frictional P [Pa], mu, lambda [Pa s]
  closures.friction.p_star   Schaeffer plastic pressure P* [Pa] (0 with Princeton)
  closures.friction.p_c, .pf_over_pc, .zeta, .n   Princeton P_c [Pa], P_f/P_c [-], zeta [1/s], n [-]
  closures.stress.p_s, .mu_s, .lambda_s, .p_star   summed solids stress coefficients
  closures.k_cp     dP_s/deps_s for the volume-fraction correction [Pa]
  closures.production, .j_vis, .j_slip   granular-energy production, viscous damping,
                    slip production [W m-3]
Sources: docs/model.md §2 and §1.3; rustdoc of runout-closures.";

/// Gas–solids drag law (MFIX `DRAG_TYPE`, docs/model.md §2.6).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum DragChoice {
    /// Syamlal–O'Brien with --drag-c1, --drag-d1 (MFIX default)
    SyamlalObrien,
    /// Gidaspow (Ergun below eps_g = 0.8, Wen–Yu above)
    Gidaspow,
    /// Gidaspow with the arctan blend
    GidaspowBlend,
    /// Wen–Yu for all eps_g
    WenYu,
}

impl DragChoice {
    /// The drag law, with Syamlal–O'Brien's `c1` and `d1` (ignored by the others).
    pub fn law(self, c1: f64, d1: f64) -> Drag {
        match self {
            DragChoice::SyamlalObrien => Drag::SyamlalOBrien { c1, d1 },
            DragChoice::Gidaspow => Drag::Gidaspow,
            DragChoice::GidaspowBlend => Drag::GidaspowBlend,
            DragChoice::WenYu => Drag::WenYu,
        }
    }
}

/// The drag-law options shared by the calculators (`runout closures`, `runout pore-pressure`).
#[derive(clap::Args, Debug, Clone)]
pub struct DragArgs {
    /// gas-solids drag law
    #[arg(long, value_enum, default_value_t = DragChoice::SyamlalObrien)]
    pub drag: DragChoice,
    /// Syamlal-O'Brien DRAG_C1 [-]
    #[arg(long, default_value_t = 0.8)]
    pub drag_c1: f64,
    /// Syamlal-O'Brien DRAG_D1 [-]
    #[arg(long, default_value_t = 2.65)]
    pub drag_d1: f64,
}

impl DragArgs {
    /// The chosen drag law with its coefficients.
    pub fn law(&self) -> Drag {
        self.drag.law(self.drag_c1, self.drag_d1)
    }

    /// The law's command-line spelling, for the echoed inputs.
    pub fn name(&self) -> String {
        choice_name(&self.drag)
    }
}

/// Print every closure value (g0, Lun kinetic theory, friction, K_cp, drag, granular-energy
/// sources) at one state as JSON. Defaults are the paper's sensitivity-analysis values
/// (paper Table 3).
#[derive(clap::Args, Debug, Clone)]
#[command(after_help = OUTPUT_FIELDS)]
pub struct ClosuresArgs {
    /// solids volume fraction eps_s [-], 0 <= eps_s < 1
    #[arg(long, allow_negative_numbers = true)]
    pub eps_s: f64,
    /// granular temperature theta [m2/s2], >= 0
    #[arg(long, allow_negative_numbers = true)]
    pub theta: f64,
    /// gas-solids relative speed |u_g - u_s| [m/s]
    #[arg(long, default_value_t = 0.0)]
    pub slip: f64,
    /// solids dilatation tr D = div u_s [1/s]
    #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
    pub tr_d: f64,
    /// S:S = tr(D^2) - (tr D)^2/3 of the solids strain rate [1/s2], >= 0
    #[arg(long, default_value_t = 0.0)]
    pub s_ddot_s: f64,
    /// the drag law
    #[command(flatten)]
    pub drag: DragArgs,
    /// particle, gas and closure options
    #[command(flatten)]
    pub material: MaterialArgs,
}

/// The echoed inputs of the JSON output.
#[derive(Serialize)]
struct Inputs<'a> {
    eps_s: f64,
    theta: f64,
    slip: f64,
    tr_d: f64,
    s_ddot_s: f64,
    drag: String,
    material: &'a MaterialArgs,
}

#[derive(Serialize)]
struct Output<'a> {
    inputs: Inputs<'a>,
    closures: runout_closures::ClosureSet,
}

impl ClosuresArgs {
    /// Reject states and parameters outside the closures' validity ranges.
    fn validate(&self) -> anyhow::Result<()> {
        ensure!(
            (0.0..1.0).contains(&self.eps_s),
            "--eps-s must be in [0, 1), got {}",
            self.eps_s
        );
        ensure!(
            self.theta >= 0.0,
            "--theta must be >= 0, got {}",
            self.theta
        );
        ensure!(self.slip >= 0.0, "--slip must be >= 0, got {}", self.slip);
        ensure!(
            self.s_ddot_s >= 0.0,
            "--s-ddot-s must be >= 0, got {}",
            self.s_ddot_s
        );
        ensure!(self.tr_d.is_finite(), "--tr-d must be finite");
        self.material.validate()
    }

    fn params(&self) -> ClosureParams {
        self.material.params(self.drag.law())
    }
}

/// Run `runout closures`: validate the options, evaluate the closure set and print it to
/// stdout as pretty JSON (field names in the `--help` text).
pub fn run(args: &ClosuresArgs) -> anyhow::Result<()> {
    args.validate()?;
    let params = args.params();
    let state = CellState {
        eps_s: args.eps_s,
        theta: args.theta,
        slip: args.slip,
        tr_d: args.tr_d,
        s_ddot_s: args.s_ddot_s,
    };
    let output = Output {
        inputs: Inputs {
            eps_s: args.eps_s,
            theta: args.theta,
            slip: args.slip,
            tr_d: args.tr_d,
            s_ddot_s: args.s_ddot_s,
            drag: args.drag.name(),
            material: &args.material,
        },
        closures: evaluate(&state, &params),
    };
    // an error (e.g. a closed pipe) is returned, not a panic as with println!
    let mut stdout = std::io::stdout().lock();
    serde_json::to_writer_pretty(&mut stdout, &output)?;
    writeln!(stdout)?;
    Ok(())
}

/// The command-line spelling of a `ValueEnum` choice.
fn choice_name<T: ValueEnum>(choice: &T) -> String {
    choice
        .to_possible_value()
        .map(|v| v.get_name().to_string())
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;
    use runout_closures::{FrictionModel, RadialDistribution};

    #[derive(Parser)]
    struct Wrapper {
        #[command(flatten)]
        args: ClosuresArgs,
    }

    fn parse(line: &[&str]) -> ClosuresArgs {
        Wrapper::try_parse_from(std::iter::once("closures").chain(line.iter().copied()))
            .expect("arguments parse")
            .args
    }

    #[test]
    fn defaults_are_the_paper_sensitivity_values() {
        let args = parse(&["--eps-s", "0.55", "--theta", "0.1"]);
        let params = args.params();
        let paper = ClosureParams::default();
        assert_eq!(params.particles, paper.particles);
        assert_eq!(params.gas, paper.gas);
        assert_eq!(params.friction, paper.friction);
        assert_eq!(params.friction_model, FrictionModel::princeton());
        assert_eq!(params.drag, Drag::default());
        assert!(args.validate().is_ok());
    }

    #[test]
    fn invalid_states_are_rejected() {
        for line in [
            ["--eps-s", "1.0", "--theta", "0.1"],
            ["--eps-s", "0.5", "--theta", "-1"],
            ["--eps-s", "-0.1", "--theta", "0.1"],
        ] {
            assert!(parse(&line).validate().is_err(), "{line:?}");
        }
        let mut args = parse(&["--eps-s", "0.5", "--theta", "0.1"]);
        args.material.phi_internal = 60.0;
        assert!(args.validate().is_err());
    }

    #[test]
    fn choices_map_to_the_closure_models() {
        let args = parse(&[
            "--eps-s",
            "0.6",
            "--theta",
            "0.01",
            "--friction",
            "schaeffer",
            "--drag",
            "gidaspow-blend",
            "--radial",
            "ma-ahmadi",
        ]);
        let params = args.params();
        assert_eq!(params.friction_model, FrictionModel::schaeffer());
        assert_eq!(params.drag, Drag::GidaspowBlend);
        assert_eq!(params.radial, RadialDistribution::MaAhmadi);
        assert_eq!(args.drag.name(), "gidaspow-blend");
    }
}
