//! One segment of a stretched axis, as MFIX users describe it.
//!
//! MFIX users describe a grid direction as consecutive segments, each with a length and a
//! cell count plus either an expansion ratio or end widths (keywords `CPX`, `NCX`, `ERX`,
//! `FIRST_DX`, `LAST_DX`). [`Segment`] covers those forms and yields its cell widths; an
//! [`crate::Axis`] is built from consecutive segments (docs/model.md §4.1).

use serde::{Deserialize, Serialize};

use crate::number::short;
use crate::MeshError;

/// Most cells one axis may have. An axis holds four vectors of its length (faces, centres,
/// widths, centre distances), so a million cells is 32 MB: a thousand times the paper's
/// longest axis (1000 cells), and more than any grid within the case crate's cap on cells
/// needs. Counts are checked against it arithmetically before anything is allocated, so
/// `cells: 18446744073709551615` is an error, not a capacity overflow (issue 21).
pub const MAX_AXIS_CELLS: usize = 1_000_000;

/// Relative tolerance used when a derived quantity (a cell count from end widths, a
/// growth ratio from a first width) is solved for numerically.
const SOLVE_RTOL: f64 = 1e-14;

/// One segment of an axis, as MFIX users describe it. Lengths and widths in metres.
///
/// `growth` is the ratio of adjacent cell widths, w[i+1] / w[i] (> 1: cells grow in the
/// direction of increasing coordinate). MFIX's `ERX` is instead last/first width over the
/// whole segment; `growth = ERX^(1/(cells-1))`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Segment {
    /// `cells` equal cells over `length`.
    Uniform {
        /// segment length [m]
        length: f64,
        /// number of cells [-]
        cells: usize,
    },
    /// `cells` cells whose widths grow geometrically by `growth` from one cell to the next.
    Geometric {
        /// segment length [m]
        length: f64,
        /// number of cells [-]
        cells: usize,
        /// adjacent width ratio w[i+1]/w[i] [-]
        growth: f64,
    },
    /// `cells` cells whose first width is `first`; the growth ratio is solved so that the
    /// widths sum to `length` (MFIX `FIRST_DX` with `NCX`).
    FirstWidth {
        /// segment length [m]
        length: f64,
        /// number of cells [-]
        cells: usize,
        /// width of the first (lowest-coordinate) cell [m]
        first: f64,
    },
    /// `cells` cells whose last width is `last`; the growth ratio is solved so that the
    /// widths sum to `length` (MFIX `LAST_DX` with `NCX`).
    LastWidth {
        /// segment length [m]
        length: f64,
        /// number of cells [-]
        cells: usize,
        /// width of the last (highest-coordinate) cell [m]
        last: f64,
    },
    /// Geometric cells going from width `first` to width `last`. The cell count is the
    /// nearest integer to the continuous solution; the growth is then solved so that the
    /// widths sum to `length` with the **smaller** end width exact (the fine end is the one
    /// that matters); the count is within one cell of the continuous solution, so the other
    /// end moves by about 1/cells relative (times one growth factor) from what was asked. When the two ends are so close that
    /// no whole number of cells admits that, the cells are uniform.
    EndWidths {
        /// segment length [m]
        length: f64,
        /// width of the first cell [m]
        first: f64,
        /// width of the last cell [m]
        last: f64,
    },
}

impl Segment {
    /// The segment length [m].
    pub fn length(&self) -> f64 {
        match *self {
            Segment::Uniform { length, .. }
            | Segment::Geometric { length, .. }
            | Segment::FirstWidth { length, .. }
            | Segment::LastWidth { length, .. }
            | Segment::EndWidths { length, .. } => length,
        }
    }

    /// Checks the segment's numbers, and that it has at most [`MAX_AXIS_CELLS`] cells
    /// (computed without building it). `field` is the path used in error messages.
    pub fn validate(&self, field: &str) -> Result<(), MeshError> {
        self.validate_numbers(field)?;
        let count = self.implied_cell_count();
        if count <= MAX_AXIS_CELLS as f64 {
            return Ok(());
        }
        Err(match *self {
            Segment::EndWidths { .. } => MeshError::Invalid {
                field: field.to_string(),
                value: format!(
                    "length {}, first {}, last {}: {} cells",
                    short(self.length()),
                    short(self.end_width(false)),
                    short(self.end_width(true)),
                    short(count)
                ),
                allowed: format!("widths that give at most {MAX_AXIS_CELLS} cells"),
            },
            Segment::Uniform { cells, .. }
            | Segment::Geometric { cells, .. }
            | Segment::FirstWidth { cells, .. }
            | Segment::LastWidth { cells, .. } => MeshError::Invalid {
                field: format!("{field}.cells"),
                value: cells.to_string(),
                allowed: format!("an integer in [1, {MAX_AXIS_CELLS}]"),
            },
        })
    }

