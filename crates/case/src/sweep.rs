//! Sweep files: a base case plus parameter lists, expanded into named cases.
//!
//! ```ron
//! Sweep(
//!     name: "S-JJ-phi",
//!     base: "base.ron",                     // relative to the sweep file
//!     set: [Diameter([5e-4])],              // fixed for every case of the sweep
//!     vary: [Specularity([1.0, 0.1, 0.01])], // Cartesian product of all lists
//! )
//! ```
//! expands to `S-JJ-phi_phi=1`, `S-JJ-phi_phi=0.1`, `S-JJ-phi_phi=0.01`. A sweep may also
//! give every case side walls (`sidewalls: Some((width: 0.30, solids: …, gas: NoSlip))`,
//! docs/model.md §8), set before the `set` parameters.

use runout_mesh::short;
use serde::{Deserialize, Serialize};

use crate::limits::MAX_SWEEP_CASES;
use crate::schema::{Boundary, Case, Clock, Gravity, Sidewalls, SolidsWall};

/// A sweep file (`Sweep(...)`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Sweep {
    /// Sweep name; the prefix of every expanded case name (the table id of cases.md).
    pub name: String,
    /// Free text (paper figure, what varies, assumptions).
    #[serde(default)]
    pub description: String,
    /// Path of the base case, relative to the sweep file.
    pub base: String,
    /// Parameters fixed for the whole sweep, one value each.
    #[serde(default)]
    pub set: Vec<Param>,
    /// Parameters varied; the sweep is the Cartesian product of their lists.
    #[serde(default)]
    pub vary: Vec<Param>,
    /// Side walls for every case of the sweep (docs/model.md §8), set before `set`; none:
    /// the base case's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sidewalls: Option<Sidewalls>,
    /// A study apart from the paper's matrix (e.g. `"release"`): its cases run only under
    /// `cargo xtask sweep --study NAME`, never in the main sweep or its report.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub study: Option<String>,
}

/// The release block of a sweep's [`Param::Release`]: the case's one initial region becomes
/// the rectangle x ∈ (front − length, front), y ∈ (bottom, bottom + height).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReleaseBlock {
    /// streamwise length [m]
    pub length: f64,
    /// height [m]
    pub height: f64,
    /// x of the downstream (front) edge [m]
    pub front: f64,
    /// height of the bottom above the floor y = 0 [m]
    pub bottom: f64,
}

impl ReleaseBlock {
    /// Label for case names, e.g. `L0.5-H0.2-F5.5-B0.4`.
    pub fn label(&self) -> String {
        format!(
            "L{}-H{}-F{}-B{}",
            short(self.length),
            short(self.height),
            short(self.front),
            short(self.bottom)
        )
    }
}

/// A sweepable parameter and its values. Each applies to every place of the case where it
/// has a meaning, and is an error where it has none (e.g. `Specularity` on a case without a
/// Johnson–Jackson wall).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Param {
    /// particle diameter of every solids phase [m]
    Diameter(Vec<f64>),
    /// specularity of every Johnson–Jackson wall, the side walls' included [-]
    Specularity(Vec<f64>),
    /// h_w^u of every user partial-slip solids wall [m⁻¹]
    PartialSlipHu(Vec<f64>),
    /// h_w^θ of every user partial-slip solids wall [m⁻¹]
    PartialSlipHTheta(Vec<f64>),
    /// c_w of every user partial-slip solids wall [m s⁻²]
    PartialSlipC(Vec<f64>),
    /// slope of the gravity schedule [deg]
    Slope(Vec<f64>),
    /// the solids condition of every wall side (not of the side walls: [`Sweep::sidewalls`])
    SolidsWalls(Vec<SolidsWall>),
    /// the release block (the case's one initial region; its solids state is kept)
    Release(Vec<ReleaseBlock>),
    /// what the times of a tilt-on-impact case count from (docs/studies/impact.md §4)
    Clock(Vec<Clock>),
    /// the factor on every gas inlet's rate [-], ≥ 0; 0 removes the inlets (the same case
    /// without gas let in: a fluidised release's unfluidised control)
    Aeration(Vec<f64>),
}

