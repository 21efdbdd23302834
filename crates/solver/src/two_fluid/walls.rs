//! The near-wall state of the solids wall closures (docs/model.md §3.2, §3.5, §3.6, §3.8):
//! the tangential solids velocity on each wall face that the closures imply (what MFIX's
//! ghost cells put into the strain rates of the wall cells, docs/model.md §4.4), and the
//! per-face Johnson–Jackson, revisited-JJ and Jenkins closures from the state gathered next to
//! the wall as MFIX gathers it (`calc_grbdry.f`, `calc_s_ddot_s.f`, `bc_theta.f`).

use runout_mesh::{Grid, Side, Sides};
use runout_walls::state::{corner_theta, face_theta};
use runout_walls::{MomentumWallState, RobinFace, SolidsWallModel, ThetaWallState, WallStrain};

use super::dilute::{relax_face, turns_back, ClosureCycle};
use super::wall_load::{extra_normal_load, BodyForce, PhaseLoad};
use super::{PhaseCoefficients, PhaseState, PhaseWallClosures, SolidsSpec, State};
use crate::momentum::{harmonic, WallFaces};
use crate::single_phase::SideBc;

/// The slot of `side` in per-node closures.
fn slot(faces: &mut WallFaces, side: Side) -> &mut Option<Vec<RobinFace>> {
    match side {
        Side::West => &mut faces.west,
        Side::East => &mut faces.east,
        Side::South => &mut faces.south,
        Side::North => &mut faces.north,
    }
}

/// Fills `s.wall_face_velocity` with the tangential solids velocity on each wall face (the
/// face value of the wall closure, docs/model.md §3.2: per-node closures of a state-dependent
/// wall, else the side's fixed closure), averaged from the two velocity nodes of each
/// boundary cell to its centre (MFIX AVG_X_E). Returns which sides are walls.
pub(super) fn wall_face_velocities(
    grid: &Grid,
    spec: &SolidsSpec,
    phase: &PhaseState,
    s: &mut PhaseWallClosures,
) -> Sides<bool> {
    let (nx, ny) = (grid.nx(), grid.ny());
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let mut on_wall = Sides {
        west: false,
        east: false,
        south: false,
        north: false,
    };
    for side in [Side::West, Side::East, Side::South, Side::North] {
        let per_node = match side {
            Side::West => s.wall_velocity.west.as_ref(),
            Side::East => s.wall_velocity.east.as_ref(),
            Side::South => s.wall_velocity.south.as_ref(),
            Side::North => s.wall_velocity.north.as_ref(),
        };
        let fixed = spec.momentum_face(side);
        if per_node.is_none() && fixed.is_none() {
            continue;
        }
        let closure = |k: usize| per_node.map_or_else(|| fixed.unwrap(), |f| f[k]);
        let (out, n_cells) = match side {
            Side::West => (&mut s.wall_face_velocity.west, ny),
            Side::East => (&mut s.wall_face_velocity.east, ny),
            Side::South => (&mut s.wall_face_velocity.south, nx),
            Side::North => (&mut s.wall_face_velocity.north, nx),
        };
        for c in 0..n_cells {
            let face = |node: usize| match side {
                Side::South => closure(node).face_value(phase.u[node], dy[0]),
                Side::North => {
                    closure(node).face_value(phase.u[node + (nx + 1) * (ny - 1)], dy[ny - 1])
                }
                Side::West => closure(node).face_value(phase.v[nx * node], dx[0]),
                Side::East => closure(node).face_value(phase.v[nx - 1 + nx * node], dx[nx - 1]),
            };
            out[c] = 0.5 * (face(c) + face(c + 1));
        }
        match side {
            Side::West => on_wall.west = true,
            Side::East => on_wall.east = true,
            Side::South => on_wall.south = true,
            Side::North => on_wall.north = true,
        }
    }
    on_wall
}

/// How the closures of the state-dependent walls are relaxed between outer iterations
/// (`TwoFluidSettings::relax_wall_closures`, `relax_wall_closures_oscillating_only`).
#[derive(Clone, Copy, Debug)]
pub(super) struct WallRelaxation {
    /// ω: new = ω·computed + (1 − ω)·previous
    pub weight: f64,
    /// relax only the nodes whose closure cycles ([`turns_back`])
    pub oscillating_only: bool,
}

