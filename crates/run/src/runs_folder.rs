//! The runs folder: a run folder below a folder named `runs` stays inside it. A case's
//! folder, a run folder or its `.partial` folder that is a symbolic link pointing outside
//! `runs/` is refused, so that clearing or replacing a run never reaches files elsewhere.
//! `runs/` itself may be a link (to a scratch disk, say).

use std::path::{Component, Path, PathBuf};

use crate::RunError;

/// Checks the folders of run folder `dir` below the nearest ancestor named `runs` (if it
/// has one): none may be a symbolic link whose target lies outside `runs/`. `dir`'s
/// `.partial` sibling (the store writes there) is checked too.
pub fn check_links(dir: &Path) -> Result<(), RunError> {
    let absolute = std::path::absolute(dir).map_err(|e| RunError::OutDir {
        dir: dir.to_path_buf(),
        reason: format!("cannot resolve the folder: {e}"),
    })?;
    let components: Vec<Component> = absolute.components().collect();
    let Some(at) = components
        .iter()
        .rposition(|c| matches!(c, Component::Normal(n) if *n == "runs"))
    else {
        return Ok(());
    };
    let runs: PathBuf = components[..=at].iter().collect();
    let Ok(inside) = runs.canonicalize() else {
        return Ok(()); // no runs folder yet: nothing below it is a link
    };
    let mut path = runs.clone();
    let mut checked = Vec::new();
    for c in &components[at + 1..] {
        path.push(c);
        checked.push(path.clone());
    }
    if let Some(name) = path.file_name().map(|n| n.to_string_lossy().into_owned()) {
        if !name.ends_with(".partial") {
            checked.push(path.with_file_name(format!("{name}.partial")));
        }
    }
    for p in checked {
        let is_link = std::fs::symlink_metadata(&p).is_ok_and(|m| m.file_type().is_symlink());
        if !is_link {
            continue;
        }
        let target = p.canonicalize();
        if target.as_ref().is_ok_and(|t| t.starts_with(&inside)) {
            continue;
        }
        let to = target.map_or_else(
            |_| "nowhere (a dangling link)".to_string(),
            |t| t.display().to_string(),
        );
        return Err(RunError::OutDir {
            dir: dir.to_path_buf(),
            reason: format!(
                "{} is a symbolic link to {to}, outside {}: runs are written only below \
                 runs/; replace the link by a folder (or link runs/ itself)",
                p.display(),
                runs.display()
            ),
        });
    }
    Ok(())
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;
    use std::os::unix::fs::symlink;

    #[test]
    fn a_link_out_of_runs_is_refused_and_one_inside_or_of_runs_itself_is_not() {
        let tmp = std::env::temp_dir().join(format!("runout-links-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&tmp);
        let runs = tmp.join("runs");
        let elsewhere = tmp.join("elsewhere");
        std::fs::create_dir_all(runs.join("kept")).unwrap();
        std::fs::create_dir_all(&elsewhere).unwrap();

        symlink(&elsewhere, runs.join("A")).unwrap();
        let err = check_links(&runs.join("A").join("smoke")).unwrap_err();
        assert!(err.to_string().contains("outside"), "{err}");

        std::fs::create_dir_all(runs.join("B")).unwrap();
        symlink(&elsewhere, runs.join("B").join("smoke.partial")).unwrap();
        let err = check_links(&runs.join("B").join("smoke")).unwrap_err();
        assert!(err.to_string().contains("smoke.partial"), "{err}");

        symlink(runs.join("kept"), runs.join("C")).unwrap();
        check_links(&runs.join("C").join("smoke")).unwrap();

        // runs/ itself a link to a scratch disk
        std::fs::create_dir_all(tmp.join("top")).unwrap();
        let scratch_runs = tmp.join("top").join("runs");
        symlink(&elsewhere, &scratch_runs).unwrap();
        check_links(&scratch_runs.join("D").join("smoke")).unwrap();

        std::fs::remove_dir_all(&tmp).unwrap();
    }
}
