//! Coverage of the calibration's stated ranges (issue 62 item 2): does the 68 % range
//! (Δχ² ≤ 1 widened to the smooth response's, docs/reference/calibrate.md) contain the truth
//! about 68 % of the time, for truths the calibration was not built on?
//!
//! A coverage study recovers one parameter ([`super::recovery::recover_in`]) from each truth
//! of a list with each kind of measurement: once from the truth's exact outputs, and once per
//! noise seed with Gaussian noise of the stated σ added to them. It counts the stated ranges
//! that contain their truth. Per kind of measurement it reports:
//! - the fraction of noisy draws whose range contains the truth, p̂ = k/n, with its binomial
//!   standard error √(p̂ (1 − p̂)/n) (a range that means what it says gives p ≈ 0.68);
//! - whether every noise-free range contains its truth (it must: the model is the truth's
//!   own, so its misfit at the truth is zero).
//!
//! Every run of a study lives in one folder (`runs/` below the study's) and is reused by any
//! recovery that asks for the same parameter value: the scan's points are the same for every
//! truth, and a killed study resumes where it stopped. Each recovery's measurements,
//! evaluations and summary go to `<kind>/truth<t>[-seed<s>]/`. A study longer than a machine
//! keeps its run folders also keeps a ledger of its finished draws ([`Ledger`], a CSV file
//! committed with the repository): a draw already in it is not recovered again.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context as _, Result};

use super::recovery::{recover_in, TruthStudy};
use super::synthetic::Measured;

/// One kind of measurement of a coverage study, with its stated σ.
#[derive(Clone, Debug)]
pub struct MeasurementKind {
    /// a folder name for its recoveries (letters, digits, `-_.`)
    pub label: String,
    /// what is measured
    pub measured: Measured,
    /// the stated measurement error σ
    pub sigma: f64,
}

/// A coverage study of one parameter.
#[derive(Clone, Debug)]
pub struct CoveragePlan {
    /// the case, monitors, fidelity, parameter (its path and bounds) and calibration
    /// settings every recovery shares; its truth, measurement, σ and noise are replaced
    pub template: TruthStudy,
    /// the true values
    pub truths: Vec<f64>,
    /// the kinds of measurement
    pub kinds: Vec<MeasurementKind>,
    /// noisy draws per truth and kind (besides the noise-free recovery)
    pub draws: u64,
}

/// One recovery of a coverage study.
#[derive(Clone, Debug, PartialEq)]
pub struct Draw {
    /// the measurement kind's label
    pub kind: String,
    /// the true value
    pub truth: f64,
    /// the noise seed (none: the truth's exact outputs)
    pub seed: Option<u64>,
    /// the optimum
    pub optimum: f64,
    /// the stated range
    pub range: (f64, f64),
}

impl Draw {
    /// Whether the stated range contains the truth.
    pub fn contains_truth(&self) -> bool {
        self.range.0 <= self.truth && self.truth <= self.range.1
    }
}

/// The noise seed of draw `draw` (from 0) of truth `t` and kind `k`: distinct for every draw
/// of a study, and the same in every session, so that a resumed study repeats its draws.
pub fn seed(k: usize, t: usize, draw: u64) -> u64 {
    1 + draw + 1_000 * t as u64 + 1_000_000 * k as u64
}

/// Runs the recoveries of `plan` below `dir` (module doc) but those already in `done`,
/// calling `report` after each; a recovery that fails is reported on stderr and left out.
pub fn run_plan(
    root: &Path,
    plan: &CoveragePlan,
    dir: &Path,
    done: &Ledger,
    mut report: impl FnMut(&Draw),
) -> Result<Vec<Draw>> {
    let runs = dir.join("runs");
    std::fs::create_dir_all(&runs)?;
    let mut draws = Vec::new();
    for (k, kind) in plan.kinds.iter().enumerate() {
        for (t, &truth) in plan.truths.iter().enumerate() {
            let seeds = std::iter::once(None).chain((0..plan.draws).map(|d| Some(seed(k, t, d))));
            for noise in seeds {
                if done.has(&kind.label, truth, noise) {
                    continue;
                }
                let mut study = plan.template.clone();
                study.params[0].truth = truth;
                study.measured = kind.measured.clone();
                study.sigma = kind.sigma;
                study.noise = noise;
                let tag = match noise {
                    None => format!("truth{truth}"),
                    Some(s) => format!("truth{truth}-seed{s}"),
                };
                let out = dir.join(&kind.label).join(tag);
                std::fs::create_dir_all(&out)?;
                match recover_in(root, &study, &runs, &out) {
                    Ok(r) => {
                        let draw = Draw {
                            kind: kind.label.clone(),
                            truth,
                            seed: noise,
                            optimum: r.optimum()[0],
                            range: r.range.bounds[0],
                        };
                        report(&draw);
                        draws.push(draw);
                    }
                    Err(e) => eprintln!("{}: {e:#}", out.display()),
                }
            }
        }
    }
    Ok(draws)
}

