//! The figures: the log–log runout against the aspect ratio (the runs of each closure beside
//! the laws), and the final deposit profiles (one panel per a, each closure a line, the
//! initial column's outline).

use std::path::Path;

use anyhow::Result;
use plotters::prelude::*;

use super::run::Outcome;
use crate::references::{
    ScalingLaw, LAGREE_CONTINUUM, LAJEUNESSE, LAJEUNESSE_AS_KUMAR_CITES, LUBE,
};
use runout_study::plots::{legend, plot_error, LINE_COLOURS};

/// SVG size of the runout figure [px].
const FIGURE_SIZE: (u32, u32) = (900, 650);
/// SVG size of one deposit panel [px].
const PANEL_SIZE: (u32, u32) = (450, 300);
/// μ(I) runs: red; Princeton runs: orange.
const MU_I_COLOUR: RGBColor = LINE_COLOURS[1];
const PRINCETON_COLOUR: RGBColor = LINE_COLOURS[4];

fn closure_colour(o: &Outcome) -> RGBColor {
    if o.mu_i {
        MU_I_COLOUR
    } else {
        PRINCETON_COLOUR
    }
}

fn closure_name(mu_i: bool) -> &'static str {
    if mu_i {
        "μ(I)"
    } else {
        "Princeton"
    }
}

/// Log–log runout against a: the laws (each branch over its side of a0; Kumar's reading of
/// Lajeunesse et al. dashed) and each closure's runs (filled squares: the grain edge, the
/// μ(I) check's runout; circles: the εs ≥ 0.01 front, triangles where it reached the end wall).
pub(super) fn draw(outcomes: &[Outcome], path: &Path) -> Result<()> {
    let (a_lo, a_hi) = (0.3, 10.0);
    let y_hi = outcomes
        .iter()
        .map(|o| o.front.runout.max(o.grain_runout))
        .fold(
            LAJEUNESSE.power(a_hi).max(LAGREE_CONTINUUM.runout(a_hi).1),
            f64::max,
        )
        * 1.5;
    let y_lo = outcomes
        .iter()
        .map(|o| o.grain_runout.min(o.front.runout))
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
    draw_laws(&mut chart, (a_lo, a_hi))?;
    draw_runs(&mut chart, outcomes)?;
    legend(&mut chart, SeriesLabelPosition::LowerRight).map_err(plot_error)?;
    root.present().map_err(plot_error)?;
    Ok(())
}

/// The runout figure's axes: log a against log (L∞ − L0)/L0.
type RunoutChart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>;

/// The laws over [`a_lo`, `a_hi`]: each branch over its side of a0, Kumar's reading of
/// Lajeunesse et al. dashed.
fn draw_laws(chart: &mut RunoutChart, (a_lo, a_hi): (f64, f64)) -> Result<()> {
    let samples =
        |from: f64, to: f64| (0..=100).map(move |k| from * (to / from).powf(k as f64 / 100.0));
    let law_label = |law: &ScalingLaw| {
        format!(
            "{}: {} a, {} a^{:.2}",
            law.name, law.lambda1, law.lambda2, law.exponent
        )
    };
    for (law, colour) in [
        (LAJEUNESSE, LINE_COLOURS[0]),
        (LUBE, LINE_COLOURS[2]),
        (LAGREE_CONTINUUM, LINE_COLOURS[3]),
    ] {
        chart
            .draw_series(LineSeries::new(
                samples(a_lo, law.a0.1).map(|a| (a, law.linear(a))),
                colour.stroke_width(2),
            ))
            .map_err(plot_error)?
            .label(law_label(&law))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        chart
            .draw_series(LineSeries::new(
                samples(law.a0.0, a_hi).map(|a| (a, law.power(a))),
                colour.stroke_width(2),
            ))
            .map_err(plot_error)?;
    }
    let kumar = LAJEUNESSE_AS_KUMAR_CITES;
    let blue = LINE_COLOURS[0];
    for (from, to, branch) in [(a_lo, kumar.a0.1, false), (kumar.a0.0, a_hi, true)] {
        let series = chart
            .draw_series(DashedLineSeries::new(
                samples(from, to).map(|a| {
                    (
                        a,
                        if branch {
                            kumar.power(a)
                        } else {
                            kumar.linear(a)
                        },
                    )
                }),
                6,
                4,
                blue.stroke_width(1),
            ))
            .map_err(plot_error)?;
        if !branch {
            series
                .label(law_label(&kumar))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 8, y)], blue));
        }
    }
    Ok(())
}

