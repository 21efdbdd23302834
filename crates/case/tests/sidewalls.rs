//! The `sidewalls` option (docs/model.md §8, issue 23): a bad width or solids condition is
//! rejected before anything runs, naming the file, the field `sidewalls.*` and the allowed
//! range; a good one loads, and the sweep parameters reach the side walls.

use std::path::{Path, PathBuf};

use runout_case::{load, CaseError, Loaded, SolidsWall};

fn shipped(rel: &str) -> String {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../cases")
        .join(rel);
    std::fs::read_to_string(p).unwrap()
}

/// `cases/mfix-slope/jj.ron` with `sidewalls` set to `value`.
fn with_sidewalls(value: &str) -> String {
    let text = shipped("mfix-slope/jj.ron");
    assert_eq!(text.matches("    initial: (").count(), 1);
    text.replacen(
        "    initial: (",
        &format!("    sidewalls: {value},\n    initial: ("),
        1,
    )
}

fn load_text(name: &str, text: &str) -> (PathBuf, Result<Loaded, CaseError>) {
    let dir = std::env::temp_dir().join(format!("runout-sidewalls-tests-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    let r = load(&path);
    (path, r)
}

fn rejected(name: &str, text: &str, must_contain: &[&str]) {
    let (path, r) = load_text(name, text);
    let err = match r {
        Ok(_) => panic!("{name} was accepted"),
        Err(e) => e.to_string(),
    };
    assert!(err.contains(&path.display().to_string()), "{err}");
    for s in must_contain {
        assert!(err.contains(s), "`{s}` missing in: {err}");
    }
}

const JENKINS: &str = "Jenkins(wall_restitution: 0.7, wall_friction_angle: 11.0)";

#[test]
fn a_width_that_is_not_positive_and_finite_is_rejected() {
    for (file, width, shown) in [
        ("zero.ron", "0.0", "sidewalls.width = 0"),
        ("negative.ron", "-0.3", "sidewalls.width = -0.3"),
        ("nan.ron", "NaN", "sidewalls.width = NaN"),
        ("inf.ron", "inf", "sidewalls.width = inf"),
    ] {
        let t = with_sidewalls(&format!(
            "Some((width: {width}, solids: {JENKINS}, gas: NoSlip))"
        ));
        rejected(file, &t, &[shown, "allowed (0, inf)"]);
    }
}

#[test]
fn the_solids_condition_is_validated_as_the_floors() {
    let t = with_sidewalls(
        "Some((width: 0.3, solids: JohnsonJackson(specularity: 1.5, wall_restitution: 1.2, \
         wall_friction_angle: 95.0), gas: FreeSlip))",
    );
    rejected(
        "jj.ron",
        &t,
        &[
            "sidewalls.solids.specularity = 1.5",
            "sidewalls.solids.wall_restitution = 1.2",
            "sidewalls.solids.wall_friction_angle = 95",
            "[0, 1]",
        ],
    );
    let t = with_sidewalls(
        "Some((width: 0.3, solids: PartialSlip(h_u: -1.0, h_theta: 1.0, theta_w: 0.01, c: 0.1), \
         gas: NoSlip))",
    );
    rejected("ps.ron", &t, &["sidewalls.solids.h_u = -1"]);
    // the side walls are at rest
    let t = with_sidewalls(
        "Some((width: 0.3, solids: Jenkins(wall_restitution: 0.7, wall_friction_angle: 11.0, \
         u_w: 1.0), gas: NoSlip))",
    );
    rejected(
        "moving.ron",
        &t,
        &["sidewalls.solids.u_w = 1", "0 (the side walls are at rest)"],
    );
    // a Coulomb wall's friction and regularisation
    let t = with_sidewalls(
        "Some((width: 0.1, solids: Coulomb(friction: -0.2, slip_floor: 0.0), gas: NoSlip))",
    );
    rejected(
        "coulomb.ron",
        &t,
        &[
            "sidewalls.solids.friction = -0.2",
            "[0, 10]",
            "sidewalls.solids.slip_floor = 0",
            "(0, 1] m/s",
        ],
    );
    // an unknown gas condition is a parse error naming the variants
    let t = with_sidewalls(&format!(
        "Some((width: 0.3, solids: {JENKINS}, gas: PartialSlip))"
    ));
    rejected("gas.ron", &t, &["NoSlip", "FreeSlip"]);
}

#[test]
fn good_side_walls_load_and_none_is_the_default() {
    let t = with_sidewalls(&format!(
        "Some((width: 0.3, solids: {JENKINS}, gas: NoSlip))"
    ));
    let (_, r) = load_text("good.ron", &t);
    let Loaded::Cases(cases) = r.unwrap() else {
        panic!("not a case")
    };
    let walls = cases[0].case.sidewalls.as_ref().unwrap();
    assert_eq!(walls.width, 0.3);
    // a Coulomb floor loads too (docs/model.md §3.11)
    let text = shipped("mfix-slope/jj.ron");
    let floor = text.find("south: Wall(").expect("a floor");
    let solids = floor + text[floor..].find("solids: ").unwrap() + "solids: ".len();
    let end = solids + text[solids..].find(")),").unwrap() + 1;
    let t = format!("{}Coulomb(friction: 0.4){}", &text[..solids], &text[end..]);
    let (_, r) = load_text("coulomb-floor.ron", &t);
    assert!(r.is_ok(), "{:?}", r.err());
    let t = with_sidewalls("Some((width: 0.1, solids: Coulomb(friction: 0.4), gas: NoSlip))");
    let (_, r) = load_text("coulomb-good.ron", &t);
    let Loaded::Cases(cases) = r.unwrap() else {
        panic!("not a case")
    };
    let walls = cases[0].case.sidewalls.as_ref().unwrap();
    assert_eq!(
        walls.solids,
        SolidsWall::Coulomb {
            friction: 0.4,
            slip_floor: None
        }
    );
    let (_, r) = load_text("plain.ron", &shipped("mfix-slope/jj.ron"));
    let Loaded::Cases(cases) = r.unwrap() else {
        panic!("not a case")
    };
    assert!(cases[0].case.sidewalls.is_none());
}

/// The flume's side-wall sweeps: φ reaches the side walls too, `SolidsWalls` leaves them.
#[test]
fn the_flume_sweeps_give_the_side_walls_the_floors_condition() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/flume");
    let Loaded::Cases(cases) = load(&root.join("FSW-JJ.ron")).unwrap() else {
        panic!("not a sweep")
    };
    let names: Vec<&str> = cases.iter().map(|c| c.case.name.as_str()).collect();
    assert_eq!(names, ["FSW-JJ_phi=0.1", "FSW-JJ_phi=0.01"]);
    for (c, phi) in cases.iter().zip([0.1, 0.01]) {
        let walls = c.case.sidewalls.as_ref().unwrap();
        assert_eq!(walls.width, 0.30);
        let SolidsWall::JohnsonJackson { specularity, .. } = walls.solids else {
            panic!("{:?}", walls.solids)
        };
        assert_eq!(specularity, phi);
        let runout_case::Boundary::Wall { solids, .. } = &c.case.boundaries.south else {
            panic!()
        };
        assert_eq!(solids, &walls.solids);
    }
    for file in ["FSW-JEN.ron", "FSW-RJJ.ron"] {
        let Loaded::Cases(cases) = load(&root.join(file)).unwrap() else {
            panic!()
        };
        let c = &cases[0].case;
        let runout_case::Boundary::Wall { solids, .. } = &c.boundaries.south else {
            panic!()
        };
        assert_eq!(solids, &c.sidewalls.as_ref().unwrap().solids);
    }
}
