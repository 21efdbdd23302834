//! `docs/reports/error-time/error_time.csv`: one row per case, scheme, level and quantity, with the
//! run's grid, cost (wall and CPU time, threads) and status, the quantity's value (station
//! numbers), its errors and observed order, and for station numbers the GCI of the ladder's
//! finest level (repeated on every row of the quantity).

use std::path::Path;

use anyhow::Result;
use runout_output::RunStatus;

use super::gci::ScalarConvergence;
use super::ladder::scheme_name;
use super::richardson::asymptotic;
use super::{opt, Ladder};

pub(super) fn write_csv(path: &Path, ladders: &[Ladder]) -> Result<()> {
    let mut w = csv::Writer::from_path(path)?;
    w.write_record([
        "case",
        "scheme",
        "level",
        "cells_x",
        "cells_y",
        "h_over_h_paper",
        "status",
        "simulated_time_s",
        "wall_time_s",
        "threads",
        "cpu_time_s",
        "steps",
        "quantity",
        "norm",
        "samples",
        "reference_level",
        "error_vs_reference",
        "max_error_vs_reference",
        "richardson_error",
        "observed_order",
        "order_asymptotic",
        "value",
        "richardson_value",
        "gci_fine",
        "gci_fine_relative",
        "gci_safety_factor",
        "gci_order",
    ])?;
    let e = |v: Option<f64>| opt(v, |x| format!("{x:.6e}"));
    for ladder in ladders {
        for (q, errors) in &ladder.errors {
            let reference = errors.reference.map(|k| ladder.runs[k].level.name());
            let p = errors.order.as_ref().and_then(|o| o.p);
            let gci = ladder.gci.iter().find(|(k, _)| k == q).map(|(_, g)| g);
            let g = |f: fn(&ScalarConvergence) -> f64| opt(gci.map(f), |x| format!("{x:.6e}"));
            for (k, run) in ladder.runs.iter().enumerate() {
                let (status, time, wall, steps) = match &run.summary {
                    Ok(s) => (
                        status_text(&s.status),
                        format!("{}", s.simulated_time),
                        format!("{:.3}", s.wall_time),
                        s.steps.to_string(),
                    ),
                    Err(why) => (
                        format!("failed: {why}"),
                        String::new(),
                        String::new(),
                        String::new(),
                    ),
                };
                w.write_record([
                    run.case.clone(),
                    scheme_name(&ladder.scheme).into(),
                    run.level.name().into(),
                    run.cells.0.to_string(),
                    run.cells.1.to_string(),
                    format!("{:.4}", run.data.h),
                    status,
                    time,
                    wall,
                    run.cost.map_or(String::new(), |c| c.threads.to_string()),
                    run.cost
                        .map_or(String::new(), |c| format!("{:.3}", c.cpu_seconds)),
                    steps,
                    q.name().into(),
                    q.norm().into(),
                    errors.samples.to_string(),
                    reference.unwrap_or_default().into(),
                    e(errors.vs_reference[k]),
                    e(errors.max_vs_reference[k]),
                    e(errors.richardson[k]),
                    opt(p, |x| format!("{x:.3}")),
                    p.map_or(String::new(), |p| asymptotic(p, &ladder.scheme).to_string()),
                    e(run.data.station.get(*q)),
                    g(|s| s.extrapolated),
                    g(|s| s.gci_fine_absolute),
                    g(|s| s.gci_fine),
                    g(|s| s.safety_factor),
                    g(|s| s.gci_order),
                ])?;
            }
        }
    }
    w.flush()?;
    Ok(())
}

/// A run's status in words (the diagnosis of a divergence included).
fn status_text(status: &RunStatus) -> String {
    match status {
        RunStatus::Completed => "completed".into(),
        RunStatus::Diverged { diagnosis } => format!("diverged: {diagnosis}"),
        other => format!("{other:?}").to_lowercase(),
    }
}
