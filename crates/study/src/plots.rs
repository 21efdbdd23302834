//! SVG panels and heat maps of the reports and the calibration landscape (plotters).

use std::path::Path;

use anyhow::Result;
use plotters::coord::CoordTranslate;
use plotters::prelude::*;

/// A drawing error of plotters (whose error types are not `std::error::Error` for every
/// backend) as an `anyhow` error.
pub fn plot_error<E: std::fmt::Debug>(e: E) -> anyhow::Error {
    anyhow::anyhow!("plotting a figure: {e:?}")
}

/// Width of one panel [px].
const PANEL_WIDTH: u32 = 460;
/// Height of one panel [px].
const PANEL_HEIGHT: u32 = 420;

/// Line colours, by series index (the tab10 palette), then black; the one palette of the
/// workspace's figures ([`LINE_COLOURS`] picks from it).
pub const COLOURS: [RGBColor; 11] = [
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

/// Line colours, cycled per curve: blue, red, green, purple, orange of [`COLOURS`], then
/// black.
pub const LINE_COLOURS: [RGBColor; 6] = [
    COLOURS[0],
    COLOURS[3],
    COLOURS[2],
    COLOURS[4],
    COLOURS[1],
    COLOURS[BLACK_INDEX],
];

/// Draws the legend of `chart`'s labelled series at `position`, on a white box (80 %
/// opaque) with a black border.
pub fn legend<'a, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    position: SeriesLabelPosition,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
}

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
        legend(&mut chart, SeriesLabelPosition::UpperRight).map_err(plot_error)?;
    }
    Ok(())
}

/// One cell of a [`Heatmap`].
pub struct HeatCell {
    /// the value that sets the colour; `None`: grey
    pub value: Option<f64>,
    /// the text written in the cell
    pub label: String,
}

/// A table of coloured cells: rows × columns, a diverging colour scale symmetric about 0.
pub struct Heatmap {
    /// caption above the table
    pub title: String,
    /// row labels (left)
    pub rows: Vec<String>,
    /// column labels (top)
    pub columns: Vec<String>,
    /// `cells[row][column]`
    pub cells: Vec<Vec<HeatCell>>,
    /// text under the colour bar
    pub note: String,
}

/// Width of the row labels of a heat map [px].
const HEAT_LABEL_WIDTH: i32 = 300;
/// Size of one heat-map cell [px].
const HEAT_CELL: (i32, i32) = (104, 28);
/// Height of the title and column labels above the cells [px].
const HEAT_TOP: i32 = 64;
/// Height of the colour bar and note below the cells [px].
const HEAT_BOTTOM: i32 = 74;
/// Ends of the diverging scale (ColorBrewer RdBu): negative, zero, positive.
const DIVERGING: [RGBColor; 3] = [
    RGBColor(33, 102, 172),
    RGBColor(247, 247, 247),
    RGBColor(178, 24, 43),
];
/// Fill of a cell without a value.
const NO_VALUE: RGBColor = RGBColor(215, 215, 215);

