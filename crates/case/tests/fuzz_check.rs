//! Fuzz test of the path `runout check` takes (issue 21 item 4): mutants of every shipped
//! case, sweep and analytic file go through [`runout_case::load`] and, when accepted, the
//! per-fidelity sizes `check` prints. It asserts that no input panics, aborts or hangs
//! (each runs on its own thread with a deadline), that every rejection is a clean error
//! naming the file with numbers in short form, and that every accepted file is physically
//! plausible: the bands of `runout_case::limits` are checked again here, independently of
//! the validation code, on the accepted cases and their built grids.
//!
//! Mutations: a number set to 0, negative, tiny, huge, NaN, ±inf, fractional, 2^64 − 1, a
//! random bit pattern or a near copy; a field deleted or duplicated; an identifier
//! misspelt or swapped for another; a string replaced (`..`, `/dev/zero`, a long name);
//! a line deleted or duplicated; truncation; byte flips; invalid UTF-8 and a byte-order
//! mark. One to three of them per input.
//!
//! The fast version (500 inputs, a second or two) runs with the normal tests. The long one:
//!
//! ```text
//! RUNOUT_FUZZ_CASES=20000 cargo test --release -p runout-case --test fuzz_check -- --ignored --nocapture
//! ```
//!
//! (`RUNOUT_FUZZ_SEED` picks another deterministic sequence.) Both print their figures and
//! write them to `target/tmp/fuzz_check_<inputs>.txt`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use proptest::prelude::Rng;
use proptest::test_runner::{RngAlgorithm, TestRng};
use runout_case::limits::*;
use runout_case::{
    case_size, estimated_memory_bytes, load, run_dir, Analytic, Boundary, Case, CaseError, Drag,
    Fidelity, GasWall, Gravity, InitialPressure, KineticTheory, Loaded, OutletPressure, SolidsWall,
};

/// Longest time one input may take on a shared 2-core machine before it counts as a hang.
const DEADLINE: Duration = Duration::from_secs(20);

/// One shipped file: its family folder and its text.
struct Seed {
    family: String,
    name: String,
    text: String,
}

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn seeds() -> Vec<Seed> {
    let mut out = Vec::new();
    let mut folders: Vec<PathBuf> = std::fs::read_dir(repo().join("cases"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.is_dir())
        .collect();
    folders.push(repo().join("examples"));
    folders.sort();
    for dir in folders {
        let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "ron"))
            .collect();
        files.sort();
        for f in files {
            out.push(Seed {
                family: dir.file_name().unwrap().to_string_lossy().into(),
                name: f.file_name().unwrap().to_string_lossy().into(),
                text: std::fs::read_to_string(&f).unwrap(),
            });
        }
    }
    assert!(out.len() >= 30, "{} seeds", out.len());
    out
}

/// A scratch copy of every family folder, so that a mutated sweep finds its base.
fn scratch(seeds: &[Seed]) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("fuzz-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    for s in seeds {
        let family = dir.join(&s.family);
        std::fs::create_dir_all(&family).unwrap();
        std::fs::write(family.join(&s.name), &s.text).unwrap();
    }
    dir
}

// ---- mutations ----

fn pick(rng: &mut TestRng, n: usize) -> usize {
    (rng.next_u64() % n.max(1) as u64) as usize
}

/// Byte ranges of `text` that are code (not comments, not inside strings), and the string
/// literals' contents.
struct Scan {
    code: Vec<bool>,
    strings: Vec<(usize, usize)>,
}

fn scan(text: &str) -> Scan {
    let b = text.as_bytes();
    let mut code = vec![false; b.len()];
    let mut strings = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i..].starts_with(b"//") {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i..].starts_with(b"/*") {
            i += 2;
            while i < b.len() && !b[i..].starts_with(b"*/") {
                i += 1;
            }
            i += 2;
        } else if b[i] == b'"' {
            let start = i + 1;
            i += 1;
            while i < b.len() && b[i] != b'"' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            strings.push((start, i.min(b.len())));
            i += 1;
        } else {
            code[i] = true;
            i += 1;
        }
    }
    Scan { code, strings }
}

