//! Two under-relaxations, one flow (`checks::Relaxation`), fast size: S-JEN-d d = 0.5 mm at
//! `wall` fidelity with family S's factors and MFIX's (about three minutes). The full size
//! adds the coarse and the paper's grids: `cargo xtask verify relaxation`.

use runout_verification::{find, Size};

#[test]
fn relaxation_fast() {
    let check = find("relaxation").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
