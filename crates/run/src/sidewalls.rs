//! The `sidewalls` option of a case as the two-fluid solver's [`Sidewalls`]
//! (docs/model.md §8).

use runout_case::{Case, GasSidewall, SolidsWall};
use runout_walls::SolidsWallModel;

use crate::RunError;
use runout_solver::two_fluid::Sidewalls;

/// The side walls of a two-fluid case, their solids condition as a wall model (validated
/// as a floor's), or none.
pub(super) fn sidewalls(case: &Case) -> Result<Option<Sidewalls>, RunError> {
    let Some(sw) = &case.sidewalls else {
        return Ok(None);
    };
    let model_err = |e: runout_walls::WallError| RunError::Unsupported {
        case: case.name.clone(),
        reason: format!("sidewalls.solids: {e}"),
    };
    let solids = match &sw.solids {
        SolidsWall::NoSlip => Ok(SolidsWallModel::NoSlip),
        SolidsWall::FreeSlip => Ok(SolidsWallModel::FreeSlip),
        SolidsWall::PartialSlip {
            h_u,
            u_w,
            h_theta,
            theta_w,
            c,
        } => SolidsWallModel::partial_slip(*h_u, *u_w, *h_theta, *theta_w, *c),
        SolidsWall::JohnsonJackson {
            specularity,
            wall_restitution,
            wall_friction_angle,
            u_w,
        } => SolidsWallModel::johnson_jackson(
            *specularity,
            *wall_restitution,
            *wall_friction_angle,
            *u_w,
        ),
        SolidsWall::RevisitedJohnsonJackson {
            wall_restitution,
            wall_friction_angle,
            phi0,
            u_w,
        } => SolidsWallModel::revisited_johnson_jackson(
            *wall_restitution,
            *wall_friction_angle,
            *phi0,
            *u_w,
        ),
        SolidsWall::Jenkins {
            wall_restitution,
            wall_friction_angle,
            u_w,
        } => SolidsWallModel::jenkins(*wall_restitution, *wall_friction_angle, *u_w),
    }
    .map_err(model_err)?;
    Ok(Some(Sidewalls {
        width: sw.width,
        solids,
        gas_no_slip: sw.gas == GasSidewall::NoSlip,
    }))
}
