//! `runout pore-pressure`: how long pore gas pressure lasts in a bed of given grains and
//! heights (issue 60 item 5; docs/guide/gas.md). Evaluates `runout_closures::pore_pressure`
//! (docs/model.md §2.8): the drag law's Darcy mobility, U_mf, the gas's and the bed's
//! storage, the diffusivity of a rigid and of a consolidating bed, and the basal excess's
//! half-life t½ = τ½ H²/D at each height; prints JSON.

use anyhow::ensure;
use runout_closures::pore_pressure::{self, Bed, GRAVITY, TAU_HALF};
use runout_closures::{evaluate, CellState, ClosureParams};
use serde::Serialize;
use std::io::Write;

use crate::cmd_closures::DragArgs;
use crate::material::MaterialArgs;

/// Bisections of [`packing_under`] (2⁻⁶⁰ of the εs interval).
const BISECTIONS: usize = 60;

/// Field names of the JSON output, shown by `runout pore-pressure --help`.
const OUTPUT_FIELDS: &str = "\
OUTPUT (JSON, SI units):
  inputs                 the options used (echo)
  bed.mobility           Darcy mobility k/mu = eps_g^2/F_gs at vanishing slip [m2 Pa-1 s-1]
  bed.permeability       k = mu_g k/mu [m2]
  bed.u_mf               minimum fluidisation speed (superficial) [m/s]
  bed.stiffness          K = dP_s/deps_s of the friction law at --eps-s, at rest [Pa]
  bed.gas_storage        eps_g/P of an ideal gas; 0 with --constant-density [1/Pa]
  bed.compaction_storage 1/(eps_s K), null where K = 0 [1/Pa]
  diffusivity.rigid      D = (k/mu)/(eps_g/P) [m2/s]; null with --constant-density
  diffusivity.consolidating   D with both storages [m2/s]; null where K = 0 (eps_s at
                         or below --eps-s-min: a suspension that settles, not a bed)
  tau_half               0.19673: t_half = tau_half H^2/D
  bed.settling_speed     with --dilated-eps-s: the dilated layer's solids settling speed,
                         its U_mf [m/s]
  heights[].height, .half_time_rigid, .half_time_consolidating   H [m], t_half [s]
  heights[].eps_s_self_weight, .half_time_self_weight   the bed under its own weight: eps_s
                         where the friction law's pressure at rest is half the buoyant
                         weight eps_s (rho_s - rho_g) g H, and t_half with K there [-], [s]
  heights[].settling_time   with --dilated-eps-s: a layer H high at that eps_s settled [s]
Sources: docs/model.md §2.8; docs/guide/gas.md; rustdoc of runout_closures::pore_pressure.";

/// The pore-pressure calculator's options. Defaults are the paper's material (Table 3)
/// at atmospheric pressure.
#[derive(clap::Args, Debug, Clone)]
#[command(after_help = OUTPUT_FIELDS)]
pub struct PorePressureArgs {
    /// the bed's solids volume fraction eps_s [-], 0 < eps_s < 1
    #[arg(long)]
    pub eps_s: f64,
    /// bed (or flow) heights H [m], comma-separated, each > 0
    #[arg(long, value_delimiter = ',', required = true)]
    pub heights: Vec<f64>,
    /// absolute gas pressure P [Pa] of the ideal gas, > 0
    #[arg(long, default_value_t = 101_325.0)]
    pub pressure: f64,
    /// the solids fraction of a layer dilated by shear or fluidisation (below --eps-s): the
    /// time it takes to settle back, its weight on the gas meanwhile
    #[arg(long)]
    pub dilated_eps_s: Option<f64>,
    /// a gas of constant density (runout's default gas): it stores nothing
    #[arg(long)]
    pub constant_density: bool,
    /// the drag law
    #[command(flatten)]
    pub drag: DragArgs,
    /// particle, gas and closure options
    #[command(flatten)]
    pub material: MaterialArgs,
}

#[derive(Serialize)]
struct Inputs<'a> {
    eps_s: f64,
    dilated_eps_s: Option<f64>,
    pressure: Option<f64>,
    drag: String,
    material: &'a MaterialArgs,
}

#[derive(Serialize)]
struct BedOut {
    mobility: f64,
    permeability: f64,
    u_mf: f64,
    stiffness: f64,
    gas_storage: f64,
    compaction_storage: Option<f64>,
    settling_speed: Option<f64>,
}

#[derive(Serialize)]
struct Diffusivity {
    rigid: Option<f64>,
    consolidating: Option<f64>,
}

#[derive(Serialize)]
struct Height {
    height: f64,
    half_time_rigid: Option<f64>,
    half_time_consolidating: Option<f64>,
    eps_s_self_weight: Option<f64>,
    half_time_self_weight: Option<f64>,
    settling_time: Option<f64>,
}

#[derive(Serialize)]
struct Output<'a> {
    inputs: Inputs<'a>,
    bed: BedOut,
    diffusivity: Diffusivity,
    tau_half: f64,
    heights: Vec<Height>,
}

