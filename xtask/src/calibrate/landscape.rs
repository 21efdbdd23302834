//! The tolerance range of a calibration and its outputs: the evaluations as CSV, the misfit
//! landscape as SVG, and a Markdown and a JSON summary.

use std::path::Path;

use anyhow::{Context, Result};
use serde::Serialize;

use super::optimise::{Calibration, Evaluation, Param};
use crate::report::plots::{self, HeatCell, Heatmap, Mark, Panel, Series, BLACK_INDEX};
use crate::sweep::csv_field;

/// The parameters whose misfit is within (1 + tol) × the minimum.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ToleranceRange {
    /// the misfit threshold, (1 + tol) × min
    pub threshold: f64,
    /// per parameter: (low, high)
    pub bounds: Vec<(f64, f64)>,
    /// 1-D: whether each end was found between an evaluation inside and one outside
    /// (else it is the last evaluated point: the range may go further); 2-D: false
    pub bracketed: (bool, bool),
    /// evaluations within the threshold outside the range (another valley, 1-D)
    pub elsewhere: usize,
    /// how the range was found
    pub method: String,
}

/// The tolerance range of `c`: in 1-D, the interval around the optimum where the misfit,
/// interpolated linearly between neighbouring evaluations (in the parameter's scale), stays
/// below the threshold; in 2-D, the bounding box of the evaluations below it.
pub fn tolerance_range(c: &Calibration, tol: f64) -> ToleranceRange {
    let best = c.optimum();
    let threshold = (1.0 + tol) * best.misfit;
    let finite: Vec<&Evaluation> = c
        .evaluations
        .iter()
        .filter(|e| e.misfit.is_finite())
        .collect();
    if c.params.len() == 2 {
        let inside: Vec<&&Evaluation> = finite.iter().filter(|e| e.misfit <= threshold).collect();
        let bounds = (0..2)
            .map(|d| {
                inside
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), e| {
                        (l.min(e.x[d]), h.max(e.x[d]))
                    })
            })
            .collect();
        return ToleranceRange {
            threshold,
            bounds,
            bracketed: (false, false),
            elsewhere: 0,
            method: format!(
                "the bounding box of the {} evaluations within the threshold",
                inside.len()
            ),
        };
    }
    let p = &c.params[0];
    let mut pts: Vec<(f64, f64)> = finite.iter().map(|e| (p.unit(e.x[0]), e.misfit)).collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    pts.dedup_by(|a, b| a.0 == b.0);
    let k = pts
        .iter()
        .position(|q| q.0 == p.unit(best.x[0]))
        .expect("the optimum is an evaluation");
    let crossing = |inside: (f64, f64), outside: (f64, f64)| {
        inside.0 + (threshold - inside.1) / (outside.1 - inside.1) * (outside.0 - inside.0)
    };
    let mut lo = k;
    while lo > 0 && pts[lo - 1].1 <= threshold {
        lo -= 1;
    }
    let mut hi = k;
    while hi + 1 < pts.len() && pts[hi + 1].1 <= threshold {
        hi += 1;
    }
    let low = if lo > 0 {
        crossing(pts[lo], pts[lo - 1])
    } else {
        pts[0].0
    };
    let high = if hi + 1 < pts.len() {
        crossing(pts[hi], pts[hi + 1])
    } else {
        pts[hi].0
    };
    let elsewhere = pts
        .iter()
        .enumerate()
        .filter(|(j, q)| (*j < lo || *j > hi) && q.1 <= threshold)
        .count();
    ToleranceRange {
        threshold,
        bounds: vec![(p.value(low), p.value(high))],
        bracketed: (lo > 0, hi + 1 < pts.len()),
        elsewhere,
        method: "linear interpolation of the misfit between neighbouring evaluations".into(),
    }
}

