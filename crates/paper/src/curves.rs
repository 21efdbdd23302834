//! The curve figures of the report: station profiles (paper Figs. 4, 5, 7, 8, 13, 14), the
//! floor probe's h_w^u against time (Fig. 9) and the flume's gate speeds and front
//! (Fig. 12).

use std::path::Path;

use anyhow::Result;
use runout_case::Fidelity;
use runout_post::gates::DescribedGate;

use super::coverage::{coverage, figure_section, legend, remove_stale};
use super::figure_sets::{ProfileFigure, FLUME, PROBE_CURVES};
use super::paper::CUSHION_LIMIT_H_U;
use super::plots::{self, Mark, Panel, Series};
use runout_post::case_data::Cases;
use runout_post::metrics::PROFILE_TIME;
use runout_post::profile::Profile;

/// Fraction of a profile's peak εs that still counts as solids when sizing the plot.
const VISIBLE_FRACTION: f64 = 0.01;

/// The height of the highest cell centre whose εs is at least [`VISIBLE_FRACTION`] of the
/// profile's peak; `None` without solids.
fn solids_top(p: &Profile) -> Option<f64> {
    let peak = p.eps_s.iter().copied().fold(0.0, f64::max);
    (peak > 0.0)
        .then(|| {
            p.y.iter()
                .zip(&p.eps_s)
                .filter(|(_, &e)| e >= VISIBLE_FRACTION * peak)
                .map(|(&y, _)| y)
                .fold(f64::NEG_INFINITY, f64::max)
        })
        .filter(|y| y.is_finite())
}

pub(super) fn draw_profile_figure(
    md: &mut String,
    fig: &ProfileFigure,
    cases: &Cases,
    out: &Path,
) -> Result<()> {
    let cov = coverage(
        cases,
        fig.rows.iter().flat_map(|r| r.curves.iter().map(|c| c.0)),
        |d| d.profile.as_ref().map(|_| ()).map_err(Clone::clone),
    );
    let path = out.join(fig.file);
    let title = format!(
        "Fig. {} — station profiles at t = {PROFILE_TIME} s",
        fig.number
    );
    let caption = format!(
        "Paper Fig. {}: {}. Profiles at the station x = 11 m (5.5 m downstream of the release) at \
         t = {PROFILE_TIME} s against the distance from the floor (profile_x11_t1.25.csv of each \
         run).{}",
        fig.number,
        fig.what,
        cov.caption()
    );
    if cov.is_empty() {
        remove_stale(&path)?;
        figure_section(md, &title, None, &caption);
        return Ok(());
    }
    let mut panels = Vec::new();
    for (r, row) in fig.rows.iter().enumerate() {
        // the vertical range: 1.3 × the highest solids of the row (εs ≥ 1 % of the profile's
        // peak), the whole profile if none
        let profiles: Vec<(String, Profile, Option<Fidelity>)> = row
            .curves
            .iter()
            .filter_map(|(case, label)| {
                let d = cases.get(case);
                let p = d.profile.as_ref().ok()?.clone();
                Some((label.to_string(), p, d.fidelity()))
            })
            .collect();
        let top = profiles
            .iter()
            .filter_map(|(_, p, _)| solids_top(p))
            .fold(0.0_f64, f64::max);
        let y_max = (top > 0.0).then_some(1.3 * top);
        for (v, var) in fig.vars.iter().enumerate() {
            let letter = (b'a' + (r * fig.vars.len() + v) as u8) as char;
            panels.push(Panel {
                title: format!("({letter}) {}", row.title),
                x_label: var.axis().into(),
                y_label: "distance from the floor [m]".into(),
                series: profiles
                    .iter()
                    .enumerate()
                    .map(|(k, (label, p, f))| Series {
                        label: legend(label, *f),
                        points: var
                            .values(p)
                            .iter()
                            .copied()
                            .zip(p.y.iter().copied())
                            .filter(|&(_, y)| y_max.is_none_or(|m| y <= m))
                            .collect(),
                        colour: k,
                        mark: Mark::LineAndDots,
                    })
                    .collect(),
                vertical: Vec::new(),
                horizontal: Vec::new(),
                y_from_zero: true,
            });
        }
    }
    plots::draw(&path, &panels, fig.vars.len())?;
    figure_section(md, &title, Some(fig.file), &caption);
    Ok(())
}

