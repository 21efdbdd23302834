//! Numeric fields of a case named by a path, read and set through the case's serde form.
//!
//! A case is serialised to a `serde_json::Value` (enums externally tagged: a variant is an
//! object with one key, its name), walked, changed and deserialised and validated again.
//!
//! Path syntax (docs/reference/calibrate.md):
//! - dotted field names with indices, `solids[0].diameter`, `initial.regions[0].x[1]`
//!   (an index may also be written as a segment: `solids.0.diameter`);
//! - enum variants are optional segments: `boundaries.south.solids.specularity` and
//!   `boundaries.south.Wall.solids.JohnsonJackson.specularity` name the same field (a
//!   variant named in the path must be the one the case has);
//! - a bare name without `.` or `[`, e.g. `specularity` or `wall_friction_angle`, names
//!   every numeric field of that name anywhere in the case (all set to one value).

use anyhow::{anyhow, bail, Context, Result};
use runout_case::{validate_case, Case};
use serde_json::Value;

/// One step of a resolved path: an object key or an array index.
#[derive(Clone, Debug, PartialEq)]
enum Step {
    Key(String),
    Index(usize),
}

/// A parameter of a case: the user's path and the concrete fields it resolves to.
#[derive(Clone, Debug)]
pub struct CasePath {
    /// the path as written
    pub text: String,
    /// every field it names, with variants explicit
    fields: Vec<Vec<Step>>,
}

/// The serde form of a case.
fn to_value(case: &Case) -> Result<Value> {
    serde_json::to_value(case).context("serialising the case")
}

/// Splits `a.b[2].c` into segments `a`, `b`, `[2]`, `c` (an index as `Index`).
fn segments(text: &str) -> Result<Vec<Step>> {
    let mut out = Vec::new();
    for part in text.split('.') {
        let (name, mut rest) = part.split_once('[').map_or((part, ""), |(n, r)| (n, r));
        if name.is_empty() && rest.is_empty() {
            bail!("`{text}`: an empty segment (two dots, or a dot at an end)");
        }
        if !name.is_empty() {
            out.push(match name.parse::<usize>() {
                Ok(k) => Step::Index(k),
                Err(_) => Step::Key(name.to_string()),
            });
        }
        while !rest.is_empty() {
            let (index, tail) = rest
                .split_once(']')
                .with_context(|| format!("`{text}`: `[` without `]`"))?;
            let k = index
                .parse()
                .map_err(|_| anyhow!("`{text}`: `[{index}]` is not an index (0, 1, ...)"))?;
            out.push(Step::Index(k));
            rest = tail.strip_prefix('[').unwrap_or(tail);
            if !tail.is_empty() && !tail.starts_with('[') {
                bail!("`{text}`: `{tail}` after `]`");
            }
        }
    }
    Ok(out)
}

/// The one key of an object that holds an enum variant (a name starting upper-case).
fn variant(map: &serde_json::Map<String, Value>) -> Option<(&String, &Value)> {
    let mut it = map.iter();
    match (it.next(), it.next()) {
        (Some((k, v)), None) if k.starts_with(|c: char| c.is_ascii_uppercase()) => Some((k, v)),
        _ => None,
    }
}

/// What kind of value `v` is, for messages.
fn kind(v: &Value) -> String {
    match v {
        Value::Null => "not set (None)".into(),
        Value::Bool(_) => "a flag".into(),
        Value::Number(_) => "a number".into(),
        Value::String(s) => format!("the text {s:?}"),
        Value::Array(a) => format!("a list of {}", a.len()),
        Value::Object(m) => match variant(m) {
            Some((k, _)) => format!("the variant {k}"),
            None => format!(
                "a struct with fields {}",
                m.keys().cloned().collect::<Vec<_>>().join(", ")
            ),
        },
    }
}

fn shown(steps: &[Step]) -> String {
    let mut s = String::new();
    for step in steps {
        match step {
            Step::Key(k) if s.is_empty() => s.push_str(k),
            Step::Key(k) => s.push_str(&format!(".{k}")),
            Step::Index(i) => s.push_str(&format!("[{i}]")),
        }
    }
    s
}

/// Checks that `v` is a real number (not an integer field).
fn check_real(v: &Value, at: &[Step]) -> Result<()> {
    match v {
        Value::Number(n) if n.is_f64() => Ok(()),
        Value::Number(_) => bail!(
            "`{}` is an integer field (a count): calibrate varies real numbers",
            shown(at)
        ),
        other => bail!("`{}` is {}, not a number", shown(at), kind(other)),
    }
}

