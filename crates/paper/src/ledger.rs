//! The metrics ledger: `docs/reports/results/ledger/<fidelity>.csv`, committed, one row per case of
//! every finished run the report has read (`RunRecord`, the columns of `row.rs`),
//! sorted by case. Run folders do not survive a change of machine; the ledger does, so the
//! findings of a fidelity can be judged from runs made in earlier sessions, on a cluster or
//! by another command (`cargo xtask ledger add RUN_DIR...`).
//!
//! A run folder read by the report replaces its case's row at its fidelity; rows of runs
//! not on this machine are kept. Smoke runs are not recorded: they are a CI check whose
//! numbers move with every solver change, and CI's report (on a clean checkout) then
//! leaves the committed files as they are.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use runout_case::Fidelity;
use runout_post::case_data::{CaseData, Cases};
use runout_post::chosen::Run;

use super::record::{is_finished, RunRecord, Source};
use super::row::{columns, from_row, to_row, Cells};

/// The ledger's folder, relative to the reports directory (docs/reports/).
pub const LEDGER_DIR: &str = "results/ledger";
/// The fidelities the ledger records, coarsest first.
pub const LEDGER_FIDELITIES: [Fidelity; 3] = [Fidelity::Coarse, Fidelity::Wall, Fidelity::Paper];

/// The rows of every fidelity, by fidelity name and case.
pub struct Ledger {
    dir: PathBuf,
    rows: BTreeMap<&'static str, BTreeMap<String, RunRecord>>,
}

/// Reads one fidelity's file; an absent file is an empty ledger.
fn read_file(path: &Path) -> Result<BTreeMap<String, RunRecord>> {
    let mut rows = BTreeMap::new();
    if !path.exists() {
        return Ok(rows);
    }
    let mut rd =
        csv::Reader::from_path(path).with_context(|| format!("reading {}", path.display()))?;
    let header = rd.headers()?.clone();
    for (k, row) in rd.records().enumerate() {
        let row = row.with_context(|| format!("{}: row {}", path.display(), k + 1))?;
        let r = from_row(&Cells::new(&header, &row))
            .map_err(anyhow::Error::msg)
            .with_context(|| format!("{}: row {}", path.display(), k + 1))?;
        rows.insert(r.case.clone(), r);
    }
    Ok(rows)
}

/// One fidelity's rows as CSV text, sorted by case.
fn csv_text(rows: &BTreeMap<String, RunRecord>) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(columns())?;
    for r in rows.values() {
        w.write_record(to_row(r))?;
    }
    Ok(String::from_utf8(w.into_inner()?)?)
}

impl Ledger {
    /// Reads the ledger under the reports directory `reports`.
    pub fn read(reports: &Path) -> Result<Ledger> {
        let dir = reports.join(LEDGER_DIR);
        let mut rows = BTreeMap::new();
        for f in LEDGER_FIDELITIES {
            rows.insert(f.name(), read_file(&dir.join(format!("{f}.csv")))?);
        }
        Ok(Ledger { dir, rows })
    }

    /// The row of `case` at `fidelity`.
    pub fn get(&self, fidelity: Fidelity, case: &str) -> Option<&RunRecord> {
        self.rows.get(fidelity.name())?.get(case)
    }

    /// Records a run, replacing its case's row; false (nothing recorded) for a smoke run.
    pub fn put(&mut self, mut r: RunRecord) -> bool {
        r.source = Source::Ledger;
        match self.rows.get_mut(r.fidelity.name()) {
            Some(rows) => {
                rows.insert(r.case.clone(), r);
                true
            }
            None => false,
        }
    }

    /// Records the finished store run of each named case of `cases` (loaded at one
    /// fidelity); returns how many rows were written.
    pub fn put_store<S: AsRef<str>>(&mut self, names: &[S], cases: &Cases) -> usize {
        let mut n = 0;
        for case in names.iter().map(AsRef::as_ref) {
            let d = cases.get(case);
            let finished = d.run.as_ref().is_ok_and(|r| is_finished(&r.summary.status));
            if let Some(r) = RunRecord::from_store(case, &d).filter(|_| finished) {
                n += usize::from(self.put(r));
            }
        }
        n
    }

