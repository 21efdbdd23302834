//! What the SVG figures of several tasks share: the line colours, the legend box and the
//! error of a failed drawing.

use plotters::coord::CoordTranslate;
use plotters::prelude::*;
use runout_study::plots::{BLACK_INDEX, COLOURS};

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

/// Line colours, cycled per curve: blue, red, green, purple, orange of the study engine's
/// palette (matplotlib's tab10), then black.
pub const LINE_COLOURS: [RGBColor; 6] = [
    COLOURS[0],
    COLOURS[3],
    COLOURS[2],
    COLOURS[4],
    COLOURS[1],
    COLOURS[BLACK_INDEX],
];

/// The error of a failed drawing (defined with the study engine's plots).
pub use runout_study::plots::plot_error;
