//! `docs/reports/error-time.md`: the date and command, the notes kept by hand in
//! `docs/reports/error-time/notes.md` (which commit ran which level, caveats), the levels (run or
//! not, and why), the error measures, one section per case (the paper's station numbers with
//! their GCI, [`super::station_page`]; the errors of every quantity with the references and
//! observed orders), the figures and every run's folder and status.

use std::fmt::Write as _;

use anyhow::Result;
use runout_case::Case;
use runout_output::RunStatus;

use super::errors::QuantityErrors;
use super::ladder::{scheme_name, Level};
use super::quantity::{quantities, Quantity, Source};
use super::richardson::{asymptotic, ASYMPTOTIC_BAND};
use super::run::Run;
use super::{opt, station_page, Ladder, NOT_RUN, OUTPUT_DIR};
use runout_post::metrics::FLOW_THRESHOLD;

/// Whether the page describes a pipeline check rather than a study.
fn pipeline_check(levels: &[Level]) -> bool {
    levels.contains(&Level::Tiny) || levels.len() < 3
}

/// The page. `notes`, if any, goes under the header as it is (the hand-kept notes of
/// `docs/reports/error-time/notes.md`, so regenerating the page keeps them).
pub(super) fn markdown(
    command: &str,
    date: &str,
    levels: &[Level],
    cases: &[Case],
    ladders: &[Ladder],
    figures: &[(String, Quantity, String)],
    notes: Option<&str>,
) -> Result<String> {
    let mut md = String::new();
    let _ = writeln!(
        md,
        "# Discretisation error against run time (issues 8, 45)\n"
    );
    let _ = writeln!(
        md,
        "Generated on {date} by `{command}` (one run at a time; each run's threads and CPU \
         time are in its row).\n"
    );
    if let Some(notes) = notes {
        let _ = writeln!(md, "{}\n", notes.trim_end());
    }
    if pipeline_check(levels) {
        let _ = writeln!(
            md,
            "> **PIPELINE CHECK, NOT A RESULT.** This page comes from {} level(s){}: too few or \
             too coarse grids to estimate a discretisation error. The study proper needs at \
             least smoke, coarse and paper (`cargo xtask error-time --levels \
             smoke,coarse,paper,finer`).\n",
            levels.len(),
            if levels.contains(&Level::Tiny) {
                " including `tiny` (the smoke grid coarsened 2× more, not a fidelity preset)"
            } else {
                ""
            }
        );
    }
    levels_section(&mut md, levels, cases)?;
    definitions_section(&mut md);
    for case in cases {
        case_section(&mut md, case, ladders, figures);
    }
    let _ = writeln!(md, "## Runs\n");
    for run in ladders.iter().flat_map(|l| &l.runs) {
        let status = match &run.summary {
            Ok(s) => match &s.status {
                RunStatus::Completed => format!("completed at t = {} s", s.simulated_time),
                RunStatus::Diverged { diagnosis } => {
                    format!("**diverged** at t = {:.3} s: {diagnosis}", s.simulated_time)
                }
                other => format!("**{other:?}** at t = {:.3} s", s.simulated_time),
            },
            Err(why) if why.starts_with(NOT_RUN) => why.clone(),
            Err(why) => format!("**failed**: {why}"),
        };
        let _ = writeln!(md, "- `{}`: {status}", run.dir);
    }
    let _ = writeln!(
        md,
        "\nThe numbers are in [error_time.csv]({}/error_time.csv).",
        OUTPUT_DIR.trim_start_matches("docs/reports/")
    );
    Ok(md)
}

