//! A floor of several bends (`checks::BedPath`), fast size: the slide on 240 × 8 cells, the
//! layers on 120 × 4 (about 25 s). The full size: `cargo xtask verify bed-path`.

use runout_verification::{find, Size};

#[test]
fn bed_path_fast() {
    let check = find("bed-path").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
