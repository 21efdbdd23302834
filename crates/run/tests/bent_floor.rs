//! A floor whose slope turns onto a flat run-out (docs/model.md §9, issue 43 item 5): gravity
//! in bed-following coordinates is the gradient of a potential, so the initial hydrostatic
//! pressure a run builds balances the gas's weight at every u and v node, over the bend and
//! at the top outlet, to round-off: gas at rest stays at rest. The contrast (the plane 40°
//! slope's hydrostatic pressure under the bent floor's gravity) is out of balance, so the
//! check can fail. (A step of a domain wholly at rest cannot show it: the momentum residual
//! is normalised by the speeds, all zero.)

use std::path::Path;

use runout_case::{load_case, Bed, BedPiece, Case, Fidelity, Gravity};
use runout_closures::FaceMean;
use runout_linsolve::{Pattern, Stencil5};
use runout_mesh::Sides;
use runout_run::two_fluid_solver;
use runout_solver::bent_floor::BentFloor;
use runout_solver::momentum::{assemble, Context, PhaseFields};
use runout_solver::staggered::Component;
use runout_solver::two_fluid::TwoFluid;
use runout_solver::{FaceData, Scheme, SideBc};
use runout_walls::RobinFace;

/// The family-S slide's domain (20 m × 1.8 m) at smoke size with no solids, a 40° slope
/// from the start.
fn empty_slide(bed: Bed) -> Case {
    empty_slide_at(bed, 40.0)
}

/// [`empty_slide`] with the gravity's slope `slope` [deg] (0 for a path).
fn empty_slide_at(bed: Bed, slope: f64) -> Case {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut case = load_case(&root.join("cases/sensitivity/base.ron")).unwrap();
    case.gravity = Gravity::Constant {
        magnitude: 9.80665,
        slope,
    };
    case.initial.regions.clear();
    case.bed = bed;
    runout_case::validate_case(&case).unwrap();
    case.at_fidelity(Fidelity::Smoke)
}

const BEND: Bed = Bed::Bend {
    at: 12.0,
    radius: 2.0,
    slope_after: 0.0,
};

/// The gas momentum sources (gravity and pressure: the gas at rest has no other) of the
/// built solver's initial pressure `p` under `floor`, largest magnitude over the u and the
/// v nodes that move (the top outlet's included), against the largest weight of a node's
/// gas, ρ_g g V.
fn largest_gas_imbalance(tf: &TwoFluid, p: &[f64], floor: Option<&BentFloor>) -> f64 {
    let grid = tf.grid();
    let (nx, ny) = (grid.nx(), grid.ny());
    let walls = SideBc::Wall(RobinFace::partial_slip(0.0, 0.0));
    let bcs = Sides {
        west: walls,
        east: walls,
        south: walls,
        north: SideBc::HydrostaticOutlet {
            p0: 101325.0,
            density: 1.2,
        },
    };
    let bulk = vec![1.2; nx * ny];
    let (ones, zeros) = (vec![1.0; nx * ny], vec![0.0; nx * ny]);
    let ctx = Context {
        grid,
        bcs: &bcs,
        gravity: tf.gravity(),
        bent_floor: floor,
        dt: f64::INFINITY,
        scheme: Scheme::Upwind,
        gas_pressure: p,
        wall_faces: None,
        form: runout_solver::momentum::MomentumForm::ContinuitySubtracted,
    };
    let (u, v) = (vec![0.0; (nx + 1) * ny], vec![0.0; nx * (ny + 1)]);
    let phase = PhaseFields {
        bulk_density: &bulk,
        bulk_density_old: &bulk,
        volume_fraction: &ones,
        viscosity: &zeros,
        viscosity_mean: FaceMean::Harmonic,
        solids_pressure: None,
        plastic_pressure: None,
        explicit_source: None,
        skip: None,
        velocity_along: Some(&u),
    };
    let mut largest: f64 = 0.0;
    for (c, comp) in Component::of_grid(grid).into_iter().enumerate() {
        let (mx, my) = if c == 0 { (nx + 1, ny) } else { (nx, ny + 1) };
        let mut a = Stencil5::new(Pattern::new(mx, my).unwrap());
        let mut faces = FaceData::zeros(mx, my);
        let old = if c == 0 { u.clone() } else { v.clone() };
        assemble(&ctx, &phase, comp, &u, &v, &old, &mut faces, &mut a);
        // the nodes that move: not the wall-normal ones (west, east and the floor)
        let moves = |k: usize| {
            let (i, j) = (k % mx, k / mx);
            if c == 0 {
                i > 0 && i < nx
            } else {
                j > 0
            }
        };
        largest = (0..mx * my)
            .filter(|&k| moves(k))
            .fold(largest, |m, k| m.max(a.b[k].abs()));
    }
    let volume = (0..nx * ny)
        .map(|k| grid.cell_volume(k % nx, k / nx))
        .fold(0.0, f64::max);
    largest / (1.2 * 9.80665 * volume)
}

