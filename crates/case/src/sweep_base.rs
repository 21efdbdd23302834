//! Where a sweep's `base` may be: a `.ron` regular file below the sweep file's folder.
//!
//! `base` was joined to the sweep's folder and read whatever it named: `/dev/zero` was read
//! until memory ran out, and a system file was read and its first word echoed in the parse
//! error (issue 21). Its size is bounded when it is read ([`crate::limits::MAX_FILE_BYTES`]).

use std::path::{Component, Path, PathBuf};

/// The path of the base case of the sweep `sweep_file`, checked: `base` is a relative path
/// to a `.ron` file that, after symbolic links and `..` are resolved, is a regular file
/// below the sweep file's folder. Errors are (field path, message).
pub(crate) fn sweep_base(sweep_file: &Path, base: &str) -> Result<PathBuf, (String, String)> {
    let fail = |message: String| Err(("base".to_string(), format!("`{base}`: {message}")));
    let relative = Path::new(base);
    let plain = relative.components().all(|c| {
        matches!(
            c,
            Component::Normal(_) | Component::ParentDir | Component::CurDir
        )
    });
    if base.is_empty() || !plain {
        return fail("a relative path below the sweep file's folder is required".into());
    }
    if relative.extension().is_none_or(|e| e != "ron") {
        return fail("a `.ron` file is required".into());
    }
    let folder = match sweep_file.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let path = folder.join(relative);
    let (Ok(folder_real), Ok(real)) = (folder.canonicalize(), path.canonicalize()) else {
        return fail(format!("{} does not exist", path.display()));
    };
    if !real.starts_with(&folder_real) {
        return fail(format!(
            "resolves to {}, outside the sweep file's folder {}",
            real.display(),
            folder_real.display()
        ));
    }
    match std::fs::metadata(&real) {
        Ok(m) if m.is_file() => Ok(path),
        _ => fail(format!("{} is not a regular file", path.display())),
    }
}
