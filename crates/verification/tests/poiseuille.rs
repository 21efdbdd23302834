//! Partial-slip Poiseuille flow against its closed form, fast size (`checks::Poiseuille`).
//! The same check at full size: `cargo xtask verify poiseuille`.

use runout_verification::{find, Size};

#[test]
fn poiseuille_fast() {
    let check = find("poiseuille").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
