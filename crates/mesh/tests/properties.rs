//! Property tests of runout-mesh (issue 2): widths sum to the length, faces increase,
//! adjacent widths follow the requested ratio, locate returns the containing cell.

use proptest::prelude::*;
use runout_mesh::strategies::{arb_segment, arb_stretched_grid};
use runout_mesh::{Axis, Segment};

/// Relative tolerance on Σ widths = length (issue 2).
const SUM_RTOL: f64 = 1e-12;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn widths_sum_to_length(seg in arb_segment(1.3)) {
        let w = seg.widths().unwrap();
        let sum: f64 = w.iter().sum();
        prop_assert!((sum - seg.length()).abs() <= SUM_RTOL * seg.length(),
            "sum {sum} vs length {}", seg.length());
        prop_assert!(w.iter().all(|&x| x > 0.0));
    }

    #[test]
    fn axis_faces_strictly_increasing_and_end_exact(origin in -5.0f64..5.0,
            segs in prop::collection::vec(arb_segment(1.3), 1..=4)) {
        let axis = Axis::from_segments(origin, &segs).unwrap();
        let f = axis.faces();
        prop_assert!(f.windows(2).all(|p| p[1] > p[0]));
        let total: f64 = segs.iter().map(Segment::length).sum();
        prop_assert!((axis.length() - total).abs() <= SUM_RTOL * total.max(origin.abs()));
        // Σ widths = length of the axis
        let sum: f64 = axis.widths().iter().sum();
        prop_assert!((sum - axis.length()).abs() <= SUM_RTOL * (total + origin.abs()));
        // centres strictly inside their cells
        for (i, c) in axis.centres().iter().enumerate() {
            prop_assert!(*c > f[i] && *c < f[i + 1]);
        }
    }

    #[test]
    fn geometric_widths_follow_growth(length in 0.01f64..10.0, cells in 2usize..=60,
            growth in 0.7f64..1.4) {
        let w = Segment::Geometric { length, cells, growth }.widths().unwrap();
        for p in w.windows(2) {
            prop_assert!((p[1] / p[0] - growth).abs() <= 1e-9 * growth,
                "ratio {} vs growth {growth}", p[1] / p[0]);
        }
    }

    #[test]
    fn first_width_segment_honours_first_and_is_geometric(length in 0.01f64..10.0,
            cells in 2usize..=60, frac in 0.05f64..1.5) {
        let first = frac * length / cells as f64;
        let w = Segment::FirstWidth { length, cells, first }.widths().unwrap();
        prop_assert!((w[0] - first).abs() <= 1e-9 * first, "first {} vs {first}", w[0]);
        let g = w[1] / w[0];
        for p in w.windows(2) {
            prop_assert!((p[1] / p[0] - g).abs() <= 1e-9 * g);
        }
    }

    #[test]
    fn end_widths_segment_honours_smaller_end(length in 0.1f64..10.0,
            a in 0.002f64..0.2, b in 0.002f64..0.2) {
        let (first, last) = (a * length, b * length);
        let w = Segment::EndWidths { length, first, last }.widths().unwrap();
        let n = w.len();
        let (small, big) = (first.min(last), first.max(last));
        let (got_small, got_big) = if first <= last { (w[0], w[n - 1]) } else { (w[n - 1], w[0]) };
        // never grows the wrong way
        if first <= last {
            prop_assert!(w.windows(2).all(|p| p[1] >= p[0] * (1.0 - 1e-12)));
        } else {
            prop_assert!(w.windows(2).all(|p| p[1] <= p[0] * (1.0 + 1e-12)));
        }
        let exact_small_possible = (length / big).ceil() <= (length / small).floor();
        if n > 1 && exact_small_possible {
            prop_assert!((got_small - small).abs() <= 1e-9 * small, "{got_small} vs {small}");
            // The count is within one cell of the continuous solution, so the other end
            // moves by about 1/n relative, times at most one growth factor.
            let g = (w[1] / w[0]).max(w[0] / w[1]);
            let bound = g * (1.0 + 2.0 / n as f64);
            prop_assert!(got_big <= big * bound && got_big >= big / bound,
                "big end {got_big} vs {big}, growth {g}");
        }
    }

    #[test]
    fn locate_returns_containing_cell(grid in arb_stretched_grid(1.3),
            sx in 0.0f64..=1.0, sy in 0.0f64..=1.0) {
        let x = grid.x.start() + sx * grid.x.length();
        let y = grid.y.start() + sy * grid.y.length();
        let x = x.min(grid.x.end());
        let y = y.min(grid.y.end());
        let (i, j) = grid.locate(x, y).expect("point inside");
        let (xf, yf) = (grid.x.faces(), grid.y.faces());
        prop_assert!(xf[i] <= x && (x < xf[i + 1] || (i + 1 == grid.nx() && x == xf[i + 1])));
        prop_assert!(yf[j] <= y && (y < yf[j + 1] || (j + 1 == grid.ny() && y == yf[j + 1])));
    }

    #[test]
    fn locate_rejects_outside(grid in arb_stretched_grid(1.3), d in 1e-9f64..1.0) {
        prop_assert!(grid.locate(grid.x.start() - d * grid.x.length(), grid.y.start()).is_none());
        prop_assert!(grid.locate(grid.x.end() + d * grid.x.length(), grid.y.start()).is_none());
        prop_assert!(grid.locate(grid.x.start(), grid.y.end() + d * grid.y.length()).is_none());
        prop_assert!(grid.locate(f64::NAN, grid.y.start()).is_none());
    }

    #[test]
    fn index_maps_round_trip(grid in arb_stretched_grid(1.3)) {
        for idx in [0, grid.cell_count() / 2, grid.cell_count() - 1] {
            let (i, j) = grid.cell_ij(idx);
            prop_assert_eq!(grid.cell_index(i, j), idx);
        }
        prop_assert_eq!(grid.u_face_index(grid.nx(), grid.ny() - 1) + 1, grid.u_face_count());
        prop_assert_eq!(grid.v_face_index(grid.nx() - 1, grid.ny()) + 1, grid.v_face_count());
    }

    #[test]
    fn face_spacing_is_centre_distance(grid in arb_stretched_grid(1.3)) {
        let ax = &grid.x;
        let c = ax.centres();
        let s = ax.face_spacing();
        prop_assert_eq!(s.len(), ax.len() + 1);
        for k in 1..ax.len() {
            prop_assert!((s[k] - (c[k] - c[k - 1])).abs() <= 1e-12 * ax.length().max(1.0));
        }
        prop_assert_eq!(s[0], ax.widths()[0]);
        prop_assert_eq!(s[ax.len()], ax.widths()[ax.len() - 1]);
    }

    #[test]
    fn coarsened_segment_keeps_length(seg in arb_segment(1.3), factor in 1u32..=8) {
        let c = seg.coarsened(factor);
        prop_assert_eq!(c.length(), seg.length());
        let w = c.widths().unwrap();
        let sum: f64 = w.iter().sum();
        prop_assert!((sum - seg.length()).abs() <= SUM_RTOL * seg.length());
    }
}