impl WallRelaxation {
    /// Whether the cycle watch is on.
    fn watches_cycles(self) -> bool {
        self.oscillating_only && self.weight < 1.0
    }
}

/// The gas next to the walls: its wall closures and velocities (the gas–solids slips use the
/// gas's own wall face values), its pressure (the buoyancy in a wall's normal load).
#[derive(Clone, Copy)]
pub(super) struct GasNearWalls<'a> {
    /// the gas's closure on each side
    pub walls: &'a Sides<SideBc>,
    /// gas u on the x-faces
    pub u: &'a [f64],
    /// gas v on the y-faces
    pub v: &'a [f64],
    /// gas pressure per cell [Pa]
    pub p: &'a [f64],
}

/// Per-face closures of the state-dependent walls from the current iterate (lagged one
/// outer iteration, docs/model.md §3.5 last line), with the near-wall state gathered as MFIX
/// does (docs/model.md §3.5, §3.6; `calc_grbdry.f`, `calc_s_ddot_s.f`, `bc_theta.f`). The
/// ghost values MFIX stores are those the previous closures imply ([`RobinFace::ghost`]):
/// - momentum, at each tangential-velocity node of the wall: εs interpolated between the
///   two fluid cells; θ the mean of the ghost- and fluid-row means over those cells
///   ([`corner_theta`]); the slip from the face value (mean of ghost and fluid); the
///   strain rate at the wall location, with the normal derivative of the tangential
///   velocity (U_F − U_G)/Δ, the normal derivative of the normal velocity from its value
///   at the fluid cell centre and zero on the wall, and the derivative along the wall
///   from the ghost/fluid-mean velocities at the two cell centres;
/// - θ, at each wall cell: the fluid cell's εs; θ the mean of ghost and fluid
///   ([`face_theta`]); the slip from the ghost/fluid-mean tangential velocity at the cell
///   centre.
///
/// Gas–solids slips use the gas's own wall face values. Returns the faces evaluated on each
/// side (the scene's counters).
pub(super) fn update_walls(
    grid: &Grid,
    gas: GasNearWalls<'_>,
    body: &BodyForce<'_>,
    relax: WallRelaxation,
    state: &State,
    (solids, coefficients): (&mut [PhaseWallClosures], &[PhaseCoefficients]),
    specs: &[SolidsSpec],
) -> Sides<u64> {
    let mut evaluated = Sides::<u64>::default();
    let phases = solids.iter_mut().zip(state.phases()).zip(coefficients);
    for (((s, phase), coefficients), spec) in phases.zip(specs) {
        for side in [Side::West, Side::East, Side::South, Side::North] {
            let Some(model) = spec.per_face_model(side) else {
                continue;
            };
            let wall = WallSide::new(grid, side);
            *evaluated.get_mut(side) += wall.n_cells as u64 + 1;
            let gas_face = match gas.walls.get(side) {
                SideBc::Wall(face) => Some(*face),
                _ => None,
            };
            let gas_side = GasSide {
                face: gas_face,
                u: gas.u,
                v: gas.v,
                delta: wall.delta,
            };
            // last iteration's closures (allocated on first use only); a first
            // evaluation starts from zero gradient (ghost = fluid)
            let mut faces = slot(&mut s.wall_velocity, side)
                .take()
                .unwrap_or_else(|| vec![RobinFace::ZERO_GRADIENT; wall.n_cells + 1]);
            let mut theta_faces = slot(&mut s.wall_theta, side)
                .take()
                .unwrap_or_else(|| vec![RobinFace::ZERO_GRADIENT; wall.n_cells]);
            let mut cycle = std::mem::take(s.wall_velocity_cycle.get_mut(side));
            if relax.watches_cycles() {
                cycle.resize(wall.n_cells + 1, ClosureCycle::default());
            }
            // the normal load beyond the pressure, for the walls that read it (wall_load.rs)
            let extra_load = model.reads_normal_traction().then(|| {
                let load = PhaseLoad {
                    eps: phase.eps(),
                    u: &phase.u,
                    v: &phase.v,
                    mu: &coefficients.mu,
                    lambda: &coefficients.lambda,
                    tr_d: &coefficients.tr_d,
                    density: spec.params.particles.density,
                };
                extra_normal_load(grid, side, &load, gas.p, body)
            });
            let closures = SideClosures {
                model,
                spec,
                phase,
                mu: &coefficients.mu,
                extra_load: extra_load.as_deref(),
                gas: gas_side,
            };
            momentum_closures(
                grid,
                &wall,
                &closures,
                relax,
                s,
                &mut faces,
                &theta_faces,
                &mut cycle,
            );
            *s.wall_velocity_cycle.get_mut(side) = cycle;
            theta_closures(&wall, &closures, s, &mut theta_faces);
            *slot(&mut s.wall_velocity, side) = Some(faces);
            *slot(&mut s.wall_theta, side) = Some(theta_faces);
        }
    }
    evaluated
}

