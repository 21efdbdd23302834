//! The figures: log–log error against CPU time (`cost.json` of each run: all threads, so a
//! user reads off what a tolerance costs whatever the thread count), one per case and
//! quantity, one colour per scheme (solid against the reference, dashed against the
//! Richardson extrapolation). A run without a recorded CPU time has no point.

use std::path::Path;

use anyhow::Result;
use plotters::prelude::*;

use super::ladder::scheme_name;
use super::quantity::Quantity;
use super::Ladder;
use runout_study::plots::{legend, plot_error, LINE_COLOURS};

/// SVG size [px].
const FIGURE_SIZE: (u32, u32) = (900, 600);

/// A file-name-safe form of a case name.
pub(super) fn file_stem(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '-' | '.') {
                c
            } else {
                '_'
            }
        })
        .collect()
}

/// The powers of ten around positive `values` (at least one decade apart), so a log axis
/// always has labelled decades.
fn decades(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, 0.0_f64), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    // a margin of 1.5× keeps points off the frame
    let lo = 10f64.powf((lo / 1.5).log10().floor());
    let hi = 10f64.powf((hi * 1.5).log10().ceil()).max(10.0 * lo);
    (lo, hi)
}

/// Log–log error against CPU time for one case and quantity, one colour per scheme: solid
/// against the reference, dashed against the Richardson extrapolation. Returns false (and
/// writes nothing) when no level has a positive error.
pub(super) fn draw(
    path: &Path,
    case: &str,
    quantity: Quantity,
    ladders: &[Ladder],
) -> Result<bool> {
    // (scheme, against reference, against Richardson), points (CPU time, error, level)
    type Points = Vec<(f64, f64, &'static str)>;
    let mut lines: Vec<(&'static str, Points, Points)> = Vec::new();
    for ladder in ladders.iter().filter(|l| l.case == case) {
        let Some((_, e)) = ladder.errors.iter().find(|(q, _)| *q == quantity) else {
            continue;
        };
        let points = |errors: &[Option<f64>]| -> Points {
            ladder
                .runs
                .iter()
                .zip(errors)
                .filter_map(|(r, e)| {
                    r.summary.as_ref().ok()?;
                    let cpu = r.cost?.cpu_seconds;
                    let e = (*e)?;
                    (e > 0.0 && e.is_finite() && cpu > 0.0).then_some((cpu, e, r.level.name()))
                })
                .collect()
        };
        lines.push((
            scheme_name(&ladder.scheme),
            points(&e.vs_reference),
            points(&e.richardson),
        ));
    }
    let all: Vec<(f64, f64)> = lines
        .iter()
        .flat_map(|(_, a, b)| a.iter().chain(b).map(|&(t, e, _)| (t, e)))
        .collect();
    if all.is_empty() {
        return Ok(false);
    }
    let (t_lo, t_hi) = decades(all.iter().map(|&(t, _)| t));
    let (e_lo, e_hi) = decades(all.iter().map(|&(_, e)| e));
    let area = SVGBackend::new(path, FIGURE_SIZE).into_drawing_area();
    area.fill(&WHITE).map_err(plot_error)?;
    let mut chart = ChartBuilder::on(&area)
        .caption(
            format!("{case}: {}", quantity.heading()),
            ("sans-serif", 18),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((t_lo..t_hi).log_scale(), (e_lo..e_hi).log_scale())
        .map_err(plot_error)?;
    chart
        .configure_mesh()
        .x_desc("CPU time [s], all threads (labels: level)")
        .y_desc(format!(
            "error: solid vs finest run, dashed vs Richardson ({})",
            quantity.norm()
        ))
        .draw()
        .map_err(plot_error)?;
    for (k, (scheme, vs_ref, vs_rich)) in lines.iter().enumerate() {
        let colour = LINE_COLOURS[k % LINE_COLOURS.len()];
        chart
            .draw_series(LineSeries::new(
                vs_ref.iter().map(|&(t, e, _)| (t, e)),
                colour.stroke_width(2),
            ))
            .map_err(plot_error)?
            .label(scheme.to_string())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        chart
            .draw_series(DashedLineSeries::new(
                vs_rich.iter().map(|&(t, e, _)| (t, e)),
                6,
                4,
                colour.stroke_width(1),
            ))
            .map_err(plot_error)?;
        for pts in [vs_ref, vs_rich] {
            chart
                .draw_series(
                    pts.iter()
                        .map(|&(t, e, _)| Circle::new((t, e), 4, colour.filled())),
                )
                .map_err(plot_error)?;
            chart
                .draw_series(pts.iter().map(|&(t, e, level)| {
                    Text::new(level, (t, e), ("sans-serif", 12).into_font().color(&colour))
                }))
                .map_err(plot_error)?;
        }
    }
    legend(&mut chart, SeriesLabelPosition::UpperRight).map_err(plot_error)?;
    area.present().map_err(plot_error)?;
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decades_are_whole_powers_of_ten_around_the_values() {
        assert_eq!(decades([3.0, 40.0].into_iter()), (1.0, 100.0));
        assert_eq!(decades([2.0].into_iter()), (1.0, 10.0));
        assert_eq!(decades([8.8].into_iter()), (1.0, 100.0));
    }
}
