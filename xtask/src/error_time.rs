//! `cargo xtask error-time`: the discretisation error of the station profiles and the gate
//! speeds against wall time (issue 8), for first-order upwind and Superbee.
//!
//! Each case (default S-JJ-phi φ = 0.1 and F-JJ φ = 0.1) runs on a ladder of grids, one run
//! at a time, into `runs/error-time/<case>/<level>-<scheme>/`:
//! - `tiny`: the smoke grid coarsened 2× more (a pipeline check, not a fidelity preset);
//! - `smoke`, `coarse`: the grids of the case's fidelity presets;
//! - `paper`: the case's own grid; `finer`: the paper grid refined 2× ([`Segment::refined`]).
//!
//! Every level runs to the case's own end time (the presets' shorter smoke end time would
//! stop before the profile time and the gates), so only the grid changes between levels;
//! `--end-time T` stops every level at T instead and compares the profiles there.
//!
//! Errors, for each case and scheme:
//! - **station profiles** (εs, u_s, θ at the x and last time of the case's first profile
//!   monitor): every run's profile is interpolated linearly onto the cell-centre heights of
//!   the reference run (extended linearly over the half cell at either end) and compared on
//!   the flow band, the heights where any run of the ladder has εs ≥ 0.01 (cases.md front
//!   threshold); L1 = Σ w |q − q_ref| / Σ w with w the reference cell heights, and the
//!   largest |q − q_ref|, both divided by the range (max − min) of q_ref over the band;
//! - **gate speeds** (front monitor): RMS and largest |v − v_ref| in m/s over the gates every
//!   run of the ladder reached;
//! - **front position and mean solids speed against time** (bulk monitor, `bulk.csv`): every
//!   run's history is interpolated linearly onto the reference run's sample times; RMS and
//!   largest difference in m and m/s over the times every run covers (for the front, the
//!   times at which every run has one). Unlike the station profile these exist at every level
//!   whether or not the front reaches the station; the bulk front is whole-cell (the east face
//!   of the last floor cell with εs ≥ the bulk threshold), so it moves in steps of Δx.
//!
//! The reference is the finest level with the quantity. With three levels or more the three
//! finest also give the observed order p, from the norms of the differences of successive
//! levels D₃₂ and D₂₁ (h = √(cells of the paper grid / cells), D₃₂/D₂₁ = (h₃ᵖ − h₂ᵖ)/(h₂ᵖ − h₁ᵖ)),
//! and the Richardson extrapolation q* = q₁ + (q₁ − q₂) h₁ᵖ/(h₂ᵖ − h₁ᵖ) (pointwise), against
//! which every level's error is given as well. The order is called asymptotic when it lies
//! in [0.5, 1.5] × the scheme's nominal order range (upwind: 1; Superbee: 1 at extrema and
//! fronts, 2 where smooth); otherwise, or when the differences do not shrink, the page says
//! so and the Richardson numbers are to be read as indicative only.
//!
//! Every level runs with MFIX's outer iteration (wall closures not relaxed, see
//! [`mfix_iteration`]), whatever the case file sets.
//!
//! Output: `docs/error-time.md` (date, command, levels not run and why, tables),
//! `docs/error-time/error_time.csv` and one log–log SVG of error against wall time per case
//! and quantity in `docs/error-time/`.
//!
//! [`Segment::refined`]: runout_mesh::Segment::refined

use std::fmt::Write as _;
use std::path::Path;
use std::str::FromStr;

use anyhow::{bail, Context, Result};
use plotters::prelude::*;
use runout_case::{
    validate_case, Case, Convection, DiluteCellClass, Fidelity, WallRelaxationScope,
};
use runout_output::{RunStatus, RunSummary};
use runout_solver::run_case;

use crate::metrics::FLOW_THRESHOLD;
use crate::report::data::{Profile, Table};
use crate::stability::today;
use crate::sweep::{finished_run, matrix};

/// The cases of issue 8's error-against-time study.
pub const DEFAULT_CASES: &str = "S-JJ-phi_phi=0.1,F-JJ_phi=0.1";
/// What `--no-run` reports for a level without a finished run.
const NOT_RUN: &str = "not run (--no-run)";
/// Run folders, relative to the workspace root.
const RUNS_DIR: &str = "runs/error-time";
/// The page, relative to the workspace root.
const PAGE: &str = "docs/error-time.md";
/// CSV and figures, relative to the workspace root.
const OUTPUT_DIR: &str = "docs/error-time";
/// SVG size [px].
const FIGURE_SIZE: (u32, u32) = (900, 600);
/// Line colours, one per scheme.
const COLOURS: [RGBColor; 4] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
];
/// Refinement factor of the `finer` level over the paper grid (and extra coarsening of
/// `tiny` over the smoke grid).
const LEVEL_STEP: u32 = 2;
/// An observed order is asymptotic within these fractions of the nominal order range.
const ASYMPTOTIC_BAND: (f64, f64) = (0.5, 1.5);

/// A grid of the ladder, coarsest first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Level {
    /// the smoke grid coarsened 2× more: a pipeline check only
    Tiny,
    /// the smoke preset's grid
    Smoke,
    /// the coarse preset's grid
    Coarse,
    /// the case's own (the paper's) grid
    Paper,
    /// the paper grid refined 2×
    Finer,
}

impl Level {
    /// Every level, coarsest first.
    pub const ALL: [Level; 5] = [
        Level::Tiny,
        Level::Smoke,
        Level::Coarse,
        Level::Paper,
        Level::Finer,
    ];

    /// Lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            Level::Tiny => "tiny",
            Level::Smoke => "smoke",
            Level::Coarse => "coarse",
            Level::Paper => "paper",
            Level::Finer => "finer",
        }
    }

    /// `case` on this level's grid, to the case's own end time.
    pub fn case(self, case: &Case) -> Case {
        let mut c = case.clone();
        let coarsen = |factor: u32, c: &mut Case| {
            c.domain.x = case.domain.x.coarsened(factor);
            c.domain.y = case.domain.y.coarsened(factor);
        };
        match self {
            Level::Tiny => coarsen(LEVEL_STEP * case.fidelity.smoke.coarsen, &mut c),
            Level::Smoke => coarsen(case.fidelity.smoke.coarsen, &mut c),
            Level::Coarse => coarsen(case.fidelity.coarse.coarsen, &mut c),
            Level::Paper => {}
            Level::Finer => {
                c.domain.x = case.domain.x.refined(LEVEL_STEP);
                c.domain.y = case.domain.y.refined(LEVEL_STEP);
            }
        }
        c
    }
}

impl std::fmt::Display for Level {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Level {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Level::ALL
            .into_iter()
            .find(|l| l.name() == s.trim())
            .ok_or_else(|| {
                format!("unknown level `{s}`: expected tiny, smoke, coarse, paper or finer")
            })
    }
}

/// Lower-case name of a convection scheme.
pub fn scheme_name(scheme: &Convection) -> &'static str {
    match scheme {
        Convection::Upwind => "upwind",
        Convection::Superbee => "superbee",
    }
}

/// A convection scheme from its name.
pub fn parse_scheme(s: &str) -> Result<Convection, String> {
    match s.trim() {
        "upwind" => Ok(Convection::Upwind),
        "superbee" => Ok(Convection::Superbee),
        other => Err(format!(
            "unknown scheme `{other}`: expected upwind or superbee"
        )),
    }
}

/// The nominal order range of a scheme (upwind: 1; Superbee: 1 at extrema and fronts where
/// the limiter falls back to upwind, 2 where the solution is smooth).
fn nominal_order(scheme: &Convection) -> (f64, f64) {
    match scheme {
        Convection::Upwind => (1.0, 1.0),
        Convection::Superbee => (1.0, 2.0),
    }
}

/// Options of the study.
pub struct Options {
    /// levels to run, any subset
    pub levels: Vec<Level>,
    /// case names (expanded sweep names, e.g. `S-JJ-phi_phi=0.1`)
    pub cases: Vec<String>,
    /// convection schemes
    pub schemes: Vec<Convection>,
    /// read finished runs of an unchanged case instead of rerunning them
    pub reuse: bool,
    /// run nothing: reuse finished runs and report the levels without one as not run
    pub no_run: bool,
    /// stop every run at this time and compare the profiles there (default: the case's end
    /// time and profile time)
    pub end_time: Option<f64>,
}

