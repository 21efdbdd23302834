//! Validation of a parsed case: every bound, before anything runs.
//!
//! Errors are collected (not stopped at the first), each naming the field path, the value
//! and the allowed range, so one `runout check` shows everything that is wrong with a
//! file. Dimensional inputs must lie in the plausibility bands of [`crate::limits`].

use runout_mesh::{short, Side};

use crate::bed::check_bed;
use crate::checker::{Checker, FieldError, B};
use crate::gas_inlet::check_gas_inlets;
use crate::limits::*;
use crate::name::name_error;
use crate::release::check_release;
use crate::schema::*;
use crate::sidewalls::check_sidewalls;
use crate::validate_grid::check_grids;

/// Validates a case; `Ok` means every field is in range and plausible, and every
/// fidelity's grid builds within the size limits (see [`crate::limits`]).
pub fn validate_case(case: &Case) -> Result<(), Vec<FieldError>> {
    let mut c = Checker::default();
    check_materials(&mut c, case);
    check_initial(&mut c, case);
    check_gravity(&mut c, case);
    check_run(&mut c, case);
    check_monitors(&mut c, case);
    check_presets(&mut c, case);
    c.into_result()
}

/// The run's end time where it is in its band, else the band's low end (the bound other
/// checks compare with).
fn bounded_end_time(case: &Case) -> f64 {
    if TIME.contains(case.run.end_time) {
        case.run.end_time
    } else {
        TIME.lo
    }
}

/// An ideal gas's molar mass and temperature, and its `density` within 1 % of its law's at
/// `reference_pressure` (the density the residual scales and mass-flux inlets read).
fn check_gas_law(c: &mut Checker, gas: &Gas) {
    if let GasLaw::IdealGas {
        molar_mass,
        temperature,
    } = gas.law
    {
        c.band("gas.law.IdealGas.molar_mass", molar_mass, &GAS_MOLAR_MASS);
        c.band(
            "gas.law.IdealGas.temperature",
            temperature,
            &GAS_TEMPERATURE,
        );
        // judged only against a law's density that is itself a gas's (a nonsense
        // temperature, e.g. −1e-66 K, gives −3e68 kg/m³: its own field is named above)
        let ideal = gas.equation_of_state().density(gas.reference_pressure);
        if GAS_DENSITY.contains(ideal)
            && (gas.density / ideal - 1.0).abs() > IDEAL_DENSITY_TOLERANCE
        {
            c.fail(
                "gas.density",
                runout_mesh::short(gas.density),
                format!(
                    "within 1 % of the ideal gas's P M/(R T) = {ideal:.4} kg/m³ at \
                     reference_pressure {} Pa (gas.law)",
                    runout_mesh::short(gas.reference_pressure)
                ),
            );
        }
    }
}

/// How far an ideal gas's `gas.density` may lie from its law's at the reference pressure.
const IDEAL_DENSITY_TOLERANCE: f64 = 0.01;

