//! A sweep: the cases of a [`Matrix`] (expanded from a case file, a sweep file or a folder
//! of them) run in parallel below a root folder (`runout sweep`, and `cargo xtask sweep` on
//! the paper's matrix).
//!
//! Every run writes into `runs/<case>/<fidelity>.partial/` and is renamed to
//! `runs/<case>/<fidelity>/` when it ends, so a finished folder is always complete; a run
//! whose folder exists with a summary is skipped, so a killed sweep resumes where it
//! stopped. `results/summary.csv` gets one row per case and fidelity: a sweep merges the
//! rows of its cases into the file (a `--shard` or `--only` keeps the other rows; several
//! shards may write at once), see [`crate::summary`].
//!
//! Runs go longest first to the first free worker (the length: the case's wall time in the
//! last results/summary.csv at this fidelity, else its cells × simulated time). A case that
//! repeats another at this fidelity in everything but its name and description (the base
//! point shared by several one-factor families) is run once; its folder is copied
//! ([`crate::repeat`]), and the summary's wall time is the one run's.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Instant;

use anyhow::{bail, Context, Result};
use indicatif::{MultiProgress, ProgressBar, ProgressStyle};
use runout_case::{case_files, load, Case, Fidelity, Loaded, SourcedCase};
use runout_output::RunSummary;
use runout_run::store::{self, Request, Reuse, Stored};
use runout_run::{signals, Progress, RunError};

use crate::metrics::{described_speeds, flow_metrics, FlowMetrics};
use crate::summary;

/// Options of a sweep.
pub struct SweepOptions {
    /// fidelity of every run
    pub fidelity: Fidelity,
    /// keep only cases whose name contains this
    pub only: Option<String>,
    /// parallel runs
    pub jobs: usize,
    /// run shard i of n (1-based)
    pub shard: Option<(usize, usize)>,
    /// list the matrix, run nothing
    pub list: bool,
    /// described or measured gate speeds (CSV `gate,x,speed`) for the `mse_vs_described`
    /// column; empty without
    pub gates: Option<PathBuf>,
    /// the program as the user types it (`runout`, `cargo xtask`), for the messages that say
    /// how to continue
    pub program: &'static str,
}

/// The case matrix of a case directory.
pub struct Matrix {
    /// every case a sweep file expands to, plus stand-alone cases no sweep uses as its base
    pub runs: Vec<SourcedCase>,
    /// analytic families: (name, file)
    pub analytic: Vec<(String, PathBuf)>,
}

/// Parses `--shard i/n` (1-based: shard i of n).
pub fn parse_shard(s: &str) -> Result<(usize, usize)> {
    let (i, n) = s.split_once('/').context("--shard must look like i/n")?;
    let (i, n): (usize, usize) = (i.trim().parse()?, n.trim().parse()?);
    if n == 0 || i == 0 || i > n {
        bail!("--shard {s}: need 1 <= i <= n");
    }
    Ok((i, n))
}

/// The progress-bar style of one run (case name, bar, time and Δt, eta).
pub fn progress_style() -> ProgressStyle {
    ProgressStyle::with_template("{prefix:<34} [{bar:25}] {msg} (eta {eta})")
        .expect("a valid template")
        .progress_chars("=> ")
}

