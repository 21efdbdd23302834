//! The page's section on the paper's station and probe numbers: one table of each level's
//! values with its difference from the next finer level and its CPU time, whether the air
//! cushion is the same at every level (a finding when it is not), and one line per number
//! with the trend, observed order, Richardson extrapolation and Roache's GCI.

use std::fmt::Write as _;

use super::gci::{ScalarConvergence, Trend, FS_NOMINAL_ORDER, FS_THREE_LEVELS};
use super::ladder::scheme_name;
use super::quantity::{Quantity, Source};
use super::richardson::ASYMPTOTIC_BAND;
use super::Ladder;

/// The station quantities of a ladder, in the order of its errors.
fn station_quantities(ladder: &Ladder) -> Vec<Quantity> {
    ladder
        .errors
        .iter()
        .map(|(q, _)| *q)
        .filter(|q| q.source() == Source::Station)
        .collect()
}

/// A value with as many significant digits as the page needs to show level differences.
pub(super) fn value(v: f64) -> String {
    if v == 0.0 {
        "0".into()
    } else if v.abs() >= 100.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.4}")
    }
}

/// Level indices of a ladder from the finest to the coarsest.
fn finest_first(ladder: &Ladder) -> Vec<usize> {
    let mut order: Vec<usize> = (0..ladder.runs.len()).collect();
    order.sort_by(|&a, &b| ladder.runs[a].data.h.total_cmp(&ladder.runs[b].data.h));
    order
}

/// The table: one row per level, finest first, with its CPU time and each number with its
/// difference from the next finer level that has it.
fn values_table(md: &mut String, ladder: &Ladder, qs: &[Quantity]) {
    let headings: Vec<&str> = qs.iter().map(|q| q.heading()).collect();
    let _ = writeln!(
        md,
        "| level | cells | h | threads | CPU [s] | air cushion | {} |",
        headings.join(" | ")
    );
    let _ = writeln!(
        md,
        "|---|---:|---:|---:|---:|---|{}",
        "---:|".repeat(qs.len())
    );
    let order = finest_first(ladder);
    for (pos, &k) in order.iter().enumerate() {
        let run = &ladder.runs[k];
        let finer = |q: Quantity| {
            order[..pos]
                .iter()
                .rev()
                .find_map(|&j| ladder.runs[j].data.station.get(q))
        };
        let cells: Vec<String> = qs
            .iter()
            .map(|&q| match (run.data.station.get(q), finer(q)) {
                (Some(v), Some(f)) => format!("{} ({:+.2e})", value(v), v - f),
                (Some(v), None) => value(v),
                (None, _) => "—".into(),
            })
            .collect();
        let cushion = match &run.data.station.air_cushion {
            Some(Ok(true)) => "yes".to_string(),
            Some(Ok(false)) => "no".to_string(),
            Some(Err(why)) => format!("— ({why})"),
            None => "—".to_string(),
        };
        let (threads, cpu) = run.cost.map_or((String::new(), String::new()), |c| {
            (
                c.threads.to_string(),
                format!(
                    "{:.0}{}",
                    c.cpu_seconds,
                    if c.resumed { " (resumed)" } else { "" }
                ),
            )
        });
        let _ = writeln!(
            md,
            "| {} | {} × {} | {:.2} | {threads} | {cpu} | {cushion} | {} |",
            run.level,
            run.cells.0,
            run.cells.1,
            run.data.h,
            cells.join(" | ")
        );
    }
    let _ = writeln!(md);
}

/// Whether the cushion appears at one level and not at the next: the ladder does not
/// converge for it, a finding of its own.
fn cushion_line(ladder: &Ladder) -> String {
    let seen: Vec<(&str, bool)> = finest_first(ladder)
        .into_iter()
        .filter_map(|k| {
            let run = &ladder.runs[k];
            match &run.data.station.air_cushion {
                Some(Ok(b)) => Some((run.level.name(), *b)),
                _ => None,
            }
        })
        .collect();
    let listed: Vec<String> = seen
        .iter()
        .map(|(l, b)| format!("{l} {}", if *b { "yes" } else { "no" }))
        .collect();
    match seen.first() {
        None => "- Air cushion: no level has a reading (no finished run with flow at the station)."
            .into(),
        Some(&(_, first)) if seen.iter().all(|&(_, b)| b == first) => format!(
            "- Air cushion: the same at every level ({}).",
            listed.join(", ")
        ),
        Some(_) => format!(
            "- **Air cushion: the ladder does not converge** ({}): the cushion appears at one \
             level and not at the next, so the cushion thickness and the numbers that depend on \
             it (floor εs, θ, h_w^u) change by a jump between those levels, not by a \
             discretisation error that shrinks with h; their orders and GCI below are not \
             meaningful across that jump.",
            listed.join(", ")
        ),
    }
}