/// The name, the grids, the gas, the solids phases, the closure models, the boundaries and the side walls.
fn check_materials(c: &mut Checker, case: &Case) {
    if let Some(e) = name_error("name", &case.name) {
        c.errors.push(e);
    }

    // Grid: sizes bounded before anything is built; then every fidelity's grid.
    check_grids(c, case);

    if let Some(gas) = &case.gas {
        c.band("gas.density", gas.density, &GAS_DENSITY);
        c.band("gas.viscosity", gas.viscosity, &GAS_VISCOSITY);
        c.band("gas.reference_pressure", gas.reference_pressure, &PRESSURE);
        check_gas_law(c, gas);
    }

    if case.solids.is_empty() && case.gas.as_ref().is_some_and(|g| !g.law.is_constant()) {
        c.fail(
            "gas.law",
            "IdealGas",
            "Constant in a case without solids (the single-phase solver's gas has a constant \
             density; an ideal gas needs the two-fluid solver)",
        );
    }
    if case.solids.is_empty() && case.gas.is_none() {
        c.fail(
            "solids",
            "[]",
            "at least one solids phase, or a gas (a single-phase case)",
        );
    }
    if case.solids.len() > MAX_SOLIDS_PHASES {
        c.fail(
            "solids",
            format!("{} phases", case.solids.len()),
            format!("at most {MAX_SOLIDS_PHASES} phases (MFIX's DIM_M)"),
        );
    }
    for (k, s) in case.solids.iter().enumerate() {
        let p = format!("solids[{k}]");
        c.band(format!("{p}.diameter"), s.diameter, &DIAMETER);
        c.band(format!("{p}.density"), s.density, &PARTICLE_DENSITY);
        c.unit(format!("{p}.restitution"), s.restitution);
        c.band(format!("{p}.max_packing"), s.max_packing, &MAX_PACKING);
        c.range(
            format!("{p}.friction_min_packing"),
            s.friction_min_packing,
            B::Open(0.0),
            B::Open(s.max_packing.clamp(0.0, 1.0)),
        );
        c.range(
            format!("{p}.internal_friction_angle"),
            s.internal_friction_angle,
            B::Open(0.0),
            B::Open(90.0),
        );
    }

    match &case.models.kinetic_theory {
        KineticTheory::Lun1984 { alpha } => {
            c.band("models.kinetic_theory.alpha", *alpha, &KT_ALPHA)
        }
        KineticTheory::Algebraic => {}
    }
    if let FrictionModel::MuI(law) = &case.models.friction {
        let p = "models.friction.MuI";
        c.band(format!("{p}.mu_s"), law.mu_s, &MU_I_FRICTION);
        c.band(format!("{p}.mu_2"), law.mu_2, &MU_I_FRICTION);
        c.range(
            format!("{p}.mu_2"),
            law.mu_2,
            B::Open(law.mu_s),
            B::Closed(MU_I_FRICTION.hi),
        );
        c.band(format!("{p}.i_0"), law.i_0, &MU_I_I0);
        c.band(
            format!("{p}.shear_rate_floor"),
            law.shear_rate_floor,
            &MU_I_SHEAR_RATE_FLOOR,
        );
    }
    if let Drag::SyamlalOBrien { c1, d1 } = &case.models.drag {
        c.band("models.drag.c1", *c1, &DRAG_C1);
        c.band("models.drag.d1", *d1, &DRAG_D1);
    }

    for (side, b) in case.boundaries.iter() {
        check_boundary(
            c,
            &format!("boundaries.{}", side.name()),
            b,
            case.gas.is_some(),
        );
    }

    if let Some(sidewalls) = &case.sidewalls {
        check_sidewalls(c, sidewalls, check_solids_wall);
    }
    check_bed(c, case);
    check_release(c, case);
    check_gas_inlets(c, case);
}

/// The initial state: θ, velocities and the regions (inside the domain).
fn check_initial(c: &mut Checker, case: &Case) {
    let (x0, x_end) = (case.domain.x.origin, case.domain.x.end());
    let (y0, y_end) = (case.domain.y.origin, case.domain.y.end());
    c.band("initial.theta", case.initial.theta, &THETA);
    c.band(
        "initial.gas_velocity.0",
        case.initial.gas_velocity.0,
        &VELOCITY,
    );
    c.band(
        "initial.gas_velocity.1",
        case.initial.gas_velocity.1,
        &VELOCITY,
    );
    if let InitialPressure::Uniform(p) = case.initial.gas_pressure {
        c.band("initial.gas_pressure", p, &PRESSURE);
    }
    for (k, block) in case.initial.regions.iter().enumerate() {
        let p = format!("initial.regions[{k}]");
        check_span(c, &format!("{p}.x"), block.x, x0, x_end);
        check_span(c, &format!("{p}.y"), block.y, y0, y_end);
        if block.solids.len() != case.solids.len() {
            c.fail(
                format!("{p}.solids"),
                format!("{} entries", block.solids.len()),
                format!("one entry per solids phase ({})", case.solids.len()),
            );
        }
        let mut total = 0.0;
        for (m, (bs, phase)) in block.solids.iter().zip(&case.solids).enumerate() {
            let q = format!("{p}.solids[{m}]");
            check_packing(c, &format!("{q}.eps_s"), bs.eps_s, phase.max_packing);
            c.band(format!("{q}.velocity.0"), bs.velocity.0, &VELOCITY);
            c.band(format!("{q}.velocity.1"), bs.velocity.1, &VELOCITY);
            c.band(format!("{q}.theta"), bs.theta, &THETA);
            total += bs.eps_s;
        }
        let max_pack = case
            .solids
            .iter()
            .map(|s| s.max_packing)
            .fold(0.0, f64::max);
        if block.solids.len() > 1 {
            check_packing(c, &format!("{p}.solids (sum of eps_s)"), total, max_pack);
        }
    }
}

