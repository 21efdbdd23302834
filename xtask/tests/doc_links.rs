//! Every relative link of README.md and the pages under docs/ resolves to a file or folder
//! of the repository (issue 59 item 3): a page moved or renamed cannot leave a dead link.

use std::path::{Path, PathBuf};

/// The markdown files: README.md and every `.md` below docs/.
fn pages(root: &Path) -> Vec<PathBuf> {
    let mut out = vec![root.join("README.md")];
    let mut stack = vec![root.join("docs")];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap().flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "md") {
                out.push(path);
            }
        }
    }
    out
}

/// The targets of the inline links `[text](target)` of a markdown text, outside code.
fn link_targets(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut in_fence = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            in_fence = !in_fence;
            continue;
        }
        if in_fence {
            continue;
        }
        let mut rest = line;
        while let Some(i) = rest.find("](") {
            let after = &rest[i + 2..];
            let Some(end) = after.find(')') else { break };
            out.push(after[..end].trim().to_string());
            rest = &after[end..];
        }
    }
    out
}

#[test]
fn every_relative_link_resolves() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let (mut dead, mut checked) = (Vec::new(), 0);
    for page in pages(&root) {
        let text = std::fs::read_to_string(&page).unwrap();
        for target in link_targets(&text) {
            let external = ["http://", "https://", "mailto:", "#"]
                .iter()
                .any(|p| target.starts_with(p));
            if external || target.is_empty() || target.contains(' ') {
                continue;
            }
            let file = target.split('#').next().unwrap_or("");
            let resolved = page.parent().unwrap().join(file);
            checked += 1;
            if !resolved.exists() {
                dead.push(format!(
                    "{}: {target}",
                    page.strip_prefix(&root).unwrap().display()
                ));
            }
        }
    }
    assert!(dead.is_empty(), "dead relative links:\n{}", dead.join("\n"));
    assert!(
        checked > 50,
        "only {checked} relative links found: the scan is broken"
    );
}

#[test]
fn links_are_found_outside_code_only() {
    let text = "see [a](x.md) and [b](../y.md#z)\n```\n[c](code.md)\n```\n[d](https://e)";
    assert_eq!(link_targets(text), ["x.md", "../y.md#z", "https://e"]);
}
