//! The direction of a staggered velocity component as a type: [`X`] for u on the x-faces,
//! [`Y`] for v on the y-faces (docs/model.md §4.1). A term of the momentum equation
//! (docs/model.md §4.4) is written once in the component's own coordinates, a along the
//! component and b across it, and compiled once per direction; the direction answers the
//! index maps: position (a, b) as (i, j), the cell, the node of its own and of the other
//! component's block, the control-volume faces normal to it (along) and beside it (across),
//! the axes, the sides at its ends and its walls. The runtime view of the same component is
//! [`crate::staggered::Component`].
//!
//! Cell indices are i + nx j, u nodes i + (nx + 1) j, v nodes i + nx j.

use std::ops::Range;

use runout_mesh::{Axis, Grid, Sides};

use crate::momentum::MassFluxes;
use crate::transport::FaceData;

/// A direction of the staggered grid (module doc).
pub(crate) trait Direction {
    /// 0 for x (u), 1 for y (v), as [`crate::staggered::Component`]'s `dir`
    const DIR: usize;

    /// `x` for x, `y` for y.
    fn pick<T>(x: T, y: T) -> T;

    /// (i, j) of position (a, b).
    fn xy(a: usize, b: usize) -> (usize, usize);

    /// Position (a, b) of (i, j), the inverse of [`Direction::xy`].
    #[inline]
    fn ab(i: usize, j: usize) -> (usize, usize) {
        Self::pick((i, j), (j, i))
    }

    /// Nodes per row of the component's block in a grid `nx` cells wide.
    #[inline]
    fn row_len(nx: usize) -> usize {
        Self::pick(nx + 1, nx)
    }

    /// Visits every (a, b) of `along` × `across` in memory order (j outer, i inner).
    #[inline]
    fn for_each(along: Range<usize>, across: Range<usize>, mut f: impl FnMut(usize, usize)) {
        let (is, js) = Self::pick((along.clone(), across.clone()), (across, along));
        for j in js {
            for i in is.clone() {
                let (a, b) = Self::ab(i, j);
                f(a, b);
            }
        }
    }

    /// The grid axis along the direction.
    #[inline]
    fn along(grid: &Grid) -> &Axis {
        Self::pick(&grid.x, &grid.y)
    }

    /// The grid axis across the direction.
    #[inline]
    fn across(grid: &Grid) -> &Axis {
        Self::pick(&grid.y, &grid.x)
    }

    /// Whether the component's column wraps: u of a periodic-x grid (`Grid::periodic_x`).
    #[inline]
    fn periodic(grid: &Grid) -> bool {
        Self::pick(grid.periodic_x(), false)
    }

    /// Cell (a, b) of a grid `nx` cells wide.
    #[inline]
    fn cell(a: usize, b: usize, nx: usize) -> usize {
        let (i, j) = Self::xy(a, b);
        i + nx * j
    }

    /// Node (a, b) of the component's own block.
    #[inline]
    fn node(a: usize, b: usize, nx: usize) -> usize {
        let (i, j) = Self::xy(a, b);
        i + Self::row_len(nx) * j
    }

    /// Node (a, b) of the other component's block: the scalar-cell face across the direction
    /// at b (bottom of cell a, b for u; west of it for v).
    #[inline]
    fn cross_node(a: usize, b: usize, nx: usize) -> usize {
        let (i, j) = Self::xy(a, b);
        i + Self::pick(nx, nx + 1) * j
    }

    /// The control-volume face normal to the direction between nodes (a − 1, b) and (a, b)
    /// (index into [`Direction::along_faces`]).
    #[inline]
    fn along_face(faces: &FaceData, a: usize, b: usize) -> usize {
        let (i, j) = Self::xy(a, b);
        Self::pick(faces.xf(i, j), faces.yf(i, j))
    }

    /// The control-volume face across the direction between nodes (a, b − 1) and (a, b)
    /// (index into [`Direction::across_faces`]).
    #[inline]
    fn across_face(faces: &FaceData, a: usize, b: usize) -> usize {
        let (i, j) = Self::xy(a, b);
        Self::pick(faces.yf(i, j), faces.xf(i, j))
    }

    /// (flux, conductance) of the faces normal to the direction.
    #[inline]
    fn along_faces(faces: &mut FaceData) -> (&mut [f64], &mut [f64]) {
        let FaceData {
            flux_x,
            flux_y,
            cond_x,
            cond_y,
            ..
        } = faces;
        Self::pick((flux_x, cond_x), (flux_y, cond_y))
    }

    /// (flux, conductance) of the faces across the direction.
    #[inline]
    fn across_faces(faces: &mut FaceData) -> (&mut [f64], &mut [f64]) {
        let FaceData {
            flux_x,
            flux_y,
            cond_x,
            cond_y,
            ..
        } = faces;
        Self::pick((flux_y, cond_y), (flux_x, cond_x))
    }

    /// The scalar-cell mass fluxes through the faces normal to the direction (at the own
    /// nodes) and across it (at the other component's nodes).
    #[inline]
    fn mass_fluxes(fluxes: &MassFluxes) -> (&[f64], &[f64]) {
        Self::pick((&fluxes.x, &fluxes.y), (&fluxes.y, &fluxes.x))
    }

    /// The sides at the low and the high end along the direction (west, east for x).
    #[inline]
    fn ends<T>(sides: &Sides<T>) -> (&T, &T) {
        Self::pick((&sides.west, &sides.east), (&sides.south, &sides.north))
    }

    /// The walls at the low and the high end across the direction (south, north for x).
    #[inline]
    fn walls<T>(sides: &Sides<T>) -> (&T, &T) {
        Self::pick((&sides.south, &sides.north), (&sides.west, &sides.east))
    }
}

/// x: u on the x-faces.
pub(crate) struct X;

/// y: v on the y-faces.
pub(crate) struct Y;

impl Direction for X {
    const DIR: usize = 0;

    #[inline]
    fn pick<T>(x: T, _: T) -> T {
        x
    }

    #[inline]
    fn xy(a: usize, b: usize) -> (usize, usize) {
        (a, b)
    }
}

impl Direction for Y {
    const DIR: usize = 1;

    #[inline]
    fn pick<T>(_: T, y: T) -> T {
        y
    }

    #[inline]
    fn xy(a: usize, b: usize) -> (usize, usize) {
        (b, a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn index_maps_follow_the_staggered_blocks() {
        let nx = 3;
        // u node (a, b) = (2, 1) is (i, j) = (2, 1); v node (a, b) = (2, 1) is (1, 2)
        assert_eq!(X::node(2, 1, nx), 2 + 4);
        assert_eq!(Y::node(2, 1, nx), 1 + 3 * 2);
        assert_eq!(X::cell(2, 1, nx), Y::cell(1, 2, nx));
        assert_eq!(X::cross_node(2, 1, nx), 2 + 3);
        assert_eq!(Y::cross_node(2, 1, nx), 1 + 4 * 2);
        let faces = FaceData::zeros(nx, 4);
        assert_eq!(Y::along_face(&faces, 2, 1), faces.yf(1, 2));
        assert_eq!(Y::across_face(&faces, 2, 1), faces.xf(1, 2));
        let mut seen = Vec::new();
        Y::for_each(0..2, 0..3, |a, b| seen.push(Y::xy(a, b)));
        assert_eq!(seen[..4], [(0, 0), (1, 0), (2, 0), (0, 1)]);
    }
}
