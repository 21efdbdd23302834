//! Case names and the run folder they name: a valid name can never lead outside `runs/`.

use std::path::{Component, Path, PathBuf};

use crate::checker::FieldError;
use crate::limits::MAX_NAME_BYTES;
use crate::load::Fidelity;

/// What a case name may be: it is the name of a folder under `runs/`, so neither `.`, `..`
/// (a case named `..` wrote its output beside `runs/`, issue 21), nor a hidden or nested
/// name, nor one with control characters.
pub(crate) fn allowed_names() -> String {
    format!(
        "1 to {MAX_NAME_BYTES} bytes of letters, digits and -_.=, not starting with a dot \
         (a folder name under runs/)"
    )
}

/// Whether `name` is a valid case name ([`allowed_names`]).
pub fn is_valid_name(name: &str) -> bool {
    !name.is_empty()
        && name.len() <= MAX_NAME_BYTES
        && !name.starts_with('.')
        && name
            .chars()
            .all(|ch| ch.is_ascii_alphanumeric() || "-_.=".contains(ch))
}

/// The error for an invalid name at `field`, `None` for a valid one.
pub(crate) fn name_error(field: &str, name: &str) -> Option<FieldError> {
    (!is_valid_name(name)).then(|| FieldError {
        field: field.into(),
        value: format!("{:?}", truncated(name)),
        allowed: allowed_names(),
    })
}

/// At most 120 characters of `name`, for messages.
fn truncated(name: &str) -> String {
    const SHOWN: usize = 120;
    if name.chars().count() <= SHOWN {
        name.to_string()
    } else {
        format!("{}…", name.chars().take(SHOWN).collect::<String>())
    }
}

/// The output folder of case `name` at `fidelity`: `root/runs/<name>/<fidelity>`. An error
/// for an invalid name; the path is checked to lie below `root/runs` (two plain components
/// further), so that no name can make a run write elsewhere.
pub fn run_dir(root: &Path, name: &str, fidelity: Fidelity) -> Result<PathBuf, FieldError> {
    if let Some(e) = name_error("name", name) {
        return Err(e);
    }
    let runs = root.join("runs");
    let dir = runs.join(name).join(fidelity.name());
    let below: Vec<Component> = dir
        .strip_prefix(&runs)
        .map(|rest| rest.components().collect())
        .unwrap_or_default();
    let plain = below.len() == 2 && below.iter().all(|c| matches!(c, Component::Normal(_)));
    if plain {
        Ok(dir)
    } else {
        Err(FieldError {
            field: "name".into(),
            value: format!("{name:?}"),
            allowed: format!("a name whose run folder lies below {}", runs.display()),
        })
    }
}
