//! The tables of the report: every number the paper reports beside runout's, the flume's
//! gate speeds, family M against MFIX, family M's four floors and the runs used.

use std::fmt::Write as _;
use std::path::Path;

use runout_post::gates::DescribedGate;

use super::figure_sets::{FLUME, FLUME_SIDEWALLS, MFIX_CASE, MFIX_SLIDE};
use super::paper::PAPER_NUMBERS;
use super::reading::reading;
use super::record::{RunRecord, Source};
use super::records::Records;
use runout_post::metrics::mse_vs_described;

/// A markdown table cell: `|` escaped.
pub(super) fn cell(s: &str) -> String {
    s.replace('|', "\\|")
}

/// Where a record comes from, for the runs table.
fn source_cell(r: &RunRecord) -> String {
    match r.source {
        Source::Store => "run folder".into(),
        Source::Ledger => format!("ledger ({}, solver {})", r.date, r.solver),
    }
}

/// Every case's record: fidelity, source, how the run ended, its size and cost.
pub(super) fn runs_table(md: &mut String, names: &[String], records: &Records) {
    md.push_str(
        "| case | fidelity | source | status | simulated [s] | cells | steps (rejected) | wall [s] |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    for name in names {
        match records.get(name) {
            Ok(r) => {
                let _ = writeln!(
                    md,
                    "| `{name}` | {} | {} | {} | {:.2} | {} × {} | {} ({}) | {:.1} |",
                    r.fidelity,
                    cell(&source_cell(r)),
                    r.status,
                    r.end_time,
                    r.cells.0,
                    r.cells.1,
                    r.steps,
                    r.rejected_steps,
                    r.wall_time
                );
            }
            Err(why) => {
                let _ = writeln!(md, "| `{name}` | — | — | {} | | | | |", cell(&why));
            }
        }
    }
    md.push('\n');
}

fn paper_table(md: &mut String, records: &Records, described: &[(usize, f64)]) {
    md.push_str(
        "| paper Fig. | quantity | case | paper (MFIX) | runout | fidelity |\n\
         |---|---|---|---|---|---|\n",
    );
    for row in PAPER_NUMBERS {
        let value = match reading(row.quantity, row.case, records, described) {
            Ok(v) => v,
            Err(why) => format!("— ({why})"),
        };
        let fidelity = records
            .get(row.case)
            .map_or("—".into(), |r| r.fidelity.to_string());
        let _ = writeln!(
            md,
            "| {} | {} | `{}` | {} | {} | {} |",
            row.figure,
            cell(&row.quantity.label()),
            row.case,
            cell(row.paper),
            cell(&value),
            fidelity
        );
    }
    md.push('\n');
}

fn flume_table(
    md: &mut String,
    records: &Records,
    gates: &[DescribedGate],
    described: &[(usize, f64)],
) {
    let numbers: Vec<usize> = gates.iter().map(|g| g.gate).collect();
    let _ = writeln!(
        md,
        "| case | fidelity | {} | MSE vs described [m²/s²] | paper's MFIX MSE vs measured [m²/s²] |",
        numbers.iter().map(|g| format!("L{g}")).collect::<Vec<_>>().join(" | ")
    );
    let _ = writeln!(md, "|---|---|{}---|---|", "---|".repeat(numbers.len()));
    let _ = writeln!(
        md,
        "| described (cases/flume/gates.csv) | — | {} | — | — |",
        gates
            .iter()
            .map(|g| g.speed.map_or(String::new(), |s| format!("{s:.1}")))
            .collect::<Vec<_>>()
            .join(" | ")
    );
    for (case, _, paper_mse) in FLUME.iter().chain(FLUME_SIDEWALLS) {
        let record = records.get(case);
        let gates = record.and_then(|r| r.gates.clone().map(|g| (r, g)));
        let (fidelity, speeds, mse) = match gates {
            Ok((r, pairs)) => {
                let speeds = numbers
                    .iter()
                    .map(|g| {
                        pairs
                            .iter()
                            .find(|p| p.0 == *g)
                            .map_or("—".into(), |p| format!("{:.2}", p.1))
                    })
                    .collect::<Vec<_>>()
                    .join(" | ");
                let mse = mse_vs_described(&pairs, described).map_or_else(
                    || format!("— ({})", r.no_gate_reached()),
                    |(e, k)| format!("{e:.2} ({k} gates)"),
                );
                (r.fidelity.to_string(), speeds, mse)
            }
            Err(why) => (
                "—".into(),
                vec!["—"; numbers.len()].join(" | "),
                format!("— ({why})"),
            ),
        };
        let _ = writeln!(
            md,
            "| `{case}` | {fidelity} | {speeds} | {} | {} |",
            cell(&mse),
            cell(paper_mse)
        );
    }
    md.push('\n');
}

