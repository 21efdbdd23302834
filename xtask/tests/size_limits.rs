//! Size limits of the source (issue 20): no Rust file under `crates/` or `xtask/` is longer
//! than [`MAX_FILE_LINES`] lines and no function longer than [`MAX_FN_LINES`] lines, except
//! the ones listed below with the reason. A function is counted from its `fn` line to the
//! first line that closes it at the same indentation (rustfmt's layout).
//!
//! `cargo test -p xtask --release --test size_limits -- --nocapture` prints every file and
//! function over the limits, listed or not.

use std::path::{Path, PathBuf};

/// Longest source file [lines].
const MAX_FILE_LINES: usize = 800;
/// Longest function [lines].
const MAX_FN_LINES: usize = 120;

/// Files allowed over [`MAX_FILE_LINES`]: (path from the workspace root, why).
const FILE_EXCEPTIONS: &[(&str, &str)] = &[
    (
        "crates/case/tests/bad_input.rs",
        "a table of rejected inputs, one short test each; grows with the wall types",
    ),
    (
        "crates/case/tests/fuzz_check.rs",
        "the fuzz test's independent table of physical bands",
    ),
];

/// Functions allowed over [`MAX_FN_LINES`]: (file, function, why).
const FN_EXCEPTIONS: &[(&str, &str, &str)] = &[
    (
        "crates/case/tests/fuzz_check.rs",
        "case_violations",
        "one band check per case field: a table in code",
    ),
    (
        "crates/solver/tests/fluidized_bed.rs",
        "fluidized_bed_hangs_on_the_gas_pressure_drop",
        "one scenario test, moved with the verification code",
    ),
];

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("the workspace root")
        .to_path_buf()
}

/// Every `.rs` file below `dir` (without `target/`), as paths from the workspace root.
fn rust_files(root: &Path, dir: &Path, out: &mut Vec<String>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.filter_map(Result::ok) {
        let path = entry.path();
        if path.is_dir() {
            if path.file_name().is_some_and(|n| n != "target") {
                rust_files(root, &path, out);
            }
        } else if path.extension().is_some_and(|e| e == "rs") {
            let rel = path.strip_prefix(root).expect("below the root");
            out.push(rel.to_string_lossy().replace('\\', "/"));
        }
    }
}

/// The name of the function a line declares, if it does (`pub`, `const`, `async`,
/// `unsafe` allowed before `fn`).
fn declared_fn(line: &str) -> Option<&str> {
    let mut rest = line.trim_start();
    loop {
        let next = [
            "pub(crate) ",
            "pub(super) ",
            "pub ",
            "const ",
            "async ",
            "unsafe ",
        ]
        .iter()
        .find_map(|p| rest.strip_prefix(p));
        match next {
            Some(r) => rest = r,
            None => break,
        }
    }
    let name = rest.strip_prefix("fn ")?;
    let end = name
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(name.len());
    Some(&name[..end])
}

/// (function, first line (1-based), length in lines) of every function of `text` longer
/// than `limit`.
fn long_functions(text: &str, limit: usize) -> Vec<(String, usize, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (k, line) in lines.iter().enumerate() {
        let Some(name) = declared_fn(line) else {
            continue;
        };
        let indent = &line[..line.len() - line.trim_start().len()];
        let close = format!("{indent}}}");
        let end = lines[k..]
            .iter()
            .position(|l| l.trim_end() == close || (l.trim_end().ends_with(';') && *l == *line));
        if let Some(n) = end.map(|e| e + 1).filter(|&n| n > limit) {
            out.push((name.to_string(), k + 1, n));
        }
    }
    out
}

/// Every file and function over the limits: (file, function or "", lines).
fn offenders() -> Vec<(String, String, usize)> {
    let root = workspace();
    let mut files = Vec::new();
    for dir in ["crates", "xtask"] {
        rust_files(&root, &root.join(dir), &mut files);
    }
    files.sort();
    let mut out = Vec::new();
    for file in files {
        let text = std::fs::read_to_string(root.join(&file)).expect("a readable source file");
        let n = text.lines().count();
        if n > MAX_FILE_LINES {
            out.push((file.clone(), String::new(), n));
        }
        for (name, _, len) in long_functions(&text, MAX_FN_LINES) {
            out.push((file.clone(), name, len));
        }
    }
    out
}

fn excepted(file: &str, function: &str) -> bool {
    if function.is_empty() {
        FILE_EXCEPTIONS.iter().any(|e| e.0 == file)
    } else {
        FN_EXCEPTIONS.iter().any(|e| e.0 == file && e.1 == function)
    }
}

#[test]
fn no_file_or_function_is_over_the_size_limits() {
    let all = offenders();
    for (file, function, n) in &all {
        let what = if function.is_empty() {
            "file".to_string()
        } else {
            format!("fn {function}")
        };
        let mark = if excepted(file, function) {
            " (listed)"
        } else {
            ""
        };
        println!("{file}: {what}: {n} lines{mark}");
    }
    let new: Vec<String> = all
        .iter()
        .filter(|(f, name, _)| !excepted(f, name))
        .map(|(f, name, n)| format!("{f} {name} ({n} lines)"))
        .collect();
    assert!(
        new.is_empty(),
        "over {MAX_FILE_LINES} lines a file or {MAX_FN_LINES} a function (split it, or list it \
         with a reason in xtask/tests/size_limits.rs): {}",
        new.join("; ")
    );
}

#[test]
fn functions_are_measured_from_fn_to_their_closing_brace() {
    let text = "pub(crate) fn a() {\n    x();\n}\n\nimpl S {\n    pub fn b(&self) {\n    }\n}\n\
                trait T {\n    fn c(&self);\n}\n";
    assert_eq!(long_functions(text, 2), vec![("a".into(), 1, 3)]);
    assert_eq!(
        long_functions(text, 0).len(),
        3,
        "a, b and the declaration c"
    );
    assert_eq!(declared_fn("    const fn n("), Some("n"));
    assert_eq!(declared_fn("let f = 1;"), None);
}
