//! The Coulomb wall against the sliding-block law, fast size (`checks::CoulombFloor`): the
//! block at μ_w = 0.2 on two grids, its momentum budget at μ_w = 0.1 on 120 × 16, the layer
//! between side walls on 25 cells. The full size
//! (four μ_w, three grids each): `cargo xtask verify coulomb-floor`.

use runout_verification::{find, Size};

#[test]
fn coulomb_floor_fast() {
    let check = find("coulomb-floor").expect("registered");
    let outcome = check.run(Size::Fast).expect("the check ran");
    print!("{outcome}");
    assert!(outcome.passed(), "{outcome}");
}

/// The Coulomb floor's load is the block's weight within 2 % at t = 0.1 and 0.15 s, on
/// 120 × 16 and 240 × 32 cells (about 6 min): `cargo test --release -p runout-verification
/// --test coulomb_floor -- --ignored --nocapture`.
#[test]
#[ignore = "six minutes: the finest grid"]
fn the_floor_load_is_the_weight() {
    use runout_verification::problems::coulomb_floor::floor_load_ratios;
    for (nx, ny) in [(120, 16), (240, 32)] {
        let ratios = floor_load_ratios(nx, ny, 0.1, &[0.1, 0.15]).expect("the block ran");
        println!("{nx} × {ny}: floor load / weight at 0.10, 0.15 s: {ratios:.4?}");
        for r in ratios {
            assert!((r - 1.0).abs() < 0.02, "{nx} × {ny}: {r}");
        }
    }
}

/// The block on a frictionless Coulomb floor (μ_w = 0) in the thin pore gas, on 120 × 16 and
/// 240 × 32 cells: whether the fine grid's deficit of about 0.003 in μ_w (a forward force
/// that does not scale with μ_w) appears without friction (about 10 min):
/// `cargo test --release -p runout-verification --test coulomb_floor frictionless --
/// --ignored --nocapture`.
#[test]
#[ignore = "ten minutes: the finest grid"]
fn the_frictionless_block_slides_at_g_sin_theta() {
    use runout_verification::problems::coulomb_floor::{run_block, PoreGas, JUDGED_FORM};
    for (nx, ny) in [(120, 16), (240, 32)] {
        let run = run_block(nx, ny, 0.0, PoreGas::Thin, JUDGED_FORM).expect("the block ran");
        println!(
            "{nx} × {ny}: a = {:.4} m/s² against g sin θ = {:.4}: effective μ_w {:+.5} ({:.0} s)",
            run.acceleration, run.expected, run.effective_mu_w, run.wall_time
        );
        assert!(
            run.effective_mu_w.abs() < 0.002,
            "{nx} × {ny}: {}",
            run.effective_mu_w
        );
    }
}