impl PorePressureArgs {
    /// Rejects options outside their ranges, naming the option.
    fn validate(&self) -> anyhow::Result<()> {
        ensure!(
            self.eps_s > 0.0 && self.eps_s < self.material.eps_s_max,
            "--eps-s must be in (0, --eps-s-max = {}), got {}",
            self.material.eps_s_max,
            self.eps_s
        );
        if let Some(d) = self.dilated_eps_s {
            ensure!(
                d > 0.0 && d < self.eps_s,
                "--dilated-eps-s must be in (0, --eps-s = {}), got {d}",
                self.eps_s
            );
        }
        for h in &self.heights {
            ensure!(h.is_finite() && *h > 0.0, "--heights must be > 0, got {h}");
        }
        ensure!(
            self.pressure.is_finite() && self.pressure > 0.0,
            "--pressure must be > 0, got {}",
            self.pressure
        );
        ensure!(
            self.material.gas_density > 0.0,
            "--gas-density must be > 0 for a pore pressure, got {}",
            self.material.gas_density
        );
        self.material.validate()
    }
}

/// A cell of the bed at rest: tr D = 0, no shear, a vanishing θ.
fn at_rest(eps_s: f64) -> CellState {
    CellState {
        eps_s,
        theta: 1e-12,
        slip: 0.0,
        tr_d: 0.0,
        s_ddot_s: 0.0,
    }
}

/// The εs at which the friction law's pressure at rest is `stress` [Pa] (bisection between
/// εs,min and εs,max, where it rises from 0); `None` for a law without a pressure at rest.
fn packing_under(stress: f64, params: &ClosureParams) -> Option<f64> {
    let pressure = |eps_s: f64| evaluate(&at_rest(eps_s), params).friction.p_fric;
    let f = &params.friction;
    let (mut lo, mut hi) = (f.eps_s_min, f.eps_s_max - 1e-9);
    if pressure(hi).partial_cmp(&stress) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    for _ in 0..BISECTIONS {
        let mid = 0.5 * (lo + hi);
        if pressure(mid) < stress {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// Run `runout pore-pressure`: validate, evaluate and print the JSON (fields in `--help`).
pub fn run(args: &PorePressureArgs) -> anyhow::Result<()> {
    args.validate()?;
    let drag = args.drag.law();
    let m = &args.material;
    let bed = Bed {
        eps_s: args.eps_s,
        diameter: m.diameter,
        solids_density: m.density,
        gas_density: m.gas_density,
        gas_viscosity: m.gas_viscosity,
    };
    let params = m.params(drag);
    let stiffness = evaluate(&at_rest(args.eps_s), &params).k_cp;
    let pressure = (!args.constant_density).then_some(args.pressure);
    let mobility = pore_pressure::mobility(&bed, drag);
    let gas_storage = pore_pressure::gas_storage(args.eps_s, pressure);
    let compaction_storage = pore_pressure::compaction_storage(args.eps_s, stiffness);
    let rigid = pressure.and_then(|_| pore_pressure::diffusivity(mobility, gas_storage));
    // no stiffness (εs at or below the friction law's εs,min): a suspension, not a bed
    let consolidating =
        compaction_storage.and_then(|s| pore_pressure::diffusivity(mobility, gas_storage + s));
    // under its own weight: K where the frictional pressure carries half the buoyant weight
    let buoyant_weight = args.eps_s * (m.density - m.gas_density) * GRAVITY;
    let self_weight = |height: f64| {
        let packed = packing_under(0.5 * buoyant_weight * height, &params)?;
        let k = evaluate(&at_rest(packed), &params).k_cp;
        let storage = pore_pressure::compaction_storage(packed, k)?;
        let d = pore_pressure::diffusivity(mobility, gas_storage + storage)?;
        Some((packed, pore_pressure::half_time(height, d)))
    };
    let dilated = args.dilated_eps_s.map(|eps_s| Bed { eps_s, ..bed });
    let heights = args
        .heights
        .iter()
        .map(|&height| Height {
            height,
            half_time_rigid: rigid.map(|d| pore_pressure::half_time(height, d)),
            half_time_consolidating: consolidating.map(|d| pore_pressure::half_time(height, d)),
            eps_s_self_weight: self_weight(height).map(|(e, _)| e),
            half_time_self_weight: self_weight(height).map(|(_, t)| t),
            settling_time: dilated
                .map(|d| pore_pressure::settling_time(height, &d, args.eps_s, drag)),
        })
        .collect();
    let output = Output {
        inputs: Inputs {
            eps_s: args.eps_s,
            dilated_eps_s: args.dilated_eps_s,
            pressure,
            drag: args.drag.name(),
            material: m,
        },
        bed: BedOut {
            mobility,
            permeability: m.gas_viscosity * mobility,
            u_mf: pore_pressure::minimum_fluidisation(&bed, drag),
            stiffness,
            gas_storage,
            compaction_storage,
            settling_speed: dilated.map(|d| pore_pressure::minimum_fluidisation(&d, drag)),
        },
        diffusivity: Diffusivity {
            rigid,
            consolidating,
        },
        tau_half: TAU_HALF,
        heights,
    };
    let mut stdout = std::io::stdout().lock();
    serde_json::to_writer_pretty(&mut stdout, &output)?;
    writeln!(stdout)?;
    Ok(())
}
