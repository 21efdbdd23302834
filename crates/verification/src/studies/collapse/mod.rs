//! `cargo xtask verify collapse [--friction princeton|mu-i|both] [--aspect LIST]
//! [--fidelity smoke|coarse|paper] [--sidewalls W_L0,MU_W] [--reuse]`: the granular column
//! collapse check (issues 7 and 43; cases/collapse/, verification-notes.md §2f,
//! docs/studies/collapse-laws.md).
//!
//! Runs the columns one after the other into `runs/<case>/<fidelity>/` (checkpointed, so a
//! killed check continues), reads the front of the bulk monitor and the last field file, and
//! reports the runout (L∞ − L0)/L0 and the deposit height H∞/L0 beside the laboratory laws,
//! untuned. `princeton`: the paper's material in the four shipped columns; the check fails
//! only if a run does not complete or loses solids mass. `mu-i`: glass-bead columns built
//! from cases/collapse/CM-a1.ron for each a; they must also meet the thresholds of
//! [`law_failures`]. `both`: each μ(I) column and beside it the same column with Princeton
//! friction (only the μ(I) ones are judged). At `coarse` the page goes to docs/reports/
//! (collapse.md for `both`, collapse-mu-i.md, collapse-princeton.md) with its figures in
//! docs/reports/collapse/; at other fidelities, and with `--sidewalls` (every column between Coulomb
//! side walls W apart, [`column::ChannelWalls`]) at any, to
//! runs/collapse-report/<fidelity>[-<walls>]/. With `--reuse`,
//! a finished run whose `resolved.ron` equals the case as it would run now is read instead
//! of rerun.
//!
//! The parts, one a file: [`options`] (the command line's options, typed), [`mod@column`]
//! (the initial column, its scales and its Princeton twin),
//! [`crate::references::runout_laws`] (the laws), [`mod@run`] (running or reusing one
//! column and measuring it, from [`front`], the bulk monitor's front history, and
//! [`fields`], the last field file), [`grids`] (the μ(I) columns on every grid the store
//! holds), [`page`] (the report) and [`plot`] (the figures); this file holds the check's
//! stages, [`run()`], and [`Collapse`], the study of the registry that calls it.

pub mod column;
mod fields;
mod front;
mod grids;
mod options;
mod page;
mod plot;
mod run;

use std::path::{Path, PathBuf};

use anyhow::{bail, Context as _, Result};
use runout_case::{load, Fidelity, Loaded};

use self::column::ChannelWalls;
pub use self::options::{Friction, Options};
use self::run::{run_one, Outcome};
use crate::references::{ScalingLaw, LAGREE_CONTINUUM, LAJEUNESSE, LAJEUNESSE_HEIGHT};
use crate::study::{Args, Context, Study};

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

/// The collapse check as a study of the registry: [`Options`] from the command line, then
/// [`run()`].
pub struct Collapse;

impl Study for Collapse {
    fn name(&self) -> &'static str {
        "collapse"
    }

    fn description(&self) -> &'static str {
        "granular column collapse against the laboratory runout laws"
    }

    fn run(&self, args: &Args, context: &Context) -> Result<()> {
        run(context, &Options::parse(args)?)
    }
}

/// Runs the collapse check with `options` and writes its report (see [`Options`]).
pub fn run(context: &Context, options: &Options) -> Result<()> {
    let Options {
        fidelity,
        reuse,
        friction,
        ref aspects,
        walls,
    } = *options;
    let root = context.root.as_path();
    // the cells as written (L0/20) for μ(I)'s grid study; Princeton's four columns are
    // reported at smoke and coarse
    if fidelity == Fidelity::Paper && friction == Friction::Princeton {
        bail!(
            "`verify collapse` runs Princeton at smoke or coarse fidelity (mu-i and both also at paper)"
        );
    }
    let cases = columns(root, friction, aspects.clone(), walls)?;
    let mut outcomes = Vec::new();
    for case in &cases {
        outcomes.push(run_one(root, case, fidelity, reuse)?);
    }
    let mut table = page::markdown_table(&outcomes);
    table.push('\n');
    table.push_str(&grids::markdown(&grids::gather(
        root, &cases, fidelity, &outcomes,
    )?));
    println!("\n{table}");
    write_report(context, (fidelity, walls), friction, &outcomes, &table)?;
    let mut failures = failures(&outcomes);
    failures.extend(law_failures(&outcomes, walls));
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
/// the friction's template; between `walls` if given.
fn columns(
    root: &Path,
    friction: Friction,
    aspects: Option<Vec<f64>>,
    walls: Option<ChannelWalls>,
) -> Result<Vec<runout_case::Case>> {
    let cases = plane_columns(root, friction, aspects)?;
    match walls {
        None => Ok(cases),
        Some(walls) => cases.iter().map(|c| walls.apply(c)).collect(),
    }
}

/// The columns of [`columns`] without side walls.
fn plane_columns(
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
        Friction::MuI | Friction::Both => MU_I_TEMPLATE,
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
            let mut cases = Vec::new();
            for a in aspects.unwrap_or_else(|| DEFAULT_ASPECTS.to_vec()) {
                let case = column::column_case(&template, a)?;
                if friction == Friction::Both {
                    cases.push(column::with_princeton(&case));
                }
                cases.push(case);
            }
            Ok(cases)
        }
    }
}