/// Expands and validates every file below `cases_dir` into the [`Matrix`].
pub fn matrix(cases_dir: &Path) -> Result<Matrix> {
    let mut loaded = Vec::new();
    let mut analytic = Vec::new();
    let mut errors = 0;
    for f in case_files(&[cases_dir.to_path_buf()]) {
        match load(&f) {
            Ok(Loaded::Cases(cases)) => loaded.push((f, cases)),
            Ok(Loaded::Analytic(a)) => analytic.push((a.name, f)),
            Err(e) => {
                errors += 1;
                eprintln!("{e}");
            }
        }
    }
    if errors > 0 {
        bail!("{errors} case file(s) rejected; nothing was run");
    }
    // A sweep's base named `base.ron` is a template, not a run of its own; a base with any
    // other name (cases/mfix-slope/jj.ron, the base of the other floors of family M) is a
    // case in its own right and runs as well.
    let canonical = |p: &Path| p.canonicalize().unwrap_or_else(|_| p.to_path_buf());
    let templates: BTreeSet<PathBuf> = loaded
        .iter()
        .flat_map(|(_, cases)| {
            cases
                .iter()
                .filter_map(|c| c.base.as_deref())
                .filter(|b| b.file_name().is_some_and(|n| n == "base.ron"))
                .map(canonical)
        })
        .collect();
    let runs = loaded
        .into_iter()
        .filter(|(f, _)| !templates.contains(&canonical(f)))
        .flat_map(|(_, cases)| cases)
        .collect();
    Ok(Matrix { runs, analytic })
}

/// How one run of the matrix ended.
pub enum Outcome {
    /// ran now or earlier; its summary
    Done(RunSummary),
    /// finished in an earlier sweep
    Skipped(RunSummary),
    /// the same case as another run of the matrix (named), whose folder was copied
    Copied(RunSummary, String),
    /// the solver cannot run this case yet
    Unsupported(String),
    /// the run failed before producing a summary
    Failed(String),
    /// stopped by a signal with a checkpoint in its `.partial` folder: the next sweep
    /// continues it
    Interrupted(RunSummary),
    /// another process is writing its folder (the lock's holder: pid, host, since): not
    /// run, and its row left alone
    Elsewhere(String),
}

/// Runs one case into its folder, atomically.
fn run_one(
    case: &SourcedCase,
    fidelity: Fidelity,
    root: &Path,
    bar: &ProgressBar,
    stop: &Arc<AtomicBool>,
) -> Outcome {
    let name = &case.case.name;
    // the folder is checked to lie below runs/ (a name such as `..` cannot pass)
    let done = match runout_case::run_dir(root, name, fidelity) {
        Ok(dir) => dir,
        Err(e) => return Outcome::Failed(e.to_string()),
    };
    // a finished run of the same resolved case is kept
    run_into(&case.case, fidelity, &done, Reuse::SameCase, bar, stop)
}

/// Runs `case` at `fidelity` into `done` through the run store (`<done>.partial`, renamed
/// when the run ends; continued from its checkpoint if one is there), or takes the finished
/// run there as `reuse` says.
pub fn run_into(
    case: &Case,
    fidelity: Fidelity,
    done: &Path,
    reuse: Reuse,
    bar: &ProgressBar,
    stop: &Arc<AtomicBool>,
) -> Outcome {
    let request = Request {
        reuse,
        checkpoint_every: Some(store::CHECKPOINT_EVERY),
        stop: Some(stop.clone()),
        ..Request::default()
    };
    let show = |p: &Progress| {
        bar.set_position((1000.0 * p.time / p.end_time) as u64);
        bar.set_message(format!(
            "t = {:.3} s, dt = {:.1e} s, {} it",
            p.time, p.dt, p.iterations
        ));
    };
    let result = store::obtain(done, case, fidelity, &request, show);
    bar.finish_and_clear();
    match result {
        Ok(Stored::Interrupted(summary)) => Outcome::Interrupted(summary),
        Ok(Stored::Ran(summary)) => Outcome::Done(summary),
        Ok(Stored::Reused(summary)) => Outcome::Skipped(summary),
        Err(RunError::Unsupported { reason, .. }) => Outcome::Unsupported(reason),
        Err(RunError::Running { holder, .. }) => Outcome::Elsewhere(holder),
        Err(e) => Outcome::Failed(e.to_string()),
    }
}

/// Wall time per case of the rows of an earlier `results/summary.csv` at `fidelity` that
/// have one (empty if there is none).
fn previous_wall_times(path: &Path, fidelity: Fidelity) -> std::collections::HashMap<String, f64> {
    let Ok(mut reader) = csv::Reader::from_path(path) else {
        return Default::default();
    };
    reader
        .records()
        .filter_map(|r| r.ok())
        .filter(|r| r.get(1) == Some(fidelity.name()))
        .filter_map(|r| Some((r.get(0)?.to_string(), r.get(3)?.parse().ok()?)))
        .collect()
}

