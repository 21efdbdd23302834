//! Which cases a figure of the report drew, at which fidelity, and which it lacks and why;
//! the figure's section of results.md (image and caption).

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use runout_case::Fidelity;

use super::FIGURE_DIR;
use runout_post::case_data::{CaseData, Cases};

/// Which cases a figure drew at which fidelity, and which it lacks and why.
#[derive(Default)]
pub(super) struct Coverage {
    /// fidelity → cases drawn
    drawn: BTreeMap<String, Vec<String>>,
    /// reason → cases missing
    missing: BTreeMap<String, Vec<String>>,
}

impl Coverage {
    pub(super) fn add_drawn(&mut self, case: &str, fidelity: Option<Fidelity>) {
        let f = fidelity.map_or("?".into(), |f| f.to_string());
        let list = self.drawn.entry(f).or_default();
        if !list.iter().any(|c| c == case) {
            list.push(case.into());
        }
    }

    pub(super) fn add_missing(&mut self, case: &str, why: &str) {
        let list = self.missing.entry(why.into()).or_default();
        if !list.iter().any(|c| c == case) {
            list.push(case.into());
        }
    }

    pub(super) fn is_empty(&self) -> bool {
        self.drawn.is_empty()
    }

    /// "Fidelity: …. Missing (…): …." for the caption.
    pub(super) fn caption(&self) -> String {
        let list = |cases: &[String]| {
            cases
                .iter()
                .map(|c| format!("`{c}`"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        let mut s = String::new();
        if !self.drawn.is_empty() {
            let parts: Vec<String> = self
                .drawn
                .iter()
                .map(|(f, cases)| format!("**{f}** ({})", list(cases)))
                .collect();
            let _ = write!(s, " Fidelity: {}.", parts.join("; "));
        }
        for (why, cases) in &self.missing {
            let _ = write!(s, " **Missing** ({why}): {}.", list(cases));
        }
        s
    }
}

/// Legend label with the run's fidelity.
pub(super) fn legend(label: &str, fidelity: Option<Fidelity>) -> String {
    fidelity.map_or(label.into(), |f| format!("{label} ({f})"))
}

/// First pass over a figure's curves: which cases have data.
pub(super) fn coverage<'a>(
    cases: &Cases,
    curves: impl IntoIterator<Item = &'a str>,
    has: impl Fn(&CaseData) -> Result<(), String>,
) -> Coverage {
    let mut c = Coverage::default();
    for case in curves {
        let d = cases.get(case);
        match has(&d) {
            Ok(()) => c.add_drawn(case, d.fidelity()),
            Err(why) => c.add_missing(case, &why),
        }
    }
    c
}

/// Removes a stale figure (from an earlier report) that has no data now.
pub(super) fn remove_stale(path: &Path) -> Result<()> {
    if path.exists() {
        std::fs::remove_file(path).with_context(|| format!("removing {}", path.display()))?;
    }
    Ok(())
}

/// One section of results.md for a figure: image (if drawn) and caption.
pub(super) fn figure_section(md: &mut String, title: &str, file: Option<&str>, caption: &str) {
    let _ = writeln!(md, "### {title}\n");
    if let Some(f) = file {
        let _ = writeln!(md, "![{title}]({FIGURE_DIR}/{f})\n");
    } else {
        let _ = writeln!(md, "*No figure: no case of it has data.*\n");
    }
    let _ = writeln!(md, "{caption}\n");
}
