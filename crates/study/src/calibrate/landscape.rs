//! The outputs of a calibration: the evaluations as CSV, the χ² landscape as SVG with the
//! range Δχ² ≤ 1 ([`super::uncertainty`]), and a Markdown and a JSON summary.

use std::path::Path;

use anyhow::{Context, Result};
use serde::Serialize;

use super::optimise::{Calibration, Param};
use super::scatter::{self, Scatter};
use super::uncertainty::Range;
use crate::plots::{self, HeatCell, Heatmap, Mark, Panel, Series, BLACK_INDEX};
use crate::sweep::csv_field;

/// What the outputs say about the study besides the calibration.
pub struct StudyInfo<'a> {
    /// title: case, fidelity
    pub title: String,
    /// the measurements: file and what it holds
    pub measurements: String,
    /// the measurement's unit
    pub unit: &'a str,
    /// where σ came from
    pub sigma: String,
    /// the number of measured points
    pub points: usize,
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
    text.push_str(",chi2,rms,note\n");
    let cell = |v: f64| {
        if v.is_finite() {
            format!("{v:e}")
        } else {
            String::new()
        }
    };
    for (k, e) in c.evaluations.iter().enumerate() {
        text.push_str(&format!("{k},{}", e.stage.name()));
        for x in &e.x {
            text.push_str(&format!(",{x:e}"));
        }
        text.push_str(&format!(
            ",{},{},{}\n",
            cell(e.chi2),
            cell(e.rms),
            csv_field(&e.note)
        ));
    }
    std::fs::write(path, text).with_context(|| format!("writing {}", path.display()))
}

/// The summary as JSON.
#[derive(Serialize)]
struct Summary<'a> {
    title: &'a str,
    command: &'a str,
    measurements: &'a str,
    sigma: &'a str,
    misfit: String,
    params: Vec<ParamSummary<'a>>,
    optimum: Vec<f64>,
    min_chi2: f64,
    rms_at_optimum: f64,
    reduced_chi2: f64,
    range: &'a Range,
    model_scatter: Option<Scatter>,
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

/// χ²_min / (n − p): near 1 if the model fits within σ.
fn reduced_chi2(c: &Calibration, points: usize) -> f64 {
    let dof = points.saturating_sub(c.params.len());
    if dof == 0 {
        f64::NAN
    } else {
        c.optimum().chi2 / dof as f64
    }
}

/// The summary's line on the model's scatter between neighbouring runs ([`scatter`]);
/// `smoothed`: the stated range includes the smooth response's ([`super::smooth`]).
fn scatter_note(s: Option<&Scatter>, cx: &StudyInfo, smoothed: bool) -> String {
    let Some(s) = s else {
        return format!(
            "\nThe model's scatter: no two evaluations within {} of each other (unit \
             coordinates) to measure it.\n",
            scatter::CLOSE
        );
    };
    let measured = format!(
        "\nThe model's scatter between neighbouring runs ({} pairs at most {:.3} apart in unit \
         coordinates): σ_model = {:.2} σ ({}).",
        s.pairs, s.widest, s.ratio, cx.sigma
    );
    if s.reliable() {
        format!("{measured}\n")
    } else if smoothed {
        format!(
            "{measured} Above {:.2} σ the evaluations' own χ² is not reliable (its minimum sits \
             on a favourable wiggle); the stated range is widened to the smooth response's, \
             which allows for the scatter (below).\n",
            scatter::RELIABLE_RATIO
        )
    } else {
        format!(
            "{measured} **Above {:.2} σ: the range is not reliable.** χ² moves by about 2 × {:.2} \
             √n between runs that differ only by the grid's wiggle, so its minimum sits on a \
             favourable wiggle; a σ of at least 3 σ_model ({:.2} × the σ used) is one the \
             scatter does not dominate, or a finer fidelity scatters less.\n",
            scatter::RELIABLE_RATIO,
            s.ratio,
            3.0 * s.ratio
        )
    }
}

/// The summary's lines on the smooth response ([`super::smooth`]); empty without one.
fn smooth_note(r: &Range) -> String {
    let Some(s) = &r.smooth else {
        return String::new();
    };
    let mut md = format!(
        "\nThe model's scatter about its smooth trend (local quadratic regression over {} \
         evaluations, its window's half-width {} of the bounds chosen by cross-validation, \
         calibrate/smooth.rs): σ_model = {:.2} σ pooled, up to {:.2} σ at one measured point, \
         a wiggle that decorrelates over any distance shorter than the window. The stated \
         range includes it: the smooth response's range, with σ_eff,i = σ_i √(1 + s_i²), is \
         {} – {}.\n",
        s.evaluations,
        s.half_width,
        s.scatter,
        s.scatter_max,
        number(s.bounds.0),
        number(s.bounds.1)
    );
    if s.scatter_max > scatter::RELIABLE_RATIO {
        md.push_str(&format!(
            "\nAbove {:.2} σ the scatter (or the trend's curvature over the window, which \
             counts as scatter) is comparable to σ: a run's outputs then jump between \
             neighbouring parameter values by as much as the measurements' error, the \
             measured run itself is one such draw, and the stated range is a guide, not a \
             68 % interval. A σ of at least 3 σ_model ({:.2} × the σ used), or a finer \
             fidelity, is one the scatter does not dominate.\n",
            scatter::RELIABLE_RATIO,
            3.0 * s.scatter_max
        ));
    }
    md
}