fn ident_byte(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_'
}

/// Byte spans of number literals in code.
fn numbers(text: &str, s: &Scan) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let starts = s.code[i]
            && b[i].is_ascii_digit()
            && (i == 0 || !(ident_byte(b[i - 1]) || b[i - 1] == b'.'));
        if !starts {
            i += 1;
            continue;
        }
        let start = if i > 0 && b[i - 1] == b'-' { i - 1 } else { i };
        let mut j = i;
        while j < b.len()
            && (b[j].is_ascii_digit()
                || b[j] == b'.'
                || b[j] == b'_'
                || b[j] == b'e'
                || b[j] == b'E'
                || ((b[j] == b'-' || b[j] == b'+') && (b[j - 1] == b'e' || b[j - 1] == b'E')))
        {
            j += 1;
        }
        out.push((start, j));
        i = j;
    }
    out
}

/// Byte spans of identifiers in code.
fn identifiers(text: &str, s: &Scan) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if s.code[i] && b[i].is_ascii_alphabetic() && (i == 0 || !ident_byte(b[i - 1])) {
            let mut j = i;
            while j < b.len() && ident_byte(b[j]) {
                j += 1;
            }
            out.push((i, j));
            i = j;
        } else {
            i += 1;
        }
    }
    out
}

/// Byte spans `name: value,` of the fields in code (the value up to the next comma or
/// closing bracket at its own depth, the comma included).
fn fields(text: &str, s: &Scan) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    for (start, end) in identifiers(text, s) {
        let mut k = end;
        while k < b.len() && b[k] == b' ' {
            k += 1;
        }
        if k >= b.len() || b[k] != b':' {
            continue;
        }
        let mut depth = 0i32;
        let mut j = k + 1;
        while j < b.len() {
            if s.code[j] {
                match b[j] {
                    b'(' | b'[' | b'{' => depth += 1,
                    b')' | b']' | b'}' if depth == 0 => break,
                    b')' | b']' | b'}' => depth -= 1,
                    b',' if depth == 0 => {
                        j += 1;
                        break;
                    }
                    _ => {}
                }
            }
            j += 1;
        }
        out.push((start, j.min(b.len())));
    }
    out
}

fn special_number(rng: &mut TestRng, orig: &str) -> String {
    const VALUES: [&str; 26] = [
        "0",
        "0.0",
        "-0.0",
        "-1",
        "-1e-3",
        "1e-300",
        "-1e-300",
        "1e300",
        "-1e300",
        "1e-30",
        "1e30",
        "NaN",
        "inf",
        "-inf",
        "2.5",
        "0.5",
        "1",
        "18446744073709551615",
        "4294967296",
        "1000000000",
        "1e6",
        "1e-6",
        "1e-9",
        "1e9",
        "0.65",
        "1e-7",
    ];
    match pick(rng, 8) {
        0 => format!("-{}", orig.trim_start_matches('-')),
        1 => format!("{orig}e3"),
        2 => format!("{orig}e-3"),
        3 => {
            let v = f64::from_bits(rng.next_u64());
            if pick(rng, 2) == 0 {
                format!("{v:e}")
            } else {
                format!("{v:?}")
            }
        }
        4 => {
            // a near copy: just inside or outside a band edge
            let v: f64 = orig.replace('_', "").parse().unwrap_or(1.0);
            format!("{:e}", v * (1.0 + (pick(rng, 3) as f64 - 1.0) * 1e-9))
        }
        _ => VALUES[pick(rng, VALUES.len())].to_string(),
    }
}

fn special_string(rng: &mut TestRng) -> String {
    let long = "n".repeat(101);
    let values = [
        ".",
        "..",
        ".hidden",
        "a/b",
        "/dev/zero",
        "../base.ron",
        "base.ron",
        "",
        "x\ty",
        "sub/../base.ron",
        "/etc/passwd",
        "nope.ron",
        long.as_str(),
        "ok-name",
    ];
    values[pick(rng, values.len())].to_string()
}

