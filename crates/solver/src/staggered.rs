//! One staggered velocity component: u on the x-faces or v on the y-faces (docs/model.md
//! §4.1). The momentum equation is the same in x and y (docs/model.md §4.4); what differs
//! between u and v is only the node block, which cells lie beside a node, the area of its
//! face and which wall a fixed node sits on. [`Component`] answers those questions, so the
//! partial elimination, the dilute-face rules and the wall rows of the two-fluid momentum
//! stage are written once for both components, and every caller of the momentum assembly
//! ([`crate::momentum::assemble`]) names the component instead of choosing a function.
//!
//! Node (i, j) of u lies on the x-face between cells (i − 1, j) and (i, j), node (i, j) of v
//! on the y-face between cells (i, j − 1) and (i, j); a node on the domain boundary has one
//! cell beside it. Cell indices are k = i + nx·j, node indices k = i + mx·j.
//!
//! A position can also be named in the component's own coordinates (a, b): a along the
//! component (x for u, y for v), b across it ([`Component::xy`]).

use runout_mesh::{Axis, Grid, Sides};

/// A staggered velocity component as a view of the grid (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Component {
    /// 0: u on the x-faces, 1: v on the y-faces
    pub(crate) dir: usize,
    /// cells per row
    pub(crate) nx: usize,
    /// cells per column
    pub(crate) ny: usize,
    /// nodes per row of the component's block
    pub(crate) mx: usize,
    /// nodes per column of the component's block
    pub(crate) my: usize,
    /// u of a periodic-x column (`Grid::periodic_x`): node 0 lies between cell
    /// nx − 1 and cell 0, and there is no x gradient of P'_g or of K_cp ε'
    pub(crate) periodic: bool,
}

impl Component {
    /// u on the x-faces ((nx + 1) × ny nodes).
    pub fn u(nx: usize, ny: usize, periodic_x: bool) -> Self {
        Component {
            dir: 0,
            nx,
            ny,
            mx: nx + 1,
            my: ny,
            periodic: periodic_x,
        }
    }

    /// v on the y-faces (nx × (ny + 1) nodes).
    pub fn v(nx: usize, ny: usize) -> Self {
        Component {
            dir: 1,
            nx,
            ny,
            mx: nx,
            my: ny + 1,
            periodic: false,
        }
    }

    /// u, then v.
    pub fn both(nx: usize, ny: usize, periodic_x: bool) -> [Self; 2] {
        [Self::u(nx, ny, periodic_x), Self::v(nx, ny)]
    }

    /// The member of a (u, v) pair that belongs to this component.
    #[inline]
    pub fn pick<T>(self, u: T, v: T) -> T {
        if self.dir == 0 {
            u
        } else {
            v
        }
    }

    /// The grid axis along the component (x for u, y for v).
    #[inline]
    pub fn axis(self, grid: &Grid) -> &Axis {
        self.pick(&grid.x, &grid.y)
    }

    /// The cells (i, j) on the low and the high side of node (i, j), `None` beyond the
    /// domain; with `wrap`, node 0 of a periodic column has cell nx − 1 on its low side.
    pub fn cells(self, i: usize, j: usize, wrap: bool) -> [Option<(usize, usize)>; 2] {
        if self.dir == 0 {
            let west = if wrap && self.periodic && i == 0 {
                Some(self.nx - 1)
            } else {
                i.checked_sub(1)
            };
            [west.map(|c| (c, j)), (i < self.nx).then_some((i, j))]
        } else {
            [
                j.checked_sub(1).map(|r| (i, r)),
                (j < self.ny).then_some((i, j)),
            ]
        }
    }

    /// Whether node (i, j) lies between two cells along the component (not on the domain
    /// boundary of its own direction).
    pub fn interior(self, i: usize, j: usize) -> bool {
        let (along, n) = self.pick((i, self.nx), (j, self.ny));
        along > 0 && along < n
    }

    /// The area (per unit depth) of node (i, j)'s face: Δy_j for u, Δx_i for v.
    pub fn face_area(self, i: usize, j: usize, dx: &[f64], dy: &[f64]) -> f64 {
        if self.dir == 0 {
            dy[j]
        } else {
            dx[i]
        }
    }