/// What the outputs say about the study besides the calibration.
pub struct StudyInfo<'a> {
    /// title: case, fidelity
    pub title: String,
    /// the measurements: file and what it holds
    pub measurements: String,
    /// the misfit's unit
    pub unit: &'a str,
    /// the relative tolerance of the range
    pub tol: f64,
    /// the command that made it
    pub command: String,
    /// per parameter: the case fields it sets
    pub fields: Vec<Vec<String>>,
}

fn number(v: f64) -> String {
    if v.is_finite() {
        format!("{v:.6}")
    } else {
        "none".into()
    }
}

/// Writes evaluations.csv.
pub fn write_csv(path: &Path, c: &Calibration) -> Result<()> {
    let mut text = String::from("k,stage");
    for p in &c.params {
        text.push_str(&format!(",{}", csv_field(&p.name)));
    }
    text.push_str(",misfit,note\n");
    for (k, e) in c.evaluations.iter().enumerate() {
        text.push_str(&format!("{k},{}", e.stage.name()));
        for x in &e.x {
            text.push_str(&format!(",{x:e}"));
        }
        let m = if e.misfit.is_finite() {
            format!("{:e}", e.misfit)
        } else {
            String::new()
        };
        text.push_str(&format!(",{m},{}\n", csv_field(&e.note)));
    }
    std::fs::write(path, text).with_context(|| format!("writing {}", path.display()))
}

/// The summary as JSON.
#[derive(Serialize)]
struct Summary<'a> {
    title: &'a str,
    command: &'a str,
    measurements: &'a str,
    misfit: String,
    params: Vec<ParamSummary<'a>>,
    optimum: Vec<f64>,
    min_misfit: f64,
    tolerance: f64,
    range: &'a ToleranceRange,
    evaluations: usize,
    evaluations_without_misfit: usize,
}

#[derive(Serialize)]
struct ParamSummary<'a> {
    name: &'a str,
    fields: &'a [String],
    lo: f64,
    hi: f64,
    start: f64,
    scale: &'a str,
}

/// Writes summary.json and summary.md; returns the Markdown.
pub fn write_summary(
    dir: &Path,
    c: &Calibration,
    r: &ToleranceRange,
    cx: &StudyInfo,
) -> Result<String> {
    let best = c.optimum();
    let misfit = format!("RMS of simulated − measured [{}]", cx.unit);
    let summary = Summary {
        title: &cx.title,
        command: &cx.command,
        measurements: &cx.measurements,
        misfit: misfit.clone(),
        params: c
            .params
            .iter()
            .zip(&cx.fields)
            .map(|(p, f)| ParamSummary {
                name: &p.name,
                fields: f,
                lo: p.lo,
                hi: p.hi,
                start: p.start,
                scale: if p.log { "log" } else { "linear" },
            })
            .collect(),
        optimum: best.x.clone(),
        min_misfit: best.misfit,
        tolerance: cx.tol,
        range: r,
        evaluations: c.evaluations.len(),
        evaluations_without_misfit: c
            .evaluations
            .iter()
            .filter(|e| !e.misfit.is_finite())
            .count(),
    };
    let json = dir.join("summary.json");
    std::fs::write(&json, serde_json::to_string_pretty(&summary)? + "\n")
        .with_context(|| format!("writing {}", json.display()))?;
    let mut md = format!("# Calibration: {}\n\n", cx.title);
    md.push_str(&format!("Command: `{}`\n\n", cx.command));
    md.push_str(&format!(
        "Measurements: {}. Misfit: {misfit}.\n\n",
        cx.measurements
    ));
    md.push_str(
        "| parameter | case fields | bounds | start | optimum | range within tolerance |\n",
    );
    md.push_str("|---|---|---|---|---|---|\n");
    for (d, p) in c.params.iter().enumerate() {
        let (lo, hi) = r.bounds[d];
        let open = |b: bool| {
            if b || c.params.len() == 2 {
                ""
            } else {
                " (not bracketed)"
            }
        };
        md.push_str(&format!(
            "| {} | {} | [{}, {}]{} | {} | {} | {}{} – {}{} |\n",
            p.name,
            cx.fields[d].join(", "),
            p.lo,
            p.hi,
            if p.log { " log" } else { "" },
            p.start,
            number(best.x[d]),
            number(lo),
            open(r.bracketed.0),
            number(hi),
            open(r.bracketed.1),
        ));
    }
    md.push_str(&format!(
        "\nMinimum misfit {} {}; tolerance range: misfit ≤ (1 + {}) × min = {} ({}).{}\n",
        number(best.misfit),
        cx.unit,
        cx.tol,
        number(r.threshold),
        r.method,
        if r.elsewhere > 0 {
            format!(
                " {} evaluation(s) outside the range are within the threshold too (another \
                 valley).",
                r.elsewhere
            )
        } else {
            String::new()
        }
    ));
    for (p, x) in c.params.iter().zip(&best.x) {
        if *x == p.lo || *x == p.hi {
            md.push_str(&format!(
                "\nThe optimum lies on a bound of {} ({x}): the minimum may lie beyond it; \
                 widen the bounds to find it.\n",
                p.name
            ));
        }
    }
    md.push_str(&format!(
        "\n{} evaluations ({} without a misfit): evaluations.csv; landscape: landscape.svg.\n",
        summary.evaluations, summary.evaluations_without_misfit
    ));
    let path = dir.join("summary.md");
    std::fs::write(&path, &md).with_context(|| format!("writing {}", path.display()))?;
    Ok(md)
}

