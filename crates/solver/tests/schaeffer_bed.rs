//! Packed bed with Schaeffer friction (docs/model.md §2.4.1): a bed poured at εs = 0.62
//! (d = 0.5 mm, Gidaspow drag) in a closed box settles under gravity until the plastic
//! pressure P* = A (εg* − εg)^10 (A = 1e24 Pa) carries its weight. The check is the vertical
//! momentum balance of the bed at rest: P_s + P* at the bottom cells' centres equals the
//! weight per area above them within 2 %, and P* carries nearly all of it (θ is forced to
//! θ_small where εg < εg*, docs/model.md §1.3, so the kinetic P_s is negligible there). Also:
//! εs at the bottom above εs,max and every εs below εs,max + 1e-2 (P* ≈ 0.94 kPa at
//! εs ≈ 0.658), solids mass conserved to 1e-10, every field finite. Without the −∇P* term in
//! the solids momentum (§4.4) only the εs correction resists the compaction: the steps then
//! stop converging (300 outer iterations each) and the mass check fails by 3.6e-5.
//! The steps are converged tightly (solids imbalance 1e-9 of the first iteration's): in
//! cells beyond εs,max the selective relaxation of §4.7 leaves an imbalance of one sign,
//! i.e. a mass error of the order of the step tolerance.

use runout_closures::FrictionModel;
use runout_mesh::{Axis, Grid, Sides};
use runout_solver::two_fluid::{SolidsSpec, TwoFluid, TwoFluidSettings};
use runout_solver::{Fluid, SideBc};
use runout_walls::{RobinFace, SolidsWallModel};

mod common;
use common::paper_particles_in_air;

const EPS_MAX: f64 = 0.65;

fn bed(steps: usize, dt: f64, verbose: bool) -> (TwoFluid, f64) {
    let (nx, ny, height) = (3, 24, 0.12);
    let grid = Grid::new(
        Axis::uniform(0.0, 0.015, nx).unwrap(),
        Axis::uniform(0.0, height, ny).unwrap(),
    );
    let gas = Fluid {
        density: 1.2,
        viscosity: 1.8e-5,
    };
    let no_slip = SideBc::Wall(RobinFace::dirichlet(0.0));
    let free_slip = SideBc::Wall(RobinFace::ZERO_GRADIENT);
    let params = paper_particles_in_air(FrictionModel::schaeffer(), EPS_MAX);
    let spec = SolidsSpec {
        params,
        eps_max: EPS_MAX,
        walls: Sides {
            west: Some(SolidsWallModel::FreeSlip),
            east: Some(SolidsWallModel::FreeSlip),
            south: Some(SolidsWallModel::NoSlip),
            north: Some(SolidsWallModel::NoSlip),
        },
    };
    let gas_walls = Sides {
        west: free_slip,
        east: free_slip,
        south: no_slip,
        north: no_slip,
    };
    let mut tf = TwoFluid::new(
        grid.clone(),
        gas,
        gas_walls,
        vec![spec],
        (0.0, -9.81),
        TwoFluidSettings::default(),
    )
    .unwrap();
    tf.state_mut().update_solids(0, |s| {
        for j in 0..ny {
            for i in 0..nx {
                if grid.y.centres()[j] < 0.08 {
                    s.eps[i + nx * j] = 0.62;
                }
                s.theta[i + nx * j] = 1e-4;
            }
        }
    });
    let mass0 = tf.solids_mass(0);
    for step in 0..steps {
        tf.begin_step();
        let mut last = None;
        let mut first_imbalance = None;
        for it in 0..300 {
            let r = tf.outer_iteration(dt).unwrap();
            last = Some((it, r));
            let s0 = *first_imbalance.get_or_insert(r.solids_mass.max(f64::MIN_POSITIVE));
            if it > 1 && r.momentum < 1e-4 && r.theta < 1e-3 && r.solids_mass <= 1e-9 * s0 {
                break;
            }
        }
        if verbose && step % 25 == 0 {
            let max_eps = tf.solids(0).eps().iter().cloned().fold(0.0, f64::max);
            eprintln!(
                "step {step}: {last:?} max eps {max_eps:.5} P* floor {:.1} mass rel change {:.3e}",
                tf.p_star(0)[0],
                tf.solids_mass(0) / mass0 - 1.0
            );
        }
    }
    (tf, mass0)
}

/// 0.2 s: the bed compacts just past εs,max and P* at the floor carries its weight.
#[test]
fn schaeffer_bed_weight_is_carried_by_the_plastic_pressure() {
    let (tf, mass0) = bed(200, 1e-3, std::env::var("RUNOUT_VERBOSE").is_ok());
    let grid = tf.grid();
    let (nx, ny) = (grid.nx(), grid.ny());
    let s = tf.solids(0);
    let mass = tf.solids_mass(0);
    assert!(
        (mass / mass0 - 1.0).abs() <= 1e-10,
        "mass change {}",
        mass / mass0 - 1.0
    );
    assert!(s
        .eps()
        .iter()
        .chain(&s.u)
        .chain(&s.v)
        .chain(&s.theta)
        .chain(tf.p_s(0))
        .chain(tf.p_star(0))
        .chain(tf.p_g())
        .all(|x| x.is_finite()));
    let max_eps = s.eps().iter().cloned().fold(0.0, f64::max);
    let mean_bottom = |f: &[f64]| (0..nx).map(|i| f[i]).sum::<f64>() / nx as f64;
    let eps_bottom = mean_bottom(s.eps());
    // packed just beyond εs,max, where P* grows as (εs − εs,max)^10
    assert!(
        eps_bottom > EPS_MAX && max_eps < EPS_MAX + 1e-2,
        "bottom eps {eps_bottom}, max eps {max_eps}"
    );
    // the top of the domain is empty
    assert!(s.eps()[nx * (ny - 1)] < 1e-6);
    // weight per area above the bottom cells' centres
    let (width, dy, g, rho_s) = (grid.x.length(), grid.y.widths()[0], 9.81, 2000.0);
    let weight = mass0 * g / width - rho_s * eps_bottom * g * 0.5 * dy;
    let p_star_bottom = mean_bottom(tf.p_star(0));
    let p_s_bottom = mean_bottom(tf.p_s(0));
    eprintln!(
        "Schaeffer bed: P* {p_star_bottom:.2} Pa + P_s {p_s_bottom:.3e} Pa at the bottom \
         centres, weight above them {weight:.2} Pa, bottom eps {eps_bottom:.5}, max eps \
         {max_eps:.5}"
    );
    let support = p_star_bottom + p_s_bottom;
    assert!(
        (support / weight - 1.0).abs() < 0.02,
        "P* + P_s = {support} Pa vs weight {weight} Pa"
    );
    assert!(
        p_star_bottom > 0.98 * weight,
        "P* = {p_star_bottom} Pa carries too little of {weight} Pa"
    );
}