/// Gravity: magnitude and slope, and the impact criterion of a tilt on impact.
fn check_gravity(c: &mut Checker, case: &Case) {
    let (magnitude, slope) = match &case.gravity {
        Gravity::Constant { magnitude, slope } => (*magnitude, *slope),
        Gravity::TiltOnImpact {
            magnitude,
            slope,
            contact_eps_s,
            criterion,
            clock,
        } => {
            c.range(
                "gravity.contact_eps_s",
                *contact_eps_s,
                B::Open(0.0),
                B::Open(1.0),
            );
            check_impact_criterion(c, criterion, case);
            if *clock == Clock::Impact
                && !matches!(
                    criterion,
                    ImpactCriterion::FreeFall | ImpactCriterion::At { .. }
                )
            {
                c.fail(
                    "gravity.clock",
                    "Impact",
                    "Start, or Impact with the criterion FreeFall or At(time) (a time from \
                     the impact needs the impact's time before the run)",
                );
            }
            (*magnitude, *slope)
        }
    };
    if magnitude != 0.0 {
        c.band("gravity.magnitude", magnitude, &GRAVITY);
    }
    c.range("gravity.slope", slope, B::Closed(0.0), B::Open(90.0));
}

/// Run control: end time, time steps, tolerances and numerics.
fn check_run(c: &mut Checker, case: &Case) {
    let run = &case.run;
    c.band("run.end_time", run.end_time, &TIME);
    let end = if TIME.contains(run.end_time) {
        run.end_time
    } else {
        TIME.lo
    };
    c.band("run.dt.min", run.dt.min, &TIME_STEP);
    if TIME_STEP.contains(run.dt.min) && run.dt.min < end * DT_MIN_PER_END_TIME {
        c.fail(
            "run.dt.min",
            short(run.dt.min),
            format!(
                ">= {} s (the end time {} s x {}: a smaller step no longer advances t in \
                 double precision)",
                short(end * DT_MIN_PER_END_TIME),
                short(end),
                short(DT_MIN_PER_END_TIME)
            ),
        );
    }
    c.band("run.dt.max", run.dt.max, &TIME_STEP);
    c.band_and_range(
        "run.dt.initial",
        run.dt.initial,
        &TIME_STEP,
        B::Closed(run.dt.min),
        B::Closed(run.dt.max),
    );
    if run.dt.min > run.dt.max {
        c.fail(
            "run.dt.min",
            short(run.dt.min),
            format!("<= run.dt.max = {}", short(run.dt.max)),
        );
    }
    c.range("run.dt.factor", run.dt.factor, B::Open(0.0), B::Closed(1.0));
    if let Some(f) = run.dt.failure_factor {
        c.range("run.dt.failure_factor", f, B::Open(0.0), B::Open(1.0));
    }
    c.count(
        "run.dt.steps_per_change",
        run.dt.steps_per_change as u64,
        1,
        MAX_ITERATIONS,
    );
    c.band(
        "run.tolerances.residual",
        run.tolerances.residual,
        &TOLERANCE,
    );
    c.band(
        "run.tolerances.theta_residual",
        run.tolerances.theta_residual,
        &TOLERANCE,
    );
    c.range(
        "run.tolerances.diverge",
        run.tolerances.diverge,
        B::Open(run.tolerances.residual),
        B::Inf,
    );
    c.count(
        "run.tolerances.max_iterations",
        u64::from(run.tolerances.max_iterations),
        2,
        MAX_ITERATIONS,
    );
    check_interval(
        c,
        "run.output_interval",
        run.output_interval,
        end,
        (MAX_OUTPUTS, "outputs"),
    );
    if let Some(interval) = run.checkpoint_interval {
        check_interval(
            c,
            "run.checkpoint_interval",
            interval,
            end,
            (MAX_OUTPUTS, "checkpoints"),
        );
    }
    if let Some(rest) = &run.stop_at_rest {
        c.band("run.stop_at_rest.speed", rest.speed, &VELOCITY);
        c.range("run.stop_at_rest.speed", rest.speed, B::Open(0.0), B::Inf);
        c.range(
            "run.stop_at_rest.duration",
            rest.duration,
            B::Open(0.0),
            B::Closed(end),
        );
        c.range(
            "run.stop_at_rest.front_threshold",
            rest.front_threshold,
            B::Open(0.0),
            B::Open(1.0),
        );
    }

    let r = &case.numerics.relaxation;
    for (name, v) in [
        ("pressure", r.pressure),
        ("eps_s", r.eps_s),
        ("velocity", r.velocity),
        ("theta", r.theta),
        ("wall_closures", r.wall_closures),
    ] {
        c.band(format!("numerics.relaxation.{name}"), v, &RELAXATION);
    }
}