impl Options {
    /// The command line that reproduces these options.
    pub fn command(&self) -> String {
        let join = |v: Vec<&str>| v.join(",");
        format!(
            "cargo xtask error-time --levels {} --cases {} --schemes {}{}{}",
            join(self.levels.iter().map(|l| l.name()).collect()),
            join(self.cases.iter().map(String::as_str).collect()),
            join(self.schemes.iter().map(scheme_name).collect()),
            self.end_time
                .map_or(String::new(), |t| format!(" --end-time {t}")),
            if self.no_run {
                " --no-run"
            } else if self.reuse {
                " --reuse"
            } else {
                ""
            }
        )
    }
}

/// `case` stopped at `t`: end time `t`, every profile monitor at `t` only, and the fidelity
/// presets ending no later.
pub fn ending_at(case: &Case, t: f64) -> Case {
    let mut c = case.clone();
    c.run.end_time = t;
    for p in &mut c.monitors.profiles {
        p.times = vec![t];
    }
    for preset in [&mut c.fidelity.smoke, &mut c.fidelity.coarse] {
        preset.end_time = preset.end_time.min(t);
    }
    c
}

/// The quantities compared.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// εs at the station
    EpsS,
    /// u_s at the station
    UsS,
    /// θ at the station
    Theta,
    /// front speed at the gates
    GateSpeed,
    /// whole-cell front position against time (bulk monitor)
    FrontPosition,
    /// εs-weighted mean solids speed against time (bulk monitor)
    MeanSpeed,
}

/// Where a quantity comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Source {
    /// the station profile
    Profile,
    /// gates.csv
    Gates,
    /// bulk.csv
    History,
}

impl Quantity {
    /// Every quantity.
    pub const ALL: [Quantity; 6] = [
        Quantity::EpsS,
        Quantity::UsS,
        Quantity::Theta,
        Quantity::GateSpeed,
        Quantity::FrontPosition,
        Quantity::MeanSpeed,
    ];

    /// Name in files and the CSV.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::EpsS => "eps_s",
            Quantity::UsS => "u_s",
            Quantity::Theta => "theta",
            Quantity::GateSpeed => "gate_speed",
            Quantity::FrontPosition => "front_x",
            Quantity::MeanSpeed => "mean_u_s",
        }
    }

    /// Heading in tables and figures.
    fn heading(self) -> &'static str {
        match self {
            Quantity::EpsS => "εs profile L1/range",
            Quantity::UsS => "u_s profile L1/range",
            Quantity::Theta => "θ profile L1/range",
            Quantity::GateSpeed => "gate speeds RMS [m/s]",
            Quantity::FrontPosition => "front x(t) RMS [m]",
            Quantity::MeanSpeed => "mean u_s(t) RMS [m/s]",
        }
    }

    /// The primary norm's name in the CSV.
    fn norm(self) -> &'static str {
        match self {
            Quantity::GateSpeed | Quantity::MeanSpeed => "rms_m_per_s",
            Quantity::FrontPosition => "rms_m",
            _ => "l1_over_range",
        }
    }

    fn source(self) -> Source {
        match self {
            Quantity::EpsS | Quantity::UsS | Quantity::Theta => Source::Profile,
            Quantity::GateSpeed => Source::Gates,
            Quantity::FrontPosition | Quantity::MeanSpeed => Source::History,
        }
    }

    fn is_profile(self) -> bool {
        self.source() == Source::Profile
    }

    /// The values of a history quantity (front positions: NaN where the run has no front).
    fn of_history(self, h: &History) -> &[f64] {
        match self {
            Quantity::FrontPosition => &h.front_x,
            Quantity::MeanSpeed => &h.mean_u_s,
            _ => unreachable!("{self:?} is not a history"),
        }
    }

    fn of_profile(self, p: &Profile) -> &[f64] {
        match self {
            Quantity::EpsS => &p.eps_s,
            Quantity::UsS => &p.u_s,
            Quantity::Theta => &p.theta,
            _ => unreachable!("{self:?} is not a profile"),
        }
    }
}

/// What one level of a ladder gives to the error computation.
#[derive(Clone, Debug, Default)]
pub struct LevelData {
    /// representative spacing relative to the paper grid, √(paper cells / cells)
    pub h: f64,
    /// station profile, or why it is missing
    pub profile: Option<Profile>,
    /// front speed per gate number, or none
    pub gates: Option<Vec<(usize, f64)>>,
    /// the bulk monitor's history, or none
    pub history: Option<History>,
}

/// A run's bulk monitor (`bulk.csv`), times increasing.
#[derive(Clone, Debug, Default)]
pub struct History {
    /// sample times [s]
    pub t: Vec<f64>,
    /// whole-cell front position [m]; NaN before the run has a front
    pub front_x: Vec<f64>,
    /// εs-weighted mean solids velocity along x [m/s]
    pub mean_u_s: Vec<f64>,
}

/// The observed order of a quantity from the three finest levels.
#[derive(Clone, Debug, PartialEq)]
pub struct Order {
    /// the three levels (indices into the ladder), finest first
    pub levels: [usize; 3],
    /// norm of (level 2 − level 1) and of (level 3 − level 2), in the quantity's unit
    pub d21: f64,
    /// see `d21`
    pub d32: f64,
    /// the observed order, if the differences shrink at a positive rate (p ≤ 20)
    pub p: Option<f64>,
}

/// The errors of one quantity over a ladder.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct QuantityErrors {
    /// index of the reference level, if any level has the quantity
    pub reference: Option<usize>,
    /// primary norm against the reference, per level (None: the reference itself, or no data)
    pub vs_reference: Vec<Option<f64>>,
    /// largest difference against the reference (relative to the range for profiles)
    pub max_vs_reference: Vec<Option<f64>>,
    /// primary norm against the Richardson extrapolation, per level
    pub richardson: Vec<Option<f64>>,
    /// observed order, with three levels or more
    pub order: Option<Order>,
    /// samples compared (heights in the flow band, or gates)
    pub samples: usize,
    /// why the quantity has no errors, if so
    pub note: Option<String>,
}

/// Linear interpolation of (xs, ys) at `x`, extended linearly beyond the ends (xs
/// increasing, at least one point). On a sample point it is that sample's value alone, so a
/// NaN neighbour (a history sample without a front) does not spread onto it.
pub fn interpolate(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    if xs.len() == 1 {
        return ys[0];
    }
    let k = xs.partition_point(|&v| v <= x).clamp(1, xs.len() - 1);
    let (x0, x1, y0, y1) = (xs[k - 1], xs[k], ys[k - 1], ys[k]);
    if x == x0 {
        y0
    } else if x == x1 {
        y1
    } else {
        y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    }
}

/// Cell heights from cell-centre heights above a floor at y = 0 (each centre is the midpoint
/// of its faces).
pub fn cell_heights(centres: &[f64]) -> Vec<f64> {
    let mut face = 0.0;
    centres
        .iter()
        .map(|&c| {
            let top = 2.0 * c - face;
            let w = (top - face).max(0.0);
            face = top;
            w
        })
        .collect()
}

/// The observed order p > 0 with d32/d21 = (h3ᵖ − h2ᵖ)/(h2ᵖ − h1ᵖ) for h1 < h2 < h3, if any
/// p in (0, 20] solves it (the right side grows with p from ln(h3/h2)/ln(h2/h1)).
pub fn observed_order(d32: f64, d21: f64, h: [f64; 3]) -> Option<f64> {
    let [h1, h2, h3] = h;
    if !(d21 > 0.0 && d32.is_finite() && h1 < h2 && h2 < h3 && h1 > 0.0) {
        return None;
    }
    let ratio = d32 / d21;
    let g = |p: f64| (h3.powf(p) - h2.powf(p)) / (h2.powf(p) - h1.powf(p));
    let (mut lo, mut hi) = (1e-9, 20.0);
    if !(g(lo) < ratio && ratio <= g(hi)) {
        return None;
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if g(mid) < ratio {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(0.5 * (lo + hi))
}

/// Whether an observed order lies within [`ASYMPTOTIC_BAND`] of the scheme's nominal range.
pub fn asymptotic(p: f64, scheme: &Convection) -> bool {
    let (lo, hi) = nominal_order(scheme);
    (ASYMPTOTIC_BAND.0 * lo..=ASYMPTOTIC_BAND.1 * hi).contains(&p)
}

/// Weighted norm of a difference: weighted L1 for profiles, RMS for gate speeds.
fn norm(quantity: Quantity, weights: &[f64], diff: &[f64]) -> f64 {
    let total: f64 = weights.iter().sum();
    if quantity.is_profile() {
        weights
            .iter()
            .zip(diff)
            .map(|(w, d)| w * d.abs())
            .sum::<f64>()
            / total
    } else {
        (weights
            .iter()
            .zip(diff)
            .map(|(w, d)| w * d * d)
            .sum::<f64>()
            / total)
            .sqrt()
    }
}

fn max_abs(diff: &[f64]) -> f64 {
    diff.iter().fold(0.0, |m, d| m.max(d.abs()))
}

/// Range (max − min) of `values`; the scale of a profile error.
fn range(values: &[f64]) -> f64 {
    let (lo, hi) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), &v| {
            (lo.min(v), hi.max(v))
        });
    hi - lo
}

