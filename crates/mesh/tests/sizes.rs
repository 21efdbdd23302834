//! Cell counts are bounded before anything is allocated (issue 21): a huge count, given or
//! implied by end widths, is an error naming the field, never a capacity-overflow panic or
//! an allocation abort.

use runout_mesh::{AxisSpec, Segment, MAX_AXIS_CELLS};

fn axis(segments: Vec<Segment>) -> AxisSpec {
    AxisSpec {
        origin: 0.0,
        segments,
    }
}

/// The error text of building the axis; panics if it builds.
fn build_error(segments: Vec<Segment>) -> String {
    let spec = axis(segments);
    let counted = spec.cell_count().expect_err("count rejected").to_string();
    let built = spec.build().expect_err("build rejected").to_string();
    assert_eq!(counted, built);
    built
}

#[test]
fn huge_given_counts_are_errors() {
    for cells in [usize::MAX, 4_294_967_296, 1_000_000_000, MAX_AXIS_CELLS + 1] {
        let e = build_error(vec![Segment::Uniform { length: 1.0, cells }]);
        assert!(
            e.contains("segments[0].cells") && e.contains(&format!("[1, {MAX_AXIS_CELLS}]")),
            "{e}"
        );
        let e = build_error(vec![Segment::FirstWidth {
            length: 1.0,
            cells,
            first: 1e-3,
        }]);
        assert!(e.contains("segments[0].cells"), "{e}");
    }
}

#[test]
fn huge_counts_implied_by_end_widths_are_errors() {
    for seg in [
        Segment::EndWidths {
            length: 0.5,
            first: 1e-300,
            last: 1e-300,
        },
        Segment::EndWidths {
            length: 1e300,
            first: 0.05,
            last: 0.01,
        },
        Segment::EndWidths {
            length: 1.0,
            first: 1e-9,
            last: 2e-9,
        },
    ] {
        let e = build_error(vec![seg]);
        assert!(e.contains("segments[0]") && e.contains("cells"), "{e}");
        assert!(!e.contains("0000000000"), "a long decimal in: {e}");
    }
    // a very small first width next to a wide last one implies few cells: it builds
    let fine = axis(vec![Segment::EndWidths {
        length: 0.5,
        first: 1e-300,
        last: 0.05,
    }]);
    assert!(fine.cell_count().unwrap() < MAX_AXIS_CELLS);
}

#[test]
fn segments_that_sum_above_the_cap_are_an_error() {
    let half = Segment::Uniform {
        length: 1.0,
        cells: MAX_AXIS_CELLS / 2 + 1,
    };
    let e = build_error(vec![half.clone(), half]);
    assert!(e.contains("per axis"), "{e}");
}

#[test]
fn counts_match_the_built_axis() {
    let segments = vec![
        Segment::EndWidths {
            length: 0.5,
            first: 0.05,
            last: 0.01,
        },
        Segment::Uniform {
            length: 5.5,
            cells: 550,
        },
        Segment::FirstWidth {
            length: 1.5,
            cells: 25,
            first: 0.01,
        },
    ];
    let spec = axis(segments);
    assert_eq!(spec.cell_count().unwrap(), spec.build().unwrap().len());
}
