//! The findings not reproduced, explained (issue 45, item 4): for each, one line with the
//! grid effect (the error ladder, [`super::error_bars`]), the release effect (the release
//! study, docs/studies/impact.md §4) and what is left, so a reader sees whether the gap is runout,
//! the grid or the set-up the paper did not report.
//!
//! For a number v read from a run at fidelity F:
//! - grid: at coarse the ladder's coarse-to-paper change c = (f_p − f_c)/f_c, and at the paper
//!   grid its relative bar g (GCI): the grid can move v to v (1 + c)(1 ± g);
//! - release: over the blocks of the release sweep of the case's floor (R-JEN-t0 for the
//!   Jenkins floors, R-JJ-t0 for every other: the study has no other floor), each quantity
//!   relative to the base block, r ∈ [r_lo, r_hi];
//! - left: where the paper's value or range lies beyond v (1 + c)(1 ± g)(1 + r), the
//!   distance from that reach, relative to the paper's value; else nothing.
//!
//! Both effects are estimates from one ladder and one coarse study applied to the family,
//! said so in each line; the cushion (a yes/no) is said in words.

use std::path::Path;

use anyhow::{Context, Result};
use runout_case::Fidelity;

use super::error_bars::{settles, Ladders, UNCONVERGED_GCI};
use super::findings::{expected, Judged};
use super::paper::Quantity;
use super::records::Records;
use super::release::CSV_COLUMNS;

/// The release study's CSV the report reads (coarse: the fidelity with every block),
/// relative to the reports directory (docs/reports/).
pub const RELEASE_CSV: &str = "release/release_coarse.csv";
/// The base block's label in the release cases' names.
const BASE_BLOCK: &str = "release=L0.5-H0.2-F5.5-B0.4";

/// One release run's station numbers (`None`: the row has no value).
#[derive(Clone, Debug, Default)]
struct ReleaseValues {
    case: String,
    sweep: String,
    /// max u_s, floor εs, air cushion (1/0), cushion thickness, flow thickness
    values: [Option<f64>; 5],
}

/// The release study's rows.
#[derive(Clone, Debug, Default)]
pub struct Releases {
    rows: Vec<ReleaseValues>,
}

/// The column of a quantity in [`ReleaseValues::values`].
fn release_column(q: Quantity) -> Option<usize> {
    Some(match q {
        Quantity::MaxUs => 0,
        Quantity::FloorEpsS => 1,
        Quantity::AirCushion => 2,
        Quantity::CushionThickness => 3,
        Quantity::FlowThickness => 4,
        _ => return None,
    })
}

/// The release sweep standing for a case's floor.
fn sweep_for(case: &str) -> &'static str {
    if case.starts_with("S-JEN") {
        "R-JEN-t0"
    } else {
        "R-JJ-t0"
    }
}

impl Releases {
    /// Reads docs/reports/release/release_coarse.csv below `reports`; no file is no study.
    pub fn read(reports: &Path) -> Result<Releases> {
        let path = reports.join(RELEASE_CSV);
        if !path.exists() {
            return Ok(Releases::default());
        }
        let text = std::fs::read_to_string(&path)?;
        Releases::parse(&text).with_context(|| format!("{}", path.display()))
    }

    /// The rows of a CSV text with [`CSV_COLUMNS`].
    pub fn parse(text: &str) -> Result<Releases> {
        let mut reader = csv::Reader::from_reader(text.as_bytes());
        let header: Vec<String> = reader.headers()?.iter().map(String::from).collect();
        anyhow::ensure!(
            header == CSV_COLUMNS,
            "columns {header:?}, expected {CSV_COLUMNS:?}"
        );
        let mut rows = Vec::new();
        for r in reader.records() {
            let r = r?;
            let v = |k: usize| r.get(k).and_then(|s| s.parse().ok());
            rows.push(ReleaseValues {
                case: r.get(0).unwrap_or_default().into(),
                sweep: r.get(1).unwrap_or_default().into(),
                values: [v(2), v(3), v(4), v(5), v(6)],
            });
        }
        Ok(Releases { rows })
    }