/// The samples of one quantity: weights and each level's values on them (None: no data).
struct Samples {
    weights: Vec<f64>,
    values: Vec<Option<Vec<f64>>>,
}

/// Samples of a profile quantity on the reference heights within the flow band.
fn profile_samples(quantity: Quantity, ladder: &[LevelData], reference: usize) -> Samples {
    let r = ladder[reference]
        .profile
        .as_ref()
        .expect("the reference has a profile");
    let heights = cell_heights(&r.y);
    let on_reference = |p: &Profile, v: &[f64]| -> Vec<f64> {
        r.y.iter().map(|&y| interpolate(&p.y, v, y)).collect()
    };
    // the flow band: any level's εs ≥ FLOW_THRESHOLD
    let eps: Vec<Vec<f64>> = ladder
        .iter()
        .filter_map(|l| l.profile.as_ref())
        .map(|p| on_reference(p, &p.eps_s))
        .collect();
    let band: Vec<usize> = (0..r.y.len())
        .filter(|&k| eps.iter().any(|e| e[k] >= FLOW_THRESHOLD))
        .collect();
    Samples {
        weights: band.iter().map(|&k| heights[k]).collect(),
        values: ladder
            .iter()
            .map(|l| {
                l.profile.as_ref().map(|p| {
                    let v = on_reference(p, quantity.of_profile(p));
                    band.iter().map(|&k| v[k]).collect()
                })
            })
            .collect(),
    }
}

/// Samples of the gate speeds: the gates every level with gate data reached.
fn gate_samples(ladder: &[LevelData]) -> Samples {
    let with: Vec<&Vec<(usize, f64)>> = ladder.iter().filter_map(|l| l.gates.as_ref()).collect();
    let common: Vec<usize> = with
        .first()
        .map(|g| g.iter().map(|&(n, _)| n).collect::<Vec<_>>())
        .unwrap_or_default()
        .into_iter()
        .filter(|n| with.iter().all(|g| g.iter().any(|(m, _)| m == n)))
        .collect();
    Samples {
        weights: vec![1.0; common.len()],
        values: ladder
            .iter()
            .map(|l| {
                l.gates.as_ref().map(|g| {
                    common
                        .iter()
                        .map(|n| g.iter().find(|(m, _)| m == n).map_or(f64::NAN, |&(_, v)| v))
                        .collect()
                })
            })
            .collect(),
    }
}

/// Samples of a history on the reference run's times that every level covers (for the front,
/// where every level has one). Each level is interpolated linearly in time; a time between a
/// sample with a front and one without is left out.
fn history_samples(quantity: Quantity, ladder: &[LevelData], reference: usize) -> Samples {
    let r = ladder[reference]
        .history
        .as_ref()
        .expect("the reference has a history");
    let with: Vec<&History> = ladder.iter().filter_map(|l| l.history.as_ref()).collect();
    let start = with
        .iter()
        .map(|h| h.t[0])
        .fold(f64::NEG_INFINITY, f64::max);
    let end = with
        .iter()
        .map(|h| h.t[h.t.len() - 1])
        .fold(f64::INFINITY, f64::min);
    // interpolated in time; NaN between a sample with a front and one without
    let at = |h: &History, t: f64| interpolate(&h.t, quantity.of_history(h), t);
    let times: Vec<f64> =
        r.t.iter()
            .copied()
            .filter(|&t| (start..=end).contains(&t))
            .filter(|&t| with.iter().all(|h| at(h, t).is_finite()))
            .collect();
    Samples {
        weights: vec![1.0; times.len()],
        values: ladder
            .iter()
            .map(|l| {
                l.history
                    .as_ref()
                    .map(|h| times.iter().map(|&t| at(h, t)).collect())
            })
            .collect(),
    }
}

/// The errors of `quantity` over `ladder` (levels in any order).
pub fn quantity_errors(quantity: Quantity, ladder: &[LevelData]) -> QuantityErrors {
    let n = ladder.len();
    let has = |l: &LevelData| match quantity.source() {
        Source::Profile => l.profile.is_some(),
        Source::Gates => l.gates.is_some(),
        Source::History => l.history.as_ref().is_some_and(|h| !h.t.is_empty()),
    };
    // levels with data, finest first
    let mut with: Vec<usize> = (0..n).filter(|&k| has(&ladder[k])).collect();
    with.sort_by(|&a, &b| ladder[a].h.total_cmp(&ladder[b].h));
    let mut out = QuantityErrors {
        vs_reference: vec![None; n],
        max_vs_reference: vec![None; n],
        richardson: vec![None; n],
        ..QuantityErrors::default()
    };
    let Some(&reference) = with.first() else {
        out.note = Some("no run has it".into());
        return out;
    };
    out.reference = Some(reference);
    // a station profile is compared only where the reference run has flow there: below the
    // threshold the band is a few dilute cells and the range that scales the error is noise
    if let Some(p) = ladder[reference].profile.as_ref() {
        let peak = p.eps_s.iter().copied().fold(0.0, f64::max);
        if quantity.is_profile() && peak < FLOW_THRESHOLD {
            out.note = Some(format!(
                "the reference run has no flow at the station (largest εs {peak:.1e} < \
                 {FLOW_THRESHOLD}): no profile error"
            ));
            return out;
        }
    }
    let samples = match quantity.source() {
        Source::Profile => profile_samples(quantity, ladder, reference),
        Source::Gates => gate_samples(ladder),
        Source::History => history_samples(quantity, ladder, reference),
    };
    out.samples = samples.weights.len();
    if samples.weights.is_empty() {
        out.note = Some(match quantity.source() {
            Source::Profile => format!("no run has εs ≥ {FLOW_THRESHOLD} at the station"),
            Source::Gates => "no gate reached by every run".into(),
            Source::History => "no sample time common to every run".into(),
        });
        return out;
    }
    let values = |k: usize| samples.values[k].as_ref().expect("a level with data");
    let diff = |a: &[f64], b: &[f64]| -> Vec<f64> { a.iter().zip(b).map(|(x, y)| x - y).collect() };
    let scale = |v: &[f64]| if quantity.is_profile() { range(v) } else { 1.0 };
    let q_ref = values(reference);
    for &k in &with[1..] {
        let d = diff(values(k), q_ref);
        out.vs_reference[k] = Some(norm(quantity, &samples.weights, &d) / scale(q_ref));
        out.max_vs_reference[k] = Some(max_abs(&d) / scale(q_ref));
    }
    if let [l1, l2, l3, ..] = with[..] {
        let (q1, q2, q3) = (values(l1), values(l2), values(l3));
        let d21 = norm(quantity, &samples.weights, &diff(q2, q1));
        let d32 = norm(quantity, &samples.weights, &diff(q3, q2));
        let h = [ladder[l1].h, ladder[l2].h, ladder[l3].h];
        let p = observed_order(d32, d21, h);
        if let Some(p) = p {
            let factor = h[0].powf(p) / (h[1].powf(p) - h[0].powf(p));
            let extrapolated: Vec<f64> = q1
                .iter()
                .zip(q2)
                .map(|(a, b)| a + (a - b) * factor)
                .collect();
            for &k in &with {
                let d = diff(values(k), &extrapolated);
                out.richardson[k] =
                    Some(norm(quantity, &samples.weights, &d) / scale(&extrapolated));
            }
        }
        out.order = Some(Order {
            levels: [l1, l2, l3],
            d21,
            d32,
            p,
        });
    }
    out
}

/// One run of the ladder.
struct Run {
    case: String,
    level: Level,
    cells: (usize, usize),
    /// speed resolution of gates.csv on this grid, if the case has gates [m/s]
    speed_quantum: Option<f64>,
    data: LevelData,
    /// its summary, or why the run failed
    summary: Result<RunSummary, String>,
    reused: bool,
    /// its folder, relative to the workspace root
    dir: String,
}

/// The station profile of a finished run: the case's first profile monitor at its last time.
fn read_profile(dir: &Path, case: &Case) -> Option<Profile> {
    let monitor = case.monitors.profiles.first()?;
    let t = monitor.times.last()?;
    let file = dir.join(format!("profile_x{}_t{t}.csv", monitor.x));
    let table = Table::read(&file).ok()?;
    Some(Profile {
        y: table.column("y").ok()?,
        eps_s: table.column("eps_s").ok()?,
        u_s: table.column("u_s").ok()?,
        theta: table.column("theta").ok()?,
    })
}