/// For each selected case, the index of an earlier one it repeats at this fidelity (equal
/// in everything but its name and description), if any.
fn duplicates(selected: &[&SourcedCase], fidelity: Fidelity) -> Vec<Option<usize>> {
    let anonymous: Vec<_> = selected
        .iter()
        .map(|r| {
            let mut c = r.case.at_fidelity(fidelity);
            c.name.clear();
            c.description.clear();
            c
        })
        .collect();
    (0..selected.len())
        .map(|k| (0..k).find(|&e| anonymous[e] == anonymous[k]))
        .collect()
}

pub use runout_run::store::finished_run;

/// CSV field quoting (RFC 4180).
pub fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// Header of results/summary.csv (issue 8); the flow columns are defined in
/// [`crate::metrics`] and are empty where a run has no such monitor (or did not reach its
/// time, e.g. the 1.25 s profiles at smoke fidelity).
const HEADER: &str = "case,fidelity,status,wall_time_s,steps,rejected_steps,mean_dt_s,air_cushion,\
cushion_thickness_m,floor_eps_s,flow_thickness_m,max_u_s,h_wu_probe_t1.25,gate_speeds,mse_vs_described";

fn csv_row(name: &str, fidelity: Fidelity, outcome: &Outcome, flow: &FlowMetrics) -> String {
    // the eight flow columns after mean_dt_s
    let empty_flow = ",".repeat(8);
    match outcome {
        Outcome::Done(s) | Outcome::Skipped(s) | Outcome::Copied(s, _) => format!(
            "{},{fidelity},{},{:.3},{},{},{:e},{}",
            csv_field(name),
            csv_field(&format!("{:?}", s.status)),
            s.wall_time,
            s.steps,
            s.rejected_steps,
            s.dt.mean,
            flow.csv()
        ),
        Outcome::Unsupported(why) => format!(
            "{},{fidelity},{},,,,{empty_flow}",
            csv_field(name),
            csv_field(&format!("unsupported: {why}"))
        ),
        Outcome::Failed(why) => format!(
            "{},{fidelity},{},,,,{empty_flow}",
            csv_field(name),
            csv_field(&format!("failed: {why}"))
        ),
        Outcome::Interrupted(s) => format!(
            "{},{fidelity},{},,,,{empty_flow}",
            csv_field(name),
            csv_field(&format!(
                "interrupted at t = {} s (a checkpoint: the next sweep continues it)",
                s.simulated_time
            ))
        ),
        Outcome::Elsewhere(_) => unreachable!("a run going elsewhere has no row here"),
    }
}

/// The cases of the sweeps of `study` under `cases_dir` (`Sweep(study: "...")`); an error
/// if there are none.
pub fn study_matrix(cases_dir: &Path, study: &str) -> Result<Matrix> {
    let mut m = matrix(cases_dir)?;
    m.runs.retain(|r| r.study.as_deref() == Some(study));
    m.analytic.clear();
    if m.runs.is_empty() {
        bail!(
            "no sweep under {} declares `study: \"{study}\"`",
            cases_dir.display()
        );
    }
    Ok(m)
}

