//! `runout calibrate` (and `cargo xtask calibrate`): fits one or two numeric fields of a case to measurements by
//! minimising χ² = Σ (simulated − measured)²/σ², and states the range Δχ² ≤ 1 of the
//! parameters consistent with them (docs/reference/calibrate.md).
//!
//! Everything is checked before the first run: the case file, each `--param` (its path in
//! the case, its bounds and start, the case valid at every corner of the bounds) and the
//! measurements file. Every evaluation is a run in
//! `runs/calibrate/<study>/<case>_<key>=<value>/<fidelity>/` (written as `.partial`, renamed
//! when done); a finished run of the same resolved case is reused, so a killed study resumes
//! when the same command is run again. The outputs go to the study folder: evaluations.csv,
//! landscape.svg, summary.md and summary.json.

pub mod brent;
#[cfg(test)]
pub mod coverage;
pub mod ellipse;
pub mod landscape;
pub mod measurements;
pub mod optimise;
pub mod path;
#[cfg(test)]
pub mod recovery;
pub mod scatter;
pub mod smooth;
pub mod synthetic;
pub mod uncertainty;
pub mod valley;

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use anyhow::{bail, Context, Result};
use indicatif::{MultiProgress, ProgressBar};
use runout_case::{is_valid_name, load, Case, Fidelity, Loaded};
use runout_run::signals;

use runout_run::store::Reuse;

use crate::sweep::{finished_run, progress_style, run_into, Outcome as RunOutcome};
use measurements::Measurements;
use optimise::{calibrate, Model, Outcome, Param, Settings};
use path::{set_all, CasePath};
use runout_post::front::FrontDefinition;

/// Options of `runout calibrate` and `cargo xtask calibrate`.
pub struct Options {
    /// the case or sweep file
    pub case_file: PathBuf,
    /// the case of a sweep file (by name)
    pub case: Option<String>,
    /// `PATH=LO:HI[:START][:log]`, one or two
    pub params: Vec<String>,
    /// the measurements CSV
    pub measurements: PathBuf,
    /// fidelity of every run
    pub fidelity: Fidelity,
    /// scan points per parameter
    pub scan: usize,
    /// refinement evaluations at most
    pub refine: usize,
    /// parallel runs in the scan
    pub jobs: usize,
    /// the measurement error σ of every point (overrides the file's)
    pub sigma: Option<f64>,
    /// Brent's and the range edges' tolerance in unit coordinates
    pub xtol: f64,
    /// Nelder–Mead's tolerance: the standard deviation of its simplex's χ²
    pub ftol: f64,
    /// evaluations per side pinning the edges of the range, and rounds sampling the smooth
    /// response's range (1-D)
    pub profile: usize,
    /// stations of the profile along the loosely constrained parameter (2-D; 0: none)
    pub valley: usize,
    /// study name (default: the case name)
    pub name: Option<String>,
    /// check the input and print the plan, run nothing
    pub dry_run: bool,
    /// the program as the user types it (`runout`, `cargo xtask`), for the command line
    /// the summary records
    pub program: &'static str,
}

/// Parses `PATH=LO:HI[:START][:log]` against `case`.
pub fn parse_param(spec: &str, case: &Case) -> Result<(CasePath, Param)> {
    let (text, range) = spec
        .split_once('=')
        .with_context(|| format!("--param {spec}: expected PATH=LO:HI[:START][:log]"))?;
    let path = CasePath::parse(text, case).with_context(|| format!("--param {spec}"))?;
    let mut tokens: Vec<&str> = range.split(':').map(str::trim).collect();
    let log = tokens.last() == Some(&"log");
    if log {
        tokens.pop();
    }
    if !(2..=3).contains(&tokens.len()) {
        bail!("--param {spec}: expected PATH=LO:HI[:START][:log]");
    }
    let numbers = tokens
        .iter()
        .map(|t| {
            t.parse::<f64>()
                .map_err(|_| anyhow::anyhow!("--param {spec}: `{t}` is not a number"))
        })
        .collect::<Result<Vec<f64>>>()?;
    let current = path.get(case)?;
    let mut param = Param {
        name: path.text.clone(),
        lo: numbers[0],
        hi: numbers[1],
        start: numbers.get(2).copied().unwrap_or(current[0]),
        log,
    };
    if numbers.len() == 2 && !(param.lo..=param.hi).contains(&param.start) {
        // the case's own value lies outside the bounds: start in the middle
        param.start = param.value(0.5);
    }
    param.check()?;
    Ok((path, param))
}

