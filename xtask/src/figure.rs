//! What the SVG figures of several tasks share: the line colours, the legend box and the
//! error of a failed drawing.

use plotters::coord::CoordTranslate;
use plotters::prelude::*;

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

/// Line colours, cycled per curve: blue, red, green, purple, orange (matplotlib's tab10),
/// then black.
pub const LINE_COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(0, 0, 0),
];

/// The error of a failed drawing (defined with the study engine's plots).
pub use runout_study::plots::plot_error;