/// The smallest of 1, 2, 5 × 10ᵏ at or above `v` (1 for no positive `v`).
pub fn nice_ceiling(v: f64) -> f64 {
    if !(v > 0.0 && v.is_finite()) {
        return 1.0;
    }
    let decade = 10f64.powf(v.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .iter()
        .map(|m| m * decade)
        .find(|&c| c >= v * (1.0 - 1e-12))
        .unwrap_or(10.0 * decade)
}

/// The colour of `v` on the diverging scale of ±`limit` (clipped beyond it).
pub fn diverging(v: f64, limit: f64) -> RGBColor {
    let t = (v / limit).clamp(-1.0, 1.0);
    let (end, t) = if t < 0.0 {
        (DIVERGING[0], -t)
    } else {
        (DIVERGING[2], t)
    };
    let mix = |a: u8, b: u8| (a as f64 + t * (b as f64 - a as f64)).round() as u8;
    let zero = DIVERGING[1];
    RGBColor(mix(zero.0, end.0), mix(zero.1, end.1), mix(zero.2, end.2))
}

/// Draws `map` into the SVG `path`; the scale is ±the largest |value| rounded up to 1, 2 or
/// 5 × 10ᵏ.
pub fn draw_heatmap(path: &Path, map: &Heatmap) -> Result<()> {
    use plotters::style::text_anchor::{HPos, Pos, VPos};
    let (cw, ch) = HEAT_CELL;
    let n_cols = map.columns.len().max(1) as i32;
    let n_rows = map.rows.len() as i32;
    let width = HEAT_LABEL_WIDTH + cw * n_cols + 20;
    let height = HEAT_TOP + ch * n_rows + HEAT_BOTTOM;
    let limit = nice_ceiling(
        map.cells
            .iter()
            .flatten()
            .filter_map(|c| c.value)
            .filter(|v| v.is_finite())
            .fold(0.0, |m, v| f64::max(m, v.abs())),
    );
    let root = SVGBackend::new(path, (width as u32, height as u32)).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let font = |size: i32, h: HPos| {
        TextStyle::from(("sans-serif", size).into_font()).pos(Pos::new(h, VPos::Center))
    };
    root.draw(&Text::new(
        map.title.clone(),
        (width / 2, 16),
        font(20, HPos::Center),
    ))
    .map_err(plot_error)?;
    for (k, c) in map.columns.iter().enumerate() {
        let x = HEAT_LABEL_WIDTH + cw * k as i32 + cw / 2;
        root.draw(&Text::new(
            c.clone(),
            (x, HEAT_TOP - 14),
            font(16, HPos::Center),
        ))
        .map_err(plot_error)?;
    }
    let white = WHITE;
    for (r, (label, row)) in map.rows.iter().zip(&map.cells).enumerate() {
        let y0 = HEAT_TOP + ch * r as i32;
        root.draw(&Text::new(
            label.clone(),
            (HEAT_LABEL_WIDTH - 8, y0 + ch / 2),
            font(16, HPos::Right),
        ))
        .map_err(plot_error)?;
        for (k, cell) in row.iter().enumerate() {
            let x0 = HEAT_LABEL_WIDTH + cw * k as i32;
            let value = cell.value.filter(|v| v.is_finite());
            let fill = value.map_or(NO_VALUE, |v| diverging(v, limit));
            root.draw(&Rectangle::new(
                [(x0, y0), (x0 + cw, y0 + ch)],
                fill.filled(),
            ))
            .map_err(plot_error)?;
            root.draw(&Rectangle::new(
                [(x0, y0), (x0 + cw, y0 + ch)],
                white.stroke_width(1),
            ))
            .map_err(plot_error)?;
            // white text on the darker half of the scale
            let dark = value.is_some_and(|v| (v / limit).abs() > 0.6);
            let style = font(16, HPos::Center);
            let style = if dark { style.color(&white) } else { style };
            root.draw(&Text::new(
                cell.label.clone(),
                (x0 + cw / 2, y0 + ch / 2),
                style,
            ))
            .map_err(plot_error)?;
        }
    }
    // the colour bar: −limit … +limit
    let bar_y = HEAT_TOP + ch * n_rows + 14;
    let (bar_x, bar_w, steps) = (HEAT_LABEL_WIDTH, cw * n_cols.min(5), 50);
    for s in 0..steps {
        let v = limit * (2.0 * (s as f64 + 0.5) / steps as f64 - 1.0);
        let x = bar_x + bar_w * s / steps;
        root.draw(&Rectangle::new(
            [(x, bar_y), (bar_x + bar_w * (s + 1) / steps, bar_y + 12)],
            diverging(v, limit).filled(),
        ))
        .map_err(plot_error)?;
    }
    for (v, x) in [
        (-limit, bar_x),
        (0.0, bar_x + bar_w / 2),
        (limit, bar_x + bar_w),
    ] {
        root.draw(&Text::new(
            format!("{v}"),
            (x, bar_y + 22),
            font(14, HPos::Center),
        ))
        .map_err(plot_error)?;
    }
    root.draw(&Text::new(
        map.note.clone(),
        (bar_x, bar_y + 44),
        font(14, HPos::Left),
    ))
    .map_err(plot_error)?;
    root.present().map_err(plot_error)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_diverging_scale_is_white_at_zero_and_clipped_at_its_ends() {
        assert_eq!(diverging(0.0, 2.0), DIVERGING[1]);
        assert_eq!(diverging(2.0, 2.0), DIVERGING[2]);
        assert_eq!(diverging(-7.0, 2.0), DIVERGING[0]);
        assert_eq!(nice_ceiling(0.0), 1.0);
        assert_eq!(nice_ceiling(0.3), 0.5);
        assert_eq!(nice_ceiling(1.0), 1.0);
        assert_eq!(nice_ceiling(1.2), 2.0);
        assert_eq!(nice_ceiling(6.0), 10.0);
    }

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
