//! Fluidized bed hanging on the gas pressure drop (`checks::FluidizedBed`; one size).
//! The same check at full size: `cargo xtask verify fluidized-bed`.

use runout_verification::{find, Size};

#[test]
fn fluidized_bed_fast() {
    let check = find("fluidized-bed").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
