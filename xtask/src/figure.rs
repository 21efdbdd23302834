//! What the SVG figures of several tasks share: the legend box.

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
