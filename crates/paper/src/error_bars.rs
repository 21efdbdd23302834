//! Each station number's discretisation error at the paper grid (issue 45, item 3), from the
//! uniform error ladder of `cargo xtask error-time` (docs/reports/error-time/error_time.csv).
//!
//! The error bar of a value f_p at the paper level is Roache's grid convergence index with
//! the ladder's Richardson value f_R and safety factor Fs (error_time/gci.rs):
//!
//!   e = Fs |f_p − f_R|,
//!
//! which is the ladder's GCI_fine = Fs |f_1 − f_2| / (r^p − 1) when the paper grid is its
//! finest level, and stays the paper level's error when a finer level exists. Fs is 3 outside
//! the asymptotic range, 1.25 inside (Roache 1998; ASME V&V 20).
//!
//! A ladder costs three runs, so only some cases have one. A family-S case without its own
//! takes the relative bar e/|f_p| of the ladder of the same floor condition (the word after
//! "S-": JJ, JEN, PS, RJJ), else of the first ladder in the file, and the report names the
//! ladder it used. Bars apply to paper-grid values only: a coarse value's error is the
//! ladder's coarse-to-paper change, which [`Ladders::grid_change`] gives for item 4.

use std::path::Path;

use anyhow::{Context, Result};

use super::findings::{matches, Expected};
use super::paper::Quantity;
use super::reading::Reading;

/// The ladder file, relative to the reports directory (docs/reports/).
pub const LADDER_FILE: &str = "error-time/error_time.csv";

/// One station number of one ladder.
#[derive(Clone, Debug, PartialEq)]
pub struct LadderValue {
    /// the ladder's case
    pub case: String,
    /// the ladder's name of the quantity (error_time/quantity.rs)
    pub quantity: String,
    /// value at the paper level
    pub paper: f64,
    /// value at the coarse level, if that level ran
    pub coarse: Option<f64>,
    /// error bar of the paper value, Fs |f_p − f_R|
    pub bar: f64,
}

impl LadderValue {
    /// The bar relative to the paper value; `None` where the value is 0.
    pub fn relative(&self) -> Option<f64> {
        (self.paper != 0.0).then(|| self.bar / self.paper.abs())
    }
}

/// A number's error bar at the paper grid.
#[derive(Clone, Debug, PartialEq)]
pub struct ErrorBar {
    /// half-width, in the quantity's unit
    pub half_width: f64,
    /// the ladder it came from
    pub ladder: String,
    /// whether that ladder is the case's own
    pub own: bool,
}

impl ErrorBar {
    /// "± 0.086 (GCI 1.2 %, own ladder)" with `decimals`.
    pub fn describe(&self, value: f64, decimals: usize) -> String {
        let whose = if self.own {
            "own ladder".to_string()
        } else {
            format!("ladder of `{}`", self.ladder)
        };
        if self.half_width == 0.0 {
            // equal values at the three levels: a quantity read in whole cells
            return format!("± 0 ({whose}: its levels agree)");
        }
        let relative = if value != 0.0 {
            format!("GCI {:.1} %, ", 100.0 * self.half_width / value.abs())
        } else {
            String::new()
        };
        format!("± {:.decimals$} ({relative}{whose})", self.half_width)
    }
}

/// Every ladder's station numbers at the paper level.
#[derive(Clone, Debug, Default)]
pub struct Ladders {
    values: Vec<LadderValue>,
}

/// The ladder's name of a report quantity, for the quantities a ladder measures.
fn ladder_name(q: Quantity) -> Option<&'static str> {
    Some(match q {
        Quantity::AirCushion | Quantity::CushionThickness => "cushion_thickness",
        Quantity::FloorEpsS => "floor_eps_s",
        Quantity::FloorTheta => "floor_theta",
        Quantity::MaxUs => "max_u_s",
        Quantity::FlowThickness => "flow_thickness",
        Quantity::ProbeHu => "probe_h_w_u",
        _ => return None,
    })
}

/// The floor condition of a family-S case: "S-JJ-phi_phi=0.1" → "JJ", "S-RJJ" → "RJJ".
fn floor_of(case: &str) -> Option<&str> {
    let rest = case.strip_prefix("S-")?;
    rest.split(['-', '_']).next()
}

impl Ladders {
    /// Reads `docs/reports/error-time/error_time.csv` below `reports`; no file is no ladder.
    pub fn read(reports: &Path) -> Result<Ladders> {
        let path = reports.join(LADDER_FILE);
        if !path.exists() {
            return Ok(Ladders::default());
        }
        let text = std::fs::read_to_string(&path).with_context(|| format!("{}", path.display()))?;
        Ladders::parse(&text).with_context(|| format!("{}", path.display()))
    }