    /// The other component of a phase's velocity that MFIX stores at the same index as
    /// node k (the north face of the cell west of a u-node, the east face of the cell south
    /// of a v-node; 0 without that cell), for the speed of the momentum residual
    /// (docs/model.md §4.11).
    pub fn cross_velocity(self, u: &[f64], v: &[f64], low_cell: Option<usize>) -> f64 {
        match (self.dir, low_cell) {
            (0, Some(c)) => v[c + self.nx],
            (1, Some(c)) => u[c + c / self.nx + 1],
            _ => 0.0,
        }
    }

    /// The gas normal velocity (in +x or +y) that fixed node k holds: the inflow through
    /// its wall face (`inflow`: per side, one velocity into the domain per face along it,
    /// empty for none), 0 on impermeable walls.
    pub fn wall_inflow(self, inflow: &Sides<Vec<f64>>, k: usize) -> f64 {
        let at = |faces: &[f64], along: usize| faces.get(along).copied().unwrap_or(0.0);
        if self.dir == 0 {
            let j = k / (self.nx + 1);
            match k % (self.nx + 1) {
                0 => at(&inflow.west, j),
                i if i == self.nx => -at(&inflow.east, j),
                _ => 0.0,
            }
        } else {
            let i = k % self.nx;
            match k / self.nx {
                0 => at(&inflow.south, i),
                j if j == self.ny => -at(&inflow.north, i),
                _ => 0.0,
            }
        }
    }
}

/// The component's own coordinates (a along, b across; module doc).
impl Component {
    /// u and v of `grid` (u periodic where the grid's x axis is).
    pub fn of_grid(grid: &Grid) -> [Self; 2] {
        Self::both(grid.nx(), grid.ny(), grid.periodic_x())
    }

    /// Cells along and across the component: (nx, ny) for u, (ny, nx) for v.
    pub fn cells_along_across(self) -> (usize, usize) {
        self.pick((self.nx, self.ny), (self.ny, self.nx))
    }

    /// (i, j) of position (a, b).
    pub fn xy(self, a: usize, b: usize) -> (usize, usize) {
        self.pick((a, b), (b, a))
    }
}

/// The mean of the phase's u at the (up to) four u nodes around v node (i, j) between rows
/// `south` and `north` (the centrifugal force's u², docs/model.md §9).
pub(crate) fn mean_u_at_v_node(
    u: &[f64],
    nx: usize,
    i: usize,
    south: Option<usize>,
    north: Option<usize>,
) -> f64 {
    let rows = [south, north];
    let (sum, n) = rows.iter().flatten().fold((0.0, 0.0), |(s, n), &r| {
        let k = i + (nx + 1) * r;
        (s + 0.5 * (u[k] + u[k + 1]), n + 1.0)
    });
    if n > 0.0 {
        sum / n
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nodes_see_the_cells_beside_their_face() {
        let (u, v) = (Component::u(3, 2, false), Component::v(3, 2));
        assert_eq!((u.mx, u.my, v.mx, v.my), (4, 2, 3, 3));
        assert_eq!(u.cells(0, 1, true), [None, Some((0, 1))]);
        assert_eq!(u.cells(3, 1, true), [Some((2, 1)), None]);
        assert_eq!(v.cells(2, 1, true), [Some((2, 0)), Some((2, 1))]);
        assert_eq!(v.cells(2, 2, true), [Some((2, 1)), None]);
        assert!(u.interior(2, 0) && !u.interior(3, 0) && !v.interior(1, 0));
        // a periodic column's node 0 has the column's cell on both sides, only when asked
        let p = Component::u(1, 2, true);
        assert_eq!(p.cells(0, 1, true), [Some((0, 1)), Some((0, 1))]);
        assert_eq!(p.cells(0, 1, false), [None, Some((0, 1))]);
        // residual partners: u node (1, 1) stores v of cell (0, 1)'s north face, v node (1, 1)
        // u of cell (1, 0)'s east face
        let uf: Vec<f64> = (0..8).map(f64::from).collect();
        let vf: Vec<f64> = (0..9).map(|x| 10.0 + f64::from(x)).collect();
        assert_eq!(u.cross_velocity(&uf, &vf, Some(3)), vf[6]);
        assert_eq!(v.cross_velocity(&uf, &vf, Some(1)), uf[2]);
        assert_eq!(u.cross_velocity(&uf, &vf, None), 0.0);
    }
}