    /// Writes every fidelity that has rows (a file whose text is unchanged is not touched).
    pub fn write(&self) -> Result<()> {
        for (name, rows) in &self.rows {
            let path = self.dir.join(format!("{name}.csv"));
            if rows.is_empty() && !path.exists() {
                continue;
            }
            let text = csv_text(rows)?;
            if std::fs::read_to_string(&path).ok().as_deref() == Some(text.as_str()) {
                continue;
            }
            std::fs::create_dir_all(&self.dir)
                .with_context(|| format!("creating {}", self.dir.display()))?;
            runout_output::write_atomic(&path, text.as_bytes())
                .with_context(|| format!("writing {}", path.display()))?;
        }
        Ok(())
    }
}

/// What `cargo xtask ledger add` is told beyond the folders.
#[derive(Default)]
pub struct AddOptions {
    /// the case, if the summary's name is not the matrix's (one folder only)
    pub case: Option<String>,
    /// the fidelity, if the summary's is not the one to record under
    pub fidelity: Option<Fidelity>,
    /// the solver's `git describe`, for folders that do not record it
    pub solver: Option<String>,
}

/// The record of one run folder.
fn record_of(dir: &Path, opts: &AddOptions) -> Result<RunRecord> {
    let run = Run::read(dir, opts.fidelity).map_err(anyhow::Error::msg)?;
    if !is_finished(&run.summary.status) {
        bail!(
            "{}: the run has not finished ({:?}); continue it first",
            dir.display(),
            run.summary.status
        );
    }
    let case = opts
        .case
        .clone()
        .unwrap_or_else(|| run.summary.case.clone());
    let data = CaseData::of_run(run);
    let mut r = RunRecord::from_store(&case, &data).context("no run")?;
    if let Some(s) = &opts.solver {
        if r.solver == super::record::UNKNOWN_SOLVER {
            r.solver = s.clone();
        }
    }
    Ok(r)
}

/// The grid of `case` at `f` in the paper's matrix under `cases`; `None` if it is not a
/// case of the matrix.
fn matrix_grid(cases: &Path, case: &str, f: Fidelity) -> Result<Option<(usize, usize)>> {
    let matrix = crate::matrix::paper_matrix(cases)?;
    let Some(run) = matrix.runs.iter().find(|r| r.case.name == case) else {
        return Ok(None);
    };
    let grid = run.case.at_fidelity(f).grid()?;
    Ok(Some((grid.nx(), grid.ny())))
}

/// Refuses a record whose grid is not its case's grid at its fidelity (a run of the
/// error-time ladder says "paper" at every level); notes a case outside the matrix.
fn check_grid(cases: &Path, r: &RunRecord) -> Result<()> {
    match matrix_grid(cases, &r.case, r.fidelity)? {
        Some(g) if g != r.cells => bail!(
            "{} ran on {} × {} cells, not the {} grid of the matrix ({} × {}): give the \
             fidelity whose grid it is (--fidelity)",
            r.case,
            r.cells.0,
            r.cells.1,
            r.fidelity,
            g.0,
            g.1
        ),
        Some(_) => Ok(()),
        None => {
            println!(
                "note: `{}` is not a case of the paper's matrix; its row is kept, the report \
                 does not read it (--case names the matrix case)",
                r.case
            );
            Ok(())
        }
    }
}

