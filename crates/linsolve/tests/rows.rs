//! `for_each_row`: every row visited once, with its index, below and above the parallel
//! threshold.

use runout_linsolve::for_each_row;

#[test]
fn every_row_is_visited_once_with_its_index() {
    for (row_len, rows) in [(7, 3), (401, 100), (1, 40_000)] {
        let mut data = vec![0.0; row_len * rows];
        for_each_row(&mut data, row_len, |j, row| {
            assert_eq!(row.len(), row_len);
            row.iter_mut().for_each(|x| *x += 1.0 + j as f64);
        });
        for (k, x) in data.iter().enumerate() {
            assert_eq!(*x, 1.0 + (k / row_len) as f64);
        }
    }
}
