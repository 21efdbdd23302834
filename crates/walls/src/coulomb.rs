//! A Coulomb wall: the grains slide on the wall against a friction proportional to the
//! load they put on it (docs/model.md §3.11; not in MFIX).
//!
//! τ_w = −μ_w N_w u_sl/|u_sl|, N_w the solids' normal load on the wall (the normal traction
//! −n·σ_s·n: the pressure P = P_kin + P_fric at the wall and the load beyond it that the
//! solver measures, [`MomentumWallState::extra_normal_load`]), μ_w = tan δ_w the grain–wall
//! friction coefficient. This is the side-wall stress of Jop, Forterre &
//! Pouliquen (2005, J. Fluid Mech. 541, 167) for a granular flow between glass walls, and
//! the frictional wall that a μ(I) flow needs (a Coulomb law at the wall like the Coulomb law
//! in the bulk). The sign function is regularised as the μ(I) law's strain rate is
//! (docs/model.md §2.4.4):
//!
//!   K = τ_w/|u_sl| = μ_w N_w/√(|u_sl|² + u_min²)   [Pa s m⁻¹],
//!
//! so that a layer pushed along the wall by a stress r μ_w N_w, r < 1, creeps at
//! |u_sl| = u_min r/√(1 − r²) ([`CoulombWall::creep_slip`]) instead of standing still.
//! The default u_min = 1e-4 m/s keeps that creep below 2.1e-4 m/s for r ≤ 0.9: at most
//! 0.05 % of √(g H0) for the collapse check's columns (H0 ≥ 2.5 cm), far below its "at
//! rest" threshold of 1 %. The wall's frictional work heats the wall, not the granular temperature: the
//! granular-energy flux through a Coulomb wall is zero.

use crate::error::{Checks, WallError};
use crate::face::RobinFace;
use crate::model::{
    ratio_or_zero, wall_kinetics, MomentumBranch, MomentumDiagnostics, MomentumWall,
};
use crate::state::MomentumWallState;
use runout_closures::guards::DIL_EP_S;
use runout_closures::ClosureParams;
use serde::Serialize;

/// Default slip-speed regularisation u_min of a Coulomb wall [m s⁻¹] (module doc).
pub const DEFAULT_SLIP_FLOOR: f64 = 1e-4;

/// A Coulomb wall with friction coefficient μ_w and slip regularisation u_min, validated.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CoulombWall {
    /// grain–wall friction coefficient μ_w = tan δ_w [-]
    pub friction: f64,
    /// slip-speed regularisation u_min [m s⁻¹]
    pub slip_floor: f64,
}

impl CoulombWall {
    /// μ_w ∈ [0, 10] (a wall friction angle below 84°), u_min ∈ (0, 1] m/s.
    pub fn new(friction: f64, slip_floor: f64) -> Result<Self, WallError> {
        let mut checks = Checks::default();
        let wall = Self {
            friction: checks.check("friction", friction, "[0, 10]", |v| {
                (0.0..=10.0).contains(&v)
            }),
            slip_floor: checks.check("slip_floor", slip_floor, "(0, 1] m/s", |v| {
                v > 0.0 && v <= 1.0
            }),
        };
        checks.finish(Some(wall))
    }

    /// K = μ_w N/√(|u_sl|² + u_min²) [Pa s m⁻¹]: the wall stress per unit slip at normal
    /// load `normal_load` [Pa] and slip speed `slip` [m s⁻¹] (module doc).
    #[inline]
    pub fn stress_per_slip(&self, normal_load: f64, slip: f64) -> f64 {
        self.friction * normal_load / slip.hypot(self.slip_floor)
    }

    /// The slip speed at which the regularised wall stress K |u_sl| equals r μ_w N, r ∈ [0, 1):
    /// u_min r/√(1 − r²) [m s⁻¹] (the creep of a layer loaded below the wall's strength).
    pub fn creep_slip(&self, stress_ratio: f64) -> f64 {
        self.slip_floor * stress_ratio / (1.0 - stress_ratio * stress_ratio).sqrt()
    }
}

