//! `cargo xtask stability`: the stiff and extreme cases of issue 7 (cases/stability/).
//!
//! Every case must either run to its end time or stop with a diagnosis (equation, cell,
//! time); none may write a non-finite value. Each case runs in-process like a sweep run
//! (one at a time unless `--jobs`), into `runs/stability/<case>/<fidelity>/` (cleared first),
//! and gets one row: how it ended, the smallest accepted Δt, steps and rejected steps, the
//! relative solids mass error, the largest εs of the run and the wall time. Every monitor,
//! field and summary file of the run is then scanned for NaN/inf. The table goes to
//! docs/reports/stability.md and docs/reports/stability/summary.csv; the command fails if a run wrote a
//! non-finite value or panicked (a stop with a diagnosis is an acceptable outcome).

use std::fmt::Write as _;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::Instant;

use anyhow::{bail, Context, Result};
use indicatif::{MultiProgress, ProgressBar};
use runout_case::{Fidelity, SourcedCase};
use runout_output::{RunStatus, RunSummary};
use runout_run::store::{self, Request, Reuse};
use runout_run::RunError;

use crate::date::today;
use crate::matrix::STABILITY_DIR;
use runout_study::jobs::run_queue;
use runout_study::sweep::{csv_field, matrix, progress_style};

/// Options of a stability run.
pub struct StabilityOptions {
    /// fidelity of every run
    pub fidelity: Fidelity,
    /// keep only cases whose name contains this
    pub only: Option<String>,
    /// parallel runs
    pub jobs: usize,
}

/// How one case ended.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// reached its end time
    Completed,
    /// a step failed below dt_min; the solver's diagnosis
    Stopped(String),
    /// the solver refused the case before any step (it lacks what the case needs)
    Refused(String),
    /// the run ended with an error after it started (no summary)
    Error(String),
    /// the run panicked
    Panicked(String),
}

impl Outcome {
    /// Short label for the tables.
    pub fn label(&self) -> &'static str {
        match self {
            Outcome::Completed => "completed",
            Outcome::Stopped(_) => "stopped",
            Outcome::Refused(_) => "refused",
            Outcome::Error(_) => "error",
            Outcome::Panicked(_) => "panicked",
        }
    }

    /// The solver's message, if any.
    pub fn message(&self) -> Option<&str> {
        match self {
            Outcome::Completed => None,
            Outcome::Stopped(m)
            | Outcome::Refused(m)
            | Outcome::Error(m)
            | Outcome::Panicked(m) => Some(m),
        }
    }
}

/// One row of the table.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// case name
    pub case: String,
    /// what the case stresses (its description)
    pub stresses: String,
    /// cells (nx, ny) at the fidelity run
    pub cells: (usize, usize),
    /// end time at the fidelity run [s]
    pub end_time: f64,
    /// how it ended
    pub outcome: Outcome,
    /// simulated time reached [s]
    pub time: f64,
    /// smallest accepted Δt [s] (none without an accepted step)
    pub min_dt: Option<f64>,
    /// accepted steps
    pub steps: u64,
    /// rejected steps (unknown without a summary)
    pub rejected: Option<u64>,
    /// relative solids mass error at the end [-] (unknown without a summary)
    pub mass_error: Option<f64>,
    /// largest εs over the run [-] (unknown without a summary)
    pub max_eps_s: Option<f64>,
    /// the packing limit εs,max of the case [-]
    pub eps_s_max: f64,
    /// wall-clock time [s]
    pub wall_time: f64,
    /// files (or summary fields) holding non-finite values, with their count
    pub non_finite: Vec<(String, usize)>,
}

impl Row {
    /// Whether this case breaks the rule of the suite: a non-finite value was written, or
    /// the run panicked.
    pub fn violates(&self) -> bool {
        !self.non_finite.is_empty() || matches!(self.outcome, Outcome::Panicked(_))
    }

    /// The status column: the outcome, `NaN written` overriding it.
    pub fn status(&self) -> String {
        if self.non_finite.is_empty() {
            self.outcome.label().to_string()
        } else {
            format!("NaN written ({})", self.outcome.label())
        }
    }
}