/// Front speeds per gate of a finished run with a front monitor; none if its front reached
/// no gate (such a run is left out rather than emptying the common gates of the ladder).
fn read_gates(dir: &Path, case: &Case) -> Option<Vec<(usize, f64)>> {
    case.monitors.front.as_ref()?;
    let pairs = Table::read(&dir.join("gates.csv"))
        .ok()?
        .pairs("gate", "speed")
        .ok()?;
    let speeds: Vec<(usize, f64)> = pairs
        .into_iter()
        .filter(|(_, v)| v.is_finite())
        .map(|(g, v)| (g as usize, v))
        .collect();
    (!speeds.is_empty()).then_some(speeds)
}

/// The bulk monitor history of a finished run, front positions at the domain's west end (no
/// floor cell reaches the threshold yet) replaced by NaN.
fn read_history(dir: &Path, case: &Case, x_start: f64) -> Option<History> {
    case.monitors.bulk.as_ref()?;
    let table = Table::read(&dir.join("bulk.csv")).ok()?;
    let t = table.column("t").ok()?;
    let front_x = table
        .column("front_x")
        .ok()?
        .into_iter()
        .map(|x| if x > x_start { x } else { f64::NAN })
        .collect();
    let mean_u_s = table.column("mean_u_s").ok()?;
    (!t.is_empty()).then_some(History {
        t,
        front_x,
        mean_u_s,
    })
}

/// Every level iterates as MFIX does: the wall closures as computed, not relaxed where they
/// cycle (`numerics.relaxation.wall_closures` = 1, which the sensitivity base sets to 0.5 at
/// cycling nodes for the sweep's speed). The relaxation changes the path of the outer
/// iterations, not the converged step (S-JJ-phi φ = 0.1 at coarse: mean u_s at 1.25 s
/// 4.108170 against 4.108188 m/s with it, docs/performance.md session 6); fixing it keeps
/// the study's runs, made before the sensitivity base relaxed, one solver configuration.
/// Likewise every θ row is classified dilute or dense by the current εs at every outer
/// iteration (`numerics.dilute_cells`), and Δt follows MFIX's controller (a change per 5
/// converged steps, × `factor` after a failed one), which the sensitivity and flume bases
/// change for speed (docs/performance.md, session 7).
fn mfix_iteration(case: &mut Case) {
    case.numerics.relaxation.wall_closures = 1.0;
    case.numerics.relaxation.wall_closures_at = WallRelaxationScope::Everywhere;
    case.numerics.dilute_cells = DiluteCellClass::EveryIteration;
    case.run.dt.steps_per_change = 5;
    case.run.dt.failure_factor = None;
}

/// Runs (or with `reuse` reads) one level of one case with one scheme.
fn run_level(
    root: &Path,
    case: &Case,
    scheme: &Convection,
    level: Level,
    paper_cells: usize,
    opts: &Options,
) -> Result<Run> {
    let mut resolved = level.case(case);
    resolved.numerics.convection = scheme.clone();
    mfix_iteration(&mut resolved);
    if let Err(errors) = validate_case(&resolved) {
        let list: Vec<String> = errors.iter().map(ToString::to_string).collect();
        bail!(
            "{} at level {level}: invalid grid: {}",
            case.name,
            list.join("; ")
        );
    }
    let grid = resolved.grid()?;
    let cells = (grid.nx(), grid.ny());
    // gates.csv takes a central difference of the front over four samples; a whole-cell
    // front would give speeds in steps of Δx/(4 × interval) at the gates (the interpolated
    // front of front.csv does not: the value is printed for scale)
    let speed_quantum = resolved.monitors.front.as_ref().and_then(|f| {
        let x = f.gate_origin + f.gates.first()?;
        let k = grid.x.locate(x)?;
        Some(grid.x.widths()[k] / (4.0 * f.interval))
    });
    let folder = root.join(RUNS_DIR).join(&case.name);
    let tag = format!("{level}-{}", scheme_name(scheme));
    let done = folder.join(&tag);
    let partial = folder.join(format!("{tag}.partial"));
    let previous = if opts.reuse || opts.no_run {
        finished_run(&done, &resolved)
    } else {
        None
    };
    let reused = previous.is_some();
    let summary = if let Some(s) = previous {
        println!("{} {tag}: reusing {}", case.name, done.display());
        Ok(s)
    } else if opts.no_run {
        println!("{} {tag}: no finished run, not run (--no-run)", case.name);
        Err(format!(
            "{NOT_RUN}: no finished run of this case at this level"
        ))
    } else {
        let _ = std::fs::remove_dir_all(&partial);
        println!(
            "{} {tag}: {} × {} cells to t = {} s ...",
            case.name, cells.0, cells.1, resolved.run.end_time
        );
        // `Paper` runs the resolved case as it is (at_fidelity(Paper) is the identity)
        match run_case(&resolved, Fidelity::Paper, &partial, |p| {
            if p.steps % 500 == 0 {
                eprintln!(
                    "  t = {:.3} s, dt = {:.1e} s, {} it",
                    p.time, p.dt, p.iterations
                );
            }
        }) {
            Ok(mut s) => {
                // the summary names the level, not the `Paper` the runner was handed
                s.fidelity = format!("error-time {level}");
                s.write_json(&partial.join("summary.json"))?;
                let _ = std::fs::remove_dir_all(&done);
                std::fs::rename(&partial, &done).with_context(|| {
                    format!("renaming {} to {}", partial.display(), done.display())
                })?;
                println!(
                    "  {:?} at t = {:.3} s: {} steps, {:.1} s wall",
                    s.status, s.simulated_time, s.steps, s.wall_time
                );
                Ok(s)
            }
            Err(e) => {
                println!("  FAILED: {e}");
                Err(e.to_string())
            }
        }
    };
    let data = LevelData {
        h: (paper_cells as f64 / (cells.0 * cells.1) as f64).sqrt(),
        profile: summary.as_ref().ok().and(read_profile(&done, &resolved)),
        gates: summary.as_ref().ok().and(read_gates(&done, &resolved)),
        history: summary
            .as_ref()
            .ok()
            .and(read_history(&done, &resolved, grid.x.start())),
    };
    Ok(Run {
        case: case.name.clone(),
        level,
        cells,
        speed_quantum,
        data,
        summary,
        reused,
        dir: format!("{RUNS_DIR}/{}/{tag}", case.name),
    })
}

/// The ladder of one case and scheme, with the errors of every quantity the case has.
struct Ladder {
    case: String,
    scheme: Convection,
    runs: Vec<Run>,
    errors: Vec<(Quantity, QuantityErrors)>,
}

/// The quantities a case's monitors give.
fn quantities(case: &Case) -> Vec<Quantity> {
    Quantity::ALL
        .into_iter()
        .filter(|q| match q.source() {
            Source::Profile => !case.monitors.profiles.is_empty(),
            Source::Gates => case.monitors.front.is_some(),
            Source::History => case.monitors.bulk.is_some(),
        })
        .collect()
}