pub(super) fn draw_probe_figure(md: &mut String, cases: &Cases, out: &Path) -> Result<()> {
    let file = "fig9.svg";
    let cov = coverage(cases, PROBE_CURVES.iter().map(|c| c.0), |d| {
        d.probe.as_ref().map(|_| ()).map_err(Clone::clone)
    });
    let title = "Fig. 9 — h_w^u at the floor probe against time";
    let caption = format!(
        "Paper Fig. 9: h_w^u of the floor face at x = 11 m against time, d = 0.5 mm, for the \
         state-dependent floor conditions (JJ = Johnson–Jackson); dashed: the paper's limit of \
         air-cushion formation, h_w^u = {CUSHION_LIMIT_H_U} m⁻¹ (wall_probe_south_x11.csv of each \
         run).{}",
        cov.caption()
    );
    let path = out.join(file);
    if cov.is_empty() {
        remove_stale(&path)?;
        figure_section(md, title, None, &caption);
        return Ok(());
    }
    let series = PROBE_CURVES
        .iter()
        .enumerate()
        .filter_map(|(k, (case, label))| {
            let d = cases.get(case);
            Some(Series {
                label: legend(label, d.fidelity()),
                points: d.probe.as_ref().ok()?.clone(),
                colour: k,
                mark: Mark::Line,
            })
        })
        .collect();
    let panel = Panel {
        title: "h_w^u at x = 11 m, d = 0.5 mm".into(),
        x_label: "t [s]".into(),
        y_label: "h_w^u [1/m]".into(),
        series,
        vertical: Vec::new(),
        horizontal: vec![(CUSHION_LIMIT_H_U, "air-cushion limit 70 1/m".into())],
        y_from_zero: true,
    };
    plots::draw(&path, &[panel], 1)?;
    figure_section(md, title, Some(file), &caption);
    Ok(())
}

pub(super) fn draw_flume_figure(
    md: &mut String,
    cases: &Cases,
    gates: &[DescribedGate],
    out: &Path,
) -> Result<()> {
    let file = "fig12.svg";
    let cov = coverage(cases, FLUME.iter().map(|c| c.0), |d| {
        d.gates.as_ref().map_err(Clone::clone).and_then(|g| {
            if g.is_empty() {
                Err(d.no_gate_reached())
            } else {
                Ok(())
            }
        })
    });
    let front_cov = coverage(cases, FLUME.iter().map(|c| c.0), |d| {
        d.front.as_ref().map(|_| ()).map_err(Clone::clone)
    });
    let title = "Fig. 12 — flume front speed at the gates";
    let caption = format!(
        "Paper Fig. 12: front speed as the front crosses each laser gate, against the gate's \
         distance from the channel inlet (gates.csv of each run); black squares: the speeds the \
         paper *describes* for the experiment (cases/flume/gates.csv: no measured values are in \
         the paper's text); dotted: the gates L1–L7. Panel (b), not in the paper: the front \
         position against time (front.csv: where the floor row's εs falls through 0.01, \
         interpolated between cell centres), from which the gate speeds are taken by central \
         differences.{} Panel (b):{}",
        cov.caption(),
        front_cov.caption()
    );
    let path = out.join(file);
    if cov.is_empty() && front_cov.is_empty() {
        remove_stale(&path)?;
        figure_section(md, title, None, &caption);
        return Ok(());
    }
    let distance = |g: usize| gates.iter().find(|r| r.gate == g).map(|r| r.distance);
    let mut speed_series: Vec<Series> = FLUME
        .iter()
        .enumerate()
        .filter_map(|(k, (case, label, _))| {
            let d = cases.get(case);
            let g = d.gates.as_ref().ok()?;
            Some(Series {
                label: legend(label, d.fidelity()),
                points: g
                    .iter()
                    .filter_map(|g| Some((distance(g.gate)?, g.speed)))
                    .collect(),
                colour: k,
                mark: Mark::LineAndDots,
            })
        })
        .filter(|s| !s.points.is_empty())
        .collect();
    speed_series.push(Series {
        label: "described (paper text)".into(),
        points: gates
            .iter()
            .filter_map(|g| Some((g.distance, g.speed?)))
            .collect(),
        colour: plots::BLACK_INDEX,
        mark: Mark::Squares,
    });
    let vertical: Vec<(f64, String)> = gates
        .iter()
        .map(|g| (g.distance, format!("L{}", g.gate)))
        .collect();
    let front_series = FLUME
        .iter()
        .enumerate()
        .filter_map(|(k, (case, label, _))| {
            let d = cases.get(case);
            let origin = d.gate_origin.unwrap_or(0.0);
            Some(Series {
                label: legend(label, d.fidelity()),
                points: d
                    .front
                    .as_ref()
                    .ok()?
                    .iter()
                    // a front at the domain's start (x = 0) means no solids on the floor yet
                    .filter(|&&(_, x)| x > 0.0)
                    .map(|&(t, x)| (t, x - origin))
                    .collect(),
                colour: k,
                mark: Mark::Line,
            })
        })
        .collect();
    let panels = [
        Panel {
            title: "(a) front speed at the gates".into(),
            x_label: "distance from the channel inlet [m]".into(),
            y_label: "front speed [m/s]".into(),
            series: speed_series,
            vertical: vertical.clone(),
            horizontal: Vec::new(),
            y_from_zero: true,
        },
        Panel {
            title: "(b) front position".into(),
            x_label: "t [s]".into(),
            y_label: "front, distance from the channel inlet [m]".into(),
            series: front_series,
            vertical: Vec::new(),
            horizontal: vertical,
            y_from_zero: false,
        },
    ];
    plots::draw(&path, &panels, 2)?;
    figure_section(md, title, Some(file), &caption);
    Ok(())
}
