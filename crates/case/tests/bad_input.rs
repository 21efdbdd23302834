//! Bad input is rejected before anything runs, with the file, the field and the allowed
//! range in the message, and never a panic (issue 2).

use std::path::{Path, PathBuf};

use runout_case::{load, CaseError};

fn shipped(rel: &str) -> String {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../cases")
        .join(rel);
    std::fs::read_to_string(p).unwrap()
}

/// Writes `text` to a fresh temporary file and loads it.
fn load_text(name: &str, text: &str) -> (PathBuf, Result<runout_case::Loaded, CaseError>) {
    let dir = std::env::temp_dir().join(format!("runout-case-tests-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    let r = load(&path);
    (path, r)
}

/// Replaces exactly one occurrence (so a test cannot silently edit nothing).
fn replace_once(text: &str, from: &str, to: &str) -> String {
    assert_eq!(text.matches(from).count(), 1, "`{from}` must occur once");
    text.replacen(from, to, 1)
}

fn rejected(name: &str, text: &str, must_contain: &[&str]) {
    let (path, r) = load_text(name, text);
    let err = match r {
        Ok(_) => panic!("{name} was accepted"),
        Err(e) => e.to_string(),
    };
    assert!(
        err.contains(&path.display().to_string()),
        "no file name in: {err}"
    );
    for s in must_contain {
        assert!(err.contains(s), "`{s}` missing in: {err}");
    }
}

fn mslide() -> String {
    shipped("mfix-slope/jj.ron")
}

#[test]
fn negative_diameter() {
    let t = replace_once(&mslide(), "diameter: 5e-4", "diameter: -1e-3");
    rejected(
        "d.ron",
        &t,
        &["solids[0].diameter", "-0.001", "[1e-6, 1] m"],
    );
}

#[test]
fn specularity_above_one() {
    let t = replace_once(&mslide(), "specularity: 0.1", "specularity: 1.5");
    rejected(
        "phi.ron",
        &t,
        &["boundaries.south.solids.specularity", "1.5", "[0, 1]"],
    );
}

#[test]
fn unknown_field() {
    let t = replace_once(
        &mslide(),
        "restitution: 0.9,",
        "restitution: 0.9, colour: 3,",
    );
    rejected("unknown.ron", &t, &["colour", "Solids", "diameter"]);
}

#[test]
fn unknown_boundary_condition() {
    let t = replace_once(
        &mslide(),
        "west: Wall(gas: FreeSlip, solids: FreeSlip)",
        "west: Wall(gas: FreeSlip, solids: Sticky)",
    );
    rejected("bc.ron", &t, &["Sticky", "JohnsonJackson"]);
}

#[test]
fn packing_above_one_and_block_denser_than_packing() {
    let t = replace_once(&mslide(), "max_packing: 0.65", "max_packing: 1.2");
    rejected("pack.ron", &t, &["solids[0].max_packing", "[0.3, 0.9]"]);
    let t = replace_once(&mslide(), "eps_s: 0.6,", "eps_s: 0.7,");
    rejected(
        "block.ron",
        &t,
        &["initial.regions[0].solids[0].eps_s", "[0, 0.65)"],
    );
}

#[test]
fn restitution_and_angles() {
    let t = replace_once(&mslide(), "restitution: 0.9,", "restitution: 1.1,");
    rejected("e.ron", &t, &["solids[0].restitution", "[0, 1]"]);
    let t = replace_once(
        &mslide(),
        "internal_friction_angle: 35.0",
        "internal_friction_angle: 95.0",
    );
    rejected(
        "angle.ron",
        &t,
        &["solids[0].internal_friction_angle", "(0, 90)"],
    );
    let t = replace_once(&mslide(), "slope: 40.0", "slope: 120.0");
    rejected("slope.ron", &t, &["gravity.slope", "[0, 90)"]);
}

#[test]
fn time_step_bounds() {
    let t = replace_once(
        &mslide(),
        "dt: (initial: 1e-4, min: 1e-6, max: 1e-3",
        "dt: (initial: 1e-2, min: 1e-6, max: 1e-3",
    );
    rejected("dt.ron", &t, &["run.dt.initial", "[1e-6, 0.001]"]);
    let t = replace_once(
        &mslide(),
        "dt: (initial: 1e-4, min: 1e-6, max: 1e-3",
        "dt: (initial: 1e-4, min: 1e-2, max: 1e-3",
    );
    rejected("dtmin.ron", &t, &["run.dt.min"]);
    // a smallest step that would no longer advance t near the end time
    let t = replace_once(&mslide(), "end_time: 1.0,", "end_time: 1e6,");
    let t = replace_once(&t, "min: 1e-6,", "min: 1e-4,");
    rejected(
        "dtrel.ron",
        &t,
        &["run.dt.min", ">= 0.001 s (the end time 1e6 s x 1e-9"],
    );
    let t = replace_once(&mslide(), "factor: 0.9", "factor: 0.9, steps_per_change: 0");
    rejected(
        "dtsteps.ron",
        &t,
        &["run.dt.steps_per_change", "an integer in [1, 10000]"],
    );
    let t = replace_once(
        &mslide(),
        "factor: 0.9",
        "factor: 0.9, failure_factor: Some(1.5)",
    );
    rejected("dtfail.ron", &t, &["run.dt.failure_factor", "(0, 1)"]);
}

#[test]
fn block_station_and_gates_inside_domain() {
    let t = replace_once(
        &mslide(),
        "regions: [(x: (0.0, 0.5)",
        "regions: [(x: (3.8, 4.5)",
    );
    rejected("block.ron", &t, &["initial.regions[0].x.1", "[0, 4]"]);
    let flume = shipped("flume/base.ron");
    let t = replace_once(&flume, "gates: [1.65, 2.10,", "gates: [2.10, 1.65,");
    rejected(
        "gates.ron",
        &t,
        &["monitors.front.gates[1]", "strictly increasing"],
    );
    let t = replace_once(&flume, "4.35]", "9.35]");
    rejected("gate_out.ron", &t, &["monitors.front.gates[6]"]);
    let s = shipped("sensitivity/base.ron");
    let t = replace_once(&s, "profiles: [(x: 11.0", "profiles: [(x: 21.0");
    rejected("station.ron", &t, &["monitors.profiles[0].x", "[0, 20]"]);
}

#[test]
fn several_errors_are_all_reported() {
    let t = replace_once(&mslide(), "diameter: 5e-4", "diameter: -1e-3");
    let t = replace_once(&t, "specularity: 0.1", "specularity: 1.5");
    rejected(
        "two.ron",
        &t,
        &["2 invalid fields", "diameter", "specularity"],
    );
}

#[test]
fn syntax_error_has_a_position() {
    let t = replace_once(&mslide(), "density: 2000.0,", "density: 2000.0,,");
    let (path, r) = load_text("syntax.ron", &t);
    let e = r.expect_err("rejected").to_string();
    assert!(e.starts_with(&format!("{}:", path.display())), "{e}");
}

#[test]
fn sweep_that_does_not_apply_is_rejected() {
    let dir = std::env::temp_dir().join(format!("runout-sweep-tests-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("base.ron"), mslide()).unwrap();
    // M-JJ has no user partial-slip wall, so PartialSlipHu has nothing to set
    let sweep = r#"Sweep(name: "X", base: "base.ron", vary: [PartialSlipHu([1.0, 2.0])])"#;
    std::fs::write(dir.join("x.ron"), sweep).unwrap();
    let e = load(&dir.join("x.ron")).expect_err("rejected").to_string();
    assert!(
        e.contains("x.ron") && e.contains("PartialSlipHu") && e.contains("no wall"),
        "{e}"
    );
    // a swept value out of range names the expanded case and the field
    let sweep = r#"Sweep(name: "Y", base: "base.ron", vary: [Specularity([0.5, 2.0])])"#;
    std::fs::write(dir.join("y.ron"), sweep).unwrap();
    let e = load(&dir.join("y.ron")).expect_err("rejected").to_string();
    assert!(
        e.contains("Y_phi=2") && e.contains("specularity") && e.contains("[0, 1]"),
        "{e}"
    );
    // a missing base file names it
    let sweep = r#"Sweep(name: "Z", base: "nope.ron")"#;
    std::fs::write(dir.join("z.ron"), sweep).unwrap();
    let e = load(&dir.join("z.ron")).expect_err("rejected").to_string();
    assert!(e.contains("nope.ron"), "{e}");
}

// ---- issue 21: inputs that hung, crashed or ran to nonsense ----

#[test]
fn intervals_too_small_to_advance_time_are_rejected() {
    let short_form = |name: &str, text: &str, field: &str| {
        let (_, r) = load_text(name, text);
        let e = r.expect_err("rejected").to_string();
        assert!(e.contains(field) && e.contains("= 1e-300"), "{e}");
        assert!(!e.contains("00000000"), "a long decimal in: {e}");
    };
    let t = replace_once(
        &mslide(),
        "output_interval: 0.05",
        "output_interval: 1e-300",
    );
    rejected("out.ron", &t, &["run.output_interval", "[1e-5, 1e7] s"]);
    short_form("out2.ron", &t, "run.output_interval");
    // at most 100 000 field outputs: end time 1 s, so 1e-5 s is the smallest interval
    let t = replace_once(&mslide(), "output_interval: 0.05", "output_interval: 9e-6");
    rejected(
        "out3.ron",
        &t,
        &["run.output_interval", "at most 100000 outputs"],
    );
    let t = replace_once(&mslide(), "output_interval: 0.05", "output_interval: 1e-5");
    load_text("out4.ron", &t)
        .1
        .expect("1e-5 s is 1e5 outputs: accepted");
    let t = replace_once(
        &mslide(),
        "bulk: (interval: 0.01",
        "bulk: (interval: 1e-300",
    );
    short_form("bulk.ron", &t, "monitors.bulk.interval");
    let t = replace_once(
        &mslide(),
        "side: South, interval: 0.005",
        "side: South, interval: 1e-300",
    );
    short_form("probe.ron", &t, "monitors.wall_probes[0].interval");
    let flume = shipped("flume/base.ron");
    let t = replace_once(&flume, "interval: 0.002", "interval: 1e-300");
    short_form("front.ron", &t, "monitors.front.interval");
}

#[test]
fn huge_grids_are_rejected_before_anything_is_allocated() {
    for cells in ["18446744073709551615", "4294967296", "1000000000"] {
        let t = replace_once(&mslide(), "cells: 200)", &format!("cells: {cells})"));
        rejected(
            "cells.ron",
            &t,
            &["domain.x.segments[0].cells", cells, "[1, 1000000]"],
        );
    }
    let flume = shipped("flume/base.ron");
    let first = "EndWidths(length: 0.5, first: 0.05, last: 0.01)";
    let t = replace_once(
        &flume,
        first,
        "EndWidths(length: 1e300, first: 0.05, last: 0.01)",
    );
    rejected("long.ron", &t, &["domain.x.segments[0]", "cells"]);
    let t = replace_once(
        &flume,
        first,
        "EndWidths(length: 0.5, first: 1e-300, last: 1e-300)",
    );
    rejected("tiny.ron", &t, &["domain.x.segments[0]", "cells"]);
    let t = replace_once(
        &flume,
        first,
        "EndWidths(length: 0.5, first: 1e-300, last: 0.01)",
    );
    rejected("tiny_first.ron", &t, &["domain.x"]);
    // each axis within its cap, 1e9 cells in all: ~1.8 TiB for the two-fluid solver
    let t = replace_once(&mslide(), "cells: 200)", "cells: 40000)");
    let t = replace_once(&t, "cells: 50)", "cells: 25000)");
    rejected(
        "big.ron",
        &t,
        &[
            "domain (cells)",
            "40000 x 25000 = 1000000000",
            "at most 10000000 cells",
        ],
    );
}

#[test]
fn physically_impossible_values_name_field_value_and_band() {
    let m = mslide();
    let cases: [(&str, &str, &[&str]); 14] = [
        (
            "Uniform(length: 4.0, cells: 200)",
            "Uniform(length: 1.8e19, cells: 200)",
            &[
                "domain.x.segments (total length)",
                "1.8e19",
                "[0.0001, 100000] m",
            ],
        ),
        (
            "viscosity: 1.8e-5",
            "viscosity: 1e-300",
            &["gas.viscosity", "1e-300", "[1e-7, 1] Pa s"],
        ),
        (
            "diameter: 5e-4",
            "diameter: 1e300",
            &["solids[0].diameter", "1e300", "[1e-6, 1] m"],
        ),
        (
            "density: 2000.0",
            "density: 1e9",
            &["solids[0].density", "[100, 25000] kg/m³"],
        ),
        (
            "density: 1.2",
            "density: 1e-9",
            &["gas.density", "[0.001, 100] kg/m³"],
        ),
        (
            "reference_pressure: 101325.0",
            "reference_pressure: 1e-300",
            &["gas.reference_pressure", "[1, 1e9] Pa"],
        ),
        (
            "Hydrostatic(101325.0)",
            "Hydrostatic(1e12)",
            &["boundaries.north.pressure", "1e12"],
        ),
        (
            "magnitude: 9.81",
            "magnitude: 1e-300",
            &["gravity.magnitude", "[0.01, 1000] m/s²"],
        ),
        (
            "theta: 1e-5,\n",
            "theta: 1e9,\n",
            &["initial.theta", "[0, 10000] m²/s²"],
        ),
        (
            "wall_friction_angle: 11.0)",
            "wall_friction_angle: 11.0, u_w: 1e6)",
            &["boundaries.south.solids.u_w", "[-1000, 1000] m/s"],
        ),
        (
            "Lun1984(alpha: 1.6)",
            "Lun1984(alpha: 1e300)",
            &["models.kinetic_theory.alpha"],
        ),
        (
            "end_time: 1.0,",
            "end_time: 1e300,",
            &["run.end_time", "[1e-6, 1e7] s"],
        ),
        ("min: 1e-6,", "min: 1e-300,", &["run.dt.min", "1e-300"]),
        (
            "residual: 1e-3)",
            "residual: 1e-300)",
            &["run.tolerances.residual"],
        ),
    ];
    for (k, (from, to, want)) in cases.iter().enumerate() {
        let t = replace_once(&m, from, to);
        rejected(&format!("band{k}.ron"), &t, want);
    }
    let s = shipped("sensitivity/base.ron");
    let t = replace_once(
        &s,
        "drag: SyamlalOBrien(c1: 0.8, d1: 2.65)",
        "drag: SyamlalOBrien(c1: 1e-300, d1: 1e300)",
    );
    rejected("drag.ron", &t, &["models.drag.c1", "models.drag.d1"]);
    // a 1e-300 m cell layer next to 0.05 m cells
    let t = replace_once(
        &m,
        "y: (segments: [Uniform(length: 0.5, cells: 50)])",
        "y: (segments: [Uniform(length: 1e-300, cells: 1), Uniform(length: 0.5, cells: 10)])",
    );
    rejected(
        "layer.ron",
        &t,
        &[
            "domain.y (smallest cell width)",
            "1e-300",
            "[1e-7, 100000] m",
        ],
    );
    // a jump from 0.5 mm to 5 cm cells
    let t = replace_once(
        &m,
        "y: (segments: [Uniform(length: 0.5, cells: 50)])",
        "y: (segments: [Uniform(length: 0.3, cells: 600), Uniform(length: 0.5, cells: 10)])",
    );
    rejected(
        "ratio.ron",
        &t,
        &["domain.y (largest adjacent width ratio)", "100", "[1, 50]"],
    );
}

#[test]
fn zero_gravity_is_allowed_but_tiny_gravity_is_not() {
    let t = replace_once(&mslide(), "magnitude: 9.81", "magnitude: 0.0");
    load_text("g0.ron", &t)
        .1
        .expect("no gravity is a valid case");
    let t = replace_once(&mslide(), "magnitude: 9.81", "magnitude: 0.001");
    rejected("g.ron", &t, &["gravity.magnitude", "exactly 0"]);
}

#[test]
fn a_block_at_max_packing_is_rejected() {
    let t = replace_once(&mslide(), "eps_s: 0.6,", "eps_s: 0.65,");
    rejected(
        "packed.ron",
        &t,
        &[
            "initial.regions[0].solids[0].eps_s",
            "0.65",
            "[0, 0.65)",
            "strictly below max_packing",
        ],
    );
    let t = replace_once(&mslide(), "eps_s: 0.6,", "eps_s: 0.6499,");
    load_text("below.ron", &t)
        .1
        .expect("below the limit is accepted");
}

#[test]
fn names_that_leave_the_runs_folder_are_rejected() {
    let long = "a".repeat(101);
    for name in [
        ".",
        "..",
        ".hidden",
        "a/b",
        "..\\\\x",
        "tab\there",
        long.as_str(),
        "",
    ] {
        let t = replace_once(&mslide(), "name: \"M-JJ\"", &format!("name: {name:?}"));
        rejected("name.ron", &t, &["name", "not starting with a dot"]);
    }
    let t = replace_once(
        &mslide(),
        "name: \"M-JJ\"",
        &format!("name: \"{}\"", "a".repeat(100)),
    );
    load_text("name100.ron", &t)
        .1
        .expect("100 bytes is allowed");
    // a sweep named `..` expands to a case named `..`
    let dir = std::env::temp_dir().join(format!("runout-name-tests-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("base.ron"), mslide()).unwrap();
    std::fs::write(
        dir.join("dots.ron"),
        r#"Sweep(name: "..", base: "base.ron")"#,
    )
    .unwrap();
    let e = load(&dir.join("dots.ron"))
        .expect_err("rejected")
        .to_string();
    assert!(e.contains("name") && e.contains("\"..\""), "{e}");
}

/// A fresh folder for one test's files.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("runout-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn a_byte_order_mark_is_accepted() {
    let (_, r) = load_text("bom.ron", &format!("\u{feff}{}", mslide()));
    r.expect("a UTF-8 byte-order mark is skipped");
}

#[test]
fn a_non_utf8_byte_is_reported_with_line_and_offset() {
    let dir = folder("utf8");
    let text = mslide();
    let at = text.find("Family M").unwrap() + "Family ".len();
    let mut bytes = text.as_bytes().to_vec();
    bytes.insert(at, 0xff);
    let path = dir.join("latin1.ron");
    std::fs::write(&path, bytes).unwrap();
    let e = load(&path).expect_err("rejected").to_string();
    let line = 1 + text[..at].matches('\n').count();
    assert!(
        e.contains(&format!(
            "latin1.ron:{line}: byte 0xff at offset {at} is not UTF-8"
        )),
        "{e}"
    );
}

#[test]
fn a_fraction_where_an_integer_is_expected_says_so() {
    for (from, to, want) in [
        (
            "cells: 200)",
            "cells: 2.5)",
            "`cells` = 2.5: expected an integer",
        ),
        (
            "cells: 200)",
            "cells: 2e3)",
            "`cells` = 2e3: expected an integer",
        ),
        (
            "cells: 200)",
            "cells: -3)",
            "`cells` = -3: expected an integer in range",
        ),
        (
            "coarsen: 5,",
            "coarsen: 0.5,",
            "`coarsen` = 0.5: expected an integer",
        ),
        (
            "tolerances: (residual: 1e-3)",
            "tolerances: (residual: 1e-3, max_iterations: 2.5)",
            "`max_iterations` = 2.5: expected an integer",
        ),
    ] {
        let t = replace_once(&mslide(), from, to);
        rejected("int.ron", &t, &[want]);
    }
}

#[test]
fn files_larger_than_1_mib_are_not_read() {
    let padding = format!("// {}\n", "x".repeat(100)).repeat(11_000);
    let (_, r) = load_text("big_comment.ron", &format!("{padding}{}", mslide()));
    let e = r.expect_err("rejected").to_string();
    assert!(
        e.contains("big_comment.ron") && e.contains("at most 1048576 bytes"),
        "{e}"
    );
    // a device with no end is read only up to the limit
    if Path::new("/dev/zero").exists() {
        let e = load(Path::new("/dev/zero"))
            .expect_err("rejected")
            .to_string();
        assert!(
            e.contains("/dev/zero") && e.contains("at most 1048576 bytes"),
            "{e}"
        );
    }
}

#[test]
fn a_sweep_base_must_be_a_ron_file_below_the_sweep_folder() {
    let top = folder("base");
    let dir = top.join("sweeps");
    std::fs::create_dir_all(dir.join("sub")).unwrap();
    std::fs::write(dir.join("sub/base.ron"), mslide()).unwrap();
    std::fs::write(top.join("outside.ron"), mslide()).unwrap();
    std::fs::create_dir_all(dir.join("folder.ron")).unwrap();
    let sweep = |base: &str| {
        std::fs::write(
            dir.join("s.ron"),
            format!(r#"Sweep(name: "S", base: {base:?}, vary: [Slope([30.0, 40.0])])"#),
        )
        .unwrap();
        load(&dir.join("s.ron"))
    };
    let cases = match sweep("sub/base.ron").expect("a base below the folder is accepted") {
        runout_case::Loaded::Cases(c) => c,
        _ => unreachable!(),
    };
    assert_eq!(cases.len(), 2);
    sweep("sub/../sub/base.ron").expect("`..` that stays below is accepted");
    for (base, want) in [
        ("/dev/zero", "a relative path"),
        ("/etc/passwd", "a relative path"),
        ("../outside.ron", "outside the sweep file's folder"),
        ("sub/base.txt", "a `.ron` file"),
        ("folder.ron", "not a regular file"),
        ("", "a relative path"),
    ] {
        let e = sweep(base).expect_err(base).to_string();
        assert!(
            e.contains("s.ron: base: ") && e.contains(want),
            "{base}: {e}"
        );
        assert!(!e.contains("root:"), "{base}: file content echoed: {e}");
    }
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink("/dev/zero", dir.join("zero.ron")).unwrap();
        let e = sweep("zero.ron")
            .expect_err("a link out is refused")
            .to_string();
        assert!(e.contains("outside the sweep file's folder"), "{e}");
    }
}

#[test]
fn sweep_set_values_are_validated_even_when_vary_overrides_them() {
    let dir = folder("set");
    std::fs::write(dir.join("base.ron"), mslide()).unwrap();
    std::fs::write(
        dir.join("s.ron"),
        r#"Sweep(name: "S", base: "base.ron", set: [Slope([NaN])], vary: [Slope([30.0, 40.0])])"#,
    )
    .unwrap();
    let e = load(&dir.join("s.ron")).expect_err("rejected").to_string();
    assert!(
        e.contains("the base with `set` applied") && e.contains("gravity.slope = NaN"),
        "{e}"
    );
}

#[test]
fn a_sweep_of_more_than_1000_cases_is_refused_before_expanding() {
    let dir = folder("many");
    std::fs::write(dir.join("base.ron"), mslide()).unwrap();
    let list = |n: usize, scale: f64| {
        (0..n)
            .map(|k| format!("{:?}", 1.0 + k as f64 * scale))
            .collect::<Vec<_>>()
            .join(", ")
    };
    std::fs::write(
        dir.join("s.ron"),
        format!(
            r#"Sweep(name: "S", base: "base.ron", vary: [Slope([{}]), Diameter([{}]), Specularity([{}])])"#,
            list(11, 1.0),
            list(10, 1e-5),
            list(10, 0.01)
        ),
    )
    .unwrap();
    let e = load(&dir.join("s.ron")).expect_err("rejected").to_string();
    assert!(
        e.contains("at most 1000 cases") && e.contains("11 x 10 x 10"),
        "{e}"
    );
}

fn sensitivity_base() -> String {
    shipped("sensitivity/base.ron")
}

/// The base's gravity with another impact criterion (docs/studies/impact.md).
fn with_criterion(criterion: &str) -> String {
    replace_once(
        &sensitivity_base(),
        "criterion: FreeFall, clock: Impact)",
        &format!("contact_eps_s: 0.01, criterion: {criterion})"),
    )
}

/// The base's gravity with no criterion given (the default, `FloorCell`).
fn default_criterion() -> String {
    replace_once(
        &sensitivity_base(),
        ", criterion: FreeFall, clock: Impact)",
        ")",
    )
}

#[test]
fn impact_criteria_are_accepted_and_bounded() {
    for ok in [
        "FloorCell",
        "DenseContact(fraction: 0.5)",
        "DenseContact(fraction: 1.0)",
        "FreeFall",
        "CentroidDrop",
        "At(time: 0.2856)",
    ] {
        let (_, r) = load_text("criterion-ok.ron", &with_criterion(ok));
        assert!(r.is_ok(), "{ok}: {:?}", r.err());
    }
    rejected(
        "fraction0.ron",
        &with_criterion("DenseContact(fraction: 0.0)"),
        &["gravity.criterion.fraction", "(0, 1]"],
    );
    rejected(
        "fraction2.ron",
        &with_criterion("DenseContact(fraction: 1.5)"),
        &["gravity.criterion.fraction", "1.5", "(0, 1]"],
    );
    rejected(
        "at-late.ron",
        &with_criterion("At(time: 2.0)"),
        &["gravity.criterion.time", "[0, 1.25]"],
    );
    rejected(
        "at-nan.ron",
        &with_criterion("At(time: NaN)"),
        &["gravity.criterion.time", "NaN"],
    );
    rejected(
        "criterion-typo.ron",
        &with_criterion("FreeFal"),
        &["FreeFal", "FloorCell"],
    );
    // the free fall and the dense contact are measured from a release
    for needs in ["FreeFall", "CentroidDrop", "DenseContact(fraction: 0.5)"] {
        let t = replace_once(
            &with_criterion(needs),
            "regions: [(x: (5.0, 5.5), y: (0.40, 0.60), solids: [(eps_s: 0.60, theta: 1e-5)], fill: CoveredFraction)],",
            "regions: [],",
        );
        rejected(
            "no-release.ron",
            &t,
            &["gravity.criterion", "no initial region holds solids"],
        );
    }
}

#[test]
fn a_clock_from_the_impact_needs_a_time_known_before_the_run() {
    for ok in ["FreeFall, clock: Impact", "At(time: 0.3), clock: Impact"] {
        let (_, r) = load_text("clock.ron", &with_criterion(ok));
        assert!(r.is_ok(), "{ok}: {:?}", r.err().map(|e| e.to_string()));
    }
    for field in ["FloorCell", "DenseContact(fraction: 0.5)", "CentroidDrop"] {
        rejected(
            "clock.ron",
            &with_criterion(&format!("{field}, clock: Impact")),
            &["gravity.clock", "Impact", "FreeFall or At(time)"],
        );
    }
}

#[test]
fn the_default_criterion_is_not_written_so_resolved_cases_are_unchanged() {
    let Ok(runout_case::Loaded::Cases(cases)) = load_text("base.ron", &default_criterion()).1
    else {
        panic!("the base loads")
    };
    let text = ron::ser::to_string(&cases[0].case).unwrap();
    assert!(!text.contains("criterion"), "{text}");
    let Ok(runout_case::Loaded::Cases(cases)) =
        load_text("free.ron", &with_criterion("FreeFall")).1
    else {
        panic!("the free-fall case loads")
    };
    let text = ron::ser::to_string(&cases[0].case).unwrap();
    assert!(text.contains("criterion:FreeFall"), "{text}");
}

#[test]
fn per_axis_coarsening_is_bounded() {
    let base = sensitivity_base();
    let ok = replace_once(
        &base,
        "coarse: (coarsen: 4, end_time: 1.25),",
        "coarse: (coarsen: 4, end_time: 1.25),\n        wall: (coarsen: 4, coarsen_y: 2, end_time: 0.5),",
    );
    let (_, r) = load_text("wall-ok.ron", &ok);
    assert!(r.is_ok(), "{:?}", r.err());
    rejected(
        "coarsen-y0.ron",
        &replace_once(&ok, "coarsen_y: 2", "coarsen_y: 0"),
        &["fidelity.wall.coarsen_y", ">= 1"],
    );
    rejected(
        "wall-late.ron",
        &replace_once(
            &ok,
            "coarsen_y: 2, end_time: 0.5",
            "coarsen_y: 2, end_time: 5.0",
        ),
        &["fidelity.wall.end_time"],
    );
    rejected(
        "smoke-y0.ron",
        &replace_once(
            &base,
            "smoke: (coarsen: 10, end_time: 0.4)",
            "smoke: (coarsen: 10, coarsen_y: 0, end_time: 0.4)",
        ),
        &["fidelity.smoke.coarsen_y"],
    );
}

/// μ(I) input: μ_2 ≤ μ_s, I_0 ≤ 0, a negative or NaN value and an unknown parameter are each
/// refused with the field named (issue 43 item 6); a well-formed μ(I) case loads.
#[test]
fn mu_i_parameters_out_of_range() {
    let with = |law: &str| replace_once(&mslide(), "friction: Princeton", law);
    let ok = with("friction: MuI(mu_s: 0.38, mu_2: 0.64, i_0: 0.28)");
    if let Err(e) = load_text("mui-ok.ron", &ok).1 {
        panic!("{e}");
    }
    rejected(
        "mui-order.ron",
        &with("friction: MuI(mu_s: 0.5, mu_2: 0.4, i_0: 0.28)"),
        &["models.friction.MuI.mu_2", "0.4", "(0.5, 2]"],
    );
    rejected(
        "mui-i0.ron",
        &with("friction: MuI(mu_s: 0.38, mu_2: 0.64, i_0: 0.0)"),
        &["models.friction.MuI.i_0", "[0.001, 10]"],
    );
    rejected(
        "mui-neg.ron",
        &with("friction: MuI(mu_s: -0.38, mu_2: 0.64, i_0: 0.28)"),
        &["models.friction.MuI.mu_s", "-0.38"],
    );
    rejected(
        "mui-nan.ron",
        &with("friction: MuI(mu_s: 0.38, mu_2: NaN, i_0: 0.28)"),
        &["models.friction.MuI.mu_2", "NaN"],
    );
    rejected(
        "mui-floor.ron",
        &with("friction: MuI(mu_s: 0.38, mu_2: 0.64, i_0: 0.28, shear_rate_floor: 10.0)"),
        &["models.friction.MuI.shear_rate_floor", "[1e-8, 1] 1/s"],
    );
    rejected(
        "mui-unknown.ron",
        &with("friction: MuI(mu_s: 0.38, mu_2: 0.64, i_0: 0.28, mu_3: 1.0)"),
        &["mu_3"],
    );
}

/// `run.stop_at_rest`: a duration beyond the end time and a speed of 0 are refused.
#[test]
fn stop_at_rest_out_of_range() {
    let with = |rule: &str| {
        let t = mslide();
        let at = t
            .find("output_interval")
            .expect("the case has an output interval");
        format!("{}stop_at_rest: {rule}, {}", &t[..at], &t[at..])
    };
    rejected(
        "rest-duration.ron",
        &with("(speed: 0.01, duration: 100.0)"),
        &["run.stop_at_rest.duration", "100"],
    );
    rejected(
        "rest-speed.ron",
        &with("(speed: 0.0, duration: 0.1)"),
        &["run.stop_at_rest.speed"],
    );
}
