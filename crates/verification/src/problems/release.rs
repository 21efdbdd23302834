//! Issue 57 item 2's checks of the laboratory's release: a pile given as a polygon in world
//! coordinates and held by a gate (`initial.polygons`, `gates`, crates/case/src/release.rs).
//!
//! The set-up is the laboratory's (e.g. Mangeney et al. 2010, J. Geophys. Res. 115, F03040):
//! glass beads with μ(I) (cases/collapse/CM-a1.ron, friction angle 20.9°) in a thin gas (as
//! the Coulomb floor's block), on a 30° slope, in a box behind a gate standing normal to the
//! floor 0.1 m down it: the pile is the polygon of the floor from the back wall to the gate,
//! the gate, a horizontal free surface 3 cm above the floor's top and the back wall, at
//! εs 0.58. A horizontal surface does not avalanche, and the back wall, the floor and the
//! gate hold the rest, so the pile stays at rest until the gate is removed at 0.2 s; then it
//! flows down the slope.
//!
//! Judged: the released mass is the polygon's area × εs × ρs to 1e-10 (the exact covered
//! fraction of each cell); once settled and until the gate opens the εs-weighted mean speed
//! stays below [`REST_SPEED`], and the front does not pass the gate; 0.2 s after it opens the
//! front is at least 5 cm past it; the solids mass drifts by at most [`MASS_DRIFT`].

use anyhow::{Context, Result};
use runout_case::{Case, Fidelity, Gate, GateOpening, Gravity, Polygon};

use crate::problems::case_copy::{ending_at, template_on_grid, thin_gas, validated};

/// The case the pile is built on, relative to the workspace root.
pub const TEMPLATE: &str = "cases/collapse/CM-a1.ron";
/// The slope [deg].
pub const SLOPE_DEG: f64 = 30.0;
/// The domain along the floor and normal to it [m].
pub const DOMAIN: (f64, f64) = (0.5, 0.15);
/// The gate: where it stands along the floor, its height [m] and when it is removed [s].
pub const GATE: (f64, f64, f64) = (0.1, 0.1, 0.2);
/// The pile's free surface above the top of the floor [m] and its εs.
pub const PILE: (f64, f64) = (0.03, 0.58);
/// The run's simulated time [s].
pub const END: f64 = 0.4;
/// The largest εs-weighted mean speed of the pile from [`SETTLED`] until the gate opens
/// [m s⁻¹]: 0.013 % of √(g h) for its 6 cm.
pub const REST_SPEED: f64 = 1e-4;
/// When the pile has settled [s]: released at εs 0.58, below the packing its weight holds at
/// its base, it sinks into it first, at up to about a centimetre per second in its first
/// tens of milliseconds.
pub const SETTLED: f64 = 0.1;
/// The largest drift of the solids mass over the run [-]: the εs correction's closure
/// (`numerics.exact_solids_mass`), 2e-10 on 100 × 30 once the pile flows.
pub const MASS_DRIFT: f64 = 1e-9;

/// The pile's corners in world coordinates (X, Z) from the floor at the back wall: the
/// floor at the back wall and at the gate, then the gate and the back wall where they meet
/// the free surface (crates/case/src/release.rs: on a plane floor tilted by α a point x
/// along the floor and y from it is at X = x cos α + y sin α, Z = −x sin α + y cos α).
pub fn pile_corners() -> Vec<(f64, f64)> {
    let a = SLOPE_DEG.to_radians();
    let (gate_x, surface) = (GATE.0, PILE.0);
    let world = |x: f64, y: f64| (x * a.cos() + y * a.sin(), -x * a.sin() + y * a.cos());
    // the height along each normal at which Z reaches the surface
    let up_to_surface = |x: f64| (surface + x * a.sin()) / a.cos();
    vec![
        world(0.0, 0.0),
        world(gate_x, 0.0),
        world(gate_x, up_to_surface(gate_x)),
        world(0.0, up_to_surface(0.0)),
    ]
}