/// Number of non-finite numbers in `text`: tokens `nan`, `inf` or `infinity` (any case, any
/// sign) between separators, as Rust, C and Python print them; with `json`, also `null`
/// (serde_json's rendering of a non-finite f64).
pub fn non_finite_tokens(text: &str, json: bool) -> usize {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|t| {
            let t = t.to_ascii_lowercase();
            t == "nan" || t == "inf" || t == "infinity" || (json && t == "null")
        })
        .count()
}

/// Every output file of a run folder (.csv, .vtr, .pvd, .json) with non-finite values, and
/// how many; files that cannot be read count as one.
pub fn scan_run(dir: &Path) -> Vec<(String, usize)> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.extension()
                .and_then(|e| e.to_str())
                .is_some_and(|e| matches!(e, "csv" | "vtr" | "pvd" | "json"))
        })
        .collect();
    files.sort();
    files
        .into_iter()
        .filter_map(|p| {
            let name = p.file_name()?.to_string_lossy().into_owned();
            let json = p.extension().is_some_and(|e| e == "json");
            let count = std::fs::read_to_string(&p).map_or(1, |t| non_finite_tokens(&t, json));
            (count > 0).then_some((name, count))
        })
        .collect()
}

/// Which of equation, cell and time a diagnosis names (issue 7 asks for all three).
pub fn diagnosis_names(text: &str) -> (bool, bool, bool) {
    let t = text.to_lowercase();
    let equation = [
        "momentum",
        "continuity",
        "granular energy",
        "pressure",
        "theta",
        "θ",
    ]
    .iter()
    .any(|e| t.contains(e));
    let cell = t.contains("x =") || t.contains("cell");
    let time = t.contains("t =");
    (equation, cell, time)
}

/// What a diagnosis lacks of equation, cell and time, e.g. `no cell`; empty if complete.
fn diagnosis_gaps(text: &str) -> String {
    let (e, c, t) = diagnosis_names(text);
    let missing: Vec<&str> = [(e, "equation"), (c, "cell"), (t, "time")]
        .iter()
        .filter(|(named, _)| !named)
        .map(|(_, what)| *what)
        .collect();
    if missing.is_empty() {
        String::new()
    } else {
        format!("no {}", missing.join(", no "))
    }
}

/// The row of a finished run from its summary.
fn row_from_summary(base: Row, s: &RunSummary) -> Row {
    let mut non_finite = base.non_finite;
    for (field, v) in [
        ("summary.json: simulated_time", s.simulated_time),
        ("summary.json: dt.min", s.dt.min),
        ("summary.json: solids_mass_change", s.solids_mass_change),
        ("summary.json: max_eps_s", s.max_eps_s),
    ] {
        if !v.is_finite() {
            non_finite.push((field.to_string(), 1));
        }
    }
    Row {
        outcome: match &s.status {
            RunStatus::Diverged { diagnosis } => Outcome::Stopped(diagnosis.clone()),
            RunStatus::Completed => Outcome::Completed,
            other => Outcome::Error(format!("run ended as {other:?}")),
        },
        time: s.simulated_time,
        min_dt: (s.steps > 0).then_some(s.dt.min),
        steps: s.steps,
        rejected: Some(s.rejected_steps),
        mass_error: Some(s.solids_mass_change),
        max_eps_s: Some(s.max_eps_s),
        wall_time: s.wall_time,
        non_finite,
        ..base
    }
}

