//! Defluidisation (issue 60 item 3, cases/gas/defluidisation.ron): a packed bed of 80 µm
//! beads aerated through the floor below its minimum fluidisation velocity, the floor then
//! closed, and the basal excess gas pressure's half time against the rigid bed's
//! pore-pressure diffusion ([`crate::references::pore_pressure`]), run through the driver.
//!
//! [`at`] scales the shipped case to an absolute pressure P and a bed height H (domain 1.5 H
//! tall in 2.5 mm cells, as the shipped 0.1 m bed): the bed settles for 0.2 s, air enters at
//! a superficial 0.1 mm/s below 50 kPa (2 mm/s above) for max(1 s, 3 H²/D₀), long enough for
//! the steady linear profile, and the floor stays closed for max(0.4 s, 6 k t½₀) more, k = 1.5
//! below 50 kPa and 8 above (the compaction's slowing at 1 atm), with D₀ and t½₀ the rigid
//! bed's at εs 0.58. Its time step is at most t½₀/200 and its snapshots t½₀/50 apart.
//!
//! [`run`] reads the snapshots: the floor row's mean gas pressure, the bed (the rows of mean
//! εs > 0.3) at the shut-off, its height H (the solids' volume over the mean εs of its rows
//! below the top one) and mean εs, the absolute pressure P at the floor.
//! The excess p0 is the floor pressure at the shut-off less the last snapshot's (the bed's
//! weight on the gas at rest); the measured t½ is where the excess falls to p0/2,
//! interpolated linearly between snapshots. The references: the rigid bed's τ½ H²/D with
//! D = P εg/β of that bed (Gidaspow's dense branch at zero slip, the drag law the case runs
//! with), and the 1-D nonlinear consolidation of that bed (its H, mean εs and floor pressure P,
//! the case's inflow, grains and gas; Princeton's P_c: [`crate::references::consolidation`]).
//!
//! At 1 kPa the gas stores several times more per pascal than the bed's frictional compaction
//! does, so the bed is nearly rigid and both references apply; at 1 atm the compaction
//! dominates, the decay is several times slower than the rigid bed's and only the
//! consolidation solution holds (docs/status.md).

use std::path::Path;

use anyhow::{ensure, Context, Result};
use runout_case::{load_case, Boundary, Case, Fidelity, InletRate, OutletPressure};
use runout_closures::{Drag, FrictionModel, PrincetonConstants};
use runout_mesh::Segment;

use crate::references::consolidation::{self, AeratedBed, Skeleton};
use crate::references::pore_pressure::{diffusivity, tau_half};

/// The shipped case, relative to the workspace root.
pub const CASE_FILE: &str = "cases/gas/defluidisation.ron";

/// The grid's cell size in the scaled cases [m].
pub const CELL: f64 = 0.0025;

/// Mean εs above which a row counts as bed.
const BED_EPS_S: f64 = 0.3;

/// εs of the settled bed the schedule is planned with (the run's own is measured).
const PLANNED_EPS_S: f64 = 0.58;

/// The shipped case scaled to absolute pressure `pressure` [Pa] and bed height `height` [m]
/// (module doc), and the time the floor closes [s].
pub fn at(base: &Case, pressure: f64, height: f64) -> Result<(Case, f64)> {
    let mut case = base.clone();
    let gas = case.gas.as_mut().context("the case has a gas")?;
    let law = gas.equation_of_state();
    ensure!(law.is_compressible(), "{CASE_FILE}: the gas is not ideal");
    gas.density = pressure * law.compressibility();
    gas.reference_pressure = pressure;
    let viscosity = gas.viscosity;
    let diameter = case.solids.first().context("the case has solids")?.diameter;
    let d0 = diffusivity(pressure, PLANNED_EPS_S, viscosity, diameter);
    let half = tau_half() * height * height / d0;
    let low = pressure < 5e4;
    let off = 0.2 + (3.0 * height * height / d0).max(1.0);
    let end = off + (6.0 * if low { 1.5 } else { 8.0 } * half).max(0.4);
    let cells = (1.5 * height / CELL).round() as usize;
    case.name = format!("defluidisation-p{pressure}-h{height}");
    case.domain.y.segments = vec![Segment::Uniform {
        length: cells as f64 * CELL,
        cells,
    }];
    let bed = case
        .initial
        .regions
        .first_mut()
        .context("the case has a bed")?;
    bed.y = (0.0, height);
    case.boundaries.north = Boundary::PressureOutlet {
        pressure: OutletPressure::Hydrostatic(pressure),
    };
    let inlet = case
        .gas_inlets
        .first_mut()
        .context("the case has a floor inlet")?;
    inlet.rate = InletRate::Velocity(if low { 1e-4 } else { 2e-3 });
    inlet.until = Some(off);
    case.run.dt.max = half / 200.0;
    case.run.dt.min = 2e-9 * end;
    case.run.output_interval = half / 50.0;
    Ok((super::case_copy::ending_at(case, end), off))
}

