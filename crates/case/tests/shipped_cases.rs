//! Every file under cases/ loads and validates, and the matrix has the size of cases.md.

use std::path::{Path, PathBuf};

use runout_case::{load, Fidelity, Loaded, SolidsWall};

fn cases_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases")
}

fn load_cases(rel: &str) -> Vec<runout_case::SourcedCase> {
    match load(&cases_dir().join(rel)).unwrap_or_else(|e| panic!("{e}")) {
        Loaded::Cases(c) => c,
        Loaded::Analytic(_) => panic!("{rel} is analytic"),
    }
}

#[test]
fn every_shipped_file_is_valid() {
    let mut n = 0;
    let families = [
        "sensitivity",
        "flume",
        "mfix-slope",
        "analytic",
        "collapse",
        "stability",
        "../examples",
    ];
    for family in families {
        for entry in std::fs::read_dir(cases_dir().join(family)).unwrap() {
            let path = entry.unwrap().path();
            if path.extension().is_some_and(|e| e == "ron") {
                load(&path).unwrap_or_else(|e| panic!("{e}"));
                n += 1;
            }
        }
    }
    assert!(n >= 30, "only {n} case files found");
}

#[test]
fn sensitivity_matrix_matches_cases_md() {
    // cases.md family S: 3 + 3 + 3 + 1 + 5 + 3 + 6 + 6 runs
    let expected = [
        ("S-JJ-phi.ron", 3),
        ("S-JJ-d.ron", 3),
        ("S-JEN-d.ron", 3),
        ("S-RJJ.ron", 1),
        ("S-PS-hu.ron", 5),
        ("S-PS-d.ron", 3),
        ("S-PS-htheta.ron", 6),
        ("S-PS-cw.ron", 6),
    ];
    for (file, count) in expected {
        let cases = load_cases(&format!("sensitivity/{file}"));
        assert_eq!(cases.len(), count, "{file}");
    }
    let phi = load_cases("sensitivity/S-JJ-phi.ron");
    let names: Vec<&str> = phi.iter().map(|c| c.case.name.as_str()).collect();
    assert_eq!(
        names,
        ["S-JJ-phi_phi=1", "S-JJ-phi_phi=0.1", "S-JJ-phi_phi=0.01"]
    );
    for (c, want) in phi.iter().zip([1.0, 0.1, 0.01]) {
        // the floor and both ends carry the swept specularity (cases.md: same solids BC)
        for side in [
            &c.case.boundaries.south,
            &c.case.boundaries.west,
            &c.case.boundaries.east,
        ] {
            match side {
                runout_case::Boundary::Wall {
                    solids: SolidsWall::JohnsonJackson { specularity, .. },
                    ..
                } => {
                    assert_eq!(*specularity, want)
                }
                other => panic!("unexpected {other:?}"),
            }
        }
        assert_eq!(c.case.solids[0].diameter, 5e-4);
    }
}

#[test]
fn cartesian_product_of_two_lists() {
    let cases = load_cases("sensitivity/S-PS-cw.ron");
    let pairs: Vec<(f64, f64)> = cases
        .iter()
        .map(|c| {
            let cw = match &c.case.boundaries.south {
                runout_case::Boundary::Wall {
                    solids: SolidsWall::PartialSlip { c, .. },
                    ..
                } => *c,
                other => panic!("{other:?}"),
            };
            (cw, c.case.gravity.slope())
        })
        .collect();
    assert_eq!(
        pairs,
        [
            (0.1, 40.0),
            (0.1, 0.0),
            (1.0, 40.0),
            (1.0, 0.0),
            (10.0, 40.0),
            (10.0, 0.0)
        ]
    );
}

#[test]
fn flume_has_the_seven_gates_of_the_paper() {
    let cases = load_cases("flume/F-JJ.ron");
    assert_eq!(cases.len(), 2);
    let front = cases[0].case.monitors.front.as_ref().unwrap();
    let gates: Vec<f64> = (0..7).map(|k| 1.65 + 0.45 * k as f64).collect();
    for (g, want) in front.gates.iter().zip(&gates) {
        assert!((g - want).abs() < 1e-12, "{g} vs {want}");
    }
    assert_eq!(front.gates.len(), 7);
}

