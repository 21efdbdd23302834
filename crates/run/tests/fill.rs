//! The fill of an initial block (issue 19 item 6): by cell centres (the default) the
//! released mass depends on the grid; by covered fraction it is the block's area × εs × ρs
//! at every fidelity, to round-off.

use std::path::Path;

use runout_case::{load, Case, Fidelity, Fill, Loaded};
use runout_run::two_fluid_solver;

fn base() -> Case {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/sensitivity/base.ron");
    let Loaded::Cases(cases) = load(&file).unwrap() else {
        panic!("a case")
    };
    cases.into_iter().next().unwrap().case
}

/// The solids mass per unit depth at t = 0 [kg/m].
fn released(case: &Case, fidelity: Fidelity) -> f64 {
    two_fluid_solver(&case.at_fidelity(fidelity))
        .unwrap()
        .solids_mass(0)
}

const FIDELITIES: [Fidelity; 3] = [Fidelity::Smoke, Fidelity::Coarse, Fidelity::Paper];

#[test]
fn covered_fraction_releases_the_blocks_mass_on_every_grid() {
    let mut case = base();
    case.initial.regions[0].fill = Fill::CoveredFraction;
    // the base's block, and one whose edges cross cells anywhere
    for (x, y) in [
        ((5.0, 5.5), (0.40, 0.60)),
        ((5.0137, 5.5171), (0.4033, 0.6071)),
    ] {
        case.initial.regions[0].x = x;
        case.initial.regions[0].y = y;
        let exact = (x.1 - x.0) * (y.1 - y.0) * 0.60 * 2000.0;
        for f in FIDELITIES {
            let m = released(&case, f);
            assert!(
                ((m - exact) / exact).abs() <= 1e-12,
                "{f}: {m} kg/m, expected {exact}"
            );
        }
    }
}

#[test]
fn cell_centres_release_a_mass_that_depends_on_the_grid() {
    // the base fills by covered fraction since issue 19's criterion; this is the old fill
    let mut case = base();
    case.initial.regions[0].fill = Fill::CellCentre;
    let masses: Vec<f64> = FIDELITIES.iter().map(|&f| released(&case, f)).collect();
    let mut covered = case.clone();
    covered.initial.regions[0].fill = Fill::CoveredFraction;
    for (f, m) in FIDELITIES.iter().zip(&masses) {
        eprintln!(
            "released at {f}: {m:.6} kg/m by cell centres, {:.12} kg/m by covered fraction",
            released(&covered, *f)
        );
    }
    // issue 19: 117.8 / 149.8 / 131.8 kg/m against 120
    for (m, expected) in masses.iter().zip([117.8, 149.8, 131.8]) {
        assert!((m - expected).abs() < 0.05, "{masses:?}");
    }
}
