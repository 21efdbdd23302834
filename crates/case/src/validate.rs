//! Validation of a parsed case: every bound, before anything runs.
//!
//! Errors are collected (not stopped at the first), each naming the field path and the
//! allowed range, so one `runout check` shows everything that is wrong with a file.

use std::fmt;

use runout_mesh::{AxisSpec, Grid, Side};

use crate::schema::*;

/// One out-of-range field.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldError {
    /// path of the field, e.g. `solids[0].diameter`
    pub field: String,
    /// the value found
    pub value: String,
    /// what is allowed
    pub allowed: String,
}

impl fmt::Display for FieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} = {}: allowed {}",
            self.field, self.value, self.allowed
        )
    }
}

/// Collects field errors.
#[derive(Default)]
struct Checker {
    errors: Vec<FieldError>,
}

/// An interval bound.
#[derive(Clone, Copy)]
enum B {
    Open(f64),
    Closed(f64),
    Inf,
}

fn fmt_interval(lo: B, hi: B) -> String {
    let l = match lo {
        B::Open(v) => format!("({v}"),
        B::Closed(v) => format!("[{v}"),
        B::Inf => "(-inf".into(),
    };
    let h = match hi {
        B::Open(v) => format!("{v})"),
        B::Closed(v) => format!("{v}]"),
        B::Inf => "inf)".into(),
    };
    format!("{l}, {h}")
}

impl Checker {
    fn fail(&mut self, field: impl Into<String>, value: impl ToString, allowed: impl Into<String>) {
        self.errors.push(FieldError {
            field: field.into(),
            value: value.to_string(),
            allowed: allowed.into(),
        });
    }

    /// Checks lo ⋚ v ⋚ hi and finiteness.
    fn range(&mut self, field: impl Into<String>, v: f64, lo: B, hi: B) {
        let above = match lo {
            B::Open(l) => v > l,
            B::Closed(l) => v >= l,
            B::Inf => true,
        };
        let below = match hi {
            B::Open(h) => v < h,
            B::Closed(h) => v <= h,
            B::Inf => true,
        };
        if !(v.is_finite() && above && below) {
            self.fail(field, v, fmt_interval(lo, hi));
        }
    }

    fn positive(&mut self, field: impl Into<String>, v: f64) {
        self.range(field, v, B::Open(0.0), B::Inf);
    }

    fn non_negative(&mut self, field: impl Into<String>, v: f64) {
        self.range(field, v, B::Closed(0.0), B::Inf);
    }

    fn unit(&mut self, field: impl Into<String>, v: f64) {
        self.range(field, v, B::Closed(0.0), B::Closed(1.0));
    }

    fn finite(&mut self, field: impl Into<String>, v: f64) {
        self.range(field, v, B::Inf, B::Inf);
    }

    fn increasing(&mut self, field: &str, values: &[f64]) {
        for k in 1..values.len() {
            if values[k] <= values[k - 1] || values[k].is_nan() {
                self.fail(
                    format!("{field}[{k}]"),
                    values[k],
                    format!(
                        "> {field}[{}] = {} (strictly increasing)",
                        k - 1,
                        values[k - 1]
                    ),
                );
            }
        }
    }
}

