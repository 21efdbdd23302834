//! The figure: log–log runout against the aspect ratio, the runs beside both laboratory
//! laws.

use std::path::Path;

use anyhow::Result;
use plotters::prelude::*;

use super::run::Outcome;
use crate::figure::{legend, plot_error};
use runout_verification::references::{LAGREE_CONTINUUM, LAJEUNESSE, LUBE};

/// SVG size [px].
const FIGURE_SIZE: (u32, u32) = (900, 650);

/// Log–log runout against a: the runs (filled: εs ≥ 0.01 front, triangles where it reached
/// the end wall; hollow: εs ≥ 0.3; black squares: the grain edge) and both laws, each branch
/// over its side of a0.
pub(super) fn draw(outcomes: &[Outcome], path: &Path) -> Result<()> {
    let (a_lo, a_hi) = (0.3, 10.0);
    let y_hi = outcomes
        .iter()
        .map(|o| o.front.runout.max(o.dense_runout))
        .fold(
            LAJEUNESSE.power(a_hi).max(LAGREE_CONTINUUM.runout(a_hi).1),
            f64::max,
        )
        * 1.5;
    let y_lo = outcomes
        .iter()
        .map(|o| o.dense_runout.min(o.front.runout))
        .filter(|&r| r > 0.0)
        .fold(LUBE.linear(a_lo), f64::min)
        / 1.5;
    let root = SVGBackend::new(path, FIGURE_SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Column collapse: runout against aspect ratio (untuned)",
            ("sans-serif", 20),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d((a_lo..a_hi).log_scale(), (y_lo..y_hi).log_scale())
        .map_err(plot_error)?;
    chart
        .configure_mesh()
        .x_desc("a = H0/L0")
        .y_desc("(L∞ − L0)/L0")
        .draw()
        .map_err(plot_error)?;
    let samples =
        |from: f64, to: f64| (0..=100).map(move |k| from * (to / from).powf(k as f64 / 100.0));
    for (law, colour) in [
        (LAJEUNESSE, RGBColor(31, 119, 180)),
        (LUBE, RGBColor(44, 160, 44)),
        (LAGREE_CONTINUUM, RGBColor(148, 103, 189)),
    ] {
        chart
            .draw_series(LineSeries::new(
                samples(a_lo, law.a0.1).map(|a| (a, law.linear(a))),
                colour.stroke_width(2),
            ))
            .map_err(plot_error)?
            .label(format!(
                "{}: {} a, {} a^{:.2}",
                law.name, law.lambda1, law.lambda2, law.exponent
            ))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        chart
            .draw_series(LineSeries::new(
                samples(law.a0.0, a_hi).map(|a| (a, law.power(a))),
                colour.stroke_width(2),
            ))
            .map_err(plot_error)?;
    }
    let red = RGBColor(214, 39, 40);
    let points: Vec<(f64, f64, bool)> = outcomes
        .iter()
        .filter(|o| o.front.runout > 0.0)
        .map(|o| (o.column.aspect(), o.front.runout, o.front.reached_end_wall))
        .collect();
    chart
        .draw_series(
            points
                .iter()
                .filter(|p| !p.2)
                .map(|&(a, r, _)| Circle::new((a, r), 5, red.filled())),
        )
        .map_err(plot_error)?
        .label("runout, front εs ≥ 0.01")
        .legend(move |(x, y)| Circle::new((x + 10, y), 5, red.filled()));
    chart
        .draw_series(
            points
                .iter()
                .filter(|p| p.2)
                .map(|&(a, r, _)| TriangleMarker::new((a, r), 7, red.filled())),
        )
        .map_err(plot_error)?
        .label("front reached the end wall (lower bound)")
        .legend(move |(x, y)| TriangleMarker::new((x + 10, y), 7, red.filled()));
    chart
        .draw_series(
            outcomes
                .iter()
                .filter(|o| o.dense_runout > 0.0)
                .map(|o| Circle::new((o.column.aspect(), o.dense_runout), 5, red.stroke_width(2))),
        )
        .map_err(plot_error)?
        .label("runout, dense front εs ≥ 0.3")
        .legend(move |(x, y)| Circle::new((x + 10, y), 5, red.stroke_width(2)));
    let black = RGBColor(0, 0, 0);
    chart
        .draw_series(outcomes.iter().filter(|o| o.grain_runout > 0.0).map(|o| {
            let (a, r) = (o.column.aspect(), o.grain_runout);
            Rectangle::new([(a / 1.03, r / 1.03), (a * 1.03, r * 1.03)], black.filled())
        }))
        .map_err(plot_error)?
        .label("runout, grain edge (Σ εs Δy ≥ d; the μ(I) check's)")
        .legend(move |(x, y)| Rectangle::new([(x + 5, y - 5), (x + 15, y + 5)], black.filled()));
    legend(&mut chart, SeriesLabelPosition::LowerRight).map_err(plot_error)?;
    root.present().map_err(plot_error)?;
    Ok(())
}
