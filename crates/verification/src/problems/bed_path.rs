//! Issue 57 item 1's checks of a bed of several bends (`bed: Path`, docs/model.md §9):
//! glass beads with μ(I) (cases/collapse/CM-a1.ron, Jop et al. 2005: μ_s = 0.382, a
//! friction angle of 20.9°) on laboratory-sized paths in a thin gas (air's density, a
//! hundredth of its viscosity, as the Coulomb floor's block: the laws below are those of
//! grains in vacuum).
//!
//! **The slide.** A thin block released at rest near the top of a path that turns flatter,
//! then steeper (a convex arc), then onto a flat run-out, on a free-slip floor: no force
//! along the floor but gravity's, so its centre of mass gains the speed the drop of its
//! centre gives,
//!
//!   ū(t) = √(2 g (z_c(0) − z_c(t)))                                                  (1)
//!
//! less what the grains dissipate as the block deforms (it spreads on the slopes, is pressed
//! together at the concave arcs); z_c = z_b(x) + y cos α(x) of the εs-weighted mean of each
//! cell's elevation, ū the εs-weighted mean u_s. The check judges ū/√(2 g Δz_c) at every
//! sample once the centre has dropped [`SLIDE_SETTLED_DROP`] (before, the block's settling
//! onto the floor moves its centre by a few tenths of a millimetre, a visible share of a
//! drop of millimetres).
//!
//! **The layer at rest.** A layer 1 cm thick along a path whose every piece is flatter than
//! the beads' friction angle (15°, 5°, 12°, 0°, joined by a concave, a convex and a concave
//! arc), wall to wall on a no-slip floor: it settles into the packing its weight holds and
//! stays put. The contrast: the same layer on the same path with its first piece at 30°,
//! steeper than the friction angle, flows. The floor's solids pressure is printed against
//! the weight above the floor cell's centre, not judged: at rest the regularised μ(I) law
//! shares the weight between P and the normal viscous stress of the last slow compaction
//! (docs/model.md §3.11), a split the history sets and no closed form gives (the gas's
//! hydrostatic balance over a path of bends is exact, to round-off:
//! crates/run/tests/bent_floor.rs).

use anyhow::{Context, Result};
use runout_case::{Bed, BedPiece, Boundary, Case, Fidelity, Gravity, SolidsWall};
use runout_mesh::bent_floor::BentFloor;
use runout_solver::two_fluid::TwoFluid;

use crate::problems::case_copy::{ending_at, template_on_grid, thin_gas, validated};
use crate::problems::stepping::Stepping;

/// The case the paths are built on, relative to the workspace root.
pub const TEMPLATE: &str = "cases/collapse/CM-a1.ron";
/// Standard gravity of CM-a1.ron [m s⁻²].
pub const GRAVITY: f64 = 9.81;
/// The domain's length along the floor and its height [m].
pub const DOMAIN: (f64, f64) = (1.2, 0.02);
/// Every arc's radius where the floor turns flatter, and the convex arc's [m].
pub const RADII: (f64, f64) = (0.1, 1.0);

/// The slide's path: 30°, 10°, 20°, 0° (module doc).
pub fn slide_path() -> Vec<BedPiece> {
    let s = |length: f64, slope: f64| BedPiece::Straight { length, slope };
    let a = |radius: f64| BedPiece::Arc { radius };
    let (concave, convex) = RADII;
    vec![
        s(0.25, 30.0),
        a(concave),
        s(0.15, 10.0),
        a(convex),
        s(0.15, 20.0),
        a(concave),
        s(0.5, 0.0),
    ]
}

/// The resting layer's path with its first piece at `first_slope` [deg] (module doc).
pub fn rest_path(first_slope: f64) -> Vec<BedPiece> {
    let s = |length: f64, slope: f64| BedPiece::Straight { length, slope };
    let a = |radius: f64| BedPiece::Arc { radius };
    let (concave, convex) = RADII;
    vec![
        s(0.3, first_slope),
        a(concave),
        s(0.2, 5.0),
        a(convex),
        s(0.15, 12.0),
        a(concave),
        s(0.5, 0.0),
    ]
}

