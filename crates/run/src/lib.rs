//! runout-run, the driver: running a case: the time loop with MFIX's adaptive time step (docs/model.md §4.12) and its
//! retries, the monitors, checkpoints and restarts, stopping on a signal, and the run
//! summary.
//!
//! One concept per file: [`build`] turns a case into a solver, [`explain`] says what it
//! computes and costs, [`case_solver`] is the loop's view of a solver, [`dt_controller`]
//! the Δt rule, [`monitors`] the scheduled hooks, [`checkpoint`] the restart files,
//! [`out_dir`] the run folder's protection, [`lock`] its one writer, [`runs_folder`] the
//! links below `runs/`, [`seal`] a finished run's file list, [`store`] the folders of
//! finished runs, [`signals`] the stop on SIGINT/SIGTERM, [`cpu_time`] the process's CPU time
//! for timing runs.

#![deny(missing_docs)]

mod build;
mod case_solver;
pub mod checkpoint;
pub mod cpu_time;
mod dt_controller;
pub mod explain;
mod gas_inlets;
mod gates;
pub mod lock;
mod monitors;
pub mod out_dir;
mod polygon;
pub mod runs_folder;
pub mod seal;
mod sidewalls;
pub mod signals;
pub mod store;

use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use runout_case::{Case, Fidelity, RunControl};
use runout_output::{DtStats, OutputError, RunStatus, RunSummary};

pub use build::{single_phase_solver, two_fluid_solver};
pub use dt_controller::DtController;

use case_solver::{CaseSolver, PendingTilt, SinglePhaseCase, StepReport, TwoFluidCase};
use checkpoint::Checkpoint;
use monitors::Monitors;
use runout_solver::single_phase::SolverError;

/// Why a case cannot run or stopped.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    /// The case needs physics this solver does not have yet.
    #[error("case `{case}`: {reason}")]
    Unsupported {
        /// case name
        case: String,
        /// what is missing
        reason: String,
    },
    /// The grid could not be built.
    #[error("case `{case}`: grid: {source}")]
    Mesh {
        /// case name
        case: String,
        /// the mesh error
        source: runout_mesh::MeshError,
    },
    /// The solver could not be built (an error during a step is a failed step, retried).
    #[error("case `{case}`: {source}")]
    Solver {
        /// case name
        case: String,
        /// the solver error
        source: SolverError,
    },
    /// Another run is writing the folder now (it holds the folder's lock).
    #[error(
        "{}: a run is running in this folder ({holder}); wait for it to end or stop it, or \
         choose another folder (--overwrite does not replace a running run)",
        dir.display()
    )]
    Running {
        /// the folder
        dir: std::path::PathBuf,
        /// who holds the lock: pid, host and since when
        holder: String,
    },
    /// The output folder cannot take the run.
    #[error("{dir}: {reason}")]
    OutDir {
        /// the folder
        dir: std::path::PathBuf,
        /// why not
        reason: String,
    },
    /// A checkpoint cannot be written, read or used.
    #[error("case `{case}`: checkpoint: {source}")]
    Checkpoint {
        /// case name
        case: String,
        /// what is wrong
        source: checkpoint::CheckpointError,
    },
    /// Writing output failed.
    #[error("case `{case}`: output: {source}")]
    Output {
        /// case name
        case: String,
        /// the output error
        source: OutputError,
    },
}

/// Progress of a running case, for progress bars.
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    /// simulated time [s]
    pub time: f64,
    /// end time [s]
    pub end_time: f64,
    /// current Δt [s]
    pub dt: f64,
    /// outer iterations of the last step
    pub iterations: usize,
    /// accepted steps so far
    pub steps: u64,
}

/// How a run starts and when it stops early.
#[derive(Clone, Debug, Default)]
pub struct RunOptions {
    /// continue from the newest checkpoint in the output folder instead of from t = 0
    pub restart: bool,
    /// a fresh run replaces an earlier run in the output folder (its files only) instead
    /// of refusing to start
    pub replace: bool,
    /// also write a checkpoint after every this much wall time (besides the case's
    /// `run.checkpoint_interval` of simulated time)
    pub checkpoint_every: Option<Duration>,
    /// set (by a signal handler) to stop at the end of the current step, with a
    /// checkpoint and status `Interrupted`
    pub stop: Option<Arc<AtomicBool>>,
}

