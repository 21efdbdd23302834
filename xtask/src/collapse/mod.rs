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

pub mod column;
mod fields;
mod front;
mod page;
mod plot;
mod run;

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use runout_case::{load, Fidelity, Loaded};

use self::run::{run_one, Outcome};
use runout_verification::references::LAJEUNESSE;

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
/// μ(I): largest relative distance of (L∞ − L0)/L0 from Lajeunesse et al.'s (issue 43).
const RUNOUT_TOLERANCE: f64 = 0.25;
/// The template of the μ(I) columns (glass beads as the laboratory ran them).
const MU_I_TEMPLATE: &str = "cases/collapse/CM-a1.ron";
/// The template of `--aspect` columns with Princeton (the paper's material).
const PRINCETON_TEMPLATE: &str = "cases/collapse/C-a1.ron";
/// The aspect ratios run by default.
pub const DEFAULT_ASPECTS: [f64; 4] = [0.5, 1.0, 3.0, 6.0];

/// The friction law of a collapse check.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Friction {
    /// the paper's material and Princeton friction (the four shipped C-a* cases), untuned:
    /// the check fails only on a failed run or lost mass
    Princeton,
    /// glass beads with μ(I) (cases/collapse/CM-a1.ron as template): the runout within 25 %
    /// of Lajeunesse et al.'s and the deposit at rest by 10 √(H0/g)
    MuI,
}

impl Friction {
    /// `princeton` or `mu-i`.
    pub fn parse(s: &str) -> Result<Self> {
        match s {
            "princeton" => Ok(Self::Princeton),
            "mu-i" => Ok(Self::MuI),
            _ => bail!("--friction {s}: expected princeton or mu-i"),
        }
    }
}

/// Runs the collapse check at `fidelity` (smoke or coarse) with `friction` and writes its
/// report; `aspects` builds the columns of those a from the friction's template (default:
/// the four shipped Princeton cases, or μ(I) columns of a = 0.5, 1, 3, 6); `reuse` takes
/// finished runs of unchanged cases instead of rerunning them.
pub fn verify(
    root: &Path,
    fidelity: Fidelity,
    reuse: bool,
    friction: Friction,
    aspects: Option<Vec<f64>>,
) -> Result<()> {
    // the cells as written (L0/20) for μ(I)'s grid study; Princeton's four columns are
    // reported at smoke and coarse
    if fidelity == Fidelity::Paper && friction == Friction::Princeton {
        bail!("`verify collapse` runs Princeton at smoke or coarse fidelity (mu-i also at paper)");
    }
    let cases = columns(root, friction, aspects)?;
    let mut outcomes = Vec::new();
    for case in &cases {
        outcomes.push(run_one(root, case, fidelity, reuse)?);
    }
    let table = page::markdown_table(&outcomes);
    println!("\n{table}");
    write_report(root, fidelity, friction, &outcomes, &table)?;
    let mut failures = failures(&outcomes);
    if friction == Friction::MuI {
        failures.extend(law_failures(&outcomes));
    }
    if !failures.is_empty() {
        bail!(
            "{} collapse run(s) failed:\n  {}",
            failures.len(),
            failures.join("\n  ")
        );
    }
    Ok(())
}

/// The columns of the check: the shipped Princeton cases, or those of `aspects` built from
/// the friction's template.
fn columns(
    root: &Path,
    friction: Friction,
    aspects: Option<Vec<f64>>,
) -> Result<Vec<runout_case::Case>> {
    let from_file = |path: &Path| -> Result<Vec<runout_case::Case>> {
        let Loaded::Cases(cases) = load(path)? else {
            bail!("{} is not a case file", path.display());
        };
        Ok(cases.into_iter().map(|c| c.case).collect())
    };
    let template = match friction {
        Friction::Princeton => PRINCETON_TEMPLATE,
        Friction::MuI => MU_I_TEMPLATE,
    };
    match (friction, aspects) {
        (Friction::Princeton, None) => {
            let mut cases = Vec::new();
            for path in case_paths(root) {
                cases.extend(from_file(&path)?);
            }
            Ok(cases)
        }
        (_, aspects) => {
            let template = from_file(&root.join(template))?
                .pop()
                .context("the template holds one case")?;
            aspects
                .unwrap_or_else(|| DEFAULT_ASPECTS.to_vec())
                .iter()
                .map(|&a| column::column_case(&template, a))
                .collect()
        }
    }
}

