//! `cargo xtask bench two-fluid`: the two-fluid solver's cost on this machine (issue 22).
//!
//! Rows, each run in this process on a rayon pool of the stated threads, timed by
//! getrusage (CPU s, all threads) and the wall clock:
//! - family M (`cases/mfix-slope/jj.ron`, MFIX's 200 × 50 grid) to `--window` s (default
//!   1 s, MFIX's whole run) on 1 and 2 threads: CPU s per simulated s, against MFIX's
//!   411 CPU s measured beside runout on this kind of machine (issue 22);
//! - family M refined k = 1, 2, 4 in x and y (10k, 40k, 160k cells) to `--refine-window` s
//!   (default 0.15 s) on one thread: the cost per cell per outer iteration, which should not grow with the grid;
//!   from k = `--two-threads-from` (default 2: 40k cells) on two threads as well, with the
//!   two-thread speed-up (one thread's wall time over two threads') printed per size;
//! - S-JJ-phi φ = 0.1 at the paper grid (1000 × 90) over a window after impact, restarted
//!   from a checkpoint at `--after` s that the first call makes and later calls reuse
//!   (runs/bench/), on 2 threads;
//! - with `--paper-full`, the same case's whole run to the paper's t = 1.25 s on 2 threads
//!   (about 20 min here; issue 22's target: under 30 min).
//!
//! Each row gives steps, outer iterations per step, µs per cell per outer iteration, the
//! linear-solver iterations per solve of each equation and the profile (share of the
//! solver's time per part). `--smoke` runs every row at a tiny size (CI: the command works;
//! no timing is asserted); `--write` appends the rows to docs/studies/performance.md with the
//! commit and date.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{bail, Context, Result};
use clap::Parser;
use runout_case::{load, Case, Fidelity, Loaded};
use runout_mesh::{AxisSpec, Segment};
use runout_output::RunSummary;
use runout_run::cpu_time::cpu_seconds;
use runout_run::{run_case_with, RunOptions};

/// MFIX 21.3.2's CPU seconds for family M's 1 s on this kind of machine (issue 22).
const MFIX_CPU_PER_SIMULATED_SECOND: f64 = 411.0;

/// Options of `cargo xtask bench two-fluid`.
#[derive(Parser, Debug)]
#[command(name = "bench two-fluid")]
pub struct Options {
    /// tiny sizes and windows: checks that the command works (CI), times nothing useful
    #[arg(long)]
    smoke: bool,
    /// family M's simulated window [s] for the thread rows
    #[arg(long, default_value_t = 1.0)]
    window: f64,
    /// the refinements of family M for the cost per cell (k: grid × k in x and y)
    #[arg(long, value_delimiter = ',', default_values_t = [1usize, 2, 4])]
    refine: Vec<usize>,
    /// the refinements from which the refined runs are also timed on two threads
    #[arg(long, default_value_t = 2)]
    two_threads_from: usize,
    /// the refined runs' simulated window [s]
    #[arg(long, default_value_t = 0.15)]
    refine_window: f64,
    /// S-JJ-phi paper grid: the window starts at this time [s] (after impact)
    #[arg(long, default_value_t = 0.3)]
    after: f64,
    /// S-JJ-phi paper grid: the window's length [s]
    #[arg(long, default_value_t = 0.02)]
    span: f64,
    /// leave out the S-JJ-phi paper-grid window
    #[arg(long)]
    skip_paper: bool,
    /// also time S-JJ-phi φ = 0.1's whole run at the paper grid (to the paper's t = 1.25 s)
    #[arg(long)]
    paper_full: bool,
    /// leave out the family-M rows (thread and refinement)
    #[arg(long)]
    skip_family_m: bool,
    /// append the rows to docs/studies/performance.md
    #[arg(long)]
    write: bool,
}

/// One measured row.
struct Row {
    what: String,
    threads: usize,
    cells: usize,
    simulated: f64,
    cpu: f64,
    wall: f64,
    summary: RunSummary,
}

impl Row {
    /// Every outer iteration the run did: of its accepted and of its rejected steps.
    fn all_outer_iterations(&self) -> u64 {
        self.summary.outer_iterations + self.summary.rejected_outer_iterations
    }

    /// CPU µs per cell per outer iteration, over all of them (the CPU time includes the
    /// rejected steps' iterations, so they are counted too).
    fn per_cell_iteration_us(&self) -> f64 {
        1e6 * self.cpu / (self.cells as f64 * self.all_outer_iterations().max(1) as f64)
    }

    fn iterations_per_step(&self) -> f64 {
        self.summary.outer_iterations as f64 / self.summary.steps.max(1) as f64
    }