/// The axis coordinate of `v` (log10 on a log scale) and its label.
fn axis(p: &Param, v: f64) -> f64 {
    if p.log {
        v.log10()
    } else {
        v
    }
}

fn axis_label(p: &Param) -> String {
    if p.log {
        format!("log10 {}", p.name)
    } else {
        p.name.clone()
    }
}

/// Draws the misfit landscape: misfit against the parameter (1-D) or a heat map of the scan
/// grid (2-D).
pub fn draw(path: &Path, c: &Calibration, r: &ToleranceRange, cx: &StudyInfo) -> Result<()> {
    let best = c.optimum();
    if c.params.len() == 1 {
        let p = &c.params[0];
        let mut pts: Vec<(f64, f64)> = c
            .evaluations
            .iter()
            .filter(|e| e.misfit.is_finite())
            .map(|e| (axis(p, e.x[0]), e.misfit))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let panel = Panel {
            title: cx.title.clone(),
            x_label: axis_label(p),
            y_label: format!("misfit [{}]", cx.unit),
            series: vec![
                Series {
                    label: "evaluations".into(),
                    points: pts,
                    colour: 0,
                    mark: Mark::LineAndDots,
                },
                Series {
                    label: "optimum".into(),
                    points: vec![(axis(p, best.x[0]), best.misfit)],
                    colour: BLACK_INDEX,
                    mark: Mark::Squares,
                },
            ],
            vertical: vec![
                (axis(p, r.bounds[0].0), "range".into()),
                (axis(p, r.bounds[0].1), String::new()),
            ],
            horizontal: vec![(r.threshold, format!("(1 + {}) min", cx.tol))],
            y_from_zero: true,
        };
        return plots::draw(path, &[panel], 1);
    }
    // the scan grid: rows the second parameter (high at the top), columns the first
    let grid = |d: usize| {
        let mut v: Vec<f64> = c
            .evaluations
            .iter()
            .filter(|e| e.stage == super::optimise::Stage::Scan)
            .map(|e| e.x[d])
            .collect();
        v.sort_by(f64::total_cmp);
        v.dedup();
        v
    };
    let (xs, mut ys) = (grid(0), grid(1));
    ys.reverse();
    let cell = |x: f64, y: f64| {
        let e = c.evaluations.iter().find(|e| e.x == [x, y]);
        let value = e.map(|e| e.misfit).filter(|m| m.is_finite());
        HeatCell {
            value,
            label: value.map_or("—".into(), |m| format!("{m:.3}")),
        }
    };
    let map = Heatmap {
        title: format!(
            "{}: misfit [{}], columns: {}",
            cx.title, cx.unit, c.params[0].name
        ),
        rows: ys
            .iter()
            .map(|y| format!("{} = {y:.4}", c.params[1].name))
            .collect(),
        columns: xs.iter().map(|x| format!("{x:.4}")).collect(),
        cells: ys
            .iter()
            .map(|&y| xs.iter().map(|&x| cell(x, y)).collect())
            .collect(),
        note: format!(
            "optimum ({:.4}, {:.4}): {:.4}",
            best.x[0], best.x[1], best.misfit
        ),
    };
    plots::draw_heatmap(path, &map)
}