/// Runs the study and writes its page, CSV and figures.
pub fn error_time(root: &Path, opts: &Options) -> Result<()> {
    if opts.levels.is_empty() || opts.cases.is_empty() || opts.schemes.is_empty() {
        bail!("--levels, --cases and --schemes need at least one entry each");
    }
    let mut levels = opts.levels.clone();
    levels.sort();
    levels.dedup();
    let all = matrix(&root.join("cases"))?.runs;
    let mut cases = Vec::new();
    for name in &opts.cases {
        let Some(c) = all.iter().find(|r| &r.case.name == name) else {
            let near: Vec<&str> = all
                .iter()
                .map(|r| r.case.name.as_str())
                .filter(|n| n.split('_').next() == name.split('_').next())
                .collect();
            bail!(
                "no case `{name}` in cases/ (same family: {})",
                near.join(", ")
            );
        };
        cases.push(match opts.end_time {
            Some(t) => ending_at(&c.case, t),
            None => c.case.clone(),
        });
    }
    let command = opts.command();
    println!("{command}");
    println!(
        "levels {}, one run at a time on {} rayon thread(s)",
        levels
            .iter()
            .map(|l| l.name())
            .collect::<Vec<_>>()
            .join(", "),
        rayon::current_num_threads()
    );
    let mut ladders = Vec::new();
    for case in &cases {
        let paper_cells = case.grid()?.cell_count();
        for scheme in &opts.schemes {
            let runs = levels
                .iter()
                .map(|&level| run_level(root, case, scheme, level, paper_cells, opts))
                .collect::<Result<Vec<Run>>>()?;
            let data: Vec<LevelData> = runs.iter().map(|r| r.data.clone()).collect();
            let errors = quantities(case)
                .into_iter()
                .map(|q| (q, quantity_errors(q, &data)))
                .collect();
            ladders.push(Ladder {
                case: case.name.clone(),
                scheme: scheme.clone(),
                runs,
                errors,
            });
        }
    }
    let out = root.join(OUTPUT_DIR);
    std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
    write_csv(&out.join("error_time.csv"), &ladders)?;
    let mut figures = Vec::new();
    for case in &cases {
        for q in quantities(case) {
            let file = format!("{}_{}.svg", file_stem(&case.name), q.name());
            if draw(&out.join(&file), &case.name, q, &ladders)? {
                figures.push((case.name.clone(), q, file));
            }
        }
    }
    let page = markdown(&command, &today(), &levels, &cases, &ladders, &figures)?;
    runout_output::write_atomic(&root.join(PAGE), page.as_bytes())
        .with_context(|| format!("writing {PAGE}"))?;
    println!(
        "wrote {PAGE}, {OUTPUT_DIR}/error_time.csv and {} figure(s)",
        figures.len()
    );
    let failed = ladders
        .iter()
        .flat_map(|l| &l.runs)
        .filter(|r| {
            r.summary
                .as_ref()
                .is_err_and(|why| !why.starts_with(NOT_RUN))
        })
        .count();
    if failed > 0 {
        bail!("{failed} run(s) failed (see {PAGE})");
    }
    Ok(())
}

/// A file-name-safe form of a case name.
fn file_stem(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '-' | '.') {
                c
            } else {
                '_'
            }
        })
        .collect()
}

fn opt(v: Option<f64>, fmt: impl Fn(f64) -> String) -> String {
    v.filter(|x| x.is_finite()).map_or(String::new(), fmt)
}

fn write_csv(path: &Path, ladders: &[Ladder]) -> Result<()> {
    let mut w = csv::Writer::from_path(path)?;
    w.write_record([
        "case",
        "scheme",
        "level",
        "cells_x",
        "cells_y",
        "h_over_h_paper",
        "status",
        "simulated_time_s",
        "wall_time_s",
        "steps",
        "quantity",
        "norm",
        "samples",
        "reference_level",
        "error_vs_reference",
        "max_error_vs_reference",
        "richardson_error",
        "observed_order",
        "order_asymptotic",
    ])?;
    let e = |v: Option<f64>| opt(v, |x| format!("{x:.6e}"));
    for ladder in ladders {
        for (q, errors) in &ladder.errors {
            let reference = errors.reference.map(|k| ladder.runs[k].level.name());
            let p = errors.order.as_ref().and_then(|o| o.p);
            for (k, run) in ladder.runs.iter().enumerate() {
                let (status, time, wall, steps) = match &run.summary {
                    Ok(s) => (
                        status_text(&s.status),
                        format!("{}", s.simulated_time),
                        format!("{:.3}", s.wall_time),
                        s.steps.to_string(),
                    ),
                    Err(why) => (
                        format!("failed: {why}"),
                        String::new(),
                        String::new(),
                        String::new(),
                    ),
                };
                w.write_record([
                    run.case.clone(),
                    scheme_name(&ladder.scheme).into(),
                    run.level.name().into(),
                    run.cells.0.to_string(),
                    run.cells.1.to_string(),
                    format!("{:.4}", run.data.h),
                    status,
                    time,
                    wall,
                    steps,
                    q.name().into(),
                    q.norm().into(),
                    errors.samples.to_string(),
                    reference.unwrap_or_default().into(),
                    e(errors.vs_reference[k]),
                    e(errors.max_vs_reference[k]),
                    e(errors.richardson[k]),
                    opt(p, |x| format!("{x:.3}")),
                    p.map_or(String::new(), |p| asymptotic(p, &ladder.scheme).to_string()),
                ])?;
            }
        }
    }
    w.flush()?;
    Ok(())
}

/// A run's status in words (the diagnosis of a divergence included).
fn status_text(status: &RunStatus) -> String {
    match status {
        RunStatus::Completed => "completed".into(),
        RunStatus::Diverged { diagnosis } => format!("diverged: {diagnosis}"),
        other => format!("{other:?}").to_lowercase(),
    }
}

/// Whether the page describes a pipeline check rather than a study.
fn pipeline_check(levels: &[Level]) -> bool {
    levels.contains(&Level::Tiny) || levels.len() < 3
}

/// The page: date, command, levels (run or not, and why), definitions, one table per case
/// with the references and observed orders, the figures and every run's folder and status.
fn markdown(
    command: &str,
    date: &str,
    levels: &[Level],
    cases: &[Case],
    ladders: &[Ladder],
    figures: &[(String, Quantity, String)],
) -> Result<String> {
    let mut md = String::new();
    let _ = writeln!(md, "# Discretisation error against run time (issue 8)\n");
    let _ = writeln!(
        md,
        "Generated on {date} by `{command}` (one run at a time, {} rayon thread(s)).\n",
        rayon::current_num_threads()
    );
    if pipeline_check(levels) {
        let _ = writeln!(
            md,
            "> **PIPELINE CHECK, NOT A RESULT.** This page comes from {} level(s){}: too few or \
             too coarse grids to estimate a discretisation error. The study proper needs at \
             least smoke, coarse and paper (`cargo xtask error-time --levels \
             smoke,coarse,paper,finer`).\n",
            levels.len(),
            if levels.contains(&Level::Tiny) {
                " including `tiny` (the smoke grid coarsened 2× more, not a fidelity preset)"
            } else {
                ""
            }
        );
    }
    levels_section(&mut md, levels, cases)?;
    definitions_section(&mut md);
    for case in cases {
        case_section(&mut md, case, ladders, figures);
    }
    let _ = writeln!(md, "## Runs\n");
    for run in ladders.iter().flat_map(|l| &l.runs) {
        let status = match &run.summary {
            Ok(s) => match &s.status {
                RunStatus::Completed => format!("completed at t = {} s", s.simulated_time),
                RunStatus::Diverged { diagnosis } => {
                    format!("**diverged** at t = {:.3} s: {diagnosis}", s.simulated_time)
                }
                other => format!("**{other:?}** at t = {:.3} s", s.simulated_time),
            },
            Err(why) if why.starts_with(NOT_RUN) => why.clone(),
            Err(why) => format!("**failed**: {why}"),
        };
        let _ = writeln!(md, "- `{}`: {status}", run.dir);
    }
    let _ = writeln!(
        md,
        "\nThe numbers are in [error_time.csv]({}/error_time.csv).",
        OUTPUT_DIR.trim_start_matches("docs/")
    );
    Ok(md)
}

fn levels_section(md: &mut String, levels: &[Level], cases: &[Case]) -> Result<()> {
    let _ = writeln!(md, "## Levels\n");
    let _ = writeln!(
        md,
        "Every level runs a case to the same end time (given with the case below; the smoke \
         preset's shorter end time is not used: it would stop before the profile time and the \
         gates); only the grid changes. Every level iterates as MFIX does (the wall closures \
         as computed: `numerics.relaxation.wall_closures` = 1, which the sensitivity base \
         relaxes where they cycle for the sweep's speed; it changes the outer iterations' path, \
         not the converged step). `h` is √(paper cells / cells).\n"
    );
    let names: Vec<String> = cases.iter().map(|c| format!("{} cells", c.name)).collect();
    let _ = writeln!(md, "| level | grid | run here | {} |", names.join(" | "));
    let _ = writeln!(md, "|---|---|---|{}", "---:|".repeat(cases.len()));
    for level in Level::ALL {
        let grid = match level {
            Level::Tiny => "smoke preset coarsened 2× more (pipeline check)",
            Level::Smoke => "smoke preset's coarsening",
            Level::Coarse => "coarse preset's coarsening",
            Level::Paper => "the case's own grid",
            Level::Finer => "paper grid refined 2× in x and y",
        };
        let run = if levels.contains(&level) {
            "yes"
        } else {
            "**no**: not in `--levels` of this command"
        };
        let mut cells = Vec::new();
        for c in cases {
            let g = level.case(c).grid()?;
            cells.push(format!("{} × {} = {}", g.nx(), g.ny(), g.cell_count()));
        }
        let _ = writeln!(md, "| {level} | {grid} | {run} | {} |", cells.join(" | "));
    }
    let _ = writeln!(md);
    Ok(())
}

