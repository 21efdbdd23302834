//! Side walls of a quasi-2-D channel (docs/model.md §8), issue 23 item 1: the plane limit.
//! A case with side walls of an enormous width (W = 1e30 m) gives the plane case's fields
//! bit for bit over a few two-fluid steps, while the flume's 0.30 m changes them (so the
//! comparison can fail). The slide: the flume base at smoke size with its block put on the
//! floor, sliding at 2 m/s down a constant 40° slope.

use std::path::Path;

use runout_case::{load_case, Case, Fidelity, GasSidewall, Gravity, Sidewalls, SolidsWall};
use runout_closures::{FrictionModel, MuIConstants};
use runout_run::two_fluid_solver;
use runout_solver::two_fluid::TwoFluid;

/// Steps of the comparison and their Δt [s].
const STEPS: usize = 5;
const DT: f64 = 2e-4;

fn flume_slide(sidewalls: Option<Sidewalls>) -> TwoFluid {
    flume_slide_with(sidewalls, |_| {}, |_| {})
}

/// The slide of [`flume_slide`] with the case changed by `adjust` first and `after_step`
/// called with the solver after each step.
fn flume_slide_with(
    sidewalls: Option<Sidewalls>,
    adjust: impl Fn(&mut Case),
    mut after_step: impl FnMut(&TwoFluid),
) -> TwoFluid {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut case = load_case(&root.join("cases/flume/base.ron")).unwrap();
    adjust(&mut case);
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
        after_step(&tf);
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

/// The solids momentum Σ εs u V of a solver's cells [m⁴ s⁻¹] (u at the cell centre).
fn momentum(tf: &TwoFluid) -> f64 {
    let s = tf.solids(0);
    let g = tf.grid();
    let (nx, dx, dy) = (g.nx(), g.x.widths(), g.y.widths());
    s.eps()
        .iter()
        .enumerate()
        .map(|(k, e)| {
            let (i, j) = (k % nx, k / nx);
            e * 0.5 * (s.u[i + (nx + 1) * j] + s.u[i + 1 + (nx + 1) * j]) * dx[i] * dy[j]
        })
        .sum()
}

/// ∫N dV over the cells with solids [Pa m²]: the side walls' normal load, the pressure
/// P_kin + P_c ([`mu_i_pressure`]) and the load beyond it that the solver measured
/// ([`TwoFluid::sidewall_extra_normal_load`], −λ_s tr D).
fn load_volume(tf: &TwoFluid) -> f64 {
    let s = tf.solids(0);
    let g = tf.grid();
    let (nx, dx, dy) = (g.nx(), g.x.widths(), g.y.widths());
    let extra = tf.sidewall_extra_normal_load(0);
    s.eps()
        .iter()
        .zip(&s.theta)
        .enumerate()
        .filter(|(_, (&eps, _))| eps > 1e-4)
        .map(|(k, (&eps, &theta))| {
            (mu_i_pressure(eps, theta) + extra[k]).max(0.0) * dx[k % nx] * dy[k / nx]
        })
        .sum()
}

/// Prints the ratio of the momentum the block `lost` to the walls' impulse `expected`
/// [m⁴ s⁻¹] and asserts it within 2 %.
fn assert_budget(what: &str, lost: f64, expected: f64) {
    println!(
        "{what}: momentum lost {lost:e}, expected {expected:e}, ratio {}",
        lost / expected
    );
    assert!(
        (lost / expected - 1.0).abs() < 0.02,
        "momentum lost to the {what} {lost:e}, their impulse over ρs {expected:e}"
    );
}

/// Coulomb side walls (docs/model.md §3.11) take μ_w N per unit wall area from a block that
/// slides at 2 m/s (|u_sl| ≫ u_min): each step of Δt the block loses
/// (2/W) μ_w ∫N dV Δt/ρs of its momentum Σ εs u V, with N (the pressure and −λ_s tr D) at
/// the step's end (the walls' terms are implicit).
#[test]
fn coulomb_side_walls_take_mu_w_n_from_a_sliding_block() {
    let mu_i = |case: &mut Case| {
        case.models.friction = FrictionModel::MuI(MuIConstants::glass_beads_jop_2005());
        // the walls change u by 3e-4 of itself per step, below the case's residual 1e-3: the
        // outer iterations must converge further for the budget to close
        case.run.tolerances.residual = 1e-6;
    };
    let (width, mu_w, rho_s) = (0.30, 0.4, 2300.0);
    let coulomb = SolidsWall::Coulomb {
        friction: mu_w,
        slip_floor: None,
    };
    let plane = flume_slide_with(None, mu_i, |_| {});
    let mut expected = 0.0;
    let walled = flume_slide_with(walls(width, coulomb), mu_i, |tf| {
        expected += 2.0 / width * mu_w * load_volume(tf) * DT / rho_s;
    });
    assert_budget("side walls", momentum(&plane) - momentum(&walled), expected);
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

/// μ(I)'s pressure P_kin + P_c [Pa] at (εs, θ), written from the formulas (Lun 1984 with
/// Carnahan–Starling; paper Eq. 10 with MFIX's Fr = 0.05 Pa), the flume's grains.
fn mu_i_pressure(eps: f64, theta: f64) -> f64 {
    let (rho_s, e) = (2300.0, 0.9);
    let g0 = (1.0 - 0.5 * eps) / (1.0 - eps).powi(3);
    let p_kin = rho_s * eps * theta * (1.0 + 2.0 * (1.0 + e) * eps * g0);
    let p_c = if eps > 0.5 {
        0.05 * (eps - 0.5).powi(2) / (0.65 - eps).powi(5)
    } else {
        0.0
    };
    p_kin + p_c
}

/// A Coulomb floor (docs/model.md §3.11) under the sliding μ(I) block, against a free-slip
/// one: each step the block loses Σ μ_w N_w w Δt/ρs of its momentum, summed over the floor's
/// u nodes of width w, with N_w the normal load the floor read at each node
/// ([`TwoFluid::floor_normal_load`]: the pressure and the load beyond it; no stress where the
/// cell west of the node holds εs ≤ 1e-4, docs/model.md §3.5 step 0). That N_w is the
/// block's weight is `cargo test --release -p runout-verification --test coulomb_floor`'s
/// check; this one, that the floor imposes μ_w times it.
#[test]
fn a_coulomb_floor_takes_mu_w_n_from_a_sliding_block() {
    let (mu_w, rho_s) = (0.4, 2300.0);
    let floor = |solids: SolidsWall| {
        move |case: &mut Case| {
            case.models.friction = FrictionModel::MuI(MuIConstants::glass_beads_jop_2005());
            // see coulomb_side_walls_take_mu_w_n_from_a_sliding_block
            case.run.tolerances.residual = 1e-6;
            if let runout_case::Boundary::Wall { solids: s, .. } = &mut case.boundaries.south {
                *s = solids.clone();
            }
        }
    };
    let free = flume_slide_with(None, floor(SolidsWall::FreeSlip), |_| {});
    let coulomb = SolidsWall::Coulomb {
        friction: mu_w,
        slip_floor: None,
    };
    let mut expected = 0.0;
    let mut beyond_pressure: f64 = 0.0;
    let walled = flume_slide_with(None, floor(coulomb), |tf| {
        let s = tf.solids(0);
        let x = &tf.grid().x;
        let dx = x.widths();
        let load = tf.floor_normal_load(0);
        // interior u nodes k (between cells k − 1 and k) of the floor row
        let force: f64 = (1..tf.grid().nx())
            .filter(|&k| s.eps()[k - 1] > 1e-4)
            .map(|k| {
                let w = x.interpolation_weight(k - 1);
                let eps = w * s.eps()[k - 1] + (1.0 - w) * s.eps()[k];
                let theta = 0.5 * (s.theta[k - 1] + s.theta[k]);
                beyond_pressure = beyond_pressure.max((load[k] - mu_i_pressure(eps, theta)).abs());
                mu_w * load[k] * 0.5 * (dx[k - 1] + dx[k])
            })
            .sum();
        expected += force * DT / rho_s;
    });
    // the floor read more than the pressure (the half cell's weight at least)
    assert!(beyond_pressure > 1.0, "{beyond_pressure} Pa");
    assert_budget("floor", momentum(&free) - momentum(&walled), expected);
}
