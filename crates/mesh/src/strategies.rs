//! proptest strategies for grids (feature `proptest`), for the tests of crates that use
//! runout-mesh.

use proptest::prelude::*;

use crate::{Axis, Grid, Segment};

/// A random segment of any kind with lengths in [0.01, 10] m, 1..=60 cells and growth
/// ratios in [1/max_ratio, max_ratio].
pub fn arb_segment(max_ratio: f64) -> impl Strategy<Value = Segment> {
    let length = 0.01f64..10.0;
    let cells = 1usize..=60;
    let growth = (1.0 / max_ratio)..max_ratio;
    prop_oneof![
        (length.clone(), cells.clone())
            .prop_map(|(length, cells)| Segment::Uniform { length, cells }),
        (length.clone(), cells.clone(), growth.clone()).prop_map(|(length, cells, growth)| {
            Segment::Geometric {
                length,
                cells,
                growth,
            }
        }),
        (length.clone(), 2usize..=60, 0.05f64..1.5).prop_map(|(length, cells, frac)| {
            // first width as a fraction of the mean width keeps the problem solvable
            Segment::FirstWidth {
                length,
                cells,
                first: frac * length / cells as f64,
            }
        }),
        (length.clone(), 2usize..=60, 0.05f64..1.5).prop_map(|(length, cells, frac)| {
            Segment::LastWidth {
                length,
                cells,
                last: frac * length / cells as f64,
            }
        }),
        (length, 0.002f64..0.2, 0.002f64..0.2).prop_map(|(length, a, b)| Segment::EndWidths {
            length,
            first: a * length,
            last: b * length
        }),
    ]
}

/// A random axis from 1..=4 segments starting at an origin in [-5, 5] m.
pub fn arb_axis(max_ratio: f64) -> impl Strategy<Value = Axis> {
    (
        -5.0f64..5.0,
        prop::collection::vec(arb_segment(max_ratio), 1..=4),
    )
        .prop_map(|(origin, segs)| Axis::from_segments(origin, &segs).expect("valid segments"))
}

/// A random stretched grid with adjacent-width ratios up to `max_ratio` inside segments.
pub fn arb_stretched_grid(max_ratio: f64) -> impl Strategy<Value = Grid> {
    (arb_axis(max_ratio), arb_axis(max_ratio)).prop_map(|(x, y)| Grid::new(x, y))
}