/// Runs `case` at `fidelity` from t = 0, writing into `out_dir` and replacing any earlier
/// run there; see [`run_case_with`].
pub fn run_case(
    case: &Case,
    fidelity: Fidelity,
    out_dir: &Path,
    progress: impl FnMut(&Progress) + Send,
) -> Result<RunSummary, RunError> {
    let options = RunOptions {
        replace: true,
        ..RunOptions::default()
    };
    run_case_with(case, fidelity, out_dir, &options, progress)
}

/// The solver of a case behind the time loop's interface.
fn case_solver(case: &Case) -> Result<Box<dyn CaseSolver>, RunError> {
    if case.solids.is_empty() {
        let s = single_phase_solver(case)?;
        let n = s.grid().cell_count();
        return Ok(Box::new(SinglePhaseCase {
            solver: s,
            velocity: vec![0.0; 2 * n],
        }));
    }
    let tf = two_fluid_solver(case)?;
    let n = tf.grid().cell_count();
    // the tilt's thresholds and times come from the case, so a checkpoint needs only
    // whether the tilt is still pending
    let tilt = PendingTilt::of(case);
    let gates = gates::GateSchedule::new(&case.gates, tf.grid());
    let density = case.gas.as_ref().map_or(0.0, |g| g.density);
    let inlets = gas_inlets::InletSchedule::new(&case.gas_inlets, density, tf.grid());
    Ok(Box::new(TwoFluidCase {
        solver: tf,
        tilt,
        gates,
        inlets,
        tilted_at: None,
        scratch: vec![0.0; 2 * n],
        scratch2: vec![0.0; 2 * n],
    }))
}

/// The summary as reported: the raw tallies of `raw` (Δt mean still a sum) turned into
/// statistics at `time`.
fn reported(raw: &RunSummary, time: f64, mass_now: f64, mass0: f64) -> RunSummary {
    let mut s = raw.clone();
    if s.steps > 0 {
        s.dt.mean /= s.steps as f64;
    }
    if !s.dt.min.is_finite() {
        // no accepted step, or only one shortened to the end time
        s.dt.min = s.dt.max;
    }
    if mass0 > 0.0 {
        s.solids_mass_change = mass_now / mass0 - 1.0;
    }
    s.simulated_time = time;
    s
}

/// A tally by name (wall time per part, iterations per equation): `before` (from a
/// checkpoint) plus this process's.
fn merged<T: Copy + Default + std::ops::Add<Output = T>>(
    before: &[(String, T)],
    now: Vec<(String, T)>,
) -> Vec<(String, T)> {
    if before.is_empty() {
        return now;
    }
    now.into_iter()
        .map(|(name, t)| {
            let earlier = before
                .iter()
                .find(|(n, _)| *n == name)
                .map_or(T::default(), |p| p.1);
            (name, earlier + t)
        })
        .collect()
}

/// Where a run stands between steps, besides the solver and the monitors: what a
/// checkpoint saves with them.
struct Standing {
    /// simulated time [s]
    time: f64,
    dt: DtController,
    /// the summary's raw tallies (Δt mean still a sum; wall time and profile of the
    /// processes before this one)
    summary: RunSummary,
    /// the solids mass at t = 0 [kg m⁻¹]
    initial_solids_mass: f64,
}

/// What every stage of a run reads.
struct RunContext<'a> {
    case: &'a Case,
    fidelity: Fidelity,
    out_dir: &'a Path,
    options: &'a RunOptions,
    /// the resolved case as RON (`resolved.ron`, and the identity of a checkpoint)
    resolved: String,
    /// when this process started running the case
    started: Instant,
}

impl RunContext<'_> {
    fn out_err(&self, source: OutputError) -> RunError {
        RunError::Output {
            case: self.case.name.clone(),
            source,
        }
    }

    fn ckpt_err(&self, source: checkpoint::CheckpointError) -> RunError {
        RunError::Checkpoint {
            case: self.case.name.clone(),
            source,
        }
    }

    /// The raw summary with this process's wall time and profile added.
    fn tallied(&self, standing: &Standing, solver: &dyn CaseSolver) -> RunSummary {
        let mut raw = standing.summary.clone();
        raw.wall_time += self.started.elapsed().as_secs_f64();
        raw.profile = merged(&standing.summary.profile, solver.time_profile());
        raw.linear_iterations = merged(
            &standing.summary.linear_iterations,
            solver.linear_iterations(),
        );
        raw
    }
}

