//! Vector kernels shared by the iterative solvers.
//!
//! Each kernel runs its loop on a [`Team`]: rayon above [`PAR_MIN_LEN`] entries outside a
//! multigrid solve, the solve's spinning team above [`crate::team::TEAM_MIN_LEN`] inside
//! one. Reductions are split into at most [`N_PARTIALS`] fixed chunks (their length a
//! function of the vector's length and the kind of team, never of the number of threads)
//! whose partial sums are added in a fixed order, so a dot product gives the same bits on
//! every run regardless of work stealing.

use rayon::prelude::*;

use crate::team::Team;

/// Vectors shorter than this are processed serially (rayon's fork/join overhead of a few
/// microseconds exceeds the work below about 16k entries).
pub(crate) const PAR_MIN_LEN: usize = 1 << 14;

/// Number of fixed partial sums in a parallel reduction.
const N_PARTIALS: usize = 32;

fn chunk_len(n: usize) -> usize {
    n.div_ceil(N_PARTIALS).max(1)
}

/// The fixed chunk length of a loop of `n` entries by `team`: [`N_PARTIALS`] chunks on
/// rayon, chunks of at least the team's [`Team::min_chunk`] with a team (a function of n
/// alone, so the partial sums are the same on any number of threads).
fn chunk_len_on(team: &Team<'_>, n: usize) -> usize {
    if team.is_rayon() {
        chunk_len(n)
    } else {
        chunk_len(n).max(team.min_chunk())
    }
}

/// x · y on one thread, summed in four interleaved partial sums (the order is fixed by
/// the length alone).
#[inline]
pub(crate) fn dot_serial(x: &[f64], y: &[f64]) -> f64 {
    // four independent accumulators let the compiler vectorise the loop
    let mut acc = [0.0f64; 4];
    let mut xc = x.chunks_exact(4);
    let mut yc = y.chunks_exact(4);
    for (a, b) in (&mut xc).zip(&mut yc) {
        acc[0] += a[0] * b[0];
        acc[1] += a[1] * b[1];
        acc[2] += a[2] * b[2];
        acc[3] += a[3] * b[3];
    }
    let tail: f64 = xc
        .remainder()
        .iter()
        .zip(yc.remainder())
        .map(|(a, b)| a * b)
        .sum();
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}

/// x · y, deterministic.
pub(crate) fn dot(x: &[f64], y: &[f64]) -> f64 {
    dot_on(&Team::RAYON, x, y)
}

/// x · y by `team`: fixed chunks whose partial sums are added in order (module doc).
pub(crate) fn dot_on(team: &Team<'_>, x: &[f64], y: &[f64]) -> f64 {
    debug_assert_eq!(x.len(), y.len());
    let n = x.len();
    if n < team.min_len() {
        return dot_serial(x, y);
    }
    let c = chunk_len_on(team, n);
    let mut partial = [0.0f64; N_PARTIALS];
    team.for_each_chunk_mut(&mut partial[..n.div_ceil(c)], 1, |i, p| {
        let r = i * c..((i + 1) * c).min(n);
        p[0] = dot_serial(&x[r.clone()], &y[r]);
    });
    partial.iter().sum()
}

/// ‖x‖₂.
pub(crate) fn norm2(x: &[f64]) -> f64 {
    dot(x, x).sqrt()
}

/// ‖x‖₂ by `team`.
pub(crate) fn norm2_on(team: &Team<'_>, x: &[f64]) -> f64 {
    dot_on(team, x, x).sqrt()
}

/// Applies `f(i, &mut y_i)` to every entry, on rayon from [`PAR_MIN_LEN`] entries.
pub(crate) fn for_each_indexed<F>(y: &mut [f64], f: F)
where
    F: Fn(usize, &mut f64) + Sync + Send,
{
    for_each_indexed_on(&Team::RAYON, y, f);
}

/// [`for_each_indexed`] by `team`.
pub(crate) fn for_each_indexed_on<F>(team: &Team<'_>, y: &mut [f64], f: F)
where
    F: Fn(usize, &mut f64) + Sync + Send,
{
    let n = y.len();
    if n < team.min_len() {
        y.iter_mut().enumerate().for_each(|(i, v)| f(i, v));
    } else {
        let c = chunk_len_on(team, n);
        team.for_each_chunk_mut(y, c, |ci, chunk| {
            let base = ci * c;
            chunk
                .iter_mut()
                .enumerate()
                .for_each(|(i, v)| f(base + i, v));
        });
    }
}

/// y ← y + α x.
pub(crate) fn axpy(alpha: f64, x: &[f64], y: &mut [f64]) {
    axpy_on(&Team::RAYON, alpha, x, y);
}

/// y ← y + α x by `team`.
pub(crate) fn axpy_on(team: &Team<'_>, alpha: f64, x: &[f64], y: &mut [f64]) {
    for_each_indexed_on(team, y, |i, v| *v += alpha * x[i]);
}

/// The exponent bits of an f64: all set exactly for ±∞ and NaN.
const EXPONENT_BITS: u64 = 0x7ff0_0000_0000_0000;

/// Whether every entry of a serial block is finite: an OR over the block, which the compiler
/// vectorises (a short-circuiting `all` tests one entry at a time).
fn block_is_finite(x: &[f64]) -> bool {
    let non_finite = |v: &f64| u8::from(v.to_bits() & EXPONENT_BITS == EXPONENT_BITS);
    x.chunks(256)
        .all(|block| block.iter().fold(0u8, |acc, v| acc | non_finite(v)) == 0)
}

/// Returns true when every entry is finite.
pub(crate) fn all_finite(x: &[f64]) -> bool {
    if x.len() < PAR_MIN_LEN {
        block_is_finite(x)
    } else {
        x.par_chunks(chunk_len(x.len())).all(block_is_finite)
    }
}

/// Index of the first non-finite entry, if any.
pub(crate) fn first_non_finite(x: &[f64]) -> Option<usize> {
    if all_finite(x) {
        None
    } else {
        x.iter().position(|v| !v.is_finite())
    }
}

/// A raw pointer to a vector shared by parallel tasks that write disjoint entries (the line
/// smoothers of the multigrid, the column blocks of the line preconditioner; see the SAFETY
/// notes at the call sites).
#[derive(Clone, Copy)]
pub(crate) struct SharedMut(pub(crate) *mut f64);
// SAFETY: only used for the disjoint writes documented at the call sites.
unsafe impl Send for SharedMut {}
unsafe impl Sync for SharedMut {}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first non-finite entry is found wherever it is, for NaN and both infinities,
    /// serial and parallel lengths, and subnormal or huge finite values are finite.
    #[test]
    fn first_non_finite_finds_nan_and_infinities_anywhere() {
        for n in [1, 7, 255, 256, 257, 1000, PAR_MIN_LEN + 3] {
            let mut x: Vec<f64> = (0..n).map(|i| (i as f64 - 3.5) * 1e300).collect();
            x[0] = f64::MIN_POSITIVE / 4.0;
            assert_eq!(first_non_finite(&x), None, "n = {n}");
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                for at in [0, n / 2, n - 1] {
                    let mut y = x.clone();
                    y[at] = bad;
                    assert_eq!(first_non_finite(&y), Some(at), "n = {n}, {bad} at {at}");
                }
            }
        }
    }
}