/// The momentum face of a Coulomb wall (module doc): free slip next to a
/// cell with εs ≤ `DIL_EP_S` (as JJ, docs/model.md §3.5 step 0); else, with θ ≥ 1e-8,
/// P = P_kin (Lun 1984) + P_fric (the friction model's, where it has a wall friction and the
/// interpolated εs > εs,min), N_w = P + the state's `extra_normal_load` (≥ 0),
/// K = μ_w N_w/√(|u_sl|² + u_min²) (in `col`), and
/// h_w^u = K/μ_s with the viscosity of the wall routine, μ_k joined with μ_f as the friction
/// model joins them (the rule that forms JJ's h_w^u, §3.5 step 4). The wall is at rest.
/// The solver replaces h by K/Γ with its own face viscosity Γ
/// ([`MomentumWall::with_face_viscosity`]), and uses K itself on side walls.
pub(crate) fn coulomb_momentum(
    wall: &CoulombWall,
    state: &MomentumWallState,
    params: &ClosureParams,
) -> MomentumWall {
    let mut diagnostics = MomentumDiagnostics {
        branch: MomentumBranch::DiluteFreeSlip,
        slip: state.slip,
        ..MomentumDiagnostics::default()
    };
    if state.eps_s_fluid <= DIL_EP_S {
        return MomentumWall {
            face: RobinFace::ZERO_GRADIENT,
            diagnostics,
        };
    }
    let (theta, _, kinetic) = wall_kinetics(state, params);
    diagnostics.branch = MomentumBranch::Coulomb;
    diagnostics.theta = theta;
    diagnostics.mu_kin = kinetic.mu_kin;
    diagnostics.p_kin = kinetic.p_kin;
    if params
        .friction_model
        .wall_friction_acts_at(state.eps_s, &params.friction)
    {
        diagnostics.add_wall_friction(state, params);
    }
    diagnostics.normal_load = normal_load(&diagnostics, state);
    diagnostics.col = wall.stress_per_slip(diagnostics.normal_load, state.slip);
    diagnostics.h_u = ratio_or_zero(diagnostics.col, diagnostics.viscosity());
    MomentumWall {
        face: RobinFace::partial_slip(diagnostics.h_u, 0.0),
        diagnostics,
    }
}