/// Stage 1a: a run from t = 0 into a folder that holds no other run (or whose earlier run
/// it may replace): the monitors' files, the fields at t = 0, a fresh Δt controller.
fn start_fresh(
    ctx: &RunContext,
    solver: &mut dyn CaseSolver,
) -> Result<(Monitors, Standing), RunError> {
    let out_dir = ctx.out_dir;
    let earlier = out_dir::run_files(out_dir);
    if !earlier.is_empty() {
        if !ctx.options.replace {
            let restart = if checkpoint::exists(out_dir) {
                "continue it from its checkpoint (--restart) or replace it (--overwrite)"
            } else {
                "replace it (--overwrite) or choose another folder"
            };
            return Err(RunError::OutDir {
                dir: out_dir.to_path_buf(),
                reason: format!(
                    "holds an earlier run, not running now ({}): {restart}",
                    earlier.join(", ")
                ),
            });
        }
        out_dir::clear_run(out_dir).map_err(|e| RunError::OutDir {
            dir: out_dir.to_path_buf(),
            reason: format!("clearing the earlier run: {e}"),
        })?;
    }
    std::fs::create_dir_all(out_dir).map_err(|source| {
        ctx.out_err(OutputError::Io {
            path: out_dir.to_path_buf(),
            source,
        })
    })?;
    let monitors = Monitors::start(ctx.case, solver, out_dir).map_err(|e| ctx.out_err(e))?;
    let d = &ctx.case.run.dt;
    let dt = DtController::new(d.initial, d.min, d.max, d.factor, d.steps_per_change)
        .with_failure_factor(d.failure_factor.unwrap_or(d.factor));
    let grid = solver.grid();
    let summary = RunSummary {
        case: ctx.case.name.clone(),
        fidelity: ctx.fidelity.to_string(),
        cells: (grid.nx(), grid.ny()),
        simulated_time: 0.0,
        wall_time: 0.0,
        steps: 0,
        rejected_steps: 0,
        outer_iterations: 0,
        rejected_outer_iterations: 0,
        dt: DtStats {
            min: f64::INFINITY,
            max: 0.0,
            mean: 0.0,
        },
        solids_mass_change: 0.0,
        max_mass_imbalance: 0.0,
        max_eps_s: solver.max_eps_s(),
        status: RunStatus::Running,
        profile: Vec::new(),
        linear_iterations: Vec::new(),
        files: Vec::new(),
    };
    let standing = Standing {
        time: 0.0,
        dt,
        summary,
        initial_solids_mass: solver.solids_mass(),
    };
    Ok((monitors, standing))
}

/// Stage 1b: a run continued from the newest checkpoint of its folder (one of the same
/// case, fidelity and solver version).
fn resume(ctx: &RunContext, solver: &mut dyn CaseSolver) -> Result<(Monitors, Standing), RunError> {
    let (path, c) = checkpoint::latest(ctx.out_dir, &ctx.resolved, ctx.fidelity.name())
        .map_err(|e| ctx.ckpt_err(e))?;
    solver.load_state(&c.solver).map_err(|e| {
        ctx.ckpt_err(checkpoint::CheckpointError::Mismatch {
            path: path.clone(),
            reason: e.to_string(),
        })
    })?;
    let monitors =
        Monitors::resume(ctx.case, ctx.out_dir, &c.monitors).map_err(|e| ctx.out_err(e))?;
    tracing::info!("restarting from {} at t = {} s", path.display(), c.time);
    let mut summary = c.summary;
    summary.status = RunStatus::Running;
    let standing = Standing {
        time: c.time,
        dt: c.dt,
        summary,
        initial_solids_mass: c.initial_solids_mass,
    };
    Ok((monitors, standing))
}