    /// The number of cells, computed without building the segment (for
    /// [`Segment::EndWidths`] from its widths and length); an error for an invalid segment
    /// or one with more than [`MAX_AXIS_CELLS`] cells.
    pub fn cell_count(&self) -> Result<usize, MeshError> {
        self.validate("segment")?;
        Ok(self.implied_cell_count() as usize)
    }

    /// The cell count as a float, so that a huge count implied by end widths is compared
    /// with the cap before it is converted (or allocated).
    fn implied_cell_count(&self) -> f64 {
        match *self {
            Segment::Uniform { cells, .. }
            | Segment::Geometric { cells, .. }
            | Segment::FirstWidth { cells, .. }
            | Segment::LastWidth { cells, .. } => cells as f64,
            Segment::EndWidths {
                length,
                first,
                last,
            } => end_widths_cell_count(length, first, last),
        }
    }

    /// `first` (or `last` when `last_end`) of an `EndWidths` segment, for messages.
    fn end_width(&self, last_end: bool) -> f64 {
        match *self {
            Segment::EndWidths { first, last, .. } => {
                if last_end {
                    last
                } else {
                    first
                }
            }
            _ => f64::NAN,
        }
    }

    /// The checks of [`Segment::validate`] that need no cell count.
    fn validate_numbers(&self, field: &str) -> Result<(), MeshError> {
        let positive = |name: &str, v: f64| -> Result<(), MeshError> {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(MeshError::Invalid {
                    field: format!("{field}.{name}"),
                    value: short(v),
                    allowed: "a finite number > 0".into(),
                })
            }
        };
        let cells_ok = |cells: usize| -> Result<(), MeshError> {
            if cells >= 1 {
                Ok(())
            } else {
                Err(MeshError::Invalid {
                    field: format!("{field}.cells"),
                    value: cells.to_string(),
                    allowed: format!("an integer in [1, {MAX_AXIS_CELLS}]"),
                })
            }
        };
        let width_below_length = |name: &str, w: f64, length: f64| -> Result<(), MeshError> {
            if w <= length {
                Ok(())
            } else {
                Err(MeshError::Invalid {
                    field: format!("{field}.{name}"),
                    value: short(w),
                    allowed: format!("(0, length = {}]", short(length)),
                })
            }
        };
        positive("length", self.length())?;
        match *self {
            Segment::Uniform { cells, .. } => cells_ok(cells),
            Segment::Geometric { cells, growth, .. } => {
                cells_ok(cells)?;
                positive("growth", growth)
            }
            Segment::FirstWidth {
                length,
                cells,
                first,
            } => {
                cells_ok(cells)?;
                positive("first", first)?;
                width_below_length("first", first, length)?;
                if cells == 1 && (first - length).abs() > 1e-12 * length {
                    return Err(MeshError::Invalid {
                        field: format!("{field}.first"),
                        value: short(first),
                        allowed: format!("= length ({}) when cells = 1", short(length)),
                    });
                }
                Ok(())
            }
            Segment::LastWidth {
                length,
                cells,
                last,
            } => {
                cells_ok(cells)?;
                positive("last", last)?;
                width_below_length("last", last, length)?;
                if cells == 1 && (last - length).abs() > 1e-12 * length {
                    return Err(MeshError::Invalid {
                        field: format!("{field}.last"),
                        value: short(last),
                        allowed: format!("= length ({}) when cells = 1", short(length)),
                    });
                }
                Ok(())
            }
            Segment::EndWidths {
                length,
                first,
                last,
            } => {
                positive("first", first)?;
                positive("last", last)?;
                width_below_length("first", first, length)?;
                width_below_length("last", last, length)?;
                if first + last > length * (1.0 + 1e-12) && (first - last).abs() > 1e-12 * length {
                    return Err(MeshError::Invalid {
                        field: format!("{field}.first + last"),
                        value: short(first + last),
                        allowed: format!("≤ length ({}) unless first = last", short(length)),
                    });
                }
                Ok(())
            }
        }
    }

    /// The same segment with cells `factor` times wider (for the fidelity presets): cell
    /// counts divided by `factor` (rounded, at least 1), widths multiplied by it and growth
    /// raised to its power, so the coarse grid keeps the shape of the fine one.
    pub fn coarsened(&self, factor: u32) -> Segment {
        let f = f64::from(factor.max(1));
        let fewer = |cells: usize| ((cells as f64 / f).round() as usize).max(1);
        match *self {
            Segment::Uniform { length, cells } => Segment::Uniform {
                length,
                cells: fewer(cells),
            },
            Segment::Geometric {
                length,
                cells,
                growth,
            } => Segment::Geometric {
                length,
                cells: fewer(cells),
                growth: growth.powf(f),
            },
            Segment::FirstWidth {
                length,
                cells,
                first,
            } => {
                let cells = fewer(cells);
                let first = if cells == 1 {
                    length
                } else {
                    (first * f).min(length)
                };
                Segment::FirstWidth {
                    length,
                    cells,
                    first,
                }
            }
            Segment::LastWidth {
                length,
                cells,
                last,
            } => {
                let cells = fewer(cells);
                let last = if cells == 1 {
                    length
                } else {
                    (last * f).min(length)
                };
                Segment::LastWidth {
                    length,
                    cells,
                    last,
                }
            }
            Segment::EndWidths {
                length,
                first,
                last,
            } => {
                let (first, last) = (first * f, last * f);
                if first + last > length {
                    // Too coarse for two distinct ends: one or two equal cells.
                    let cells = ((2.0 * length / (first + last)).round() as usize).max(1);
                    Segment::Uniform { length, cells }
                } else {
                    Segment::EndWidths {
                        length,
                        first,
                        last,
                    }
                }
            }
        }
    }

    /// The same segment with cells `factor` times narrower (the inverse of
    /// [`Segment::coarsened`], for grid-convergence studies): cell counts multiplied by
    /// `factor`, widths divided by it and growth raised to the power 1/`factor`, so the fine
    /// grid keeps the shape of the original. `refined(f).coarsened(f)` is the segment again
    /// (up to the round-off of the width and growth arithmetic).
    pub fn refined(&self, factor: u32) -> Segment {
        let f = f64::from(factor.max(1));
        let more = |cells: usize| cells.saturating_mul(factor.max(1) as usize);
        match *self {
            Segment::Uniform { length, cells } => Segment::Uniform {
                length,
                cells: more(cells),
            },
            Segment::Geometric {
                length,
                cells,
                growth,
            } => Segment::Geometric {
                length,
                cells: more(cells),
                growth: growth.powf(1.0 / f),
            },
            Segment::FirstWidth {
                length,
                cells,
                first,
            } => Segment::FirstWidth {
                length,
                cells: more(cells),
                first: first / f,
            },
            Segment::LastWidth {
                length,
                cells,
                last,
            } => Segment::LastWidth {
                length,
                cells: more(cells),
                last: last / f,
            },
            Segment::EndWidths {
                length,
                first,
                last,
            } => Segment::EndWidths {
                length,
                first: first / f,
                last: last / f,
            },
        }
    }

    /// The cell widths of this segment, lowest coordinate first.
    pub fn widths(&self) -> Result<Vec<f64>, MeshError> {
        self.validate("segment")?;
        Ok(match *self {
            Segment::Uniform { length, cells } => vec![length / cells as f64; cells],
            Segment::Geometric {
                length,
                cells,
                growth,
            } => geometric_widths(length, cells, growth),
            Segment::FirstWidth {
                length,
                cells,
                first,
            } => {
                let growth = solve_growth(length, cells, first)?;
                geometric_widths(length, cells, growth)
            }
            Segment::LastWidth {
                length,
                cells,
                last,
            } => {
                let growth = solve_growth(length, cells, last)?;
                let mut w = geometric_widths(length, cells, growth);
                w.reverse();
                w
            }
            Segment::EndWidths {
                length,
                first,
                last,
            } => {
                let (small, big) = (first.min(last), first.max(last));
                // validate() bounded the count by MAX_AXIS_CELLS
                let cells = end_widths_cell_count(length, first, last) as usize;
                // With the small end exact, a monotone segment needs
                // cells·small ≤ length ≤ cells·big.
                let monotone = (cells as f64) * small <= length * (1.0 + 1e-12)
                    && (cells as f64) * big >= length * (1.0 - 1e-12);
                let mut w = if cells == 1 || !monotone {
                    vec![length / cells as f64; cells]
                } else {
                    geometric_widths(length, cells, solve_growth(length, cells, small)?)
                };
                if last < first {
                    w.reverse();
                }
                w
            }
        })
    }
}

