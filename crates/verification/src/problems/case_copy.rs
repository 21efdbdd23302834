//! Editing a shipped case into a check's own: its end time at every fidelity, and
//! validation that names every refused field.

use anyhow::Result;
use runout_case::Case;

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
