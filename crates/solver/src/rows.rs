//! Row-parallel loops over the cell and face arrays (one row = one grid line j), for the
//! stages whose rows are independent: each row is computed exactly as a serial loop would
//! compute it, so the results are the same on any number of threads.

use rayon::prelude::*;

/// Fewest entries per parallel task: rayon's fork/join costs a few microseconds (more when
/// a sleeping worker must be woken), a row's entry 1–10 ns.
pub(crate) const PAR_ROW_ENTRIES: usize = 1 << 14;

/// Rows per parallel task for rows of `row_len` entries.
pub(crate) fn rows_per_task(row_len: usize) -> usize {
    (PAR_ROW_ENTRIES / row_len.max(1)).max(1)
}

/// Calls `f(j, row)` for every row of `row_len` entries of `data`, in parallel over blocks of
/// rows of at least [`PAR_ROW_ENTRIES`] entries (serially below that).
pub(crate) fn for_each_row<T, F>(data: &mut [T], row_len: usize, f: F)
where
    T: Send,
    F: Fn(usize, &mut [T]) + Sync + Send,
{
    if data.len() < PAR_ROW_ENTRIES {
        data.chunks_mut(row_len)
            .enumerate()
            .for_each(|(j, row)| f(j, row));
    } else {
        data.par_chunks_mut(row_len)
            .enumerate()
            .with_min_len(rows_per_task(row_len))
            .for_each(|(j, row)| f(j, row));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