#[test]
fn invalid_segments_are_rejected_with_field_names() {
    let err = Segment::Uniform {
        length: -1.0,
        cells: 3,
    }
    .validate("x.segments[0]")
    .unwrap_err();
    assert!(err.to_string().contains("x.segments[0].length"), "{err}");
    let err = Segment::Geometric {
        length: 1.0,
        cells: 0,
        growth: 1.1,
    }
    .validate("s")
    .unwrap_err();
    assert!(err.to_string().contains("s.cells"), "{err}");
    let err = Segment::FirstWidth {
        length: 1.0,
        cells: 4,
        first: 2.0,
    }
    .validate("s")
    .unwrap_err();
    assert!(err.to_string().contains("s.first"), "{err}");
    assert!(Axis::from_faces(vec![0.0, 1.0, 1.0]).is_err());
}

#[test]
fn interpolation_weight_is_distance_weighting() {
    let axis = Axis::from_faces(vec![0.0, 1.0, 4.0]).unwrap();
    // face at x = 1: centres at 0.5 and 2.5; linear interpolation weight of cell 0 is
    // (2.5 − 1)/(2.5 − 0.5) = 0.75 = Δx_1/(Δx_0 + Δx_1)
    assert!((axis.interpolation_weight(0) - 0.75).abs() < 1e-15);
}
