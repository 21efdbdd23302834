//! Verification of the 1-D steady chute solver (`runout_verification::chute1d`, docs/studies/chute1d.md):
//! the discrete diffusion operator against closed forms, the integral momentum and energy
//! balances of a converged profile, grid convergence of u_s and θ on uniform and stretched
//! grids against a fine-grid solution, and the error paths.

use runout_closures::{ClosureParams, Gas};
use runout_mesh::{Axis, Segment};
use runout_verification::chute1d::{
    diffusive_fluxes, interpolate, solve, solve_linear_diffusion, Chute1dError, ChuteParams,
    ChuteProfile, InitialGuess, SolverSettings, WallTreatment,
};
use runout_walls::{RobinFace, SolidsWallModel};

/// Depth of the reference layer \[m\]: the bed fills the strip up to the lid
/// (docs/studies/chute1d.md §2).
const HEIGHT: f64 = 0.0087;
/// Holdup ∫εs dy of the reference case \[m\] (mean εs = 0.575, about 17 particle diameters
/// of bed, so that θ stays far above MFIX's clip of 1e-12 m²/s² everywhere).
const HOLDUP: f64 = 0.005;
/// Slope of the reference case \[deg\].
const SLOPE_DEG: f64 = 25.0;
/// Standard gravity [m/s²].
const GRAVITY: f64 = 9.81;
/// Observed order required of a second-order scheme (issue 7, as for Poiseuille).
const MIN_ORDER: f64 = 1.8;
/// Observed order required of a first-order scheme.
const MIN_FIRST_ORDER: f64 = 0.9;
/// Ratio of last to first cell width of the stretched grids (cells finest at the floor).
const STRETCH: f64 = 10.0;
/// Cells of the coarsest grid of the convergence studies.
const COARSE_CELLS: usize = 80;
/// Refinement levels of the convergence studies (each doubles the cells).
const LEVELS: usize = 3;
/// The fine reference has this many times the cells of the finest studied grid.
const REFERENCE_FACTOR: usize = 8;

/// The paper's material (Table 3) without gas: d = 0.5 mm, ρs = 2000, e = 0.9, Princeton
/// friction φ = 35°, εs,max = 0.65, εs,min = 0.5.
fn dry_paper_material() -> ClosureParams {
    ClosureParams {
        gas: Gas {
            density: 0.0,
            ..Gas::default()
        },
        ..ClosureParams::default()
    }
}

/// JJ floor of the paper's S-JJ-phi case: φ = 0.1, e_w = 0.7, δ_w = 11°, U_w = 0.
fn jj_floor() -> SolidsWallModel {
    SolidsWallModel::johnson_jackson(0.1, 0.7, 11.0, 0.0).unwrap()
}

fn uniform(cells: usize) -> Axis {
    Axis::uniform(0.0, HEIGHT, cells).unwrap()
}

/// Geometric cells, finest at the floor, with the same mapping at every level: growth
/// STRETCH^(1/(cells − 1)).
fn stretched(cells: usize) -> Axis {
    let growth = STRETCH.powf(1.0 / (cells as f64 - 1.0));
    Axis::from_segments(
        0.0,
        &[Segment::Geometric {
            length: HEIGHT,
            cells,
            growth,
        }],
    )
    .unwrap()
}

fn reference_case(grid: Axis) -> ChuteParams {
    with_treatment(grid, WallTreatment::FluidCell)
}

fn with_treatment(grid: Axis, wall_treatment: WallTreatment) -> ChuteParams {
    ChuteParams {
        wall_treatment,
        closures: dry_paper_material(),
        slope_deg: SLOPE_DEG,
        gravity: GRAVITY,
        holdup: HOLDUP,
        floor: jj_floor(),
        grid,
        sidewalls: None,
    }
}

fn solve_from(params: &ChuteParams, initial: Option<&ChuteProfile>) -> ChuteProfile {
    let mut settings = SolverSettings::default();
    if let Some(previous) = initial {
        settings.initial = InitialGuess::Profile(Box::new(previous.clone()));
    }
    solve(params, &settings).unwrap()
}

/// Max-norm error of `values` at `y` against the linear interpolant of the reference, relative
/// to the reference's largest magnitude.
fn relative_error(y: &[f64], values: &[f64], reference_y: &[f64], reference: &[f64]) -> f64 {
    let scale = reference.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    y.iter()
        .zip(values)
        .map(|(&at, v)| (v - interpolate(reference_y, reference, at)).abs())
        .fold(0.0, f64::max)
        / scale
}