/// One wall side as the near-wall gathering sees it: the fluid row next to it and the
/// direction along it.
struct WallSide<'a> {
    side: Side,
    /// along a south/north wall the tangential component is u (nodes 0..=nx, cells k−1 and k
    /// of the wall row); along west/east it is v
    horizontal: bool,
    /// +1 where the wall is on the low side of the fluid (south, west)
    sign: f64,
    /// the fluid row (or column) next to the wall
    row: usize,
    /// cells along the wall
    n_cells: usize,
    nx: usize,
    /// width of the fluid row normal to the wall
    delta: f64,
    /// node spacing along the wall
    along_spacing: &'a [f64],
}

impl<'a> WallSide<'a> {
    fn new(grid: &'a Grid, side: Side) -> Self {
        let (nx, ny) = (grid.nx(), grid.ny());
        let (dx, dy) = (grid.x.widths(), grid.y.widths());
        let horizontal = matches!(side, Side::South | Side::North);
        let (row, n_cells) = match side {
            Side::South => (0, nx),
            Side::North => (ny - 1, nx),
            Side::West => (0, ny),
            Side::East => (nx - 1, ny),
        };
        WallSide {
            side,
            horizontal,
            sign: if matches!(side, Side::South | Side::West) {
                1.0
            } else {
                -1.0
            },
            row,
            n_cells,
            nx,
            delta: if horizontal { dy[row] } else { dx[row] },
            along_spacing: if horizontal {
                grid.x.face_spacing()
            } else {
                grid.y.face_spacing()
            },
        }
    }

    /// The fluid cell at position `along` of the wall row.
    fn cell(&self, along: usize) -> usize {
        if self.horizontal {
            along + self.nx * self.row
        } else {
            self.row + self.nx * along
        }
    }

    /// Tangential velocity of a phase with faces velocities `f_u`, `f_v` at node k of the
    /// fluid row.
    fn tangential(&self, f_u: &[f64], f_v: &[f64], k: usize) -> f64 {
        let nx = self.nx;
        if self.horizontal {
            f_u[k + (nx + 1) * self.row]
        } else {
            f_v[self.row + nx * k]
        }
    }

    /// Normal velocity at the centre of fluid cell c (zero on the wall face).
    fn normal_centre(&self, u: &[f64], v: &[f64], c: usize) -> f64 {
        let nx = self.nx;
        let (i, j) = (c % nx, c / nx);
        if self.horizontal {
            0.5 * (v[i + nx * j] + v[i + nx * (j + 1)])
        } else {
            0.5 * (u[i + (nx + 1) * j] + u[i + 1 + (nx + 1) * j])
        }
    }

    /// The gas's tangential velocity at the centre of fluid cell `along`, from its wall face
    /// values.
    fn gas_centre(&self, gas: &GasSide<'_>, along: usize) -> f64 {
        let nx = self.nx;
        let c = self.cell(along);
        let (i, j) = (c % nx, c / nx);
        if self.horizontal {
            0.5 * (gas.face_value(gas.u[i + (nx + 1) * j])
                + gas.face_value(gas.u[i + 1 + (nx + 1) * j]))
        } else {
            0.5 * (gas.face_value(gas.v[c]) + gas.face_value(gas.v[c + nx]))
        }
    }
}