    /// (lowest, highest) of `q` over the blocks of `sweep` relative to its base block, and
    /// the number of blocks with a value; `None` without a base value or at a base of 0.
    fn spread(&self, sweep: &str, q: Quantity) -> Option<(f64, f64, usize)> {
        let k = release_column(q)?;
        let of_sweep = || self.rows.iter().filter(|r| r.sweep == sweep);
        let base =
            of_sweep().find(|r| r.case.ends_with(BASE_BLOCK))?.values[k].filter(|b| *b != 0.0)?;
        let values: Vec<f64> = of_sweep().filter_map(|r| r.values[k]).collect();
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Some((lo / base - 1.0, hi / base - 1.0, values.len()))
    }

    /// (blocks with a cushion, blocks with a profile) of `sweep`.
    fn cushions(&self, sweep: &str) -> (usize, usize) {
        let v: Vec<f64> = self
            .rows
            .iter()
            .filter(|r| r.sweep == sweep)
            .filter_map(|r| r.values[2])
            .collect();
        (v.iter().filter(|c| **c > 0.5).count(), v.len())
    }
}

/// "+4 %", "−12 %".
fn percent(x: f64) -> String {
    format!("{:+.0} %", 100.0 * x).replace('-', "−")
}

/// "4 %" for ±0.04.
fn magnitude(x: f64) -> String {
    format!("{:.0} %", 100.0 * x.abs())
}

/// The grid part of a number's line and its reach (1 + c)(1 ± g) as a factor range;
/// `None` as the reach where the ladder does not converge ([`UNCONVERGED_GCI`]).
fn grid_effect(
    case: &str,
    q: Quantity,
    fidelity: Fidelity,
    ladders: &Ladders,
) -> (String, Option<(f64, f64)>) {
    let Some(l) = ladders.ladder_for(case, q) else {
        return ("grid: no error ladder measures it".into(), Some((1.0, 1.0)));
    };
    let g = l.relative().unwrap_or(0.0);
    let whose = if l.case == case {
        "its own ladder".to_string()
    } else {
        format!("the ladder of `{}`", l.case)
    };
    if g >= UNCONVERGED_GCI {
        let text = format!(
            "grid: does not converge on {whose} (GCI {:.0} % at paper)",
            100.0 * g
        );
        return (text, None);
    }
    let bar = if l.bar == 0.0 {
        format!("its levels agree on {whose} (whole cells)")
    } else {
        format!("± {:.1} % at paper ({whose})", 100.0 * g)
    };
    let coarse_shift = (fidelity == Fidelity::Coarse)
        .then(|| ladders.grid_change(case, q))
        .flatten();
    match (fidelity, coarse_shift) {
        (Fidelity::Paper, _) => (format!("grid: {bar}"), Some((1.0 - g, 1.0 + g))),
        (_, Some(c)) => (
            format!("grid: coarse to paper {}, {bar}", percent(c)),
            Some(((1.0 + c) * (1.0 - g), (1.0 + c) * (1.0 + g))),
        ),
        _ => (
            format!("grid: no ladder level at {fidelity}; {bar}"),
            Some((1.0 - g, 1.0 + g)),
        ),
    }
}

/// The line of a number `v` the paper gives as `exp`.
fn number_line(
    case: &str,
    q: Quantity,
    v: f64,
    (p_lo, p_hi): (f64, f64),
    fidelity: Fidelity,
    ladders: &Ladders,
    releases: &Releases,
) -> String {
    let (grid, reach) = grid_effect(case, q, fidelity, ladders);
    let sweep = sweep_for(case);
    let (release, (r_lo, r_hi)) = match releases.spread(sweep, q) {
        Some((lo, hi, n)) => (
            format!(
                "release: {} to {} over the {n} blocks of {sweep} (coarse)",
                percent(lo),
                percent(hi)
            ),
            (1.0 + lo, 1.0 + hi),
        ),
        None => (
            format!("release: not measured by the release study ({sweep})"),
            (1.0, 1.0),
        ),
    };
    let left = match reach {
        None => "left: undecided while the grid does not converge".to_string(),
        Some((g_lo, g_hi)) => {
            let (a, b) = (v * g_lo * r_lo, v * g_hi * r_hi);
            let (lo, hi) = (a.min(b), a.max(b));
            if p_hi < lo {
                let gap = magnitude(p_hi / lo - 1.0);
                format!("left: the paper's value is {gap} below that reach")
            } else if p_lo > hi {
                let gap = magnitude(p_lo / hi - 1.0);
                format!("left: the paper's value is {gap} above that reach")
            } else {
                "left: nothing; the grid and the release together reach the paper's value".into()
            }
        }
    };
    format!("{grid}; {release}; {left}")
}