/// "[a, b, …]" with three significant digits.
fn show(values: &[f64]) -> String {
    let items: Vec<String> = values.iter().map(|v| format!("{v:.3e}")).collect();
    format!("[{}]", items.join(", "))
}

fn orders(errors: &[f64]) -> Vec<f64> {
    errors.windows(2).map(|e| (e[0] / e[1]).log2()).collect()
}

// ------------------------------------------------------------------ the discrete operator

/// Transport coefficient profiles of the manufactured problems.
#[derive(Clone, Copy, Debug)]
enum Coefficient {
    /// Γ = Γ₀(1 + (y/H)²): flat at the floor
    FlatAtFloor,
    /// Γ = Γ₀(1 + y/H): sloped at the floor
    SlopedAtFloor,
}

/// d/dy(Γ dφ/dy) + S = 0 on [0, H], Robin floor g(−dφ/dy) + h φ = c at y = 0, dφ/dy = 0 at
/// y = H, exact solution φ = A + B(Hy − y²/2) with S = −d/dy(Γ φ'), A from the Robin
/// condition. Returns the relative max-norm errors on COARSE_CELLS·2^level cells.
fn manufactured_errors(
    grid_of: impl Fn(usize) -> Axis,
    coefficient: Coefficient,
    treatment: WallTreatment,
) -> Vec<f64> {
    let (gamma0, curvature) = (0.7, 40.0);
    let floor = RobinFace {
        g: 1.0,
        h: 150.0,
        c: 0.0,
    };
    let gamma_of = |y: f64| match coefficient {
        Coefficient::FlatAtFloor => gamma0 * (1.0 + (y / HEIGHT).powi(2)),
        Coefficient::SlopedAtFloor => gamma0 * (1.0 + y / HEIGHT),
    };
    let dgamma_of = |y: f64| match coefficient {
        Coefficient::FlatAtFloor => 2.0 * gamma0 * y / (HEIGHT * HEIGHT),
        Coefficient::SlopedAtFloor => gamma0 / HEIGHT,
    };
    // φ' = B(H − y), φ'' = −B: S = −(Γ' φ' + Γ φ'')
    let source_of = |y: f64| -(dgamma_of(y) * curvature * (HEIGHT - y) - gamma_of(y) * curvature);
    // Robin at y = 0: −g φ'(0) + h φ(0) = c with φ'(0) = B H
    let offset = (floor.c + floor.g * curvature * HEIGHT) / floor.h;
    let exact = |y: f64| offset + curvature * (HEIGHT * y - 0.5 * y * y);
    (0..LEVELS + 1)
        .map(|level| {
            let grid = grid_of(COARSE_CELLS << level);
            let y = grid.centres();
            let gamma: Vec<f64> = y.iter().map(|&y| gamma_of(y)).collect();
            let source: Vec<f64> = y.iter().map(|&y| source_of(y)).collect();
            let phi = solve_linear_diffusion(&grid, &gamma, &source, &floor, treatment).unwrap();
            // the chute rows use the same operator: its fluxes balance the source cell by cell
            let flux = diffusive_fluxes(&grid, &gamma, &phi, &floor, treatment);
            for j in 0..grid.len() {
                let balance = flux[j + 1] - flux[j] + source[j] * grid.widths()[j];
                assert!(
                    balance.abs() <= 1e-9 * (flux[j + 1].abs() + flux[j].abs()).max(1.0),
                    "cell {j}: {balance}"
                );
            }
            let scale = y.iter().map(|&y| exact(y).abs()).fold(0.0, f64::max);
            y.iter()
                .zip(&phi)
                .map(|(&y, p)| (p - exact(y)).abs())
                .fold(0.0, f64::max)
                / scale
        })
        .collect()
}

fn manufactured_orders(coefficient: Coefficient, treatment: WallTreatment) -> Vec<Vec<f64>> {
    [
        ("uniform", uniform as fn(usize) -> Axis),
        ("stretched", stretched),
    ]
    .iter()
    .map(|(label, grid_of)| {
        let errors = manufactured_errors(grid_of, coefficient, treatment);
        let orders = orders(&errors);
        eprintln!(
            "manufactured, {coefficient:?}, {treatment:?}, {label}: errors {}, orders {}",
            show(&errors),
            show(&orders)
        );
        orders
    })
    .collect()
}