/// `cargo xtask ledger add RUN_DIR...`: records each run folder in the ledger under the
/// reports directory `reports` (docs/reports/), checked against the matrix of the case
/// directory `cases`.
pub fn add(reports: &Path, cases: &Path, dirs: &[PathBuf], opts: &AddOptions) -> Result<()> {
    if opts.case.is_some() && dirs.len() > 1 {
        bail!("--case names the case of one folder; give one RUN_DIR");
    }
    let mut ledger = Ledger::read(reports)?;
    for dir in dirs {
        let r = record_of(dir, opts)?;
        check_grid(cases, &r).with_context(|| dir.display().to_string())?;
        let line = format!(
            "{} {} ({} × {}, to t = {} s, solver {})",
            r.case, r.fidelity, r.cells.0, r.cells.1, r.end_time, r.solver
        );
        if !ledger.put(r) {
            bail!(
                "{}: smoke runs are not recorded (the ledger holds coarse, wall and paper)",
                dir.display()
            );
        }
        println!("recorded {line}");
    }
    ledger.write()
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_post::fixture::*;

    #[test]
    fn store_runs_replace_their_rows_and_other_rows_stay() {
        let tmp = TempDir::new("ledger");
        let runs = tmp.0.join("runs");
        let docs = tmp.0.join("docs");
        let profile = "profile_x11_t1.25.csv";
        write_run(&runs, "A", "coarse", 1.25, &[(profile, CUSHION_PROFILE)]);
        write_run(&runs, "B", "coarse", 1.25, &[(profile, DENSE_PROFILE)]);
        write_run(&runs, "A", "smoke", 0.4, &[]);
        let mut ledger = Ledger::read(&docs).unwrap();
        let cases = Cases::load(&runs, ["A", "B"], Some(Fidelity::Coarse));
        let n = ledger.put_store(&["A", "B"], &cases);
        assert_eq!(n, 2);
        ledger.write().unwrap();
        let file = docs.join(LEDGER_DIR).join("coarse.csv");
        let text = std::fs::read_to_string(&file).unwrap();
        assert_eq!(text.lines().count(), 3, "a header and two rows:\n{text}");
        assert!(text
            .lines()
            .nth(1)
            .unwrap()
            .starts_with("A,coarse,10,4,1.25,completed,unknown,"));
        assert!(
            !docs.join(LEDGER_DIR).join("wall.csv").exists(),
            "no empty files"
        );

        // B's folder is gone, A's run is redone: A's row changes, B's stays
        std::fs::remove_dir_all(runs.join("B")).unwrap();
        write_run(&runs, "A", "coarse", 1.25, &[(profile, DENSE_PROFILE)]);
        let mut ledger = Ledger::read(&docs).unwrap();
        assert_eq!(
            ledger
                .get(Fidelity::Coarse, "B")
                .unwrap()
                .station
                .as_ref()
                .unwrap()
                .floor_eps_s,
            0.6
        );
        let cases = Cases::load(&runs, ["A", "B"], Some(Fidelity::Coarse));
        assert_eq!(ledger.put_store(&["A", "B"], &cases), 1);
        ledger.write().unwrap();
        let ledger = Ledger::read(&docs).unwrap();
        let a = ledger.get(Fidelity::Coarse, "A").unwrap();
        assert_eq!(a.station.as_ref().unwrap().air_cushion, Some(false));
        assert!(ledger.get(Fidelity::Coarse, "B").is_some());

        // a folder elsewhere, with its solver stated; smoke is refused, and so is a run
        // whose grid is not its case's at the fidelity it claims
        let cases = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases");
        let elsewhere = tmp.0.join("cluster");
        write_run(
            &elsewhere,
            "C",
            "paper",
            1.25,
            &[(profile, CUSHION_PROFILE)],
        );
        write_run(
            &elsewhere,
            "S-RJJ",
            "paper",
            1.25,
            &[(profile, CUSHION_PROFILE)],
        );
        let opts = AddOptions {
            solver: Some("5eeb3c3".into()),
            ..AddOptions::default()
        };
        let add = |dir: PathBuf| add(&docs, &cases, &[dir], &opts).map_err(|e| format!("{e:#}"));
        add(elsewhere.join("C").join("paper")).unwrap();
        let ledger = Ledger::read(&docs).unwrap();
        assert_eq!(ledger.get(Fidelity::Paper, "C").unwrap().solver, "5eeb3c3");
        let err = add(runs.join("A").join("smoke")).unwrap_err();
        assert!(err.contains("smoke runs are not recorded"), "{err}");
        let err = add(elsewhere.join("S-RJJ").join("paper")).unwrap_err();
        assert!(
            err.contains("ran on 10 × 4 cells, not the paper grid of the matrix (1000 × 90)"),
            "{err}"
        );
    }
}