/// A value as it appears in a run name (shortest exact form).
fn label(v: f64) -> String {
    if v == 0.0 || (1e-4..1e6).contains(&v.abs()) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// The run name of an evaluation: `<case>_<key>=<value>...`, or a hash of the values if
/// that is too long for a folder name.
fn eval_name(base: &str, keys: &[String], x: &[f64]) -> String {
    let mut name = base.to_string();
    for (k, v) in keys.iter().zip(x) {
        name.push_str(&format!("_{k}={}", label(*v)));
    }
    if is_valid_name(&name) {
        return name;
    }
    // FNV-1a of the values' bits
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for v in x {
        for b in v.to_bits().to_le_bytes() {
            h = (h ^ b as u64).wrapping_mul(0x0100_0000_01b3);
        }
    }
    let head: String = base.chars().take(60).collect();
    format!("{head}_cal-{h:016x}")
}

/// A case run as the model: the misfit of its run against the measurements.
struct CaseModel<'a> {
    base: &'a Case,
    paths: &'a [CasePath],
    keys: Vec<String>,
    fidelity: Fidelity,
    study: PathBuf,
    root: &'a Path,
    measurements: &'a Measurements,
    stop: Arc<AtomicBool>,
    progress: MultiProgress,
}

impl Model for CaseModel<'_> {
    fn evaluate(&self, x: &[f64]) -> Result<Outcome> {
        if self.stop.load(Ordering::SeqCst) {
            bail!("interrupted");
        }
        let values: Vec<(&CasePath, f64)> = self.paths.iter().zip(x.iter().copied()).collect();
        let shown: Vec<String> = values
            .iter()
            .map(|(p, v)| format!("{} = {}", p.text, label(*v)))
            .collect();
        let shown = shown.join(", ");
        let mut case = match set_all(self.base, &values) {
            Ok(case) => case,
            Err(e) => {
                return Ok(Outcome {
                    chi2: f64::NAN,
                    rms: f64::NAN,
                    note: format!("{e:#}"),
                    residuals: Vec::new(),
                })
            }
        };
        case.name = eval_name(&self.base.name, &self.keys, x);
        let done = self.study.join(&case.name).join(self.fidelity.name());
        let shown_dir = done
            .strip_prefix(self.root)
            .unwrap_or(&done)
            .display()
            .to_string();
        let resolved = case.at_fidelity(self.fidelity);
        let reused = finished_run(&done, &resolved).is_some();
        let how = if reused {
            "reused".to_string()
        } else {
            let bar = self.progress.add(ProgressBar::new(1000));
            bar.set_style(progress_style());
            bar.set_prefix(shown.clone());
            match run_into(&case, self.fidelity, &done, Reuse::Never, &bar, &self.stop) {
                RunOutcome::Done(s) | RunOutcome::Skipped(s) | RunOutcome::Copied(s, _) => {
                    format!("ran: {:?}, {:.0} s", s.status, s.wall_time)
                }
                RunOutcome::Interrupted(s) => bail!(
                    "interrupted at t = {} s ({shown}); run the same command again to continue",
                    s.simulated_time
                ),
                RunOutcome::Elsewhere(holder) => bail!(
                    "{shown_dir}: running elsewhere ({holder}); run the same command again \
                     after it ends"
                ),
                RunOutcome::Unsupported(why) | RunOutcome::Failed(why) => {
                    println!("  {shown}: no misfit: {why}");
                    return Ok(Outcome {
                        chi2: f64::NAN,
                        rms: f64::NAN,
                        note: format!("{shown_dir}: {why}"),
                        residuals: Vec::new(),
                    });
                }
            }
        };
        let mut residuals = Vec::new();
        let (chi2, rms, note) = match self.measurements.misfit(&done) {
            Ok(m) if m.missing.is_empty() => {
                let front = match m.front {
                    Some(FrontDefinition::WholeCell) => {
                        ", whole-cell front: a run older than bulk.csv's interpolated front"
                    }
                    _ => "",
                };
                residuals = m.residuals;
                (m.chi2, m.rms, format!("{shown_dir} ({how}{front})"))
            }
            Ok(m) => (
                f64::INFINITY,
                f64::INFINITY,
                format!("{shown_dir} ({how}): {}", m.missing.join("; ")),
            ),
            Err(e) => (f64::NAN, f64::NAN, format!("{shown_dir} ({how}): {e:#}")),
        };
        println!(
            "  {shown}: {} ({how})",
            if chi2.is_finite() {
                format!("χ² {chi2:.4}, RMS {rms:.4} {}", self.measurements.unit())
            } else {
                "no misfit".into()
            },
        );
        Ok(Outcome {
            chi2,
            rms,
            note,
            residuals,
        })
    }
}

/// A path as given, else below the workspace root.
fn locate(root: &Path, p: &Path) -> PathBuf {
    if p.is_absolute() || p.exists() {
        p.to_path_buf()
    } else {
        root.join(p)
    }
}

