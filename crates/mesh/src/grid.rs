//! The 2-D staggered (MAC) grid of MFIX (docs/model.md §4.1).
//!
//! Scalars (ε, P, θ) live at cell centres (i, j); u at east faces (i+½, j); v at north
//! faces (i, j+½). x runs down the channel, y is wall-normal, the floor is y = y0.
//! Linear indices run fastest in x: cell (i, j) ↦ i + nx·j.

use std::fmt;

use serde::{Deserialize, Serialize};

use crate::axis::Axis;
use crate::segment::{total_cells, Segment};
use crate::MeshError;

/// A side of the rectangular domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Side {
    /// x = x0 (upstream end).
    West,
    /// x = x1 (downstream end).
    East,
    /// y = y0 (the floor).
    South,
    /// y = y1 (the top).
    North,
}

impl Side {
    /// All four sides in the order west, east, south, north.
    pub const ALL: [Side; 4] = [Side::West, Side::East, Side::South, Side::North];

    /// Unit normal pointing out of the domain (from the fluid into the wall, MFIX's
    /// convention for Robin conditions, docs/model.md §0.3).
    pub fn outward_normal(self) -> (f64, f64) {
        match self {
            Side::West => (-1.0, 0.0),
            Side::East => (1.0, 0.0),
            Side::South => (0.0, -1.0),
            Side::North => (0.0, 1.0),
        }
    }

    /// Whether the side runs along x (the floor and the top), so that its faces are
    /// counted by the cells along x; the west and east sides run along y.
    pub fn is_horizontal(self) -> bool {
        matches!(self, Side::South | Side::North)
    }

    /// Lower-case name, as in case files and messages.
    pub fn name(self) -> &'static str {
        match self {
            Side::West => "west",
            Side::East => "east",
            Side::South => "south",
            Side::North => "north",
        }
    }
}

/// One value per side of the domain.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sides<T> {
    /// x = x0
    pub west: T,
    /// x = x1
    pub east: T,
    /// y = y0 (floor)
    pub south: T,
    /// y = y1 (top)
    pub north: T,
}

impl<T: Clone> Sides<T> {
    /// The same value on every side.
    pub fn all(value: T) -> Self {
        Sides {
            west: value.clone(),
            east: value.clone(),
            south: value.clone(),
            north: value,
        }
    }
}

impl<T> Sides<T> {
    /// The value `f(side)` on each side.
    pub fn from_fn(mut f: impl FnMut(Side) -> T) -> Self {
        Sides {
            west: f(Side::West),
            east: f(Side::East),
            south: f(Side::South),
            north: f(Side::North),
        }
    }

    /// The value on `side`.
    pub fn get(&self, side: Side) -> &T {
        match side {
            Side::West => &self.west,
            Side::East => &self.east,
            Side::South => &self.south,
            Side::North => &self.north,
        }
    }

    /// The value on `side`, mutable.
    pub fn get_mut(&mut self, side: Side) -> &mut T {
        match side {
            Side::West => &mut self.west,
            Side::East => &mut self.east,
            Side::South => &mut self.south,
            Side::North => &mut self.north,
        }
    }

    /// Iterates over (side, value) in the order of [`Side::ALL`].
    pub fn iter(&self) -> impl Iterator<Item = (Side, &T)> {
        Side::ALL.into_iter().map(move |s| (s, self.get(s)))
    }
}

/// The grid of one direction as segments from an origin (what a case file states).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AxisSpec {
    /// coordinate of the first face [m]
    #[serde(default)]
    pub origin: f64,
    /// consecutive segments, lowest coordinate first
    pub segments: Vec<Segment>,
}

impl AxisSpec {
    /// Builds the axis.
    pub fn build(&self) -> Result<Axis, MeshError> {
        Axis::from_segments(self.origin, &self.segments)
    }

    /// The number of cells, computed without building the axis; an error for an invalid
    /// segment (its path `segments[k]`) or more than [`crate::MAX_AXIS_CELLS`] cells.
    pub fn cell_count(&self) -> Result<usize, MeshError> {
        total_cells(&self.segments)
    }