/// The summary's note for each parameter whose optimum lies on a bound.
fn bound_notes(c: &Calibration) -> String {
    c.params
        .iter()
        .zip(&c.optimum().x)
        .filter(|(p, x)| **x == p.lo || **x == p.hi)
        .map(|(p, x)| {
            format!(
                "\nThe optimum lies on a bound of {} ({x}): the minimum may lie beyond it; \
                 widen the bounds to find it.\n",
                p.name
            )
        })
        .collect()
}

/// Writes summary.json and summary.md; returns the Markdown.
pub fn write_summary(dir: &Path, c: &Calibration, r: &Range, cx: &StudyInfo) -> Result<String> {
    let best = c.optimum();
    let misfit = format!(
        "χ² = Σ (simulated − measured)²/σ² over {} points; RMS of simulated − measured [{}]",
        cx.points, cx.unit
    );
    let reduced = reduced_chi2(c, cx.points);
    let summary = Summary {
        title: &cx.title,
        command: &cx.command,
        measurements: &cx.measurements,
        sigma: &cx.sigma,
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
        min_chi2: best.chi2,
        rms_at_optimum: best.rms,
        reduced_chi2: reduced,
        range: r,
        model_scatter: scatter::of(c),
        evaluations: c.evaluations.len(),
        evaluations_without_misfit: c.evaluations.iter().filter(|e| !e.chi2.is_finite()).count(),
    };
    let json = dir.join("summary.json");
    std::fs::write(&json, serde_json::to_string_pretty(&summary)? + "\n")
        .with_context(|| format!("writing {}", json.display()))?;
    let mut md = format!("# Calibration: {}\n\n", cx.title);
    md.push_str(&format!("Command: `{}`\n\n", cx.command));
    md.push_str(&format!(
        "Measurements: {}; {}. Misfit: {misfit}.\n\n",
        cx.measurements, cx.sigma
    ));
    md.push_str(&format!(
        "| parameter | case fields | bounds | start | optimum | range Δχ² ≤ {} |\n",
        r.delta_chi2
    ));
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
        "\nχ²_min {} (RMS {} {}), χ²_min/(n − p) = {}; the range: χ² ≤ χ²_min + {} = {} ({}).{}\n",
        number(best.chi2),
        number(best.rms),
        cx.unit,
        number(reduced),
        r.delta_chi2,
        number(r.threshold),
        r.method,
        if r.elsewhere > 0 {
            format!(
                " {} evaluation(s) within the threshold lie in another valley than the \
                 minimum's; the range spans them.",
                r.elsewhere
            )
        } else {
            String::new()
        }
    ));
    if reduced > 2.0 {
        md.push_str(&format!(
            "\nχ²_min/(n − p) = {reduced:.1} > 2: the model does not fit the measurements within \
             σ, and the range understates the uncertainty (with σ scaled by √{reduced:.1} it \
             would be wider).\n"
        ));
    }
    md.push_str(&scatter_note(
        summary.model_scatter.as_ref(),
        cx,
        r.smooth.is_some(),
    ));
    md.push_str(&smooth_note(r));
    md.push_str(&bound_notes(c));
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

