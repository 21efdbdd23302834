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

use super::cell;
use super::paper::{Quantity, CUSHION_LIMIT_H_U, PAPER_NUMBERS};
use super::reading::{value, Reading};
use super::record::RunRecord;
use super::records::Records;

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
}

/// A trend, ranking or threshold of the paper, with its rule.
pub struct Trend {
    /// the paper's figure
    pub figure: &'static str,
    /// the finding, in words
    pub finding: &'static str,
    /// the paper's numbers behind it
    pub paper: &'static str,
    /// runout's judgement from the cases and the flume's described gate speeds:
    /// (reproduced, what the runs show), or why there is none
    pub judge: fn(&Records, &[(usize, f64)]) -> Verdict,
}

/// One output of each case of a list, as (label, value); the first missing one is the error.
fn outputs(
    records: &Records,
    list: &[(&'static str, &'static str)],
    output: impl Fn(&RunRecord) -> Result<f64, String>,
) -> Result<Vec<(&'static str, f64)>, String> {
    list.iter()
        .map(|&(label, case)| {
            records
                .get(case)
                .and_then(&output)
                .map(|v| (label, v))
                .map_err(|e| format!("`{case}`: {e}"))
        })
        .collect()
}

/// "a / b / c for φ = 1 / 0.1 / 0.01" with `decimals`.
fn listed(symbol: &str, values: &[(&str, f64)], decimals: usize) -> String {
    let v: Vec<String> = values
        .iter()
        .map(|(_, v)| format!("{v:.decimals$}"))
        .collect();
    let l: Vec<&str> = values.iter().map(|(l, _)| *l).collect();
    format!("{} for {symbol} = {}", v.join(" / "), l.join(" / "))
}

fn increasing(v: &[(&str, f64)]) -> bool {
    v.windows(2).all(|w| w[1].1 > w[0].1)
}

fn decreasing(v: &[(&str, f64)]) -> bool {
    v.windows(2).all(|w| w[1].1 < w[0].1)
}

/// The label of the largest value.
fn largest<'a>(v: &[(&'a str, f64)]) -> &'a str {
    v.iter()
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map_or("", |p| p.0)
}

fn floor_eps_s(r: &RunRecord) -> Result<f64, String> {
    Ok(r.station.as_ref().map_err(Clone::clone)?.floor_eps_s)
}

fn floor_theta(r: &RunRecord) -> Result<f64, String> {
    Ok(r.station.as_ref().map_err(Clone::clone)?.floor_theta)
}

fn max_u_s(r: &RunRecord) -> Result<f64, String> {
    r.flow()?.max_u_s.ok_or_else(|| "no max u_s".into())
}

fn flow_thickness(r: &RunRecord) -> Result<f64, String> {
    r.flow()?
        .flow_thickness
        .ok_or_else(|| "no flow thickness".into())
}

/// The cushion thickness, 0 without a cushion.
fn cushion_thickness(r: &RunRecord) -> Result<f64, String> {
    let m = r.flow()?;
    match m.air_cushion {
        Some(true) => m
            .cushion_thickness
            .ok_or_else(|| "no cushion thickness".into()),
        Some(false) => Ok(0.0),
        None => Err("cushion not defined for this profile".into()),
    }
}

fn has_cushion(r: &RunRecord) -> Result<bool, String> {
    r.flow()?
        .air_cushion
        .ok_or_else(|| "cushion not defined for this profile".into())
}

fn probe_h_u(records: &Records, case: &str) -> Result<f64, String> {
    match value(Quantity::ProbeHu, case, records, &[])? {
        Reading::Number { value, .. } => Ok(value),
        Reading::YesNo(_) => Err("not a number".into()),
    }
}

fn flume_mse(r: &RunRecord, described: &[(usize, f64)]) -> Result<f64, String> {
    crate::metrics::mse_vs_described(r.gates.as_ref().map_err(Clone::clone)?, described)
        .map(|(e, _)| e)
        .ok_or_else(|| r.no_gate_reached())
}

