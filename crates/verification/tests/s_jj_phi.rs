//! S-JJ-phi φ = 0.1 through the driver to 1.25 s, smoke fidelity (`checks::SJjPhi`).
//! The same check at full size: `cargo xtask verify s-jj-phi`.

use runout_verification::{find, Size};

#[test]
fn s_jj_phi_fast() {
    let check = find("s-jj-phi").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