/// One text-level mutation of `text` (which stays UTF-8).
fn mutate_text(rng: &mut TestRng, text: &str) -> String {
    let s = scan(text);
    let splice = |range: (usize, usize), with: &str| {
        format!("{}{with}{}", &text[..range.0], &text[range.1..])
    };
    // numbers most often: they reach validation, the other mutations mostly the parser
    match pick(rng, 14) {
        0..=7 => {
            let nums = numbers(text, &s);
            if nums.is_empty() {
                return text.to_string();
            }
            let r = nums[pick(rng, nums.len())];
            let value = special_number(rng, &text[r.0..r.1]);
            splice(r, &value)
        }
        8 => {
            let f = fields(text, &s);
            if f.is_empty() {
                return text.to_string();
            }
            splice(f[pick(rng, f.len())], "")
        }
        9 => {
            let f = fields(text, &s);
            if f.is_empty() {
                return text.to_string();
            }
            let r = f[pick(rng, f.len())];
            let copy = &text[r.0..r.1];
            let sep = if copy.trim_end().ends_with(',') {
                " "
            } else {
                ", "
            };
            format!("{}{copy}{sep}{}", &text[..r.1], &text[r.1..])
        }
        10 => {
            let ids = identifiers(text, &s);
            if ids.is_empty() {
                return text.to_string();
            }
            let r = ids[pick(rng, ids.len())];
            let word = &text[r.0..r.1];
            let mut chars: Vec<char> = word.chars().collect();
            match pick(rng, 4) {
                0 if chars.len() > 1 => {
                    chars.remove(pick(rng, chars.len()));
                }
                1 if chars.len() > 1 => {
                    let k = pick(rng, chars.len() - 1);
                    chars.swap(k, k + 1);
                }
                2 => chars.insert(pick(rng, chars.len() + 1), 'x'),
                _ => {
                    let k = pick(rng, chars.len());
                    chars[k] = if chars[k].is_uppercase() {
                        chars[k].to_ascii_lowercase()
                    } else {
                        chars[k].to_ascii_uppercase()
                    };
                }
            }
            splice(r, &chars.into_iter().collect::<String>())
        }
        11 => {
            let ids = identifiers(text, &s);
            if ids.is_empty() {
                return text.to_string();
            }
            let a = ids[pick(rng, ids.len())];
            let b = ids[pick(rng, ids.len())];
            splice(a, &text[b.0..b.1])
        }
        12 => {
            if s.strings.is_empty() {
                return text.to_string();
            }
            let r = s.strings[pick(rng, s.strings.len())];
            splice(r, &special_string(rng))
        }
        _ => {
            let lines: Vec<&str> = text.split_inclusive('\n').collect();
            let k = pick(rng, lines.len());
            let mut out = String::new();
            for (i, l) in lines.iter().enumerate() {
                if i != k || pick(rng, 2) == 0 {
                    out.push_str(l);
                }
                if i == k {
                    out.push_str(l);
                }
            }
            out
        }
    }
}

/// One byte-level mutation (which may leave the text invalid UTF-8).
fn mutate_bytes(rng: &mut TestRng, mut bytes: Vec<u8>) -> Vec<u8> {
    match pick(rng, 4) {
        0 => {
            let at = pick(rng, bytes.len() + 1);
            bytes.truncate(at);
        }
        1 => {
            for _ in 0..1 + pick(rng, 4) {
                if !bytes.is_empty() {
                    let k = pick(rng, bytes.len());
                    bytes[k] ^= 1 + pick(rng, 255) as u8;
                }
            }
        }
        2 => {
            let bad: [&[u8]; 4] = [b"\xff", b"\xc3", b"\x80", b"\xed\xa0\x80"];
            let at = pick(rng, bytes.len() + 1);
            bytes.splice(at..at, bad[pick(rng, bad.len())].iter().copied());
        }
        _ => {
            bytes.splice(0..0, b"\xEF\xBB\xBF".iter().copied());
        }
    }
    bytes
}