/// One line per number: its trend over the three finest levels, the observed order, the
/// extrapolation and the GCI with its factor of safety.
fn gci_line(ladder: &Ladder, q: Quantity, s: &ScalarConvergence) -> String {
    let trend = match s.trend {
        Trend::Monotone => "monotone",
        Trend::Oscillatory => "**oscillatory**",
        Trend::Diverging => "**not converging** (the finer difference is not the smaller)",
    };
    let order = match (s.observed_order, s.asymptotic) {
        (Some(p), true) => format!("observed order {p:.2}, in the asymptotic range"),
        (Some(p), false) => format!("observed order {p:.2}, **not in the asymptotic range**"),
        (None, _) => "no observed order".into(),
    };
    let relative = if s.gci_fine.is_finite() {
        format!(" = {:.1} % of the finest value", 100.0 * s.gci_fine)
    } else {
        String::new()
    };
    let basis = if s.safety_factor == FS_THREE_LEVELS {
        format!("Fs = {FS_THREE_LEVELS}, p = {:.2}", s.gci_order)
    } else {
        format!(
            "Fs = {FS_NOMINAL_ORDER} at the nominal order p = {} (the observed order is not \
             trusted)",
            s.gci_order
        )
    };
    format!(
        "- {}, {}: ε₂₁ = {:+.3e}, ε₃₂ = {:+.3e}, {trend}; {order}; Richardson q* = {}; \
         GCI of the finest level {:.3e}{relative} ({basis}).",
        scheme_name(&ladder.scheme),
        q.heading(),
        s.eps21,
        s.eps32,
        value(s.extrapolated),
        s.gci_fine_absolute,
    )
}

/// The station section of one ladder.
pub(super) fn station_section(md: &mut String, ladder: &Ladder) {
    let qs = station_quantities(ladder);
    if qs.is_empty() {
        return;
    }
    let _ = writeln!(
        md,
        "### The paper's station and probe numbers ({})\n",
        scheme_name(&ladder.scheme)
    );
    let _ = writeln!(
        md,
        "Read from each run as `cargo xtask report` reads them (finest level first; in brackets \
         the difference from the next finer level):\n"
    );
    values_table(md, ladder, &qs);
    let _ = writeln!(md, "{}", cushion_line(ladder));
    for q in &qs {
        match ladder.gci.iter().find(|(k, _)| k == q) {
            Some((_, s)) => {
                let _ = writeln!(md, "{}", gci_line(ladder, *q, s));
            }
            None => {
                let _ = writeln!(
                    md,
                    "- {}, {}: fewer than three levels have it: no order, no GCI.",
                    scheme_name(&ladder.scheme),
                    q.heading()
                );
            }
        }
    }
    let _ = writeln!(md);
}

/// The definitions of the station numbers and of the GCI, for the page's measures section.
pub(super) fn definitions(md: &mut String) {
    let _ = writeln!(
        md,
        "- **The paper's station and probe numbers** (air-cushion thickness, 0 without a \
         cushion; flow thickness; εs and θ of the floor cell; the largest u_s, at the station \
         at the profile time; h_w^u at the floor probe then): read from each run by the \
         report's own functions (`cargo xtask report`, crate::metrics), so the ladder judges \
         exactly the numbers docs/reports/results.md shows. Their error is |q − q_ref| in the \
         quantity's unit.\n\
         - **GCI** (Roache's grid convergence index, the ASME V&V 20 practice as Celik et al. \
         2008 state it): with the three finest levels, ε₂₁ = q₂ − q₁, ε₃₂ = q₃ − q₂ (1 the \
         finest); monotone when they have one sign and |ε₂₁| < |ε₃₂|; then the observed order \
         p as above, q* = q₁ + (q₁ − q₂)/(r₂₁ᵖ − 1) and GCI = Fs |ε₂₁|/(r₂₁ᵖ − 1) (also as a \
         fraction of |q₁|), with Fs = {FS_THREE_LEVELS} when p lies in [{}, {}] × the \
         scheme's nominal order, and otherwise (outside that range, oscillating or not \
         converging) Fs = {FS_NOMINAL_ORDER} at the nominal order, said so on the line.",
        ASYMPTOTIC_BAND.0, ASYMPTOTIC_BAND.1
    );
}