/// Writes a checkpoint of the current state and the summary so far (status `Running`, or
/// `Interrupted` when the run stops on a signal).
fn save_checkpoint(
    ctx: &RunContext,
    solver: &dyn CaseSolver,
    monitors: &Monitors,
    standing: &Standing,
) -> Result<(), RunError> {
    let wrote = Instant::now();
    let raw = ctx.tallied(standing, solver);
    let c = Checkpoint {
        solver_version: checkpoint::SOLVER_VERSION.to_string(),
        case: ctx.resolved.clone(),
        fidelity: ctx.fidelity.name().to_string(),
        time: standing.time,
        dt: standing.dt.clone(),
        summary: raw.clone(),
        initial_solids_mass: standing.initial_solids_mass,
        monitors: monitors.state().map_err(|e| ctx.out_err(e))?,
        solver: solver.save_state(),
    };
    let (path, bytes) = checkpoint::write(ctx.out_dir, &c).map_err(|e| ctx.ckpt_err(e))?;
    reported(
        &raw,
        standing.time,
        solver.solids_mass(),
        standing.initial_solids_mass,
    )
    .write_json(&ctx.out_dir.join("summary.json"))
    .map_err(|e| ctx.out_err(e))?;
    tracing::info!(
        bytes,
        values = c.solver.value_count(),
        seconds = wrote.elapsed().as_secs_f64(),
        "checkpoint {} at t = {} s",
        path.display(),
        standing.time
    );
    Ok(())
}

/// Stage 2: one attempt at a step of `step_dt`: a failed linear solve (or any solver
/// error) is a step that did not converge, retried with a smaller Δt like one.
fn attempt_step(
    solver: &mut dyn CaseSolver,
    time: f64,
    step_dt: f64,
    run: &RunControl,
) -> StepReport {
    let outcome = solver.step(step_dt, run).unwrap_or_else(|e| {
        solver.restore();
        StepReport {
            converged: false,
            iterations: 0,
            residual: f64::INFINITY,
            detail: format!("the solver failed: {e}"),
        }
    });
    tracing::debug!(
        time,
        dt = step_dt,
        iterations = outcome.iterations,
        converged = outcome.converged,
        residual = outcome.residual,
        detail = outcome.detail.as_str(),
        "step"
    );
    outcome
}

/// Adds an accepted step to the summary's tallies.
fn tally_step(
    summary: &mut RunSummary,
    solver: &dyn CaseSolver,
    step_dt: f64,
    shortened: bool,
    iterations: usize,
) {
    summary.steps += 1;
    summary.outer_iterations += iterations as u64;
    if !shortened {
        summary.dt.min = summary.dt.min.min(step_dt);
    }
    summary.dt.max = summary.dt.max.max(step_dt);
    summary.dt.mean += step_dt;
    summary.max_mass_imbalance = summary
        .max_mass_imbalance
        .max(solver.mass_imbalance_ratio());
    summary.max_eps_s = summary.max_eps_s.max(solver.max_eps_s());
}

/// Whether the solids have been at rest long enough to end the run (`run.stop_at_rest`):
/// since when the mean u_s has stayed at or below the rule's speed with the front where
/// it is.
#[derive(Default)]
struct RestWatch {
    /// (time, front x) of the first step of the current still stretch
    since: Option<(f64, f64)>,
}

impl RestWatch {
    /// Takes the step's bulk values (front x, mean u_s; `None` without solids) at `time`
    /// and says whether the stretch at rest has lasted the rule's duration.
    fn at_rest_after(
        &mut self,
        bulk: Option<(f64, f64)>,
        time: f64,
        rule: &runout_case::StopAtRest,
    ) -> bool {
        let Some((front, mean_u)) = bulk else {
            self.since = None;
            return false;
        };
        if mean_u.abs() > rule.speed {
            self.since = None;
            return false;
        }
        match self.since {
            Some((start, at)) if at == front => time - start >= rule.duration * (1.0 - 1e-12),
            _ => {
                self.since = Some((time, front));
                false
            }
        }
    }
}