    /// The same axis with cells `factor` times wider (see [`Segment::coarsened`]).
    pub fn coarsened(&self, factor: u32) -> AxisSpec {
        AxisSpec {
            origin: self.origin,
            segments: self.segments.iter().map(|s| s.coarsened(factor)).collect(),
        }
    }

    /// The same axis with cells `factor` times narrower (see [`Segment::refined`]).
    pub fn refined(&self, factor: u32) -> AxisSpec {
        AxisSpec {
            origin: self.origin,
            segments: self.segments.iter().map(|s| s.refined(factor)).collect(),
        }
    }

    /// End coordinate: origin plus the segment lengths [m].
    pub fn end(&self) -> f64 {
        self.origin + self.segments.iter().map(Segment::length).sum::<f64>()
    }
}

/// A stretched rectangular staggered grid.
#[derive(Clone, Debug, PartialEq)]
pub struct Grid {
    /// the x (along-channel) axis
    pub x: Axis,
    /// the y (wall-normal) axis
    pub y: Axis,
}

impl Grid {
    /// A grid from two axes.
    pub fn new(x: Axis, y: Axis) -> Grid {
        Grid { x, y }
    }

    /// A grid from the segment descriptions of both directions.
    pub fn from_specs(x: &AxisSpec, y: &AxisSpec) -> Result<Grid, MeshError> {
        Ok(Grid {
            x: x.build()?,
            y: y.build()?,
        })
    }

    /// Whether the x axis is periodic ([`Axis::periodic`]).
    pub fn periodic_x(&self) -> bool {
        self.x.is_periodic()
    }

    /// Cells in x.
    pub fn nx(&self) -> usize {
        self.x.len()
    }

    /// Cells in y.
    pub fn ny(&self) -> usize {
        self.y.len()
    }

    /// Number of cells (scalar unknowns).
    pub fn cell_count(&self) -> usize {
        self.nx() * self.ny()
    }

    /// Linear index of cell (i, j), x fastest.
    #[inline]
    pub fn cell_index(&self, i: usize, j: usize) -> usize {
        i + self.nx() * j
    }

    /// (i, j) of a linear cell index.
    #[inline]
    pub fn cell_ij(&self, index: usize) -> (usize, usize) {
        (index % self.nx(), index / self.nx())
    }

    /// Number of u-faces (east/west faces): (nx + 1) × ny, including the two end walls.
    pub fn u_face_count(&self) -> usize {
        (self.nx() + 1) * self.ny()
    }

    /// Linear index of the u-face at x-face i (0..=nx), row j; x fastest.
    #[inline]
    pub fn u_face_index(&self, i: usize, j: usize) -> usize {
        i + (self.nx() + 1) * j
    }

    /// Number of v-faces (south/north faces): nx × (ny + 1), including floor and top.
    pub fn v_face_count(&self) -> usize {
        self.nx() * (self.ny() + 1)
    }

    /// Linear index of the v-face in column i, at y-face j (0..=ny); x fastest.
    #[inline]
    pub fn v_face_index(&self, i: usize, j: usize) -> usize {
        i + self.nx() * j
    }

    /// Centre of cell (i, j) [m].
    pub fn cell_centre(&self, i: usize, j: usize) -> (f64, f64) {
        (self.x.centres()[i], self.y.centres()[j])
    }

    /// Position of the u-face (i, j): x-face i, centre height of row j [m].
    pub fn u_face_position(&self, i: usize, j: usize) -> (f64, f64) {
        (self.x.faces()[i], self.y.centres()[j])
    }

    /// Position of the v-face (i, j): centre of column i, y-face j [m].
    pub fn v_face_position(&self, i: usize, j: usize) -> (f64, f64) {
        (self.x.centres()[i], self.y.faces()[j])
    }

    /// Volume per unit depth of cell (i, j) [m²].
    pub fn cell_volume(&self, i: usize, j: usize) -> f64 {
        self.x.widths()[i] * self.y.widths()[j]
    }

    /// Volume per unit depth of the u momentum cell at x-face i (it spans centre i−1 to
    /// centre i, ghost widths at the ends, docs/model.md §4.1) [m²].
    pub fn u_cell_volume(&self, i: usize, j: usize) -> f64 {
        self.x.face_spacing()[i] * self.y.widths()[j]
    }