#[test]
fn paper_grids_have_the_papers_cell_sizes() {
    // 20 m × 1.8 m with 0.02 m × 0.005 m focus cells (paper Fig. 2)
    let s = load_cases("sensitivity/base.ron")[0]
        .case
        .grid()
        .unwrap()
        .summary();
    assert!((s.x_range.1 - 20.0).abs() < 1e-12 && (s.y_range.1 - 1.8).abs() < 1e-12);
    assert!((s.dx_min - 0.02).abs() < 1e-12 && (s.dy_min - 0.005).abs() < 1e-12);
    // 7.5 m × 1.8 m with 0.01 m × 0.01 m cells (paper Fig. 11)
    let s = load_cases("flume/base.ron")[0]
        .case
        .grid()
        .unwrap()
        .summary();
    assert!((s.x_range.1 - 7.5).abs() < 1e-12 && (s.y_range.1 - 1.8).abs() < 1e-12);
    assert!((s.dx_min - 0.01).abs() < 1e-12 && (s.dy_min - 0.01).abs() < 1e-12);
    // family M: 200 × 50 uniform cells of 0.02 m × 0.01 m
    let g = load_cases("mfix-slope/jj.ron")[0].case.grid().unwrap();
    assert_eq!((g.nx(), g.ny()), (200, 50));
}

#[test]
fn fidelity_changes_only_grid_and_end_time() {
    // besides the clock: the base counts its times from the impact, which every fidelity
    // resolves to times from the start (docs/studies/impact.md §4)
    let case = load_cases("sensitivity/base.ron").remove(0).case;
    let tilt = case.scheduled_tilt_time().unwrap();
    let resolved = case.clone().with_start_clock();
    assert_eq!(resolved.run.end_time, case.run.end_time + tilt);
    for f in [Fidelity::Smoke, Fidelity::Coarse] {
        let mut c = case.at_fidelity(f);
        assert!(c.grid().unwrap().cell_count() < case.grid().unwrap().cell_count());
        // restore the two fields; everything else must be identical
        c.domain = case.domain.clone();
        c.run.end_time = resolved.run.end_time;
        assert_eq!(c, resolved);
    }
    assert_eq!(case.at_fidelity(Fidelity::Paper), resolved);
    let smoke = case.at_fidelity(Fidelity::Smoke);
    assert_eq!(smoke.run.end_time, case.fidelity.smoke.end_time + tilt);
    // the block must still be resolved on the smoke grid
    let g = smoke.grid().unwrap();
    let b = &smoke.initial.regions[0];
    assert!(g.locate(b.x.0, b.y.0).unwrap() != g.locate(b.x.1, b.y.1).unwrap());
}

#[test]
fn the_bands_table_of_the_docs_is_the_code_s() {
    let doc = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/reference/input-validation.md"),
    )
    .unwrap();
    let table = runout_case::limits::bands_table();
    assert!(
        doc.contains(&table),
        "docs/reference/input-validation.md lacks the table of runout_case::limits; it is:\n{table}"
    );
}

#[test]
fn the_wall_fidelity_keeps_the_papers_cells_in_y() {
    let case = load_cases("sensitivity/base.ron").remove(0).case;
    // no `wall` preset written: the coarse preset's x and end time, the paper's y
    assert_eq!(case.fidelity.wall, None);
    let wall = case.at_fidelity(Fidelity::Wall);
    let (g, paper, coarse) = (
        wall.grid().unwrap(),
        case.grid().unwrap(),
        case.at_fidelity(Fidelity::Coarse).grid().unwrap(),
    );
    assert_eq!((g.nx(), g.ny()), (250, 90));
    assert_eq!(g.x, coarse.x);
    assert_eq!(g.y, paper.y);
    assert!((g.y.width_range().0 - 0.005).abs() < 1e-12);
    let tilt = case.scheduled_tilt_time().unwrap();
    assert_eq!(wall.run.end_time, case.fidelity.coarse.end_time + tilt);
    let mut c = wall.clone();
    c.domain = case.domain.clone();
    let resolved = case.clone().with_start_clock();
    c.run.end_time = resolved.run.end_time;
    assert_eq!(c, resolved);
    // an explicit preset with per-axis factors
    let mut written = case.clone();
    written.fidelity.wall = Some(runout_case::Preset {
        coarsen: 2,
        coarsen_y: Some(3),
        end_time: 0.5,
    });
    let g = written.at_fidelity(Fidelity::Wall).grid().unwrap();
    assert_eq!((g.nx(), g.ny()), (500, 30));
    assert_eq!(written.at_fidelity(Fidelity::Wall).run.end_time, 0.5 + tilt);
    // the existing presets and resolved cases are unchanged: nothing new is written
    let text = ron::ser::to_string(&case).unwrap();
    assert!(
        !text.contains("wall:(") && !text.contains("coarsen_y"),
        "{text}"
    );
    assert_eq!("wall".parse::<Fidelity>().unwrap(), Fidelity::Wall);
}

