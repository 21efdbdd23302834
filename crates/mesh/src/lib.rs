//! runout-mesh: stretched rectangular staggered grids.
//!
//! A direction is described the way MFIX users do it, as consecutive [`Segment`]s
//! (length + cell count + growth ratio, or length + end widths); an [`Axis`] stores its
//! faces and caches centres, widths and centre-to-centre distances; a [`Grid`] pairs two
//! axes into the staggered (MAC) grid of docs/model.md §4.1: scalars at cell centres, u on
//! east faces, v on north faces. [`bent_floor`]: the floor of a slope whose foot turns, in
//! bed-following coordinates (docs/model.md §9). [`interpolate`]: piecewise-linear
//! interpolation in a sampled series.
#![deny(missing_docs)]

mod axis;
pub mod bent_floor;
mod grid;
mod interpolate;
mod number;
mod segment;
#[cfg(feature = "proptest")]
pub mod strategies;

pub use axis::Axis;
pub use grid::{AxisSpec, Grid, GridSummary, Side, Sides};
pub use interpolate::{interpolate, Beyond};
pub use number::short;
pub use segment::{Segment, MAX_AXIS_CELLS};

/// Errors building a grid.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MeshError {
    /// A segment number is out of range.
    #[error("{field} = {value}: allowed {allowed}")]
    Invalid {
        /// field path inside the axis description
        field: String,
        /// the offending value
        value: String,
        /// the allowed range
        allowed: String,
    },
    /// The numbers are each valid but admit no grid.
    #[error("{0}")]
    Unsolvable(String),
}
