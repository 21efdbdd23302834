//! Homogeneous cooling through the whole two-fluid step (`checks::Cooling`; one size).
//! The same check at full size: `cargo xtask verify cooling`.

use runout_verification::{find, Size};

#[test]
fn tfm_cooling_fast() {
    let check = find("cooling").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