/// Runs one case at `fidelity` into `dir` through the run store (never reused, never
/// continued: every suite run is made afresh) and makes its row from the finished run, or
/// from what its `.partial` folder holds when it failed.
pub fn run_one(case: &SourcedCase, fidelity: Fidelity, dir: &Path, bar: &ProgressBar) -> Row {
    let c = case.case.at_fidelity(fidelity);
    let cells = c.grid().map_or((0, 0), |g| (g.nx(), g.ny()));
    // an earlier suite's run is not this one's
    let _ = std::fs::remove_dir_all(dir);
    // accepted steps as the progress reports them, for a run that ends without a summary
    let (mut time, mut steps, mut min_dt) = (0.0_f64, 0_u64, f64::INFINITY);
    let started = Instant::now();
    let result = catch_unwind(AssertUnwindSafe(|| {
        let request = Request {
            reuse: Reuse::Never,
            resume: false,
            ..Request::default()
        };
        store::obtain(dir, &case.case, fidelity, &request, |p| {
            min_dt = min_dt.min(p.time - time);
            time = p.time;
            steps = p.steps;
            bar.set_position((1000.0 * p.time / p.end_time) as u64);
            bar.set_message(format!(
                "t = {:.3} s, dt = {:.1e} s, {} it",
                p.time, p.dt, p.iterations
            ));
        })
        .map(|stored| stored.summary().clone())
    }));
    bar.finish_and_clear();
    let written = if dir.exists() {
        dir.to_path_buf()
    } else {
        store::partial_dir(dir)
    };
    let base = Row {
        case: c.name.clone(),
        stresses: c
            .description
            .trim_start_matches("Stability:")
            .trim()
            .to_string(),
        cells,
        end_time: c.run.end_time,
        outcome: Outcome::Completed,
        time,
        min_dt: (steps > 0).then_some(min_dt),
        steps,
        rejected: None,
        mass_error: None,
        max_eps_s: None,
        eps_s_max: c.solids.iter().map(|s| s.max_packing).fold(0.0, f64::max),
        wall_time: started.elapsed().as_secs_f64(),
        non_finite: scan_run(&written),
    };
    match result {
        Ok(Ok(summary)) => row_from_summary(base, &summary),
        Ok(Err(RunError::Unsupported { reason, .. })) if steps == 0 => Row {
            outcome: Outcome::Refused(reason),
            ..base
        },
        Ok(Err(e)) => Row {
            outcome: Outcome::Error(format!("at t = {time:.6e} s after {steps} steps: {e}")),
            ..base
        },
        Err(panic) => {
            let message = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "a panic without a message".into());
            Row {
                outcome: Outcome::Panicked(format!("at t = {time:.6e} s: {message}")),
                ..base
            }
        }
    }
}

/// Runs the cases of `cases_dir` (sweeps expanded) at `opts.fidelity`, each into
/// `runs_dir/<case>/<fidelity>/`, and returns their rows in case order.
pub fn run_cases(cases_dir: &Path, runs_dir: &Path, opts: &StabilityOptions) -> Result<Vec<Row>> {
    let runs = matrix(cases_dir)?.runs;
    let selected: Vec<&SourcedCase> = runs
        .iter()
        .filter(|r| opts.only.as_deref().is_none_or(|p| r.case.name.contains(p)))
        .collect();
    if selected.is_empty() {
        bail!("no stability case in {}", cases_dir.display());
    }
    let progress = MultiProgress::new();
    let rows: Mutex<Vec<(usize, Row)>> = Mutex::new(Vec::new());
    // each worker on a pool of its own (runout_study::jobs): a run waiting in a parallel
    // stage of a shared pool could steal and run the next case inside it
    run_queue(
        selected.iter().enumerate(),
        opts.jobs,
        || true,
        |(k, r)| {
            let bar = progress.add(ProgressBar::new(1000));
            bar.set_style(progress_style());
            bar.set_prefix(r.case.name.clone());
            let dir = runs_dir.join(&r.case.name).join(opts.fidelity.name());
            let row = run_one(r, opts.fidelity, &dir, &bar);
            println!(
                "  {:<16} {}{}",
                row.case,
                row.status(),
                row.outcome
                    .message()
                    .map_or(String::new(), |m| format!(": {m}"))
            );
            rows.lock().expect("no poisoned lock").push((k, row));
        },
    )?;
    let mut rows = rows.into_inner().expect("no poisoned lock");
    rows.sort_by_key(|(k, _)| *k);
    Ok(rows.into_iter().map(|(_, r)| r).collect())
}

fn num(v: Option<f64>, f: impl Fn(f64) -> String) -> String {
    v.map_or(String::new(), f)
}

/// Header of docs/reports/stability/summary.csv.
pub const CSV_HEADER: &str = "case,fidelity,nx,ny,status,end_time_s,time_reached_s,min_dt_s,\
steps,rejected_steps,solids_mass_error,max_eps_s,eps_s_max,wall_time_s,non_finite,diagnosis_gaps,message";