/// Widths w_k = w_0 g^k (k = 0..n-1) with Σ w_k = length exactly up to round-off: the
/// last width absorbs the rounding error of the sum.
fn geometric_widths(length: f64, cells: usize, growth: f64) -> Vec<f64> {
    // Σ g^k = (g^n - 1)/(g - 1); written via ln for g near 1 to avoid cancellation.
    let sum_of_powers = if (growth - 1.0).abs() < 1e-12 {
        cells as f64
    } else {
        let n = cells as f64;
        (n * growth.ln()).exp_m1() / (growth - 1.0)
    };
    let first = length / sum_of_powers;
    let mut widths: Vec<f64> = (0..cells).map(|k| first * growth.powi(k as i32)).collect();
    // Rescale away the round-off of the closed-form sum; ratios stay exact.
    let scale = length / widths.iter().sum::<f64>();
    widths.iter_mut().for_each(|w| *w *= scale);
    widths
}

/// Growth g > 0 such that `first` · Σ_{k<n} g^k = `length` (MFIX FIRST_DX with NCX).
/// The sum is monotone in g, so bisection on ln g is robust for any admissible input.
fn solve_growth(length: f64, cells: usize, first: f64) -> Result<f64, MeshError> {
    let n = cells as f64;
    let target = length / first;
    if cells == 1 {
        return Ok(1.0);
    }
    if (target - n).abs() <= 1e-13 * n {
        return Ok(1.0);
    }
    // f(s) = Σ e^{ks} - target, increasing in s = ln g.
    let sum = |s: f64| -> f64 {
        if s.abs() < 1e-300 {
            n
        } else {
            (n * s).exp_m1() / s.exp_m1()
        }
    };
    let (mut lo, mut hi) = if target > n { (0.0, 1.0) } else { (-1.0, 0.0) };
    while sum(hi) < target {
        hi *= 2.0;
        if hi > 700.0 {
            return Err(MeshError::Unsolvable(format!(
                "no growth ratio gives {cells} cells of first width {first} in length {length}"
            )));
        }
    }
    while sum(lo) > target {
        lo *= 2.0;
        if lo < -700.0 {
            return Err(MeshError::Unsolvable(format!(
                "no growth ratio gives {cells} cells of first width {first} in length {length}"
            )));
        }
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if sum(mid) < target {
            lo = mid;
        } else {
            hi = mid;
        }
        if (hi - lo).abs() <= SOLVE_RTOL * hi.abs().max(1e-300) {
            break;
        }
    }
    Ok((0.5 * (lo + hi)).exp())
}

