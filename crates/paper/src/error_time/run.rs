//! Running one level of a ladder (or reading its finished run): the case on the level's grid
//! with the scheme, its numerics otherwise as the case file sets them (the iteration and
//! time-step controller of the sweep's runs), run into
//! `runs/error-time/<case>/<level>-<scheme>/`.

use std::path::Path;

use anyhow::{bail, Result};
use runout_case::{validate_case, Case, Convection, Fidelity};
use runout_output::RunSummary;
use runout_run::cpu_time::cpu_seconds;
use runout_run::store::{self, finished_run, Request, Reuse};

use super::cost::{read_cost, write_cost, RunCost};
use super::ladder::{scheme_name, Level};
use super::quantity::LevelData;
use super::read::{read_gates, read_history};
use super::station::{case_data, station_values, StationValues};
use super::{Options, NOT_RUN, RUNS_DIR};

/// One run of the ladder.
pub(super) struct Run {
    pub(super) case: String,
    pub(super) level: Level,
    pub(super) cells: (usize, usize),
    /// speed resolution of gates.csv on this grid, if the case has gates [m/s]
    pub(super) speed_quantum: Option<f64>,
    pub(super) data: LevelData,
    /// its summary, or why the run failed
    pub(super) summary: Result<RunSummary, String>,
    pub(super) reused: bool,
    /// its threads and CPU time, where the run folder holds them
    pub(super) cost: Option<RunCost>,
    /// its folder, relative to the workspace root
    pub(super) dir: String,
}

/// Runs (or with `reuse` reads) one level of one case with one scheme.
pub(super) fn run_level(
    root: &Path,
    case: &Case,
    scheme: &Convection,
    level: Level,
    paper_cells: usize,
    opts: &Options,
) -> Result<Run> {
    let mut resolved = level.case(case);
    resolved.numerics.convection = scheme.clone();
    if let Err(errors) = validate_case(&resolved) {
        let list: Vec<String> = errors.iter().map(ToString::to_string).collect();
        bail!(
            "{} at level {level}: invalid grid: {}",
            case.name,
            list.join("; ")
        );
    }
    let grid = resolved.grid()?;
    let cells = (grid.nx(), grid.ny());
    // gates.csv takes a central difference of the front over four samples; a whole-cell
    // front would give speeds in steps of Δx/(4 × interval) at the gates (the interpolated
    // front of front.csv does not: the value is printed for scale)
    let speed_quantum = resolved.monitors.front.as_ref().and_then(|f| {
        let x = f.gate_origin + f.gates.first()?;
        let k = grid.x.locate(x)?;
        Some(grid.x.widths()[k] / (4.0 * f.interval))
    });
    let folder = root.join(RUNS_DIR).join(&case.name);
    let tag = format!("{level}-{}", scheme_name(scheme));
    let done = folder.join(&tag);
    let previous = if opts.reuse || opts.no_run {
        finished_run(&done, &resolved)
    } else {
        None
    };
    let reused = previous.is_some();
    let summary = if let Some(s) = previous {
        println!("{} {tag}: reusing {}", case.name, done.display());
        Ok(s)
    } else if opts.no_run {
        println!("{} {tag}: no finished run, not run (--no-run)", case.name);
        Err(format!(
            "{NOT_RUN}: no finished run of this case at this level"
        ))
    } else {
        println!(
            "{} {tag}: {} × {} cells to t = {} s ...",
            case.name, cells.0, cells.1, resolved.run.end_time
        );
        // `Paper` runs the resolved case as it is (at_fidelity(Paper) is the identity); the
        // summary names the level, not the `Paper` the runner was handed
        let resumed = runout_run::checkpoint::exists(&store::partial_dir(&done));
        let cpu_before = cpu_seconds();
        let request = Request {
            reuse: Reuse::Never,
            label: Some(format!("error-time {level}")),
            checkpoint_every: Some(store::CHECKPOINT_EVERY),
            ..Request::default()
        };
        match store::obtain(&done, &resolved, Fidelity::Paper, &request, |p| {
            if p.steps % 500 == 0 {
                eprintln!(
                    "  t = {:.3} s, dt = {:.1e} s, {} it",
                    p.time, p.dt, p.iterations
                );
            }
        }) {
            Ok(stored) => {
                let s = stored.summary().clone();
                let cost = RunCost {
                    threads: rayon::current_num_threads(),
                    cpu_seconds: cpu_seconds() - cpu_before,
                    resumed,
                };
                if let Err(e) = write_cost(&done, &cost) {
                    println!("  could not write its cost: {e}");
                }
                println!(
                    "  {:?} at t = {:.3} s: {} steps, {:.1} s wall",
                    s.status, s.simulated_time, s.steps, s.wall_time
                );
                Ok(s)
            }
            Err(e) => {
                println!("  FAILED: {e}");
                Err(e.to_string())
            }
        }
    };
    // the station profile and numbers as the report reads them (at the profile time in the
    // run's clock: later than the case's `times` by the tilt time for a clock from impact)
    let report_data = summary.as_ref().ok().map(|_| case_data(&done, level));
    let data = LevelData {
        h: (paper_cells as f64 / (cells.0 * cells.1) as f64).sqrt(),
        profile: report_data.as_ref().and_then(|d| d.profile.clone().ok()),
        station: report_data
            .as_ref()
            .map_or_else(StationValues::default, station_values),
        gates: summary.as_ref().ok().and(read_gates(&done, &resolved)),
        history: summary
            .as_ref()
            .ok()
            .and(read_history(&done, &resolved, grid.x.start())),
    };
    Ok(Run {
        case: case.name.clone(),
        level,
        cells,
        speed_quantum,
        data,
        summary,
        reused,
        cost: read_cost(&done),
        dir: format!("{RUNS_DIR}/{}/{tag}", case.name),
    })
}
