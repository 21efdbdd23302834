//! The calibration core, independent of runout: a [`Model`] maps parameter values to
//! χ² = Σ (s_i − m_i)²/σ_i² (a case run in production, a closed form in the tests).
//!
//! 1. the start point and a landscape scan (N points in 1-D, an N × N grid in 2-D, evenly
//!    spaced in each parameter's scale), evaluated in parallel on `jobs` workers;
//! 2. refinement from where the scan found the minimum, at most `refine` more evaluations,
//!    none repeated: in 1-D Brent's method ([`super::brent`]) from the bracket of the best
//!    evaluation and its neighbours with their known χ², until the bracket is narrower than
//!    2 `xtol`; in 2-D Nelder–Mead (argmin) from the simplex of the best scan point and its
//!    better grid neighbour along each parameter (all three known), until the standard
//!    deviation of the simplex's χ² is below `ftol`;
//! 3. in 1-D, the edges of the range Δχ² ≤ 1 pinned by at most `profile` more evaluations
//!    per side ([`super::uncertainty`]); one round looking into each wide gap between
//!    evaluations outside the range beside a near-consistent one
//!    ([`super::uncertainty::gap_proposals`]) and the edges pinned again; then the smooth
//!    response's range sampled in at most `profile` rounds of evaluations a quarter of its
//!    width apart ([`super::smooth::sampling_proposals`]), so that its trend is carried by
//!    evaluations across the range, not by the refinement's cluster alone.
//!
//! The optimum is the best evaluation of all. The optimiser works in unit coordinates
//! u ∈ [0, 1] per parameter (linear or log scale); a point outside the box, or one whose χ²
//! is not finite, costs a penalty above every scanned χ², so neither method leaves the box
//! or stops on a failed run.

use std::sync::Mutex;

use anyhow::{bail, Result};
use argmin::core::{CostFunction, Error as ArgminError, Executor};
use argmin::solver::neldermead::NelderMead;

use super::brent::{self, Bracket};
use super::smooth;
use super::uncertainty;
use super::valley::{self, Valley};

/// One calibrated parameter: bounds, start and scale.
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    /// name, for messages and tables
    pub name: String,
    /// lower bound
    pub lo: f64,
    /// upper bound
    pub hi: f64,
    /// the start value (evaluated first)
    pub start: f64,
    /// scan and optimise in log(value)
    pub log: bool,
}

impl Param {
    /// Checks the bounds and the start: an error names the parameter.
    pub fn check(&self) -> Result<()> {
        let name = &self.name;
        if !(self.lo.is_finite() && self.hi.is_finite() && self.start.is_finite()) {
            bail!("--param {name}: the bounds and the start must be finite numbers");
        }
        if self.lo >= self.hi {
            bail!(
                "--param {name}: the lower bound {} is not below the upper {}",
                self.lo,
                self.hi
            );
        }
        if !(self.lo..=self.hi).contains(&self.start) {
            bail!(
                "--param {name}: the start {} lies outside the bounds [{}, {}]",
                self.start,
                self.lo,
                self.hi
            );
        }
        if self.log && self.lo <= 0.0 {
            bail!(
                "--param {name}: a log scale needs a positive lower bound, found {}",
                self.lo
            );
        }
        Ok(())
    }

    /// The value at unit coordinate `u`.
    pub fn value(&self, u: f64) -> f64 {
        let v = if self.log {
            (self.lo.ln() + u * (self.hi.ln() - self.lo.ln())).exp()
        } else {
            self.lo + u * (self.hi - self.lo)
        };
        // exact at the ends, whatever the rounding
        if u <= 0.0 {
            self.lo
        } else if u >= 1.0 {
            self.hi
        } else {
            snap(v)
        }
    }

    /// The unit coordinate of `v`.
    pub fn unit(&self, v: f64) -> f64 {
        if self.log {
            (v.ln() - self.lo.ln()) / (self.hi.ln() - self.lo.ln())
        } else {
            (v - self.lo) / (self.hi - self.lo)
        }
    }
}

