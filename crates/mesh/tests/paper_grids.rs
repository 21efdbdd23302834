//! The two grids of the paper (issue 2): the sensitivity domain 20 m × 1.8 m with
//! 0.02 m × 0.005 m focus cells (paper Fig. 2) and the flume 7.5 m × 1.8 m with
//! 0.01 m × 0.01 m cells (paper Fig. 11), as described in cases/.

use runout_mesh::{AxisSpec, Grid, Segment};

#[test]
fn sensitivity_grid_has_focus_cells_of_the_paper() {
    let x = AxisSpec {
        origin: 0.0,
        segments: vec![Segment::Uniform {
            length: 20.0,
            cells: 1000,
        }],
    };
    let y = AxisSpec {
        origin: 0.0,
        segments: vec![
            Segment::Uniform {
                length: 0.30,
                cells: 60,
            },
            Segment::FirstWidth {
                length: 1.50,
                cells: 30,
                first: 0.005,
            },
        ],
    };
    let grid = Grid::from_specs(&x, &y).unwrap();
    let s = grid.summary();
    assert_eq!((s.nx, s.ny), (1000, 90));
    assert!((s.dx_min - 0.02).abs() < 1e-12 && (s.dx_max - 0.02).abs() < 1e-12);
    assert!((s.dy_min - 0.005).abs() < 1e-12, "{}", s.dy_min);
    assert!((s.y_range.1 - 1.8).abs() < 1e-12);
    // the stretched part starts with the focus height, so the join is smooth
    assert!(s.max_adjacent_ratio_y < 1.2, "{}", s.max_adjacent_ratio_y);
}