/// Validates a case; `Ok` means every field is in range and every fidelity's grid builds.
pub fn validate_case(case: &Case) -> Result<(), Vec<FieldError>> {
    let mut c = Checker::default();
    check_name(&mut c, "name", &case.name);

    // Grid: the paper fidelity and both presets must build.
    let x_end = case.domain.x.end();
    let y_end = case.domain.y.end();
    let (x0, y0) = (case.domain.x.origin, case.domain.y.origin);
    check_axis(&mut c, "domain.x", &case.domain.x);
    check_axis(&mut c, "domain.y", &case.domain.y);

    if let Some(gas) = &case.gas {
        c.positive("gas.density", gas.density);
        c.positive("gas.viscosity", gas.viscosity);
        c.positive("gas.reference_pressure", gas.reference_pressure);
    }

    if case.solids.is_empty() && case.gas.is_none() {
        c.fail(
            "solids",
            "[]",
            "at least one solids phase, or a gas (a single-phase case)",
        );
    }
    for (k, s) in case.solids.iter().enumerate() {
        let p = format!("solids[{k}]");
        c.positive(format!("{p}.diameter"), s.diameter);
        c.positive(format!("{p}.density"), s.density);
        c.unit(format!("{p}.restitution"), s.restitution);
        c.range(
            format!("{p}.max_packing"),
            s.max_packing,
            B::Open(0.0),
            B::Open(1.0),
        );
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
        KineticTheory::Lun1984 { alpha } => c.non_negative("models.kinetic_theory.alpha", *alpha),
        KineticTheory::Algebraic => {}
    }
    if let Drag::SyamlalOBrien { c1, d1 } = &case.models.drag {
        c.positive("models.drag.c1", *c1);
        c.positive("models.drag.d1", *d1);
    }

    for (side, b) in case.boundaries.iter() {
        check_boundary(
            &mut c,
            &format!("boundaries.{}", side.name()),
            b,
            case.gas.is_some(),
        );
    }

    // Initial state.
    c.non_negative("initial.theta", case.initial.theta);
    c.finite("initial.gas_velocity.0", case.initial.gas_velocity.0);
    c.finite("initial.gas_velocity.1", case.initial.gas_velocity.1);
    if let InitialPressure::Uniform(p) = case.initial.gas_pressure {
        c.positive("initial.gas_pressure", p);
    }
    for (k, block) in case.initial.regions.iter().enumerate() {
        let p = format!("initial.regions[{k}]");
        check_span(&mut c, &format!("{p}.x"), block.x, x0, x_end);
        check_span(&mut c, &format!("{p}.y"), block.y, y0, y_end);
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
            c.range(
                format!("{q}.eps_s"),
                bs.eps_s,
                B::Closed(0.0),
                B::Closed(phase.max_packing),
            );
            c.finite(format!("{q}.velocity.0"), bs.velocity.0);
            c.finite(format!("{q}.velocity.1"), bs.velocity.1);
            c.non_negative(format!("{q}.theta"), bs.theta);
            total += bs.eps_s;
        }
        let max_pack = case
            .solids
            .iter()
            .map(|s| s.max_packing)
            .fold(0.0, f64::max);
        if block.solids.len() > 1 && total > max_pack {
            c.fail(
                format!("{p}.solids (sum of eps_s)"),
                total,
                format!("[0, {max_pack}]"),
            );
        }
    }

    // Gravity.
    match &case.gravity {
        Gravity::Constant { magnitude, slope } => {
            c.non_negative("gravity.magnitude", *magnitude);
            c.range("gravity.slope", *slope, B::Closed(0.0), B::Open(90.0));
        }
        Gravity::TiltOnImpact {
            magnitude,
            slope,
            contact_eps_s,
        } => {
            c.non_negative("gravity.magnitude", *magnitude);
            c.range("gravity.slope", *slope, B::Closed(0.0), B::Open(90.0));
            c.range(
                "gravity.contact_eps_s",
                *contact_eps_s,
                B::Open(0.0),
                B::Open(1.0),
            );
        }
    }

    // Run control.
    let run = &case.run;
    c.positive("run.end_time", run.end_time);
    c.positive("run.dt.min", run.dt.min);
    c.positive("run.dt.max", run.dt.max);
    c.range(
        "run.dt.initial",
        run.dt.initial,
        B::Closed(run.dt.min),
        B::Closed(run.dt.max),
    );
    if run.dt.min > run.dt.max {
        c.fail(
            "run.dt.min",
            run.dt.min,
            format!("<= run.dt.max = {}", run.dt.max),
        );
    }
    c.range("run.dt.factor", run.dt.factor, B::Open(0.0), B::Closed(1.0));
    if let Some(f) = run.dt.failure_factor {
        c.range("run.dt.failure_factor", f, B::Open(0.0), B::Open(1.0));
    }
    if run.dt.steps_per_change < 1 {
        c.fail(
            "run.dt.steps_per_change",
            run.dt.steps_per_change,
            "an integer >= 1",
        );
    }
    c.positive("run.tolerances.residual", run.tolerances.residual);
    c.positive(
        "run.tolerances.theta_residual",
        run.tolerances.theta_residual,
    );
    c.range(
        "run.tolerances.diverge",
        run.tolerances.diverge,
        B::Open(run.tolerances.residual),
        B::Inf,
    );
    if run.tolerances.max_iterations < 2 {
        c.fail(
            "run.tolerances.max_iterations",
            run.tolerances.max_iterations,
            "an integer >= 2",
        );
    }
    c.positive("run.output_interval", run.output_interval);
    if let Some(interval) = run.checkpoint_interval {
        c.positive("run.checkpoint_interval", interval);
    }

    let r = &case.numerics.relaxation;
    for (name, v) in [
        ("pressure", r.pressure),
        ("eps_s", r.eps_s),
        ("velocity", r.velocity),
        ("theta", r.theta),
        ("wall_closures", r.wall_closures),
    ] {
        c.range(
            format!("numerics.relaxation.{name}"),
            v,
            B::Open(0.0),
            B::Closed(1.0),
        );
    }

    // Monitors.
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
        c.positive(format!("{p}.interval"), probe.interval);
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
        c.positive(format!("{p}.interval"), front.interval);
    }
    if let Some(bulk) = &case.monitors.bulk {
        c.positive("monitors.bulk.interval", bulk.interval);
        c.range(
            "monitors.bulk.front_threshold",
            bulk.front_threshold,
            B::Open(0.0),
            B::Open(1.0),
        );
    }

    // Fidelity presets: coarsening ≥ 1, end times in (0, paper end time], grids build.
    let grid_ok = c.errors.is_empty();
    for (name, preset) in [
        ("smoke", &case.fidelity.smoke),
        ("coarse", &case.fidelity.coarse),
    ] {
        let p = format!("fidelity.{name}");
        if preset.coarsen < 1 {
            c.fail(format!("{p}.coarsen"), preset.coarsen, "an integer >= 1");
        }
        c.range(
            format!("{p}.end_time"),
            preset.end_time,
            B::Open(0.0),
            B::Closed(run.end_time),
        );
        let cx = case.domain.x.coarsened(preset.coarsen);
        let cy = case.domain.y.coarsened(preset.coarsen);
        if grid_ok && preset.coarsen >= 1 {
            if let Err(e) = Grid::from_specs(&cx, &cy) {
                c.fail(
                    format!("{p}.coarsen"),
                    preset.coarsen,
                    format!("a factor whose grid builds ({e})"),
                );
            }
        }
    }

    if c.errors.is_empty() {
        Ok(())
    } else {
        Err(c.errors)
    }
}

