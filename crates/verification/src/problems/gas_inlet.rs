//! A bed fluidised through a gas inlet in the floor and then shut off (issue 60 item 2,
//! cases/gas/fluidised-bed.ron), run through the driver so that the case's `gas_inlets`
//! schedule opens and closes the floor: while the gas flows the bed hangs on it, and the gas
//! pressure drop across the bed equals the bed's buoyant weight per area (the column's
//! momentum balance, time-averaged, with free-slip side walls); before the inlet opens and
//! after it closes the solids carry the weight and the gas pressure is the gas's own column.
//!
//! The drop is read from the field snapshots: the mean gas pressure of the lowest row of
//! cells less the top row's, less the gas column ρ_g g between their centres, against the
//! buoyant weight (ρs − ρg) g of the solids above the lowest row's centre (the half of the
//! lowest row's solids below its centre lean on the floor), per area.

use std::path::Path;

use anyhow::{Context, Result};
use runout_case::{load_case, Case, Fidelity};

/// The shipped case, relative to the workspace root.
pub const CASE_FILE: &str = "cases/gas/fluidised-bed.ron";
/// The windows the drop is averaged over [s]: before the inlet opens, while it is open
/// (after 0.8 s of fluidising), after it closed (0.5 s on).
pub const WINDOWS: [(f64, f64); 3] = [(0.05, 0.2), (1.0, 2.0), (2.5, 3.0)];

/// The shipped case.
pub fn shipped_case() -> Result<Case> {
    let file = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(CASE_FILE);
    load_case(&file).with_context(|| format!("loading {}", file.display()))
}

/// The run: the drop over the weight averaged over each of [`WINDOWS`], the snapshots in
/// each, and the solids mass change.
#[derive(Clone, Debug)]
pub struct InletRun {
    /// mean gas pressure drop over buoyant weight in each window, and the snapshots averaged
    pub drop_over_weight: [(f64, usize); 3],
    /// relative change of the solids mass over the run
    pub mass_change: f64,
    /// the inlet's velocity [m s⁻¹]
    pub inflow: f64,
    /// steps and wall time [s]
    pub steps: u64,
    /// wall time [s]
    pub wall_time: f64,
}

/// Runs the shipped case at `fidelity` in a temporary directory.
pub fn run(fidelity: Fidelity) -> Result<InletRun> {
    let case = shipped_case()?;
    let resolved = case.at_fidelity(fidelity);
    let grid = resolved.grid()?;
    let gas = case.gas.as_ref().context("the case has a gas")?;
    let solids = case.solids.first().context("the case has solids")?;
    let inflow = case
        .gas_inlets
        .first()
        .context("the case has a gas inlet")?
        .velocity(gas.density);
    let gravity = match case.gravity {
        runout_case::Gravity::Constant { magnitude, .. } => magnitude,
        _ => anyhow::bail!("{CASE_FILE}: gravity is not constant"),
    };
    let out = std::env::temp_dir().join(format!(
        "runout-gas-inlet-{}-{}",
        fidelity.name(),
        std::process::id()
    ));
    let summary = runout_run::run_case(&case, fidelity, &out, |_| {})?;
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let width = grid.x.length();
    let rise = grid.y.centres()[ny - 1] - grid.y.centres()[0];
    let mut sums = [(0.0, 0usize); 3];
    for (t, file) in runout_post::fields::field_files(&out)? {
        let xml = std::fs::read_to_string(out.join(&file))?;
        let p = runout_output::read_vtr_array(&xml, "p_g").context("p_g in a snapshot")?;
        let eps = runout_output::read_vtr_array(&xml, "eps_s").context("eps_s in a snapshot")?;
        let row_mean = |j: usize| (0..nx).map(|i| p[i + nx * j] * dx[i]).sum::<f64>() / width;
        let drop = row_mean(0) - row_mean(ny - 1) - gas.density * gravity * rise;
        // solids volume per area above the lowest row's centre
        let volume: f64 = (0..ny)
            .map(|j| {
                let share = if j == 0 { 0.5 } else { 1.0 };
                share * dy[j] * (0..nx).map(|i| eps[i + nx * j] * dx[i]).sum::<f64>()
            })
            .sum::<f64>()
            / width;
        let weight = (solids.density - gas.density) * gravity * volume;
        for (sum, (a, b)) in sums.iter_mut().zip(WINDOWS) {
            if (a..=b).contains(&t) {
                sum.0 += drop / weight;
                sum.1 += 1;
            }
        }
    }
    let _ = std::fs::remove_dir_all(&out);
    Ok(InletRun {
        drop_over_weight: sums.map(|(s, n)| (s / n.max(1) as f64, n)),
        mass_change: summary.solids_mass_change,
        inflow,
        steps: summary.steps,
        wall_time: summary.wall_time,
    })
}