fn definitions_section(md: &mut String) {
    let _ = writeln!(md, "## Error measures\n");
    let _ = writeln!(
        md,
        "- **Station profiles** (εs, u_s, θ at the x and last time of the case's first profile \
         monitor): each run's profile is interpolated linearly onto the reference run's \
         cell-centre heights and compared where any run of the ladder has εs ≥ {FLOW_THRESHOLD} \
         (the flow band); the error is Σ w |q − q_ref| / Σ w (w: reference cell heights) divided \
         by the range of q_ref over the band (the CSV also has the largest difference over the \
         range).\n\
         - **Gate speeds** (front monitor): RMS of v − v_ref over the gates every run of the \
         ladder reached [m/s] (the CSV also has the largest difference).\n\
         - **Front position and mean solids speed against time** (bulk monitor, `bulk.csv`, \
         every 0.01 s or the case's bulk interval): each run's history is interpolated \
         linearly onto the reference run's sample times; RMS of the difference over the times \
         every run covers (for the front: where every run has one) [m, m/s]. They exist at \
         every level, also where the front never reaches the station. The bulk front is \
         whole-cell (the east face of the last floor cell with εs ≥ the bulk threshold), so it \
         moves in steps of one Δx of its grid.\n\
         - **Reference**: the finest level run with the quantity (named below each table).\n\
         - **Richardson**: with three levels or more, the three finest give the observed order \
         p (D₃₂/D₂₁ = (h₃ᵖ − h₂ᵖ)/(h₂ᵖ − h₁ᵖ), D the same norm of the difference of successive \
         levels) and the extrapolation q* = q₁ + (q₁ − q₂) h₁ᵖ/(h₂ᵖ − h₁ᵖ); the number in \
         brackets is each level's error against q*. The order is **asymptotic** when it lies in \
         [{}, {}] × the scheme's nominal order (upwind 1; Superbee 1 to 2, as its limiter falls \
         back to upwind at extrema and fronts); outside that, or when the differences do not \
         shrink, the extrapolation is not reliable and the page says so.\n",
        ASYMPTOTIC_BAND.0, ASYMPTOTIC_BAND.1
    );
}

/// One row per run of the case: grid, cost, status and the error of each quantity.
fn case_section(
    md: &mut String,
    case: &Case,
    ladders: &[Ladder],
    figures: &[(String, Quantity, String)],
) {
    let qs = quantities(case);
    let _ = writeln!(md, "## {}\n", case.name);
    if qs.is_empty() {
        let _ = writeln!(
            md,
            "The case has neither a profile nor a front monitor: nothing to compare.\n"
        );
        return;
    }
    let _ = writeln!(md, "Every level runs to t = {} s.", case.run.end_time);
    if let Some(m) = case.monitors.profiles.first() {
        let t = m.times.last().copied().unwrap_or(f64::NAN);
        let _ = writeln!(md, "Station profile at x = {} m, t = {t} s.", m.x);
    }
    if let Some(f) = &case.monitors.front {
        let gates: Vec<String> = f.gates.iter().map(f64::to_string).collect();
        let _ = writeln!(
            md,
            "Gates at {} m from x = {} m. The gate speeds of `gates.csv` are a central \
             difference of the front position over four samples {} s apart; that front is \
             interpolated within the floor row (`front.csv`), so the speeds are not quantised. \
             The column \"speed step\", Δx/(4 × {} s), is the quantisation a whole-cell front \
             would have, for scale.",
            gates.join(", "),
            f.gate_origin,
            f.interval,
            f.interval
        );
    }
    let _ = writeln!(
        md,
        "Error cells: against the reference, then (in brackets) against the Richardson \
         extrapolation where it exists; — where the run lacks the quantity (see Runs).\n"
    );
    let headings: Vec<&str> = qs.iter().map(|q| q.heading()).collect();
    let _ = writeln!(
        md,
        "| scheme | level | cells | h | wall time [s] | steps | status |{} {} |",
        if case.monitors.front.is_some() {
            " speed step [m/s] |"
        } else {
            ""
        },
        headings.join(" | ")
    );
    let _ = writeln!(
        md,
        "|---|---|---:|---:|---:|---:|---|{}{}",
        if case.monitors.front.is_some() {
            "---:|"
        } else {
            ""
        },
        "---:|".repeat(qs.len())
    );
    let ladders: Vec<&Ladder> = ladders.iter().filter(|l| l.case == case.name).collect();
    for ladder in &ladders {
        for (k, run) in ladder.runs.iter().enumerate() {
            let (wall, steps, status) = match &run.summary {
                Ok(s) => (
                    format!(
                        "{:.1}{}",
                        s.wall_time,
                        if run.reused { " (reused)" } else { "" }
                    ),
                    s.steps.to_string(),
                    match &s.status {
                        RunStatus::Completed => "completed".to_string(),
                        RunStatus::Diverged { .. } => {
                            format!("diverged at t = {:.3} s", s.simulated_time)
                        }
                        other => format!("{other:?} at t = {:.3} s", s.simulated_time),
                    },
                ),
                Err(why) if why.starts_with(NOT_RUN) => {
                    (String::new(), String::new(), "not run".to_string())
                }
                Err(_) => (String::new(), String::new(), "failed".to_string()),
            };
            let errors: Vec<String> = ladder
                .errors
                .iter()
                .map(|(_, e)| {
                    if e.reference == Some(k) {
                        let rich = opt(e.richardson[k], |x| format!(" ({x:.3e})"));
                        return format!("reference{rich}");
                    }
                    let main = opt(e.vs_reference[k], |x| format!("{x:.3e}"));
                    let rich = opt(e.richardson[k], |x| format!(" ({x:.3e})"));
                    if main.is_empty() && rich.is_empty() {
                        "—".into()
                    } else {
                        format!("{main}{rich}")
                    }
                })
                .collect();
            let _ = writeln!(
                md,
                "| {} | {} | {} × {} | {:.2} | {wall} | {steps} | {status} |{} {} |",
                scheme_name(&ladder.scheme),
                run.level,
                run.cells.0,
                run.cells.1,
                run.data.h,
                run.speed_quantum
                    .map_or(String::new(), |q| format!(" {q:.2} |")),
                errors.join(" | ")
            );
        }
    }
    let _ = writeln!(md);
    for ladder in &ladders {
        for (q, e) in &ladder.errors {
            let _ = writeln!(md, "{}", order_line(ladder, *q, e));
        }
    }
    let _ = writeln!(md);
    for (_, q, file) in figures.iter().filter(|(c, _, _)| c == &case.name) {
        let _ = writeln!(
            md,
            "![{} {}: error against wall time]({}/{file})\n",
            case.name,
            q.name(),
            OUTPUT_DIR.trim_start_matches("docs/")
        );
    }
    for q in &qs {
        if !figures.iter().any(|(c, f, _)| c == &case.name && f == q) {
            let _ = writeln!(
                md,
                "No figure for {}: no level has an error (the reference alone, or no data).\n",
                q.name()
            );
        }
    }
}

/// The reference, the samples and the observed order of one quantity, as a list item.
fn order_line(ladder: &Ladder, q: Quantity, e: &QuantityErrors) -> String {
    let level = |k: usize| ladder.runs[k].level.name();
    let mut line = format!("- {}, {}: ", scheme_name(&ladder.scheme), q.name());
    match e.reference {
        Some(r) => {
            let what = match q.source() {
                Source::Profile => "heights in the flow band",
                Source::Gates => "gates",
                Source::History => "sample times",
            };
            let _ = write!(line, "reference `{}` ({} {what})", level(r), e.samples);
        }
        None => line.push_str("no reference"),
    }
    if let Some(note) = &e.note {
        let _ = write!(line, "; {note}");
    }
    match &e.order {
        Some(o) => {
            let used = o.levels.map(level).join(", ");
            let diffs = format!("D₂₁ = {:.3e}, D₃₂ = {:.3e}", o.d21, o.d32);
            match o.p {
                Some(p) if asymptotic(p, &ladder.scheme) => {
                    let _ = write!(
                        line,
                        "; observed order p = {p:.2} from {used} ({diffs}), in the asymptotic \
                         range"
                    );
                }
                Some(p) => {
                    let _ = write!(
                        line,
                        "; observed order p = {p:.2} from {used} ({diffs}), **not in the \
                         asymptotic range**: the Richardson numbers are indicative only"
                    );
                }
                None => {
                    let _ = write!(
                        line,
                        "; **no observed order** from {used}: the differences do not shrink at \
                         a positive rate ({diffs}), not in the asymptotic range, no Richardson \
                         estimate"
                    );
                }
            }
        }
        None if e.reference.is_some() => {
            line.push_str("; fewer than three levels: no observed order, no Richardson estimate")
        }
        None => {}
    }
    line.push('.');
    line
}

