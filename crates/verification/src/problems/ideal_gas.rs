//! Air as an ideal gas in a closed box while a bed settles (issue 60 item 1,
//! cases/gas/ideal-gas-box.ron; docs/model.md §1.4), run through the driver. Three closed
//! forms, read from the field snapshots with ρ_g = P M/(R T):
//! - the gas's mass Σ ρ_g εg V is the initial one (the box is closed; the continuity
//!   remainder the outer iterations leave at their tolerance is all that may change it);
//! - once the bed has settled the gas is at rest, and the clear gas above the bed follows the
//!   isothermal column P(z) = P_top exp(M g (z_top − z)/(R T)) (dP/dz = −ρ_g(P) g);
//! - the column's level, in the same box without the bed ([`without_bed`]): with the gas at
//!   rest everywhere its mass fixes the top pressure,
//!   P_top = m / (M/(R T) Σ εg exp(M g (z_top − z)/(R T)) V).
//!   (With the bed the gas in it sits a constant ~42 Pa above the column on the smoke grid,
//!   with a constant density as with the ideal gas: the staggered drag at the face above
//!   the bed's top cell, where the solids' face velocity is not zero though no solids cross
//!   it, hands part of that cell's weight to the gas. So the level is judged without it.)

use std::path::Path;

use anyhow::{Context, Result};
use runout_case::{load_case, Case, Fidelity};

/// The shipped case, relative to the workspace root.
pub const CASE_FILE: &str = "cases/gas/ideal-gas-box.ron";

/// What the run gives.
#[derive(Clone, Debug)]
pub struct IdealGasRun {
    /// largest |m(t)/m(0) − 1| of the gas's mass over the snapshots
    pub mass_change: f64,
    /// largest |P/P_column − 1| over the clear rows (row means) of the last snapshot
    pub column_error: f64,
    /// rows of clear gas in the last snapshot
    pub clear_rows: usize,
    /// the last snapshot's top pressure over the one the mass fixes, less 1 (meaningful
    /// without a bed, [`without_bed`])
    pub level_error: f64,
    /// the top pressure at the end [Pa] (the gas started at a uniform 101 325 Pa)
    pub top_pressure: f64,
    /// steps, outer iterations and wall time [s]
    pub steps: u64,
    /// outer iterations
    pub outer_iterations: u64,
    /// wall time [s]
    pub wall_time: f64,
}

/// The gas's dρ/dP = M/(R T) of `case` [s² m⁻²].
fn compressibility(case: &Case) -> Result<f64> {
    let gas = case.gas.as_ref().context("the case has a gas")?;
    let law = gas.equation_of_state();
    anyhow::ensure!(law.is_compressible(), "{CASE_FILE}: the gas is not ideal");
    Ok(law.compressibility())
}

/// Runs `case` (the shipped one, or a copy) at `fidelity` in a temporary directory.
pub fn run(case: &Case, fidelity: Fidelity) -> Result<IdealGasRun> {
    let kappa = compressibility(case)?;
    let gravity = match case.gravity {
        runout_case::Gravity::Constant {
            magnitude,
            slope: 0.0,
        } => magnitude,
        _ => anyhow::bail!("{CASE_FILE}: gravity is not constant and vertical"),
    };
    let grid = case.at_fidelity(fidelity).grid()?;
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy, yc) = (grid.x.widths(), grid.y.widths(), grid.y.centres());
    let out = std::env::temp_dir().join(format!(
        "runout-ideal-gas-{}-{}",
        fidelity.name(),
        std::process::id()
    ));
    let summary = runout_run::run_case(case, fidelity, &out, |_| {})?;
    let mut mass0 = None;
    let mut mass_change: f64 = 0.0;
    let mut last = None;
    for (_, file) in runout_post::fields::field_files(&out)? {
        let xml = std::fs::read_to_string(out.join(&file))?;
        let p = runout_output::read_vtr_array(&xml, "p_g").context("p_g in a snapshot")?;
        let eps = runout_output::read_vtr_array(&xml, "eps_s").context("eps_s in a snapshot")?;
        let volume = |k: usize| dx[k % nx] * dy[k / nx];
        let mass: f64 = (0..nx * ny)
            .map(|k| kappa * p[k] * (1.0 - eps[k]) * volume(k))
            .sum();
        let m0 = *mass0.get_or_insert(mass);
        mass_change = mass_change.max((mass / m0 - 1.0).abs());
        last = Some((p, eps));
    }
    let _ = std::fs::remove_dir_all(&out);
    let (p, eps) = last.context("no snapshot")?;
    let mass0 = mass0.context("no snapshot")?;
    let row_mean = |j: usize| (0..nx).map(|i| p[i + nx * j] * dx[i]).sum::<f64>() / grid.x.length();
    let top = row_mean(ny - 1);
    let column = |j: usize| (kappa * gravity * (yc[ny - 1] - yc[j])).exp();
    let clear: Vec<usize> = (0..ny)
        .filter(|&j| (0..nx).all(|i| eps[i + nx * j] == 0.0))
        .collect();
    let column_error = clear
        .iter()
        .map(|&j| (row_mean(j) / (top * column(j)) - 1.0).abs())
        .fold(0.0, f64::max);
    let weighted: f64 = (0..nx * ny)
        .map(|k| (1.0 - eps[k]) * column(k / nx) * dx[k % nx] * dy[k / nx])
        .sum();
    let level = mass0 / (kappa * weighted);
    Ok(IdealGasRun {
        mass_change,
        column_error,
        clear_rows: clear.len(),
        level_error: top / level - 1.0,
        top_pressure: top,
        steps: summary.steps,
        outer_iterations: summary.outer_iterations,
        wall_time: summary.wall_time,
    })
}

/// `case` without its bed: a closed box of gas only (the solids phase kept, εs = 0).
pub fn without_bed(case: &Case) -> Case {
    let mut empty = case.clone();
    empty.name = format!("{}-without-bed", case.name);
    empty.initial.regions.clear();
    empty.initial.polygons.clear();
    empty
}

/// The shipped case.
pub fn shipped_case() -> Result<Case> {
    let file = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(CASE_FILE);
    load_case(&file).with_context(|| format!("loading {}", file.display()))
}
