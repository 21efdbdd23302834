//! The summary at the top of results.md (issue 19, item 5): each of the paper's findings
//! judged, from runout's runs, reproduced or not, and for each one that is not, what the
//! runs show instead.
//!
//! Three kinds of finding, each judged by a rule stated here and in the report:
//! - **Air cushion, yes or no**, for every case the paper says it of (the yes/no rows of
//!   [`PAPER_NUMBERS`]): reproduced when runout's station profile says the same.
//! - **Trends, rankings and thresholds** ([`TRENDS`]): how an output changes along a sweep
//!   (the floor εs with φ, the cushion with d, the flow with h_w^u and d), which case of a
//!   sweep is highest, the ranking of h_w^u at the floor probe, and the 70 m⁻¹ threshold of
//!   cushion formation. Each is a comparison of runout's values, so it does not depend on how
//!   close the values are to MFIX's.
//! - **Numbers** (the numeric rows of [`PAPER_NUMBERS`]): reproduced when runout's value, as
//!   the report shows it (rounded to its decimals), lies in the paper's range ("8.4–8.5",
//!   "between 70 and 156") or within [`RELATIVE_TOLERANCE`] of its single value. The flume's
//!   MSEs are not counted: the paper's are against the measured gate speeds, which its text
//!   does not give, and runout's against the speeds it describes.
//!
//! A finding whose runs are missing (not run, ended early, no flow at the station) is
//! neither reproduced nor not: it is counted apart, with the reason.

use std::fmt::Write as _;

use runout_case::Fidelity;

use super::cell;
use super::error_bars::{cushion_note, judge_number, Ladders};
use super::explain::{explain, Releases};
use super::paper::{Quantity, PAPER_NUMBERS};
use super::reading::{value, Reading};
use super::records::Records;
pub use super::trends::{cases_named, TRENDS};
use super::trends::{cushion_thickness, yes_no};

/// A single value of the paper is matched within this fraction of it.
pub const RELATIVE_TOLERANCE: f64 = 0.2;

/// What the paper says of a quantity, read from its printed value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Expected {
    /// "yes"
    Yes,
    /// "no"
    No,
    /// "a–b" or "between a and b"
    Range(f64, f64),
    /// "a", "approaching a", "a (…)"
    Value(f64),
}

impl Expected {
    /// A number's range (a single value is a range of zero width); `None` for yes/no.
    pub fn range(self) -> Option<(f64, f64)> {
        match self {
            Expected::Range(lo, hi) => Some((lo, hi)),
            Expected::Value(v) => Some((v, v)),
            Expected::Yes | Expected::No => None,
        }
    }
}

/// The paper's printed value as an expectation; `None` if it is not one of the forms above.
pub fn expected(paper: &str) -> Option<Expected> {
    let text = paper.trim();
    let head = text.split_whitespace().next()?;
    match head {
        "yes" => return Some(Expected::Yes),
        "no" => return Some(Expected::No),
        "between" => {
            let rest = text.strip_prefix("between")?;
            let (lo, hi) = rest.split_once(" and ")?;
            return Some(Expected::Range(
                lo.trim().parse().ok()?,
                hi.trim().parse().ok()?,
            ));
        }
        "approaching" => {
            let v = text.split_whitespace().nth(1)?;
            return Some(Expected::Value(v.parse().ok()?));
        }
        _ => {}
    }
    match head.split_once('–') {
        Some((lo, hi)) => Some(Expected::Range(lo.parse().ok()?, hi.parse().ok()?)),
        None => Some(Expected::Value(head.parse().ok()?)),
    }
}

/// Whether a value as the report shows it matches the paper's number.
pub fn matches(shown: f64, expected: Expected) -> Option<bool> {
    match expected {
        Expected::Range(lo, hi) => Some(lo <= shown && shown <= hi),
        Expected::Value(v) => Some((shown - v).abs() <= RELATIVE_TOLERANCE * v.abs()),
        Expected::Yes | Expected::No => None,
    }
}

/// The kind of a finding, for the summary's counts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// an air cushion, yes or no, at one case's station
    Cushion,
    /// a trend, ranking or threshold
    Trend,
    /// a number within the paper's range or tolerance
    Number,
}

/// Reproduced or not, with what runout shows; or why runout has no value.
pub type Verdict = Result<(bool, String), String>;

