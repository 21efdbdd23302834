//! Running one level of a ladder (or reading its finished run): the case on the level's grid
//! with the scheme and MFIX's outer iteration, run into `runs/error-time/<case>/<level>-<scheme>/`.

use std::path::Path;

use anyhow::{bail, Result};
use runout_case::{
    validate_case, Case, Convection, DiluteCellClass, Fidelity, WallRelaxationScope,
};
use runout_output::RunSummary;
use runout_run::store::{self, finished_run, Request, Reuse};

use super::ladder::{scheme_name, Level};
use super::quantity::LevelData;
use super::read::{read_gates, read_history, read_profile};
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
    /// its folder, relative to the workspace root
    pub(super) dir: String,
}

/// Every level iterates as MFIX does: the wall closures as computed, not relaxed where they
/// cycle (`numerics.relaxation.wall_closures` = 1, which the sensitivity base sets to 0.5 at
/// cycling nodes for the sweep's speed). The relaxation changes the path of the outer
/// iterations, not the converged step (S-JJ-phi φ = 0.1 at coarse: mean u_s at 1.25 s
/// 4.108170 against 4.108188 m/s with it, docs/history/performance-log.md session 6); fixing it keeps
/// the study's runs, made before the sensitivity base relaxed, one solver configuration.
/// Likewise every θ row is classified dilute or dense by the current εs at every outer
/// iteration (`numerics.dilute_cells`), and Δt follows MFIX's controller (a change per 5
/// converged steps, × `factor` after a failed one), which the sensitivity and flume bases
/// change for speed (docs/history/performance-log.md, session 7).
fn mfix_iteration(case: &mut Case) {
    case.numerics.relaxation.wall_closures = 1.0;
    case.numerics.relaxation.wall_closures_at = WallRelaxationScope::Everywhere;
    case.numerics.dilute_cells = DiluteCellClass::EveryIteration;
    case.run.dt.steps_per_change = 5;
    case.run.dt.failure_factor = None;
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
    mfix_iteration(&mut resolved);
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
    let data = LevelData {
        h: (paper_cells as f64 / (cells.0 * cells.1) as f64).sqrt(),
        profile: summary.as_ref().ok().and(read_profile(&done, &resolved)),
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
        dir: format!("{RUNS_DIR}/{}/{tag}", case.name),
    })
}