impl Param {
    /// Short key used in expanded case names.
    pub fn key(&self) -> &'static str {
        match self {
            Param::Diameter(_) => "d",
            Param::Specularity(_) => "phi",
            Param::PartialSlipHu(_) => "hu",
            Param::PartialSlipHTheta(_) => "htheta",
            Param::PartialSlipC(_) => "cw",
            Param::Slope(_) => "slope",
            Param::SolidsWalls(_) => "wall",
            Param::Release(_) => "release",
            Param::Clock(_) => "clock",
            Param::Aeration(_) => "aeration",
        }
    }

    /// Path-like name used in messages.
    pub fn field(&self) -> &'static str {
        match self {
            Param::Diameter(_) => "Diameter",
            Param::Specularity(_) => "Specularity",
            Param::PartialSlipHu(_) => "PartialSlipHu",
            Param::PartialSlipHTheta(_) => "PartialSlipHTheta",
            Param::PartialSlipC(_) => "PartialSlipC",
            Param::Slope(_) => "Slope",
            Param::SolidsWalls(_) => "SolidsWalls",
            Param::Release(_) => "Release",
            Param::Clock(_) => "Clock",
            Param::Aeration(_) => "Aeration",
        }
    }

    /// Number of values.
    pub fn len(&self) -> usize {
        match self {
            Param::Diameter(v)
            | Param::Specularity(v)
            | Param::PartialSlipHu(v)
            | Param::PartialSlipHTheta(v)
            | Param::PartialSlipC(v)
            | Param::Slope(v)
            | Param::Aeration(v) => v.len(),
            Param::SolidsWalls(v) => v.len(),
            Param::Release(v) => v.len(),
            Param::Clock(v) => v.len(),
        }
    }

    /// Whether the list is empty.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Label of value `k` for case names (numbers in short form: `1e-300`, never 300
    /// digits; the shipped values print as they are written).
    pub fn label(&self, k: usize) -> String {
        match self {
            Param::Diameter(v)
            | Param::Specularity(v)
            | Param::PartialSlipHu(v)
            | Param::PartialSlipHTheta(v)
            | Param::PartialSlipC(v)
            | Param::Slope(v)
            | Param::Aeration(v) => short(v[k]),
            Param::SolidsWalls(v) => v[k].label(),
            Param::Release(v) => v[k].label(),
            Param::Clock(v) => format!("{:?}", v[k]),
        }
    }

    /// Applies value `k` to `case`; `Err` says why it does not apply.
    pub fn apply(&self, k: usize, case: &mut Case) -> Result<(), String> {
        match self {
            Param::Diameter(v) => {
                case.solids.iter_mut().for_each(|s| s.diameter = v[k]);
                Ok(())
            }
            Param::Specularity(v) => {
                self.set_wall_number(case, v[k], "a JohnsonJackson solids condition")
            }
            Param::PartialSlipHu(v) | Param::PartialSlipHTheta(v) | Param::PartialSlipC(v) => {
                self.set_wall_number(case, v[k], "a PartialSlip solids condition")
            }
            Param::Slope(v) => {
                match &mut case.gravity {
                    Gravity::Constant { slope, .. } | Gravity::TiltOnImpact { slope, .. } => {
                        *slope = v[k]
                    }
                }
                Ok(())
            }
            Param::SolidsWalls(v) => {
                // the four sides only: the side walls keep their own condition
                let sidewalls = case.sidewalls.take();
                let applied = for_each_solids_wall(case, "any wall side", &mut |w| {
                    *w = v[k].clone();
                    true
                });
                case.sidewalls = sidewalls;
                applied
            }
            Param::Release(v) => {
                let n = case.initial.regions.len();
                let [region] = case.initial.regions.as_mut_slice() else {
                    return Err(format!(
                        "the base case has {n} initial regions; a release needs exactly one"
                    ));
                };
                let b = v[k];
                region.x = (b.front - b.length, b.front);
                region.y = (b.bottom, b.bottom + b.height);
                Ok(())
            }
            Param::Aeration(v) => aerate(case, v[k]),
            Param::Clock(v) => match &mut case.gravity {
                Gravity::TiltOnImpact { clock, .. } => {
                    *clock = v[k];
                    Ok(())
                }
                Gravity::Constant { .. } => {
                    Err("the base case's gravity does not tilt on impact".into())
                }
            },
        }
    }

    /// Sets `value` as this parameter's number of the solids condition of every wall; an
    /// error naming the condition it `needs` if no wall has that number.
    fn set_wall_number(&self, case: &mut Case, value: f64, needs: &str) -> Result<(), String> {
        for_each_solids_wall(case, needs, &mut |w| {
            self.wall_number(w).map(|number| *number = value).is_some()
        })
    }

    /// The number of `wall` this parameter sets, `None` if the condition has no such number.
    fn wall_number<'w>(&self, wall: &'w mut SolidsWall) -> Option<&'w mut f64> {
        match (self, wall) {
            (Param::Specularity(_), SolidsWall::JohnsonJackson { specularity, .. }) => {
                Some(specularity)
            }
            (Param::PartialSlipHu(_), SolidsWall::PartialSlip { h_u, .. }) => Some(h_u),
            (Param::PartialSlipHTheta(_), SolidsWall::PartialSlip { h_theta, .. }) => Some(h_theta),
            (Param::PartialSlipC(_), SolidsWall::PartialSlip { c, .. }) => Some(c),
            _ => None,
        }
    }
}