/// Each closure's runs: filled squares the grain edge, circles the εs ≥ 0.01 front,
/// triangles where it reached the end wall.
fn draw_runs(chart: &mut RunoutChart, outcomes: &[Outcome]) -> Result<()> {
    for mu_i in [true, false] {
        let runs: Vec<&Outcome> = outcomes.iter().filter(|o| o.mu_i == mu_i).collect();
        if runs.is_empty() {
            continue;
        }
        let colour = if mu_i { MU_I_COLOUR } else { PRINCETON_COLOUR };
        let name = closure_name(mu_i);
        chart
            .draw_series(runs.iter().filter(|o| o.grain_runout > 0.0).map(|o| {
                let (a, r) = (o.column.aspect(), o.grain_runout);
                Rectangle::new(
                    [(a / 1.03, r / 1.03), (a * 1.03, r * 1.03)],
                    colour.filled(),
                )
            }))
            .map_err(plot_error)?
            .label(format!("{name}: grain edge (Σ εs Δy ≥ d)"))
            .legend(move |(x, y)| {
                Rectangle::new([(x + 5, y - 5), (x + 15, y + 5)], colour.filled())
            });
        chart
            .draw_series(
                runs.iter()
                    .filter(|o| o.front.runout > 0.0 && !o.front.reached_end_wall)
                    .map(|o| {
                        Circle::new(
                            (o.column.aspect(), o.front.runout),
                            5,
                            colour.stroke_width(2),
                        )
                    }),
            )
            .map_err(plot_error)?
            .label(format!("{name}: front εs ≥ 0.01"))
            .legend(move |(x, y)| Circle::new((x + 10, y), 5, colour.stroke_width(2)));
        chart
            .draw_series(runs.iter().filter(|o| o.front.reached_end_wall).map(|o| {
                TriangleMarker::new((o.column.aspect(), o.front.runout), 7, colour.filled())
            }))
            .map_err(plot_error)?;
    }
    Ok(())
}

/// The final deposits: one panel per aspect ratio (two columns of panels), the thickness at
/// εs ≥ 0.3 over L0 against x/L0 from the west wall for each closure's run, and the initial
/// column's outline in grey.
pub(super) fn draw_deposits(outcomes: &[Outcome], path: &Path) -> Result<()> {
    let mut aspects: Vec<f64> = outcomes.iter().map(|o| o.column.aspect()).collect();
    aspects.sort_by(f64::total_cmp);
    aspects.dedup();
    let rows = aspects.len().div_ceil(2).max(1);
    let size = (2 * PANEL_SIZE.0, rows as u32 * PANEL_SIZE.1);
    let root = SVGBackend::new(path, size).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let panels = root.split_evenly((rows, 2));
    for (panel, &a) in panels.iter().zip(&aspects) {
        let runs: Vec<&Outcome> = outcomes.iter().filter(|o| o.column.aspect() == a).collect();
        let x_hi = runs
            .iter()
            .map(|o| 1.0 + o.grain_runout.max(o.front.runout))
            .fold(1.0, f64::max)
            * 1.1;
        let y_hi = runs.iter().map(|o| o.height).fold(a, f64::max) * 1.15;
        let mut chart = ChartBuilder::on(panel)
            .caption(format!("a = {a}"), ("sans-serif", 16))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(45)
            .build_cartesian_2d(0.0..x_hi, 0.0..y_hi)
            .map_err(plot_error)?;
        chart
            .configure_mesh()
            .x_desc("x / L0")
            .y_desc("h / L0 (εs ≥ 0.3)")
            .draw()
            .map_err(plot_error)?;
        let grey = RGBColor(150, 150, 150);
        chart
            .draw_series(LineSeries::new(
                [(0.0, a), (1.0, a), (1.0, 0.0)],
                grey.stroke_width(1),
            ))
            .map_err(plot_error)?
            .label("initial column")
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], grey));
        for o in runs {
            let colour = closure_colour(o);
            let l0 = o.column.l0;
            let x0 = o.column.x_wall;
            chart
                .draw_series(LineSeries::new(
                    o.deposit
                        .iter()
                        .map(|c| ((c.x - x0) / l0, c.thickness_dense / l0)),
                    colour.stroke_width(2),
                ))
                .map_err(plot_error)?
                .label(format!("{} ({})", closure_name(o.mu_i), o.name))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        }
        legend(&mut chart, SeriesLabelPosition::UpperRight).map_err(plot_error)?;
    }
    root.present().map_err(plot_error)?;
    Ok(())
}
