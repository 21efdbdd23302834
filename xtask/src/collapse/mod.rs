//! `cargo xtask verify collapse [--fidelity smoke|coarse]`: issue 7's granular column
//! collapse check (family C, cases/collapse/, verification-notes.md §2f).
//!
//! Runs the four columns a = H0/L0 = 0.5, 1, 3, 6 one after the other into
//! `runs/<case>/<fidelity>/`, reads the front of the bulk monitor (the largest x whose floor
//! cell has εs ≥ 0.01) and the last field file, and reports the runout (L∞ − L0)/L0 beside
//! the laboratory laws of Lajeunesse et al. (2005) and Lube et al. (2005), untuned: nothing
//! is fitted and no agreement is required. The check fails only if a run does not complete
//! or loses solids mass. At `coarse` the table goes to docs/collapse.md and the log–log
//! figure to docs/collapse/runout.svg; at `smoke` both go to runs/collapse-report/smoke/
//! (the committed report is the coarse one). With `--reuse`, a finished run whose
//! `resolved.ron` equals the case as it would run now is read instead of rerun (its
//! recorded wall time is reported), e.g. to regenerate the report after changing it.
//!
//! The parts, one a file: [`column`] (the initial column and its scales), `runout_verification::references::runout_laws` (the
//! laboratory runout laws), [`run`] (running or reusing one column and measuring it, from
//! [`front`], the bulk monitor's front history, and [`fields`], the last field file),
//! [`page`] (the report) and [`plot`] (the figure); this file holds the check's stages.

mod column;
mod fields;
mod front;
mod page;
mod plot;
mod run;

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use runout_case::{load, Fidelity, Loaded};

use self::run::{run_one, Outcome};

/// The folder of the collapse cases under cases/ (left out of `cargo xtask sweep`).
pub const COLLAPSE_DIR: &str = "collapse";

/// The four columns, smallest aspect ratio first.
const CASE_FILES: [&str; 4] = [
    "cases/collapse/C-a0.5.ron",
    "cases/collapse/C-a1.ron",
    "cases/collapse/C-a3.ron",
    "cases/collapse/C-a6.ron",
];
/// Largest relative change of the solids mass accepted over a run.
const MASS_TOLERANCE: f64 = 1e-8;

/// Runs the collapse check at `fidelity` (smoke or coarse) and writes its report; `reuse`
/// takes finished runs of unchanged cases instead of rerunning them.
pub fn verify(root: &Path, fidelity: Fidelity, reuse: bool) -> Result<()> {
    if fidelity == Fidelity::Paper {
        bail!("`verify collapse` runs at smoke or coarse fidelity");
    }
    let mut outcomes = Vec::new();
    for path in case_paths(root) {
        let Loaded::Cases(cases) = load(&path)? else {
            bail!("{} is not a case file", path.display());
        };
        for c in cases {
            outcomes.push(run_one(root, &c.case, fidelity, reuse)?);
        }
    }
    let table = page::markdown_table(&outcomes);
    println!("\n{table}");
    write_report(root, fidelity, &outcomes, &table)?;
    let failures = failures(&outcomes);
    if !failures.is_empty() {
        bail!(
            "{} collapse run(s) failed:\n  {}",
            failures.len(),
            failures.join("\n  ")
        );
    }
    Ok(())
}

/// Writes the report and the figure: docs/collapse.md and docs/collapse/runout.svg at
/// coarse, runs/collapse-report/<fidelity>/ otherwise.
fn write_report(root: &Path, fidelity: Fidelity, outcomes: &[Outcome], table: &str) -> Result<()> {
    let out_dir = match fidelity {
        Fidelity::Coarse => root.join("docs"),
        _ => root.join("runs/collapse-report").join(fidelity.name()),
    };
    let figure_dir = match fidelity {
        Fidelity::Coarse => out_dir.join("collapse"),
        _ => out_dir.clone(),
    };
    std::fs::create_dir_all(&figure_dir)
        .with_context(|| format!("creating {}", figure_dir.display()))?;
    let figure = figure_dir.join("runout.svg");
    plot::draw(outcomes, &figure)?;
    let report = out_dir.join("collapse.md");
    let figure_link = figure
        .strip_prefix(&out_dir)
        .unwrap_or(&figure)
        .display()
        .to_string();
    std::fs::write(
        &report,
        page::document(outcomes, fidelity, table, &figure_link),
    )
    .with_context(|| format!("writing {}", report.display()))?;
    println!("wrote {} and {}", report.display(), figure.display());
    Ok(())
}

/// What fails the check: a run that did not complete, or lost or gained solids mass.
fn failures(outcomes: &[Outcome]) -> Vec<String> {
    let mut failures = Vec::new();
    for o in outcomes {
        if !o.completed() {
            failures.push(format!("{}: {:?}", o.name, o.summary.status));
        }
        if o.summary.solids_mass_change.abs() > MASS_TOLERANCE {
            failures.push(format!(
                "{}: solids mass changed by {:.2e} (limit {MASS_TOLERANCE:e})",
                o.name, o.summary.solids_mass_change
            ));
        }
    }
    failures
}

/// The case files of the check.
pub fn case_paths(root: &Path) -> Vec<PathBuf> {
    CASE_FILES.iter().map(|f| root.join(f)).collect()
}

#[cfg(test)]
mod tests {
    use super::column::Column;
    use super::*;

    #[test]
    fn shipped_collapse_cases_are_columns_of_the_four_aspect_ratios() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        let aspects: Vec<f64> = case_paths(root)
            .iter()
            .map(|p| {
                let Loaded::Cases(c) = load(p).unwrap() else {
                    panic!("{} is not a case", p.display())
                };
                Column::of(&c[0].case).unwrap().aspect()
            })
            .collect();
        for (a, want) in aspects.iter().zip([0.5, 1.0, 3.0, 6.0]) {
            assert_eq!(*a, want, "{aspects:?}");
        }
    }
}
