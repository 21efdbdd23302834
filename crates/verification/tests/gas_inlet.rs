//! A bed fluidised through a floor inlet on a schedule (`checks::GasInlet`), fast size: the
//! smoke grid (5 × 30 cells, a few seconds). The full size adds the 10 × 60 grid: `cargo
//! xtask verify gas-inlet`.

use runout_verification::{find, Size};

#[test]
fn gas_inlet_fast() {
    let check = find("gas-inlet").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}