/// μ(I)'s thresholds: the runout to the grain edge (solids height ≥ one grain diameter,
/// `runout_post::deposit`) within 25 % of Lajeunesse et al.'s (of the nearer end of its
/// range where a lies in the crossover) and the deposit at rest by 10 √(H0/g).
fn law_failures(outcomes: &[Outcome]) -> Vec<String> {
    let mut failures = Vec::new();
    for o in outcomes {
        let (lo, hi) = LAJEUNESSE.runout(o.column.aspect());
        let r = o.grain_runout;
        let off = if r < lo {
            (lo - r) / lo
        } else if r > hi {
            (r - hi) / hi
        } else {
            0.0
        };
        if off > RUNOUT_TOLERANCE || o.front.reached_end_wall {
            failures.push(format!(
                "{}: runout {r:.2}, {:.0} % from Lajeunesse's {} (limit {:.0} %)",
                o.name,
                100.0 * off,
                LAJEUNESSE.label(o.column.aspect()),
                100.0 * RUNOUT_TOLERANCE
            ));
        }
        match o.front.rest_time {
            Some(t) if t <= column::REST_DEADLINE => {}
            _ => failures.push(format!(
                "{}: not at rest by {} √(H0/g) (mean u_s {:.1} % of √(g H0) at the end)",
                o.name,
                column::REST_DEADLINE,
                100.0 * o.front.mean_u
            )),
        }
    }
    failures
}

/// Writes the report and the figure: docs/collapse.md and docs/collapse/runout.svg
/// (Princeton) or docs/collapse-mu-i.md and docs/collapse/runout-mu-i.svg (μ(I)) at coarse,
/// runs/collapse-report/<fidelity>/ otherwise.
fn write_report(
    root: &Path,
    fidelity: Fidelity,
    friction: Friction,
    outcomes: &[Outcome],
    table: &str,
) -> Result<()> {
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
    let (figure_name, report_name) = match friction {
        Friction::Princeton => ("runout.svg", "collapse.md"),
        Friction::MuI => ("runout-mu-i.svg", "collapse-mu-i.md"),
    };
    let figure = figure_dir.join(figure_name);
    plot::draw(outcomes, &figure)?;
    let report = out_dir.join(report_name);
    let figure_link = figure
        .strip_prefix(&out_dir)
        .unwrap_or(&figure)
        .display()
        .to_string();
    let text = match friction {
        Friction::Princeton => page::document(outcomes, fidelity, table, &figure_link),
        Friction::MuI => page::document_mu_i(outcomes, fidelity, table, &figure_link),
    };
    std::fs::write(&report, text).with_context(|| format!("writing {}", report.display()))?;
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

    /// A built column holds its a, reaches 10 √(H0/g), has cell counts the smoke preset
    /// divides, and room for 2.5 times Lajeunesse's runout; bad a is refused.
    #[test]
    fn columns_of_any_aspect_from_the_template() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        let cases = columns(root, Friction::MuI, Some(vec![0.5, 2.0, 8.0])).unwrap();
        for (case, a) in cases.iter().zip([0.5, 2.0, 8.0]) {
            let column = Column::of(case).unwrap();
            assert_eq!(column.aspect(), a);
            assert_eq!(case.name, format!("CM-a{a}"));
            let end = column::REST_DEADLINE * column.time_scale();
            assert!(case.run.end_time >= end && case.run.end_time < end + 1e-3);
            let grid = case.grid().unwrap();
            assert_eq!((grid.nx() % 4, grid.ny() % 4), (0, 0));
            let (_, laj) = LAJEUNESSE.runout(a);
            assert!(grid.x.end() >= column.l0 * (1.0 + 2.5 * laj));
            assert!(runout_case::validate_case(case).is_ok());
        }
        assert!(columns(root, Friction::MuI, Some(vec![0.0])).is_err());
        assert_eq!(columns(root, Friction::Princeton, None).unwrap().len(), 4);
    }

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
