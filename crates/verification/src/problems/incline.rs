//! Issue 43's inclined-plane check of the μ(I) law: a layer of glass beads on a rough
//! (no-slip) incline, periodic along the slope, computed by the 2-D two-fluid solver as the
//! `chute` check's column ([`crate::problems::chute_column`]) and marched to its steady state.
//!
//! **Flowing, μ_s < tan α < μ_2.** In steady, fully developed flow the weight above a depth
//! sets both stresses: τ(y) = tan α P(y), P(y) = ρ_s g cos α ∫_y^H εs dy'. Where the μ(I)
//! stress is the whole shear stress (the dense layer, docs/model.md §2.4.4: the kinetic
//! viscosity joins as the larger of the two) μ(I) = τ/P = tan α, so the inertial number is the
//! same at every depth, I_α = I_0 (tan α − μ_s)/(μ_2 − tan α), and the shear rate follows the
//! pressure: γ̇ = (I_α/d) √(P/ρ_s). The velocity is its integral from the floor (Bagnold
//! profile; Jop, Forterre & Pouliquen 2005, JFM 541, §3; GDR MiDi 2004):
//!
//!   u(y) = (I_α/d) ∫_0^y √(P(y')/ρ_s) dy'                                   (generalised)
//!   u(y) = (2/3)(I_α/d) √(φ g cos α) [h^{3/2} − (h − y)^{3/2}]              (uniform εs = φ)
//!
//! The layer's εs is not uniform in the model (P = P_kin + P_c(εs) rises with depth, so εs
//! runs from εs,min near the surface to about 0.57 at the floor), so the check's reference is
//! the generalised form with the run's own εs: [`bagnold_profile`] integrates √P exactly over
//! the piecewise-linear P of the cell centres. The uniform closed form with the layer's mean
//! εs is reported beside it ([`uniform_bagnold_surface_speed`]).
//!
//! **At rest, tan α < μ_s.** A layer started at rest stays at rest up to the creep of the
//! regularisation (docs/model.md §2.4.4): with τ/P = r μ_s, r = tan α/μ_s < 1, uniform, the
//! shear rate is γ̇_min r/√(1 − r²) everywhere ([`runout_closures::mu_i::creep_shear_rate`]),
//! so the surface moves at h γ̇_min r/√(1 − r²).
//!
//! Set-up: glass beads d = 0.53 mm, ρs = 2500 kg m⁻³, e = 0.9, εs,max = 0.65, εs,min = 0.5,
//! μ(I) of Jop et al. (2005): μ_s = tan 20.9°, μ_2 = tan 32.76°, I_0 = 0.279 (the collapse
//! check's material, cases/collapse/CM-a1.ron); holdup 5.5 mm (a layer h ≈ 9.7 mm ≈ 18 d) in
//! a strip H = 12.5 mm high, so the free surface lies inside the grid with the negligible
//! gas above it (the chute check's ρ_g = 1e-3 kg m⁻³, μ_g = 1e-8 Pa s); free-slip lid.

use runout_closures::{
    ClosureParams, FrictionModel, FrictionParams, Gas, MuIConstants, Particles, PrincetonConstants,
};
use runout_walls::SolidsWallModel;

use crate::problems::chute_column::{
    steady_column, ChuteCheckError, ChuteCheckSetup, SteadyColumn,
};

/// Standard gravity of the check [m s⁻²] (the chute column's).
pub const GRAVITY: f64 = 9.81;
/// Bead diameter d \[m\] (Jop et al. 2005).
pub const DIAMETER: f64 = 5.3e-4;
/// Bead density ρ_s [kg m⁻³].
pub const DENSITY: f64 = 2500.0;
/// Holdup M = ∫ εs dy of the layer \[m\].
pub const HOLDUP: f64 = 0.0055;
/// Height H of the strip \[m\]: the layer and about a quarter of it again of gas.
pub const HEIGHT: f64 = 0.0125;
/// Depth steps of the integration of the hydrostatic starting layer ([`packed_layer`]).
const PACKING_STEPS: usize = 20_000;
/// The flowing slope [deg]: tan α = 0.466 between μ_s = 0.382 and μ_2 = 0.643, I_α = 0.133.
pub const FLOWING_SLOPE_DEG: f64 = 25.0;
/// The slope at rest [deg]: tan α = 0.325, r = tan α/μ_s = 0.85.
pub const REST_SLOPE_DEG: f64 = 18.0;
/// εs from which a cell counts as the dense layer in the comparisons [-].
pub const DENSE: f64 = 0.3;