    /// Linear iterations per outer iteration of each equation.
    fn linear(&self) -> String {
        let per = self.all_outer_iterations().max(1) as f64;
        self.summary
            .linear_iterations
            .iter()
            .map(|(eq, n)| format!("{eq} {:.1}", *n as f64 / per))
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// The three largest parts of the profile, as shares of the solver's time.
    fn profile(&self) -> String {
        let total: f64 = self.summary.profile.iter().map(|p| p.1).sum();
        let mut parts = self.summary.profile.clone();
        parts.sort_by(|a, b| b.1.total_cmp(&a.1));
        parts
            .iter()
            .take(4)
            .map(|(name, t)| format!("{name} {:.0} %", 100.0 * t / total.max(1e-300)))
            .collect::<Vec<_>>()
            .join(", ")
    }
}

fn load_case(root: &Path, file: &str, name: Option<&str>) -> Result<Case> {
    let path = root.join(file);
    let Loaded::Cases(cases) = load(&path).with_context(|| format!("loading {file}"))? else {
        bail!("{file} is not a case file")
    };
    cases
        .into_iter()
        .find(|c| name.is_none_or(|n| c.case.name == n))
        .map(|c| c.case)
        .with_context(|| format!("{file}: no case {name:?}"))
}

/// An axis with every uniform segment's cell count multiplied by `k`.
fn refined_axis(axis: &AxisSpec, k: usize) -> Result<AxisSpec> {
    let mut out = axis.clone();
    for s in out.segments.iter_mut() {
        match s {
            Segment::Uniform { cells, .. } => *cells *= k,
            other => bail!("refining only uniform segments, not {other:?}"),
        }
    }
    Ok(out)
}

/// Runs `case` (already at its fidelity) to `end` on `threads` threads into `dir`,
/// optionally continuing from the checkpoint there.
fn timed(
    what: String,
    case: &Case,
    threads: usize,
    dir: &Path,
    restart: bool,
    simulated: f64,
) -> Result<Row> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .context("building the thread pool")?;
    let options = RunOptions {
        restart,
        replace: true,
        ..RunOptions::default()
    };
    eprintln!("bench: {what} ({threads} thread(s))");
    let cpu0 = cpu_seconds();
    let wall = Instant::now();
    let summary = pool
        .install(|| run_case_with(case, Fidelity::Paper, dir, &options, |_| {}))
        .with_context(|| format!("running {what}"))?;
    let cpu = cpu_seconds() - cpu0;
    let wall = wall.elapsed().as_secs_f64();
    let (nx, ny) = summary.cells;
    Ok(Row {
        what,
        threads,
        cells: nx * ny,
        simulated,
        cpu,
        wall,
        summary,
    })
}

/// Family M on 1 and 2 threads, then refined.
fn family_m(root: &Path, opts: &Options, rows: &mut Vec<Row>) -> Result<()> {
    let base = load_case(root, "cases/mfix-slope/jj.ron", None)?;
    let fidelity = if opts.smoke {
        Fidelity::Smoke
    } else {
        Fidelity::Paper
    };
    let window = if opts.smoke { 0.02 } else { opts.window };
    let dir = root.join("runs/bench/M-JJ");
    for threads in [1, 2] {
        let mut case = base.at_fidelity(fidelity);
        case.run.end_time = window;
        let what = format!("family M to {window} s");
        rows.push(timed(
            what,
            &case,
            threads,
            &dir.join(format!("t{threads}")),
            false,
            window,
        )?);
    }
    let window = if opts.smoke { 0.01 } else { opts.refine_window };
    for &k in &opts.refine {
        let mut case = base.at_fidelity(fidelity);
        case.domain.x = refined_axis(&case.domain.x, k)?;
        case.domain.y = refined_axis(&case.domain.y, k)?;
        case.run.end_time = window;
        let threads: &[usize] = if k >= opts.two_threads_from {
            &[1, 2]
        } else {
            &[1]
        };
        for &t in threads {
            let what = format!("family M × {k} to {window} s");
            let out = dir.join(format!("k{k}-t{t}"));
            rows.push(timed(what, &case, t, &out, false, window)?);
        }
    }
    Ok(())
}

/// One thread's wall time over two threads' for every run timed on both.
fn speedups(rows: &[Row]) -> Vec<String> {
    let on =
        |what: &str, threads: usize| rows.iter().find(|r| r.what == what && r.threads == threads);
    let mut lines = Vec::new();
    for r in rows.iter().filter(|r| r.threads == 1) {
        if let Some(two) = on(&r.what, 2) {
            lines.push(format!(
                "{} ({} cells): two threads {:.2}× faster than one (wall {:.1} s → {:.1} s)",
                r.what,
                r.cells,
                r.wall / two.wall,
                r.wall,
                two.wall
            ));
        }
    }
    lines
}