/// `v` rounded to 6 significant digits if that changes it by rounding error only (1e-12
/// relative): 0.1 for the 0.10000000000000002 of a log scale, so that a scan point is the
/// run of the value as a user writes it (and reuses that run).
fn snap(v: f64) -> f64 {
    let short: f64 = format!("{v:.5e}").parse().unwrap_or(v);
    if (short - v).abs() <= 1e-12 * v.abs() {
        short
    } else {
        v
    }
}

/// What one evaluation gave.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// χ² = Σ (s_i − m_i)²/σ_i²; not finite if the evaluation has none (a failed run, a
    /// missing point)
    pub chi2: f64,
    /// the RMS of s_i − m_i in the measurement's unit (NaN if the model has none)
    pub rms: f64,
    /// what to note beside it (the run folder, why it has no misfit)
    pub note: String,
    /// (s_i − m_i)/σ_i per measured point, in the measurements' order (empty if none)
    pub residuals: Vec<f64>,
}

/// The thing calibrated: parameter values → χ². An `Err` stops the calibration (an
/// interrupt); a failed evaluation is an [`Outcome`] with a non-finite misfit.
pub trait Model: Sync {
    /// χ² at `x` (one value per parameter).
    fn evaluate(&self, x: &[f64]) -> Result<Outcome>;
}

impl<F: Fn(&[f64]) -> f64 + Sync> Model for F {
    fn evaluate(&self, x: &[f64]) -> Result<Outcome> {
        Ok(Outcome {
            chi2: self(x),
            rms: f64::NAN,
            note: String::new(),
            residuals: Vec::new(),
        })
    }
}

/// Which stage made an evaluation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    /// the start point
    Start,
    /// the landscape scan
    Scan,
    /// the refinement (Brent or Nelder–Mead)
    Refine,
    /// pinning an edge of the range Δχ² ≤ 1
    Profile,
    /// sampling the smooth response's range (1-D, [`smooth::sampling_proposals`])
    Sample,
    /// looking into a wide gap beside a near-consistent value (1-D,
    /// [`uncertainty::gap_proposals`])
    Gap,
    /// a station of the profile along the valley (2-D)
    Valley,
}

impl Stage {
    /// Lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            Stage::Start => "start",
            Stage::Scan => "scan",
            Stage::Refine => "refine",
            Stage::Profile => "profile",
            Stage::Sample => "sample",
            Stage::Gap => "gap",
            Stage::Valley => "valley",
        }
    }
}

/// One evaluation of the model.
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluation {
    /// parameter values
    pub x: Vec<f64>,
    /// χ² (not finite: none)
    pub chi2: f64,
    /// RMS of simulated − measured [the measurement's unit]
    pub rms: f64,
    /// the stage that asked for it first
    pub stage: Stage,
    /// the model's note
    pub note: String,
    /// (s_i − m_i)/σ_i per measured point (empty if none)
    pub residuals: Vec<f64>,
}

/// How to calibrate.
#[derive(Clone, Debug)]
pub struct Settings {
    /// scan points per parameter (0: none, the refinement starts at the start point)
    pub scan: usize,
    /// at most this many refinement evaluations
    pub refine: usize,
    /// parallel evaluations in the scan
    pub jobs: usize,
    /// Brent's absolute tolerance in unit coordinates (and the profile's edge tolerance)
    pub xtol: f64,
    /// Nelder–Mead stops when the standard deviation of its simplex's χ² is below this
    pub ftol: f64,
    /// at most this many evaluations per side pinning the edges of the range, one round
    /// looking into the gaps beside near fits (none at 0), then as many rounds sampling the
    /// smooth response's range (1-D)
    pub profile: usize,
    /// stations of the profile of χ² along the loosely constrained parameter (2-D, 0: none;
    /// [`super::valley`]), at most [`super::valley::STATION_EVALUATIONS`] evaluations each
    pub valley: usize,
}

/// A finished calibration.
#[derive(Clone, Debug)]
pub struct Calibration {
    /// the parameters
    pub params: Vec<Param>,
    /// every evaluation, in the order made (scan in grid order)
    pub evaluations: Vec<Evaluation>,
    /// index of the best evaluation
    pub best: usize,
    /// the profile of χ² along the valley (2-D with `Settings::valley` stations)
    pub valley: Option<Valley>,
}

impl Calibration {
    /// The best evaluation.
    pub fn optimum(&self) -> &Evaluation {
        &self.evaluations[self.best]
    }
}