fn mutant(rng: &mut TestRng, seed: &Seed) -> Vec<u8> {
    let mut text = seed.text.clone();
    for _ in 0..1 + pick(rng, 3) {
        text = mutate_text(rng, &text);
    }
    let bytes = text.into_bytes();
    if pick(rng, 4) == 0 {
        mutate_bytes(rng, bytes)
    } else {
        bytes
    }
}

// ---- the independent plausibility check of an accepted file ----

fn in_band(out: &mut Vec<String>, field: &str, v: f64, b: &Band) {
    if !(v >= b.lo && v <= b.hi) {
        out.push(format!("{field} = {v:e} outside {}", b.what));
    }
}

fn interval_ok(out: &mut Vec<String>, field: &str, v: f64, end: f64, count: f64) {
    if !(v >= MIN_INTERVAL && v * count >= end * (1.0 - 1e-12) && v <= TIME.hi) {
        out.push(format!("{field} = {v:e} too small for end time {end:e}"));
    }
}

/// What is implausible about an accepted case, by the bands alone.
fn case_violations(case: &Case) -> Vec<String> {
    let mut v = Vec::new();
    let out = &mut v;
    if run_dir(Path::new("/r"), &case.name, Fidelity::Paper).is_err() {
        out.push(format!("name {:?}", case.name));
    }
    if let Some(g) = &case.gas {
        in_band(out, "gas.density", g.density, &GAS_DENSITY);
        in_band(out, "gas.viscosity", g.viscosity, &GAS_VISCOSITY);
        in_band(
            out,
            "gas.reference_pressure",
            g.reference_pressure,
            &PRESSURE,
        );
    }
    if case.solids.len() > MAX_SOLIDS_PHASES {
        out.push("too many phases".into());
    }
    for s in &case.solids {
        in_band(out, "diameter", s.diameter, &DIAMETER);
        in_band(out, "density", s.density, &PARTICLE_DENSITY);
        in_band(out, "max_packing", s.max_packing, &MAX_PACKING);
        if !(s.restitution >= 0.0 && s.restitution <= 1.0) {
            out.push("restitution".into());
        }
    }
    if let KineticTheory::Lun1984 { alpha } = case.models.kinetic_theory {
        in_band(out, "alpha", alpha, &KT_ALPHA);
    }
    if let Drag::SyamlalOBrien { c1, d1 } = case.models.drag {
        in_band(out, "c1", c1, &DRAG_C1);
        in_band(out, "d1", d1, &DRAG_D1);
    }
    for (_, b) in case.boundaries.iter() {
        match b {
            Boundary::PressureOutlet {
                pressure: OutletPressure::Uniform(p) | OutletPressure::Hydrostatic(p),
            } => in_band(out, "outlet pressure", *p, &PRESSURE),
            Boundary::Wall { gas, solids } => {
                match gas {
                    GasWall::Moving { u_w } => in_band(out, "gas u_w", *u_w, &VELOCITY),
                    GasWall::PartialSlip { h_u, u_w } => {
                        in_band(out, "gas h_u", *h_u, &SLIP_COEFFICIENT);
                        in_band(out, "gas u_w", *u_w, &VELOCITY);
                    }
                    GasWall::NoSlip | GasWall::FreeSlip => {}
                }
                match solids {
                    SolidsWall::PartialSlip {
                        h_u,
                        u_w,
                        h_theta,
                        theta_w,
                        c,
                    } => {
                        in_band(out, "h_u", *h_u, &SLIP_COEFFICIENT);
                        in_band(out, "u_w", *u_w, &VELOCITY);
                        in_band(out, "h_theta", *h_theta, &SLIP_COEFFICIENT);
                        in_band(out, "theta_w", *theta_w, &THETA);
                        in_band(out, "c", *c, &THETA_FLUX);
                    }
                    SolidsWall::JohnsonJackson { u_w, .. }
                    | SolidsWall::RevisitedJohnsonJackson { u_w, .. }
                    | SolidsWall::Jenkins { u_w, .. } => in_band(out, "u_w", *u_w, &VELOCITY),
                    SolidsWall::NoSlip | SolidsWall::FreeSlip | SolidsWall::Coulomb { .. } => {}
                }
            }
        }
    }
    in_band(out, "initial.theta", case.initial.theta, &THETA);
    in_band(out, "gas u0", case.initial.gas_velocity.0, &VELOCITY);
    in_band(out, "gas v0", case.initial.gas_velocity.1, &VELOCITY);
    if let InitialPressure::Uniform(p) = case.initial.gas_pressure {
        in_band(out, "initial pressure", p, &PRESSURE);
    }
    for block in &case.initial.regions {
        for (bs, phase) in block.solids.iter().zip(&case.solids) {
            if !(bs.eps_s >= 0.0 && bs.eps_s < phase.max_packing) {
                out.push(format!(
                    "block eps_s {} at max_packing {}",
                    bs.eps_s, phase.max_packing
                ));
            }
            in_band(out, "block u", bs.velocity.0, &VELOCITY);
            in_band(out, "block v", bs.velocity.1, &VELOCITY);
            in_band(out, "block theta", bs.theta, &THETA);
        }
    }
    let (Gravity::Constant { magnitude, .. } | Gravity::TiltOnImpact { magnitude, .. }) =
        case.gravity;
    if magnitude != 0.0 {
        in_band(out, "|g|", magnitude, &GRAVITY);
    }
    let run = &case.run;
    let end = run.end_time;
    in_band(out, "end_time", end, &TIME);
    for (f, dt) in [
        ("dt.min", run.dt.min),
        ("dt.max", run.dt.max),
        ("dt.initial", run.dt.initial),
    ] {
        in_band(out, f, dt, &TIME_STEP);
    }
    if run.dt.min < end * DT_MIN_PER_END_TIME {
        out.push("dt.min below end time x 1e-9".into());
    }
    in_band(out, "residual", run.tolerances.residual, &TOLERANCE);
    in_band(
        out,
        "theta_residual",
        run.tolerances.theta_residual,
        &TOLERANCE,
    );
    if u64::from(run.tolerances.max_iterations) > MAX_ITERATIONS
        || run.dt.steps_per_change as u64 > MAX_ITERATIONS
    {
        out.push("iterations".into());
    }
    interval_ok(
        out,
        "output_interval",
        run.output_interval,
        end,
        MAX_OUTPUTS,
    );
    if let Some(b) = &case.monitors.bulk {
        interval_ok(out, "bulk.interval", b.interval, end, MAX_SAMPLES);
    }
    if let Some(f) = &case.monitors.front {
        interval_ok(out, "front.interval", f.interval, end, MAX_SAMPLES);
    }
    for p in &case.monitors.wall_probes {
        interval_ok(out, "probe.interval", p.interval, end, MAX_SAMPLES);
    }
    if case.monitors.wall_probes.len() > MAX_WALL_PROBES {
        out.push("too many probes".into());
    }
    let r = &case.numerics.relaxation;
    for x in [r.pressure, r.eps_s, r.velocity, r.theta, r.wall_closures] {
        in_band(out, "relaxation", x, &RELAXATION);
    }
    for axis in [&case.domain.x, &case.domain.y] {
        in_band(out, "origin", axis.origin, &COORDINATE);
        let length: f64 = axis.segments.iter().map(|s| s.length()).sum();
        in_band(out, "domain length", length, &DOMAIN_LENGTH);
    }
    // every fidelity: the size `check` prints, then the built grid's widths
    for f in [Fidelity::Smoke, Fidelity::Coarse, Fidelity::Paper] {
        let c = case.at_fidelity(f);
        in_band(out, "preset end time", c.run.end_time, &TIME);
        let Ok(size) = case_size(&c) else {
            out.push(format!("{f}: no size"));
            continue;
        };
        if size.cells > MAX_CELLS as u64 || estimated_memory_bytes(&c) == u64::MAX {
            out.push(format!("{f}: {} cells", size.cells));
            continue;
        }
        match c.grid() {
            Ok(g) => {
                for axis in [&g.x, &g.y] {
                    in_band(out, "smallest width", axis.width_range().0, &CELL_WIDTH);
                    if f == Fidelity::Paper {
                        let ratio = axis.max_adjacent_ratio();
                        in_band(out, "width ratio", ratio, &ADJACENT_WIDTH_RATIO);
                    }
                }
                if (g.nx() * g.ny()) as u64 != size.cells {
                    out.push(format!(
                        "{f}: size {} but grid {}",
                        size.cells,
                        g.nx() * g.ny()
                    ));
                }
            }
            Err(e) => out.push(format!("{f}: grid does not build: {e}")),
        }
    }
    v
}