    /// The ladder rows of a CSV text (the header of error_time/csv_file.rs).
    pub fn parse(text: &str) -> Result<Ladders> {
        let mut reader = csv::Reader::from_reader(text.as_bytes());
        let header = reader.headers()?.clone();
        let col = |name: &str| {
            header
                .iter()
                .position(|h| h == name)
                .with_context(|| format!("no column `{name}`"))
        };
        let [case, level, status, quantity, value, richardson, fs] = [
            "case",
            "level",
            "status",
            "quantity",
            "value",
            "richardson_value",
            "gci_safety_factor",
        ]
        .map(col);
        let (case, level, status, quantity) = (case?, level?, status?, quantity?);
        let (value, richardson, fs) = (value?, richardson?, fs?);
        let rows: Vec<csv::StringRecord> = reader.records().collect::<Result<_, _>>()?;
        let number = |r: &csv::StringRecord, k: usize| r.get(k).and_then(|s| s.parse().ok());
        let mut values = Vec::new();
        for r in rows
            .iter()
            .filter(|r| r.get(level) == Some("paper") && r.get(status) == Some("completed"))
        {
            let (Some(paper), Some(f_r), Some(fs)) =
                (number(r, value), number(r, richardson), number(r, fs))
            else {
                continue; // a history quantity, or no three levels
            };
            let coarse = rows
                .iter()
                .find(|c| {
                    c.get(case) == r.get(case)
                        && c.get(quantity) == r.get(quantity)
                        && c.get(level) == Some("coarse")
                        && c.get(status) == Some("completed")
                })
                .and_then(|c| number(c, value));
            values.push(LadderValue {
                case: r.get(case).unwrap_or_default().to_string(),
                quantity: r.get(quantity).unwrap_or_default().to_string(),
                paper,
                coarse,
                bar: fs * (paper - f_r).abs(),
            });
        }
        Ok(Ladders { values })
    }

    /// The ladder used for `case`'s `quantity`: its own, else its floor's, else the first.
    pub fn ladder_for(&self, case: &str, quantity: Quantity) -> Option<&LadderValue> {
        let name = ladder_name(quantity)?;
        let of = |pick: &dyn Fn(&LadderValue) -> bool| {
            self.values.iter().find(|v| v.quantity == name && pick(v))
        };
        of(&|v| v.case == case)
            .or_else(|| of(&|v| floor_of(&v.case).is_some() && floor_of(&v.case) == floor_of(case)))
            .or_else(|| self.first_for(quantity))
    }

    /// The first ladder that measures `quantity` (for a finding over several cases).
    pub fn first_for(&self, quantity: Quantity) -> Option<&LadderValue> {
        let name = ladder_name(quantity)?;
        self.values.iter().find(|v| v.quantity == name)
    }

    /// The error bar of `case`'s paper-grid `value` of `quantity`: the own ladder's bar, or
    /// another ladder's relative bar times |value| (its absolute bar where its value is 0).
    pub fn bar(&self, case: &str, quantity: Quantity, value: f64) -> Option<ErrorBar> {
        let l = self.ladder_for(case, quantity)?;
        let own = l.case == case;
        let half_width = match (own, l.relative()) {
            (false, Some(rel)) => rel * value.abs(),
            _ => l.bar,
        };
        Some(ErrorBar {
            half_width,
            ladder: l.case.clone(),
            own,
        })
    }

    /// The relative change of `quantity` from the coarse to the paper level on `case`'s
    /// ladder ([`Ladders::ladder_for`]), (f_p − f_c)/|f_c|; `None` without a coarse level or
    /// at f_c = 0.
    pub fn grid_change(&self, case: &str, quantity: Quantity) -> Option<f64> {
        let l = self.ladder_for(case, quantity)?;
        let c = l.coarse.filter(|c| *c != 0.0)?;
        Some((l.paper - c) / c.abs())
    }
}

/// Whether the interval `value ± bar` reaches the paper's `range` (a single value is a
/// range of zero width).
pub fn bar_reaches(value: f64, bar: f64, range: (f64, f64)) -> bool {
    value - bar <= range.1 && range.0 <= value + bar
}

/// A relative bar (GCI) at or above this: the ladder does not say where the value converges
/// (its levels differ by as much as the value), so the grid leaves a finding undecided.
pub const UNCONVERGED_GCI: f64 = 0.5;