/// Evaluations with a cache: a point asked twice is evaluated once.
struct Evaluator<'a> {
    model: &'a dyn Model,
    params: &'a [Param],
    done: Mutex<Vec<Evaluation>>,
    /// refinement evaluations left
    budget: Mutex<usize>,
    /// the cost of a point outside the box or without a misfit
    penalty: f64,
}

impl Evaluator<'_> {
    fn cached(&self, x: &[f64]) -> Option<f64> {
        let done = self.done.lock().expect("no poisoned lock");
        done.iter().find(|e| e.x == x).map(|e| e.chi2)
    }

    fn evaluate(&self, x: Vec<f64>, stage: Stage) -> Result<f64> {
        if let Some(m) = self.cached(&x) {
            return Ok(m);
        }
        let outcome = self.model.evaluate(&x)?;
        let mut done = self.done.lock().expect("no poisoned lock");
        done.push(Evaluation {
            x,
            chi2: outcome.chi2,
            rms: outcome.rms,
            stage,
            note: outcome.note,
            residuals: outcome.residuals,
        });
        Ok(outcome.chi2)
    }

    /// The refinement's cost at unit coordinates `u`.
    fn cost(&self, u: &[f64]) -> Result<f64, ArgminError> {
        let outside: f64 = u.iter().map(|&v| (-v).max(v - 1.0).max(0.0)).sum();
        if outside > 0.0 {
            return Ok(self.penalty * (1.0 + outside));
        }
        let x: Vec<f64> = self
            .params
            .iter()
            .zip(u)
            .map(|(p, &v)| p.value(v))
            .collect();
        if let Some(m) = self.cached(&x) {
            return Ok(if m.is_finite() { m } else { self.penalty });
        }
        {
            let mut left = self.budget.lock().expect("no poisoned lock");
            if *left == 0 {
                return Err(anyhow::anyhow!(BUDGET));
            }
            *left -= 1;
        }
        let m = self.evaluate(x, Stage::Refine)?;
        Ok(if m.is_finite() { m } else { self.penalty })
    }
}

/// The error that ends the refinement when its evaluations are spent.
const BUDGET: &str = "the refinement's evaluations are spent";

struct Simplex<'a, 'b>(&'a Evaluator<'b>);
impl CostFunction for Simplex<'_, '_> {
    type Param = Vec<f64>;
    type Output = f64;
    fn cost(&self, u: &Vec<f64>) -> Result<f64, ArgminError> {
        self.0.cost(u)
    }
}

/// The scan's unit coordinates per parameter: n evenly spaced points including both ends
/// (the middle for n = 1).
pub fn scan_points(n: usize) -> Vec<f64> {
    match n {
        0 => Vec::new(),
        1 => vec![0.5],
        _ => (0..n).map(|k| k as f64 / (n - 1) as f64).collect(),
    }
}

/// Evaluates `points` on `jobs` workers, each on a thread pool of its own ([`crate::jobs`]).
fn evaluate_all(ev: &Evaluator, points: Vec<Vec<f64>>, stage: Stage, jobs: usize) -> Result<()> {
    let first_error = Mutex::new(None);
    let no_error = || first_error.lock().expect("no poisoned lock").is_none();
    crate::jobs::run_queue(points, jobs, no_error, |x| {
        if let Err(e) = ev.evaluate(x, stage) {
            first_error
                .lock()
                .expect("no poisoned lock")
                .get_or_insert(e);
        }
    })?;
    match first_error.into_inner().expect("no poisoned lock") {
        Some(e) => Err(e),
        None => Ok(()),
    }
}

/// Index of the lowest finite χ².
pub fn best_index(evaluations: &[Evaluation]) -> Option<usize> {
    (0..evaluations.len())
        .filter(|&k| evaluations[k].chi2.is_finite())
        .min_by(|&a, &b| evaluations[a].chi2.total_cmp(&evaluations[b].chi2))
}

/// The evaluations so far as (u, χ²) in the order of u, a point without χ² at the penalty.
fn known_1d(ev: &Evaluator) -> Vec<(f64, f64)> {
    let done = ev.done.lock().expect("no poisoned lock");
    let mut pts: Vec<(f64, f64)> = done
        .iter()
        .map(|e| {
            let f = if e.chi2.is_finite() {
                e.chi2
            } else {
                ev.penalty
            };
            (ev.params[0].unit(e.x[0]), f)
        })
        .collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    pts.dedup_by(|a, b| a.0 == b.0);
    pts
}

