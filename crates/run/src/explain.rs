//! `runout check --explain`: what a case computes and what it costs. The solver is built
//! from the case as `runout run` builds it, and its scene ([`runout_solver::two_fluid::Scene`])
//! is printed with the monitors the case asks for and the size of the problem.

use std::fmt::Write;

use runout_case::{case_size, format_bytes, Case, Fidelity};

use crate::{single_phase_solver, two_fluid_solver, RunError};

/// The monitors `case` writes, one line each (the solids monitors only with solids).
pub fn monitor_lines(case: &Case) -> Vec<String> {
    let m = &case.monitors;
    let solids = !case.solids.is_empty();
    let mut lines = vec![format!(
        "fields (VTK) every {} s and at the end",
        case.run.output_interval
    )];
    if let (Some(b), true) = (&m.bulk, solids) {
        lines.push(format!(
            "bulk (mass, front, mean u_s) every {} s",
            b.interval
        ));
    }
    for p in m
        .wall_probes
        .iter()
        .filter(|p| solids && p.side == runout_mesh::Side::South)
    {
        lines.push(format!(
            "floor probe h_w^u at x = {} m every {} s",
            p.at, p.interval
        ));
    }
    if let (Some(f), true) = (&m.front, solids) {
        lines.push(format!(
            "front every {} s, speeds at {} gate(s)",
            f.interval,
            f.gates.len()
        ));
    }
    for p in &m.profiles {
        lines.push(format!("profile at x = {} m at t = {:?} s", p.x, p.times));
    }
    lines
}

/// What `case` at `fidelity` computes, its monitors and its size, as text.
pub fn explain(case: &Case, fidelity: Fidelity) -> Result<String, RunError> {
    let resolved = case.at_fidelity(fidelity);
    let mut text = String::new();
    let _ = writeln!(text, "{} at {fidelity} fidelity", resolved.name);
    if resolved.solids.is_empty() {
        let solver = single_phase_solver(&resolved)?;
        let g = solver.grid();
        let _ = writeln!(
            text,
            "single-phase incompressible flow (SIMPLE), {} × {} cells: momentum u, v and the \
             pressure correction each iteration; no closures, no wall closures, no granular \
             energy",
            g.nx(),
            g.ny()
        );
    } else {
        let solver = two_fluid_solver(&resolved)?;
        let _ = write!(text, "{}", solver.scene());
        if let Ok(Some(floor)) = resolved.bent_floor() {
            let x = &resolved.domain.x;
            let _ = write!(text, "{}", floor.describe(x.origin, x.end()));
        }
    }
    let _ = writeln!(text, "monitors:");
    for line in monitor_lines(&resolved) {
        let _ = writeln!(text, "  {line}");
    }
    if let Ok(size) = case_size(&resolved) {
        let _ = writeln!(
            text,
            "cost: {} cells, {} unknowns per outer iteration, about {} of memory",
            size.cells,
            size.unknowns,
            format_bytes(size.memory_bytes)
        );
    }
    Ok(text)
}