fn check_name(c: &mut Checker, field: &str, name: &str) {
    let ok = !name.is_empty()
        && name
            .chars()
            .all(|ch| ch.is_ascii_alphanumeric() || "-_.=".contains(ch));
    if !ok {
        c.fail(
            field,
            format!("{name:?}"),
            "a non-empty name of letters, digits and -_.=",
        );
    }
}

fn check_axis(c: &mut Checker, field: &str, axis: &AxisSpec) {
    let before = c.errors.len();
    c.finite(format!("{field}.origin"), axis.origin);
    if axis.segments.is_empty() {
        c.fail(format!("{field}.segments"), "[]", "at least one segment");
    }
    for (k, seg) in axis.segments.iter().enumerate() {
        if let Err(runout_mesh::MeshError::Invalid {
            field: f,
            value,
            allowed,
        }) = seg.validate(&format!("{field}.segments[{k}]"))
        {
            c.fail(f, value, allowed);
        }
    }
    if c.errors.len() == before {
        if let Err(e) = axis.build() {
            c.fail(
                format!("{field}.segments"),
                "(as given)",
                format!("segments that form a grid: {e}"),
            );
        }
    }
}

fn check_span(c: &mut Checker, field: &str, span: (f64, f64), lo: f64, hi: f64) {
    c.range(format!("{field}.0"), span.0, B::Closed(lo), B::Closed(hi));
    c.range(format!("{field}.1"), span.1, B::Closed(lo), B::Closed(hi));
    if span.1 <= span.0 || span.1.is_nan() {
        c.fail(
            format!("{field}.1"),
            span.1,
            format!("> {field}.0 = {}", span.0),
        );
    }
}