/// Brent from the best evaluation and its neighbours (all known).
fn refine_1d(ev: &Evaluator, settings: &Settings) -> Result<()> {
    let pts = known_1d(ev);
    let k = (0..pts.len())
        .min_by(|&a, &b| pts[a].1.total_cmp(&pts[b].1))
        .expect("the scan has points");
    let bracket = Bracket {
        a: pts[k.saturating_sub(1)],
        x: pts[k],
        b: pts[(k + 1).min(pts.len() - 1)],
    };
    brent::minimise(bracket, settings.xtol, |u| match ev.cost(&[u]) {
        Ok(f) => Ok(Some(f)),
        Err(e) if e.to_string() == BUDGET => Ok(None),
        Err(e) => Err(e),
    })
}

/// argmin's Nelder–Mead from `simplex` (unit coordinates) until the standard deviation of
/// its χ² is below `ftol` or the budget is spent.
fn nelder_mead(ev: &Evaluator, simplex: Vec<Vec<f64>>, settings: &Settings) -> Result<()> {
    let result = NelderMead::new(simplex)
        .with_sd_tolerance(settings.ftol)
        .map_err(|e| anyhow::anyhow!("{e}"))
        .and_then(|solver| {
            Executor::new(Simplex(ev), solver)
                .configure(|s| s.max_iters(settings.refine as u64))
                .run()
                .map(|_| ())
        });
    match result {
        Err(e) if e.to_string() != BUDGET => Err(e),
        _ => Ok(()),
    }
}

/// Nelder–Mead from the best scan point `best` (grid indices) and its better grid
/// neighbour along each parameter: three known vertices.
fn refine_2d(ev: &Evaluator, axis: &[f64], best: [usize; 2], settings: &Settings) -> Result<()> {
    let value = |i: usize, j: usize| {
        let u = vec![axis[i], axis[j]];
        let f = ev.cost(&u).unwrap_or(f64::INFINITY);
        (u, f)
    };
    let [i, j] = best;
    let neighbours = |k: usize| [k.checked_sub(1), (k + 1 < axis.len()).then_some(k + 1)];
    let mut simplex = vec![value(i, j).0];
    for (d, &at) in best.iter().enumerate() {
        let along = |k: usize| if d == 0 { value(k, j) } else { value(i, k) };
        let (u, _) = neighbours(at)
            .into_iter()
            .flatten()
            .map(along)
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .expect("a scan of two or more points per axis");
        simplex.push(u);
    }
    nelder_mead(ev, simplex, settings)
}

/// Nelder–Mead from the start point when there is no scan grid: a simplex of a quarter of
/// the box along each parameter.
fn refine_2d_without_scan(ev: &Evaluator, u0: Vec<f64>, settings: &Settings) -> Result<()> {
    let mut simplex = vec![u0.clone()];
    for d in 0..2 {
        let mut v = u0.clone();
        v[d] += if u0[d] <= 0.75 { 0.25 } else { -0.25 };
        simplex.push(v);
    }
    for v in &simplex {
        match ev.cost(v) {
            Ok(_) => {}
            Err(e) if e.to_string() == BUDGET => return Ok(()),
            Err(e) => return Err(e),
        }
    }
    nelder_mead(ev, simplex, settings)
}

/// At most `settings.profile` rounds of 1-D evaluations (in parallel) as `stage`, each at the
/// unit coordinates `propose` gives from the evaluations so far that are not yet evaluated;
/// none once it proposes nothing new.
fn rounds(
    ev: &Evaluator,
    settings: &Settings,
    stage: Stage,
    propose: impl Fn(&Evaluator) -> Vec<f64>,
) -> Result<()> {
    for _ in 0..settings.profile {
        let proposals: Vec<Vec<f64>> = propose(ev)
            .into_iter()
            .map(|u| vec![ev.params[0].value(u)])
            .filter(|x| ev.cached(x).is_none())
            .collect();
        if proposals.is_empty() {
            break;
        }
        evaluate_all(ev, proposals, stage, settings.jobs)?;
    }
    Ok(())
}