/// The normal load N_w = P_kin + P_fric + (N_w − P_s) the wall's friction is proportional
/// to \[Pa\] (docs/model.md §3.11): the pressure at the wall state plus the load beyond it
/// that the solver measured ([`MomentumWallState::extra_normal_load`]); a wall is pressed
/// on, never pulled, so N_w ≥ 0.
fn normal_load(diagnostics: &MomentumDiagnostics, state: &MomentumWallState) -> f64 {
    (diagnostics.p_kin + diagnostics.p_fric + state.extra_normal_load).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::SolidsWallModel;

    #[test]
    fn fast_slip_carries_the_coulomb_stress() {
        let wall = CoulombWall::new(0.4, DEFAULT_SLIP_FLOOR).unwrap();
        // |u_sl| ≫ u_min: τ_w = K |u_sl| → μ_w P
        let (p, slip) = (800.0, 0.5);
        let tau = wall.stress_per_slip(p, slip) * slip;
        assert!((tau / (0.4 * p) - 1.0).abs() < 1e-7, "{tau}");
    }

    #[test]
    fn creep_is_where_the_regularised_stress_meets_the_load() {
        let wall = CoulombWall::new(0.5, 2e-4).unwrap();
        let p = 300.0;
        for r in [0.0, 0.3, 0.9, 0.99] {
            let u = wall.creep_slip(r);
            let tau = wall.stress_per_slip(p, u) * u;
            assert!((tau - r * 0.5 * p).abs() <= 1e-12 * p, "r = {r}: {tau}");
        }
        // the module doc's bound: r = 0.9 creeps below 2.1e-4 m/s at the default floor
        let default = CoulombWall::new(0.5, DEFAULT_SLIP_FLOOR).unwrap();
        assert!(default.creep_slip(0.9) < 2.1e-4);
    }

    fn mu_i_params() -> ClosureParams {
        ClosureParams {
            friction_model: runout_closures::FrictionModel::MuI(
                runout_closures::MuIConstants::glass_beads_jop_2005(),
            ),
            ..ClosureParams::default()
        }
    }

    fn dense_state(slip: f64) -> MomentumWallState {
        MomentumWallState {
            eps_s_fluid: 0.58,
            eps_s: 0.58,
            theta: 1e-4,
            slip,
            gas_slip: slip,
            tr_d: 0.0,
            s_ddot_s: 50.0,
            s_nn: 0.0,
            extra_normal_load: 0.0,
        }
    }

    /// On a dense μ(I) state the face carries τ_w = μ_w (P_kin + P_c) at fast slip, P_c the
    /// critical-state pressure Fr (εs − εs,min)²/(εs,max − εs)⁵ with MFIX's Fr = 0.05 Pa
    /// (paper Eq. 10), P_kin = ρs εs θ (1 + 2 (1 + e) εs g0) (Lun 1984), both written here
    /// from the formulas.
    #[test]
    fn a_dense_face_carries_the_coulomb_stress_of_the_total_pressure() {
        let params = mu_i_params();
        let wall = SolidsWallModel::coulomb(0.4, DEFAULT_SLIP_FLOOR).unwrap();
        let state = dense_state(0.5);
        let face = wall.momentum(&state, &params);
        let d = face.diagnostics;
        assert_eq!(d.branch, MomentumBranch::Coulomb);
        let (eps, e) = (0.58, params.particles.restitution);
        let g0 = params.radial.g0(eps);
        let p_kin = params.particles.density * eps * 1e-4 * (1.0 + 2.0 * (1.0 + e) * eps * g0);
        let p_c = 0.05 * (eps - 0.5f64).powi(2) / (0.65 - eps).powi(5);
        let expected = 0.4 * (p_kin + p_c) / 0.5f64.hypot(DEFAULT_SLIP_FLOOR);
        assert!(
            (d.col / expected - 1.0).abs() < 1e-12,
            "{} {expected}",
            d.col
        );
        // the Robin face h u = K u/μ_s: the stress it imposes is K |u_sl|
        let tau = face.face.h * d.viscosity() * state.slip;
        assert!((tau / (0.4 * (p_kin + p_c)) - 1.0).abs() < 1e-7, "{tau}");
        assert_eq!((face.face.g, face.face.c), (1.0, 0.0));
    }

    /// The load beyond the pressure adds to it (N_w = P + extra), and a wall is never pulled:
    /// an extra load below −P gives no stress.
    #[test]
    fn the_normal_load_beyond_the_pressure_adds_to_it() {
        let params = mu_i_params();
        let wall = SolidsWallModel::coulomb(0.3, DEFAULT_SLIP_FLOOR).unwrap();
        let bare = wall.momentum(&dense_state(0.5), &params).diagnostics;
        let pressure = bare.p_kin + bare.p_fric;
        let loaded = MomentumWallState {
            extra_normal_load: 0.25 * pressure,
            ..dense_state(0.5)
        };
        let col = wall.momentum(&loaded, &params).diagnostics.col;
        assert!((col / bare.col - 1.25).abs() < 1e-12, "{col} {}", bare.col);
        let pulled = MomentumWallState {
            extra_normal_load: -2.0 * pressure,
            ..dense_state(0.5)
        };
        assert_eq!(wall.momentum(&pulled, &params).diagnostics.col, 0.0);
    }

    /// Dilute cells slide freely; the granular-energy flux is zero everywhere; the side-wall
    /// stress per slip is K.
    #[test]
    fn dilute_cells_slide_freely_and_no_granular_energy_crosses() {
        let params = mu_i_params();
        let wall = SolidsWallModel::coulomb(0.4, DEFAULT_SLIP_FLOOR).unwrap();
        let dilute = MomentumWallState {
            eps_s_fluid: 1e-5,
            eps_s: 1e-5,
            ..dense_state(1.0)
        };
        assert_eq!(
            wall.momentum(&dilute, &params).face,
            RobinFace::ZERO_GRADIENT
        );
        let theta = crate::ThetaWallState {
            eps_s: 0.58,
            theta: 1e-3,
            slip: 1.0,
            gas_slip: 1.0,
        };
        assert_eq!(
            wall.granular_temperature(&theta, &params).face,
            RobinFace::ZERO_GRADIENT
        );
        let state = dense_state(0.01);
        let k = wall.side_wall_stress_per_slip(&state, 1.0, 0.1, &params);
        assert_eq!(k, wall.momentum(&state, &params).diagnostics.col);
        assert!(k > 0.0);
    }

    #[test]
    fn bad_parameters_are_named() {
        let e = CoulombWall::new(-0.1, 0.0).unwrap_err();
        let names: Vec<_> = e.fields.iter().map(|f| f.field).collect();
        assert_eq!(names, ["friction", "slip_floor"]);
        assert!(CoulombWall::new(f64::NAN, 1e-4).is_err());
        assert!(CoulombWall::new(0.4, f64::INFINITY).is_err());
    }
}
