//! Keeps the model citations resolvable: every `docs/model.md §N` cited in the repository's
//! sources, docs and case files names a numbered section of docs/model.md, and no citation
//! of the old external specification is left.
//!
//! A citation is `docs/model.md` followed (possibly after a closing backtick, a line break
//! and a comment marker) by one or more section numbers: `§4.12`, `§3.5–3.8` (every section
//! of the range), `§2.2, §2.6`, `§2 and §1.3`.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

/// Folders and files walked, relative to the repository root.
const ROOTS: [&str; 6] = ["crates", "xtask", "docs", "cases", "examples", "README.md"];

/// Text files that may cite the model.
const EXTENSIONS: [&str; 8] = ["rs", "md", "ron", "py", "toml", "sh", "sbatch", "txt"];

const MODEL: &str = "docs/model.md";

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn walk(path: &Path, out: &mut Vec<PathBuf>) {
    if path.is_file() {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        if EXTENSIONS.contains(&ext) {
            out.push(path.to_path_buf());
        }
        return;
    }
    let Ok(entries) = fs::read_dir(path) else {
        return;
    };
    for entry in entries.flatten() {
        let p = entry.path();
        let name = entry.file_name();
        if name == "target" || name == ".git" || name == "runs" {
            continue;
        }
        walk(&p, out);
    }
}

/// The section numbers of docs/model.md: headings `## 4.`, `### 4.12 …`, `#### 3.10.1 …`.
fn sections(text: &str) -> BTreeSet<String> {
    text.lines()
        .filter_map(|line| {
            let rest = line.trim_start_matches('#');
            if rest.len() == line.len() || !rest.starts_with(' ') {
                return None;
            }
            let number = rest.split_whitespace().next()?;
            let number = number.trim_end_matches('.');
            number
                .split('.')
                .all(|p| !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit()))
                .then(|| number.to_string())
        })
        .collect()
}

/// Skips spaces, a line break and the comment markers of the next line.
fn skip_gap(s: &str) -> &str {
    let t = s.trim_start_matches([' ', '\t']);
    if let Some(rest) = t.strip_prefix('\n') {
        rest.trim_start()
            .trim_start_matches("//!")
            .trim_start_matches("///")
            .trim_start_matches("//")
            .trim_start_matches('#')
            .trim_start_matches('*')
            .trim_start_matches([' ', '\t'])
    } else {
        t
    }
}

/// A section number at the start of `s` (digits and dots, no trailing dot) and the rest.
fn number(s: &str) -> Option<(&str, &str)> {
    let end = s
        .char_indices()
        .find(|&(_, c)| !(c.is_ascii_digit() || c == '.'))
        .map_or(s.len(), |(i, _)| i);
    let n = s[..end].trim_end_matches('.');
    if n.is_empty() || !n.as_bytes()[0].is_ascii_digit() {
        return None;
    }
    Some((n, &s[n.len()..]))
}

/// The sections of a range `a–b` (same prefix, last component from a to b), else both ends.
fn range(a: &str, b: &str) -> Vec<String> {
    let (pa, la) = a.rsplit_once('.').unwrap_or(("", a));
    let (pb, lb) = b.rsplit_once('.').unwrap_or(("", b));
    match (la.parse::<u32>(), lb.parse::<u32>()) {
        (Ok(x), Ok(y)) if pa == pb && x <= y => (x..=y)
            .map(|k| {
                if pa.is_empty() {
                    k.to_string()
                } else {
                    format!("{pa}.{k}")
                }
            })
            .collect(),
        _ => vec![a.to_string(), b.to_string()],
    }
}

/// The section numbers cited right after one occurrence of `docs/model.md`.
fn cited(after: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut s = skip_gap(after.strip_prefix('`').unwrap_or(after));
    while let Some(rest) = s.strip_prefix('§') {
        let Some((a, rest)) = number(rest) else {
            break;
        };
        let mut rest = rest;
        let mut end = None;
        for dash in ['–', '-'] {
            if let Some(r) = rest.strip_prefix(dash) {
                if let Some((b, r2)) = number(r.strip_prefix('§').unwrap_or(r)) {
                    end = Some(b);
                    rest = r2;
                }
            }
        }
        match end {
            Some(b) => out.extend(range(a, b)),
            None => out.push(a.to_string()),
        }
        // another section right after a separator: ", §2.6", " and §1.3", "; §4.8"
        let next = [", ", " and ", "; ", ", and "]
            .iter()
            .find_map(|sep| rest.strip_prefix(sep))
            .map(skip_gap);
        match next {
            Some(n) if n.starts_with('§') => s = n,
            _ => break,
        }
    }
    out
}

#[test]
fn model_citations_resolve() {
    let root = repo_root();
    let model = fs::read_to_string(root.join(MODEL)).expect("docs/model.md exists");
    let known = sections(&model);
    // the numbering of the specification it replaces, which older citations used
    for s in ["0.1", "1.3", "2.4.2", "3.10", "4.12", "4.13", "5", "6", "7"] {
        assert!(known.contains(s), "docs/model.md lacks its section {s}");
    }
    let old = concat!("model", "-spec");
    let mut files = Vec::new();
    for r in ROOTS {
        walk(&root.join(r), &mut files);
    }
    assert!(files.len() > 50, "walked only {} files", files.len());
    let (mut count, mut missing, mut stale) = (0usize, Vec::new(), Vec::new());
    for path in &files {
        let Ok(text) = fs::read_to_string(path) else {
            continue;
        };
        let rel = path
            .strip_prefix(&root)
            .unwrap_or(path)
            .display()
            .to_string();
        for (k, line) in text.lines().enumerate() {
            if line.to_lowercase().contains(old) {
                stale.push(format!("{rel}:{}", k + 1));
            }
        }
        if rel.ends_with(MODEL) {
            continue;
        }
        for (at, _) in text.match_indices(MODEL) {
            let line = text[..at].matches('\n').count() + 1;
            for s in cited(&text[at + MODEL.len()..]) {
                count += 1;
                if !known.contains(&s) {
                    missing.push(format!("{rel}:{line}: §{s}"));
                }
            }
        }
    }
    assert!(
        stale.is_empty(),
        "citations of the old specification (cite docs/model.md §N instead):\n{}",
        stale.join("\n")
    );
    assert!(
        missing.is_empty(),
        "citations of sections docs/model.md does not have:\n{}",
        missing.join("\n")
    );
    eprintln!(
        "{count} section citations in {} files resolve to the {} sections of docs/model.md",
        files.len(),
        known.len()
    );
    assert!(count > 300, "only {count} section citations found");
}

#[test]
fn citation_parsing() {
    assert_eq!(cited(" §4.12)."), ["4.12"]);
    assert_eq!(cited("` §3; paper"), ["3"]);
    assert_eq!(cited(" §3.5–3.8)"), ["3.5", "3.6", "3.7", "3.8"]);
    assert_eq!(cited(" §2.2, §2.6 (wall"), ["2.2", "2.6"]);
    assert_eq!(cited(" §2 and §1.3"), ["2", "1.3"]);
    assert_eq!(cited("\n    // §3.10.1): x"), ["3.10.1"]);
    assert_eq!(cited(" §4.4 step 3; §4.8"), ["4.4"]);
    assert_eq!(cited(" section in brackets"), Vec::<String>::new());
    let s = sections("# t\n## 4. Numerical\n### 4.12 Adaptive\n#### 3.10.1 P-Eq. 5\n### x 1.2\n");
    assert_eq!(s.into_iter().collect::<Vec<_>>(), ["3.10.1", "4", "4.12"]);
}
