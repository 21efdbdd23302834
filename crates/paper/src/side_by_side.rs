//! The opening table of results.md (issue 45): the paper's findings judged at each
//! fidelity (coarse, wall, paper) from that fidelity's runs alone, run folder or ledger
//! row, with how many cases had a run, and the findings whose verdict changes between
//! fidelities. A fidelity whose runs do not cover every case the findings read gets no
//! count, only how many of them ran: an N over part of the matrix would read as a verdict.

use std::fmt::Write as _;

use runout_case::Fidelity;

use super::error_bars::Ladders;
use super::findings::{cases_named, counts, judge_all, Judged};
use super::ledger::{Ledger, LEDGER_FIDELITIES};
use super::record::Source;
use super::records::{Records, Store};

/// A count of an earlier report whose runs are gone, quoted where its fidelity has no
/// complete set of runs now: (fidelity, what it said, where it is recorded).
pub const HISTORICAL: &[(Fidelity, &str)] = &[(
    Fidelity::Wall,
    "last generated 2026-12-03 from 30 family-S runs at wall (docs/results.md of commit \
     6c83f77): **40 of 64**; those run folders are lost and this count is not re-derivable \
     from the ledger",
)];

/// The command that fills a fidelity, for the note of an incomplete one.
fn fill_command(f: Fidelity) -> String {
    format!(
        "`cargo xtask sweep --fidelity {f} --only S-` (or on a cluster \
         `FIDELITY={f} sbatch examples/slurm/sweep.sbatch`; a run folder made elsewhere: \
         `cargo xtask ledger add RUN_DIR`), then `cargo xtask report`"
    )
}

/// One fidelity judged.
struct Column {
    fidelity: Fidelity,
    judged: Vec<Judged>,
    /// (cases with a run, of them from the ledger) over the matrix
    run: (usize, usize),
    /// family S: (cases with a run, cases)
    family_s: (usize, usize),
    /// (cases the findings read that have a run, cases they read)
    needed: (usize, usize),
}

impl Column {
    fn complete(&self) -> bool {
        self.needed.0 == self.needed.1
    }
}

/// Judges every finding at `f` from that fidelity's records.
fn column(
    f: Fidelity,
    names: &[String],
    store: &Store,
    ledger: &Ledger,
    described: &[(usize, f64)],
    ladders: &Ladders,
) -> Column {
    let records = Records::choose(names, store, ledger, Some(f));
    let has = |c: &str| records.get(c).is_ok();
    let s_cases: Vec<&String> = names.iter().filter(|n| n.starts_with("S-")).collect();
    let named = cases_named();
    Column {
        fidelity: f,
        judged: judge_all(&records, described, ladders),
        run: (
            names.iter().filter(|n| has(n)).count(),
            records.with_source(Source::Ledger).len(),
        ),
        family_s: (s_cases.iter().filter(|n| has(n)).count(), s_cases.len()),
        needed: (named.iter().filter(|n| has(n)).count(), named.len()),
    }
}

/// The findings cell: "N of 64" (reproduced of judged, as [`super::findings::summary_line`]),
/// or why there is no N.
fn findings_cell(c: &Column) -> String {
    let (yes, n, missing) = counts(&c.judged, None);
    if c.complete() {
        // of the findings judged, as the summary line counts them
        let mut s = format!("**{yes} of {n}**");
        if missing > 0 {
            let _ = write!(s, " ({missing} without a value)");
        }
        return s;
    }
    if n == 0 {
        return "— (no finding has its runs)".into();
    }
    format!("— (partial: {yes} of the {n} findings whose runs exist)")
}

/// The note of an incomplete fidelity: the earlier count if there is one, and the command.
fn note(c: &Column) -> String {
    if c.complete() {
        return String::new();
    }
    let mut parts = Vec::new();
    if c.run.0 == 0 {
        parts.push("no runs on this machine or in the ledger".to_string());
    }
    parts.extend(
        HISTORICAL
            .iter()
            .filter(|(f, _)| *f == c.fidelity)
            .map(|(_, s)| s.to_string()),
    );
    parts.push(format!("to fill it: {}", fill_command(c.fidelity)));
    parts.join("; ")
}

