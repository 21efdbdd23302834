//! The paper's trends, rankings and thresholds (issue 19, item 5): each a rule over runout's
//! own values along a sweep, so it does not depend on how close the values are to MFIX's;
//! and the station readings they and the numbers share.

use super::findings::Verdict;
use super::paper::{Quantity, CUSHION_LIMIT_H_U, PAPER_NUMBERS};
use super::reading::{value, Reading};
use super::record::RunRecord;
use super::records::Records;

/// A trend, ranking or threshold of the paper, with its rule.
pub struct Trend {
    /// the paper's figure
    pub figure: &'static str,
    /// the finding, in words
    pub finding: &'static str,
    /// the paper's numbers behind it
    pub paper: &'static str,
    /// the quantities it compares (for their error bars)
    pub quantities: &'static [Quantity],
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
pub(super) fn cushion_thickness(r: &RunRecord) -> Result<f64, String> {
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
    runout_post::metrics::mse_vs_described(r.gates.as_ref().map_err(Clone::clone)?, described)
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

pub(super) fn yes_no(b: bool) -> &'static str {
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
        quantities: &[Quantity::FloorEpsS],
        judge: |c, _| {
            let v = outputs(c, JJ_PHI, floor_eps_s)?;
            Ok((increasing(&v), format!("floor εs {}", listed("φ", &v, 3))))
        },
    },
    Trend {
        figure: "4c",
        finding: "Johnson–Jackson: the floor θ is highest at φ = 1",
        paper: "2.2 m²/s² at φ = 1",
        quantities: &[Quantity::FloorTheta],
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
        quantities: &[Quantity::CushionThickness],
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
        quantities: &[Quantity::MaxUs],
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
        quantities: &[Quantity::FloorTheta],
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
        quantities: &[Quantity::FlowThickness, Quantity::MaxUs],
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
        quantities: &[Quantity::AirCushion],
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
        quantities: &[Quantity::FlowThickness],
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
        quantities: &[Quantity::MaxUs],
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
        quantities: &[Quantity::FloorTheta],
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
        quantities: &[Quantity::FlowThickness, Quantity::MaxUs],
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
        quantities: &[Quantity::CushionThickness],
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
        quantities: &[Quantity::ProbeHu],
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
        quantities: &[Quantity::ProbeHu, Quantity::AirCushion],
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
        quantities: &[Quantity::FlumeMse],
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
