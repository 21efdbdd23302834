//! The record the findings and tables read for each case: its run folder on this machine
//! (the store) if it has one at the fidelity, else its row of the ledger; at one fidelity,
//! or the best fidelity that has either (paper, then wall, then coarse, then smoke).

use std::collections::BTreeMap;
use std::path::Path;

use runout_case::Fidelity;
use runout_post::case_data::{CaseData, Cases};
use runout_post::chosen::BEST_FIRST;

use super::ledger::Ledger;
use super::record::{RunRecord, Source};

/// Each case's record, or why it has none.
pub struct Records {
    by_case: BTreeMap<String, Result<RunRecord, String>>,
}

/// The store runs of every case at each fidelity.
pub struct Store {
    /// (fidelity, the cases loaded at it), best first
    pub at: Vec<(Fidelity, Cases)>,
}

impl Store {
    /// Every named case's run folders under `runs`, at each fidelity.
    pub fn load<S: AsRef<str>>(runs: &Path, names: &[S]) -> Store {
        Store {
            at: BEST_FIRST
                .iter()
                .map(|&f| {
                    (
                        f,
                        Cases::load(runs, names.iter().map(AsRef::as_ref), Some(f)),
                    )
                })
                .collect(),
        }
    }

    /// The cases loaded at `f`.
    pub fn cases(&self, f: Fidelity) -> Option<&Cases> {
        self.at.iter().find(|(g, _)| *g == f).map(|(_, c)| c)
    }
}

/// The record of `case` at `f`: its store run, else its ledger row; else why not.
fn record_at(case: &str, f: Fidelity, store: &Store, ledger: &Ledger) -> Result<RunRecord, String> {
    let data = store.cases(f).map(|c| c.get(case));
    let from_store = data.as_ref().and_then(|d| RunRecord::from_store(case, d));
    match (from_store, ledger.get(f, case)) {
        (Some(r), _) => Ok(r),
        (None, Some(r)) => Ok(r.clone()),
        (None, None) => Err(match data.and_then(|d| d.run.as_ref().err().cloned()) {
            Some(why) if why.starts_with("not run") || why.is_empty() => {
                format!("not run at {f} fidelity")
            }
            Some(why) => why,
            None => format!("not run at {f} fidelity"),
        }),
    }
}

impl Records {
    /// Every named case at `requested`, or at the best fidelity it has.
    pub fn choose<S: AsRef<str>>(
        names: &[S],
        store: &Store,
        ledger: &Ledger,
        requested: Option<Fidelity>,
    ) -> Records {
        let by_case = names
            .iter()
            .map(AsRef::as_ref)
            .map(|case| {
                let r = match requested {
                    Some(f) => record_at(case, f, store, ledger),
                    None => BEST_FIRST
                        .iter()
                        .find_map(|&f| record_at(case, f, store, ledger).ok())
                        .ok_or_else(|| "not run".to_string()),
                };
                (case.to_string(), r)
            })
            .collect();
        Records { by_case }
    }

    /// The one run read into `data`, as the record of `case` (a run folder outside the
    /// matrix's store, e.g. a level of `cargo xtask error-time`).
    pub fn of_one(case: &str, data: &CaseData) -> Records {
        let record = RunRecord::from_store(case, data).ok_or_else(|| match &data.run {
            Err(why) => why.clone(),
            Ok(_) => "the run has not ended for good".to_string(),
        });
        Records {
            by_case: BTreeMap::from([(case.to_string(), record)]),
        }
    }

    /// The record of `case`, or why it has none.
    pub fn get(&self, case: &str) -> Result<&RunRecord, String> {
        match self.by_case.get(case) {
            Some(r) => r.as_ref().map_err(Clone::clone),
            None => Err("not in the case matrix".into()),
        }
    }

    /// The cases that have a record from `source`.
    pub fn with_source(&self, source: Source) -> Vec<&str> {
        self.by_case
            .iter()
            .filter(|(_, r)| r.as_ref().is_ok_and(|r| r.source == source))
            .map(|(c, _)| c.as_str())
            .collect()
    }

    /// The fidelities of the records, in case order.
    pub fn fidelities(&self) -> Vec<Fidelity> {
        self.by_case
            .values()
            .filter_map(|r| r.as_ref().ok().map(|r| r.fidelity))
            .collect()
    }
}

/// The records of the run folders under `runs` alone (no ledger), for tests.
#[cfg(test)]
pub fn from_runs(runs: &Path, names: &[&str], requested: Option<Fidelity>) -> Records {
    let ledger = Ledger::read(&runs.join("no-docs")).expect("an empty ledger");
    Records::choose(names, &Store::load(runs, names), &ledger, requested)
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_post::fixture::*;

    #[test]
    fn a_store_run_comes_before_a_ledger_row_and_a_better_fidelity_before_both() {
        let tmp = TempDir::new("records");
        let runs = tmp.0.join("runs");
        let docs = tmp.0.join("docs");
        let p = "profile_x11_t1.25.csv";
        write_run(&runs, "A", "coarse", 1.25, &[(p, CUSHION_PROFILE)]);
        write_run(&runs, "B", "coarse", 1.25, &[(p, DENSE_PROFILE)]);
        let names = ["A", "B", "C"];
        let load = |runs: &Path| Store::load(runs, &names);
        let mut ledger = Ledger::read(&docs).unwrap();
        let store = load(&runs);
        ledger.put_store(&names, store.cases(Fidelity::Coarse).unwrap());
        // B has a paper row from elsewhere; A's coarse folder is gone
        let mut b = ledger.get(Fidelity::Coarse, "B").unwrap().clone();
        b.fidelity = Fidelity::Paper;
        ledger.put(b);
        std::fs::remove_dir_all(runs.join("A")).unwrap();
        let store = load(&runs);
        let best = Records::choose(&names, &store, &ledger, None);
        let a = best.get("A").unwrap();
        assert_eq!((a.fidelity, a.source), (Fidelity::Coarse, Source::Ledger));
        let b = best.get("B").unwrap();
        assert_eq!((b.fidelity, b.source), (Fidelity::Paper, Source::Ledger));
        assert_eq!(best.get("C").unwrap_err(), "not run");
        assert_eq!(best.get("D").unwrap_err(), "not in the case matrix");
        let coarse = Records::choose(&names, &store, &ledger, Some(Fidelity::Coarse));
        assert_eq!(coarse.get("B").unwrap().source, Source::Store);
        assert_eq!(coarse.with_source(Source::Ledger), vec!["A"]);
        assert_eq!(
            Records::choose(&names, &store, &ledger, Some(Fidelity::Wall))
                .get("A")
                .unwrap_err(),
            "not run at wall fidelity"
        );
    }
}
