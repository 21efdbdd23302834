//! The two-fluid solver skips the closures of cells without solids (εs = 0) and uses zero
//! for every closure value it reads there; this checks that runout-closures gives exactly
//! that, for every drag law and frictional model, over a range of θ, slip and strain.

use runout_closures::{CellState, ClosureParams, Drag, FrictionModel};
use runout_solver::two_fluid::CellClosures;

#[test]
fn closures_vanish_without_solids() {
    let drags = [
        Drag::SyamlalOBrien { c1: 0.8, d1: 2.65 },
        Drag::Gidaspow,
        Drag::GidaspowBlend,
        Drag::WenYu,
    ];
    let frictions = [
        FrictionModel::None,
        FrictionModel::schaeffer(),
        FrictionModel::princeton(),
    ];
    for drag in drags {
        for friction_model in frictions {
            let params = ClosureParams {
                drag,
                friction_model,
                ..ClosureParams::default()
            };
            for theta in [1e-12, 1e-5, 0.1, 10.0] {
                for slip in [0.0, 0.3, 20.0] {
                    for (tr_d, s_ddot_s) in [(0.0, 0.0), (-2.0, 50.0), (3.0, 1e4)] {
                        let state = CellState {
                            eps_s: 0.0,
                            theta,
                            slip,
                            tr_d,
                            s_ddot_s,
                        };
                        assert_eq!(
                            CellClosures::evaluate(&state, &params),
                            CellClosures::default(),
                            "{state:?} {drag:?} {friction_model:?}"
                        );
                    }
                }
            }
        }
    }
}