/// Lists and (unless `list`) runs the matrix below `root` (`runs/`); merges its rows into
/// `results/summary.csv` there.
pub fn sweep(root: &Path, matrix: &Matrix, opts: &SweepOptions) -> Result<()> {
    let (runs, analytic) = (&matrix.runs, &matrix.analytic);
    let selected: Vec<&SourcedCase> = runs
        .iter()
        .filter(|r| opts.only.as_deref().is_none_or(|p| r.case.name.contains(p)))
        .enumerate()
        .filter(|(k, _)| opts.shard.is_none_or(|(i, n)| k % n == i - 1))
        .map(|(_, r)| r)
        .collect();
    let fidelity = opts.fidelity;
    list_selection(root, &selected, runs.len(), analytic, opts)?;
    if opts.list {
        return Ok(());
    }
    // refused before anything runs: a file of another xtask version cannot take the rows
    let results = root.join("results").join("summary.csv");
    summary::check_header(&results, HEADER)?;

    let runs_dir = root.join("runs");
    let started = Instant::now();
    // Runs the matrix repeats (the base point of several one-factor families: same case
    // apart from its name and description) are computed once and copied.
    let same_as = duplicates(&selected, fidelity);
    let order = longest_first(&selected, &same_as, &results, fidelity);
    let stop = signals::stop_on_signals(
        "sweep",
        "the running cases stop after their step with a checkpoint; run the sweep again to \
         continue them",
    );
    let mut outcomes = run_in_parallel(root, &selected, order, fidelity, opts.jobs, &stop)?;
    for (k, original) in same_as.iter().enumerate() {
        let Some(original) = *original else {
            continue;
        };
        let from = &selected[original].case.name;
        let of_original = outcomes
            .iter()
            .find(|(e, _)| *e == original)
            .map(|(_, o)| o);
        let copy = || crate::repeat::copy_run(&runs_dir, from, &selected[k].case.name, fidelity);
        if let Some(outcome) = crate::repeat::repeat_outcome(from, of_original, copy) {
            outcomes.push((k, outcome));
        }
    }
    outcomes.sort_by_key(|(k, _)| *k);

    let described = opts
        .gates
        .as_deref()
        .map(described_speeds)
        .unwrap_or_default();
    let mut rows = Vec::new();
    let mut tally = Tally::default();
    for (k, outcome) in &outcomes {
        let name = &selected[*k].case.name;
        tally.count(name, outcome);
        if matches!(outcome, Outcome::Elsewhere(_)) {
            continue; // its row is the other process's to write
        }
        let flow = match outcome {
            Outcome::Done(_) | Outcome::Skipped(_) | Outcome::Copied(..) => {
                flow_metrics(&runs_dir.join(name).join(fidelity.name()), &described)
            }
            _ => FlowMetrics::default(),
        };
        rows.push(csv_row(name, fidelity, outcome, &flow));
    }
    let order: Vec<&str> = runs.iter().map(|r| r.case.name.as_str()).collect();
    let total = summary::write_merged(&results, HEADER, &rows, &order, summary::LOCK_TIMEOUT)?;
    let Tally {
        ran,
        skipped,
        copied,
        unsupported,
        failed,
        interrupted,
        elsewhere,
    } = tally;
    println!(
        "ran {ran}, copied {copied} (repeats of a run), skipped {skipped} (finished earlier), \
         unsupported {unsupported}, failed {failed}, running elsewhere {elsewhere} in {:.1} s; \
         {} row(s) merged into {} ({total} in all)",
        started.elapsed().as_secs_f64(),
        rows.len(),
        results.strip_prefix(root).unwrap_or(&results).display()
    );
    if unsupported > 0 {
        println!(
            "NOT YET: {unsupported} case(s) need parts of the two-fluid model (issue 7) that do not \
             exist yet (see the status column of results/summary.csv); they were validated but not \
             solved."
        );
    }
    if failed > 0 {
        bail!("{failed} run(s) failed");
    }
    if elsewhere > 0 {
        bail!(
            "{elsewhere} case(s) running elsewhere were not run here and their rows were left \
             alone: the process writing them merges them; run the sweep again after it ends \
             for any it did not finish"
        );
    }
    if interrupted > 0 || stop.load(Ordering::SeqCst) {
        bail!(
            "interrupted: {interrupted} run(s) keep a checkpoint; `{} sweep` with the same \
             options continues them (finished runs are skipped)",
            opts.program
        );
    }
    Ok(())
}

