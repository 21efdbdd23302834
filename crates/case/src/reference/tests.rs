//! The reference kept honest: every field a shipped case holds is documented, every
//! documented field exists, and every band is documented where validation applies it.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

use serde_json::Value;

use super::*;
use crate::{case_files, load, validate_case, Case, Loaded};

/// The section a value at `path` starts, if it starts one: the same type in several places
/// is documented once.
fn reroot(path: &str) -> Option<&'static str> {
    match path {
        "boundaries.west" | "boundaries.east" | "boundaries.south" | "boundaries.north" => {
            Some("Boundary")
        }
        "Boundary.Wall.solids" | "sidewalls.solids" => Some("SolidsWall"),
        "domain.x" | "domain.y" => Some("AxisSpec"),
        "fidelity.smoke" | "fidelity.coarse" | "fidelity.wall" => Some("Preset"),
        _ => None,
    }
}

fn join(path: &str, key: &str) -> String {
    let joined = if path.is_empty() {
        key.to_string()
    } else {
        format!("{path}.{key}")
    };
    reroot(&joined).map_or(joined, str::to_string)
}

/// Calls `leaf(path, value)` on every leaf of `v` (numbers, strings, booleans, nulls, and
/// arrays of numbers), with the reference's path of each.
fn walk(path: &str, v: &mut Value, leaf: &mut dyn FnMut(&str, &mut Value)) {
    match v {
        Value::Object(map) => {
            for (k, child) in map.iter_mut() {
                walk(&join(path, k), child, leaf);
            }
        }
        Value::Array(items) if items.iter().any(|i| i.is_object() || i.is_string()) => {
            for child in items.iter_mut() {
                walk(&format!("{path}[]"), child, leaf);
            }
        }
        _ => leaf(path, v),
    }
}

fn shipped_cases() -> Vec<(PathBuf, Case)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases");
    let mut out = Vec::new();
    for file in case_files(&[root]) {
        if let Ok(Loaded::Cases(cases)) = load(&file) {
            out.extend(cases.into_iter().map(|c| (file.clone(), c.case)));
        }
    }
    assert!(out.len() > 30, "found {} shipped cases", out.len());
    out
}

fn documented() -> Vec<Field> {
    SECTIONS
        .iter()
        .flat_map(|s| s.fields.iter().copied())
        .collect()
}

fn find(path: &str) -> Option<Field> {
    documented().into_iter().find(|f| f.path == path)
}

/// Whether a leaf the walk found at `path` is documented: the field itself, or a newtype
/// variant (`initial.gas_pressure.Uniform`) of a documented enum field that lists it.
fn is_documented(path: &str, leaf: &Value) -> Result<(), String> {
    if let Some(field) = find(path) {
        if let Value::String(s) = leaf {
            let free_text = field.ty == "string";
            if !free_text
                && !field
                    .ty
                    .split(|c: char| !c.is_alphanumeric())
                    .any(|w| w == s)
            {
                return Err(format!(
                    "`{path}` = {s}: variant not listed in `{}`",
                    field.ty
                ));
            }
        }
        return Ok(());
    }
    if let Some((parent, variant)) = path.rsplit_once('.') {
        if let Some(field) = find(parent) {
            if field
                .ty
                .split(|c: char| !c.is_alphanumeric())
                .any(|w| w == variant)
            {
                return Ok(());
            }
        }
    }
    Err(format!("`{path}` is not in the reference"))
}

#[test]
fn every_field_of_every_shipped_case_is_documented() {
    let mut missing = BTreeSet::new();
    for (file, case) in shipped_cases() {
        let mut v = serde_json::to_value(&case).unwrap();
        walk("", &mut v, &mut |p, leaf| {
            if let Err(e) = is_documented(p, leaf) {
                missing.insert(format!("{e} ({})", file.display()));
            }
        });
    }
    assert!(
        missing.is_empty(),
        "undocumented:\n{}",
        missing.into_iter().collect::<Vec<_>>().join("\n")
    );
}

/// The Rust sources of the case file's types.
const SOURCES: [&str; 12] = [
    include_str!("../schema.rs"),
    include_str!("../gas_inlet.rs"),
    include_str!("../run_control.rs"),
    include_str!("../sidewalls.rs"),
    include_str!("../bed.rs"),
    include_str!("../release.rs"),
    include_str!("../../../walls/src/spec.rs"),
    include_str!("../../../closures/src/friction.rs"),
    include_str!("../../../closures/src/drag.rs"),
    include_str!("../../../closures/src/radial.rs"),
    include_str!("../../../mesh/src/grid.rs"),
    include_str!("../../../mesh/src/segment.rs"),
];