/// Which rule reproduced a number (the report states it beside the verdict).
fn rule_name(exp: Expected) -> &'static str {
    match exp {
        Expected::Range(..) => "in the paper's range",
        _ => "within 20 %",
    }
}

/// A number judged: reproduced when its shown value is in the paper's range or within 20 %
/// of its value ([`matches`]), or, at the paper grid, when `value ± bar` reaches the paper's
/// value or range. Returns (reproduced, runout's value as shown with its bar, the rule that
/// reproduced it).
pub fn judge_number(
    reading: &Reading,
    exp: Expected,
    bar: Option<&ErrorBar>,
) -> Result<(bool, String, Option<&'static str>), String> {
    let Reading::Number {
        value, decimals, ..
    } = reading
    else {
        return Err("not a number".into());
    };
    let shown = reading.shown_value().ok_or("not a number")?;
    let by_rule = matches(shown, exp).ok_or("not a numeric expectation")?;
    let range = exp.range().ok_or("not a numeric expectation")?;
    let by_bar = bar.is_some_and(|b| bar_reaches(*value, b.half_width, range));
    let text = match bar {
        Some(b) => format!("{reading} {}", b.describe(*value, *decimals + 1)),
        None => reading.to_string(),
    };
    let unconverged = bar.is_some_and(|b| b.half_width >= UNCONVERGED_GCI * value.abs());
    let rule = if by_rule {
        Some(rule_name(exp))
    } else if by_bar && unconverged {
        // a bar as large as the value reaches almost any paper value: said so
        Some("within its error bar, which is as large as the value: the grid does not decide")
    } else if by_bar {
        Some("within its error bar")
    } else {
        None
    };
    Ok((by_rule || by_bar, text, rule))
}

/// Whether a cushion's thickness is settled by the grid: larger than its bar (beyond
/// round-off: Fs |f − f_R| equals f where the ladder's cushion vanishes at one level), or no
/// cushion at any level.
pub fn settles(thickness: f64, bar: f64) -> bool {
    thickness > bar * (1.0 + 1e-9) + 1e-15 || (thickness == 0.0 && bar == 0.0)
}

/// The note a paper-grid cushion yes/no gets: its thickness with the bar, and whether the
/// grid settles the yes/no (the bar smaller than the thickness, or no cushion and a bar of 0).
pub fn cushion_note(thickness: f64, bar: &ErrorBar) -> String {
    let settled = if settles(thickness, bar.half_width) {
        "settled by the grid"
    } else {
        "not settled by the grid"
    };
    format!(
        "thickness {thickness:.3} m {}: {settled}",
        bar.describe(thickness, 3)
    )
}

/// Two ladders in error_time.csv's columns: JJ with max u_s (coarse 7.0, paper 7.3,
/// Richardson 7.32, Fs 3: bar 0.06) and a cushion that is 0 at coarse; JEN with max u_s
/// 7.0 at paper (Richardson 7.1, Fs 1.25: bar 0.125). A history row is skipped.
#[cfg(test)]
pub(super) const TEST_LADDER: &str = "\
case,scheme,level,status,quantity,value,richardson_value,gci_safety_factor
S-JJ-phi_phi=0.1,upwind,coarse,completed,max_u_s,7.0,7.32,3
S-JJ-phi_phi=0.1,upwind,paper,completed,max_u_s,7.3,7.32,3
S-JJ-phi_phi=0.1,upwind,coarse,completed,cushion_thickness,0,0.01,3
S-JJ-phi_phi=0.1,upwind,paper,completed,cushion_thickness,0.015,0.01,3
S-JJ-phi_phi=0.1,upwind,paper,completed,eps_s,,,
S-JEN-d_d=0.0005,upwind,paper,completed,max_u_s,7.0,7.1,1.25
S-JEN-d_d=0.0005,upwind,finer,failed: not run,max_u_s,,7.1,1.25
";

#[cfg(test)]
mod tests {
    use super::*;