/// Monitors: profiles, wall probes, bulk and front (inside the domain and the run).
fn check_monitors(c: &mut Checker, case: &Case) {
    let (x0, x_end) = (case.domain.x.origin, case.domain.x.end());
    let (y0, y_end) = (case.domain.y.origin, case.domain.y.end());
    let run = &case.run;
    let end = bounded_end_time(case);
    for (k, prof) in case.monitors.profiles.iter().enumerate() {
        let p = format!("monitors.profiles[{k}]");
        c.range(format!("{p}.x"), prof.x, B::Closed(x0), B::Closed(x_end));
        if prof.times.is_empty() {
            c.fail(format!("{p}.times"), "[]", "at least one time");
        }
        for (m, t) in prof.times.iter().enumerate() {
            c.range(
                format!("{p}.times[{m}]"),
                *t,
                B::Closed(0.0),
                B::Closed(run.end_time),
            );
        }
        c.increasing(&format!("{p}.times"), &prof.times);
    }
    if case.monitors.wall_probes.len() > MAX_WALL_PROBES {
        c.fail(
            "monitors.wall_probes",
            format!("{} probes", case.monitors.wall_probes.len()),
            format!("at most {MAX_WALL_PROBES} (each keeps a file open during the run)"),
        );
    }
    for (k, probe) in case.monitors.wall_probes.iter().enumerate() {
        let p = format!("monitors.wall_probes[{k}]");
        let (lo, hi) = match probe.side {
            Side::South | Side::North => (x0, x_end),
            Side::West | Side::East => (y0, y_end),
        };
        c.range(format!("{p}.at"), probe.at, B::Closed(lo), B::Closed(hi));
        if !matches!(case.boundaries.get(probe.side), Boundary::Wall { .. }) {
            c.fail(
                format!("{p}.side"),
                probe.side.name(),
                "a side that is a Wall",
            );
        }
        check_interval(
            c,
            &format!("{p}.interval"),
            probe.interval,
            end,
            (MAX_SAMPLES, "samples"),
        );
    }
    if let Some(front) = &case.monitors.front {
        let p = "monitors.front";
        c.range(
            format!("{p}.threshold"),
            front.threshold,
            B::Open(0.0),
            B::Open(1.0),
        );
        c.range(
            format!("{p}.gate_origin"),
            front.gate_origin,
            B::Closed(x0),
            B::Closed(x_end),
        );
        for (k, g) in front.gates.iter().enumerate() {
            c.range(
                format!("{p}.gates[{k}]"),
                *g,
                B::Closed(x0 - front.gate_origin),
                B::Closed(x_end - front.gate_origin),
            );
        }
        c.increasing(&format!("{p}.gates"), &front.gates);
        check_interval(
            c,
            &format!("{p}.interval"),
            front.interval,
            end,
            (MAX_SAMPLES, "samples"),
        );
    }
    if let Some(bulk) = &case.monitors.bulk {
        check_interval(
            c,
            "monitors.bulk.interval",
            bulk.interval,
            end,
            (MAX_SAMPLES, "samples"),
        );
        c.range(
            "monitors.bulk.front_threshold",
            bulk.front_threshold,
            B::Open(0.0),
            B::Open(1.0),
        );
    }
}