/// The template on `cells` (along, across) over [`DOMAIN`] with `path`, a `floor`, one
/// block of beads at εs `eps_s` over `x` × `y` at rest, in the thin gas, ending at `end`.
fn path_case(
    name: &str,
    cells: (usize, usize),
    path: Vec<BedPiece>,
    floor: SolidsWall,
    block: ((f64, f64), (f64, f64), f64),
    end: f64,
) -> Result<Case> {
    let case = template_on_grid(
        TEMPLATE,
        format!("bed-path-{name}-{}x{}", cells.0, cells.1),
        DOMAIN,
        cells,
        Gravity::Constant {
            magnitude: GRAVITY,
            slope: 0.0,
        },
    )?;
    let mut case = thin_gas(
        case,
        crate::problems::coulomb_floor::THIN_GAS_VISCOSITY_FRACTION,
    )?;
    case.bed = Bed::Path(path);
    let Boundary::Wall { solids, .. } = &mut case.boundaries.south else {
        anyhow::bail!("{TEMPLATE}: the floor is not a wall");
    };
    *solids = floor;
    let (x, y, eps_s) = block;
    let region = &mut case.initial.regions[0];
    region.x = x;
    region.y = y;
    region.solids[0].eps_s = eps_s;
    region.solids[0].velocity = (0.0, 0.0);
    Ok(validated(ending_at(case, end), name)?.at_fidelity(Fidelity::Paper))
}

/// The εs-weighted centre of the solids: its x along the floor, its elevation z_c [m] and
/// its speed along the floor (εs-weighted mean u_s) [m s⁻¹].
fn centre(tf: &TwoFluid, floor: &BentFloor) -> (f64, f64, f64) {
    let g = tf.grid();
    let (nx, ny) = (g.nx(), g.ny());
    let (xc, yc) = (g.x.centres(), g.y.centres());
    let s = tf.solids(0);
    let (mut x, mut z, mut u, mut mass) = (0.0, 0.0, 0.0, 0.0);
    for j in 0..ny {
        for i in 0..nx {
            let w = s.eps()[i + nx * j] * g.cell_volume(i, j);
            x += w * xc[i];
            z += w * (floor.floor_elevation(xc[i]) + yc[j] * floor.angle(xc[i]).cos());
            u += w * 0.5 * (s.u[i + (nx + 1) * j] + s.u[i + 1 + (nx + 1) * j]);
            mass += w;
        }
    }
    (x / mass, z / mass, u / mass)
}

/// One sample of the slide: time [s], centre x [m], drop of the centre [m], speed and
/// Eq. (1)'s speed [m s⁻¹].
#[derive(Clone, Copy, Debug)]
pub struct SlideSample {
    /// t [s]
    pub time: f64,
    /// the centre's x along the floor [m]
    pub x: f64,
    /// z_c(0) − z_c(t) [m]
    pub drop: f64,
    /// the εs-weighted mean u_s [m s⁻¹]
    pub speed: f64,
    /// √(2 g drop) [m s⁻¹]
    pub law: f64,
}

/// The slide's block: 0.1 m long, 5 mm thick, from x = 0.03 m, εs 0.57.
pub const SLIDE_BLOCK: ((f64, f64), (f64, f64), f64) = ((0.03, 0.13), (0.0, 0.005), 0.57);
/// The drop of the centre from which the slide is judged [m] (module doc).
pub const SLIDE_SETTLED_DROP: f64 = 0.01;
/// The slide's simulated time and the interval of its samples [s].
pub const SLIDE_TIME: (f64, f64) = (0.7, 0.02);

/// Runs the slide (module doc) on `cells`, sampling every [`SLIDE_TIME`].1.
pub fn run_slide(cells: (usize, usize)) -> Result<Vec<SlideSample>> {
    let case = path_case(
        "slide",
        cells,
        slide_path(),
        SolidsWall::FreeSlip,
        SLIDE_BLOCK,
        SLIDE_TIME.0,
    )?;
    let floor = case.bent_floor()?.context("a path is a bent floor")?;
    let mut tf = runout_run::two_fluid_solver(&case)?;
    let stepping = Stepping::of(&case);
    let (mut time, mut dt) = (0.0, stepping.dt.0);
    let (_, z0, _) = centre(&tf, &floor);
    let mut samples = Vec::new();
    let count = (SLIDE_TIME.0 / SLIDE_TIME.1).round() as usize;
    for k in 1..=count {
        stepping.march(
            &mut tf,
            (&mut time, &mut dt),
            k as f64 * SLIDE_TIME.1,
            |_, _| {},
        )?;
        let (x, z, speed) = centre(&tf, &floor);
        let drop = z0 - z;
        samples.push(SlideSample {
            time,
            x,
            drop,
            speed,
            law: (2.0 * GRAVITY * drop.max(0.0)).sqrt(),
        });
    }
    Ok(samples)
}