fn levels_section(md: &mut String, levels: &[Level], cases: &[Case]) -> Result<()> {
    let _ = writeln!(md, "## Levels\n");
    let _ = writeln!(
        md,
        "Every level runs a case to the same end time (given with the case below; the smoke \
         preset's shorter end time is not used: it would stop before the profile time and the \
         gates); only the grid changes: every other setting (the convection scheme unless \
         `--schemes` names one, the outer iteration, the time-step controller) is the case \
         file's, as in the sweep's runs. `h` is √(paper cells / cells).\n"
    );
    let names: Vec<String> = cases.iter().map(|c| format!("{} cells", c.name)).collect();
    let _ = writeln!(
        md,
        "| level | grid | in this command | {} |",
        names.join(" | ")
    );
    let _ = writeln!(md, "|---|---|---|{}", "---:|".repeat(cases.len()));
    for level in Level::ALL {
        let grid = match level {
            Level::Tiny => "smoke preset coarsened 2× more (pipeline check)",
            Level::Smoke => "smoke preset's coarsening",
            Level::Coarse => "coarse preset's coarsening",
            Level::Half => "paper grid coarsened 2× in x and y",
            Level::Paper => "the case's own grid",
            Level::Finer => "paper grid refined 2× in x and y",
        };
        let run = if levels.contains(&level) {
            "in `--levels` (whether it ran: Runs)"
        } else {
            "**no**: not in `--levels` of this command"
        };
        let mut cells = Vec::new();
        for c in cases {
            let g = level.case(c).grid()?;
            cells.push(format!("{} × {} = {}", g.nx(), g.ny(), g.cell_count()));
        }
        let _ = writeln!(md, "| {level} | {grid} | {run} | {} |", cells.join(" | "));
    }
    let _ = writeln!(md);
    Ok(())
}

fn definitions_section(md: &mut String) {
    let _ = writeln!(md, "## Error measures\n");
    let _ = writeln!(
        md,
        "- **Station profiles** (εs, u_s, θ at the x and last time of the case's first profile \
         monitor): each run's profile is interpolated linearly onto the reference run's \
         cell-centre heights and compared where any run of the ladder has εs ≥ {FLOW_THRESHOLD} \
         (the flow band); the error is Σ w |q − q_ref| / Σ w (w: reference cell heights) divided \
         by the range of q_ref over the band (the CSV also has the largest difference over the \
         range).\n\
         - **Gate speeds** (front monitor): RMS of v − v_ref over the gates every run of the \
         ladder reached [m/s] (the CSV also has the largest difference).\n\
         - **Front position and mean solids speed against time** (bulk monitor, `bulk.csv`, \
         every 0.01 s or the case's bulk interval): each run's history is interpolated \
         linearly onto the reference run's sample times; RMS of the difference over the times \
         every run covers (for the front: where every run has one) [m, m/s]. They exist at \
         every level, also where the front never reaches the station. The bulk front is \
         whole-cell (the east face of the last floor cell with εs ≥ the bulk threshold), so it \
         moves in steps of one Δx of its grid.\n\
         - **Reference**: the finest level run with the quantity (named below each table).\n\
         - **Richardson**: with three levels or more, the three finest give the observed order \
         p (D₃₂/D₂₁ = (h₃ᵖ − h₂ᵖ)/(h₂ᵖ − h₁ᵖ), D the same norm of the difference of successive \
         levels) and the extrapolation q* = q₁ + (q₁ − q₂) h₁ᵖ/(h₂ᵖ − h₁ᵖ); the number in \
         brackets is each level's error against q*. The order is **asymptotic** when it lies in \
         [{}, {}] × the scheme's nominal order (upwind 1; Superbee 1 to 2, as its limiter falls \
         back to upwind at extrema and fronts); outside that, or when the differences do not \
         shrink, the extrapolation is not reliable and the page says so.\n",
        ASYMPTOTIC_BAND.0, ASYMPTOTIC_BAND.1
    );
    station_page::definitions(md);
    let _ = writeln!(
        md,
        "- **Cost**: the CPU time of each run (getrusage of the process that ran it, user + \
         system, all threads, kept in the run's `cost.json`), with its thread count; the \
         figures plot each level's error against it.\n"
    );
}

