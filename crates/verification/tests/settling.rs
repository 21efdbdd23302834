//! Settling column: the packed bed carries its weight (`checks::Settling`; one size).
//! The same check at full size: `cargo xtask verify settling`.

use runout_verification::{find, Size};

#[test]
fn settling_fast() {
    let check = find("settling").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