/// The resting layer: from wall to wall (no ends to slump), 1 cm thick, εs 0.58.
pub const REST_LAYER: ((f64, f64), (f64, f64), f64) = ((0.0, DOMAIN.0), (0.0, 0.01), 0.58);
/// The resting layer's simulated time [s].
pub const REST_TIME: f64 = 0.5;
/// How far inside the end walls the resting layer's floor pressure is judged [m].
pub const REST_MARGIN: f64 = 0.05;

/// What the resting layer did by [`REST_TIME`].
#[derive(Clone, Copy, Debug)]
pub struct RestRun {
    /// the largest |u_s| of a cell holding εs ≥ 0.1 [m s⁻¹]
    pub largest_speed: f64,
    /// the smallest and largest P_s of a floor cell over the weight above its centre,
    /// ρs g cos α (∫εs dy − εs Δy/2), over the columns [`REST_MARGIN`] or more inside the
    /// end walls (module doc: not judged)
    pub pressure_ratio: (f64, f64),
    /// how far the centre moved along the floor [m]
    pub centre_moved: f64,
}

/// Runs the layer (module doc) on `cells` with the path's first piece at `first_slope`.
pub fn run_rest(cells: (usize, usize), first_slope: f64) -> Result<RestRun> {
    let case = path_case(
        &format!("rest-{first_slope}"),
        cells,
        rest_path(first_slope),
        SolidsWall::NoSlip,
        REST_LAYER,
        REST_TIME,
    )?;
    let floor = case.bent_floor()?.context("a path is a bent floor")?;
    let density = case.solids[0].density;
    let mut tf = runout_run::two_fluid_solver(&case)?;
    let stepping = Stepping::of(&case);
    let (x0, _, _) = centre(&tf, &floor);
    let (mut time, mut dt) = (0.0, stepping.dt.0);
    stepping.march(&mut tf, (&mut time, &mut dt), REST_TIME, |_, _| {})?;
    let (x1, _, _) = centre(&tf, &floor);
    let g = tf.grid();
    let (nx, ny) = (g.nx(), g.ny());
    let (xc, dy) = (g.x.centres(), g.y.widths());
    let s = tf.solids(0);
    let mut largest_speed: f64 = 0.0;
    for j in 0..ny {
        for i in 0..nx {
            if s.eps()[i + nx * j] >= 0.1 {
                let u = 0.5 * (s.u[i + (nx + 1) * j] + s.u[i + 1 + (nx + 1) * j]);
                let v = 0.5 * (s.v[i + nx * j] + s.v[i + nx * (j + 1)]);
                largest_speed = largest_speed.max(u.hypot(v));
            }
        }
    }
    let (ends, margin) = (REST_LAYER.0, REST_MARGIN);
    let p_s = tf.p_s(0);
    let mut pressure_ratio = (f64::INFINITY, f64::NEG_INFINITY);
    for i in (0..nx).filter(|&i| xc[i] > ends.0 + margin && xc[i] < ends.1 - margin) {
        let column: f64 = (0..ny).map(|j| s.eps()[i + nx * j] * dy[j]).sum();
        // the weight above the floor cell's centre, and its half cell, against P there
        let above = column - 0.5 * s.eps()[i] * dy[0];
        let weight = density * GRAVITY * floor.angle(xc[i]).cos() * above;
        let ratio = p_s[i] / weight;
        pressure_ratio = (pressure_ratio.0.min(ratio), pressure_ratio.1.max(ratio));
    }
    Ok(RestRun {
        largest_speed,
        pressure_ratio,
        centre_moved: x1 - x0,
    })
}