/// "coarse no, paper yes" for a finding judged at several fidelities; `None` when it does
/// not change.
fn change(columns: &[Column], k: usize) -> Option<String> {
    let verdicts: Vec<(Fidelity, bool)> = columns
        .iter()
        .filter_map(|c| match &c.judged[k].verdict {
            Ok((ok, _)) => Some((c.fidelity, *ok)),
            Err(_) => None,
        })
        .collect();
    let changes = verdicts.windows(2).any(|w| w[0].1 != w[1].1);
    changes.then(|| {
        verdicts
            .iter()
            .map(|(f, ok)| format!("{f} {}", if *ok { "yes" } else { "no" }))
            .collect::<Vec<_>>()
            .join(", ")
    })
}

/// The section: the table, then the findings that change verdict.
pub fn section(
    md: &mut String,
    names: &[String],
    store: &Store,
    ledger: &Ledger,
    described: &[(usize, f64)],
    ladders: &Ladders,
) {
    let columns: Vec<Column> = LEDGER_FIDELITIES
        .iter()
        .map(|&f| column(f, names, store, ledger, described, ladders))
        .collect();
    md.push_str("## The findings at each fidelity\n\n");
    md.push_str(
        "Each fidelity judged from its own runs only: the run folder on this machine where \
         there is one, else the case's row of the committed ledger \
         (docs/reports/results/ledger/<fidelity>.csv, written by `cargo xtask report` and \
         `cargo xtask ledger add`). A fidelity without a run of every case the findings read \
         gets no count. Smoke runs are a CI check and are not judged here.\n\n",
    );
    md.push_str(
        "| fidelity | findings reproduced | cases with a run (of them from the ledger) | family S | note |\n\
         |---|---|---|---|---|\n",
    );
    for c in &columns {
        let _ = writeln!(
            md,
            "| {} | {} | {} of {} ({}) | {} of {} | {} |",
            c.fidelity,
            findings_cell(c),
            c.run.0,
            names.len(),
            c.run.1,
            c.family_s.0,
            c.family_s.1,
            note(c).replace('|', "\\|")
        );
    }
    md.push('\n');
    let changed: Vec<String> = (0..columns[0].judged.len())
        .filter_map(|k| {
            let j = &columns[0].judged[k];
            change(&columns, k).map(|v| format!("- Fig. {}: {} — {v}.", j.figure, j.finding))
        })
        .collect();
    let judged_at: Vec<String> = columns
        .iter()
        .filter(|c| c.judged.iter().any(|j| j.verdict.is_ok()))
        .map(|c| c.fidelity.to_string())
        .collect();
    if judged_at.len() < 2 {
        let _ = writeln!(
            md,
            "Findings that change verdict between fidelities: none can be named yet (findings \
             are judged at {} only).\n",
            if judged_at.is_empty() {
                "no fidelity".into()
            } else {
                judged_at.join(", ")
            }
        );
    } else if changed.is_empty() {
        let _ = writeln!(
            md,
            "No finding judged at more than one of {} changes verdict between them.\n",
            judged_at.join(", ")
        );
    } else {
        md.push_str(
            "Findings that change verdict between fidelities (where each has a value):\n\n",
        );
        for line in changed {
            let _ = writeln!(md, "{line}");
        }
        md.push('\n');
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_post::fixture::*;

    #[test]
    fn a_finding_whose_verdict_differs_between_fidelities_is_listed() {
        let tmp = TempDir::new("side-by-side");
        let runs = tmp.0.join("runs");
        let p = "profile_x11_t1.25.csv";
        write_run(
            &runs,
            "S-JJ-phi_phi=1",
            "coarse",
            1.25,
            &[(p, CUSHION_PROFILE)],
        );
        write_run(
            &runs,
            "S-JJ-phi_phi=1",
            "paper",
            1.25,
            &[(p, DENSE_PROFILE)],
        );
        let names: Vec<String> = ["S-JJ-phi_phi=1", "S-RJJ", "F-JEN"]
            .map(String::from)
            .to_vec();
        let store = Store::load(&runs, &names);
        let ledger = Ledger::read(&tmp.0.join("docs")).unwrap();
        let mut md = String::new();
        section(&mut md, &names, &store, &ledger, &[], &Ladders::default());
        assert!(
            md.contains(
                "- Fig. 4a: air cushion at the station (`S-JJ-phi_phi=1`) — coarse yes, paper no."
            ),
            "{md}"
        );
        // one of the two family-S cases ran; no count where the findings' cases did not run
        assert!(md.contains("| paper | — (partial: "), "{md}");
        assert!(md.contains("| 1 of 3 (0) | 1 of 2 |"), "{md}");
    }
}