/// One finding judged.
#[derive(Clone, Debug)]
pub struct Judged {
    /// the paper's figure
    pub figure: &'static str,
    /// what the paper finds
    pub finding: String,
    /// the paper's value or statement
    pub paper: String,
    /// kind, for the counts
    pub kind: Kind,
    /// reproduced or not, with what runout shows; or why runout has no value
    pub verdict: Verdict,
    /// for a number reproduced, the rule that did it (range, 20 %, error bar)
    pub rule: Option<&'static str>,
    /// the case of a number or cushion (a trend reads several)
    pub case: Option<&'static str>,
    /// the quantities it reads
    pub quantities: &'static [Quantity],
}

/// Every finding of the paper, judged from `records`; a number or cushion read from a
/// paper-grid run carries its error bar from `ladders` ([`super::error_bars`]).
pub fn judge_all(records: &Records, described: &[(usize, f64)], ladders: &Ladders) -> Vec<Judged> {
    let mut out = Vec::new();
    for row in PAPER_NUMBERS {
        let Some(exp) = expected(row.paper) else {
            continue;
        };
        if matches!(row.quantity, Quantity::FlumeMse) {
            continue; // not the same error as the paper's (module doc)
        }
        let reading = value(row.quantity, row.case, records, described)
            .map_err(|e| format!("`{}`: {e}", row.case));
        let at_paper = records
            .get(row.case)
            .is_ok_and(|r| r.fidelity == Fidelity::Paper);
        let bar = |v: f64| {
            at_paper
                .then(|| ladders.bar(row.case, row.quantity, v))
                .flatten()
        };
        let mut rule = None;
        let (kind, verdict) = match exp {
            Expected::Yes | Expected::No => (
                Kind::Cushion,
                reading.and_then(|r| match r {
                    Reading::YesNo(b) => {
                        let thickness = records.get(row.case).and_then(cushion_thickness);
                        let note = thickness
                            .ok()
                            .and_then(|t| bar(t).map(|b| format!(" ({})", cushion_note(t, &b))));
                        Ok((
                            b == (exp == Expected::Yes),
                            format!("{r}{}", note.unwrap_or_default()),
                        ))
                    }
                    _ => Err("not a yes/no reading".into()),
                }),
            ),
            _ => (
                Kind::Number,
                reading.and_then(|r| {
                    let b = match r {
                        Reading::Number { value, .. } => bar(value),
                        Reading::YesNo(_) => None,
                    };
                    let (ok, text, by) = judge_number(&r, exp, b.as_ref())?;
                    rule = by;
                    Ok((ok, text))
                }),
            ),
        };
        out.push(Judged {
            figure: row.figure,
            finding: format!("{} (`{}`)", row.quantity.label(), row.case),
            paper: row.paper.to_string(),
            kind,
            verdict,
            rule,
            case: Some(row.case),
            quantities: std::slice::from_ref(&row.quantity),
        });
    }
    for t in TRENDS {
        out.push(Judged {
            figure: t.figure,
            finding: t.finding.to_string(),
            paper: t.paper.to_string(),
            kind: Kind::Trend,
            verdict: (t.judge)(records, described),
            rule: None,
            case: None,
            quantities: t.quantities,
        });
    }
    out
}

/// Counts of one kind: (reproduced, judged, without a value).
pub fn counts(judged: &[Judged], kind: Option<Kind>) -> (usize, usize, usize) {
    let of_kind = judged.iter().filter(|j| kind.is_none_or(|k| j.kind == k));
    let (mut yes, mut judged_n, mut missing) = (0, 0, 0);
    for j in of_kind {
        match &j.verdict {
            Ok((true, _)) => {
                yes += 1;
                judged_n += 1;
            }
            Ok((false, _)) => judged_n += 1,
            Err(_) => missing += 1,
        }
    }
    (yes, judged_n, missing)
}

/// The one-line summary, e.g. "12 of 50 findings reproduced (…)".
pub fn summary_line(judged: &[Judged]) -> String {
    let (yes, n, missing) = counts(judged, None);
    let part = |k: Kind, what: &str| {
        let (y, n, _) = counts(judged, Some(k));
        format!("{y} of {n} {what}")
    };
    let mut line = format!(
        "**{yes} of {n} findings reproduced**: {}, {}, {}",
        part(Kind::Cushion, "air cushions yes/no"),
        part(Kind::Trend, "trends, rankings and thresholds"),
        part(
            Kind::Number,
            "numbers (in the paper's range or within 20 % of its value)"
        ),
    );
    if missing > 0 {
        let _ = write!(line, "; {missing} without a runout value (listed below)");
    }
    line.push('.');
    line
}