/// Prints the selection: a header line, one line per flow case (grid, end time, file) and
/// per analytic family, and the total cell count.
fn list_selection(
    root: &Path,
    selected: &[&SourcedCase],
    matrix_size: usize,
    analytic: &[(String, PathBuf)],
    opts: &SweepOptions,
) -> Result<()> {
    let fidelity = opts.fidelity;
    println!(
        "case matrix at fidelity `{fidelity}`: {} of {} flow case(s){}, {} analytic famil{}",
        selected.len(),
        matrix_size,
        opts.shard
            .map_or(String::new(), |(i, n)| format!(" (shard {i}/{n})")),
        analytic.len(),
        if analytic.len() == 1 { "y" } else { "ies" }
    );
    let mut cells = 0usize;
    for r in selected {
        let c = r.case.at_fidelity(fidelity);
        let g = c.grid()?;
        cells += g.cell_count();
        println!(
            "  {:<34} {:>5} x {:<4} to {:>6.3} s   {}",
            c.name,
            g.nx(),
            g.ny(),
            c.run.end_time,
            r.file.strip_prefix(root).unwrap_or(&r.file).display()
        );
    }
    for (name, f) in analytic {
        println!(
            "  {name:<34} closed form: {}   {}",
            analytic_hint(opts.program),
            f.strip_prefix(root).unwrap_or(f).display()
        );
    }
    println!("total cells over the selection: {cells}");
    if !opts.list {
        println!(
            "{} run(s) at once, {} thread(s) each",
            opts.jobs.max(1),
            crate::jobs::threads_per_job(opts.jobs)
        );
    }
    Ok(())
}

/// What a sweep says of an analytic family: the report that draws it (the repository's
/// `cargo xtask report analytic`), or that a sweep does not run it.
fn analytic_hint(program: &str) -> String {
    if program == "cargo xtask" {
        "`cargo xtask report analytic`".into()
    } else {
        "not run by a sweep".into()
    }
}

/// The runs to compute (not repeats, `same_as[k]` none), longest first, each worker taking
/// the next: the sweep's duration then is not set by a long run started last. The length is
/// the wall time of the case's row in the last results/summary.csv at this fidelity, else
/// cells × simulated time scaled by the rows that have both (stiff runs take 10× a normal
/// one on the same grid).
fn longest_first(
    selected: &[&SourcedCase],
    same_as: &[Option<usize>],
    results: &Path,
    fidelity: Fidelity,
) -> Vec<usize> {
    let mut order: Vec<usize> = (0..selected.len())
        .filter(|&k| same_as[k].is_none())
        .collect();
    let measured = previous_wall_times(results, fidelity);
    let size = |k: usize| -> f64 {
        let c = selected[k].case.at_fidelity(fidelity);
        c.grid().map_or(0.0, |g| g.cell_count() as f64) * c.run.end_time
    };
    // seconds per (cell × simulated second) over the cases that have a measured time
    let (t_sum, s_sum) = (0..selected.len())
        .filter_map(|k| measured.get(&selected[k].case.name).map(|t| (t, size(k))))
        .fold((0.0, 0.0), |(a, b), (t, s)| (a + t, b + s));
    let rate = if s_sum > 0.0 { t_sum / s_sum } else { 1.0 };
    let work = |k: usize| -> f64 {
        measured
            .get(&selected[k].case.name)
            .copied()
            .unwrap_or_else(|| rate * size(k))
    };
    order.sort_by(|&a, &b| work(b).total_cmp(&work(a)));
    order
}

/// Runs the selected cases `order` names on `jobs` workers, each on a thread pool of its own
/// ([`crate::jobs`]) and with a progress bar, until the queue is empty or a signal stops the
/// sweep; the outcomes in the order they ended.
fn run_in_parallel(
    root: &Path,
    selected: &[&SourcedCase],
    order: Vec<usize>,
    fidelity: Fidelity,
    jobs: usize,
    stop: &Arc<AtomicBool>,
) -> Result<Vec<(usize, Outcome)>> {
    let progress = MultiProgress::new();
    let style = progress_style();
    let outcomes: Mutex<Vec<(usize, Outcome)>> = Mutex::new(Vec::new());
    crate::jobs::run_queue(
        order,
        jobs,
        || !stop.load(Ordering::SeqCst),
        |k| {
            let r = selected[k];
            let bar = progress.add(ProgressBar::new(1000));
            bar.set_style(style.clone());
            bar.set_prefix(r.case.name.clone());
            let outcome = run_one(r, fidelity, root, &bar, stop);
            outcomes
                .lock()
                .expect("no poisoned lock")
                .push((k, outcome));
        },
    )?;
    Ok(outcomes.into_inner().expect("no poisoned lock"))
}