/// The largest aspect ratio judged against the laboratory laws (the decision on issue 57,
/// verification-notes.md §2f): the laboratory channels' side walls shorten the tall columns
/// (Balmforth & Kerswell 2005: runout exponent 0.65 in narrow slots, 0.9 in wide channels)
/// and the laws' prefactors differ by 50 % between laboratories, so a plane 2-D run meets
/// them only where a ≤ 3.
pub const LABORATORY_MAX_ASPECT: f64 = 3.0;

/// How far `r` lies outside the range [lo, hi], relative to its nearer end (0 inside).
fn relative_distance(r: f64, (lo, hi): (f64, f64)) -> f64 {
    if r < lo {
        (lo - r) / lo
    } else if r > hi {
        (r - hi) / hi
    } else {
        0.0
    }
}

/// The column's runout to the grain edge more than 25 % outside `law`'s range at its a, or
/// at the end wall: the failure, said.
fn runout_failure(o: &Outcome, law: &ScalingLaw) -> Option<String> {
    let (a, r) = (o.column.aspect(), o.grain_runout);
    let off = relative_distance(r, law.runout(a));
    (off > RUNOUT_TOLERANCE || o.front.reached_end_wall).then(|| {
        format!(
            "{}: runout {r:.2}, {:.0} % from {}'s {} (limit {:.0} %)",
            o.name,
            100.0 * off,
            law.name,
            law.label(a),
            100.0 * RUNOUT_TOLERANCE
        )
    })
}