#[test]
fn diffusion_operator_is_second_order_on_uniform_and_stretched_grids() {
    for (coefficient, treatment) in [
        (Coefficient::FlatAtFloor, WallTreatment::FluidCell),
        (Coefficient::FlatAtFloor, WallTreatment::Extrapolated),
        (Coefficient::SlopedAtFloor, WallTreatment::Extrapolated),
    ] {
        for orders in manufactured_orders(coefficient, treatment) {
            assert!(orders.iter().all(|&p| p >= MIN_ORDER), "{orders:?}");
        }
    }
}

/// The wall face takes the fluid cell's Γ (docs/model.md §3.1, as MFIX), which is Γ(Δ/2), not
/// Γ(0): where Γ has a slope at the wall the wall flux, and so the solution, are first order.
/// This documents the convention's cost; the chute inherits it through μ_s and κ_s.
#[test]
fn fluid_cell_coefficient_on_the_wall_face_is_first_order_where_it_varies() {
    for orders in manufactured_orders(Coefficient::SlopedAtFloor, WallTreatment::FluidCell) {
        assert!(
            orders.iter().all(|&p| (0.9..1.2).contains(&p)),
            "{orders:?}"
        );
    }
}

// ------------------------------------------------------------------ balances

#[test]
fn converged_profile_satisfies_the_integral_balances() {
    let p = solve_from(&reference_case(stretched(40)), None);
    let rho_s = p_rho_s();
    let alpha = SLOPE_DEG.to_radians();
    let holdup: f64 = p.eps_s.iter().zip(&p.dy).map(|(e, d)| e * d).sum();
    assert!((holdup - HOLDUP).abs() <= 1e-10 * HOLDUP, "holdup {holdup}");
    // x-momentum: the floor carries the whole downslope weight (free-slip lid)
    let weight_t = rho_s * GRAVITY * alpha.sin() * holdup;
    let shear_error = (p.floor.shear_stress - weight_t).abs() / weight_t;
    // y-momentum: P_s(0) − P_lid = ρs g cos α ∫εs dy
    let weight_n = rho_s * GRAVITY * alpha.cos() * holdup;
    let pressure_error = (p.floor.pressure - p.lid_pressure - weight_n).abs() / weight_n;
    // the wall shear is the Robin form μ_s,1 h_w^u (u_face − U_w) (docs/model.md §3.2)
    let robin = p.floor.viscosity * p.floor.momentum.h_u * p.floor.slip;
    let robin_error = (robin - p.floor.shear_stress).abs() / weight_t;
    // granular energy: ∫(Π − γ) dy + flux in through the floor = 0 (zero flux at the lid)
    let net: f64 = (0..p.y.len())
        .map(|j| (p.production[j] - p.dissipation[j]) * p.dy[j])
        .sum();
    let gross: f64 = (0..p.y.len())
        .map(|j| (p.production[j] + p.dissipation[j]) * p.dy[j])
        .sum();
    let energy_error = (net + p.floor.energy_flux_into_flow).abs() / gross;
    eprintln!(
        "balances: τ_w {:.6} vs W sinα {weight_t:.6} (rel {shear_error:.1e}); P(0) − P_lid \
         {:.6} vs W cosα {weight_n:.6} (rel {pressure_error:.1e}); Robin form rel \
         {robin_error:.1e}; energy rel {energy_error:.1e}; iterations {}, residual {:.1e}",
        p.floor.shear_stress,
        p.floor.pressure - p.lid_pressure,
        p.iterations,
        p.residual
    );
    assert!(shear_error <= 1e-8, "{shear_error}");
    assert!(pressure_error <= 1e-8, "{pressure_error}");
    assert!(robin_error <= 1e-12, "{robin_error}");
    assert!(energy_error <= 1e-8, "{energy_error}");
    // a sliding, sheared, steady layer: positive slip, u increasing upwards, θ > 0
    assert!(p.floor.slip > 0.0);
    assert!(p.u_s.windows(2).all(|w| w[1] >= w[0] - 1e-12));
    assert!(p.theta.iter().all(|&t| t > 0.0));
}

fn p_rho_s() -> f64 {
    dry_paper_material().particles.density
}

// ------------------------------------------------------------------ grid convergence