fn analytic_violations(a: &Analytic) -> Vec<String> {
    let mut v = Vec::new();
    let out = &mut v;
    in_band(out, "depth", a.depth, &DOMAIN_LENGTH);
    in_band(out, "bulk", a.velocity.bulk, &VELOCITY);
    in_band(out, "wall", a.velocity.wall, &VELOCITY);
    in_band(out, "theta bulk", a.temperature.bulk, &THETA);
    in_band(out, "theta wall", a.temperature.wall, &THETA);
    for h in a.velocity.h_u.iter().chain(&a.temperature.h_theta) {
        in_band(out, "h", *h, &SLIP_COEFFICIENT);
    }
    for c in &a.temperature.c {
        in_band(out, "c", *c, &THETA_FLUX);
    }
    v
}

// ---- one input ----

enum Outcome {
    /// accepted: the number of cases and what is implausible about them
    Accepted(usize, Vec<String>),
    /// rejected: the error's kind and message
    Rejected(&'static str, String),
    Panicked(String),
}

fn kind(e: &CaseError) -> &'static str {
    match e {
        CaseError::Io { .. } => "io",
        CaseError::TooLarge { .. } => "too large",
        CaseError::Encoding { .. } => "encoding",
        CaseError::Parse { .. } => "parse",
        CaseError::Kind { .. } => "file kind",
        CaseError::Invalid { .. } => "invalid field",
        CaseError::Sweep { .. } => "sweep",
    }
}