/// What a run gives.
#[derive(Clone, Debug)]
pub struct DefluidisationRun {
    /// the bed's height at the shut-off [m]
    pub height: f64,
    /// its mean εs at the shut-off and at the end
    pub eps_s: (f64, f64),
    /// the absolute pressure at the floor at the shut-off [Pa]
    pub pressure: f64,
    /// the rigid bed's D = P εg/β [m²/s]
    pub diffusivity: f64,
    /// the basal excess pressure at the shut-off [Pa]
    pub excess: f64,
    /// the excess a tenth of the inflow time before the shut-off, over `excess` (1: steady)
    pub steadiness: f64,
    /// the measured half time [s]
    pub half_time: f64,
    /// the rigid bed's τ½ H²/D [s]
    pub rigid_half_time: f64,
    /// the consolidation solution's half time \[s\] ([`consolidation_half_time`])
    pub consolidation_half_time: f64,
    /// steps, outer iterations and wall time [s]
    pub steps: u64,
    /// outer iterations
    pub outer_iterations: u64,
    /// wall time [s]
    pub wall_time: f64,
}

/// One snapshot: time, the floor row's mean p_g, the row means of εs.
type Snapshot = (f64, f64, Vec<f64>);

/// Runs `case` (from [`at`], the floor closing at `off`) at `fidelity` in a temporary
/// directory and measures the half time (module doc).
pub fn run(case: &Case, fidelity: Fidelity, off: f64) -> Result<DefluidisationRun> {
    let grid = case.at_fidelity(fidelity).grid()?;
    let (nx, ny) = (grid.nx(), grid.ny());
    let dy = grid.y.widths()[0];
    let out = std::env::temp_dir().join(format!("runout-{}-{}", case.name, std::process::id()));
    let summary = runout_run::run_case(case, fidelity, &out, |_| {})?;
    let mut snaps: Vec<Snapshot> = Vec::new();
    for (t, file) in runout_post::fields::field_files(&out)? {
        let xml = std::fs::read_to_string(out.join(&file))?;
        let p = runout_output::read_vtr_array(&xml, "p_g").context("p_g in a snapshot")?;
        let eps = runout_output::read_vtr_array(&xml, "eps_s").context("eps_s in a snapshot")?;
        let row = |v: &[f64], j: usize| v[nx * j..nx * (j + 1)].iter().sum::<f64>() / nx as f64;
        snaps.push((t, row(&p, 0), (0..ny).map(|j| row(&eps, j)).collect()));
    }
    let _ = std::fs::remove_dir_all(&out);
    let last = snaps.last().context("no snapshot")?;
    let p_end = last.1;
    let at_off = snaps
        .iter()
        .rev()
        .find(|s| s.0 <= off + 1e-9)
        .context("no snapshot before the shut-off")?;
    let before = snaps
        .iter()
        .rev()
        .find(|s| s.0 <= off - 0.1 * (off - 0.2) + 1e-9)
        .context("no snapshot during the inflow")?;
    let excess = at_off.1 - p_end;
    ensure!(
        excess > 0.0,
        "{}: no excess pressure at the shut-off",
        case.name
    );
    let (height, eps_s) = bed(&at_off.2, dy).context("no bed at the shut-off")?;
    let gas = case.gas.as_ref().context("the case has a gas")?;
    let diameter = case.solids[0].diameter;
    let d = diffusivity(at_off.1, eps_s, gas.viscosity, diameter);
    let half_time = half_time(&snaps, off, p_end, excess).context("the excess never halved")?;
    let consolidation_half_time = consolidation_half_time(case, height, eps_s, at_off.1)?;
    Ok(DefluidisationRun {
        height,
        eps_s: (eps_s, bed(&last.2, dy).map_or(f64::NAN, |b| b.1)),
        pressure: at_off.1,
        diffusivity: d,
        excess,
        steadiness: (before.1 - p_end) / excess,
        half_time,
        rigid_half_time: tau_half() * height * height / d,
        consolidation_half_time,
        steps: summary.steps,
        outer_iterations: summary.outer_iterations,
        wall_time: summary.wall_time,
    })
}

/// Cells of the consolidation solution (its half time within 0.2 % of the converged one).
const CONSOLIDATION_CELLS: usize = 100;