/// The gas along one wall side.
struct GasSide<'a> {
    /// the gas's wall closure (none on an outlet)
    face: Option<RobinFace>,
    u: &'a [f64],
    v: &'a [f64],
    delta: f64,
}

impl GasSide<'_> {
    /// The gas's wall face value of a tangential velocity next to the wall.
    fn face_value(&self, vel: f64) -> f64 {
        self.face.map_or(vel, |f| f.face_value(vel, self.delta))
    }
}

/// What the closures of one side are evaluated with.
struct SideClosures<'a> {
    model: &'a SolidsWallModel,
    spec: &'a SolidsSpec,
    /// the phase's fields
    phase: &'a PhaseState,
    /// μ_s per cell [Pa s], whose mean along the wall the momentum assembly applies a face's
    /// h with
    mu: &'a [f64],
    /// the normal load beyond the pressure per cell of the wall row [Pa], where the wall
    /// reads it ([`extra_normal_load`])
    extra_load: Option<&'a [f64]>,
    gas: GasSide<'a>,
}

/// The momentum closure of each tangential-velocity node of one wall (`faces`, updated and
/// relaxed), from the near-wall state with the θ ghosts of `theta_faces` (update_walls' doc).
#[allow(clippy::too_many_arguments)]
fn momentum_closures(
    grid: &Grid,
    wall: &WallSide<'_>,
    closures: &SideClosures<'_>,
    relax: WallRelaxation,
    s: &mut PhaseWallClosures,
    faces: &mut [RobinFace],
    theta_faces: &[RobinFace],
    cycle: &mut [ClosureCycle],
) {
    let SideClosures {
        model,
        spec,
        phase: p,
        mu,
        extra_load,
        gas,
    } = closures;
    let u_w = model.wall_velocity();
    let (delta, sign, n_cells) = (wall.delta, wall.sign, wall.n_cells);
    let face_velocity = s.wall_face_velocity.get(wall.side);
    let ghost_theta = |c_along: usize| {
        let c = wall.cell(c_along);
        theta_faces[c_along].ghost(p.theta[c], delta)
    };
    for k in 0..=n_cells {
        // the cells beside node k (one at a corner)
        let lo = k.checked_sub(1);
        let hi = (k < n_cells).then_some(k);
        let (c_lo, c_hi) = (lo.or(hi).unwrap(), hi.or(lo).unwrap());
        let weight = match (lo, hi) {
            (Some(a), Some(_)) => {
                if wall.horizontal {
                    grid.x.interpolation_weight(a)
                } else {
                    grid.y.interpolation_weight(a)
                }
            }
            _ => 0.5,
        };
        let interp = |f: &[f64]| weight * f[wall.cell(c_lo)] + (1.0 - weight) * f[wall.cell(c_hi)];
        let vel = wall.tangential(&p.u, &p.v, k);
        let closure = faces[k];
        let ghost = closure.ghost(vel, delta);
        let face_vel = closure.face_value(vel, delta);
        // strain rate at the wall location (CALC_S_DDOT_S)
        let d_tangent_normal = sign * (vel - ghost) / delta;
        let d_normal = sign
            * 0.5
            * (wall.normal_centre(&p.u, &p.v, wall.cell(c_lo))
                + wall.normal_centre(&p.u, &p.v, wall.cell(c_hi)))
            / delta;
        let d_along = match (lo, hi) {
            (Some(a), Some(b)) => (face_velocity[b] - face_velocity[a]) / wall.along_spacing[k],
            _ => 0.0,
        };
        // (along, normal) play the roles of (x, y) of a floor on every side
        let strain = WallStrain::planar_floor(d_along, d_tangent_normal, 0.0, d_normal);
        let theta_rows = corner_theta(
            0.5 * (ghost_theta(c_lo) + ghost_theta(c_hi)),
            0.5 * (p.theta[wall.cell(c_lo)] + p.theta[wall.cell(c_hi)]),
        );
        let gas_vel = gas.face_value(wall.tangential(gas.u, gas.v, k));
        let state = MomentumWallState {
            // MFIX's IJK2 for U(i) is the cell west of the face (cell i)
            eps_s_fluid: p.eps()[wall.cell(c_lo)],
            eps_s: interp(p.eps()),
            theta: theta_rows,
            slip: (face_vel - u_w).abs(),
            gas_slip: (gas_vel - face_vel).abs(),
            tr_d: strain.tr_d,
            s_ddot_s: strain.s_ddot_s,
            s_nn: strain.s_nn,
            // along the wall as εs is
            extra_normal_load: extra_load.map_or(0.0, |load| {
                weight * load[c_lo] + (1.0 - weight) * load[c_hi]
            }),
        };
        // a Coulomb face's h is K over the viscosity the assembly applies it with
        // (momentum.rs `mu_wall`), so that it imposes μ_w P (docs/model.md §3.11)
        let gamma = harmonic(mu[wall.cell(c_lo)], mu[wall.cell(c_hi)], weight);
        let computed = model
            .momentum(&state, &spec.params)
            .with_face_viscosity(gamma);
        if wall.side == Side::South {
            s.floor_h_u[k] = computed.diagnostics.h_u;
            s.floor_normal_load[k] = computed.diagnostics.normal_load;
        }
        faces[k] = if relax.watches_cycles() {
            let node = &mut cycle[k];
            node.cycling |= turns_back(computed.face.h - closure.h, node.last_change);
            let w = if node.cycling { relax.weight } else { 1.0 };
            let applied = relax_face(computed.face, closure, w);
            node.last_change = applied.h - closure.h;
            applied
        } else {
            relax_face(computed.face, closure, relax.weight)
        };
    }
}