#[test]
fn gas_at_rest_stays_at_rest_over_the_bend() {
    let case = empty_slide(BEND);
    let tf = two_fluid_solver(&case).unwrap();
    let floor = tf.bent_floor();
    assert!(
        floor.is_some(),
        "a constant gravity's bend acts from the start"
    );
    let imbalance = largest_gas_imbalance(&tf, tf.p_g(), floor);
    eprintln!("balanced: {imbalance:e}");
    assert!(
        imbalance < 1e-9,
        "gas imbalance {imbalance} of a node's weight"
    );

    // contrast: the plane 40° slope's hydrostatic pressure under the bent floor's gravity
    let plane = two_fluid_solver(&empty_slide(Bed::Plane)).unwrap();
    let imbalance = largest_gas_imbalance(&tf, plane.p_g(), floor);
    eprintln!("contrast: {imbalance:e}");
    assert!(
        imbalance > 1e-2,
        "the contrast should be out of balance: {imbalance}"
    );
}

/// A path down the family-S domain with a concave arc, a convex one and a concave one onto
/// an uphill counter-slope (every concave radius above the domain's 1.8 m).
fn hills() -> Bed {
    let s = |length: f64, slope: f64| BedPiece::Straight { length, slope };
    let a = |radius: f64| BedPiece::Arc { radius };
    Bed::Path(vec![
        s(6.0, 40.0),
        a(3.0),
        s(3.0, 15.0),
        a(2.0),
        s(3.0, 30.0),
        a(4.0),
        s(20.0, -5.0),
    ])
}

#[test]
fn gas_at_rest_stays_at_rest_on_a_path_of_bends() {
    let case = empty_slide_at(hills(), 0.0);
    let tf = two_fluid_solver(&case).unwrap();
    let floor = tf.bent_floor();
    assert!(floor.is_some());
    let imbalance = largest_gas_imbalance(&tf, tf.p_g(), floor);
    eprintln!("balanced on the path: {imbalance:e}");
    assert!(
        imbalance < 1e-9,
        "gas imbalance {imbalance} of a node's weight"
    );
    let plane = two_fluid_solver(&empty_slide(Bed::Plane)).unwrap();
    let imbalance = largest_gas_imbalance(&tf, plane.p_g(), floor);
    assert!(
        imbalance > 1e-2,
        "the contrast should be out of balance: {imbalance}"
    );
}

/// Paths and transects the bed-following coordinates cannot carry are refused before any
/// step, naming the field: a concave arc no wider than the domain is high (a fold), a kink,
/// a step beyond vertical, a path that stops short of the domain's end, a tilted gravity.
#[test]
fn bad_paths_are_refused_with_the_field() {
    let fields = |bed: Bed, slope: f64| -> Vec<String> {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let mut case = load_case(&root.join("cases/sensitivity/base.ron")).unwrap();
        case.gravity = Gravity::Constant {
            magnitude: 9.80665,
            slope,
        };
        case.bed = bed;
        runout_case::validate_case(&case)
            .err()
            .unwrap_or_default()
            .into_iter()
            .map(|e| e.field)
            .collect()
    };
    let s = |length: f64, slope: f64| BedPiece::Straight { length, slope };
    let a = |radius: f64| BedPiece::Arc { radius };
    assert!(fields(hills(), 0.0).is_empty());
    assert_eq!(fields(hills(), 40.0), ["gravity"]);
    let fold = Bed::Path(vec![s(5.0, 40.0), a(1.5), s(20.0, 0.0)]);
    assert_eq!(fields(fold, 0.0), ["bed.Path: arc 0 at x = 5 m"]);
    let convex = Bed::Path(vec![s(5.0, 10.0), a(1.0), s(20.0, 40.0)]);
    assert!(fields(convex, 0.0).is_empty(), "a convex arc does not fold");
    let kink = Bed::Path(vec![s(5.0, 40.0), s(20.0, 0.0)]);
    assert_eq!(fields(kink, 0.0), ["bed.Path[1]"]);
    let short = Bed::Path(vec![s(5.0, 40.0), a(3.0), s(5.0, 0.0)]);
    assert_eq!(fields(short, 0.0), ["bed.Path"]);
    let transect = |points: Vec<(f64, f64)>| Bed::Transect {
        points,
        radius: 2.0,
    };
    let cliff = transect(vec![(0.0, 20.0), (8.0, 10.0), (8.0, 5.0), (30.0, 0.0)]);
    assert_eq!(fields(cliff, 0.0), ["bed.Transect.points[2]"]);
    let fine = transect(vec![(0.0, 20.0), (8.0, 10.0), (12.0, 9.0), (30.0, 8.0)]);
    assert!(fields(fine, 0.0).is_empty());
}

