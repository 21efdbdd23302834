//! Defluidisation of a bed aerated through the floor at 1 kPa (`checks::Defluidisation`),
//! fast size: one bed height, H = 0.025 m (about a minute), against the rigid bed's diffusion
//! and the consolidation solution. The full size adds 0.035 and 0.05 m, the H² scaling and a
//! 0.05 m bed at 1 atm: `cargo xtask verify defluidisation`.

use runout_verification::{find, Size};

#[test]
fn defluidisation_fast() {
    let check = find("defluidisation").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