const JJ_PHI: &[(&str, &str)] = &[
    ("1", "S-JJ-phi_phi=1"),
    ("0.1", "S-JJ-phi_phi=0.1"),
    ("0.01", "S-JJ-phi_phi=0.01"),
];
const JJ_D: &[(&str, &str)] = &[
    ("0.1", "S-JJ-d_d=0.0001"),
    ("0.5", "S-JJ-d_d=0.0005"),
    ("1", "S-JJ-d_d=0.001"),
];
const JEN_D: &[(&str, &str)] = &[
    ("0.1", "S-JEN-d_d=0.0001"),
    ("0.5", "S-JEN-d_d=0.0005"),
    ("1", "S-JEN-d_d=0.001"),
];
const PS_HU: &[(&str, &str)] = &[
    ("1", "S-PS-hu_hu=1"),
    ("10", "S-PS-hu_hu=10"),
    ("40", "S-PS-hu_hu=40"),
    ("70", "S-PS-hu_hu=70"),
    ("100", "S-PS-hu_hu=100"),
];
const PS_HU_ENDS: &[(&str, &str)] = &[("10", "S-PS-hu_hu=10"), ("100", "S-PS-hu_hu=100")];
const PS_D_ENDS: &[(&str, &str)] = &[("0.1", "S-PS-d_d=0.0001"), ("1", "S-PS-d_d=0.001")];
/// The floors of paper Fig. 9, in the paper's order of h_w^u at the probe (largest first).
const PROBE_RANKING: &[(&str, &str)] = &[
    ("JJ φ = 1", "S-JJ-phi_phi=1"),
    ("JJ φ = 0.1", "S-JJ-phi_phi=0.1"),
    ("revisited JJ", "S-RJJ"),
    ("JJ φ = 0.01", "S-JJ-phi_phi=0.01"),
    ("Jenkins", "S-JEN-d_d=0.0005"),
];
const FLUME_CASES: &[(&str, &str)] = &[
    ("JJ φ = 0.1", "F-JJ_phi=0.1"),
    ("JJ φ = 0.01", "F-JJ_phi=0.01"),
    ("Jenkins", "F-JEN"),
    ("revisited JJ", "F-RJJ"),
];

fn yes_no(b: bool) -> &'static str {
    if b {
        "yes"
    } else {
        "no"
    }
}