/// What `runout check` does with one file: load, and for each case the sizes it prints.
fn check(path: &Path) -> Outcome {
    let result = std::panic::catch_unwind(|| match load(path) {
        Ok(Loaded::Cases(cases)) => {
            let bad: Vec<String> = cases
                .iter()
                .flat_map(|sc| case_violations(&sc.case))
                .collect();
            Outcome::Accepted(cases.len(), bad)
        }
        Ok(Loaded::Analytic(a)) => Outcome::Accepted(1, analytic_violations(&a)),
        Err(e) => Outcome::Rejected(kind(&e), e.to_string()),
    });
    result.unwrap_or_else(|p| {
        let msg = p
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default();
        Outcome::Panicked(msg)
    })
}

/// The longest run of decimal digits in `s` (a long-decimal bound has hundreds).
fn longest_digit_run(s: &str) -> usize {
    s.split(|c: char| !c.is_ascii_digit())
        .map(str::len)
        .max()
        .unwrap_or(0)
}

#[derive(Default)]
struct Figures {
    inputs: usize,
    accepted: usize,
    accepted_cases: usize,
    clean_errors: usize,
    by_kind: BTreeMap<&'static str, usize>,
    panics: Vec<String>,
    hangs: Vec<String>,
    implausible: Vec<String>,
    unclean: Vec<String>,
    slowest: Duration,
}

impl Figures {
    fn report(&self, seconds: f64) -> String {
        let kinds: Vec<String> = self
            .by_kind
            .iter()
            .map(|(k, n)| format!("{k} {n}"))
            .collect();
        format!(
            "fuzz_check: {} inputs in {seconds:.1} s: {} accepted ({} cases, all plausible: {}), \
             {} clean errors ({}), panics {}, hangs {}, unclean messages {}; slowest input {:.3} s",
            self.inputs,
            self.accepted,
            self.accepted_cases,
            self.implausible.is_empty(),
            self.clean_errors,
            kinds.join(", "),
            self.panics.len(),
            self.hangs.len(),
            self.unclean.len(),
            self.slowest.as_secs_f64(),
        )
    }
}