/// The finished draws of a coverage study, one CSV row each
/// (`kind,truth,seed,optimum,low,high`, seed empty for the noise-free recovery; module doc).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Ledger {
    /// the draws, in the order they finished
    pub draws: Vec<Draw>,
}

/// One row of a [`Ledger`]'s CSV file.
#[derive(serde::Serialize, serde::Deserialize)]
struct LedgerRow {
    kind: String,
    truth: f64,
    seed: Option<u64>,
    optimum: f64,
    low: f64,
    high: f64,
}

impl Ledger {
    /// Reads a ledger; a missing file is an empty ledger.
    pub fn read(path: &Path) -> Result<Self> {
        if !path.exists() {
            return Ok(Self::default());
        }
        let mut reader = csv::Reader::from_path(path)?;
        let draws = reader
            .deserialize()
            .map(|row| {
                let r: LedgerRow = row.with_context(|| path.display().to_string())?;
                Ok(Draw {
                    kind: r.kind,
                    truth: r.truth,
                    seed: r.seed,
                    optimum: r.optimum,
                    range: (r.low, r.high),
                })
            })
            .collect::<Result<_>>()?;
        Ok(Self { draws })
    }

    /// Whether the draw of `kind`, `truth` and `seed` is in the ledger.
    pub fn has(&self, kind: &str, truth: f64, seed: Option<u64>) -> bool {
        self.draws
            .iter()
            .any(|d| d.kind == kind && d.truth == truth && d.seed == seed)
    }

    /// The ledger as CSV (values in Rust's shortest round-trip form).
    pub fn to_csv(&self) -> Result<String> {
        let mut writer = csv::Writer::from_writer(Vec::new());
        for d in &self.draws {
            writer.serialize(LedgerRow {
                kind: d.kind.clone(),
                truth: d.truth,
                seed: d.seed,
                optimum: d.optimum,
                low: d.range.0,
                high: d.range.1,
            })?;
        }
        Ok(String::from_utf8(writer.into_inner()?)?)
    }
}

/// The coverage of one kind of measurement (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct KindCoverage {
    /// the kind's label
    pub kind: String,
    /// noisy draws, and those whose range contains the truth
    pub noisy: (usize, usize),
    /// noise-free recoveries, and those whose range contains the truth
    pub noise_free: (usize, usize),
}

impl KindCoverage {
    /// p̂ = k/n over the noisy draws (NaN without any).
    pub fn fraction(&self) -> f64 {
        self.noisy.1 as f64 / self.noisy.0 as f64
    }

    /// The binomial standard error √(p̂ (1 − p̂)/n) of [`Self::fraction`].
    pub fn standard_error(&self) -> f64 {
        let p = self.fraction();
        (p * (1.0 - p) / self.noisy.0 as f64).sqrt()
    }
}

/// The coverage per kind of measurement, in the order the kinds first appear in `draws`.
pub fn summarise(draws: &[Draw]) -> Vec<KindCoverage> {
    let mut kinds: Vec<KindCoverage> = Vec::new();
    for d in draws {
        let i = match kinds.iter().position(|k| k.kind == d.kind) {
            Some(i) => i,
            None => {
                kinds.push(KindCoverage {
                    kind: d.kind.clone(),
                    noisy: (0, 0),
                    noise_free: (0, 0),
                });
                kinds.len() - 1
            }
        };
        let count = if d.seed.is_some() {
            &mut kinds[i].noisy
        } else {
            &mut kinds[i].noise_free
        };
        count.0 += 1;
        count.1 += usize::from(d.contains_truth());
    }
    kinds
}