/// The half time \[s\] of the 1-D nonlinear consolidation ([`consolidation::basal_half_time`])
/// of a bed of height `height` \[m\] and mean `eps_s` in `case`'s gas at the absolute pressure
/// `pressure` \[Pa\], aerated at the case's first inlet's superficial velocity; refused unless
/// the case runs the reference's closures (Princeton friction with MFIX's constants and its
/// εs,min and εs,max, Gidaspow's drag).
pub fn consolidation_half_time(case: &Case, height: f64, eps_s: f64, pressure: f64) -> Result<f64> {
    let solids = case.solids.first().context("the case has solids")?;
    let gas = case.gas.as_ref().context("the case has a gas")?;
    ensure!(
        case.models.friction == FrictionModel::Princeton(PrincetonConstants::MFIX)
            && solids.max_packing == consolidation::EPS_S_MAX
            && solids.friction_min_packing == consolidation::EPS_S_MIN
            && case.models.drag == Drag::Gidaspow,
        "{}: the consolidation reference needs Princeton friction (εs,min {}, εs,max {}) \
         and Gidaspow's drag",
        case.name,
        consolidation::EPS_S_MIN,
        consolidation::EPS_S_MAX
    );
    let inflow = match case.gas_inlets.first().map(|inlet| inlet.rate) {
        Some(InletRate::Velocity(v)) => v,
        _ => anyhow::bail!("{}: no floor inlet at a velocity", case.name),
    };
    let bed = AeratedBed {
        height,
        eps_s,
        inflow,
        pressure,
        diameter: solids.diameter,
        solids_density: solids.density,
        gas_density: gas.density,
        gas_viscosity: gas.viscosity,
        skeleton: Skeleton::Princeton,
    };
    Ok(consolidation::basal_half_time(&bed, CONSOLIDATION_CELLS))
}

/// The bed's height and εs from the row means `column` of εs on rows `dy` tall: εs the mean
/// of the bed's rows (mean εs > [`BED_EPS_S`]) below its top one, the height the solids'
/// volume over it (the top row is partly filled: counting it whole put H 2–5 % off on
/// 10–20 rows, t½ twice that); `None` without two bed rows.
fn bed(column: &[f64], dy: f64) -> Option<(f64, f64)> {
    let rows: Vec<f64> = column.iter().copied().filter(|&e| e > BED_EPS_S).collect();
    let below_top = &rows[..rows.len().checked_sub(1)?];
    if below_top.is_empty() {
        return None;
    }
    let eps_s = below_top.iter().sum::<f64>() / below_top.len() as f64;
    Some((column.iter().sum::<f64>() * dy / eps_s, eps_s))
}

/// Time after `off` at which the floor's excess over `p_end` first falls to half of
/// `excess`, interpolated linearly between the snapshots either side.
fn half_time(snaps: &[Snapshot], off: f64, p_end: f64, excess: f64) -> Option<f64> {
    let target = 0.5 * excess;
    snaps.windows(2).find_map(|w| {
        let (a, b) = (&w[0], &w[1]);
        let (ea, eb) = (a.1 - p_end, b.1 - p_end);
        (b.0 > off && ea > target && eb <= target)
            .then(|| a.0 + (ea - target) * (b.0 - a.0) / (ea - eb) - off)
    })
}

/// The shipped case.
pub fn shipped_case() -> Result<Case> {
    let file = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(CASE_FILE);
    load_case(&file).with_context(|| format!("loading {}", file.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_scaled_case_is_valid_and_planned_from_the_rigid_bed() {
        let (case, off) = at(&shipped_case().unwrap(), 1000.0, 0.025).unwrap();
        let case = super::super::case_copy::validated(case, "defluidisation").unwrap();
        assert_eq!(case.domain.y.segments.len(), 1);
        assert_eq!(case.initial.regions[0].y, (0.0, 0.025));
        // D0 = 1000 · 0.42 / (150 · 0.58² · 1.8e-5 / (0.42 · 6.4e-9)) = 1.24296e-3 m²/s,
        // 3 H²/D0 = 1.50850 s
        assert!((off - 1.708_50).abs() < 1e-5, "{off}");
        let gas = case.gas.as_ref().unwrap();
        assert!(
            (gas.density / 0.011_884 - 1.0).abs() < 1e-3,
            "{}",
            gas.density
        );
    }

    #[test]
    fn the_bed_height_is_its_solids_volume_over_its_packing() {
        // three full rows at 0.6 and a top row at 0.3 (half full), 0.01 m rows: 0.035 m
        let (h, e) = bed(&[0.6, 0.6, 0.6, 0.3, 0.0], 0.01).unwrap();
        assert!(
            (h - 0.035).abs() < 1e-15 && (e - 0.6).abs() < 1e-15,
            "{h} {e}"
        );
        assert!(bed(&[0.6, 0.0], 0.01).is_none());
    }

    #[test]
    fn the_half_time_is_interpolated_after_the_shut_off() {
        let snap = |t: f64, p: f64| (t, p, Vec::new());
        // an excess of 10 at 1.0 s decaying linearly to 0 at 2.0 s, one at 0.9 s before it
        let snaps = [
            snap(0.9, 110.0),
            snap(1.0, 110.0),
            snap(1.4, 106.0),
            snap(1.6, 104.0),
            snap(3.0, 100.0),
        ];
        let t = half_time(&snaps, 1.0, 100.0, 10.0).unwrap();
        assert!((t - 0.5).abs() < 1e-12, "{t}");
        assert!(half_time(&snaps[..3], 1.0, 100.0, 10.0).is_none());
    }
}