/// Stage 3: the time loop, from the standing time to the end time, until the run
/// diverges, is asked to stop, cannot write its output (returned) or, with
/// `run.stop_at_rest`, its solids are at rest.
fn time_loop(
    ctx: &RunContext,
    solver: &mut dyn CaseSolver,
    monitors: &mut Monitors,
    standing: &mut Standing,
    progress: &mut dyn FnMut(&Progress),
) -> Result<Option<OutputError>, RunError> {
    let run = &ctx.case.run;
    let grid = solver.grid().clone();
    let end = run.end_time;
    let max_it = run.tolerances.max_iterations as usize;
    let next_multiple = |t: f64, interval: f64| ((t / interval).floor() + 1.0) * interval;
    let mut next_checkpoint = run
        .checkpoint_interval
        .map_or(f64::INFINITY, |i| next_multiple(standing.time, i));
    let mut last_checkpoint = Instant::now();
    let stop = ctx.options.stop.as_ref();
    let mut rest = run.stop_at_rest.as_ref().map(|_| RestWatch::default());
    while standing.time < end * (1.0 - 1e-12) {
        if stop.is_some_and(|s| s.load(Ordering::SeqCst)) {
            standing.summary.status = RunStatus::Interrupted;
            save_checkpoint(ctx, solver, monitors, standing)?;
            return Ok(None);
        }
        let time = standing.time;
        // a step lands on a scheduled event (a timed tilt) as on the end time
        let until = match solver.next_event(time) {
            Some(t) if !case_solver::at_or_after(time, t) => t.min(end),
            _ => end,
        };
        let step_dt = standing.dt.dt().min(until - time);
        let shortened = step_dt < standing.dt.dt();
        solver.before_step(time);
        let outcome = attempt_step(solver, time, step_dt, run);
        if !outcome.converged {
            standing.summary.rejected_steps += 1;
            standing.summary.rejected_outer_iterations += outcome.iterations as u64;
            // a step shortened to land on the end time is retried shorter than itself
            if shortened {
                standing.dt.shorten_to(step_dt);
            }
            if !standing.dt.failed() {
                standing.summary.status = RunStatus::Diverged {
                    diagnosis: format!(
                        "the step from t = {time:.6e} s did not converge and dt fell below dt_min = {:.1e} s; \
                         last try: dt = {step_dt:.3e} s, {} outer iterations, residual sum {:.3e}: {}",
                        run.dt.min, outcome.iterations, outcome.residual, outcome.detail
                    ),
                };
                return Ok(None);
            }
            continue;
        }
        standing.time += step_dt;
        tally_step(
            &mut standing.summary,
            solver,
            step_dt,
            shortened,
            outcome.iterations,
        );
        let hit_cap = outcome.iterations >= max_it;
        standing.dt.converged(step_dt, outcome.iterations, hit_cap);
        if let Err(e) = monitors.after_step(solver, &grid, standing.time, end) {
            return Ok(Some(e));
        }
        if let (Some(rule), Some(watch)) = (&run.stop_at_rest, rest.as_mut()) {
            // a block still falling before its tilt, or a pile behind its gate, is not at rest
            let bulk = (!solver.release_pending(standing.time))
                .then(|| solver.bulk(rule.front_threshold))
                .flatten();
            if watch.at_rest_after(bulk, standing.time, rule) {
                break;
            }
        }
        progress(&Progress {
            time: standing.time,
            end_time: end,
            dt: standing.dt.dt(),
            iterations: outcome.iterations,
            steps: standing.summary.steps,
        });
        let by_wall = ctx
            .options
            .checkpoint_every
            .is_some_and(|every| last_checkpoint.elapsed() >= every);
        if standing.time >= next_checkpoint * (1.0 - 1e-9) || by_wall {
            save_checkpoint(ctx, solver, monitors, standing)?;
            if let Some(i) = run.checkpoint_interval {
                next_checkpoint = next_multiple(standing.time * (1.0 + 1e-9), i);
            }
            last_checkpoint = Instant::now();
        }
    }
    Ok(None)
}

/// Runs `case` at `fidelity`, writing into `out_dir`: `fields.pvd` + `.vtr` files at every
/// output interval, `profile_x<x>_t<t>.csv` for each profile monitor, `bulk.csv` for a bulk
/// monitor (solids mass, front, mean u_s), `resolved.ron` (the case as run),
/// `checkpoints/` and `summary.json` (rewritten at every checkpoint). A step that does not
/// converge, or whose linear solve fails, is retried with a smaller Δt; below Δt_min the
/// run stops with a diagnosis in the summary and keeps what it wrote. A stop request
/// ([`RunOptions::stop`]) ends the run after the current step with a checkpoint; an output
/// error ends it with status `Failed` in the summary where the summary can still be written.
///
/// The run holds its folder's lock ([`lock::RunLock`]) while it writes: a folder another
/// run writes is refused with [`RunError::Running`], whatever `options` say. A run that
/// ends (but interrupted) lists its synced files in the summary ([`seal`]). The run
/// executes on a thread of the current rayon pool ([`on_the_pool`]).
pub fn run_case_with(
    case: &Case,
    fidelity: Fidelity,
    out_dir: &Path,
    options: &RunOptions,
    progress: impl FnMut(&Progress) + Send,
) -> Result<RunSummary, RunError> {
    let _lock = lock::RunLock::acquire(out_dir)?;
    run_locked(case, fidelity, out_dir, options, progress)
}