/// The glass beads with the μ(I) law, dry (the gas is added by the column).
pub fn glass_beads() -> ClosureParams {
    ClosureParams {
        particles: Particles {
            diameter: DIAMETER,
            density: DENSITY,
            restitution: 0.9,
        },
        gas: Gas {
            density: 0.0,
            ..Gas::default()
        },
        friction: FrictionParams::new(0.65, 0.5, 35.0),
        friction_model: FrictionModel::MuI(MuIConstants::glass_beads_jop_2005()),
        ..ClosureParams::default()
    }
}

/// The μ(I) constants of [`glass_beads`].
pub fn law() -> MuIConstants {
    MuIConstants::glass_beads_jop_2005()
}

/// I_α = I_0 (tan α − μ_s)/(μ_2 − tan α) [-], the inertial number with μ(I_α) = tan α;
/// `None` outside μ_s < tan α < μ_2 (no steady flow).
pub fn slope_inertial_number(law: &MuIConstants, slope_deg: f64) -> Option<f64> {
    let tan = slope_deg.to_radians().tan();
    (law.mu_s < tan && tan < law.mu_2).then(|| law.i_0 * (tan - law.mu_s) / (law.mu_2 - tan))
}

/// εs with P_c(εs) = `pressure` (bisection between εs,min and εs,max; εs,min at P = 0).
fn packing_at(pressure: f64, closures: &ClosureParams) -> f64 {
    let f = &closures.friction;
    let (mut lo, mut hi) = (f.eps_s_min, f.eps_s_max);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if PrincetonConstants::MFIX.critical_pressure(mid, f) < pressure {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The starting layer on `cells` uniform cells of the strip: at rest and in hydrostatic
/// balance on its critical-state pressure, P_c(εs(ζ)) = ρ_s g cos α ∫_0^ζ εs dζ' at depth ζ
/// (θ → 0), integrated down from εs,min at the surface until it holds [`HOLDUP`], then
/// averaged over the cells.
pub fn packed_layer(cells: usize, slope_deg: f64) -> Vec<f64> {
    let closures = glass_beads();
    let weight = DENSITY * GRAVITY * slope_deg.to_radians().cos();
    // εs(ζ) on a fine depth grid: midpoint steps of dP/dζ = ρ g cos α εs(P)
    let step = 2.0 * HOLDUP / closures.friction.eps_s_min / PACKING_STEPS as f64;
    let (mut pressure, mut held) = (0.0, 0.0);
    let mut layer = Vec::with_capacity(PACKING_STEPS);
    while held < HOLDUP {
        let half = packing_at(
            pressure + 0.5 * step * weight * packing_at(pressure, &closures),
            &closures,
        );
        let eps = half.min((HOLDUP - held) / step);
        layer.push(eps);
        held += eps * step;
        pressure += weight * eps * step;
    }
    // top down → floor up, averaged over the cells
    let dy = HEIGHT / cells as f64;
    let depth = layer.len() as f64 * step;
    (0..cells)
        .map(|j| {
            let (bottom, top) = (j as f64 * dy, (j + 1) as f64 * dy);
            let covered: f64 = layer
                .iter()
                .enumerate()
                .map(|(k, eps)| {
                    // fine step k spans heights depth − (k + 1) step … depth − k step
                    let (lo, hi) = (depth - (k + 1) as f64 * step, depth - k as f64 * step);
                    eps * (hi.min(top) - lo.max(bottom)).max(0.0)
                })
                .sum();
            covered / dy
        })
        .collect()
}

/// The column of the check on `cells` uniform cells at `slope_deg`: started at rest as the
/// [`packed_layer`], θ = 1e-6 m²/s².
pub fn setup(cells: usize, slope_deg: f64) -> ChuteCheckSetup {
    ChuteCheckSetup {
        cells,
        height: HEIGHT,
        holdup: HOLDUP,
        slope_deg,
        floor: SolidsWallModel::NoSlip,
        closures: glass_beads(),
        initial_velocity: 0.0,
        initial_theta: 1e-6,
        initial_eps_s: Some(packed_layer(cells, slope_deg)),
        end_time: 20.0,
        ..ChuteCheckSetup::default()
    }
}

/// The generalised Bagnold velocity at the cell centres `y` (widths `dy`, from a no-slip
/// floor at y = 0) for the layer's εs: P at the centres from the weight above
/// (P_i = ρ_s g cos α (Σ_{j>i} εs_j Δy_j + εs_i Δy_i/2), P = 0 at the lid), linear between
/// centres and to the floor, and u(y) = (I_α/d) ∫_0^y √(P/ρ_s) dy' integrated exactly on each
/// linear piece (∫ √(a + b s) ds in closed form).
pub fn bagnold_profile(
    y: &[f64],
    dy: &[f64],
    eps_s: &[f64],
    slope_deg: f64,
    inertial_number: f64,
) -> Vec<f64> {
    let n = y.len();
    let weight = DENSITY * GRAVITY * slope_deg.to_radians().cos();
    let mut pressure = vec![0.0; n];
    let mut above = 0.0;
    for i in (0..n).rev() {
        pressure[i] = weight * (above + 0.5 * eps_s[i] * dy[i]);
        above += eps_s[i] * dy[i];
    }
    // the floor's value from the first centre's slope (the weight of the half cell)
    let floor_pressure = pressure[0] + weight * 0.5 * eps_s[0] * dy[0];
    let rate = |p: f64| inertial_number / DIAMETER * (p.max(0.0) / DENSITY).sqrt();
    let mut u = vec![0.0; n];
    let (mut from_y, mut from_p, mut integral) = (0.0, floor_pressure, 0.0);
    for i in 0..n {
        integral += linear_sqrt_integral(from_p, pressure[i], y[i] - from_y, &rate);
        u[i] = integral;
        (from_y, from_p) = (y[i], pressure[i]);
    }
    u
}

/// ∫_0^L f(P(s)) ds for P linear from `p0` to `p1` over a length `length`, where
/// f(P) = c √P: (2/3) c (p1^{3/2} − p0^{3/2}) L/(p1 − p0), or c √p0 L for p1 = p0.
fn linear_sqrt_integral(p0: f64, p1: f64, length: f64, rate: &impl Fn(f64) -> f64) -> f64 {
    let (p0, p1) = (p0.max(0.0), p1.max(0.0));
    let c = rate(1.0);
    if (p1 - p0).abs() <= 1e-12 * p0.max(p1) {
        return c * p0.sqrt() * length;
    }
    2.0 / 3.0 * c * (p1.powf(1.5) - p0.powf(1.5)) / (p1 - p0) * length
}

/// The surface speed of the uniform closed form, (2/3)(I_α/d) √(φ g cos α) h^{3/2}, for a
/// layer of holdup M at εs = φ (h = M/φ) [m/s].
pub fn uniform_bagnold_surface_speed(phi: f64, slope_deg: f64, inertial_number: f64) -> f64 {
    let h = HOLDUP / phi;
    2.0 / 3.0 * inertial_number / DIAMETER
        * (phi * GRAVITY * slope_deg.to_radians().cos()).sqrt()
        * h.powf(1.5)
}

/// A flowing run against the Bagnold profile.
#[derive(Clone, Debug)]
pub struct FlowingIncline {
    /// the steady column
    pub column: SteadyColumn,
    /// the generalised Bagnold velocity with the column's εs [m/s]
    pub reference: Vec<f64>,
    /// max over the dense layer (εs ≥ [`DENSE`]) of |u − u_ref|, relative to max u_ref
    pub velocity_error: f64,
    /// the solids flux Σ εs u Δy relative to the reference's, minus 1
    pub flux_error: f64,
    /// the largest u_s of the dense layer [m/s]
    pub surface_speed: f64,
    /// the dense layer's mean εs, M over its depth [-]
    pub mean_eps_s: f64,
    /// the uniform closed form's surface speed at that εs [m/s]
    pub uniform_surface_speed: f64,
}

/// Runs the flowing column on `cells` cells and compares it with the Bagnold profile.
pub fn flowing(cells: usize, verbose: bool) -> Result<FlowingIncline, ChuteCheckError> {
    let slope = FLOWING_SLOPE_DEG;
    let inertial = slope_inertial_number(&law(), slope).expect("the flowing slope flows");
    let dy = vec![HEIGHT / cells as f64; cells];
    let start = setup(cells, slope);
    // started on the Bagnold profile of the packed layer: from rest or sliding as a block
    // the first step of 100 cells and more does not converge (the Coulomb viscosity's
    // fixed point at a shear rate far from its own); the steady state does not remember the
    // start (50 cells from rest: the same error, 9.072e-4)
    let centres: Vec<f64> = (0..cells).map(|j| (j as f64 + 0.5) * dy[j]).collect();
    let packed = start.initial_eps_s.clone().expect("the packed layer");
    let initial_u_s = bagnold_profile(&centres, &dy, &packed, slope, inertial);
    let column = steady_column(&ChuteCheckSetup {
        verbose,
        initial_u_s: Some(initial_u_s),
        ..start
    })?;
    let reference = bagnold_profile(&column.y, &dy, &column.eps_s, slope, inertial);
    let dense: Vec<usize> = (0..cells).filter(|&i| column.eps_s[i] >= DENSE).collect();
    let largest = dense.iter().map(|&i| reference[i]).fold(0.0, f64::max);
    let velocity_error = dense
        .iter()
        .map(|&i| (column.u_s[i] - reference[i]).abs())
        .fold(0.0, f64::max)
        / largest;
    let flux = |u: &[f64]| -> f64 { (0..cells).map(|i| column.eps_s[i] * u[i] * dy[i]).sum() };
    let flux_error = flux(&column.u_s) / flux(&reference) - 1.0;
    let surface_speed = dense.iter().map(|&i| column.u_s[i]).fold(0.0, f64::max);
    let depth: f64 = dense.iter().map(|&i| dy[i]).sum();
    let dense_holdup: f64 = dense.iter().map(|&i| column.eps_s[i] * dy[i]).sum();
    let mean_eps_s = dense_holdup / depth;
    Ok(FlowingIncline {
        uniform_surface_speed: uniform_bagnold_surface_speed(mean_eps_s, slope, inertial),
        column,
        reference,
        velocity_error,
        flux_error,
        surface_speed,
        mean_eps_s,
    })
}

/// A layer below μ_s.
#[derive(Clone, Debug)]
pub struct RestingIncline {
    /// the column at the end
    pub column: SteadyColumn,
    /// the largest u_s of the dense layer [m/s]
    pub surface_speed: f64,
    /// the creep of the regularisation, h γ̇_min r/√(1 − r²), h = M/(mean εs) [m/s]
    pub creep_speed: f64,
    /// 1 % of √(g h), the collapse check's "at rest" speed [m/s]
    pub rest_speed: f64,
}

/// Runs the column at rest on `cells` cells for `duration` seconds.
pub fn resting(
    cells: usize,
    duration: f64,
    verbose: bool,
) -> Result<RestingIncline, ChuteCheckError> {
    let slope = REST_SLOPE_DEG;
    let law = law();
    let column = steady_column(&ChuteCheckSetup {
        verbose,
        end_time: duration,
        // run the whole duration: the creep is what is measured
        steady_rate: 0.0,
        ..setup(cells, slope)
    })?;
    let dense: Vec<usize> = (0..cells).filter(|&i| column.eps_s[i] >= DENSE).collect();
    let surface_speed = dense
        .iter()
        .map(|&i| column.u_s[i].abs())
        .fold(0.0, f64::max);
    let depth = HOLDUP / (dense.iter().map(|&i| column.eps_s[i]).sum::<f64>() / dense.len() as f64);
    let ratio = slope.to_radians().tan() / law.mu_s;
    let creep_speed = depth * runout_closures::mu_i::creep_shear_rate(law.shear_rate_floor, ratio);
    Ok(RestingIncline {
        column,
        surface_speed,
        creep_speed,
        rest_speed: 0.01 * (GRAVITY * depth).sqrt(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The generalised profile of a uniform layer is the closed form at the centres (the
    /// centres' pressure is then exact and linear, and each piece is integrated exactly).
    #[test]
    fn a_uniform_layer_gives_the_closed_form() {
        let (n, phi, slope, inertial) = (400, 0.6, 25.0, 0.1);
        let h = HOLDUP / phi;
        let dy = vec![h / n as f64; n];
        let y: Vec<f64> = (0..n).map(|i| (i as f64 + 0.5) * dy[0]).collect();
        let u = bagnold_profile(&y, &dy, &vec![phi; n], slope, inertial);
        let g_n = GRAVITY * f64::to_radians(slope).cos();
        let closed = |z: f64| {
            2.0 / 3.0 * inertial / DIAMETER * (phi * g_n).sqrt() * (h.powf(1.5) - (h - z).powf(1.5))
        };
        let surface = uniform_bagnold_surface_speed(phi, slope, inertial);
        assert!((closed(h) - surface).abs() < 1e-12 * surface);
        for i in 0..n {
            assert!(
                (u[i] - closed(y[i])).abs() < 1e-12 * surface,
                "{i}: {} {}",
                u[i],
                closed(y[i])
            );
        }
    }

    /// The packed layer holds the holdup and lies in the strip.
    #[test]
    fn the_packed_layer_holds_the_holdup() {
        for cells in [25, 50, 200] {
            let eps = packed_layer(cells, FLOWING_SLOPE_DEG);
            let held: f64 = eps.iter().sum::<f64>() * HEIGHT / cells as f64;
            assert!((held / HOLDUP - 1.0).abs() < 1e-9, "{cells}: {held}");
            assert!(eps.iter().all(|e| (0.0..0.65).contains(e)));
            assert_eq!(*eps.last().unwrap(), 0.0);
        }
    }

    /// I_α solves μ(I_α) = tan α, and no flow outside (μ_s, μ_2).
    #[test]
    fn the_slope_sets_the_inertial_number() {
        let m = law();
        let i = slope_inertial_number(&m, FLOWING_SLOPE_DEG).unwrap();
        let tan = FLOWING_SLOPE_DEG.to_radians().tan();
        assert!((m.friction_coefficient(i) - tan).abs() < 1e-14);
        assert!(slope_inertial_number(&m, REST_SLOPE_DEG).is_none());
        assert!(slope_inertial_number(&m, 40.0).is_none());
    }
}