/// How the runs of a sweep ended, counted.
#[derive(Default)]
struct Tally {
    ran: usize,
    skipped: usize,
    copied: usize,
    unsupported: usize,
    failed: usize,
    interrupted: usize,
    elsewhere: usize,
}

impl Tally {
    /// Counts `outcome` of run `name`, printing a line for a run made now, a copy, a failure
    /// or an interruption.
    fn count(&mut self, name: &str, outcome: &Outcome) {
        match outcome {
            Outcome::Done(s) => {
                self.ran += 1;
                println!(
                    "  {name:<34} {:?}, {} steps, {:.1} s wall",
                    s.status, s.steps, s.wall_time
                );
            }
            Outcome::Skipped(_) => self.skipped += 1,
            Outcome::Copied(_, from) => {
                self.copied += 1;
                println!("  {name:<34} the same case as {from}: copied");
            }
            Outcome::Unsupported(_) => self.unsupported += 1,
            Outcome::Failed(why) => {
                self.failed += 1;
                println!("  {name:<34} FAILED: {why}");
            }
            Outcome::Interrupted(s) => {
                self.interrupted += 1;
                println!(
                    "  {name:<34} interrupted at t = {} s with a checkpoint",
                    s.simulated_time
                );
            }
            Outcome::Elsewhere(holder) => {
                self.elsewhere += 1;
                println!("  {name:<34} running elsewhere ({holder}): skipped, row left alone");
            }
        }
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use runout_output::{DtStats, RunStatus};

    #[test]
    fn a_run_of_a_case_timed_from_the_impact_is_found_again() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let case = runout_case::load_case(&root.join("cases/sensitivity/base.ron")).unwrap();
        // a caller that sets its own end time on the impact clock (as error-time does)
        let mut on_impact = case.clone();
        on_impact.run.end_time = 0.2;
        // the run writes its case in the start clock
        let tmp = runout_post::fixture::TempDir::new("finished-impact-clock");
        let written = ron::ser::to_string(&on_impact.clone().with_start_clock()).unwrap();
        runout_post::fixture::write_run(
            &tmp.0,
            &case.name,
            "smoke",
            0.2,
            &[("resolved.ron", &written)],
        );
        let dir = tmp.0.join(&case.name).join("smoke");
        assert!(
            finished_run(&dir, &on_impact).is_some(),
            "the impact-clock case matches its start-clock record"
        );
        let mut other = on_impact.clone();
        other.run.end_time = 0.3;
        assert!(
            finished_run(&dir, &other).is_none(),
            "another end time does not"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    fn columns(row: &str) -> usize {
        csv::ReaderBuilder::new()
            .has_headers(false)
            .from_reader(row.as_bytes())
            .records()
            .next()
            .expect("one record")
            .expect("valid CSV")
            .len()
    }

    #[test]
    fn previous_wall_times_read_the_rows_of_one_fidelity() {
        let dir = std::env::temp_dir().join(format!("runout-sweep-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("summary.csv");
        let text = format!(
            "{HEADER}\na,coarse,Completed,12.5,1,0,1e-3{empty}\nb,smoke,Completed,2.0,1,0,1e-3{empty}\n\
             c,coarse,\"failed: x, y\",,,,{empty}\n",
            empty = ",".repeat(8)
        );
        std::fs::write(&path, text).unwrap();
        let t = previous_wall_times(&path, Fidelity::Coarse);
        assert_eq!(t.len(), 1);
        assert_eq!(t["a"], 12.5);
        assert!(previous_wall_times(&dir.join("none.csv"), Fidelity::Coarse).is_empty());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// Issue 21: sweeps of subsets (`--only`, `--shard`) run in turn keep each other's rows
    /// of results/summary.csv, in the matrix's order. The runs exist already (a summary.json
    /// each), so nothing is solved.
    #[test]
    fn subsets_run_in_turn_keep_each_others_rows() {
        use runout_post::fixture::{write_run, TempDir};
        let tmp = TempDir::new("sweep-subsets");
        let cases = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases");
        let names = [
            "S-JJ-d_d=0.0001",
            "S-JJ-d_d=0.0005",
            "S-JJ-d_d=0.001",
            "S-JJ-phi_phi=1",
            "S-JJ-phi_phi=0.1",
            "S-JJ-phi_phi=0.01",
        ];
        for name in names {
            write_run(&tmp.0.join("runs"), name, "smoke", 0.4, &[]);
        }
        let sweep_of = |only: &str, shard: Option<(usize, usize)>| {
            let opts = SweepOptions {
                fidelity: Fidelity::Smoke,
                only: Some(only.into()),
                jobs: 1,
                shard,
                list: false,
                gates: None,
                program: "runout",
            };
            sweep(&tmp.0, &matrix(&cases).unwrap(), &opts).unwrap();
            let text = std::fs::read_to_string(tmp.0.join("results").join("summary.csv")).unwrap();
            let mut reader = csv::Reader::from_reader(text.as_bytes());
            assert_eq!(
                reader
                    .headers()
                    .unwrap()
                    .iter()
                    .collect::<Vec<_>>()
                    .join(","),
                HEADER
            );
            reader
                .records()
                .map(|r| r.unwrap().get(0).unwrap().to_string())
                .collect::<Vec<_>>()
        };
        assert_eq!(sweep_of("S-JJ-phi", None), names[3..]);
        assert_eq!(
            sweep_of("S-JJ-d", None),
            names,
            "the S-JJ-phi rows are kept"
        );
        // a rerun of a subset replaces its rows and keeps the rest
        assert_eq!(sweep_of("S-JJ-phi_phi=1", None), names);
        // shards of one sweep, written in turn
        std::fs::remove_file(tmp.0.join("results").join("summary.csv")).unwrap();
        assert_eq!(sweep_of("S-JJ", Some((2, 2))).len(), 3);
        assert_eq!(sweep_of("S-JJ", Some((1, 2))), names);
    }

    /// A finished run's summary for the outcomes of the tests.
    pub(crate) fn summary() -> RunSummary {
        RunSummary {
            case: "x".into(),
            fidelity: "smoke".into(),
            cells: (1, 1),
            simulated_time: 1.0,
            wall_time: 1.0,
            steps: 3,
            rejected_steps: 0,
            outer_iterations: 9,
            rejected_outer_iterations: 0,
            dt: DtStats {
                min: 0.1,
                max: 0.5,
                mean: 0.3,
            },
            solids_mass_change: 0.0,
            max_mass_imbalance: 0.0,
            max_eps_s: 0.6,
            status: RunStatus::Completed,
            profile: Vec::new(),
            linear_iterations: Vec::new(),
            files: Vec::new(),
        }
    }

    #[test]
    fn every_row_has_the_header_width() {
        let width = columns(HEADER);
        let summary = summary();
        for outcome in [
            Outcome::Done(summary.clone()),
            Outcome::Skipped(summary),
            Outcome::Unsupported("needs, \"quotes\"".into()),
            Outcome::Failed("x".into()),
        ] {
            let flow = FlowMetrics {
                gate_speeds: vec![(1, 2.0), (2, 3.5)],
                ..FlowMetrics::default()
            };
            assert_eq!(
                columns(&csv_row("S-PS-cw_cw=1", Fidelity::Smoke, &outcome, &flow)),
                width
            );
        }
    }
}
