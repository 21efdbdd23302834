//! Paper Figs. 6 and 10: maps of the gas volume fraction εg = 1 − εs near the floor around
//! the station, at the station time, one panel per case; the station (x = 11 m) dotted.
//!
//! Each map is the run's `fields_*.vtr` listed in `fields.pvd` nearest the station time
//! (every S run writes one at its end time, which is the station time); a field further than
//! [`TIME_TOLERANCE`] from it is refused with the reason. The window is fixed
//! ([`WINDOW_X`], [`WINDOW_Y`]) so that panels of different cases and fidelities compare;
//! the vertical scale is stretched (the flow is a few cm thick over several m).

use std::path::Path;

use anyhow::Result;
use plotters::prelude::*;
use runout_output::{read_vtr_array, read_vtr_cells};
use runout_post::fields::{field_files, nearest};

use super::coverage::{figure_section, legend, remove_stale, Coverage};
use super::figure_sets::FieldFigure;
use runout_post::case_data::Cases;
use runout_post::chosen::Run;
use runout_study::plots::plot_error;

/// Along-slope window of the maps [m]: from behind the release to past the furthest front.
pub const WINDOW_X: (f64, f64) = (5.5, 15.0);
/// Height above the floor shown [m].
pub const WINDOW_Y: (f64, f64) = (0.0, 0.08);
/// A field more than this far from the asked time is not used [s].
pub const TIME_TOLERANCE: f64 = 0.01;
/// The station, dotted [m].
const STATION_X: f64 = 11.0;
/// Lowest εg of the colour scale (a packed bed is ≈ 0.37).
const EPS_G_MIN: f64 = 0.35;
/// Colour steps of the scale (cells in one step and one row are drawn as one rectangle).
const STEPS: usize = 26;
/// The colour scale from dense (εg = [`EPS_G_MIN`]) to gas (εg = 1): viridis at five stops.
const SCALE: [RGBColor; 5] = [
    RGBColor(68, 1, 84),
    RGBColor(59, 82, 139),
    RGBColor(33, 145, 140),
    RGBColor(94, 201, 98),
    RGBColor(253, 231, 37),
];
/// Size of one panel [px].
const PANEL: (u32, u32) = (900, 150);
/// Height of the colour bar strip [px].
const BAR_HEIGHT: u32 = 70;

/// εg of one run at one time, on the grid's cells (x fastest).
#[derive(Clone, Debug)]
pub struct GasMap {
    /// the field's time [s]
    pub time: f64,
    /// cell faces in x [m]
    pub x: Vec<f64>,
    /// cell faces in y [m]
    pub y: Vec<f64>,
    /// εg of each cell, index i + nx·j
    pub eps_g: Vec<f64>,
}

/// The εg map of `run` nearest `time`, or why there is none.
pub fn gas_map(run: &Run, time: f64) -> Result<GasMap, String> {
    let read = |name: &str| {
        std::fs::read_to_string(run.dir.join(name))
            .map_err(|e| format!("the {} run's {name}: {e}", run.fidelity))
    };
    let entries =
        field_files(&run.dir).map_err(|e| format!("the {} run's fields.pvd: {e}", run.fidelity))?;
    let (field_time, file) = nearest(&entries, time)
        .ok_or_else(|| format!("the {} run's fields.pvd lists no field", run.fidelity))?;
    if (field_time - time).abs() > TIME_TOLERANCE {
        return Err(format!(
            "the {} run has no field at t = {time:.3} s (nearest: {field_time:.3} s)",
            run.fidelity
        ));
    }
    let xml = read(file)?;
    let missing = |what: &str| format!("{file} of the {} run: no {what}", run.fidelity);
    let (nx, ny) = read_vtr_cells(&xml).ok_or_else(|| missing("extent"))?;
    let x = read_vtr_array(&xml, "x").ok_or_else(|| missing("x coordinates"))?;
    let y = read_vtr_array(&xml, "y").ok_or_else(|| missing("y coordinates"))?;
    let eps_s = read_vtr_array(&xml, "eps_s").ok_or_else(|| missing("eps_s"))?;
    if x.len() != nx + 1 || y.len() != ny + 1 || eps_s.len() != nx * ny {
        return Err(missing("consistent sizes"));
    }
    Ok(GasMap {
        time: *field_time,
        x,
        y,
        eps_g: eps_s.iter().map(|e| 1.0 - e).collect(),
    })
}