/// μ(I)'s thresholds on the μ(I) columns (the decision on issue 57): a plane 2-D run's
/// runout to the grain edge (solids height ≥ one grain diameter, `runout_post::deposit`)
/// within 25 % of the like-for-like 2-D μ(I) continuum of Lagrée, Staron & Popinet (2011)
/// at every a; where a ≤ [`LABORATORY_MAX_ASPECT`], also within 25 % of Lajeunesse et al.'s
/// (the nearer end of its range where a lies in the crossover) and H∞/L0 within 25 % of
/// their height law; and the deposit at rest by 10 √(H0/g). A column between side walls is
/// not the continuum's plane flow: it is judged against the laboratory laws where a ≤ 3.
fn law_failures(outcomes: &[Outcome], walls: Option<ChannelWalls>) -> Vec<String> {
    let mut failures = Vec::new();
    for o in outcomes.iter().filter(|o| o.mu_i) {
        let a = o.column.aspect();
        if walls.is_none() {
            failures.extend(runout_failure(o, &LAGREE_CONTINUUM));
        }
        if a <= LABORATORY_MAX_ASPECT {
            failures.extend(runout_failure(o, &LAJEUNESSE));
            let h_law = LAJEUNESSE_HEIGHT.height(a);
            let h_off = (o.height - h_law).abs() / h_law;
            if h_off > RUNOUT_TOLERANCE {
                failures.push(format!(
                    "{}: H∞/L0 {:.2}, {:.0} % from Lajeunesse's {h_law:.2} (limit {:.0} %)",
                    o.name,
                    o.height,
                    100.0 * h_off,
                    100.0 * RUNOUT_TOLERANCE
                ));
            }
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

/// Writes the report and its figures (runout against a; the deposits): at coarse without
/// side walls into docs/reports/ (`collapse.md` with both closures, `collapse-mu-i.md`,
/// `collapse-princeton.md` for the paper's material) and docs/reports/collapse/, otherwise into
/// runs/collapse-report/<fidelity>[-<walls>]/.
fn write_report(
    context: &Context,
    (fidelity, walls): (Fidelity, Option<ChannelWalls>),
    friction: Friction,
    outcomes: &[Outcome],
    table: &str,
) -> Result<()> {
    let to_docs = fidelity == Fidelity::Coarse && walls.is_none();
    let runs = context.root.join("runs/collapse-report");
    let out_dir = match walls {
        _ if to_docs => context.reports.clone(),
        None => runs.join(fidelity.name()),
        Some(w) => runs.join(format!("{}-{}", fidelity.name(), w.label())),
    };
    let figure_dir = if to_docs {
        out_dir.join("collapse")
    } else {
        out_dir.clone()
    };
    std::fs::create_dir_all(&figure_dir)
        .with_context(|| format!("creating {}", figure_dir.display()))?;
    let stem = match friction {
        Friction::Princeton => "collapse-princeton",
        Friction::MuI => "collapse-mu-i",
        Friction::Both => "collapse",
    };
    let link = |path: &Path| {
        path.strip_prefix(&out_dir)
            .unwrap_or(path)
            .display()
            .to_string()
    };
    let runout_figure = figure_dir.join(format!("{stem}-runout.svg"));
    plot::draw(outcomes, &runout_figure)?;
    let deposit_figure = figure_dir.join(format!("{stem}-deposits.svg"));
    plot::draw_deposits(outcomes, &deposit_figure)?;
    let figures = page::Figures {
        runout: link(&runout_figure),
        deposits: link(&deposit_figure),
    };
    let report = out_dir.join(format!("{stem}.md"));
    let text = match friction {
        Friction::Princeton => page::document(outcomes, fidelity, table, &figures),
        Friction::MuI | Friction::Both => page::document_mu_i(
            outcomes,
            fidelity,
            friction == Friction::Both,
            table,
            &figures,
        ),
    };
    std::fs::write(&report, text).with_context(|| format!("writing {}", report.display()))?;
    println!(
        "wrote {}, {} and {}",
        report.display(),
        runout_figure.display(),
        deposit_figure.display()
    );
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
    #[test]
    fn distance_from_a_range_is_relative_to_its_nearer_end() {
        assert_eq!(super::relative_distance(5.0, (4.0, 6.0)), 0.0);
        assert!((super::relative_distance(3.0, (4.0, 6.0)) - 0.25).abs() < 1e-12);
        assert!((super::relative_distance(7.5, (4.0, 6.0)) - 0.25).abs() < 1e-12);
    }

    use super::column::Column;
    use super::*;

    /// The repository root (two levels above this crate).
    fn repository() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
    }

    /// A built column holds its a, reaches 10 √(H0/g), has cell counts the smoke preset
    /// divides, and room for 2.5 times Lajeunesse's runout; bad a is refused.
    #[test]
    fn columns_of_any_aspect_from_the_template() {
        let root = &repository();
        let cases = columns(root, Friction::MuI, Some(vec![0.5, 2.0, 8.0]), None).unwrap();
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
        assert!(columns(root, Friction::MuI, Some(vec![0.0]), None).is_err());
        assert_eq!(
            columns(root, Friction::Princeton, None, None)
                .unwrap()
                .len(),
            4
        );
    }

    /// `both` puts the Princeton twin of each μ(I) column beside it: the same case but for
    /// the friction law and the name.
    #[test]
    fn both_builds_a_princeton_twin_of_each_column() {
        let root = &repository();
        let cases = columns(root, Friction::Both, Some(vec![1.0, 3.0]), None).unwrap();
        let names: Vec<&str> = cases.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["CMP-a1", "CM-a1", "CMP-a3", "CM-a3"]);
        for pair in cases.chunks(2) {
            let (twin, mu_i) = (&pair[0], &pair[1]);
            assert!(!column::is_mu_i(twin) && column::is_mu_i(mu_i));
            let mut same = twin.clone();
            same.models.friction = mu_i.models.friction;
            same.name = mu_i.name.clone();
            same.description = mu_i.description.clone();
            assert_eq!(&same, mu_i);
        }
    }

    /// `--sidewalls` puts each column, and its Princeton twin, between Coulomb side walls W =
    /// w L0 apart; nothing else changes; bad values are refused.
    #[test]
    fn side_walls_put_every_column_in_a_channel() {
        let root = &repository();
        let walls = ChannelWalls::parse(&[5.0, 0.38]).unwrap();
        let plane = columns(root, Friction::Both, Some(vec![6.0]), None).unwrap();
        let walled = columns(root, Friction::Both, Some(vec![6.0]), Some(walls)).unwrap();
        let names: Vec<&str> = walled.iter().map(|c| c.name.as_str()).collect();
        assert_eq!(names, ["CMP-a6-W5L0-mu0.38", "CM-a6-W5L0-mu0.38"]);
        for (p, w) in plane.iter().zip(&walled) {
            let sw = w.sidewalls.as_ref().unwrap();
            assert_eq!(sw.width, 5.0 * Column::of(p).unwrap().l0);
            assert!(runout_case::validate_case(w).is_ok());
            let mut same = w.clone();
            same.sidewalls = None;
            same.name = p.name.clone();
            same.description = p.description.clone();
            assert_eq!(&same, p);
        }
        for bad in [&[5.0][..], &[0.0, 0.3], &[5.0, -0.1], &[f64::NAN, 0.3]] {
            assert!(ChannelWalls::parse(bad).is_err(), "{bad:?}");
        }
    }

    #[test]
    fn shipped_collapse_cases_are_columns_of_the_four_aspect_ratios() {
        let root = &repository();
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