fn fuzz(inputs: usize, seed: u64) {
    let seeds = seeds();
    let dir = scratch(&seeds);
    let mut rng = TestRng::from_seed(RngAlgorithm::ChaCha, &{
        let mut s = [0u8; 32];
        s[..8].copy_from_slice(&seed.to_le_bytes());
        s
    });
    let mut fig = Figures::default();
    let started = Instant::now();
    for k in 0..inputs {
        let s = &seeds[pick(&mut rng, seeds.len())];
        let bytes = mutant(&mut rng, s);
        let path = dir.join(&s.family).join("fuzz.ron");
        std::fs::write(&path, &bytes).unwrap();
        let keep = |what: &str| {
            let kept = dir.join(format!("{what}-{k}.ron"));
            std::fs::write(&kept, &bytes).unwrap();
            format!(
                "input {k} (from {}/{}), kept as {}",
                s.family,
                s.name,
                kept.display()
            )
        };
        let (tx, rx) = mpsc::channel();
        let worker_path = path.clone();
        let t0 = Instant::now();
        std::thread::spawn(move || {
            let _ = tx.send(check(&worker_path));
        });
        fig.inputs += 1;
        match rx.recv_timeout(DEADLINE) {
            Err(_) => fig.hangs.push(keep("hang")),
            Ok(outcome) => {
                fig.slowest = fig.slowest.max(t0.elapsed());
                match outcome {
                    Outcome::Panicked(m) => fig.panics.push(format!("{}: {m}", keep("panic"))),
                    Outcome::Accepted(n, bad) => {
                        fig.accepted += 1;
                        fig.accepted_cases += n;
                        if !bad.is_empty() {
                            fig.implausible
                                .push(format!("{}: {bad:?}", keep("implausible")));
                        }
                    }
                    Outcome::Rejected(kind, msg) => {
                        *fig.by_kind.entry(kind).or_default() += 1;
                        let names_file = msg.contains(&path.display().to_string());
                        if names_file && longest_digit_run(&msg) <= 30 {
                            fig.clean_errors += 1;
                        } else {
                            fig.unclean.push(format!("{}: {msg}", keep("unclean")));
                        }
                    }
                }
            }
        }
    }
    let report = fig.report(started.elapsed().as_secs_f64());
    println!("{report}");
    let record = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("fuzz_check_{inputs}.txt"));
    let mut text = format!("{report}\nseed {seed}\n");
    for (what, list) in [
        ("panic", &fig.panics),
        ("hang", &fig.hangs),
        ("implausible", &fig.implausible),
        ("unclean", &fig.unclean),
    ] {
        for e in list.iter().take(10) {
            text.push_str(&format!("{what}: {e}\n"));
        }
    }
    std::fs::write(&record, &text).unwrap();
    assert!(
        fig.panics.is_empty()
            && fig.hangs.is_empty()
            && fig.implausible.is_empty()
            && fig.unclean.is_empty(),
        "{text}"
    );
    // the mutations reach both outcomes
    assert!(fig.accepted > 0 && fig.clean_errors > 0, "{report}");
    let _ = std::fs::remove_dir_all(&dir);
}

fn env_number(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// The fast version: 500 inputs, a second or two.
#[test]
fn check_survives_mutated_case_files() {
    fuzz(500, env_number("RUNOUT_FUZZ_SEED", 21));
}

/// The long version: `RUNOUT_FUZZ_CASES` inputs (default 20 000), see the module header.
#[test]
#[ignore = "long: RUNOUT_FUZZ_CASES=20000 cargo test --release -p runout-case --test fuzz_check -- --ignored --nocapture"]
fn check_survives_many_mutated_case_files() {
    fuzz(
        env_number("RUNOUT_FUZZ_CASES", 20_000) as usize,
        env_number("RUNOUT_FUZZ_SEED", 2021),
    );
}