/// S-JJ-phi φ = 0.1, the case of the paper-grid rows, at the paper fidelity (smoke with
/// `--smoke`).
fn s_jj_phi(root: &Path, opts: &Options) -> Result<(Case, Fidelity)> {
    let base = load_case(
        root,
        "cases/sensitivity/S-JJ-phi.ron",
        Some("S-JJ-phi_phi=0.1"),
    )?;
    let fidelity = if opts.smoke {
        Fidelity::Smoke
    } else {
        Fidelity::Paper
    };
    Ok((base.at_fidelity(fidelity), fidelity))
}

/// S-JJ-phi φ = 0.1 at the paper grid over [after, after + span] from a kept checkpoint.
fn paper_window(root: &Path, opts: &Options, rows: &mut Vec<Row>) -> Result<()> {
    let (mut case, fidelity) = s_jj_phi(root, opts)?;
    let (after, span) = if opts.smoke {
        (0.22, 0.01)
    } else {
        (opts.after, opts.span)
    };
    // the window's case: its checkpoint at `after` and the window both run it
    case.run.end_time = after + span;
    let start = root.join(format!("runs/bench/S-JJ-phi-{}-t{after}", fidelity.name()));
    // kept from an earlier call, if interrupted there and written by this version
    let has_checkpoint = start.join("summary.json").exists()
        && std::fs::read_to_string(start.join("summary.json"))
            .is_ok_and(|s| s.contains("\"Interrupted\""))
        && runout_run::checkpoint::of_this_version(&start);
    if !has_checkpoint {
        eprintln!(
            "bench: S-JJ-phi to t = {after} s at {fidelity} (once; kept in {})",
            start.display()
        );
        let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
        let flag = stop.clone();
        let options = RunOptions {
            replace: true,
            stop: Some(stop),
            ..RunOptions::default()
        };
        // a stop request at the first step past `after` makes the checkpoint the window
        // starts from (a case ending at `after` would be another case to restart)
        run_case_with(&case, Fidelity::Paper, &start, &options, |p| {
            if p.time >= after {
                flag.store(true, std::sync::atomic::Ordering::SeqCst);
            }
        })
        .context("running S-JJ-phi to the start of the window")?;
    }
    // copy the run folder so that the kept checkpoint stays at `after`
    let window_dir = root.join(format!("runs/bench/S-JJ-phi-{}-window", fidelity.name()));
    let _ = std::fs::remove_dir_all(&window_dir);
    copy_dir(&start, &window_dir)?;
    let before: RunSummary = runout_post::folder::read_summary(&start)
        .with_context(|| format!("no summary.json in {}", start.display()))??;
    let what = format!(
        "S-JJ-phi φ = 0.1 {fidelity} grid, t = {:.3}–{:.3} s",
        before.simulated_time,
        after + span
    );
    let mut row = timed(
        what,
        &case,
        2,
        &window_dir,
        true,
        after + span - before.simulated_time,
    )?;
    // the window's own tallies
    let s = &mut row.summary;
    s.steps -= before.steps;
    s.outer_iterations -= before.outer_iterations;
    s.rejected_steps -= before.rejected_steps;
    s.rejected_outer_iterations -= before.rejected_outer_iterations;
    for (part, t) in s.profile.iter_mut() {
        *t -= before
            .profile
            .iter()
            .find(|p| p.0 == *part)
            .map_or(0.0, |p| p.1);
    }
    for (eq, n) in s.linear_iterations.iter_mut() {
        *n -= before
            .linear_iterations
            .iter()
            .find(|p| p.0 == *eq)
            .map_or(0, |p| p.1);
    }
    rows.push(row);
    Ok(())
}

/// Wall time target of issue 22 for S-JJ-phi's whole paper-grid run on two threads [s].
const PAPER_FULL_TARGET_WALL: f64 = 30.0 * 60.0;
/// The end of the whole-run row's label, by which the target line finds it.
const WHOLE_RUN: &str = "whole run";

/// S-JJ-phi φ = 0.1's whole run at the paper grid (or smoke with `--smoke`) on 2 threads,
/// from t = 0 to the case's end (the paper's t = 1.25 s after the impact).
fn paper_full(root: &Path, opts: &Options, rows: &mut Vec<Row>) -> Result<()> {
    let (case, fidelity) = s_jj_phi(root, opts)?;
    let dir = root.join(format!("runs/bench/S-JJ-phi-{}-full", fidelity.name()));
    let what = format!("S-JJ-phi φ = 0.1 {fidelity} grid, {WHOLE_RUN}");
    let row = timed(what, &case, 2, &dir, false, case.run.end_time)?;
    // the case's end time is on the paper's clock (from the impact); per simulated second
    // counts the run's own clock, which ends later
    rows.push(Row {
        simulated: row.summary.simulated_time,
        ..row
    });
    Ok(())
}