/// Fidelity presets: coarsening ≥ 1, end times in the band and ≤ the paper end time (their grids are checked with the domain's).
fn check_presets(c: &mut Checker, case: &Case) {
    let run = &case.run;
    for (name, preset) in [
        ("smoke", Some(&case.fidelity.smoke)),
        ("coarse", Some(&case.fidelity.coarse)),
        ("wall", case.fidelity.wall.as_ref()),
    ] {
        let Some(preset) = preset else { continue };
        let p = format!("fidelity.{name}");
        if preset.coarsen < 1 {
            c.fail(format!("{p}.coarsen"), preset.coarsen, "an integer >= 1");
        }
        if preset.coarsen_y.is_some_and(|f| f < 1) {
            c.fail(
                format!("{p}.coarsen_y"),
                preset.factor_y(),
                "an integer >= 1",
            );
        }
        c.band_and_range(
            format!("{p}.end_time"),
            preset.end_time,
            &TIME,
            B::Open(0.0),
            B::Closed(run.end_time),
        );
    }
}

/// The impact criterion of a tilt-on-impact schedule: its numbers in range, and a release
/// to measure from where the criterion needs one (docs/studies/impact.md).
fn check_impact_criterion(c: &mut Checker, criterion: &ImpactCriterion, case: &Case) {
    let p = "gravity.criterion";
    let has_release = case
        .initial
        .regions
        .iter()
        .any(|b| b.solids.iter().any(|s| s.eps_s > 0.0));
    let needs_release = |c: &mut Checker, what: &str| {
        if !has_release {
            c.fail(
                p,
                what,
                "FloorCell or At(time) when no initial region holds solids (this criterion \
                 is measured from the release)",
            );
        }
    };
    match criterion {
        ImpactCriterion::FloorCell => {}
        ImpactCriterion::DenseContact { fraction } => {
            c.range(
                format!("{p}.fraction"),
                *fraction,
                B::Open(0.0),
                B::Closed(1.0),
            );
            needs_release(c, "DenseContact");
        }
        ImpactCriterion::FreeFall => needs_release(c, "FreeFall"),
        ImpactCriterion::CentroidDrop => needs_release(c, "CentroidDrop"),
        ImpactCriterion::At { time } => c.range(
            format!("{p}.time"),
            *time,
            B::Closed(0.0),
            B::Closed(case.run.end_time),
        ),
    }
}

/// A block's εs (or the sum over phases) strictly below the packing limit: at εs,max the
/// solids pressure's packing term diverges (MFIX's P_c ∝ 1/(εs,max − εs)^D), so a block
/// at exactly max_packing stopped at t = 0 after retries (issue 21).
fn check_packing(c: &mut Checker, field: &str, eps_s: f64, max_packing: f64) {
    if !(eps_s.is_finite() && eps_s >= 0.0 && eps_s < max_packing) {
        c.fail(
            field,
            short(eps_s),
            format!(
                "[0, {}) (strictly below max_packing: the solids pressure diverges at the \
                 packing limit)",
                short(max_packing)
            ),
        );
    }
}

/// An output or monitor interval: at most `max_count` outputs to `end_time`, at least
/// [`MIN_INTERVAL`], at most the longest end time. Below that, `next += interval` stops
/// advancing past t and the run spins (issue 21).
fn check_interval(
    c: &mut Checker,
    field: &str,
    v: f64,
    end_time: f64,
    (max_count, what): (f64, &str),
) {
    let lo = (end_time / max_count).max(MIN_INTERVAL);
    if !(v.is_finite() && v >= lo && v <= TIME.hi) {
        c.fail(
            field,
            short(v),
            format!(
                "[{}, {}] s (at most {} {what} to the end time {} s, and >= {} s: \
                 docs/reference/input-validation.md)",
                short(lo),
                short(TIME.hi),
                short(max_count),
                short(end_time),
                short(MIN_INTERVAL)
            ),
        );
    }
}