    const CSV: &str = TEST_LADDER;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-12
    }

    #[test]
    fn the_bar_is_the_safety_factor_times_the_distance_to_richardson() {
        let l = Ladders::parse(CSV).unwrap();
        let own = l.bar("S-JJ-phi_phi=0.1", Quantity::MaxUs, 7.3).unwrap();
        assert!(own.own && close(own.half_width, 0.06), "{own:?}");
        let jen = l.bar("S-JEN-d_d=0.0005", Quantity::MaxUs, 7.0).unwrap();
        assert!(close(jen.half_width, 0.125));
        // the cushion's bar (0.015) is its whole value: the yes/no is not settled by the grid
        let cushion = l
            .bar("S-JJ-phi_phi=0.1", Quantity::AirCushion, 0.015)
            .unwrap();
        assert!(close(cushion.half_width, 0.015));
    }

    #[test]
    fn a_case_without_a_ladder_takes_its_floors_relative_bar_else_the_first() {
        let l = Ladders::parse(CSV).unwrap();
        // JEN d = 1 mm: JEN's relative bar 0.125 / 7 applied to 8.4
        let jen = l.bar("S-JEN-d_d=0.001", Quantity::MaxUs, 8.4).unwrap();
        assert!(!jen.own && jen.ladder == "S-JEN-d_d=0.0005");
        assert!(close(jen.half_width, 8.4 * 0.125 / 7.0));
        // JJ d = 0.1 mm: the JJ floor's ladder
        let jj = l.bar("S-JJ-d_d=0.0001", Quantity::MaxUs, 7.3).unwrap();
        assert_eq!(jj.ladder, "S-JJ-phi_phi=0.1");
        // partial slip has no ladder of its floor: the first ladder
        let ps = l.bar("S-PS-hu_hu=70", Quantity::MaxUs, 7.3).unwrap();
        assert_eq!(ps.ladder, "S-JJ-phi_phi=0.1");
        assert!(close(ps.half_width, 0.06));
        // no ladder measures the flume's gate speeds
        assert!(l.bar("F-JEN", Quantity::FlumeLastGateSpeed, 4.0).is_none());
    }

    #[test]
    fn the_grid_change_runs_from_coarse_to_paper() {
        let l = Ladders::parse(CSV).unwrap();
        let change = l.grid_change("S-JJ-d_d=0.001", Quantity::MaxUs).unwrap();
        let ladder = &l
            .ladder_for("S-JJ-d_d=0.001", Quantity::MaxUs)
            .unwrap()
            .case;
        assert!(close(change, 0.3 / 7.0) && ladder == "S-JJ-phi_phi=0.1");
        // no coarse cushion to be relative to; JEN's ladder has no coarse level
        assert!(l
            .grid_change("S-JJ-phi_phi=0.1", Quantity::CushionThickness)
            .is_none());
        assert!(l.grid_change("S-JEN-d_d=0.0005", Quantity::MaxUs).is_none());
    }

    #[test]
    fn a_number_is_reproduced_by_its_rule_or_its_bar_and_says_which() {
        let reading = Reading::Number {
            value: 7.30,
            decimals: 2,
            note: None,
        };
        let bar = ErrorBar {
            half_width: 0.11,
            ladder: "S-JJ-phi_phi=0.1".into(),
            own: true,
        };
        let range = Expected::Range(7.4, 7.5);
        assert_eq!(
            judge_number(&reading, range, Some(&bar)),
            Ok((
                true,
                "7.30 ± 0.110 (GCI 1.5 %, own ladder)".into(),
                Some("within its error bar")
            ))
        );
        assert_eq!(
            judge_number(&reading, range, None),
            Ok((false, "7.30".into(), None))
        );
        let wide = ErrorBar {
            half_width: 5.0,
            ..bar.clone()
        };
        let undecided = judge_number(&reading, Expected::Value(11.0), Some(&wide)).unwrap();
        assert!(undecided.0 && undecided.2.unwrap().ends_with("the grid does not decide"));
        let near = judge_number(&reading, Expected::Value(8.5), Some(&bar)).unwrap();
        assert_eq!((near.0, near.2), (true, Some("within 20 %")));
        let agree = ErrorBar {
            half_width: 0.0,
            ..bar.clone()
        };
        assert_eq!(
            agree.describe(0.03, 3),
            "± 0 (own ladder: its levels agree)"
        );
        let cushion = cushion_note(
            0.015,
            &ErrorBar {
                half_width: 0.015,
                ..bar
            },
        );
        assert!(cushion.ends_with("not settled by the grid"), "{cushion}");
    }

    #[test]
    fn a_bar_reaches_a_range_or_a_value() {
        assert!(bar_reaches(7.3, 0.11, (7.4, 7.5)));
        assert!(!bar_reaches(7.3, 0.09, (7.4, 7.5)));
        assert!(bar_reaches(0.015, 0.015, (0.0, 0.0)));
        assert!(!bar_reaches(8.0, 0.1, (7.0, 7.0)));
    }
}