/// The gated pile on `cells` (along, across) cells.
pub fn pile_case(cells: (usize, usize)) -> Result<Case> {
    let case = template_on_grid(
        TEMPLATE,
        format!("release-pile-{}x{}", cells.0, cells.1),
        DOMAIN,
        cells,
        Gravity::Constant {
            magnitude: 9.81,
            slope: SLOPE_DEG,
        },
    )?;
    let mut case = thin_gas(
        case,
        crate::problems::coulomb_floor::THIN_GAS_VISCOSITY_FRACTION,
    )?;
    let mut solids = case.initial.regions[0].solids.clone();
    solids[0].eps_s = PILE.1;
    case.initial.regions.clear();
    case.initial.polygons = vec![Polygon {
        points: pile_corners(),
        solids,
    }];
    let (x, height, at) = GATE;
    case.gates = vec![Gate {
        x,
        height,
        open: GateOpening::Removed { at },
    }];
    Ok(validated(ending_at(case, END), "gated pile")?.at_fidelity(Fidelity::Paper))
}

/// What the gated pile did.
#[derive(Clone, Debug)]
pub struct PileRun {
    /// the released mass over the polygon's area × εs × ρs, less 1
    pub mass_error: f64,
    /// the largest |solids mass / its start − 1| over the run
    pub mass_drift: f64,
    /// the largest |εs-weighted mean u_s| from [`SETTLED`] until the gate opens [m s⁻¹]
    pub rest_speed: f64,
    /// the front's largest x before the gate opens [m]
    pub front_before: f64,
    /// the front 0.2 s after the gate opens [m]
    pub front_after: f64,
    /// the gate's u face [m]
    pub gate_face: f64,
}

/// Runs the gated pile through the driver.
pub fn run_pile(cells: (usize, usize)) -> Result<PileRun> {
    let case = pile_case(cells)?;
    let out = std::env::temp_dir().join(format!("runout-{}-{}", case.name, std::process::id()));
    runout_run::run_case(&case, Fidelity::Paper, &out, |_| {})?;
    let bulk = runout_post::table::Table::read(&out.join("bulk.csv"))
        .map_err(|e| anyhow::anyhow!("{}: {e}", out.display()))?;
    let _ = std::fs::remove_dir_all(&out);
    let column = |name: &str| bulk.column(name).map_err(anyhow::Error::msg);
    let (times, mass, fronts, speeds) = (
        column("t")?,
        column("solids_mass")?,
        column("front_x")?,
        column("mean_u_s")?,
    );
    let area = runout_case::release::signed_area(&pile_corners()).abs();
    let expected = area * PILE.1 * case.solids[0].density;
    let opens = GATE.2;
    let before = |k: &usize| times[*k] < opens - 1e-9;
    let settled = |k: &usize| times[*k] >= SETTLED && times[*k] < opens - 1e-9;
    let grid = case.grid()?;
    let faces = grid.x.faces();
    let gate_face = faces
        .iter()
        .copied()
        .min_by(|a, b| (a - GATE.0).abs().total_cmp(&(b - GATE.0).abs()))
        .unwrap_or(GATE.0);
    let after = times
        .iter()
        .position(|&t| t >= END - 1e-9)
        .context("the run ended early")?;
    Ok(PileRun {
        mass_error: mass[0] / expected - 1.0,
        mass_drift: mass
            .iter()
            .map(|m| (m / mass[0] - 1.0).abs())
            .fold(0.0, f64::max),
        rest_speed: (0..times.len())
            .filter(settled)
            .map(|k| speeds[k].abs())
            .fold(0.0, f64::max),
        front_before: (0..times.len())
            .filter(before)
            .map(|k| fronts[k])
            .fold(f64::NEG_INFINITY, f64::max),
        front_after: fronts[after],
        gate_face,
    })
}
