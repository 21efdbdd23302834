//! Steady chute flow, 2-D periodic column against the 1-D reference, fast size (`checks::Chute`).
//! The same check at full size: `cargo xtask verify chute`.

use runout_verification::{find, Size};

#[test]
fn chute_column_fast() {
    let check = find("chute").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