/// Draws `fig` from the runs of `cases` into `out` and writes its section of results.md.
pub fn draw_figure(md: &mut String, fig: &FieldFigure, cases: &Cases, out: &Path) -> Result<()> {
    // each field is read once: for the caption's coverage and for the panels
    let mut cov = Coverage::default();
    let mut panels: Vec<(String, GasMap)> = Vec::new();
    for (case, label) in fig.panels {
        let d = cases.get(case);
        match d
            .run
            .as_ref()
            .map_err(Clone::clone)
            .and_then(|run| gas_map(run, d.station_time))
        {
            Ok(map) => {
                cov.add_drawn(case, d.fidelity());
                panels.push((legend(label, d.fidelity()), map));
            }
            Err(why) => cov.add_missing(case, &why),
        }
    }
    let title = format!("Fig. {} — gas volume fraction near the station", fig.number);
    let caption = format!(
        "Paper Fig. {}: {}. εg = 1 − εs over x = {}–{} m, up to {} m above the floor (the \
         vertical scale stretched), at the station time of each run (1.25 s after the \
         impact for family S; the field of fields.pvd nearest it, its time in each title); \
         dotted: the station x = 11 m where the profiles are taken.{}",
        fig.number,
        fig.what,
        WINDOW_X.0,
        WINDOW_X.1,
        WINDOW_Y.1,
        cov.caption()
    );
    let path = out.join(fig.file);
    if cov.is_empty() {
        remove_stale(&path)?;
        figure_section(md, &title, None, &caption);
        return Ok(());
    }
    draw(&path, &panels)?;
    figure_section(md, &title, Some(fig.file), &caption);
    Ok(())
}