#[test]
fn the_release_study_moves_only_the_block_one_factor_at_a_time() {
    // docs/studies/impact.md §4: nine blocks per floor, each differing from base.ron's in one of
    // length, height, front edge and bottom; everything else is the family's base
    let mut base = runout_case::load_case(&cases_dir().join("sensitivity/base.ron")).unwrap();
    if let runout_case::Gravity::TiltOnImpact { clock, .. } = &mut base.gravity {
        *clock = runout_case::Clock::Start;
    }
    let [block] = base.initial.regions.as_slice() else {
        panic!("base.ron has one release block")
    };
    for file in [
        "release-JEN.ron",
        "release-JJ.ron",
        "release-JEN-t0.ron",
        "release-JJ-t0.ron",
    ] {
        let cases = load_cases(&format!("sensitivity/{file}"));
        assert_eq!(cases.len(), 9, "{file}");
        for c in &cases {
            assert_eq!(c.study.as_deref(), Some("release"), "{}", c.case.name);
            let [r] = c.case.initial.regions.as_slice() else {
                panic!("{}: one block", c.case.name)
            };
            assert_eq!(r.solids, block.solids);
            assert_eq!(r.fill, block.fill);
            let differ = differ_at_round_off;
            let changed = [
                differ(r.x.1 - r.x.0, block.x.1 - block.x.0),
                differ(r.y.1 - r.y.0, block.y.1 - block.y.0),
                differ(r.x.1, block.x.1),
                differ(r.y.0, block.y.0),
            ];
            // a longer block keeps its front edge, so only its length changes
            assert!(
                changed.iter().filter(|&&c| c).count() <= 1,
                "{}: {changed:?}",
                c.case.name
            );
            let mut same = c.case.clone();
            same.initial.regions = base.initial.regions.clone();
            same.name = base.name.clone();
            same.description = base.description.clone();
            same.boundaries = base.boundaries.clone();
            same.solids = base.solids.clone();
            // the -t0 files count the times from the impact (docs/studies/impact.md §4)
            if let runout_case::Gravity::TiltOnImpact { clock, .. } = &mut same.gravity {
                let want = if file.ends_with("-t0.ron") {
                    runout_case::Clock::Impact
                } else {
                    runout_case::Clock::Start
                };
                assert_eq!(*clock, want, "{}", c.case.name);
                *clock = runout_case::Clock::Start;
            }
            assert_eq!(
                same, base,
                "{}: only the block, walls, d and clock differ",
                c.case.name
            );
        }
        let first = &cases[0].case.initial.regions[0];
        assert!(
            [first.x.0, first.x.1, first.y.0, first.y.1]
                .iter()
                .zip([block.x.0, block.x.1, block.y.0, block.y.1])
                .all(|(a, b)| !differ_at_round_off(*a, b)),
            "{file} starts at base"
        );
    }
}

fn differ_at_round_off(a: f64, b: f64) -> bool {
    (a - b).abs() > 1e-12
}

#[test]
fn a_release_needs_exactly_one_block() {
    use runout_case::{Param, ReleaseBlock};
    let mut case = runout_case::load_case(&cases_dir().join("sensitivity/base.ron")).unwrap();
    let release = Param::Release(vec![ReleaseBlock {
        length: 1.0,
        height: 0.1,
        front: 7.0,
        bottom: 0.3,
    }]);
    release.apply(0, &mut case).unwrap();
    assert_eq!(case.initial.regions[0].x, (6.0, 7.0));
    assert_eq!(case.initial.regions[0].y, (0.3, 0.4));
    assert_eq!(release.label(0), "L1-H0.1-F7-B0.3");
    let block = case.initial.regions[0].clone();
    case.initial.regions.push(block);
    let err = release.apply(0, &mut case).unwrap_err();
    assert!(err.contains("2 initial regions"), "{err}");
    case.initial.regions.clear();
    assert!(release.apply(0, &mut case).is_err());
}