/// A bend that ends beyond the domain, a convex one and one in a gas-only case are refused
/// before any step, naming the field.
#[test]
fn bad_bends_are_refused_with_the_field() {
    let fields = |bed: Bed| -> Vec<String> {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        let mut case = load_case(&root.join("cases/sensitivity/base.ron")).unwrap();
        case.bed = bed;
        runout_case::validate_case(&case)
            .err()
            .unwrap_or_default()
            .into_iter()
            .map(|e| e.field)
            .collect()
    };
    let bend = |at: f64, radius: f64, slope_after: f64| Bed::Bend {
        at,
        radius,
        slope_after,
    };
    assert!(fields(bend(12.0, 2.0, 0.0)).is_empty());
    assert_eq!(fields(bend(19.0, 2.0, 0.0)), ["bed.Bend.radius"]);
    assert_eq!(fields(bend(12.0, 2.0, 45.0)), ["bed.Bend.slope_after"]);
    assert_eq!(fields(bend(25.0, 2.0, 0.0)), ["bed.Bend.at"]);
    assert_eq!(fields(bend(12.0, -1.0, 0.0)), ["bed.Bend.radius"]);
}

/// The mean u_s of each `bulk.csv` row and the last front of a run folder.
fn speeds_and_front(dir: &Path) -> (Vec<f64>, f64) {
    let text = std::fs::read_to_string(dir.join("bulk.csv")).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    // t, solids_mass, front_x, mean_u_s, front_x_interpolated
    let speeds = rows.iter().map(|r| r[3]).collect();
    (speeds, rows.last().unwrap()[2])
}

/// A μ(I) block sliding at 6 m/s from x = 10 m on the 40° slope of the family-FS slide (smoke
/// size, 1.2 s): with the foot it passes onto the flat run-out and slows there (its last
/// mean speed well below its largest), while on the plane slope it keeps its speed. A
/// smoke test of the whole chain (case, solver, bulk monitor), not a measurement.
#[test]
fn a_block_slides_through_the_foot_and_slows_on_the_run_out() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let run = |bed: Bed, tag: &str| {
        let mut case = load_case(&root.join("cases/foot/mu-i/base.ron")).unwrap();
        case.gravity = Gravity::Constant {
            magnitude: 9.80665,
            slope: 40.0,
        };
        case.bed = bed;
        let block = &mut case.initial.regions[0];
        block.x = (10.0, 10.5);
        block.y = (0.0, 0.1);
        block.solids[0].velocity = (6.0, 0.0);
        case.run.stop_at_rest = None;
        case.fidelity.smoke.end_time = 1.2;
        runout_case::validate_case(&case).unwrap();
        let dir = std::env::temp_dir().join(format!("runout-foot-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let summary = runout_run::run_case(&case, Fidelity::Smoke, &dir, |_| {}).unwrap();
        assert_eq!(summary.status, runout_output::RunStatus::Completed, "{tag}");
        assert!(
            summary.solids_mass_change.abs() < 1e-9,
            "{tag}: {}",
            summary.solids_mass_change
        );
        let out = speeds_and_front(&dir);
        std::fs::remove_dir_all(&dir).unwrap();
        out
    };
    let foot = 12.0 + 2.0 * 40f64.to_radians();
    let (speeds, front) = run(BEND, "bend");
    let largest = speeds.iter().fold(0.0, |m: f64, &v| m.max(v));
    let last = *speeds.last().unwrap();
    assert!(front > foot + 1.0, "front {front} m, foot {foot} m");
    assert!(
        last < 0.8 * largest,
        "last {last} m/s, largest {largest} m/s"
    );
    let (plane, _) = run(Bed::Plane, "plane");
    let plane_last = *plane.last().unwrap();
    eprintln!("bend: front {front} m, mean u_s largest {largest}, last {last}; plane last {plane_last} m/s");
    assert!(
        plane_last > 1.2 * last,
        "plane {plane_last} m/s, bend {last} m/s"
    );
}