/// The powers of ten around positive `values` (at least one decade apart), so a log axis
/// always has labelled decades.
fn decades(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, 0.0_f64), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    // a margin of 1.5× keeps points off the frame
    let lo = 10f64.powf((lo / 1.5).log10().floor());
    let hi = 10f64.powf((hi * 1.5).log10().ceil()).max(10.0 * lo);
    (lo, hi)
}

fn plot_error<E: std::fmt::Debug>(e: E) -> anyhow::Error {
    anyhow::anyhow!("plotting the error-time figure: {e:?}")
}

/// Log–log error against wall time for one case and quantity, one colour per scheme: solid
/// against the reference, dashed against the Richardson extrapolation. Returns false (and
/// writes nothing) when no level has a positive error.
fn draw(path: &Path, case: &str, quantity: Quantity, ladders: &[Ladder]) -> Result<bool> {
    // (scheme, against reference, against Richardson), points (wall time, error, level)
    type Points = Vec<(f64, f64, &'static str)>;
    let mut lines: Vec<(&'static str, Points, Points)> = Vec::new();
    for ladder in ladders.iter().filter(|l| l.case == case) {
        let Some((_, e)) = ladder.errors.iter().find(|(q, _)| *q == quantity) else {
            continue;
        };
        let points = |errors: &[Option<f64>]| -> Points {
            ladder
                .runs
                .iter()
                .zip(errors)
                .filter_map(|(r, e)| {
                    let wall = r.summary.as_ref().ok()?.wall_time;
                    let e = (*e)?;
                    (e > 0.0 && e.is_finite() && wall > 0.0).then_some((wall, e, r.level.name()))
                })
                .collect()
        };
        lines.push((
            scheme_name(&ladder.scheme),
            points(&e.vs_reference),
            points(&e.richardson),
        ));
    }
    let all: Vec<(f64, f64)> = lines
        .iter()
        .flat_map(|(_, a, b)| a.iter().chain(b).map(|&(t, e, _)| (t, e)))
        .collect();
    if all.is_empty() {
        return Ok(false);
    }
    let (t_lo, t_hi) = decades(all.iter().map(|&(t, _)| t));
    let (e_lo, e_hi) = decades(all.iter().map(|&(_, e)| e));
    let area = SVGBackend::new(path, FIGURE_SIZE).into_drawing_area();
    area.fill(&WHITE).map_err(plot_error)?;
    let mut chart = ChartBuilder::on(&area)
        .caption(
            format!("{case}: {}", quantity.heading()),
            ("sans-serif", 18),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((t_lo..t_hi).log_scale(), (e_lo..e_hi).log_scale())
        .map_err(plot_error)?;
    chart
        .configure_mesh()
        .x_desc("wall time [s] (labels: level)")
        .y_desc(format!(
            "error: solid vs finest run, dashed vs Richardson ({})",
            quantity.norm()
        ))
        .draw()
        .map_err(plot_error)?;
    for (k, (scheme, vs_ref, vs_rich)) in lines.iter().enumerate() {
        let colour = COLOURS[k % COLOURS.len()];
        chart
            .draw_series(LineSeries::new(
                vs_ref.iter().map(|&(t, e, _)| (t, e)),
                colour.stroke_width(2),
            ))
            .map_err(plot_error)?
            .label(scheme.to_string())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        chart
            .draw_series(DashedLineSeries::new(
                vs_rich.iter().map(|&(t, e, _)| (t, e)),
                6,
                4,
                colour.stroke_width(1),
            ))
            .map_err(plot_error)?;
        for pts in [vs_ref, vs_rich] {
            chart
                .draw_series(
                    pts.iter()
                        .map(|&(t, e, _)| Circle::new((t, e), 4, colour.filled())),
                )
                .map_err(plot_error)?;
            chart
                .draw_series(pts.iter().map(|&(t, e, level)| {
                    Text::new(level, (t, e), ("sans-serif", 12).into_font().color(&colour))
                }))
                .map_err(plot_error)?;
        }
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(plot_error)?;
    area.present().map_err(plot_error)?;
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Linear profiles q_h(y) = f(y) + C hᵖ g(y) on a uniform grid of `cells` cells over
    /// [0, 0.3] m: linear interpolation is exact for them, so every error is known in
    /// closed form.
    fn synthetic(h: f64, cells: usize, c: f64, p: f64) -> LevelData {
        let dy = 0.3 / cells as f64;
        let y: Vec<f64> = (0..cells).map(|k| (k as f64 + 0.5) * dy).collect();
        let profile = |a: f64, b: f64| -> Vec<f64> {
            y.iter()
                .map(|&y| a + b * y + c * h.powf(p) * (1.0 + 2.0 * y))
                .collect()
        };
        LevelData {
            h,
            profile: Some(Profile {
                eps_s: profile(0.2, 1.0),
                u_s: profile(1.0, 10.0),
                theta: profile(0.01, 0.1),
                y,
            }),
            // gate g: speed 2 + g/2 + C hᵖ g
            gates: Some(
                (1..=7)
                    .map(|g| (g, 2.0 + 0.5 * g as f64 + c * h.powf(p) * g as f64))
                    .collect(),
            ),
            history: Some(synthetic_history(h, c, p, 0.0)),
        }
    }

    /// A bulk history sampled every 0.01 s from `offset` (levels sample at different times):
    /// no front before t = 0.1 s, then front x = 5 + 2t + C hᵖ t; mean speed 3t + C hᵖ (1 + t).
    /// Both are linear in t, so interpolation onto the reference times is exact.
    fn synthetic_history(h: f64, c: f64, p: f64, offset: f64) -> History {
        let t: Vec<f64> = (0..=100).map(|k| offset + 0.01 * k as f64).collect();
        let e = c * h.powf(p);
        History {
            front_x: t
                .iter()
                .map(|&t| {
                    if t < 0.1 {
                        f64::NAN
                    } else {
                        5.0 + 2.0 * t + e * t
                    }
                })
                .collect(),
            mean_u_s: t.iter().map(|&t| 3.0 * t + e * (1.0 + t)).collect(),
            t,
        }
    }

    #[test]
    fn errors_orders_and_richardson_of_synthetic_ladders_are_exact() {
        let (c, p) = (0.01, 1.3);
        // coarse to fine, in a shuffled order: smoke, finer, coarse, paper of S-JJ-phi
        let ladder = vec![
            synthetic(10.0, 9, c, p),
            synthetic(0.5, 180, c, p),
            synthetic(4.0, 23, c, p),
            synthetic(1.0, 90, c, p),
        ];
        for q in [Quantity::EpsS, Quantity::UsS, Quantity::Theta] {
            let e = quantity_errors(q, &ladder);
            assert_eq!(e.reference, Some(1), "{q:?}: the finest level");
            assert_eq!(e.samples, 180, "{q:?}: every height is in the flow band");
            let slope = match q {
                Quantity::EpsS => 1.0,
                Quantity::UsS => 10.0,
                _ => 0.1,
            };
            // mean of g = 1 + 2y over [0, 0.3] is 1.3; the reference's range over its centres
            let y_span = 0.3 - 0.3 / 180.0;
            let range_ref = (slope + c * 0.5f64.powf(p) * 2.0) * y_span;
            let range_exact = slope * y_span;
            for (k, h) in [(0, 10.0_f64), (2, 4.0), (3, 1.0)] {
                let expected = c * (h.powf(p) - 0.5f64.powf(p)) * 1.3 / range_ref;
                let got = e.vs_reference[k].unwrap();
                assert!(
                    (got / expected - 1.0).abs() < 1e-9,
                    "{q:?} level {k}: {got} vs {expected}"
                );
            }
            assert_eq!(e.vs_reference[1], None);
            let order = e.order.as_ref().unwrap();
            assert_eq!(order.levels, [1, 3, 2], "the three finest, finest first");
            assert!(
                (order.p.unwrap() - p).abs() < 1e-9,
                "{q:?}: p = {:?}",
                order.p
            );
            // the extrapolation is f itself: each level's error is C hᵖ mean(g) / range(f)
            for (k, h) in [(0, 10.0_f64), (1, 0.5), (2, 4.0), (3, 1.0)] {
                let expected = c * h.powf(p) * 1.3 / range_exact;
                let got = e.richardson[k].unwrap();
                assert!(
                    (got / expected - 1.0).abs() < 1e-7,
                    "{q:?} Richardson {k}: {got} vs {expected}"
                );
            }
        }
        // gate speeds: RMS of C (hᵖ − h₁ᵖ) g over g = 1..7 is C (hᵖ − h₁ᵖ) √(140/7)
        let e = quantity_errors(Quantity::GateSpeed, &ladder);
        let rms_g = (140.0f64 / 7.0).sqrt();
        let got = e.vs_reference[3].unwrap();
        let expected = c * (1.0 - 0.5f64.powf(p)) * rms_g;
        assert!((got / expected - 1.0).abs() < 1e-9, "{got} vs {expected}");
        assert!((e.order.unwrap().p.unwrap() - p).abs() < 1e-9);
        assert!((e.richardson[1].unwrap() / (c * 0.5f64.powf(p) * rms_g) - 1.0).abs() < 1e-7);
    }

    #[test]
    fn history_errors_use_the_common_times_with_a_front() {
        let (c, p) = (0.01, 1.0);
        let mut ladder = vec![
            synthetic(4.0, 23, c, p),
            synthetic(2.0, 45, c, p),
            synthetic(1.0, 90, c, p),
        ];
        // the coarsest run samples 3 ms later and stops 0.2 s earlier
        let mut late = synthetic_history(4.0, c, p, 0.003);
        for v in [&mut late.t, &mut late.front_x, &mut late.mean_u_s] {
            v.truncate(81);
        }
        ladder[0].history = Some(late);
        // reference times 0.00 … 1.00: in [0.003, 0.803] and with a front in every run
        // (the late run's first front sample is at 0.103, so 0.10 interpolates towards NaN)
        // → 0.11 … 0.80 for the front; the mean speed exists from the start: 0.01 … 0.80
        let front_times: Vec<f64> = (11..=80).map(|k| 0.01 * k as f64).collect();
        let speed_times: Vec<f64> = (1..=80).map(|k| 0.01 * k as f64).collect();
        let rms = |times: &[f64], g: &dyn Fn(f64) -> f64| {
            (times.iter().map(|&t| g(t) * g(t)).sum::<f64>() / times.len() as f64).sqrt()
        };
        let front = quantity_errors(Quantity::FrontPosition, &ladder);
        assert_eq!(front.reference, Some(2));
        assert_eq!(front.samples, front_times.len());
        let speed = quantity_errors(Quantity::MeanSpeed, &ladder);
        assert_eq!(speed.samples, speed_times.len());
        for (k, h) in [(0, 4.0_f64), (1, 2.0)] {
            let d = c * (h.powf(p) - 1.0);
            let got = front.vs_reference[k].unwrap();
            let expected = rms(&front_times, &|t| d * t);
            assert!(
                (got / expected - 1.0).abs() < 1e-9,
                "front {k}: {got} vs {expected}"
            );
            let got = speed.vs_reference[k].unwrap();
            let expected = rms(&speed_times, &|t| d * (1.0 + t));
            assert!(
                (got / expected - 1.0).abs() < 1e-9,
                "speed {k}: {got} vs {expected}"
            );
        }
        assert!((front.order.unwrap().p.unwrap() - p).abs() < 1e-9);
        assert!((speed.order.unwrap().p.unwrap() - p).abs() < 1e-9);
        // a run without bulk.csv is left out
        ladder[1].history = None;
        assert_eq!(quantity_errors(Quantity::MeanSpeed, &ladder).order, None);
    }

    #[test]
    fn missing_data_and_non_converging_ladders_say_so() {
        let (c, p) = (0.01, 1.0);
        let mut ladder = vec![
            synthetic(10.0, 9, c, p),
            synthetic(4.0, 23, c, p),
            synthetic(1.0, 90, c, p),
        ];
        // the finest run has no profile (it ended early): the next finest is the reference
        ladder[2].profile = None;
        let e = quantity_errors(Quantity::UsS, &ladder);
        assert_eq!(e.reference, Some(1));
        assert!(e.order.is_none(), "two levels give no order");
        assert!(e.vs_reference[0].unwrap() > 0.0);
        // a reference without flow at the station gives no profile error
        let mut dry = ladder.clone();
        for e in &mut dry[1].profile.as_mut().unwrap().eps_s {
            *e = 1e-3;
        }
        let e = quantity_errors(Quantity::UsS, &dry);
        assert!(e.note.unwrap().contains("no flow at the station"));
        assert!(e.vs_reference.iter().all(Option::is_none));
        // a gate the coarsest run never reached is left out for every level
        ladder[0].gates.as_mut().unwrap().retain(|&(g, _)| g < 7);
        assert_eq!(quantity_errors(Quantity::GateSpeed, &ladder).samples, 6);
        // no data at all
        let empty = vec![LevelData {
            h: 1.0,
            ..LevelData::default()
        }];
        assert_eq!(
            quantity_errors(Quantity::EpsS, &empty).note.as_deref(),
            Some("no run has it")
        );
        // differences that grow under refinement have no positive order
        assert_eq!(observed_order(1.0, 2.0, [1.0, 2.0, 4.0]), None);
        assert_eq!(observed_order(1.0, 0.0, [1.0, 2.0, 4.0]), None);
        // constant ratio 2: D₃₂/D₂₁ = 2ᵖ
        assert!((observed_order(8.0, 2.0, [1.0, 2.0, 4.0]).unwrap() - 2.0).abs() < 1e-9);
        assert!(asymptotic(1.1, &Convection::Upwind));
        assert!(!asymptotic(2.0, &Convection::Upwind));
        assert!(asymptotic(2.0, &Convection::Superbee));
        assert!(!asymptotic(0.3, &Convection::Superbee));
    }

    #[test]
    fn interpolation_and_cell_heights() {
        let (x, y) = ([0.5, 1.5, 2.5], [1.0, 3.0, 2.0]);
        assert_eq!(interpolate(&x, &y, 1.0), 2.0);
        assert_eq!(interpolate(&x, &y, 2.5), 2.0);
        // extended linearly beyond the ends
        assert_eq!(interpolate(&x, &y, 0.0), 0.0);
        assert_eq!(interpolate(&x, &y, 3.0), 1.5);
        assert_eq!(interpolate(&[1.0], &[4.0], 7.0), 4.0);
        // on a sample point its own value, whatever its neighbours hold
        let nan = [f64::NAN, 3.0, f64::NAN];
        assert_eq!(interpolate(&x, &nan, 1.5), 3.0);
        assert!(interpolate(&x, &nan, 1.0).is_nan());
        assert_eq!(decades([3.0, 40.0].into_iter()), (1.0, 100.0));
        assert_eq!(decades([2.0].into_iter()), (1.0, 10.0));
        assert_eq!(decades([8.8].into_iter()), (1.0, 100.0));
        let h = cell_heights(&[0.005, 0.015, 0.03, 0.06]);
        let expected = [0.01, 0.01, 0.02, 0.04];
        assert!(
            h.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-15),
            "{h:?}"
        );
    }

    #[test]
    fn levels_use_the_presets_and_the_refined_paper_grid() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        let runs = matrix(&root.join("cases")).unwrap().runs;
        let case = &runs
            .iter()
            .find(|r| r.case.name == "S-JJ-phi_phi=0.1")
            .unwrap()
            .case;
        let cells = |l: Level| {
            let g = l.case(case).grid().unwrap();
            (g.nx(), g.ny())
        };
        assert_eq!(cells(Level::Paper), (1000, 90));
        assert_eq!(cells(Level::Finer), (2000, 180));
        assert_eq!(
            cells(Level::Coarse),
            case.at_fidelity(Fidelity::Coarse)
                .grid()
                .map(|g| (g.nx(), g.ny()))
                .unwrap()
        );
        assert_eq!(cells(Level::Smoke), (100, 9));
        assert_eq!(cells(Level::Tiny).0, 50);
        // every level runs to the case's own end time
        assert!(Level::ALL
            .iter()
            .all(|l| l.case(case).run.end_time == case.run.end_time));
        assert_eq!("finer".parse::<Level>(), Ok(Level::Finer));
        assert!("fine".parse::<Level>().is_err());
        assert_eq!(parse_scheme("superbee"), Ok(Convection::Superbee));
        // --end-time: the run and the profile stop there, and the case stays valid
        let early = ending_at(case, 0.3);
        assert_eq!(early.run.end_time, 0.3);
        assert_eq!(early.monitors.profiles[0].times, vec![0.3]);
        assert!(validate_case(&Level::Smoke.case(&early)).is_ok());
    }
}