/// Scales every gas inlet's rate by `factor` (≥ 0); 0 removes the inlets.
fn aerate(case: &mut Case, factor: f64) -> Result<(), String> {
    if !(factor.is_finite() && factor >= 0.0) {
        return Err(format!("a factor >= 0, found {}", short(factor)));
    }
    if case.gas_inlets.is_empty() {
        return Err("the base case has no gas inlet (`gas_inlets`)".into());
    }
    if factor == 0.0 {
        case.gas_inlets.clear();
    } else {
        for inlet in &mut case.gas_inlets {
            inlet.rate = inlet.rate.scaled(factor);
        }
    }
    Ok(())
}

/// Calls `f` on the solids condition of every wall side and of the side walls; `f` says
/// whether the wall had the field it sets. An error if no wall had it.
fn for_each_solids_wall(
    case: &mut Case,
    what: &str,
    f: &mut dyn FnMut(&mut SolidsWall) -> bool,
) -> Result<(), String> {
    let b = &mut case.boundaries;
    let mut hits = 0;
    for side in [&mut b.west, &mut b.east, &mut b.south, &mut b.north] {
        if let Boundary::Wall { solids, .. } = side {
            if f(solids) {
                hits += 1;
            }
        }
    }
    if let Some(sidewalls) = &mut case.sidewalls {
        if f(&mut sidewalls.solids) {
            hits += 1;
        }
    }
    if hits == 0 {
        Err(format!("the base case has no wall with {what}"))
    } else {
        Ok(())
    }
}

/// `base` with the sweep's side walls and `set` parameters applied (what every expanded case starts
/// from). Errors are (field path, message).
pub fn apply_set(sweep: &Sweep, base: &Case) -> Result<Case, (String, String)> {
    let mut fixed = base.clone();
    if let Some(sidewalls) = &sweep.sidewalls {
        fixed.sidewalls = Some(sidewalls.clone());
    }
    for (k, p) in sweep.set.iter().enumerate() {
        if p.len() != 1 {
            return Err((
                format!("set[{k}] ({})", p.field()),
                format!("exactly one value, found {}", p.len()),
            ));
        }
        p.apply(0, &mut fixed)
            .map_err(|m| (format!("set[{k}] ({})", p.field()), m))?;
    }
    Ok(fixed)
}

/// Expands `sweep` over `base` into named cases: at most [`MAX_SWEEP_CASES`], counted
/// before any is built. Errors are (field path, message).
pub fn expand(sweep: &Sweep, base: &Case) -> Result<Vec<Case>, (String, String)> {
    let count = sweep
        .vary
        .iter()
        .try_fold(1usize, |n, p| n.checked_mul(p.len()))
        .filter(|&n| n <= MAX_SWEEP_CASES);
    if count.is_none() {
        let lengths: Vec<String> = sweep.vary.iter().map(|p| p.len().to_string()).collect();
        return Err((
            "vary".into(),
            format!(
                "at most {MAX_SWEEP_CASES} cases in all, found {} (the product of the list \
                 lengths)",
                lengths.join(" x ")
            ),
        ));
    }
    let fixed = apply_set(sweep, base)?;
    for (k, p) in sweep.vary.iter().enumerate() {
        if p.is_empty() {
            return Err((
                format!("vary[{k}] ({})", p.field()),
                "at least one value".into(),
            ));
        }
        let labels: Vec<String> = (0..p.len()).map(|i| p.label(i)).collect();
        for i in 1..labels.len() {
            if labels[..i].contains(&labels[i]) {
                return Err((
                    format!("vary[{k}] ({})[{i}]", p.field()),
                    format!("a value not already listed ({})", labels[i]),
                ));
            }
        }
    }
    let mut cases = Vec::new();
    let mut index = vec![0usize; sweep.vary.len()];
    loop {
        let mut case = fixed.clone();
        let mut name = sweep.name.clone();
        for (p, &i) in sweep.vary.iter().zip(&index) {
            p.apply(i, &mut case)
                .map_err(|m| (format!("vary ({})", p.field()), m))?;
            name.push_str(&format!("_{}={}", p.key(), p.label(i)));
        }
        case.name = name;
        if !sweep.description.is_empty() {
            case.description = format!("{}\n{}", sweep.description, case.description);
        }
        cases.push(case);
        // odometer increment, last parameter fastest
        let mut d = sweep.vary.len();
        loop {
            if d == 0 {
                return Ok(cases);
            }
            d -= 1;
            index[d] += 1;
            if index[d] < sweep.vary[d].len() {
                break;
            }
            index[d] = 0;
        }
    }
}