#[cfg(test)]
mod tests {
    use super::super::optimise::{calibrate, Settings};
    use super::*;

    fn param(lo: f64, hi: f64) -> Param {
        Param {
            name: "a".into(),
            lo,
            hi,
            start: lo,
            log: false,
        }
    }

    #[test]
    fn the_tolerance_range_of_a_known_parabola() {
        // misfit 1 + (x − 2)²: within 10 % of the minimum for |x − 2| ≤ √0.1
        let f = |x: &[f64]| 1.0 + (x[0] - 2.0).powi(2);
        let s = Settings {
            scan: 81,
            refine: 0,
            jobs: 1,
            xtol: 1e-6,
            ftol: 1e-12,
        };
        let c = calibrate(&[param(0.0, 4.0)], &f, &s).unwrap();
        let r = tolerance_range(&c, 0.1);
        assert!((r.threshold - 1.1).abs() < 1e-12);
        let (lo, hi) = r.bounds[0];
        assert!((lo - (2.0 - 0.1f64.sqrt())).abs() < 2e-3, "{lo}");
        assert!((hi - (2.0 + 0.1f64.sqrt())).abs() < 2e-3, "{hi}");
        assert_eq!(r.bracketed, (true, true));
        assert_eq!(r.elsewhere, 0);
        // a range that reaches a bound is not bracketed there
        let c = calibrate(&[param(1.9, 4.0)], &f, &s).unwrap();
        let r = tolerance_range(&c, 0.1);
        assert_eq!(r.bounds[0].0, 1.9);
        assert_eq!(r.bracketed, (false, true));
    }

    #[test]
    fn the_2d_range_is_a_box_and_outputs_are_written() {
        let f = |x: &[f64]| 1.0 + x[0].powi(2) + (x[1] / 2.0).powi(2);
        let mut b = param(-2.0, 2.0);
        b.name = "b".into();
        let s = Settings {
            scan: 5,
            refine: 20,
            jobs: 2,
            xtol: 1e-6,
            ftol: 1e-12,
        };
        let c = calibrate(&[param(-1.0, 1.0), b], &f, &s).unwrap();
        let r = tolerance_range(&c, 0.3);
        assert!(r.bounds[0].0 <= 0.0 && r.bounds[0].1 >= 0.0);
        assert!(r.bounds[1].0 >= -2.0 && r.bounds[1].1 <= 2.0);
        let dir = std::env::temp_dir().join(format!("runout-calibrate-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let cx = StudyInfo {
            title: "test".into(),
            measurements: "none".into(),
            unit: "m/s",
            tol: 0.3,
            command: "cargo xtask calibrate".into(),
            fields: vec![vec!["a".into()], vec!["b".into()]],
        };
        write_csv(&dir.join("evaluations.csv"), &c).unwrap();
        let md = write_summary(&dir, &c, &r, &cx).unwrap();
        assert!(md.contains("| a |"));
        draw(&dir.join("landscape.svg"), &c, &r, &cx).unwrap();
        let csv = std::fs::read_to_string(dir.join("evaluations.csv")).unwrap();
        assert_eq!(csv.lines().count(), c.evaluations.len() + 1);
        assert!(dir.join("landscape.svg").exists() && dir.join("summary.json").exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