fn is_identifier_in_sources(word: &str) -> bool {
    SOURCES.iter().any(|src| {
        src.match_indices(word).any(|(i, _)| {
            let before = src[..i].chars().next_back();
            let after = src[i + word.len()..].chars().next();
            let ident = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
            !ident(before) && !ident(after)
        })
    })
}

#[test]
fn every_documented_name_exists_in_the_schema() {
    let mut unknown = Vec::new();
    for field in documented() {
        for word in field.path.split(['.', '[', ']']).filter(|w| !w.is_empty()) {
            if !is_identifier_in_sources(word) {
                unknown.push(format!("{} ({word})", field.path));
            }
        }
        for word in field.ty.split(|c: char| !c.is_alphanumeric() && c != '_') {
            if word.chars().next().is_some_and(char::is_uppercase)
                && !is_identifier_in_sources(word)
            {
                unknown.push(format!("{} type {word}", field.path));
            }
        }
    }
    assert!(
        unknown.is_empty(),
        "documented but not in the schema: {unknown:?}"
    );
}

#[test]
fn every_band_is_documented_where_validation_applies_it() {
    for band in BANDS {
        assert!(
            BAND_FIELDS.iter().any(|(_, b)| b.what == band.what),
            "band `{}` has no field in limits::BAND_FIELDS",
            band.what
        );
    }
    for (path, _) in BAND_FIELDS {
        assert!(
            find(path).is_some(),
            "BAND_FIELDS names `{path}`, not in the reference"
        );
    }
}

/// The field name validation uses for a reference path: its last component that is not a
/// variant name (`Boundary.PressureOutlet.pressure.Uniform` → `pressure`).
fn error_name(path: &str) -> &str {
    path.split(['.', '[', ']'])
        .rfind(|w| !w.is_empty() && !w.starts_with(char::is_uppercase))
        .unwrap()
}

#[test]
fn validation_rejects_every_banded_field_above_its_band() {
    let cases = shipped_cases();
    let mut tried = 0;
    for (path, band) in BAND_FIELDS {
        let bad = if band.hi > 0.0 {
            band.hi * 10.0 + 1.0
        } else {
            band.hi + 1.0
        };
        let Some((file, mut v)) = cases.iter().find_map(|(file, case)| {
            let mut v = serde_json::to_value(case).unwrap();
            let mut hit = false;
            walk("", &mut v, &mut |p, leaf| {
                if hit || p != *path {
                    return;
                }
                match leaf {
                    Value::Number(_) => {
                        *leaf = serde_json::json!(bad);
                        hit = true;
                    }
                    Value::Array(xs) if xs.first().is_some_and(Value::is_number) => {
                        xs[0] = serde_json::json!(bad);
                        hit = true;
                    }
                    _ => {}
                }
            });
            hit.then(|| (file, v.take()))
        }) else {
            continue; // in no shipped case, or not a number (AxisSpec.segments)
        };
        let case: Case = serde_json::from_value(v.take()).unwrap();
        let errors = validate_case(&case).expect_err(path);
        let name = error_name(path);
        assert!(
            errors
                .iter()
                .any(|e| e.field.contains(name) && e.allowed.contains(band.what)),
            "{path} = {bad} in {}: no error names `{name}` with the band `{}`: {errors:?}",
            file.display(),
            band.what
        );
        tried += 1;
    }
    assert!(
        tried >= 35,
        "only {tried} banded fields found in the shipped cases"
    );
}

/// The documented defaults of the structs with a `Default` are the code's.
#[test]
fn documented_defaults_are_the_codes() {
    let defaults = [
        (
            "run.tolerances",
            serde_json::to_value(crate::Tolerances::default()),
        ),
        (
            "numerics.relaxation",
            serde_json::to_value(crate::Relaxation::default()),
        ),
        ("numerics", serde_json::to_value(crate::Numerics::default())),
    ];
    let mut checked = 0;
    for (prefix, value) in defaults {
        let Value::Object(map) = value.unwrap() else {
            panic!("{prefix}")
        };
        for (key, v) in map {
            let Some(field) = find(&format!("{prefix}.{key}")) else {
                continue;
            };
            let code = match &v {
                Value::Number(n) => n.as_f64().unwrap().to_string(),
                Value::String(s) => s.clone(),
                other => other.to_string(),
            };
            let doc = field
                .default
                .parse::<f64>()
                .map_or(field.default.to_string(), |x| x.to_string());
            assert_eq!(doc, code, "default of {prefix}.{key}");
            checked += 1;
        }
    }
    assert!(checked >= 13, "{checked}");
}