/// Every trend, ranking and threshold the paper states (§§2.2–4).
pub const TRENDS: &[Trend] = &[
    Trend {
        figure: "4a",
        finding: "Johnson–Jackson: the floor cell's εs rises as φ falls",
        paper: "0.03 at φ = 1 to 0.32 at φ = 0.01",
        judge: |c, _| {
            let v = outputs(c, JJ_PHI, floor_eps_s)?;
            Ok((increasing(&v), format!("floor εs {}", listed("φ", &v, 3))))
        },
    },
    Trend {
        figure: "4c",
        finding: "Johnson–Jackson: the floor θ is highest at φ = 1",
        paper: "2.2 m²/s² at φ = 1",
        judge: |c, _| {
            let v = outputs(c, JJ_PHI, floor_theta)?;
            Ok((
                largest(&v) == "1",
                format!("floor θ {}", listed("φ", &v, 3)),
            ))
        },
    },
    Trend {
        figure: "4d",
        finding: "Johnson–Jackson: the cushion thickens with d",
        paper: "thinner for d = 0.1 mm, thicker for 1 mm",
        judge: |c, _| {
            let v = outputs(c, JJ_D, cushion_thickness)?;
            Ok((
                increasing(&v),
                format!("cushion thickness [m] {}", listed("d [mm]", &v, 3)),
            ))
        },
    },
    Trend {
        figure: "4e",
        finding: "Johnson–Jackson: the smallest grains flow fastest",
        paper: "max u_s 11.45 m/s at d = 0.1 mm, 8.4–8.5 at 0.5 and 1 mm",
        judge: |c, _| {
            let v = outputs(c, JJ_D, max_u_s)?;
            Ok((
                largest(&v) == "0.1",
                format!("max u_s [m/s] {}", listed("d [mm]", &v, 2)),
            ))
        },
    },
    Trend {
        figure: "4f",
        finding: "Johnson–Jackson: the floor θ is highest at d = 1 mm",
        paper: "2.5 m²/s² at d = 1 mm",
        judge: |c, _| {
            let v = outputs(c, JJ_D, floor_theta)?;
            Ok((
                largest(&v) == "1",
                format!("floor θ {}", listed("d [mm]", &v, 3)),
            ))
        },
    },
    Trend {
        figure: "5a, 5b",
        finding: "Jenkins: the smallest grains give the thickest and fastest flow",
        paper: "0.026 m and 8.67 m/s at d = 0.1 mm",
        judge: |c, _| {
            let h = outputs(c, JEN_D, flow_thickness)?;
            let u = outputs(c, JEN_D, max_u_s)?;
            // strictly thickest: a tie (one floor cell for all, on a coarse grid) is not
            let thickest = h[1..].iter().all(|p| h[0].1 > p.1);
            Ok((
                thickest && largest(&u) == "0.1",
                format!(
                    "flow thickness [m] {}; max u_s [m/s] {}",
                    listed("d [mm]", &h, 3),
                    listed("d [mm]", &u, 2)
                ),
            ))
        },
    },
    Trend {
        figure: "7a",
        finding: "user partial slip: a cushion for h_w^u ≥ 70 m⁻¹ and none below",
        paper: "none at 10, a cushion at 70 and 100 m⁻¹",
        judge: |c, _| {
            let mut all = true;
            let mut seen = Vec::new();
            for &(hu, case) in PS_HU {
                let yes = c
                    .get(case)
                    .and_then(has_cushion)
                    .map_err(|e| format!("`{case}`: {e}"))?;
                all &= yes == (hu.parse::<f64>().unwrap_or(0.0) >= CUSHION_LIMIT_H_U);
                seen.push(format!("{hu}: {}", yes_no(yes)));
            }
            Ok((all, format!("cushion at h_w^u [1/m] = {}", seen.join(", "))))
        },
    },
    Trend {
        figure: "7a",
        finding: "user partial slip: the flow thickens as h_w^u rises",
        paper: "0.015 m at 10 m⁻¹ to 0.030 m at 100 m⁻¹",
        judge: |c, _| {
            let v = outputs(c, PS_HU_ENDS, flow_thickness)?;
            Ok((
                increasing(&v),
                format!("flow thickness [m] {}", listed("h_w^u", &v, 3)),
            ))
        },
    },
    Trend {
        figure: "7b",
        finding: "user partial slip: max u_s falls as h_w^u rises",
        paper: "7.65 m/s at 10 m⁻¹ to 3.59 m/s at 100 m⁻¹",
        judge: |c, _| {
            let v = outputs(c, PS_HU_ENDS, max_u_s)?;
            Ok((
                decreasing(&v),
                format!("max u_s [m/s] {}", listed("h_w^u", &v, 2)),
            ))
        },
    },
    Trend {
        figure: "7c",
        finding: "user partial slip: the floor θ is highest at h_w^u = 100 m⁻¹",
        paper: "1.86 m²/s² at 100 m⁻¹",
        judge: |c, _| {
            let v = outputs(c, PS_HU, floor_theta)?;
            Ok((
                largest(&v) == "100",
                format!("floor θ {}", listed("h_w^u", &v, 3)),
            ))
        },
    },
    Trend {
        figure: "7d, 7e",
        finding: "user partial slip: the flow thins and slows as d rises",
        paper: "0.15 to 0.05 m and 9.65 to 8.15 m/s from d = 0.1 to 1 mm",
        judge: |c, _| {
            let h = outputs(c, PS_D_ENDS, flow_thickness)?;
            let u = outputs(c, PS_D_ENDS, max_u_s)?;
            Ok((
                decreasing(&h) && decreasing(&u),
                format!(
                    "flow thickness [m] {}; max u_s [m/s] {}",
                    listed("d [mm]", &h, 3),
                    listed("d [mm]", &u, 2)
                ),
            ))
        },
    },
    Trend {
        figure: "8, 10",
        finding: "revisited Johnson–Jackson: a cushion less developed than JJ φ = 0.1's",
        paper: "a thinner cushion than JJ φ = 0.1",
        judge: |c, _| {
            let v = outputs(
                c,
                &[
                    ("revisited JJ", "S-RJJ"),
                    ("JJ φ = 0.1", "S-JJ-phi_phi=0.1"),
                ],
                cushion_thickness,
            )?;
            Ok((
                v[0].1 > 0.0 && v[0].1 < v[1].1,
                format!(
                    "cushion thickness {:.3} m (revisited) against {:.3} m (φ = 0.1)",
                    v[0].1, v[1].1
                ),
            ))
        },
    },
    Trend {
        figure: "9",
        finding: "h_w^u at the floor probe ranks JJ φ = 1 > φ = 0.1 > revisited JJ > \
                  φ = 0.01 > Jenkins",
        paper: "579 > 156 > 70–156 > 59 > 26 m⁻¹",
        judge: |c, _| {
            let v = PROBE_RANKING
                .iter()
                .map(|&(l, case)| {
                    probe_h_u(c, case)
                        .map(|h| (l, h))
                        .map_err(|e| format!("`{case}`: {e}"))
                })
                .collect::<Result<Vec<_>, String>>()?;
            let shown: Vec<String> = v.iter().map(|(l, h)| format!("{l} {h:.0}")).collect();
            Ok((decreasing(&v), format!("{} m⁻¹", shown.join(", "))))
        },
    },
    Trend {
        figure: "9, 10",
        finding: "a cushion where h_w^u at the probe exceeds 70 m⁻¹, none where it is below",
        paper: "JJ φ ≥ 0.1 and revisited JJ above 70 with a cushion; JJ φ = 0.01 and \
                Jenkins below, without",
        judge: |c, _| {
            let mut all = true;
            let mut seen = Vec::new();
            for &(label, case) in PROBE_RANKING {
                let h = probe_h_u(c, case).map_err(|e| format!("`{case}`: {e}"))?;
                let yes = c
                    .get(case)
                    .and_then(has_cushion)
                    .map_err(|e| format!("`{case}`: {e}"))?;
                all &= yes == (h > CUSHION_LIMIT_H_U);
                seen.push(format!("{label} {h:.0} m⁻¹, cushion {}", yes_no(yes)));
            }
            Ok((all, seen.join("; ")))
        },
    },
    Trend {
        figure: "12",
        finding: "flume: Johnson–Jackson φ = 0.1 fits the gate speeds best of the four floors",
        paper: "MSE 0.36 against 0.53–0.93 m²/s² (against the measured speeds)",
        judge: |c, described| {
            let v = outputs(c, FLUME_CASES, |d| flume_mse(d, described))?;
            let shown: Vec<String> = v.iter().map(|(l, e)| format!("{l} {e:.2}")).collect();
            let best = v.iter().all(|p| v[0].1 <= p.1);
            Ok((
                best,
                format!(
                    "MSE against the described speeds: {} m²/s²",
                    shown.join(", ")
                ),
            ))
        },
    },
];