    /// Volume per unit depth of the v momentum cell at y-face j [m²].
    pub fn v_cell_volume(&self, i: usize, j: usize) -> f64 {
        self.x.widths()[i] * self.y.face_spacing()[j]
    }

    /// The cell (i, j) that contains the point, `None` outside the domain.
    pub fn locate(&self, x: f64, y: f64) -> Option<(usize, usize)> {
        Some((self.x.locate(x)?, self.y.locate(y)?))
    }

    /// Whether the point lies in the closed domain rectangle.
    pub fn contains(&self, x: f64, y: f64) -> bool {
        self.locate(x, y).is_some()
    }

    /// Cells adjacent to `side`, as (i, j), in increasing order along the side.
    pub fn boundary_cells(&self, side: Side) -> Vec<(usize, usize)> {
        let (nx, ny) = (self.nx(), self.ny());
        match side {
            Side::West => (0..ny).map(|j| (0, j)).collect(),
            Side::East => (0..ny).map(|j| (nx - 1, j)).collect(),
            Side::South => (0..nx).map(|i| (i, 0)).collect(),
            Side::North => (0..nx).map(|i| (i, ny - 1)).collect(),
        }
    }

    /// Size of the face of a boundary cell that lies on `side` (per unit depth) [m], and the
    /// distance from that cell's centre to its ghost neighbour's centre (the cell's own
    /// width, docs/model.md §3.1) [m].
    pub fn boundary_face_geometry(&self, side: Side, i: usize, j: usize) -> (f64, f64) {
        match side {
            Side::West | Side::East => (self.y.widths()[j], self.x.widths()[i]),
            Side::South | Side::North => (self.x.widths()[i], self.y.widths()[j]),
        }
    }

    /// Summary numbers of the grid (what `runout mesh` prints).
    pub fn summary(&self) -> GridSummary {
        let (dx_min, dx_max) = self.x.width_range();
        let (dy_min, dy_max) = self.y.width_range();
        // Largest aspect ratio over all cells: the extreme pairs of widths bound it.
        let aspect = (dx_max / dy_min).max(dy_max / dx_min);
        GridSummary {
            nx: self.nx(),
            ny: self.ny(),
            x_range: (self.x.start(), self.x.end()),
            y_range: (self.y.start(), self.y.end()),
            dx_min,
            dx_max,
            dy_min,
            dy_max,
            max_adjacent_ratio_x: self.x.max_adjacent_ratio(),
            max_adjacent_ratio_y: self.y.max_adjacent_ratio(),
            max_aspect_ratio: aspect.max(1.0),
        }
    }
}

/// What `runout mesh` reports about a grid.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct GridSummary {
    /// cells in x
    pub nx: usize,
    /// cells in y
    pub ny: usize,
    /// (x0, x1) [m]
    pub x_range: (f64, f64),
    /// (y0, y1) [m]
    pub y_range: (f64, f64),
    /// smallest cell width in x [m]
    pub dx_min: f64,
    /// largest cell width in x [m]
    pub dx_max: f64,
    /// smallest cell height in y [m]
    pub dy_min: f64,
    /// largest cell height in y [m]
    pub dy_max: f64,
    /// largest ratio of adjacent widths in x [-]
    pub max_adjacent_ratio_x: f64,
    /// largest ratio of adjacent heights in y [-]
    pub max_adjacent_ratio_y: f64,
    /// largest cell aspect ratio max(Δx/Δy, Δy/Δx) [-]
    pub max_aspect_ratio: f64,
}

impl fmt::Display for GridSummary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "cells: {} x {} = {}",
            self.nx,
            self.ny,
            self.nx * self.ny
        )?;
        writeln!(
            f,
            "x: [{}, {}] m, dx min {:.6} m, max {:.6} m, largest adjacent ratio {:.4}",
            self.x_range.0, self.x_range.1, self.dx_min, self.dx_max, self.max_adjacent_ratio_x
        )?;
        writeln!(
            f,
            "y: [{}, {}] m, dy min {:.6} m, max {:.6} m, largest adjacent ratio {:.4}",
            self.y_range.0, self.y_range.1, self.dy_min, self.dy_max, self.max_adjacent_ratio_y
        )?;
        write!(f, "largest aspect ratio: {:.3}", self.max_aspect_ratio)
    }
}