/// Observed orders of u_s, θ and the slip on COARSE_CELLS·2^level cells against a solution on
/// REFERENCE_FACTOR times the finest grid of the same family, all with the given wall
/// treatment.
fn convergence(
    grid_of: impl Fn(usize) -> Axis,
    label: &str,
    treatment: WallTreatment,
) -> [Vec<f64>; 3] {
    let case = |grid| with_treatment(grid, treatment);
    let mut previous: Option<ChuteProfile> = None;
    let mut levels = Vec::new();
    for level in 0..LEVELS {
        let p = solve_from(&case(grid_of(COARSE_CELLS << level)), previous.as_ref());
        previous = Some(p.clone());
        levels.push(p);
    }
    let fine_cells = (COARSE_CELLS << (LEVELS - 1)) * REFERENCE_FACTOR;
    let reference = solve_from(&case(grid_of(fine_cells)), previous.as_ref());
    let error = |p: &ChuteProfile, pick: fn(&ChuteProfile) -> &Vec<f64>| {
        relative_error(&p.y, pick(p), &reference.y, pick(&reference))
    };
    let u_errors: Vec<f64> = levels.iter().map(|p| error(p, |p| &p.u_s)).collect();
    let theta_errors: Vec<f64> = levels.iter().map(|p| error(p, |p| &p.theta)).collect();
    let slip_errors: Vec<f64> = levels
        .iter()
        .map(|p| (p.floor.slip - reference.floor.slip).abs() / reference.floor.slip)
        .collect();
    let (u_orders, theta_orders, slip_orders) = (
        orders(&u_errors),
        orders(&theta_errors),
        orders(&slip_errors),
    );
    eprintln!(
        "{label}, {treatment:?}: cells {:?} (reference {fine_cells} cells)\n  u_s errors {} orders {}\n  \
         θ errors {} orders {}\n  slip errors {} orders {}\n  iterations {:?}",
        levels.iter().map(|p| p.y.len()).collect::<Vec<_>>(),
        show(&u_errors),
        show(&u_orders),
        show(&theta_errors),
        show(&theta_orders),
        show(&slip_errors),
        show(&slip_orders),
        levels.iter().map(|p| p.iterations).collect::<Vec<_>>()
    );
    [u_orders, theta_orders, slip_orders]
}

/// With the wall closure's bulk values extrapolated to the wall the whole scheme is second
/// order (issue 7: observed order ≥ 1.8 in u_s and θ).
#[test]
fn grid_convergence_second_order_with_extrapolated_wall_values() {
    for (label, grid_of) in [
        ("uniform", uniform as fn(usize) -> Axis),
        ("stretched", stretched),
    ] {
        let [u, theta, slip] = convergence(grid_of, label, WallTreatment::Extrapolated);
        for (name, o) in [("u_s", &u), ("θ", &theta), ("slip", &slip)] {
            assert!(o.iter().all(|&p| p >= MIN_ORDER), "{label} {name}: {o:?}");
        }
    }
}

/// MFIX's fluid-cell values at the wall (what the 2-D solver does) make the chute first order
/// (see `fluid_cell_coefficient_on_the_wall_face_is_first_order_where_it_varies`): compare the
/// 2-D solver with this solver on the same grid, or refine both.
#[test]
fn grid_convergence_first_order_with_mfix_wall_values() {
    for (label, grid_of) in [
        ("uniform", uniform as fn(usize) -> Axis),
        ("stretched", stretched),
    ] {
        let [u, theta, slip] = convergence(grid_of, label, WallTreatment::FluidCell);
        for (name, o) in [("u_s", &u), ("θ", &theta), ("slip", &slip)] {
            assert!(
                o.iter().all(|&p| p >= MIN_FIRST_ORDER),
                "{label} {name}: {o:?}"
            );
        }
    }
}

// ------------------------------------------------------------------ error paths

#[test]
fn a_free_slip_floor_has_no_steady_state() {
    // nothing balances the downslope weight: the layer accelerates for ever
    let mut params = reference_case(uniform(COARSE_CELLS));
    params.floor = SolidsWallModel::FreeSlip;
    let settings = SolverSettings {
        max_iterations: 100,
        ..SolverSettings::default()
    };
    let result = solve(&params, &settings);
    assert!(
        matches!(
            result,
            Err(Chute1dError::NotConverged { .. } | Chute1dError::Singular(_))
        ),
        "{result:?}"
    );
}

#[test]
fn gas_and_bad_parameters_are_rejected() {
    let mut params = reference_case(uniform(COARSE_CELLS));
    params.closures.gas = Gas::default();
    assert!(matches!(
        solve(&params, &SolverSettings::default()),
        Err(Chute1dError::GasNotSupported(_))
    ));
    let mut params = reference_case(uniform(COARSE_CELLS));
    params.holdup = HEIGHT;
    assert!(matches!(
        solve(&params, &SolverSettings::default()),
        Err(Chute1dError::InvalidParameter {
            field: "holdup",
            ..
        })
    ));
}
