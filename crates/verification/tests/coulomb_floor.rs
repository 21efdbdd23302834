//! The Coulomb wall against the sliding-block law, fast size (`checks::CoulombFloor`): the
//! block at μ_w = 0.2 on two grids, the layer between side walls on 25 cells. The full size
//! (four μ_w, three grids each): `cargo xtask verify coulomb-floor`.

use runout_verification::{find, Size};

#[test]
fn coulomb_floor_fast() {
    let check = find("coulomb-floor").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