fn mfix_table(md: &mut String, records: &Records) {
    let record = records.get(MFIX_CASE);
    let fidelity = record
        .as_ref()
        .map_or("—".into(), |r| r.fidelity.to_string());
    md.push_str(
        "| t [s] | MFIX front x [m] | runout front x [m] | MFIX mean u_s [m/s] | runout mean u_s [m/s] | fidelity |\n\
         |---|---|---|---|---|---|\n",
    );
    for &(t, front, mean) in MFIX_SLIDE {
        let (ours_front, ours_mean, f) = match record.clone().and_then(|r| r.bulk_at(t)) {
            Ok((x, u)) => (format!("{x:.2}"), format!("{u:.2}"), fidelity.clone()),
            Err(why) => (format!("— ({why})"), "—".into(), "—".into()),
        };
        let _ = writeln!(
            md,
            "| {t} | {front:.2} | {} | {mean:.2} | {ours_mean} | {f} |",
            cell(&ours_front)
        );
    }
    md.push('\n');
}

/// The section of every number the paper reports beside runout's.
pub(super) fn paper_section(md: &mut String, records: &Records, described: &[(usize, f64)]) {
    md.push_str(
        "## Every number the paper reports, beside runout's\n\n\
         Profile quantities at the station x = 11 m, t = 1.25 s; \"—\" says why runout has no \
         value.\n\n",
    );
    paper_table(md, records, described);
}

/// The section of the flume's gate speeds (paper §4, Fig. 12).
pub(super) fn flume_section(
    md: &mut String,
    records: &Records,
    gates: &[DescribedGate],
    described: &[(usize, f64)],
) {
    md.push_str(
        "## Flume: front speed at the gates (paper §4, Fig. 12)\n\n\
         Speeds [m/s] from each run's gates.csv. The MSE is runout's against the speeds the \
         paper *describes* (cases/flume/gates.csv: ~4.0 m/s at L2–L6 and the last peak of \
         5.4 m/s at L7; L1 lies in the initial rise and has none), over the gates both have; \
         the paper's MSEs are MFIX's against the *measured* speeds, which are not in its text, \
         so the two columns are not the same error. The `FSW-` rows are the same cases with \
         the channel's side walls (0.30 m apart, the floor's solids condition, gas no-slip; \
         docs/model.md §8), which the paper's 2-D runs and the `F-` rows leave out.\n\n",
    );
    flume_table(md, records, gates, described);
}

/// The section of family M against MFIX.
pub(super) fn mfix_section(md: &mut String, records: &Records) {
    md.push_str(
        "## Family M: the slide run in MFIX (cross-check, not a paper number)\n\n\
         Front x and εs-weighted mean u_s from runout's bulk.csv against MFIX 21.3.2 on the same \
         case (shared/docs/cases.md family M).\n\n",
    );
    mfix_table(md, records);
}

/// The floor-variant comparison of family M (issue 9, item 4) as `cargo xtask verify
/// mfix-slope` wrote it into docs/reports/mfix-slope.md, with a sentence ranking the floors by slip;
/// a note if that file or section does not exist yet.
pub(super) fn floors_section(md: &mut String, reports: &Path) {
    const HEADING: &str = "## The four floors at t = 0.3 s";
    md.push_str("### Family M: the four floors at t = 0.3 s (issue 9)\n\n");
    let text = std::fs::read_to_string(reports.join("mfix-slope.md")).unwrap_or_default();
    let Some(start) = text.find(HEADING) else {
        md.push_str(
            "**Missing**: docs/reports/mfix-slope.md has no floor comparison yet; run `cargo xtask \
             verify mfix-slope`.\n\n",
        );
        return;
    };
    let body = &text[start + HEADING.len()..];
    let body = body.split_once("\n(").map_or(body, |(b, _)| b);
    let end = body
        .find("\n## ")
        .or_else(|| body.find("\n**Result"))
        .unwrap_or(body.len());
    let section = body[..end].trim_start_matches(|c: char| c != '\n').trim();
    md.push_str(section);
    md.push_str(
        "\n\nFrom docs/reports/mfix-slope.md (written by `cargo xtask verify mfix-slope`, MFIX's grid).",
    );
    // rank by the wall-row mean solids velocity (table column 3) and give θ (column 5)
    let mut rows: Vec<(String, f64, f64)> = section
        .lines()
        .filter(|l| l.starts_with("| M-"))
        .filter_map(|l| {
            let c: Vec<&str> = l.split('|').map(str::trim).collect();
            Some((
                c.get(1)?.to_string(),
                c.get(3)?.parse().ok()?,
                c.get(5)?.parse().ok()?,
            ))
        })
        .collect();
    if rows.len() > 1 {
        rows.sort_by(|a, b| a.1.total_cmp(&b.1));
        let order: Vec<String> = rows
            .iter()
            .map(|(name, u, theta)| format!("{name} ({u:.2} m/s, θ {theta:.1e} m²/s²)"))
            .collect();
        md.push_str(&format!(
            " Ranked by wall slip (wall-row mean u_s), least to most: {}.",
            order.join(" < ")
        ));
    }
    md.push_str("\n\n");
}