/// Cell count for a geometric segment from `first` to `last`: with g = (L − first)/(L − last)
/// the continuous count is n = 1 + ln(last/first)/ln g. The nearest integer is used,
/// moved into [⌈L/big⌉, ⌊L/small⌋] when that range is not empty, so that a monotone
/// segment with the small end exact exists. A float (possibly huge or infinite: a first
/// width of 1e-300 m, a length of 1e300 m), so that it is bounded before any conversion.
fn end_widths_cell_count(length: f64, first: f64, last: f64) -> f64 {
    if (first - last).abs() <= 1e-12 * length {
        return (length / first).round().max(1.0);
    }
    let growth = (length - first) / (length - last);
    let n = (1.0 + (last / first).ln() / growth.ln()).round().max(1.0);
    let (small, big) = (first.min(last), first.max(last));
    let lo = (length / big * (1.0 - 1e-12)).ceil().max(1.0);
    let hi = (length / small * (1.0 + 1e-12)).floor();
    if lo <= hi {
        n.clamp(lo, hi)
    } else {
        n
    }
}

/// The number of cells of consecutive segments, each validated (its path
/// `segments[k]`), without building them; an error above [`MAX_AXIS_CELLS`].
pub(crate) fn total_cells(segments: &[Segment]) -> Result<usize, MeshError> {
    let mut total = 0usize;
    for (k, seg) in segments.iter().enumerate() {
        seg.validate(&format!("segments[{k}]"))?;
        total = total.saturating_add(seg.implied_cell_count() as usize);
    }
    if total > MAX_AXIS_CELLS {
        return Err(MeshError::Invalid {
            field: "segments".into(),
            value: format!("{total} cells in all"),
            allowed: format!("at most {MAX_AXIS_CELLS} cells per axis"),
        });
    }
    Ok(total)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Axis;

    fn axis(s: &Segment) -> Axis {
        Axis::from_segments(0.0, std::slice::from_ref(s)).unwrap()
    }

    /// Largest distance of the refined axis's every `f`-th face from the original faces,
    /// relative to the original cell width there.
    fn nesting_deviation(s: &Segment, f: u32) -> f64 {
        let (a, b) = (axis(s), axis(&s.refined(f)));
        (0..a.len())
            .map(|k| (b.faces()[k * f as usize] - a.faces()[k]).abs() / a.widths()[k])
            .fold(0.0, f64::max)
    }

    #[test]
    fn refined_segments_have_f_times_the_cells_and_the_same_shape() {
        let segments = [
            Segment::Uniform {
                length: 0.3,
                cells: 60,
            },
            Segment::Geometric {
                length: 1.5,
                cells: 30,
                growth: 1.13,
            },
            Segment::FirstWidth {
                length: 1.5,
                cells: 30,
                first: 0.005,
            },
            Segment::LastWidth {
                length: 1.5,
                cells: 25,
                last: 0.05,
            },
            Segment::EndWidths {
                length: 1.5,
                first: 0.01,
                last: 0.05,
            },
        ];
        for s in &segments {
            for f in [2u32, 3] {
                let (a, r) = (axis(s), s.refined(f));
                let b = axis(&r);
                assert!(
                    (b.length() - a.length()).abs() < 1e-12,
                    "{s:?}: length kept"
                );
                // EndWidths solves its count from the widths: within one cell of f × n
                let expected = f as usize * a.len();
                assert!(
                    b.len().abs_diff(expected) <= 1,
                    "{s:?} × {f}: {} cells",
                    b.len()
                );
                // a stated end width is exact: 1/f of the original's (a geometric segment's
                // first width follows from its growth: it nests instead, checked below)
                if !matches!(s, Segment::Geometric { .. }) {
                    let (fine_a, fine_b) = (a.width_range().0, b.width_range().0);
                    assert!(
                        (fine_b * f64::from(f) - fine_a).abs() < 1e-12 * fine_a,
                        "{s:?} × {f}"
                    );
                }
                // adjacent ratios are the f-th root of the original's
                let (ga, gb) = (a.max_adjacent_ratio(), b.max_adjacent_ratio());
                assert!(
                    (gb.powi(f as i32) / ga - 1.0).abs() < 0.02,
                    "{s:?} × {f}: growth {gb} against {ga}^(1/{f})"
                );
                // coarsening undoes the refinement
                match (s, r.coarsened(f)) {
                    (
                        Segment::Geometric { growth: g0, .. },
                        Segment::Geometric {
                            growth: g1, cells, ..
                        },
                    ) => {
                        assert_eq!(cells, a.len());
                        assert!((g1 - g0).abs() < 1e-12);
                    }
                    (s, back) => assert_eq!(&back, s),
                }
            }
        }
        // uniform and geometric refinements nest exactly: every f-th face is an original one
        for s in &segments[..2] {
            assert!(nesting_deviation(s, 2) < 1e-12, "{s:?}");
            assert!(nesting_deviation(s, 3) < 1e-12, "{s:?}");
        }
        // solved growths keep the shape within a fraction of a cell
        for s in &segments[2..] {
            assert!(
                nesting_deviation(s, 2) < 0.2,
                "{s:?}: {}",
                nesting_deviation(s, 2)
            );
        }
        // factor 1 (and 0, read as 1) changes nothing
        assert_eq!(segments[2].refined(1), segments[2]);
        assert_eq!(segments[2].refined(0), segments[2]);
    }
}
