//! Air as an ideal gas in a closed box while a bed settles (`checks::IdealGas`), fast size:
//! the smoke grid (5 × 25 cells, a few seconds). The full size adds the 10 × 50 grid: `cargo
//! xtask verify ideal-gas`.

use runout_verification::{find, Size};

#[test]
fn ideal_gas_fast() {
    let check = find("ideal-gas").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