/// [`run_case_with`] for a caller that holds the folder's lock ([`lock::RunLock`]).
pub(crate) fn run_locked(
    case: &Case,
    fidelity: Fidelity,
    out_dir: &Path,
    options: &RunOptions,
    mut progress: impl FnMut(&Progress) + Send,
) -> Result<RunSummary, RunError> {
    on_the_pool(|| {
        let case = case.at_fidelity(fidelity);
        let mut solver = case_solver(&case)?;
        run_solver(
            &case,
            fidelity,
            out_dir,
            options,
            solver.as_mut(),
            &mut progress,
        )
    })
}

/// Runs `job` on a thread of the current rayon pool (the global pool of
/// `RAYON_NUM_THREADS` threads, or the pool installed by the caller): the solver's serial
/// stages then run on a pool thread rather than on the calling thread beside all of the
/// pool's, one thread fewer competing for the cores (docs/history/performance-log.md,
/// "Two threads: the drag elimination's components, the multigrid's coarse lines": 40k
/// cells on two threads, wall 0.857 of the run from the main thread). Called from a thread
/// of the pool, `job` runs where it is.
pub fn on_the_pool<R: Send>(job: impl FnOnce() -> R + Send) -> R {
    rayon::scope(|_| job())
}

/// [`run_case_with`] on a solver already built from the resolved `case`.
fn run_solver(
    case: &Case,
    fidelity: Fidelity,
    out_dir: &Path,
    options: &RunOptions,
    solver: &mut dyn CaseSolver,
    progress: &mut dyn FnMut(&Progress),
) -> Result<RunSummary, RunError> {
    let ctx = RunContext {
        case,
        fidelity,
        out_dir,
        options,
        resolved: ron::ser::to_string_pretty(case, ron::ser::PrettyConfig::default())
            .expect("a case serialises"),
        started: Instant::now(),
    };
    let (mut monitors, mut standing) = if options.restart {
        resume(&ctx, solver)?
    } else {
        start_fresh(&ctx, solver)?
    };
    runout_output::write_atomic(&out_dir.join("resolved.ron"), ctx.resolved.as_bytes())
        .map_err(|e| ctx.out_err(e))?;
    let mut failure = time_loop(&ctx, solver, &mut monitors, &mut standing, progress)?;
    if failure.is_none() {
        failure = monitors.finish().err();
    }
    // a run that ends (not one stopped to continue) lists its synced files
    let mut files = Vec::new();
    if failure.is_none() && standing.summary.status != RunStatus::Interrupted {
        match seal::seal(out_dir) {
            Ok(sealed) => files = sealed,
            Err(source) => {
                failure = Some(OutputError::Io {
                    path: out_dir.to_path_buf(),
                    source,
                })
            }
        }
    }
    let mut raw = ctx.tallied(&standing, solver);
    raw.files = files;
    raw.status = match (&failure, raw.status) {
        (Some(e), _) => RunStatus::Failed {
            reason: format!("writing output at t = {} s: {e}", standing.time),
        },
        (None, RunStatus::Running) => RunStatus::Completed,
        (None, status) => status,
    };
    let summary = reported(
        &raw,
        standing.time,
        solver.solids_mass(),
        standing.initial_solids_mass,
    );
    let written = summary
        .write_json(&out_dir.join("summary.json"))
        .and_then(|()| {
            seal::sync_folder(out_dir).map_err(|source| OutputError::Io {
                path: out_dir.to_path_buf(),
                source,
            })
        });
    if let Some(e) = failure {
        return Err(ctx.out_err(e));
    }
    written.map_err(|e| ctx.out_err(e))?;
    Ok(summary)
}

#[cfg(test)]
mod impact_tests;
#[cfg(test)]
mod tests;