/// Pins the edges of the range Δχ² ≤ 1 (1-D): each round evaluates the next estimate of every
/// edge not yet known to `xtol` ([`rounds`]).
fn pin_edges(ev: &Evaluator, settings: &Settings) -> Result<()> {
    rounds(ev, settings, Stage::Profile, |ev| {
        uncertainty::edge_proposals(&known_1d(ev), uncertainty::DELTA_CHI2_1D, settings.xtol)
    })
}

/// Looks into the wide gaps beside near-consistent values (1-D): one round of
/// [`uncertainty::gap_proposals`] ([`rounds`] with one round).
fn fill_gaps(ev: &Evaluator, settings: &Settings) -> Result<()> {
    let once = Settings {
        profile: settings.profile.min(1),
        ..settings.clone()
    };
    rounds(ev, &once, Stage::Gap, |ev| {
        uncertainty::gap_proposals(&known_1d(ev), uncertainty::DELTA_CHI2_1D, settings.xtol)
    })
}

/// Samples the smooth response's range (1-D): each round evaluates the stations of
/// [`smooth::sampling_proposals`] (`xtol` apart at least) ([`rounds`]); none without
/// residuals or a smooth range.
fn sample_range(ev: &Evaluator, settings: &Settings) -> Result<()> {
    rounds(ev, settings, Stage::Sample, |ev| {
        let evaluated: Vec<(f64, Vec<f64>)> = {
            let done = ev.done.lock().expect("no poisoned lock");
            done.iter()
                .filter(|e| e.chi2.is_finite() && !e.residuals.is_empty())
                .map(|e| (ev.params[0].unit(e.x[0]), e.residuals.clone()))
                .collect()
        };
        let view: Vec<(f64, &[f64])> = evaluated.iter().map(|(u, r)| (*u, r.as_slice())).collect();
        let units: Vec<f64> = evaluated.iter().map(|e| e.0).collect();
        smooth::range(&view, uncertainty::DELTA_CHI2_1D, |u| u).map_or(Vec::new(), |range| {
            smooth::sampling_proposals(range.bounds.0, range.bounds.1, settings.xtol, &units)
        })
    })
}

/// The profile of χ² along the parameter the region is loosest along ([`valley`]): its
/// stations evenly spaced over the box, walked outward from the best evaluation in two
/// chains (run at once when `settings.jobs` ≥ 2).
fn trace_valley(ev: &Evaluator, settings: &Settings) -> Result<Valley> {
    let units = |e: &Evaluation| [ev.params[0].unit(e.x[0]), ev.params[1].unit(e.x[1])];
    let (points, best) = {
        let done = ev.done.lock().expect("no poisoned lock");
        let points: Vec<([f64; 2], f64)> = done
            .iter()
            .filter(|e| e.chi2.is_finite())
            .map(|e| (units(e), e.chi2))
            .collect();
        let best = best_index(&done).map(|k| (units(&done[k]), done[k].chi2));
        (points, best.expect("the scan had one"))
    };
    let threshold = || {
        let done = ev.done.lock().expect("no poisoned lock");
        best_index(&done).map_or(f64::INFINITY, |k| done[k].chi2) + uncertainty::DELTA_CHI2_2D
    };
    let along = valley::loose_axis(&points, best.1, best.1 + uncertainty::DELTA_CHI2_2D);
    let across = 1 - along;
    let (right, left) = valley::chains(&scan_points(settings.valley), best.0[along]);
    let chi2 = |q: f64, t: f64| -> Result<Option<f64>> {
        let mut u = [0.0; 2];
        (u[along], u[across]) = (q, t);
        let x: Vec<f64> = (0..2).map(|d| ev.params[d].value(u[d])).collect();
        let f = ev.evaluate(x, Stage::Valley)?;
        Ok(Some(if f.is_finite() { f } else { ev.penalty }))
    };
    let walked = Mutex::new(Vec::new());
    let first_error = Mutex::new(None);
    crate::jobs::run_queue(
        [right, left],
        settings.jobs.min(2),
        || first_error.lock().expect("no poisoned lock").is_none(),
        |qs| match valley::walk_chain(&qs, best.0[across], settings.xtol, threshold, chi2) {
            Ok(stations) => walked.lock().expect("no poisoned lock").extend(stations),
            Err(e) => {
                first_error
                    .lock()
                    .expect("no poisoned lock")
                    .get_or_insert(e);
            }
        },
    )?;
    if let Some(e) = first_error.into_inner().expect("no poisoned lock") {
        return Err(e);
    }
    let mut stations = walked.into_inner().expect("no poisoned lock");
    stations.sort_by(|a, b| a.q.total_cmp(&b.q));
    Ok(Valley { along, stations })
}

