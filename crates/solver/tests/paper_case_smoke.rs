//! The paper's user partial-slip slide (S-PS-d, d = 0.5 mm) at smoke fidelity through the
//! first two-fluid solver. Slow and still failing: `cargo test -p runout-solver --release
//! --test paper_case_smoke -- --ignored --nocapture`.

use std::path::Path;

use runout_case::{load, Fidelity, Loaded};

#[test]
#[ignore]
fn s_ps_d_smoke() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/sensitivity/S-PS-d.ron");
    let Loaded::Cases(cases) = load(&file).unwrap() else {
        panic!()
    };
    let case = cases
        .into_iter()
        .find(|c| c.case.name == "S-PS-d_d=0.0005")
        .unwrap()
        .case;
    let out = std::env::temp_dir().join("runout-sps-smoke");
    let t0 = std::time::Instant::now();
    let summary = runout_solver::run_case(&case, Fidelity::Smoke, &out, |p| {
        if p.steps % 10 == 0 {
            eprintln!(
                "t = {:.4} s dt = {:.2e} it = {} steps = {} wall {:.1} s",
                p.time,
                p.dt,
                p.iterations,
                p.steps,
                t0.elapsed().as_secs_f64()
            );
        }
    })
    .unwrap();
    eprintln!("{summary:?}");
}
