//! A polygon pile behind a gate (`checks::Release`), fast size: 100 × 30 cells. The full
//! size: `cargo xtask verify release`.

use runout_verification::{find, Size};

#[test]
fn release_fast() {
    let check = find("release").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
