//! Side walls of a quasi-2-D channel (docs/model.md §8), issue 23 item 1: the plane limit.
//! A case with side walls of an enormous width (W = 1e30 m) gives the plane case's fields
//! bit for bit over a few two-fluid steps, while the flume's 0.30 m changes them (so the
//! comparison can fail). The slide: the flume base at smoke size with its block put on the
//! floor, sliding at 2 m/s down a constant 40° slope.

use std::path::Path;

use runout_case::{load_case, Fidelity, GasSidewall, Gravity, Sidewalls, SolidsWall};
use runout_run::two_fluid_solver;
use runout_solver::two_fluid::TwoFluid;

/// Steps of the comparison and their Δt [s].
const STEPS: usize = 5;
const DT: f64 = 2e-4;

fn flume_slide(sidewalls: Option<Sidewalls>) -> TwoFluid {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut case = load_case(&root.join("cases/flume/base.ron")).unwrap();
    case.gravity = Gravity::Constant {
        magnitude: 9.80665,
        slope: 40.0,
    };
    let block = &mut case.initial.regions[0];
    block.y = (0.0, 0.2);
    block.solids[0].velocity = (2.0, 0.0);
    block.solids[0].theta = 1e-3;
    case.sidewalls = sidewalls;
    runout_case::validate_case(&case).unwrap();
    let case = case.at_fidelity(Fidelity::Smoke);
    let mut tf = two_fluid_solver(&case).unwrap();
    let tol = &case.run.tolerances;
    for _ in 0..STEPS {
        let step = tf
            .step(
                DT,
                tol.residual,
                tol.theta_residual,
                tol.diverge,
                tol.max_iterations as usize,
            )
            .unwrap();
        assert!(step.converged, "{step:?}");
    }
    tf
}

fn walls(width: f64, solids: SolidsWall) -> Option<Sidewalls> {
    Some(Sidewalls {
        width,
        solids,
        gas: GasSidewall::NoSlip,
    })
}

/// Every field of the two solvers as bit patterns.
fn fields(tf: &TwoFluid) -> Vec<Vec<u64>> {
    let bits = |f: &[f64]| f.iter().map(|v| v.to_bits()).collect::<Vec<u64>>();
    let mut out = vec![
        bits(tf.eps_g()),
        bits(tf.p_g()),
        bits(tf.u_g()),
        bits(tf.v_g()),
    ];
    for s in tf.state().phases() {
        out.extend([bits(s.eps()), bits(&s.u), bits(&s.v), bits(&s.theta)]);
    }
    out
}

fn largest_difference(a: &TwoFluid, b: &TwoFluid) -> f64 {
    a.solids(0)
        .u
        .iter()
        .zip(&b.solids(0).u)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

#[test]
fn an_enormous_width_gives_the_plane_flow_bit_for_bit() {
    let jj = SolidsWall::JohnsonJackson {
        specularity: 0.1,
        wall_restitution: 0.7,
        wall_friction_angle: 11.0,
        u_w: 0.0,
    };
    let plane = flume_slide(None);
    let wide = flume_slide(walls(1e30, jj.clone()));
    assert!(
        fields(&plane) == fields(&wide),
        "W = 1e30 m changed the fields (largest u_s difference {:e} m/s)",
        largest_difference(&plane, &wide)
    );
    // the flume's width changes them: the test can fail
    let flume = flume_slide(walls(0.30, jj));
    let change = largest_difference(&plane, &flume);
    assert!(
        change > 1e-3,
        "W = 0.30 m changed u_s by only {change:e} m/s"
    );
}

#[test]
fn jenkins_side_walls_slow_the_slide() {
    let jenkins = SolidsWall::Jenkins {
        wall_restitution: 0.7,
        wall_friction_angle: 11.0,
        u_w: 0.0,
    };
    let plane = flume_slide(None);
    let wide = flume_slide(walls(1e30, jenkins.clone()));
    assert!(fields(&plane) == fields(&wide));
    let flume = flume_slide(walls(0.30, jenkins));
    let mean_u = |tf: &TwoFluid| {
        let s = tf.solids(0);
        let nx = tf.grid().nx();
        let (mut num, mut den) = (0.0, 0.0);
        for (k, e) in s.eps().iter().enumerate() {
            let (i, j) = (k % nx, k / nx);
            num += e * 0.5 * (s.u[i + (nx + 1) * j] + s.u[i + 1 + (nx + 1) * j]);
            den += e;
        }
        num / den
    };
    assert!(
        mean_u(&flume) < mean_u(&plane) - 1e-3,
        "side walls did not slow the slide: {} vs {} m/s",
        mean_u(&flume),
        mean_u(&plane)
    );
}