/// The line of a cushion yes/no or thickness.
fn cushion_line(case: &str, fidelity: Fidelity, ladders: &Ladders, releases: &Releases) -> String {
    let ladder = ladders.ladder_for(case, Quantity::CushionThickness);
    let grid_settles = ladder.is_none_or(|l| settles(l.paper, l.bar));
    let grid = match ladder {
        Some(l) => {
            let coarse = l
                .coarse
                .map_or(String::new(), |c| format!("coarse {c:.3} m, "));
            format!(
                "grid: the ladder of `{}` ({coarse}paper {:.3} ± {:.3} m) {} the cushion",
                l.case,
                l.paper,
                l.bar,
                if grid_settles {
                    "settles"
                } else {
                    "does not settle"
                }
            )
        }
        None => "grid: no error ladder measures it".into(),
    };
    let sweep = sweep_for(case);
    let (yes, n) = releases.cushions(sweep);
    let release = if n == 0 {
        format!("release: not in the release study ({sweep})")
    } else {
        format!("release: a cushion in {yes} of the {n} blocks of {sweep} (coarse)")
    };
    let unsettled = !grid_settles || (yes > 0 && yes < n);
    let left = if unsettled {
        "left: undecided; the grid or the release can change it"
    } else if fidelity == Fidelity::Paper {
        "left: the difference stands beyond the grid and the release"
    } else {
        "left: to be read at the paper grid"
    };
    format!("{grid}; {release}; {left}")
}

/// The explanation of one finding not reproduced; `None` for one that is, or has no value.
pub fn explain(
    j: &Judged,
    records: &Records,
    ladders: &Ladders,
    releases: &Releases,
) -> Option<String> {
    let Ok((false, _)) = &j.verdict else {
        return None;
    };
    let Some(case) = j.case else {
        return Some(trend_line(j, ladders));
    };
    let q = *j.quantities.first()?;
    let record = records.get(case).ok()?;
    if matches!(q, Quantity::AirCushion | Quantity::CushionThickness) {
        return Some(cushion_line(case, record.fidelity, ladders, releases));
    }
    let range = expected(&j.paper)?.range()?;
    let v = super::reading::value(q, case, records, &[]).ok()?;
    let v = match v {
        super::reading::Reading::Number { value, .. } => value,
        super::reading::Reading::YesNo(_) => return None,
    };
    if ladders.ladder_for(case, q).is_none() && release_column(q).is_none() {
        return Some("no error ladder or release study measures this case".into());
    }
    Some(number_line(
        case,
        q,
        v,
        range,
        record.fidelity,
        ladders,
        releases,
    ))
}

