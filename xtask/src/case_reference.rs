//! `cargo xtask case-reference [--check]`: writes docs/guide/case-reference.md from the
//! case crate's reference table ([`runout_case::reference::markdown`]); `--check` (in CI)
//! fails when the checked-in page differs, so the page cannot drift from the code.

use std::path::Path;

use anyhow::{bail, Context, Result};

/// The page, relative to the workspace root.
pub const PAGE: &str = "docs/guide/case-reference.md";

/// Writes the page, or with `check` compares it with what the code generates.
pub fn run(root: &Path, check: bool) -> Result<()> {
    let path = root.join(PAGE);
    let page = runout_case::reference::markdown();
    if check {
        let on_disk = std::fs::read_to_string(&path)
            .with_context(|| format!("reading {}", path.display()))?;
        if on_disk != page {
            bail!(
                "{PAGE} is out of date with crates/case/src/reference.rs and limits.rs: run \
                 `cargo xtask case-reference` and commit the page"
            );
        }
        println!("{PAGE} is up to date");
    } else {
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)?;
        }
        std::fs::write(&path, page).with_context(|| format!("writing {}", path.display()))?;
        println!("wrote {PAGE}");
    }
    Ok(())
}