fn check_span(c: &mut Checker, field: &str, span: (f64, f64), lo: f64, hi: f64) {
    c.range(format!("{field}.0"), span.0, B::Closed(lo), B::Closed(hi));
    c.range(format!("{field}.1"), span.1, B::Closed(lo), B::Closed(hi));
    if span.1 <= span.0 || span.1.is_nan() {
        c.fail(
            format!("{field}.1"),
            short(span.1),
            format!("> {field}.0 = {}", short(span.0)),
        );
    }
}

fn check_boundary(c: &mut Checker, p: &str, b: &Boundary, has_gas: bool) {
    match b {
        Boundary::PressureOutlet { pressure } => {
            let v = match pressure {
                OutletPressure::Uniform(v) | OutletPressure::Hydrostatic(v) => *v,
            };
            c.band(format!("{p}.pressure"), v, &PRESSURE);
            if !has_gas {
                c.fail(
                    p.to_string(),
                    "PressureOutlet",
                    "a Wall when the case has no gas",
                );
            }
        }
        Boundary::Wall { gas, solids } => {
            match gas {
                GasWall::PartialSlip { h_u, u_w } => {
                    c.band(format!("{p}.gas.h_u"), *h_u, &SLIP_COEFFICIENT);
                    c.band(format!("{p}.gas.u_w"), *u_w, &VELOCITY);
                }
                GasWall::Moving { u_w } => c.band(format!("{p}.gas.u_w"), *u_w, &VELOCITY),
                GasWall::NoSlip | GasWall::FreeSlip => {}
            }
            check_solids_wall(c, &format!("{p}.solids"), solids);
        }
    }
}

/// A solids wall condition's parameters (a side's or the side walls'), fields under `q`:
/// the dimensional ones in their plausibility bands, then every field the wall model's
/// validated constructors reject ([`SolidsWall::model`]) that no band did.
fn check_solids_wall(c: &mut Checker, q: &str, solids: &SolidsWall) {
    let mut banded = Vec::new();
    for (name, v) in solids.parameters() {
        let Some(band) = wall_band(name) else {
            continue;
        };
        let before = c.errors.len();
        c.band(format!("{q}.{name}"), v, band);
        if c.errors.len() > before {
            banded.push(name);
        }
    }
    if let Err(e) = solids.model() {
        for f in e.fields.iter().filter(|f| !banded.contains(&f.field)) {
            c.fail(format!("{q}.{}", f.field), short(f.value), f.range);
        }
    }
}

/// The plausibility band of a dimensional wall parameter, by its case-file name.
fn wall_band(name: &str) -> Option<&'static Band> {
    match name {
        "h_u" | "h_theta" => Some(&SLIP_COEFFICIENT),
        "u_w" => Some(&VELOCITY),
        "theta_w" => Some(&THETA),
        "c" => Some(&THETA_FLUX),
        _ => None,
    }
}

/// Validates a family-A file.
pub fn validate_analytic(a: &Analytic) -> Result<(), Vec<FieldError>> {
    let mut c = Checker::default();
    if let Some(e) = name_error("name", &a.name) {
        c.errors.push(e);
    }
    c.band("depth", a.depth, &DOMAIN_LENGTH);
    c.band("velocity.bulk", a.velocity.bulk, &VELOCITY);
    c.band("velocity.wall", a.velocity.wall, &VELOCITY);
    if a.velocity.h_u.is_empty() {
        c.fail("velocity.h_u", "[]", "at least one value");
    }
    for (k, h) in a.velocity.h_u.iter().enumerate() {
        c.band(format!("velocity.h_u[{k}]"), *h, &SLIP_COEFFICIENT);
    }
    c.band("temperature.bulk", a.temperature.bulk, &THETA);
    c.band("temperature.wall", a.temperature.wall, &THETA);
    for (k, h) in a.temperature.h_theta.iter().enumerate() {
        c.band(format!("temperature.h_theta[{k}]"), *h, &SLIP_COEFFICIENT);
    }
    for (k, v) in a.temperature.c.iter().enumerate() {
        c.band(format!("temperature.c[{k}]"), *v, &THETA_FLUX);
    }
    c.into_result()
}