/// A trend compares runout's own values: the line gives their error bar at the paper grid.
fn trend_line(j: &Judged, ladders: &Ladders) -> String {
    let bars: Vec<String> = j
        .quantities
        .iter()
        .filter_map(|&q| {
            let l = ladders.first_for(q)?;
            Some(format!(
                "{} ± {:.0} % ({})",
                q.label(),
                100.0 * l.relative().unwrap_or(0.0),
                l.case
            ))
        })
        .collect();
    if bars.is_empty() {
        return "a comparison of runout's own values; no error ladder measures them".into();
    }
    format!(
        "a comparison of runout's own values, decided by the grid only where they differ by \
         more than their error bars at the paper grid: {}",
        bars.join(", ")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// error_bars.rs's test ladder: JJ max u_s coarse 7.0, paper 7.3 ± 0.06; the cushion 0
    /// at coarse, 0.015 ± 0.015 at paper; JEN max u_s at paper only.
    const LADDER: &str = super::super::error_bars::TEST_LADDER;

    /// Three JJ blocks: the base at 7.0 m/s, one at 6.3 (−10 %), one at 7.7 (+10 %); one
    /// of them with a cushion.
    const RELEASES: &str = "\
case,sweep,max_u_s,floor_eps_s,air_cushion,cushion_thickness,flow_thickness
R-JJ-t0_release=L0.5-H0.2-F5.5-B0.4,R-JJ-t0,7.0,0.2,0,0,0.03
R-JJ-t0_release=L0.25-H0.2-F5.5-B0.4,R-JJ-t0,6.3,0.1,1,0.01,0.03
R-JJ-t0_release=L1-H0.2-F5.5-B0.4,R-JJ-t0,7.7,,,,
";

    fn evidence() -> (Ladders, Releases) {
        (
            Ladders::parse(LADDER).unwrap(),
            Releases::parse(RELEASES).unwrap(),
        )
    }

    #[test]
    fn a_coarse_number_is_moved_by_the_ladder_and_the_blocks_before_what_is_left() {
        let (l, r) = evidence();
        let exp = (8.4, 8.5);
        let line = number_line(
            "S-JJ-d_d=0.001",
            Quantity::MaxUs,
            6.86,
            exp,
            Fidelity::Coarse,
            &l,
            &r,
        );
        assert!(line.contains("coarse to paper +4 %"), "{line}");
        assert!(line.contains("release: −10 % to +10 %"), "{line}");
        assert!(
            line.contains("+10 % over the 3 blocks of R-JJ-t0"),
            "{line}"
        );
        // the reach: 6.86 × (7.3/7.0) × (1 + 0.06/7.3) × 1.1 = 8.09; 8.4 is 4 % above it
        let reach = 6.86 * (7.3 / 7.0) * (1.0 + 0.06 / 7.3) * 1.1;
        let left = format!("{:.0} % above that reach", 100.0 * (8.4 / reach - 1.0));
        assert!(line.contains(&left), "{line} / {left}");
    }

    #[test]
    fn a_number_the_effects_reach_has_nothing_left() {
        let (l, r) = evidence();
        let exp = (7.9, 7.9);
        let line = number_line(
            "S-JJ-phi_phi=0.1",
            Quantity::MaxUs,
            7.3,
            exp,
            Fidelity::Paper,
            &l,
            &r,
        );
        assert!(
            line.starts_with("grid: ± 0.8 % at paper (its own ladder)"),
            "{line}"
        );
        assert!(
            line.ends_with(
                "left: nothing; the grid and the release together reach the paper's value"
            ),
            "{line}"
        );
        // no release value of θ: said so, and the grid alone decides
        let theta = number_line(
            "S-JJ-phi_phi=0.1",
            Quantity::FloorTheta,
            0.9,
            (2.2, 2.2),
            Fidelity::Paper,
            &l,
            &r,
        );
        assert!(theta.contains("no error ladder measures it"), "{theta}");
        assert!(
            theta.contains("release: not measured by the release study"),
            "{theta}"
        );
        assert!(theta.contains("above that reach"), "{theta}");
    }

    #[test]
    fn a_cushion_the_grid_does_not_settle_is_undecided() {
        let (l, r) = evidence();
        let line = cushion_line("S-PS-hu_hu=70", Fidelity::Coarse, &l, &r);
        assert!(
            line.contains("(coarse 0.000 m, paper 0.015 ± 0.015 m) does not settle"),
            "{line}"
        );
        assert!(
            line.contains("a cushion in 1 of the 2 blocks of R-JJ-t0"),
            "{line}"
        );
        assert!(
            line.ends_with("left: undecided; the grid or the release can change it"),
            "{line}"
        );
    }

    #[test]
    fn a_release_file_of_other_columns_is_refused() {
        assert!(Releases::parse("case,sweep\nx,y\n").is_err());
    }
}
