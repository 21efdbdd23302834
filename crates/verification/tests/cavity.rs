//! Lid-driven cavity against Ghia, Ghia & Shin (1982), fast size (`checks::Cavity`).
//! The same check at full size: `cargo xtask verify cavity`.

use runout_verification::{find, Size};

#[test]
fn cavity_fast() {
    let check = find("cavity").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