/// The summary section: the line, the findings not reproduced with what runout shows, the
/// ones without a value, then every finding in a table.
pub fn section(
    md: &mut String,
    records: &Records,
    described: &[(usize, f64)],
    ladders: &Ladders,
    releases: &Releases,
) {
    let judged = judge_all(records, described, ladders);
    md.push_str("## Summary: the paper's findings in runout's runs\n\n");
    let _ = writeln!(md, "{}\n", summary_line(&judged));
    md.push_str(
        "How each is judged (crates/paper/src/findings.rs): an air cushion yes/no as the \
         station profile shows it (floor εs below 0.8 × the profile's peak); a trend, \
         ranking or threshold by comparing runout's own values along the sweep; a number by \
         runout's value as shown, inside the paper's range or within 20 % of its single \
         value, or, for a value read at the paper grid, when its error bar reaches the \
         paper's value or range (the table says which rule; a bar of half the value or more \
         comes from a ladder that does not converge, and the table says the grid does not \
         decide). The error bar is the grid \
         convergence index of the uniform ladder of docs/reports/error-time.md, Fs |f − f_Richardson| \
         at the paper level: the case's own ladder where it has one, else the relative bar of \
         its floor condition's ladder, else of S-JJ-phi φ = 0.1's (named in each value). A \
         cushion yes/no at the paper grid shows its thickness with that bar: where the bar is \
         as large as the thickness the grid does not settle it. The flume's MSEs are not \
         counted (the paper's are against measured speeds its text does not give). Every \
         number here is in the tables below.\n\n",
    );
    let not: Vec<&Judged> = judged
        .iter()
        .filter(|j| matches!(j.verdict, Ok((false, _))))
        .collect();
    if !not.is_empty() {
        md.push_str(
            "**Not reproduced**, with what runout's runs show instead and, after the arrow, \
             what moves it (issue 45, item 4; crates/paper/src/explain.rs): the grid (the \
             error ladder of docs/reports/error-time.md: at coarse its coarse-to-paper change, at \
             the paper grid its GCI), the release (the nine blocks of the release study of \
             the case's floor, docs/studies/impact.md §4, at coarse), and what is left beyond both. \
             One ladder and one coarse study stand for the family, so both effects are \
             estimates:\n\n",
        );
        for j in &not {
            if let Ok((_, shown)) = &j.verdict {
                let why = explain(j, records, ladders, releases)
                    .map_or(String::new(), |w| format!(" → {w}"));
                let _ = writeln!(
                    md,
                    "- Fig. {}: {} — paper: {}; runout: {}{why}.",
                    j.figure, j.finding, j.paper, shown
                );
            }
        }
        md.push('\n');
    }
    let missing: Vec<&Judged> = judged.iter().filter(|j| j.verdict.is_err()).collect();
    if !missing.is_empty() {
        md.push_str("**Without a runout value:**\n\n");
        for j in &missing {
            if let Err(why) = &j.verdict {
                let _ = writeln!(md, "- Fig. {}: {} — {}.", j.figure, j.finding, why);
            }
        }
        md.push('\n');
    }
    md.push_str(
        "| paper Fig. | finding | paper (MFIX) | runout | reproduced |\n|---|---|---|---|---|\n",
    );
    for j in &judged {
        let (shown, verdict) = match &j.verdict {
            Ok((ok, shown)) => (
                shown.clone(),
                match j.rule {
                    Some(rule) => format!("{} ({rule})", yes_no(*ok)),
                    None => yes_no(*ok).to_string(),
                },
            ),
            Err(why) => (format!("— ({why})"), "—".to_string()),
        };
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} |",
            j.figure,
            cell(&j.finding),
            cell(&j.paper),
            cell(&shown),
            verdict
        );
    }
    md.push('\n');
}

#[cfg(test)]
mod tests {
    use super::super::records::from_runs;
    use super::*;
    use runout_case::Fidelity;
    use runout_post::fixture::*;