fn check_boundary(c: &mut Checker, p: &str, b: &Boundary, has_gas: bool) {
    match b {
        Boundary::PressureOutlet { pressure } => {
            let v = match pressure {
                OutletPressure::Uniform(v) | OutletPressure::Hydrostatic(v) => *v,
            };
            c.positive(format!("{p}.pressure"), v);
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
                    c.non_negative(format!("{p}.gas.h_u"), *h_u);
                    c.finite(format!("{p}.gas.u_w"), *u_w);
                }
                GasWall::Moving { u_w } => c.finite(format!("{p}.gas.u_w"), *u_w),
                GasWall::NoSlip | GasWall::FreeSlip => {}
            }
            let q = format!("{p}.solids");
            let wall_angle = |c: &mut Checker, v: f64| {
                c.range(
                    format!("{q}.wall_friction_angle"),
                    v,
                    B::Closed(0.0),
                    B::Open(90.0),
                )
            };
            match solids {
                SolidsWall::NoSlip | SolidsWall::FreeSlip => {}
                SolidsWall::PartialSlip {
                    h_u,
                    u_w,
                    h_theta,
                    theta_w,
                    c: flux,
                } => {
                    c.non_negative(format!("{q}.h_u"), *h_u);
                    c.finite(format!("{q}.u_w"), *u_w);
                    c.non_negative(format!("{q}.h_theta"), *h_theta);
                    c.non_negative(format!("{q}.theta_w"), *theta_w);
                    c.finite(format!("{q}.c"), *flux);
                }
                SolidsWall::JohnsonJackson {
                    specularity,
                    wall_restitution,
                    wall_friction_angle,
                    u_w,
                } => {
                    c.unit(format!("{q}.specularity"), *specularity);
                    c.unit(format!("{q}.wall_restitution"), *wall_restitution);
                    wall_angle(c, *wall_friction_angle);
                    c.finite(format!("{q}.u_w"), *u_w);
                }
                SolidsWall::RevisitedJohnsonJackson {
                    wall_restitution,
                    wall_friction_angle,
                    phi0,
                    u_w,
                } => {
                    c.unit(format!("{q}.wall_restitution"), *wall_restitution);
                    wall_angle(c, *wall_friction_angle);
                    if let Some(phi0) = phi0 {
                        c.range(format!("{q}.phi0"), *phi0, B::Open(0.0), B::Closed(1.0));
                    }
                    c.finite(format!("{q}.u_w"), *u_w);
                }
                SolidsWall::Jenkins {
                    wall_restitution,
                    wall_friction_angle,
                    u_w,
                } => {
                    c.unit(format!("{q}.wall_restitution"), *wall_restitution);
                    wall_angle(c, *wall_friction_angle);
                    c.finite(format!("{q}.u_w"), *u_w);
                }
            }
        }
    }
}

/// Validates a family-A file.
pub fn validate_analytic(a: &Analytic) -> Result<(), Vec<FieldError>> {
    let mut c = Checker::default();
    check_name(&mut c, "name", &a.name);
    c.positive("depth", a.depth);
    c.finite("velocity.bulk", a.velocity.bulk);
    c.finite("velocity.wall", a.velocity.wall);
    if a.velocity.h_u.is_empty() {
        c.fail("velocity.h_u", "[]", "at least one value");
    }
    for (k, h) in a.velocity.h_u.iter().enumerate() {
        c.non_negative(format!("velocity.h_u[{k}]"), *h);
    }
    c.non_negative("temperature.bulk", a.temperature.bulk);
    c.non_negative("temperature.wall", a.temperature.wall);
    for (k, h) in a.temperature.h_theta.iter().enumerate() {
        c.non_negative(format!("temperature.h_theta[{k}]"), *h);
    }
    for (k, v) in a.temperature.c.iter().enumerate() {
        c.finite(format!("temperature.c[{k}]"), *v);
    }
    if c.errors.is_empty() {
        Ok(())
    } else {
        Err(c.errors)
    }
}