/// The section of one case: what is compared, one row per run (grid, cost, status and the
/// error of each quantity), the references and observed orders, and the figures.
fn case_section(
    md: &mut String,
    case: &Case,
    ladders: &[Ladder],
    figures: &[(String, Quantity, String)],
) {
    let qs = quantities(case);
    let _ = writeln!(md, "## {}\n", case.name);
    if qs.is_empty() {
        let _ = writeln!(
            md,
            "The case has neither a profile nor a front monitor: nothing to compare.\n"
        );
        return;
    }
    case_setting(md, case);
    let ladders: Vec<&Ladder> = ladders.iter().filter(|l| l.case == case.name).collect();
    for ladder in &ladders {
        station_page::station_section(md, ladder);
    }
    let _ = writeln!(md, "### Every quantity against the finest level\n");
    runs_table(md, case, &qs, &ladders);
    let _ = writeln!(md);
    for ladder in &ladders {
        for (q, e) in &ladder.errors {
            let _ = writeln!(md, "{}", order_line(ladder, *q, e));
        }
    }
    let _ = writeln!(md);
    case_figures(md, case, &qs, figures);
}

/// The end time, the station and the gates of a case, and how to read the error cells.
fn case_setting(md: &mut String, case: &Case) {
    let _ = writeln!(
        md,
        "Every level runs to the case's end time, t = {} s on the case's clock (for a clock \
         from the impact, later by the tilt time: the time reached is under Runs).",
        case.run.end_time
    );
    if let Some(m) = case.monitors.profiles.first() {
        let t = m.times.last().copied().unwrap_or(f64::NAN);
        let _ = writeln!(
            md,
            "Station profile at x = {} m, t = {t} s on the case's clock.",
            m.x
        );
    }
    if let Some(f) = &case.monitors.front {
        let gates: Vec<String> = f.gates.iter().map(f64::to_string).collect();
        let _ = writeln!(
            md,
            "Gates at {} m from x = {} m. The gate speeds of `gates.csv` are a central \
             difference of the front position over four samples {} s apart; that front is \
             interpolated within the floor row (`front.csv`), so the speeds are not quantised. \
             The column \"speed step\", Δx/(4 × {} s), is the quantisation a whole-cell front \
             would have, for scale.",
            gates.join(", "),
            f.gate_origin,
            f.interval,
            f.interval
        );
    }
    let _ = writeln!(
        md,
        "Error cells: against the reference, then (in brackets) against the Richardson \
         extrapolation where it exists; — where the run lacks the quantity (see Runs).\n"
    );
}

/// The table of a case: one row per run of its ladders.
fn runs_table(md: &mut String, case: &Case, qs: &[Quantity], ladders: &[&Ladder]) {
    let headings: Vec<&str> = qs.iter().map(|q| q.heading()).collect();
    let _ = writeln!(
        md,
        "| scheme | level | cells | h | wall time [s] | CPU [s] | steps | status |{} {} |",
        if case.monitors.front.is_some() {
            " speed step [m/s] |"
        } else {
            ""
        },
        headings.join(" | ")
    );
    let _ = writeln!(
        md,
        "|---|---|---:|---:|---:|---:|---:|---|{}{}",
        if case.monitors.front.is_some() {
            "---:|"
        } else {
            ""
        },
        "---:|".repeat(qs.len())
    );
    for ladder in ladders {
        for (k, run) in ladder.runs.iter().enumerate() {
            let (wall, steps, status) = run_cost(run);
            let _ = writeln!(
                md,
                "| {} | {} | {} × {} | {:.2} | {wall} | {} | {steps} | {status} |{} {} |",
                scheme_name(&ladder.scheme),
                run.level,
                run.cells.0,
                run.cells.1,
                run.data.h,
                run.cost.map_or(String::new(), |c| format!(
                    "{:.0} ({} thread{})",
                    c.cpu_seconds,
                    c.threads,
                    if c.threads == 1 { "" } else { "s" }
                )),
                run.speed_quantum
                    .map_or(String::new(), |q| format!(" {q:.2} |")),
                error_cells(ladder, k).join(" | ")
            );
        }
    }
}