    #[test]
    fn every_printed_value_of_the_paper_reads_as_an_expectation() {
        for row in PAPER_NUMBERS {
            assert!(
                expected(row.paper).is_some(),
                "{} / {}: `{}`",
                row.figure,
                row.case,
                row.paper
            );
        }
        assert_eq!(expected("yes (thickest)"), Some(Expected::Yes));
        assert_eq!(expected("no"), Some(Expected::No));
        assert_eq!(expected("8.4–8.5"), Some(Expected::Range(8.4, 8.5)));
        assert_eq!(
            expected("0.01–0.03 (range of Fig. 4a)"),
            Some(Expected::Range(0.01, 0.03))
        );
        assert_eq!(
            expected("between 70 and 156"),
            Some(Expected::Range(70.0, 156.0))
        );
        assert_eq!(expected("approaching 4.7"), Some(Expected::Value(4.7)));
        assert_eq!(
            expected("0.026 (thickest of 0.020–0.026)"),
            Some(Expected::Value(0.026))
        );
        assert_eq!(expected("a lot"), None);
    }

    #[test]
    fn numbers_match_inside_the_range_or_within_twenty_percent() {
        assert_eq!(matches(8.4, Expected::Range(8.4, 8.5)), Some(true));
        assert_eq!(matches(8.51, Expected::Range(8.4, 8.5)), Some(false));
        assert_eq!(matches(0.036, Expected::Value(0.03)), Some(true));
        assert_eq!(matches(0.037, Expected::Value(0.03)), Some(false));
        assert_eq!(matches(0.024, Expected::Value(0.03)), Some(true));
        assert_eq!(matches(1.0, Expected::Yes), None);
    }

    #[test]
    fn findings_are_judged_from_the_runs_and_missing_runs_say_why() {
        let tmp = TempDir::new("findings");
        let runs = tmp.0.join("runs");
        let profile = "profile_x11_t1.25.csv";
        // φ = 1 and 0.1 with a cushion (floor εs 0.05), φ = 0.01 dense (floor εs 0.6):
        // the cushion rows hold, and the floor εs rises as φ falls
        for case in ["S-JJ-phi_phi=1", "S-JJ-phi_phi=0.1"] {
            write_run(&runs, case, "coarse", 1.25, &[(profile, CUSHION_PROFILE)]);
        }
        write_run(
            &runs,
            "S-JJ-phi_phi=0.01",
            "coarse",
            1.25,
            &[(profile, DENSE_PROFILE)],
        );
        let names = ["S-JJ-phi_phi=1", "S-JJ-phi_phi=0.1", "S-JJ-phi_phi=0.01"];
        let cases = from_runs(&runs, &names, Some(Fidelity::Coarse));
        let judged = judge_all(&cases, &[], &Ladders::default());
        let find = |figure: &str, finding: &str| {
            judged
                .iter()
                .find(|j| j.figure == figure && j.finding.starts_with(finding))
                .unwrap_or_else(|| panic!("{figure}: {finding}"))
        };
        let cushion = find("4a", "air cushion at the station (`S-JJ-phi_phi=0.1`)");
        assert_eq!(cushion.kind, Kind::Cushion);
        assert_eq!(cushion.verdict, Ok((true, "yes".into())));
        let none = find("4a, 10", "air cushion at the station (`S-JJ-phi_phi=0.01`)");
        assert_eq!(none.verdict, Ok((true, "no".into())));
        // floor εs 0.05 (paper 0.03: 67 % off) and 0.6 (paper 0.32)
        let eps = find("4a", "εs of the floor cell (`S-JJ-phi_phi=1`)");
        assert_eq!(eps.verdict, Ok((false, "0.050".into())));
        let trend = find("4a", "Johnson–Jackson: the floor cell's εs rises");
        // 0.05 → 0.05 does not rise: not reproduced
        assert_eq!(
            trend.verdict,
            Ok((
                false,
                "floor εs 0.050 / 0.050 / 0.600 for φ = 1 / 0.1 / 0.01".into()
            ))
        );
        // a finding over runs that do not exist says which
        let jen = find("5a, 5b", "Jenkins");
        assert!(jen
            .verdict
            .as_ref()
            .unwrap_err()
            .contains("S-JEN-d_d=0.0001"));
        let line = summary_line(&judged);
        assert!(line.contains("findings reproduced"), "{line}");
        assert!(line.contains("without a runout value"), "{line}");
    }
}