/// The study as Markdown: one row per recovery, then the coverage per kind.
pub fn table(draws: &[Draw]) -> String {
    let mut md = String::from(
        "| measured | truth | noise seed | optimum | stated range | contains |\n|---|---|---|---|---|---|\n",
    );
    for d in draws {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {:.4} | {:.4}–{:.4} | {} |",
            d.kind,
            d.truth,
            d.seed.map_or("none".into(), |s| s.to_string()),
            d.optimum,
            d.range.0,
            d.range.1,
            if d.contains_truth() { "yes" } else { "**no**" }
        );
    }
    md.push_str(
        "\n| measured | noisy draws containing the truth | fraction ± binomial error | noise-free containing |\n|---|---|---|---|\n",
    );
    for k in summarise(draws) {
        let _ = writeln!(
            md,
            "| {} | {} of {} | {:.2} ± {:.2} | {} of {} |",
            k.kind,
            k.noisy.1,
            k.noisy.0,
            k.fraction(),
            k.standard_error(),
            k.noise_free.1,
            k.noise_free.0
        );
    }
    md
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calibrate::optimise::Settings;
    use crate::calibrate::recovery::TrueParam;
    use runout_case::{BulkSeries, Fidelity, FrontTracker, Monitors, Profile};
    use std::path::PathBuf;

    fn root() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
    }

    /// Family M (cases/mfix-slope/jj.ron) with its specularity over `bounds`, at `fidelity`
    /// to `end_time`, with laser gates at 0.5–2.0 m from x = 0.5 m and the profile station
    /// at x = 0.3 m, t = 0.3 s for every run, so that every kind of measurement shares them.
    fn family_m(
        bounds: &str,
        fidelity: Fidelity,
        end_time: Option<f64>,
        settings: Settings,
    ) -> TruthStudy {
        TruthStudy {
            case_file: "cases/mfix-slope/jj.ron".into(),
            params: vec![TrueParam {
                path: "specularity".into(),
                truth: f64::NAN,
                bounds: bounds.into(),
            }],
            monitors: Some(Monitors {
                profiles: vec![Profile {
                    x: 0.3,
                    times: vec![0.3],
                }],
                wall_probes: Vec::new(),
                front: Some(FrontTracker {
                    threshold: 0.01,
                    gate_origin: 0.5,
                    gates: vec![0.5, 1.0, 1.5, 2.0],
                    interval: 0.002,
                }),
                bulk: Some(BulkSeries {
                    interval: 0.01,
                    front_threshold: 0.01,
                }),
            }),
            fidelity,
            end_time,
            measured: Measured::GateSpeeds,
            sigma: f64::NAN,
            noise: None,
            settings,
        }
    }

    /// Issue 62's smoke version (in CI): family M at smoke fidelity to 0.3 s, a truth that is
    /// not the recovery tables' 0.3 (φ = 0.15), its fronts at 0.1–0.28 s with σ = 1 mm: the
    /// noise-free range contains the truth; one noisy draw is printed. About 12 smoke runs.
    #[test]
    fn smoke_coverage_of_a_truth_that_is_not_0_3() {
        let dir =
            std::env::temp_dir().join(format!("runout-coverage-smoke-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let settings = Settings {
            scan: 3,
            refine: 4,
            jobs: 2,
            xtol: 0.002,
            ftol: 0.05,
            profile: 1,
            valley: 0,
        };
        let plan = CoveragePlan {
            template: family_m("0.05:0.5:0.1:log", Fidelity::Smoke, Some(0.3), settings),
            truths: vec![0.15],
            kinds: vec![MeasurementKind {
                label: "fronts".into(),
                measured: Measured::Front(vec![0.1, 0.15, 0.2, 0.25, 0.28]),
                sigma: 1e-3,
            }],
            draws: 1,
        };
        let draws = run_plan(&root(), &plan, &dir, &Ledger::default(), |d| {
            println!("{d:?}")
        })
        .unwrap();
        let _ = std::fs::remove_dir_all(&dir);
        print!("{}", table(&draws));
        assert_eq!(draws.len(), 2, "both recoveries ran");
        let noise_free = draws.iter().find(|d| d.seed.is_none()).unwrap();
        assert!(noise_free.contains_truth(), "{noise_free:?}");
    }

    /// The coverage table of docs/reference/calibrate.md (issue 62 item 2): family M at coarse
    /// fidelity, the specularity over 0.01–1 (log), truths 0.05, 0.1, 0.2, 0.3, 0.45, 0.6 and
    /// 0.9, four kinds of measurement (the fronts at 0.2–1.0 s and at 0.1–0.5 s with σ = 5 mm,
    /// the u_s profile at x = 0.3 m, t = 0.3 s with σ = 0.02 m/s, the gate speeds with
    /// σ = 0.3 m/s), each noise-free and with `COVERAGE_DRAWS` noisy draws (default 4);
    /// `COVERAGE_TRUTHS=0.45,0.6` and `COVERAGE_KINDS=fronts-0.2-1.0s` run a part of it
    /// (its table then lists that part).
    /// Hours of coarse runs, resumable (runs/calibrate/coverage/, finished runs reused); the
    /// table is written to runs/calibrate/coverage/coverage.md as the draws come:
    /// `RAYON_NUM_THREADS=1 nice -n 19 cargo test --release -p runout-study coverage_table --
    /// --ignored --nocapture`.
    #[test]
    #[ignore = "hours of coarse runs"]
    fn coverage_table() {
        let draws = std::env::var("COVERAGE_DRAWS").map_or(4, |s| s.parse().expect("a count"));
        let settings = Settings {
            scan: 5,
            refine: 8,
            jobs: 1,
            xtol: 0.002,
            ftol: 0.05,
            profile: 2,
            valley: 0,
        };
        let plan = CoveragePlan {
            template: family_m("0.01:1:0.05:log", Fidelity::Coarse, None, settings),
            truths: vec![0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.9],
            kinds: vec![
                MeasurementKind {
                    label: "fronts-0.2-1.0s".into(),
                    measured: Measured::Front((2..=10).map(|k| k as f64 / 10.0).collect()),
                    sigma: 0.005,
                },
                MeasurementKind {
                    label: "fronts-0.1-0.5s".into(),
                    measured: Measured::Front((1..=5).map(|k| k as f64 / 10.0).collect()),
                    sigma: 0.005,
                },
                MeasurementKind {
                    label: "profile-u_s".into(),
                    measured: Measured::Profile {
                        file: "profile_x0.3_t0.3.csv".into(),
                        column: "u_s".into(),
                        min_eps_s: 1e-3,
                    },
                    sigma: 0.02,
                },
                MeasurementKind {
                    label: "gate-speeds".into(),
                    measured: Measured::GateSpeeds,
                    sigma: 0.3,
                },
            ],
            draws,
        };
        let only = |var: &str| {
            std::env::var(var)
                .ok()
                .map(|s| s.split(',').map(str::to_owned).collect::<Vec<_>>())
        };
        let plan = CoveragePlan {
            truths: match only("COVERAGE_TRUTHS") {
                Some(list) => list.iter().map(|t| t.parse().expect("a truth")).collect(),
                None => plan.truths,
            },
            kinds: match only("COVERAGE_KINDS") {
                Some(list) => plan
                    .kinds
                    .into_iter()
                    .filter(|k| list.contains(&k.label))
                    .collect(),
                None => plan.kinds,
            },
            ..plan
        };
        // the finished draws, committed (module doc): a new machine resumes from them
        let ledger_path = root().join("docs/reference/calibrate/coverage-draws.csv");
        let mut ledger = Ledger::read(&ledger_path).unwrap();
        let finished = ledger.clone();
        let dir = root().join("runs/calibrate/coverage");
        let in_plan = |d: &Draw| {
            plan.kinds.iter().any(|k| k.label == d.kind) && plan.truths.contains(&d.truth)
        };
        let mut done: Vec<Draw> = finished
            .draws
            .iter()
            .filter(|d| in_plan(d))
            .cloned()
            .collect();
        run_plan(&root(), &plan, &dir, &finished, |d| {
            println!("{d:?} contains: {}", d.contains_truth());
            done.push(d.clone());
            ledger.draws.push(d.clone());
            std::fs::write(&ledger_path, ledger.to_csv().unwrap()).expect("writable");
            std::fs::write(dir.join("coverage.md"), table(&done)).expect("writable");
        })
        .unwrap();
        print!("{}", table(&done));
    }

    /// The ledger reads back what it writes, a noise-free draw with an empty seed.
    #[test]
    fn the_ledger_reads_back_what_it_writes() {
        let ledger = Ledger {
            draws: vec![
                draw("fronts-0.2-1.0s", 0.45, None, (0.43, 0.47)),
                draw("gate-speeds", 0.1, Some(3002), (0.01, 1.0)),
            ],
        };
        let path = std::env::temp_dir().join(format!("runout-ledger-{}.csv", std::process::id()));
        std::fs::write(&path, ledger.to_csv().unwrap()).unwrap();
        let back = Ledger::read(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(back, ledger);
        assert!(back.has("gate-speeds", 0.1, Some(3002)));
        assert!(!back.has("gate-speeds", 0.1, None));
        assert_eq!(
            Ledger::read(Path::new("/nonexistent/ledger.csv")).unwrap(),
            Ledger::default()
        );
        // the committed ledgers read: the current one (the range spanning every valley, the
        // gap stage), its first row the second kind's noise-free 0.45, whose range now holds
        // it; the one before the gap stage, its first row the first kind's noise-free 0.05
        let calibrate = root().join("docs/reference/calibrate");
        let first = |file: &str| {
            let d = Ledger::read(&calibrate.join(file)).unwrap().draws[0].clone();
            let contains = d.contains_truth();
            (d.kind, d.truth, d.seed, contains)
        };
        assert_eq!(
            first("coverage-draws.csv"),
            ("fronts-0.1-0.5s".into(), 0.45, None, true)
        );
        assert_eq!(
            first("coverage-draws-before-gaps.csv"),
            ("fronts-0.2-1.0s".into(), 0.05, None, true)
        );
    }

    fn draw(kind: &str, truth: f64, seed: Option<u64>, range: (f64, f64)) -> Draw {
        Draw {
            kind: kind.into(),
            truth,
            seed,
            optimum: 0.5 * (range.0 + range.1),
            range,
        }
    }

    #[test]
    fn coverage_counts_the_ranges_that_contain_their_truth() {
        let draws = [
            draw("fronts", 0.3, None, (0.28, 0.31)),
            draw("fronts", 0.3, Some(1), (0.31, 0.35)),
            draw("fronts", 0.3, Some(2), (0.25, 0.30)),
            draw("gates", 0.1, None, (0.2, 0.5)),
            draw("fronts", 0.1, Some(3), (0.09, 0.2)),
            draw("fronts", 0.1, Some(4), (0.09, 0.2)),
        ];
        let kinds = summarise(&draws);
        assert_eq!(kinds.len(), 2);
        let fronts = &kinds[0];
        assert_eq!((fronts.noisy, fronts.noise_free), ((4, 3), (1, 1)));
        assert!((fronts.fraction() - 0.75).abs() < 1e-15);
        // √(0.75 · 0.25 / 4)
        assert!((fronts.standard_error() - 0.216_506_350_946_109_66).abs() < 1e-15);
        assert_eq!((kinds[1].noisy, kinds[1].noise_free), ((0, 0), (1, 0)));
        let md = table(&draws);
        assert!(
            md.contains("| fronts | 3 of 4 | 0.75 ± 0.22 | 1 of 1 |"),
            "{md}"
        );
        assert!(
            md.contains("| gates | 0.1 | none | 0.3500 | 0.2000–0.5000 | **no** |"),
            "{md}"
        );
    }

    #[test]
    fn every_draw_has_its_own_seed() {
        let mut seen = std::collections::HashSet::new();
        for k in 0..4 {
            for t in 0..7 {
                for d in 0..20 {
                    assert!(seen.insert(seed(k, t, d)));
                }
            }
        }
    }
}