/// The θ closure of each cell of one wall (`theta_faces`, updated), from the near-wall
/// state (update_walls' doc).
fn theta_closures(
    wall: &WallSide<'_>,
    closures: &SideClosures<'_>,
    s: &PhaseWallClosures,
    theta_faces: &mut [RobinFace],
) {
    let SideClosures {
        model,
        spec,
        phase: p,
        gas,
        ..
    } = closures;
    let u_w = model.wall_velocity();
    let face_velocity = s.wall_face_velocity.get(wall.side);
    for along in 0..wall.n_cells {
        let c = wall.cell(along);
        let gas_centre = wall.gas_centre(gas, along);
        let state = ThetaWallState {
            eps_s: p.eps()[c],
            theta: face_theta(theta_faces[along].ghost(p.theta[c], wall.delta), p.theta[c]),
            slip: (face_velocity[along] - u_w).abs(),
            gas_slip: (gas_centre - face_velocity[along]).abs(),
        };
        // this cell's θ ghost was read by its two nodes above and just now
        theta_faces[along] = model.granular_temperature(&state, &spec.params).face;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_mesh::Axis;

    #[test]
    fn a_wall_side_walks_its_fluid_row() {
        let grid = Grid::new(
            Axis::uniform(0.0, 3.0, 3).unwrap(),
            Axis::uniform(0.0, 1.0, 2).unwrap(),
        );
        let (u, v): (Vec<f64>, Vec<f64>) = (
            (0..8).map(f64::from).collect(),
            (0..9).map(|k| 10.0 + f64::from(k)).collect(),
        );
        let north = WallSide::new(&grid, Side::North);
        assert_eq!((north.row, north.n_cells, north.sign), (1, 3, -1.0));
        assert_eq!((north.cell(0), north.cell(2)), (3, 5));
        // u-node 2 of the top row, v at the centre of cell (1, 1)
        assert_eq!(north.tangential(&u, &v, 2), u[6]);
        assert_eq!(north.normal_centre(&u, &v, 4), 0.5 * (v[4] + v[7]));
        let east = WallSide::new(&grid, Side::East);
        assert_eq!((east.row, east.n_cells, east.sign), (2, 2, -1.0));
        assert_eq!((east.cell(0), east.cell(1)), (2, 5));
        assert_eq!(east.tangential(&u, &v, 1), v[5]);
        assert_eq!(east.normal_centre(&u, &v, 5), 0.5 * (u[6] + u[7]));
    }
}