/// Walks `steps` from `root`, stepping into enum variants the path leaves out; the
/// concrete steps of the numeric field reached.
fn resolve(root: &Value, steps: &[Step]) -> Result<Vec<Step>> {
    let mut at = Vec::new();
    let mut v = root;
    let mut k = 0;
    while k < steps.len() {
        match (&steps[k], v) {
            (Step::Key(key), Value::Object(map)) if map.contains_key(key) => {
                v = &map[key];
                at.push(Step::Key(key.clone()));
                k += 1;
            }
            (_, Value::Object(map)) if variant(map).is_some() => {
                let (name, inner) = variant(map).expect("a variant");
                if matches!(&steps[k], Step::Key(key) if key.starts_with(|c: char| c.is_ascii_uppercase()))
                {
                    bail!(
                        "`{}` is the variant {name}, not {}",
                        shown(&at),
                        shown(&steps[k..=k])
                    );
                }
                at.push(Step::Key(name.clone()));
                v = inner;
            }
            (Step::Key(key), Value::Object(map)) => bail!(
                "`{}` has no field `{key}` (fields: {})",
                if at.is_empty() {
                    "the case".into()
                } else {
                    shown(&at)
                },
                map.keys().cloned().collect::<Vec<_>>().join(", ")
            ),
            (Step::Index(i), Value::Array(items)) => {
                v = items.get(*i).with_context(|| {
                    format!("`{}` has {} entries: no index {i}", shown(&at), items.len())
                })?;
                at.push(Step::Index(*i));
                k += 1;
            }
            (step, other) => bail!(
                "`{}` is {}: no `{}` in it",
                shown(&at),
                kind(other),
                shown(std::slice::from_ref(step))
            ),
        }
    }
    // a newtype variant holding the number, e.g. `pressure: Hydrostatic(101325.0)`
    if let Value::Object(map) = v {
        if let Some((name, inner @ Value::Number(_))) = variant(map) {
            at.push(Step::Key(name.clone()));
            v = inner;
        }
    }
    check_real(v, &at)?;
    Ok(at)
}

/// Every numeric (real) field named `name` below `v`, at `prefix`.
fn find_named(v: &Value, name: &str, prefix: &mut Vec<Step>, out: &mut Vec<Vec<Step>>) {
    match v {
        Value::Object(map) => {
            for (k, inner) in map {
                prefix.push(Step::Key(k.clone()));
                if k == name && matches!(inner, Value::Number(n) if n.is_f64()) {
                    out.push(prefix.clone());
                } else {
                    find_named(inner, name, prefix, out);
                }
                prefix.pop();
            }
        }
        Value::Array(items) => {
            for (i, inner) in items.iter().enumerate() {
                prefix.push(Step::Index(i));
                find_named(inner, name, prefix, out);
                prefix.pop();
            }
        }
        _ => {}
    }
}

fn get_mut<'a>(root: &'a mut Value, steps: &[Step]) -> Option<&'a mut Value> {
    steps.iter().try_fold(root, |v, s| match s {
        Step::Key(k) => v.get_mut(k),
        Step::Index(i) => v.get_mut(*i),
    })
}

impl CasePath {
    /// Resolves `text` on `case`: an error names the path and what is wrong with it.
    pub fn parse(text: &str, case: &Case) -> Result<CasePath> {
        let text = text.trim();
        if text.is_empty() {
            bail!("an empty parameter path");
        }
        let root = to_value(case)?;
        let fields = if !text.contains(['.', '[']) && text.parse::<usize>().is_err() {
            let mut found = Vec::new();
            find_named(&root, text, &mut Vec::new(), &mut found);
            if found.is_empty() {
                // a top-level field, or a clear message about it
                vec![resolve(&root, &segments(text)?)
                    .with_context(|| format!("no numeric field named `{text}` in the case"))?]
            } else {
                found
            }
        } else {
            vec![resolve(&root, &segments(text)?)?]
        };
        Ok(CasePath {
            text: text.to_string(),
            fields,
        })
    }

    /// The concrete fields the path names, e.g. `boundaries.south.Wall.solids.JohnsonJackson
    /// .specularity`.
    pub fn fields(&self) -> Vec<String> {
        self.fields.iter().map(|f| shown(f)).collect()
    }

    /// A short key for run names: the last field name.
    pub fn key(&self) -> String {
        match self.fields[0].iter().rev().find_map(|s| match s {
            Step::Key(k) => Some(k.clone()),
            Step::Index(_) => None,
        }) {
            Some(k) => k,
            None => "p".into(),
        }
    }

    /// The value of each field the path names in `case`.
    pub fn get(&self, case: &Case) -> Result<Vec<f64>> {
        let mut root = to_value(case)?;
        self.fields
            .iter()
            .map(|f| {
                get_mut(&mut root, f)
                    .and_then(|v| v.as_f64())
                    .with_context(|| format!("`{}` is not in the case", shown(f)))
            })
            .collect()
    }