/// The colour of εg on the scale from [`EPS_G_MIN`] to 1, in [`STEPS`] steps.
fn colour(eps_g: f64) -> RGBColor {
    let t = ((eps_g - EPS_G_MIN) / (1.0 - EPS_G_MIN)).clamp(0.0, 1.0);
    let t = (t * (STEPS - 1) as f64).round() / (STEPS - 1) as f64;
    let s = t * (SCALE.len() - 1) as f64;
    let k = (s.floor() as usize).min(SCALE.len() - 2);
    let w = s - k as f64;
    let mix = |a: u8, b: u8| (a as f64 + w * (b as f64 - a as f64)).round() as u8;
    let (a, b) = (SCALE[k], SCALE[k + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The cells of one row inside the window, merged where neighbours share a colour:
/// (x from, x to, colour).
fn row_runs(map: &GasMap, j: usize) -> Vec<(f64, f64, RGBColor)> {
    let nx = map.x.len() - 1;
    let mut runs: Vec<(f64, f64, RGBColor)> = Vec::new();
    for i in 0..nx {
        let (x0, x1) = (map.x[i].max(WINDOW_X.0), map.x[i + 1].min(WINDOW_X.1));
        if x1 <= x0 {
            continue;
        }
        let c = colour(map.eps_g[i + nx * j]);
        match runs.last_mut() {
            Some(last) if last.2 == c && last.1 == x0 => last.1 = x1,
            _ => runs.push((x0, x1, c)),
        }
    }
    runs
}

/// Draws one panel per (title, map) and a colour bar into the SVG `path`.
pub fn draw(path: &Path, panels: &[(String, GasMap)]) -> Result<()> {
    let height = PANEL.1 * panels.len() as u32 + BAR_HEIGHT;
    let root = SVGBackend::new(path, (PANEL.0, height)).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let (maps, bar) = root.split_vertically(height - BAR_HEIGHT);
    for ((title, map), area) in panels.iter().zip(maps.split_evenly((panels.len(), 1))) {
        let mut chart = ChartBuilder::on(&area)
            .caption(
                format!("{title}, t = {:.3} s", map.time),
                ("sans-serif", 15),
            )
            .margin(6)
            .x_label_area_size(28)
            .y_label_area_size(56)
            .build_cartesian_2d(WINDOW_X.0..WINDOW_X.1, WINDOW_Y.0..WINDOW_Y.1)
            .map_err(plot_error)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x [m]")
            .y_desc("y [m]")
            .y_labels(3)
            .label_style(("sans-serif", 12))
            .axis_desc_style(("sans-serif", 13))
            .draw()
            .map_err(plot_error)?;
        let ny = map.y.len() - 1;
        for j in 0..ny {
            let (y0, y1) = (map.y[j].max(WINDOW_Y.0), map.y[j + 1].min(WINDOW_Y.1));
            if y1 <= y0 {
                continue;
            }
            chart
                .draw_series(
                    row_runs(map, j)
                        .into_iter()
                        .map(|(x0, x1, c)| Rectangle::new([(x0, y0), (x1, y1)], c.filled())),
                )
                .map_err(plot_error)?;
        }
        let dots = (0..16).map(|k| {
            let y = WINDOW_Y.0 + (WINDOW_Y.1 - WINDOW_Y.0) * (k as f64 + 0.25) / 16.0;
            let dy = (WINDOW_Y.1 - WINDOW_Y.0) / 32.0;
            PathElement::new(
                vec![(STATION_X, y), (STATION_X, y + dy)],
                BLACK.stroke_width(2),
            )
        });
        chart.draw_series(dots).map_err(plot_error)?;
    }
    draw_bar(&bar)
}

/// The colour bar of εg.
fn draw_bar(area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>) -> Result<()> {
    let mut chart = ChartBuilder::on(area)
        .margin_left(62)
        .margin_right(40)
        .margin_top(8)
        .x_label_area_size(36)
        .build_cartesian_2d(EPS_G_MIN..1.0, 0.0..1.0)
        .map_err(plot_error)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .disable_y_axis()
        .x_labels(8)
        .x_label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 14))
        .x_desc("gas volume fraction εg (dotted: the station, x = 11 m)")
        .draw()
        .map_err(plot_error)?;
    let width = (1.0 - EPS_G_MIN) / STEPS as f64;
    chart
        .draw_series((0..STEPS).map(|k| {
            let e0 = EPS_G_MIN + k as f64 * width;
            Rectangle::new(
                [(e0, 0.0), (e0 + width, 1.0)],
                colour(e0 + 0.5 * width).filled(),
            )
        }))
        .map_err(plot_error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map() -> GasMap {
        // 4 × 2 cells: the floor row dense under the first two cells, gas elsewhere
        GasMap {
            time: 1.25,
            x: vec![5.0, 6.0, 7.0, 8.0, 15.0],
            y: vec![0.0, 0.01, 0.1],
            eps_g: vec![0.4, 0.4, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0],
        }
    }

    #[test]
    fn the_scale_runs_from_dense_to_gas_and_is_clipped() {
        assert_eq!(colour(0.0), SCALE[0]);
        assert_eq!(colour(EPS_G_MIN), SCALE[0]);
        assert_eq!(colour(1.0), SCALE[4]);
        assert_eq!(colour(2.0), SCALE[4]);
    }

    #[test]
    fn rows_are_cut_to_the_window_and_merged_by_colour() {
        let m = map();
        let floor = row_runs(&m, 0);
        assert_eq!(
            floor,
            vec![
                (WINDOW_X.0, 7.0, colour(0.4)),
                (7.0, WINDOW_X.1, colour(1.0))
            ]
        );
        assert_eq!(row_runs(&m, 1), vec![(WINDOW_X.0, WINDOW_X.1, colour(1.0))]);
    }
}
