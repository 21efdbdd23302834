//! Taylor–Green vortex (orders in space and time, mass of every step), fast size (`checks::TaylorGreen`).
//! The same check at full size: `cargo xtask verify taylor-green`.

use runout_verification::{find, Size};

#[test]
fn taylor_green_fast() {
    let check = find("taylor-green").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