/// The case of the file: the only one, or the one named by `--case`.
fn select_case(file: &Path, name: Option<&str>) -> Result<Case> {
    let cases = match load(file)? {
        Loaded::Cases(c) => c,
        Loaded::Analytic(_) => bail!("{}: an analytic family has nothing to run", file.display()),
    };
    let names: Vec<&str> = cases.iter().map(|c| c.case.name.as_str()).collect();
    match name {
        Some(n) => cases
            .iter()
            .find(|c| c.case.name == n)
            .map(|c| c.case.clone())
            .with_context(|| {
                format!(
                    "{}: no case `{n}` (cases: {})",
                    file.display(),
                    names.join(", ")
                )
            }),
        None if cases.len() == 1 => Ok(cases[0].case.clone()),
        None => bail!(
            "{}: {} cases: name one with --case (cases: {})",
            file.display(),
            cases.len(),
            names.join(", ")
        ),
    }
}

/// Checks that the case is valid at every corner of the bounds and at the start.
fn check_corners(case: &Case, paths: &[CasePath], params: &[Param]) -> Result<()> {
    let choices: Vec<[f64; 3]> = params.iter().map(|p| [p.lo, p.hi, p.start]).collect();
    let combos: Vec<Vec<f64>> = if params.len() == 1 {
        choices[0].iter().map(|&a| vec![a]).collect()
    } else {
        choices[0]
            .iter()
            .flat_map(|&a| choices[1].iter().map(move |&b| vec![a, b]))
            .collect()
    };
    for x in combos {
        let values: Vec<(&CasePath, f64)> = paths.iter().zip(x.iter().copied()).collect();
        set_all(case, &values).with_context(|| {
            let at: Vec<String> = values
                .iter()
                .map(|(p, v)| format!("{} = {v}", p.text))
                .collect();
            format!(
                "--param: the case at {} (a bound or the start)",
                at.join(", ")
            )
        })?;
    }
    Ok(())
}

/// The command line, for the summary: `program` and this process's arguments.
fn command_line(program: &str) -> String {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .map(|a| {
            if a.contains([' ', '"', '\'']) {
                format!("'{a}'")
            } else {
                a
            }
        })
        .collect();
    format!("{program} {}", args.join(" "))
}

