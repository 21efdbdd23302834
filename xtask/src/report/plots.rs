//! SVG panels of the results report (plotters, as `report analytic` draws Fig. 1).

use std::path::Path;

use anyhow::Result;
use plotters::prelude::*;

/// Width of one panel [px].
const PANEL_WIDTH: u32 = 460;
/// Height of one panel [px].
const PANEL_HEIGHT: u32 = 420;

/// Line colours, by series index (the tab10 palette), then black.
const COLOURS: [RGBColor; 11] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
    RGBColor(0, 0, 0),
];

/// The colour index of black (reference data).
pub const BLACK_INDEX: usize = COLOURS.len() - 1;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Mark {
    /// a line
    Line,
    /// a line with a dot at every point
    LineAndDots,
    /// squares only
    Squares,
}

/// One data series of a panel.
pub struct Series {
    /// legend text
    pub label: String,
    /// (x, y) points; non-finite points are skipped
    pub points: Vec<(f64, f64)>,
    /// index into the palette
    pub colour: usize,
    /// how it is drawn
    pub mark: Mark,
}

/// One panel: axes, series and labelled reference lines.
pub struct Panel {
    /// caption above the panel
    pub title: String,
    /// x-axis label
    pub x_label: String,
    /// y-axis label
    pub y_label: String,
    /// the data
    pub series: Vec<Series>,
    /// dotted vertical lines: (x, label)
    pub vertical: Vec<(f64, String)>,
    /// dashed horizontal lines: (y, label)
    pub horizontal: Vec<(f64, String)>,
    /// start the y axis at 0 when all data are positive
    pub y_from_zero: bool,
}

/// The padded range of `values` (unit range around a single value, [0, 1] without any).
pub fn axis_range(values: impl IntoIterator<Item = f64>, from_zero: bool) -> (f64, f64) {
    let (mut lo, mut hi) = values
        .into_iter()
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        return (0.0, 1.0);
    }
    if from_zero && lo >= 0.0 {
        lo = 0.0;
    }
    if hi - lo <= f64::EPSILON * hi.abs().max(1.0) {
        let half = 0.5 * hi.abs().max(1.0);
        return (lo - half, hi + half);
    }
    let pad = 0.05 * (hi - lo);
    if !(from_zero && lo == 0.0) {
        lo -= pad;
    }
    hi += pad;
    (lo, hi)
}

fn colour(k: usize) -> RGBColor {
    if k == BLACK_INDEX {
        COLOURS[BLACK_INDEX]
    } else {
        COLOURS[k % (COLOURS.len() - 1)]
    }
}

/// Draws `panels` in a grid of `columns` into the SVG `path`.
pub fn draw(path: &Path, panels: &[Panel], columns: usize) -> Result<()> {
    let columns = columns.max(1);
    let rows = panels.len().div_ceil(columns).max(1);
    let size = (PANEL_WIDTH * columns as u32, PANEL_HEIGHT * rows as u32);
    let root = SVGBackend::new(path, size).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let areas = root.split_evenly((rows, columns));
    for (panel, area) in panels.iter().zip(areas.iter()) {
        draw_panel(panel, area)?;
    }
    root.present().map_err(plot_error)?;
    Ok(())
}

fn draw_panel(
    panel: &Panel,
    area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
) -> Result<()> {
    let xs = panel
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.0))
        .chain(panel.vertical.iter().map(|v| v.0));
    let ys = panel
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .chain(panel.horizontal.iter().map(|h| h.0));
    let (x0, x1) = axis_range(xs, false);
    let (y0, y1) = axis_range(ys, panel.y_from_zero);
    let title = if panel.series.iter().all(|s| s.points.is_empty()) {
        format!("{} (no data)", panel.title)
    } else {
        panel.title.clone()
    };
    let mut chart = ChartBuilder::on(area)
        .caption(title, ("sans-serif", 15))
        .margin(10)
        .x_label_area_size(38)
        .y_label_area_size(55)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(plot_error)?;
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .x_labels(6)
        .y_labels(8)
        .draw()
        .map_err(plot_error)?;
    let grey = RGBColor(90, 90, 90);
    for (x, label) in &panel.vertical {
        chart
            .draw_series(DashedLineSeries::new(
                [(*x, y0), (*x, y1)],
                2,
                4,
                grey.stroke_width(1),
            ))
            .map_err(plot_error)?;
        chart
            .draw_series(std::iter::once(Text::new(
                label.clone(),
                (*x, y1),
                ("sans-serif", 12).into_font().color(&grey),
            )))
            .map_err(plot_error)?;
    }
    for (y, label) in &panel.horizontal {
        chart
            .draw_series(DashedLineSeries::new(
                [(x0, *y), (x1, *y)],
                6,
                4,
                grey.stroke_width(1),
            ))
            .map_err(plot_error)?;
        chart
            .draw_series(std::iter::once(Text::new(
                label.clone(),
                (x0, *y),
                ("sans-serif", 12).into_font().color(&grey),
            )))
            .map_err(plot_error)?;
    }
    let mut labelled = false;
    for s in &panel.series {
        let c = colour(s.colour);
        let points: Vec<(f64, f64)> = s
            .points
            .iter()
            .copied()
            .filter(|p| p.0.is_finite() && p.1.is_finite())
            .collect();
        if points.is_empty() {
            continue;
        }
        labelled = true;
        let anno =
            match s.mark {
                Mark::Line | Mark::LineAndDots => {
                    if s.mark == Mark::LineAndDots {
                        chart
                            .draw_series(points.iter().map(|&p| Circle::new(p, 3, c.filled())))
                            .map_err(plot_error)?;
                    }
                    chart
                        .draw_series(LineSeries::new(points, c.stroke_width(2)))
                        .map_err(plot_error)?
                }
                Mark::Squares => chart
                    .draw_series(points.iter().map(|&p| {
                        EmptyElement::at(p) + Rectangle::new([(-4, -4), (4, 4)], c.filled())
                    }))
                    .map_err(plot_error)?,
            };
        anno.label(s.label.clone())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
    }
    if labelled {
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(plot_error)?;
    }
    Ok(())
}

fn plot_error<E: std::fmt::Debug>(e: E) -> anyhow::Error {
    anyhow::anyhow!("plotting a results figure: {e:?}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_are_padded_and_never_empty() {
        assert_eq!(axis_range([], false), (0.0, 1.0));
        assert_eq!(axis_range([f64::NAN], true), (0.0, 1.0));
        let (lo, hi) = axis_range([2.0, 2.0], false);
        assert!(lo < 2.0 && hi > 2.0);
        // positive data from zero: no padding below 0, 5 % above
        let (lo, hi) = axis_range([1.0, 3.0], true);
        assert_eq!(lo, 0.0);
        assert!((hi - 3.15).abs() < 1e-12);
        let (lo, hi) = axis_range([-1.0, 1.0], true);
        assert!((lo + 1.1).abs() < 1e-12 && (hi - 1.1).abs() < 1e-12);
    }
}