/// The grid indices of evaluation `best` if it is a scan point (of a scan of two or more
/// points per parameter).
fn grid_cell(
    done: &[Evaluation],
    best: usize,
    params: &[Param],
    axis: &[f64],
) -> Option<[usize; 2]> {
    if axis.len() < 2 {
        return None;
    }
    let index = |d: usize| (0..axis.len()).find(|&k| params[d].value(axis[k]) == done[best].x[d]);
    Some([index(0)?, index(1)?])
}

/// Calibrates the one or two `params` of `model`.
pub fn calibrate(params: &[Param], model: &dyn Model, settings: &Settings) -> Result<Calibration> {
    if !(1..=2).contains(&params.len()) {
        bail!(
            "calibrate fits one or two parameters, found {}",
            params.len()
        );
    }
    for p in params {
        p.check()?;
    }
    let mut ev = Evaluator {
        model,
        params,
        done: Mutex::new(Vec::new()),
        budget: Mutex::new(settings.refine),
        penalty: 0.0,
    };
    let start: Vec<f64> = params.iter().map(|p| p.start).collect();
    ev.evaluate(start.clone(), Stage::Start)?;
    let axis = scan_points(settings.scan);
    let grid: Vec<Vec<f64>> = if params.len() == 1 {
        axis.iter().map(|&u| vec![params[0].value(u)]).collect()
    } else {
        axis.iter()
            .flat_map(|&v| axis.iter().map(move |&u| (u, v)))
            .map(|(u, v)| vec![params[0].value(u), params[1].value(v)])
            .collect()
    };
    evaluate_all(&ev, grid, Stage::Scan, settings.jobs)?;
    let done = ev.done.lock().expect("no poisoned lock").clone();
    let Some(best) = best_index(&done) else {
        bail!("no evaluation of the start and the scan gave a misfit");
    };
    let worst = done
        .iter()
        .map(|e| e.chi2)
        .filter(|m| m.is_finite())
        .fold(0.0, f64::max);
    ev.penalty = 2.0 * worst.max(f64::MIN_POSITIVE) + 1.0;
    let u0: Vec<f64> = params
        .iter()
        .zip(&done[best].x)
        .map(|(p, &x)| p.unit(x))
        .collect();
    if settings.refine > 0 {
        if params.len() == 1 {
            refine_1d(&ev, settings)?;
        } else if let Some(cell) = grid_cell(&done, best, params, &axis) {
            refine_2d(&ev, &axis, cell, settings)?;
        } else {
            refine_2d_without_scan(&ev, u0, settings)?;
        }
    }
    let valley = if params.len() == 1 {
        pin_edges(&ev, settings)?;
        fill_gaps(&ev, settings)?;
        pin_edges(&ev, settings)?;
        sample_range(&ev, settings)?;
        None
    } else if settings.valley > 0 {
        Some(trace_valley(&ev, settings)?)
    } else {
        None
    };
    let evaluations = ev.done.into_inner().expect("no poisoned lock");
    let best = best_index(&evaluations).expect("the scan had one");
    Ok(Calibration {
        params: params.to_vec(),
        evaluations,
        best,
        valley,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn param(name: &str, lo: f64, hi: f64, start: f64) -> Param {
        Param {
            name: name.into(),
            lo,
            hi,
            start,
            log: false,
        }
    }

    fn settings(scan: usize, refine: usize) -> Settings {
        Settings {
            scan,
            refine,
            jobs: 2,
            xtol: 1e-6,
            ftol: 1e-12,
            profile: 0,
            valley: 0,
        }
    }

    #[test]
    fn brent_finds_a_known_minimum() {
        // |x − 0.37| shaped smooth misfit, minimum 0.2 at x = 0.37
        let f = |x: &[f64]| ((x[0] - 0.37).powi(2) + 0.04).sqrt();
        let c = calibrate(&[param("a", 0.0, 2.0, 1.3)], &f, &settings(9, 40)).unwrap();
        let best = c.optimum();
        assert!((best.x[0] - 0.37).abs() < 1e-4, "{best:?}");
        assert!((best.chi2 - 0.2).abs() < 1e-8);
        assert_eq!(c.evaluations[0].stage, Stage::Start);
        assert_eq!(
            c.evaluations
                .iter()
                .filter(|e| e.stage == Stage::Scan)
                .count(),
            9
        );
        assert!(
            c.evaluations
                .iter()
                .filter(|e| e.stage == Stage::Refine)
                .count()
                <= 40
        );
    }

    #[test]
    fn brent_works_on_a_log_scale() {
        let f = |x: &[f64]| (x[0].log10() + 1.5).powi(2);
        let mut p = param("phi", 1e-3, 1.0, 0.1);
        p.log = true;
        let c = calibrate(&[p], &f, &settings(5, 40)).unwrap();
        assert!((c.optimum().x[0] / 10f64.powf(-1.5) - 1.0).abs() < 1e-3);
    }

    #[test]
    fn nelder_mead_finds_a_known_2d_minimum() {
        // a tilted, anisotropic quadratic bowl with minimum 1 at (0.3, 4.0)
        let f = |x: &[f64]| {
            let (a, b) = (x[0] - 0.3, (x[1] - 4.0) / 10.0);
            1.0 + 3.0 * a * a + a * b + b * b
        };
        let params = [param("a", 0.0, 1.0, 0.9), param("b", -10.0, 10.0, 0.0)];
        let c = calibrate(&params, &f, &settings(5, 200)).unwrap();
        let best = c.optimum();
        assert!((best.x[0] - 0.3).abs() < 1e-3, "{best:?}");
        assert!((best.x[1] - 4.0).abs() < 1e-2, "{best:?}");
        assert_eq!(
            c.evaluations
                .iter()
                .filter(|e| e.stage == Stage::Scan)
                .count(),
            25
        );
    }

    #[test]
    fn the_budget_bounds_the_refinement_and_failures_are_skipped() {
        // no misfit left of 0.2 (a failed run), minimum at 0.6
        let f = |x: &[f64]| {
            if x[0] < 0.2 {
                f64::NAN
            } else {
                (x[0] - 0.6).powi(2)
            }
        };
        let c = calibrate(&[param("a", 0.0, 1.0, 0.5)], &f, &settings(5, 3)).unwrap();
        assert_eq!(
            c.evaluations
                .iter()
                .filter(|e| e.stage == Stage::Refine)
                .count(),
            3
        );
        assert!(c.optimum().chi2.is_finite());
        assert!(c.evaluations.iter().any(|e| e.chi2.is_nan()));
    }

    #[test]
    fn scale_points_are_the_values_as_written() {
        let mut p = param("phi", 0.01, 1.0, 0.1);
        p.log = true;
        assert_eq!(p.value(0.5), 0.1);
        assert_eq!(p.value(0.25), 0.0316227766016838);
        assert_eq!((p.value(0.0), p.value(1.0)), (0.01, 1.0));
        assert!((p.unit(0.1) - 0.5).abs() < 1e-15);
        let p = param("a", 0.0, 0.3, 0.1);
        assert_eq!(p.value(1.0 / 3.0), 0.1);
    }

    #[test]
    fn bad_bounds_are_refused() {
        let f = |x: &[f64]| x[0];
        let s = settings(3, 3);
        let err = |p: Param| format!("{:#}", calibrate(&[p], &f, &s).unwrap_err());
        assert!(err(param("a", 1.0, 0.0, 0.5)).contains("not below"));
        assert!(err(param("a", 0.0, 1.0, 2.0)).contains("outside the bounds"));
        assert!(err(param("a", 0.0, f64::INFINITY, 0.5)).contains("finite"));
        let mut p = param("a", 0.0, 1.0, 0.5);
        p.log = true;
        assert!(err(p).contains("positive lower bound"));
    }
}