/// Runs the calibration of `opts` below `root` (`runs/calibrate/<study>/`); relative paths
/// that do not exist as given are taken below `root`.
pub fn run(root: &Path, opts: &Options) -> Result<()> {
    let file = locate(root, &opts.case_file);
    let case = select_case(&file, opts.case.as_deref())?;
    let measurements = Measurements::read(&locate(root, &opts.measurements), opts.sigma)?;
    if !(1..=2).contains(&opts.params.len()) {
        bail!("give one or two --param, found {}", opts.params.len());
    }
    if !(opts.xtol > 0.0 && opts.xtol < 0.5) {
        bail!("--xtol {}: a fraction of the bounds in (0, 0.5)", opts.xtol);
    }
    let (paths, params): (Vec<CasePath>, Vec<Param>) = opts
        .params
        .iter()
        .map(|s| parse_param(s, &case))
        .collect::<Result<Vec<_>>>()?
        .into_iter()
        .unzip();
    check_corners(&case, &paths, &params)?;
    let study_name = opts.name.clone().unwrap_or_else(|| case.name.clone());
    if !is_valid_name(&study_name) {
        bail!("--name {study_name:?}: a study name is a folder name (letters, digits, -_.=)");
    }
    let study = root.join("runs").join("calibrate").join(&study_name);
    let mut keys: Vec<String> = paths.iter().map(CasePath::key).collect();
    if keys.len() == 2 && keys[0] == keys[1] {
        keys = vec![format!("{}1", keys[0]), format!("{}2", keys[1])];
    }
    let runs = 1 + opts.scan.pow(params.len() as u32);
    println!(
        "calibrating `{}` at {} against {} ({}, {}): {runs} start and scan run(s) on {} \
         job(s), then at most {} refinement run(s){}; runs in {}",
        case.name,
        opts.fidelity,
        measurements.path.display(),
        measurements.describe(),
        measurements.sigma_source,
        opts.jobs,
        opts.refine,
        if params.len() == 1 {
            format!(" and {} per side for the range's edges", opts.profile)
        } else if opts.valley > 0 {
            format!(
                " and at most {} along the valley ({} stations) for the range",
                opts.valley * valley::STATION_EVALUATIONS,
                opts.valley
            )
        } else {
            String::new()
        },
        study.strip_prefix(root).unwrap_or(&study).display()
    );
    for (path, p) in paths.iter().zip(&params) {
        println!(
            "  {} in [{}, {}]{}, start {}: sets {}",
            p.name,
            p.lo,
            p.hi,
            if p.log { " (log scale)" } else { "" },
            p.start,
            path.fields().join(", ")
        );
    }
    if opts.dry_run {
        return Ok(());
    }
    std::fs::create_dir_all(&study).with_context(|| format!("creating {}", study.display()))?;
    let stop = signals::stop_on_signals(
        "calibrate",
        "the running evaluation stops after its step with a checkpoint; run the same command \
         again to continue",
    );
    let model = CaseModel {
        base: &case,
        paths: &paths,
        keys,
        fidelity: opts.fidelity,
        study: study.clone(),
        root,
        measurements: &measurements,
        stop,
        progress: MultiProgress::new(),
    };
    let settings = Settings {
        scan: opts.scan,
        refine: opts.refine,
        jobs: opts.jobs,
        xtol: opts.xtol,
        ftol: opts.ftol,
        profile: opts.profile,
        valley: opts.valley,
    };
    let c = calibrate(&params, &model, &settings)?;
    let range = uncertainty::range(&c);
    let info = landscape::StudyInfo {
        title: format!("{} at {}", case.name, opts.fidelity),
        measurements: format!(
            "{} ({})",
            measurements
                .path
                .strip_prefix(root)
                .unwrap_or(&measurements.path)
                .display(),
            measurements.describe()
        ),
        unit: measurements.unit(),
        sigma: measurements.sigma_source.clone(),
        points: measurements.kind.len(),
        command: command_line(opts.program),
        fields: paths.iter().map(CasePath::fields).collect(),
    };
    landscape::write_csv(&study.join("evaluations.csv"), &c)?;
    landscape::draw(&study.join("landscape.svg"), &c, &range, &info)?;
    let md = landscape::write_summary(&study, &c, &range, &info)?;
    println!("\n{md}");
    println!("written to {}", study.display());
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flume() -> Case {
        let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/flume/base.ron");
        runout_case::load_case(&file).unwrap()
    }

    #[test]
    fn params_parse_with_their_start_and_scale() {
        let case = flume();
        let (path, p) = parse_param("specularity=0.01:0.5:log", &case).unwrap();
        assert_eq!(path.fields().len(), 3);
        assert_eq!((p.lo, p.hi, p.start, p.log), (0.01, 0.5, 0.1, true));
        let (_, p) = parse_param("boundaries.south.solids.specularity=0.2:0.5", &case).unwrap();
        assert_eq!(p.start, 0.35, "the case's 0.1 is outside: the middle");
        let (_, p) = parse_param("wall_friction_angle=5:20:8", &case).unwrap();
        assert_eq!(p.start, 8.0);
    }

    #[test]
    fn bad_params_are_refused_before_any_run() {
        let case = flume();
        let err = |s: &str| format!("{:#}", parse_param(s, &case).unwrap_err());
        assert!(err("specularity").contains("expected PATH=LO:HI"));
        assert!(err("specularity=0.1").contains("expected PATH=LO:HI"));
        assert!(err("specularity=a:1").contains("`a` is not a number"));
        assert!(err("specularity=0.5:0.1").contains("not below"));
        assert!(err("specularity=0.1:0.5:0.9").contains("outside the bounds"));
        assert!(err("specularity=0:inf").contains("finite"));
        assert!(err("boundaries.south.solid.specularity=0:1").contains("no field `solid`"));
        // valid bounds the case refuses
        let (path, p) = parse_param("specularity=0.1:2", &case).unwrap();
        let e = format!("{:#}", check_corners(&case, &[path], &[p]).unwrap_err());
        assert!(
            e.contains("specularity = 2") && e.contains("allowed"),
            "{e}"
        );
    }

    #[test]
    fn a_sweep_file_needs_the_case_named() {
        let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/flume/F-JJ.ron");
        let e = format!("{:#}", select_case(&file, None).unwrap_err());
        assert!(
            e.contains("name one with --case") && e.contains("F-JJ_phi=0.01"),
            "{e}"
        );
        let e = format!("{:#}", select_case(&file, Some("F-JJ")).unwrap_err());
        assert!(e.contains("no case `F-JJ`"), "{e}");
        let case = select_case(&file, Some("F-JJ_phi=0.01")).unwrap();
        let p = CasePath::parse("boundaries.south.solids.specularity", &case).unwrap();
        assert_eq!(p.get(&case).unwrap(), [0.01]);
    }

    #[test]
    fn run_names_are_folder_names() {
        let keys = vec!["specularity".to_string()];
        assert_eq!(
            eval_name("F-JJ_phi=0.1", &keys, &[0.05]),
            "F-JJ_phi=0.1_specularity=0.05"
        );
        assert_eq!(eval_name("c", &keys, &[1e-7]), "c_specularity=1e-7");
        let long = "x".repeat(90);
        let name = eval_name(&long, &keys, &[0.123456789]);
        assert!(is_valid_name(&name) && name.contains("_cal-"), "{name}");
        assert_ne!(name, eval_name(&long, &keys, &[0.123456788]));
    }
}