/// The wall time, steps and status cells of a run (empty and "not run" or "failed" without
/// a summary).
fn run_cost(run: &Run) -> (String, String, String) {
    match &run.summary {
        Ok(s) => (
            format!(
                "{:.1}{}",
                s.wall_time,
                if run.reused { " (reused)" } else { "" }
            ),
            s.steps.to_string(),
            match &s.status {
                RunStatus::Completed => "completed".to_string(),
                RunStatus::Diverged { .. } => {
                    format!("diverged at t = {:.3} s", s.simulated_time)
                }
                other => format!("{other:?} at t = {:.3} s", s.simulated_time),
            },
        ),
        Err(why) if why.starts_with(NOT_RUN) => {
            (String::new(), String::new(), "not run".to_string())
        }
        Err(_) => (String::new(), String::new(), "failed".to_string()),
    }
}

/// The error cells of run `k` of a ladder, one per quantity: against the reference, then
/// the Richardson extrapolation in brackets.
fn error_cells(ladder: &Ladder, k: usize) -> Vec<String> {
    ladder
        .errors
        .iter()
        .map(|(_, e)| {
            if e.reference == Some(k) {
                let rich = opt(e.richardson[k], |x| format!(" ({x:.3e})"));
                return format!("reference{rich}");
            }
            let main = opt(e.vs_reference[k], |x| format!("{x:.3e}"));
            let rich = opt(e.richardson[k], |x| format!(" ({x:.3e})"));
            if main.is_empty() && rich.is_empty() {
                "—".into()
            } else {
                format!("{main}{rich}")
            }
        })
        .collect()
}

/// The figures of a case, and a line for each quantity without one.
fn case_figures(
    md: &mut String,
    case: &Case,
    qs: &[Quantity],
    figures: &[(String, Quantity, String)],
) {
    for (_, q, file) in figures.iter().filter(|(c, _, _)| c == &case.name) {
        let _ = writeln!(
            md,
            "![{} {}: error against CPU time]({}/{file})\n",
            case.name,
            q.name(),
            OUTPUT_DIR.trim_start_matches("docs/reports/")
        );
    }
    for q in qs {
        if !figures.iter().any(|(c, f, _)| c == &case.name && f == q) {
            let _ = writeln!(
                md,
                "No figure for {}: no level has an error (the reference alone, or no data).\n",
                q.name()
            );
        }
    }
}

/// The reference, the samples and the observed order of one quantity, as a list item.
fn order_line(ladder: &Ladder, q: Quantity, e: &QuantityErrors) -> String {
    let level = |k: usize| ladder.runs[k].level.name();
    let mut line = format!("- {}, {}: ", scheme_name(&ladder.scheme), q.name());
    match e.reference {
        Some(r) => {
            let what = match q.source() {
                Source::Station => "value",
                Source::Profile => "heights in the flow band",
                Source::Gates => "gates",
                Source::History => "sample times",
            };
            let _ = write!(line, "reference `{}` ({} {what})", level(r), e.samples);
        }
        None => line.push_str("no reference"),
    }
    if let Some(note) = &e.note {
        let _ = write!(line, "; {note}");
    }
    match &e.order {
        Some(o) => {
            let used = o.levels.map(level).join(", ");
            let diffs = format!("D₂₁ = {:.3e}, D₃₂ = {:.3e}", o.d21, o.d32);
            match o.p {
                Some(p) if asymptotic(p, &ladder.scheme) => {
                    let _ = write!(
                        line,
                        "; observed order p = {p:.2} from {used} ({diffs}), in the asymptotic \
                         range"
                    );
                }
                Some(p) => {
                    let _ = write!(
                        line,
                        "; observed order p = {p:.2} from {used} ({diffs}), **not in the \
                         asymptotic range**: the Richardson numbers are indicative only"
                    );
                }
                None => {
                    let _ = write!(
                        line,
                        "; **no observed order** from {used}: the differences do not shrink at \
                         a positive rate ({diffs}), not in the asymptotic range, no Richardson \
                         estimate"
                    );
                }
            }
        }
        None if e.reference.is_some() => {
            line.push_str("; fewer than three levels: no observed order, no Richardson estimate")
        }
        None => {}
    }
    line.push('.');
    line
}