    /// `case` with every field of the path set to `value`, deserialised and validated again
    /// (an error names the fields out of range).
    #[cfg(test)]
    pub fn set(&self, case: &Case, value: f64) -> Result<Case> {
        set_all(case, &[(self, value)])
    }
}

/// `case` with each path set to its value, validated.
pub fn set_all(case: &Case, values: &[(&CasePath, f64)]) -> Result<Case> {
    let mut root = to_value(case)?;
    for (path, value) in values {
        let number = serde_json::Number::from_f64(*value)
            .with_context(|| format!("{} = {value}: not a finite number", path.text))?;
        for f in &path.fields {
            *get_mut(&mut root, f)
                .with_context(|| format!("`{}` is not in the case", shown(f)))? =
                Value::Number(number.clone());
        }
    }
    let changed: Case = serde_json::from_value(root).context("reading the changed case back")?;
    validate_case(&changed).map_err(|errors| {
        let list: Vec<String> = errors.iter().map(|e| format!("  {e}")).collect();
        anyhow!("the case is invalid:\n{}", list.join("\n"))
    })?;
    Ok(changed)
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(crate) fn flume() -> Case {
        let file =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/flume/base.ron");
        runout_case::load_case(&file).unwrap()
    }

    #[test]
    fn the_serde_form_round_trips() {
        let case = flume();
        let back: Case = serde_json::from_value(to_value(&case).unwrap()).unwrap();
        assert_eq!(back, case);
    }

    #[test]
    fn a_path_sets_and_gets_one_field() {
        let case = flume();
        for text in [
            "boundaries.south.solids.specularity",
            "boundaries.south.Wall.solids.JohnsonJackson.specularity",
        ] {
            let p = CasePath::parse(text, &case).unwrap();
            assert_eq!(
                p.fields(),
                ["boundaries.south.Wall.solids.JohnsonJackson.specularity"]
            );
            assert_eq!(p.get(&case).unwrap(), [0.1]);
            let changed = p.set(&case, 0.25).unwrap();
            assert_eq!(p.get(&changed).unwrap(), [0.25]);
            // the side walls keep theirs
            let west = CasePath::parse("boundaries.west.solids.specularity", &case).unwrap();
            assert_eq!(west.get(&changed).unwrap(), [0.1]);
            assert_eq!(p.key(), "specularity");
        }
        let p = CasePath::parse("initial.regions[0].solids.0.eps_s", &case).unwrap();
        assert_eq!(p.get(&case).unwrap(), [0.6]);
        let p = CasePath::parse("initial.regions[0].x[1]", &case).unwrap();
        assert_eq!(p.get(&p.set(&case, 0.9).unwrap()).unwrap(), [0.9]);
    }

    #[test]
    fn a_bare_name_sets_every_field_of_that_name() {
        let case = flume();
        let p = CasePath::parse("specularity", &case).unwrap();
        assert_eq!(p.fields().len(), 3, "{:?}", p.fields());
        let changed = p.set(&case, 0.03).unwrap();
        assert_eq!(p.get(&changed).unwrap(), [0.03; 3]);
        let slope = CasePath::parse("slope", &case).unwrap();
        assert_eq!(slope.fields(), ["gravity.TiltOnImpact.slope"]);
        assert_eq!(slope.get(&case).unwrap(), [40.0]);
    }

    #[test]
    fn bad_paths_are_named() {
        let case = flume();
        let err = |text: &str| format!("{:#}", CasePath::parse(text, &case).unwrap_err());
        assert!(err("boundaries.south.solids.spec").contains("no field `spec`"));
        assert!(err("boundaries.south.solids.Jenkins.wall_restitution")
            .contains("is the variant JohnsonJackson"));
        assert!(err("solids[3].diameter").contains("no index 3"));
        assert!(err("solids[0].name").contains("not a number"));
        assert!(err("domain.x.segments[1].Uniform.cells").contains("integer field"));
        assert!(err("nonsense").contains("no numeric field named `nonsense`"));
        assert!(err("solids[x].diameter").contains("not an index"));
        assert!(err("solids..diameter").contains("empty segment"));
    }

    #[test]
    fn a_value_out_of_range_names_the_field() {
        let case = flume();
        let p = CasePath::parse("boundaries.south.solids.specularity", &case).unwrap();
        let e = format!("{:#}", p.set(&case, 2.0).unwrap_err());
        assert!(e.contains("boundaries.south"), "{e}");
        assert!(p.set(&case, f64::NAN).is_err());
    }
}