/// Every case a finding reads (the cases of [`PAPER_NUMBERS`] and of the trends' sweeps).
pub fn cases_named() -> std::collections::BTreeSet<&'static str> {
    let mut names: std::collections::BTreeSet<&str> = PAPER_NUMBERS
        .iter()
        .filter(|row| !matches!(row.quantity, Quantity::FlumeMse))
        .flat_map(|row| match row.quantity {
            Quantity::FlowThicknessAbove(other) => vec![row.case, other],
            _ => vec![row.case],
        })
        .collect();
    for list in [
        JJ_PHI,
        JJ_D,
        JEN_D,
        PS_HU,
        PS_HU_ENDS,
        PS_D_ENDS,
        PROBE_RANKING,
        FLUME_CASES,
    ] {
        names.extend(list.iter().map(|p| p.1));
    }
    names
}

/// Every finding of the paper, judged from `records`.
pub fn judge_all(records: &Records, described: &[(usize, f64)]) -> Vec<Judged> {
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
        let (kind, verdict) = match exp {
            Expected::Yes | Expected::No => (
                Kind::Cushion,
                reading.and_then(|r| match r {
                    Reading::YesNo(b) => Ok((b == (exp == Expected::Yes), r.to_string())),
                    _ => Err("not a yes/no reading".into()),
                }),
            ),
            _ => (
                Kind::Number,
                reading.and_then(|r| {
                    let shown = r.shown_value().ok_or("not a number")?;
                    let ok = matches(shown, exp).ok_or("not a numeric expectation")?;
                    Ok((ok, r.to_string()))
                }),
            ),
        };
        out.push(Judged {
            figure: row.figure,
            finding: format!("{} (`{}`)", row.quantity.label(), row.case),
            paper: row.paper.to_string(),
            kind,
            verdict,
        });
    }
    for t in TRENDS {
        out.push(Judged {
            figure: t.figure,
            finding: t.finding.to_string(),
            paper: t.paper.to_string(),
            kind: Kind::Trend,
            verdict: (t.judge)(records, described),
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
pub fn section(md: &mut String, records: &Records, described: &[(usize, f64)]) {
    let judged = judge_all(records, described);
    md.push_str("## Summary: the paper's findings in runout's runs\n\n");
    let _ = writeln!(md, "{}\n", summary_line(&judged));
    md.push_str(
        "How each is judged (xtask/src/report/findings.rs): an air cushion yes/no as the \
         station profile shows it (floor εs below 0.8 × the profile's peak); a trend, \
         ranking or threshold by comparing runout's own values along the sweep; a number by \
         runout's value as shown, inside the paper's range or within 20 % of its single \
         value. The flume's MSEs are not counted (the paper's are against measured speeds \
         its text does not give). Every number here is in the tables below.\n\n",
    );
    let not: Vec<&Judged> = judged
        .iter()
        .filter(|j| matches!(j.verdict, Ok((false, _))))
        .collect();
    if !not.is_empty() {
        md.push_str("**Not reproduced**, with what runout's runs show instead:\n\n");
        for j in &not {
            if let Ok((_, shown)) = &j.verdict {
                let _ = writeln!(
                    md,
                    "- Fig. {}: {} — paper: {}; runout: {}.",
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
            Ok((ok, shown)) => (shown.clone(), yes_no(*ok).to_string()),
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
        let judged = judge_all(&cases, &[]);
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