/// Draws the landscape: χ² against the parameter with the range (1-D) or a heat map of the
/// scan grid's χ² (2-D).
pub fn draw(path: &Path, c: &Calibration, r: &Range, cx: &StudyInfo) -> Result<()> {
    let best = c.optimum();
    if c.params.len() == 1 {
        let p = &c.params[0];
        let mut pts: Vec<(f64, f64)> = c
            .evaluations
            .iter()
            .filter(|e| e.chi2.is_finite())
            .map(|e| (axis(p, e.x[0]), e.chi2))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        let panel = Panel {
            title: cx.title.clone(),
            x_label: axis_label(p),
            y_label: format!("χ² ({})", cx.sigma),
            series: vec![
                Series {
                    label: "evaluations".into(),
                    points: pts,
                    colour: 0,
                    mark: Mark::LineAndDots,
                },
                Series {
                    label: "optimum".into(),
                    points: vec![(axis(p, best.x[0]), best.chi2)],
                    colour: BLACK_INDEX,
                    mark: Mark::Squares,
                },
            ],
            vertical: vec![
                (axis(p, r.bounds[0].0), "range".into()),
                (axis(p, r.bounds[0].1), String::new()),
            ],
            horizontal: vec![(r.threshold, format!("min + {}", r.delta_chi2))],
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
        let value = e.map(|e| e.chi2).filter(|m| m.is_finite());
        HeatCell {
            value,
            label: value.map_or("—".into(), |m| format!("{m:.3}")),
        }
    };
    let map = Heatmap {
        title: format!(
            "{}: χ² ({}), columns: {}",
            cx.title, cx.sigma, c.params[0].name
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
            "optimum ({:.4}, {:.4}): χ² {:.4}",
            best.x[0], best.x[1], best.chi2
        ),
    };
    plots::draw_heatmap(path, &map)
}

#[cfg(test)]
mod tests {
    use super::super::optimise::{calibrate, Model, Outcome, Settings};
    use super::super::uncertainty;
    use super::*;

    /// A test study of six points in m/s with σ = 1, one case field per parameter.
    fn info(fields: &[&str]) -> StudyInfo<'static> {
        StudyInfo {
            title: "test".into(),
            measurements: "none".into(),
            unit: "m/s",
            sigma: "σ = 1".into(),
            points: 6,
            command: "cargo xtask calibrate".into(),
            fields: fields.iter().map(|f| vec![f.to_string()]).collect(),
        }
    }

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
            profile: 0,
            valley: 0,
        };
        let c = calibrate(&[param(-1.0, 1.0), b], &f, &s).unwrap();
        let r = super::super::uncertainty::range(&c);
        assert!(r.bounds[0].0 <= 0.0 && r.bounds[0].1 >= 0.0);
        assert!(r.bounds[1].0 >= -2.0 && r.bounds[1].1 <= 2.0);
        let dir = std::env::temp_dir().join(format!("runout-calibrate-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let cx = info(&["a", "b"]);
        write_csv(&dir.join("evaluations.csv"), &c).unwrap();
        let md = write_summary(&dir, &c, &r, &cx).unwrap();
        assert!(md.contains("| a |"));
        draw(&dir.join("landscape.svg"), &c, &r, &cx).unwrap();
        let csv = std::fs::read_to_string(dir.join("evaluations.csv")).unwrap();
        assert_eq!(csv.lines().count(), c.evaluations.len() + 1);
        assert!(dir.join("landscape.svg").exists() && dir.join("summary.json").exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// A model whose outputs wiggle by 0.5 σ from run to run: the summary measures the
    /// scatter from Brent's clustered runs, says the runs' own χ² is not reliable and states
    /// the smooth response's range, which contains the truth 0.3 where the runs' own range
    /// need not; a smooth model is said to be reliable and its range is the exact one.
    #[test]
    fn the_summary_states_the_model_scatter() {
        struct Wiggly(f64);
        impl Model for Wiggly {
            fn evaluate(&self, x: &[f64]) -> Result<Outcome> {
                let wiggle = |i: usize| self.0 * ((x[0] * 7919.0 + i as f64 * 13.0).sin());
                let residuals: Vec<f64> = (0..6).map(|i| (x[0] - 0.3) * 10.0 + wiggle(i)).collect();
                Ok(Outcome {
                    chi2: residuals.iter().map(|r| r * r).sum(),
                    rms: f64::NAN,
                    note: String::new(),
                    residuals,
                })
            }
        }
        let cx = info(&["a"]);
        let settings = Settings {
            scan: 5,
            refine: 12,
            jobs: 1,
            xtol: 0.002,
            ftol: 0.05,
            profile: 2,
            valley: 0,
        };
        let dir = std::env::temp_dir().join(format!("runout-scatter-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        for (amplitude, reliable) in [(0.7, false), (0.0, true)] {
            let c = calibrate(&[param(0.0, 1.0)], &Wiggly(amplitude), &settings).unwrap();
            let s = scatter::of(&c).expect("Brent clusters its runs");
            assert_eq!(s.reliable(), reliable, "{s:?}");
            let r = uncertainty::range(&c);
            let md = write_summary(&dir, &c, &r, &cx).unwrap();
            assert!(
                md.contains("The model's scatter between neighbouring runs"),
                "{md}"
            );
            assert_eq!(md.contains("is not reliable"), !reliable, "{md}");
            assert!(
                md.contains("The model's scatter about its smooth trend"),
                "{md}"
            );
            let (lo, hi) = r.bounds[0];
            assert!(lo <= 0.3 && 0.3 <= hi, "{r:?}");
            if reliable {
                // χ² = 6 × 100 (x − 0.3)²: Δχ² ≤ 1 for |x − 0.3| ≤ 1/√600
                let half = 1.0 / 600f64.sqrt();
                assert!(
                    (lo - (0.3 - half)).abs() < 2e-3 && (hi - (0.3 + half)).abs() < 2e-3,
                    "{r:?}"
                );
            }
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
