//! Haff's law through the granular-energy equation (`checks::Haff`; one size).
//! The same check at full size: `cargo xtask verify haff`.

use runout_verification::{find, Size};

#[test]
fn haff_fast() {
    let check = find("haff").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
