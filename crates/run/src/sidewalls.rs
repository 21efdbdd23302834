//! The `sidewalls` option of a case as the two-fluid solver's [`Sidewalls`]
//! (docs/model.md §8).

use runout_case::{Case, GasSidewall};

use crate::RunError;
use runout_solver::two_fluid::Sidewalls;

/// The side walls of a two-fluid case, their solids condition as a wall model (validated
/// as a floor's), or none.
pub(super) fn sidewalls(case: &Case) -> Result<Option<Sidewalls>, RunError> {
    let Some(sw) = &case.sidewalls else {
        return Ok(None);
    };
    let solids = sw.solids.model().map_err(|e| RunError::Unsupported {
        case: case.name.clone(),
        reason: format!("sidewalls.solids: {e}"),
    })?;
    Ok(Some(Sidewalls {
        width: sw.width,
        solids,
        gas_no_slip: sw.gas == GasSidewall::NoSlip,
    }))
}