/// One CSV row (RFC 4180 quoting).
pub fn csv_row(row: &Row, fidelity: Fidelity) -> String {
    let non_finite: Vec<String> = row
        .non_finite
        .iter()
        .map(|(f, n)| format!("{f}: {n}"))
        .collect();
    let message = row.outcome.message().unwrap_or("");
    let gaps = match row.outcome {
        Outcome::Stopped(ref d) => diagnosis_gaps(d),
        _ => String::new(),
    };
    [
        csv_field(&row.case),
        fidelity.to_string(),
        row.cells.0.to_string(),
        row.cells.1.to_string(),
        csv_field(&row.status()),
        format!("{}", row.end_time),
        format!("{:e}", row.time),
        num(row.min_dt, |v| format!("{v:e}")),
        row.steps.to_string(),
        row.rejected.map_or(String::new(), |r| r.to_string()),
        num(row.mass_error, |v| format!("{v:e}")),
        num(row.max_eps_s, |v| format!("{v:e}")),
        format!("{}", row.eps_s_max),
        format!("{:.3}", row.wall_time),
        csv_field(&non_finite.join("; ")),
        csv_field(&gaps),
        csv_field(message),
    ]
    .join(",")
}

/// Header of the Markdown table.
pub const MD_HEADER: &str = "| case | stresses | status | t reached / end [s] | cells | min Δt [s] | \
steps (rejected) | solids mass error | max εs | wall [s] |\n|---|---|---|---|---|---|---|---|---|---|";

/// One Markdown table row.
pub fn md_row(row: &Row) -> String {
    let status = match &row.outcome {
        Outcome::Stopped(d) => {
            let gaps = diagnosis_gaps(d);
            if gaps.is_empty() || !row.non_finite.is_empty() {
                row.status()
            } else {
                format!("{} (diagnosis: {gaps})", row.status())
            }
        }
        _ => row.status(),
    };
    // a stop in the first millisecond must not read as 0.000
    let time = if row.time > 0.0 && row.time < 1e-3 {
        format!("{:.2e}", row.time)
    } else {
        format!("{:.3}", row.time)
    };
    format!(
        "| {} | {} | {} | {time} / {} | {} × {} | {} | {}{} | {} | {} | {:.1} |",
        row.case,
        row.stresses.replace('|', "/"),
        status,
        row.end_time,
        row.cells.0,
        row.cells.1,
        num(row.min_dt, |v| format!("{v:.2e}")),
        row.steps,
        row.rejected.map_or(String::new(), |r| format!(" ({r})")),
        num(row.mass_error, |v| format!("{v:.1e}")),
        num(row.max_eps_s, |v| format!("{v:.4}")),
        row.wall_time
    )
}

