//! Editing a shipped case into a check's own: its end time at every fidelity, and
//! validation that names every refused field.

use std::path::Path;

use anyhow::{bail, Context, Result};
use runout_case::{load, load_case, Case, Gravity, Loaded};
use runout_mesh::Segment;

/// The shipped case `template` (relative to the workspace root) renamed `name`, on a uniform
/// grid of `cells` over `size` (along, across) [m], under `gravity`.
pub(crate) fn template_on_grid(
    template: &str,
    name: String,
    size: (f64, f64),
    cells: (usize, usize),
    gravity: Gravity,
) -> Result<Case> {
    let file = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(template);
    let mut case = load_case(&file).with_context(|| format!("loading {}", file.display()))?;
    case.name = name;
    case.domain.x.segments = vec![Segment::Uniform {
        length: size.0,
        cells: cells.0,
    }];
    case.domain.y.segments = vec![Segment::Uniform {
        length: size.1,
        cells: cells.1,
    }];
    case.gravity = gravity;
    Ok(case)
}

/// The member `name` of the shipped sweep `file` (relative to the workspace root).
pub(crate) fn sweep_member(file: &str, name: &str) -> Result<Case> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(file);
    let Loaded::Cases(cases) =
        load(&path).with_context(|| format!("loading {}", path.display()))?
    else {
        bail!("{} is not a sweep", path.display())
    };
    Ok(cases
        .into_iter()
        .find(|c| c.case.name == name)
        .with_context(|| format!("no case {name} in {}", path.display()))?
        .case)
}

/// `case` with its gas's viscosity scaled by `fraction` (a thin pore gas whose drag, in the
/// Stokes regime, scales with it).
pub(crate) fn thin_gas(mut case: Case, fraction: f64) -> Result<Case> {
    case.gas.as_mut().context("the case has a gas")?.viscosity *= fraction;
    Ok(case)
}

/// `case` with every fidelity ending at `end` [s].
pub(crate) fn ending_at(mut case: Case, end: f64) -> Case {
    case.run.end_time = end;
    case.fidelity.smoke.end_time = end;
    case.fidelity.coarse.end_time = end;
    if let Some(wall) = case.fidelity.wall.as_mut() {
        wall.end_time = end;
    }
    case
}

/// `case` if it validates, else an error naming `what` and every refused field.
pub(crate) fn validated(case: Case, what: &str) -> Result<Case> {
    runout_case::validate_case(&case).map_err(|errors| {
        let fields: Vec<String> = errors.iter().map(|e| e.to_string()).collect();
        anyhow::anyhow!("the {what} case is invalid: {}", fields.join("; "))
    })?;
    Ok(case)
}
