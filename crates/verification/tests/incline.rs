//! The μ(I) law on a rough incline, fast size (`checks::Incline`): the flowing layer at 25°
//! against the Bagnold profile on 50 cells, the layer at 18° on 25 cells against the creep of
//! the regularisation. The same check at full size (three grids, observed order):
//! `cargo xtask verify incline`.

use runout_verification::{find, Size};

#[test]
fn incline_fast() {
    let check = find("incline").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