/// The Markdown page: the command, the date, the table, the definitions and every message.
pub fn markdown(rows: &[Row], fidelity: Fidelity, command: &str, date: &str) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# Stability of stiff and extreme cases (issue 7)\n\n\
         Generated by `{command}` on {date} (fidelity `{fidelity}`, one run at a time, \
         {cores} core(s) available); regenerate it after any physics change, do not edit it \
         by hand. The same rows are in `docs/reports/stability/summary.csv`.\n\n\
         Each case in `cases/stability/` is the sensitivity slide (`cases/sensitivity/base.ron`) \
         with one stiff or extreme change; the header of each file says what it stresses and \
         what is assumed. Each case must run to its end time or stop with a diagnosis naming \
         the equation, the cell and the time; no output may contain a NaN or an infinity. \
         The command fails if a run wrote one or panicked.\n",
        cores = std::thread::available_parallelism().map_or(1, |n| n.get())
    );
    let _ = writeln!(s, "{MD_HEADER}");
    for r in rows {
        let _ = writeln!(s, "{}", md_row(r));
    }
    let _ = writeln!(
        s,
        "\n- **status**: `completed` (reached the end time); `stopped` (a step did not converge \
         and Δt fell below dt_min: the run stopped, kept its output and wrote the diagnosis \
         below; a diagnosis lacking the equation, the cell or the time says so); `refused` (the \
         solver lacks what the case needs and said so before any step); `error` (the run ended \
         on an error after it started); `panicked`; `NaN written` (a NaN or infinity in an \
         output file or in the summary: the failure this suite exists to catch).\n\
         - **min Δt**: the smallest accepted step, not counting a last step shortened to land \
         on the end time (`summary.json` `dt.min`).\n\
         - **solids mass error**: (M(end) − M(0)) / M(0) of the total solids mass \
         (`summary.json` `solids_mass_change`).\n\
         - **max εs**: the largest solids volume fraction of any cell over the initial state \
         and every accepted step (`summary.json` `max_eps_s`); {packing}.\n\
         - **NaN scan**: every `.csv`, `.vtr`, `.pvd` and `summary.json` of \
         `runs/stability/<case>/{fidelity}/` searched for `nan`, `inf`, `infinity` (any case) \
         and, in JSON, `null`.\n\
         - **wall**: wall-clock time of the run on this machine (shared with other work, so \
         indicative only).",
        packing = match rows.first() {
            Some(first) if rows.iter().all(|r| r.eps_s_max == first.eps_s_max) => {
                format!("εs,max = {} in every case", first.eps_s_max)
            }
            _ => "εs,max of each case in the `eps_s_max` column of the CSV".to_string(),
        }
    );
    let messages: Vec<&Row> = rows
        .iter()
        .filter(|r| r.outcome.message().is_some())
        .collect();
    if !messages.is_empty() {
        let _ = writeln!(s, "\n## Diagnoses and messages\n");
        for r in messages {
            let _ = writeln!(
                s,
                "- **{}** ({}): {}",
                r.case,
                r.outcome.label(),
                r.outcome.message().unwrap_or("")
            );
        }
    }
    let nan: Vec<&Row> = rows.iter().filter(|r| !r.non_finite.is_empty()).collect();
    if !nan.is_empty() {
        let _ = writeln!(s, "\n## Non-finite values written\n");
        for r in nan {
            let files: Vec<String> = r
                .non_finite
                .iter()
                .map(|(f, n)| format!("{f} ({n})"))
                .collect();
            let _ = writeln!(s, "- **{}**: {}", r.case, files.join(", "));
        }
    }
    s
}

/// `cargo xtask stability`: runs cases/stability/ and writes docs/reports/stability.md and
/// docs/reports/stability/summary.csv; fails if a run wrote a non-finite value or panicked.
pub fn stability(root: &Path, opts: &StabilityOptions) -> Result<()> {
    let cases_dir = root.join("cases").join(STABILITY_DIR);
    let runs_dir = root.join("runs").join(STABILITY_DIR);
    let started = Instant::now();
    println!(
        "stability cases of {} at fidelity `{}`",
        cases_dir.strip_prefix(root).unwrap_or(&cases_dir).display(),
        opts.fidelity
    );
    let rows = run_cases(&cases_dir, &runs_dir, opts)?;
    let mut command = format!("cargo xtask stability --fidelity {}", opts.fidelity);
    if let Some(only) = &opts.only {
        let _ = write!(command, " --only {only}");
    }
    let md = markdown(&rows, opts.fidelity, &command, &today());
    let mut csv = format!("{CSV_HEADER}\n");
    for r in &rows {
        csv.push_str(&csv_row(r, opts.fidelity));
        csv.push('\n');
    }
    let reports = root.join("docs/reports");
    runout_output::write_atomic(&reports.join("stability.md"), md.as_bytes())
        .context("writing docs/reports/stability.md")?;
    std::fs::create_dir_all(reports.join("stability"))
        .context("creating docs/reports/stability/")?;
    runout_output::write_atomic(
        &reports.join("stability").join("summary.csv"),
        csv.as_bytes(),
    )
    .context("writing docs/reports/stability/summary.csv")?;
    println!("{MD_HEADER}");
    for r in &rows {
        println!("{}", md_row(r));
    }
    println!(
        "{} case(s) in {:.1} s; table in docs/reports/stability.md and docs/reports/stability/summary.csv",
        rows.len(),
        started.elapsed().as_secs_f64()
    );
    let bad: Vec<String> = rows
        .iter()
        .filter(|r| r.violates())
        .map(|r| format!("{} ({})", r.case, r.status()))
        .collect();
    if !bad.is_empty() {
        bail!(
            "{} case(s) wrote non-finite values or panicked: {}",
            bad.len(),
            bad.join(", ")
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests;