fn copy_dir(from: &Path, to: &Path) -> Result<()> {
    std::fs::create_dir_all(to)?;
    for entry in std::fs::read_dir(from)? {
        let entry = entry?;
        let target = to.join(entry.file_name());
        if entry.file_type()?.is_dir() {
            copy_dir(&entry.path(), &target)?;
        } else {
            std::fs::copy(entry.path(), &target)?;
        }
    }
    Ok(())
}

fn commit(root: &Path) -> String {
    std::process::Command::new("git")
        .args(["rev-parse", "--short", "HEAD"])
        .current_dir(root)
        .output()
        .ok()
        .filter(|o| o.status.success())
        .map_or("unknown".into(), |o| {
            String::from_utf8_lossy(&o.stdout).trim().to_string()
        })
}

fn table(rows: &[Row], commit: &str, date: &str) -> String {
    let mut t = String::from(
        "| commit, date | run | threads | cells | steps (rejected; their outer it.) | outer it./step | CPU s | wall s | CPU s per sim. s | µs per cell per outer it. (all, rejected steps' too) | linear it. per outer it. (summed over the equation's solves: 4 for momentum) | largest profile parts |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    for r in rows {
        t.push_str(&format!(
            "| {commit}, {date} | {} | {} | {} | {} ({}; {}) | {:.1} | {:.1} | {:.1} | {:.1} | {:.2} | {} | {} |\n",
            r.what,
            r.threads,
            r.cells,
            r.summary.steps,
            r.summary.rejected_steps,
            r.summary.rejected_outer_iterations,
            r.iterations_per_step(),
            r.cpu,
            r.wall,
            r.cpu / r.simulated,
            r.per_cell_iteration_us(),
            r.linear(),
            r.profile(),
        ));
    }
    t
}

/// Runs the benchmark and prints (and with `--write` appends) its table.
pub fn run(root: &Path, args: &[String]) -> Result<()> {
    let opts = Options::try_parse_from(
        std::iter::once("bench two-fluid".to_string()).chain(args.iter().cloned()),
    )?;
    // the commit measured: the checkout as the benchmark starts
    let measured = commit(root);
    let mut rows = Vec::new();
    if !opts.skip_family_m {
        family_m(root, &opts, &mut rows)?;
    }
    if !opts.skip_paper {
        paper_window(root, &opts, &mut rows)?;
    }
    if opts.paper_full {
        paper_full(root, &opts, &mut rows)?;
    }
    let date = std::process::Command::new("date")
        .args(["-u", "+%Y-%m-%d %H:%M UTC"])
        .output()
        .map_or("unknown".into(), |o| {
            String::from_utf8_lossy(&o.stdout).trim().to_string()
        });
    let mut table = table(&rows, &measured, &date);
    let speedups = speedups(&rows);
    if !speedups.is_empty() {
        table.push('\n');
        speedups
            .iter()
            .for_each(|l| table.push_str(&format!("- {l}\n")));
    }
    println!("{table}");
    if let Some(m) = rows
        .iter()
        .find(|r| r.threads == 1 && r.what.starts_with("family M to"))
    {
        println!(
            "family M on one thread: {:.1} CPU s per simulated s; MFIX {MFIX_CPU_PER_SIMULATED_SECOND}: {:.1}× cheaper",
            m.cpu / m.simulated,
            MFIX_CPU_PER_SIMULATED_SECOND / (m.cpu / m.simulated)
        );
    }
    if let Some(full) = rows
        .iter()
        .find(|r| !opts.smoke && r.what.ends_with(WHOLE_RUN))
    {
        println!(
            "S-JJ-phi φ = 0.1 whole run ({} cells, t = {:.4} s of the run, {:?}): {:.1} min wall on 2 threads; issue 22's target {:.0} min: {}",
            full.cells,
            full.summary.simulated_time,
            full.summary.status,
            full.wall / 60.0,
            PAPER_FULL_TARGET_WALL / 60.0,
            if full.wall < PAPER_FULL_TARGET_WALL
                && full.summary.status == runout_output::RunStatus::Completed
            {
                "met"
            } else {
                "not met"
            }
        );
    }
    if opts.write && !opts.smoke {
        let path: PathBuf = root.join("docs/studies/performance.md");
        let mut text = std::fs::read_to_string(&path)?;
        text.push_str(&format!(
            "\n### `cargo xtask bench two-fluid {}` ({date})\n\n{table}",
            args.join(" ")
        ));
        runout_output::write_atomic(&path, text.as_bytes())?;
    }
    Ok(())
}
