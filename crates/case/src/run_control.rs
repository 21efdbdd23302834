//! The run-control part of a case: time stepping, tolerances, output, discretisation and
//! the cheaper fidelities (docs/model.md §4.10–§4.12). Re-exported from the crate root.

use serde::{Deserialize, Serialize};

/// Time stepping, tolerances, output.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RunControl {
    /// simulated end time at paper fidelity [s]
    pub end_time: f64,
    /// time-step control
    pub dt: TimeStep,
    /// convergence tolerances
    #[serde(default)]
    pub tolerances: Tolerances,
    /// interval between field outputs [s]
    pub output_interval: f64,
    /// interval between checkpoints [s of simulated time] (`runout run --restart` continues
    /// from the last one); none: only on a signal or `--checkpoint-every`
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub checkpoint_interval: Option<f64>,
    /// end the run early once its solids are at rest (docs/reference/deposit.md); none (the default):
    /// run to the end time
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stop_at_rest: Option<StopAtRest>,
}

/// When a run counts its solids as at rest and ends (`run.stop_at_rest`): the εs-weighted
/// mean u_s has stayed at or below `speed` and the front (the furthest floor cell with εs ≥
/// `front_threshold`, as the bulk monitor's) has not moved, for `duration` of simulated
/// time. Counted from the start or the restart of a run (not kept in checkpoints), and with a
/// tilt-on-impact gravity only once gravity has tilted (a falling block is not at rest).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StopAtRest {
    /// largest εs-weighted mean u_s at rest [m/s]
    pub speed: f64,
    /// how long the solids must stay at rest [s]
    pub duration: f64,
    /// εs of the front [-] (default 0.01)
    #[serde(default = "default_rest_front_threshold")]
    pub front_threshold: f64,
}

fn default_rest_front_threshold() -> f64 {
    0.01
}

/// Adaptive time-step control (docs/model.md §4.12).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TimeStep {
    /// first Δt [s] (MFIX `DT`)
    pub initial: f64,
    /// smallest Δt before the run stops [s] (MFIX `DT_MIN`)
    pub min: f64,
    /// largest Δt [s] (MFIX `DT_MAX`)
    pub max: f64,
    /// factor of each change (MFIX `DT_FAC`, 0.9); 1 disables adaptation
    #[serde(default = "default_dt_factor")]
    pub factor: f64,
    /// converged steps per change of Δt (MFIX's `STEPS_MIN`, 5): the controller compares
    /// the outer iterations per simulated second of each block of this many steps with the
    /// previous block's. Fewer steps let Δt recover faster after a failed step (at 5, Δt
    /// takes ~140 steps to grow back from 1e-4 to 1e-3 s with `factor` 0.9)
    #[serde(default = "default_steps_per_change")]
    pub steps_per_change: usize,
    /// factor of Δt after a failed step (default: `factor`, as MFIX). A smaller one reaches
    /// a Δt that converges in fewer retries (the coarse flume's first floor contact takes
    /// 24 retries at 0.9, from 1e-3 to 8.9e-5 s)
    #[serde(default)]
    pub failure_factor: Option<f64>,
}

fn default_dt_factor() -> f64 {
    0.9
}

fn default_steps_per_change() -> usize {
    5
}

/// Outer-iteration convergence (docs/model.md §4.11).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Tolerances {
    /// sum of normalised continuity and momentum residuals (MFIX `TOL_RESID`)
    #[serde(default = "default_tol_resid")]
    pub residual: f64,
    /// granular-energy residual (MFIX `TOL_RESID_TH`)
    #[serde(default = "default_tol_resid_theta")]
    pub theta_residual: f64,
    /// a residual sum above this means divergence (MFIX `TOL_DIVERGE`)
    #[serde(default = "default_tol_diverge")]
    pub diverge: f64,
    /// outer iterations per step before it counts as failed (MFIX `MAX_NIT`)
    #[serde(default = "default_max_iterations")]
    pub max_iterations: u32,
    /// two-fluid cases: end a step whose momentum and continuity residual sum stops falling
    /// (checked every 5 outer iterations after the 10th) and retry it with a smaller Δt
    /// (MFIX `DETECT_STALL`, default true; docs/model.md §4.11; the single-phase core ignores it)
    #[serde(default = "default_detect_stall")]
    pub detect_stall: bool,
    /// two-fluid cases: how the momentum residual is normalised (docs/model.md §4.11):
    /// per class of node (the gas; each solids phase's packed body and its loose flow;
    /// default), or pooled over every node and phase as MFIX's `calc_resid.f` does
    #[serde(default)]
    pub momentum_residual: MomentumResidual,
}

/// The normalisation of the momentum residual ([`Tolerances::momentum_residual`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum MomentumResidual {
    /// Σ|r| / Σ|a_P U| per class of node — the gas, each solids phase's nodes where
    /// friction carries most of the viscosity, the rest of its nodes — the largest class
    /// counting: the packed body's large a_P does not hide the head of a flow
    #[default]
    ByClass,
    /// Σ|r| / Σ|a_P U| over every node and phase (MFIX)
    Pooled,
}

fn default_detect_stall() -> bool {
    true
}

fn default_tol_resid() -> f64 {
    1e-3
}

fn default_tol_resid_theta() -> f64 {
    1e-4
}

fn default_tol_diverge() -> f64 {
    1e4
}

fn default_max_iterations() -> u32 {
    500
}

impl Default for Tolerances {
    fn default() -> Self {
        Tolerances {
            residual: default_tol_resid(),
            theta_residual: default_tol_resid_theta(),
            diverge: default_tol_diverge(),
            max_iterations: default_max_iterations(),
            detect_stall: default_detect_stall(),
            momentum_residual: MomentumResidual::default(),
        }
    }
}

/// Discretisation settings (docs/model.md §4.2, §4.10).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Numerics {
    /// convection scheme for every equation (MFIX default: first-order upwind)
    #[serde(default)]
    pub convection: Convection,
    /// under-relaxation factors
    #[serde(default)]
    pub relaxation: Relaxation,
    /// end every converged step with exact discrete solids continuity (not MFIX; default
    /// false: MFIX lets the step tolerance's remainder accumulate where solids compact)
    #[serde(default)]
    pub exact_solids_mass: bool,
    /// the momentum equations' transient and convection: MFIX's continuity-subtracted form
    /// (default) or the conservative form, which adds the momentum cell's continuity
    /// remainder (docs/model.md §4.3, departure M26)
    #[serde(default)]
    pub momentum_form: MomentumForm,
    /// how the θ row of a cell is classified dilute (εs ≤ DIL_EP_S: the mean of its dense
    /// neighbours) or dense (docs/model.md §4.8): at every outer iteration by the current εs
    /// (default, MFIX), or so, but dilute for the rest of a step once a cell's class has
    /// changed back (not MFIX; for cells whose εs straddles DIL_EP_S, where the step
    /// otherwise stalls)
    #[serde(default)]
    pub dilute_cells: DiluteCellClass,
}

/// The form of the momentum equations' transient and convection ([`Numerics::momentum_form`],
/// docs/model.md §4.3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum MomentumForm {
    /// a_P = Σ a_nb + a_P⁰ with the old bulk density, the momentum cell's continuity taken
    /// as satisfied (MFIX, [NUM] §3.2)
    #[default]
    ContinuitySubtracted,
    /// the continuity-subtracted form plus the momentum cell's continuity remainder r φ_P,
    /// so that the phase's momentum changes by its forces alone whatever the outer
    /// iterations leave of continuity (not MFIX)
    Conservative,
}

/// The classification of the θ rows into dilute and dense cells ([`Numerics::dilute_cells`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum DiluteCellClass {
    /// by the current εs at every outer iteration (MFIX)
    #[default]
    EveryIteration,
    /// by the current εs, until a cell's class has changed twice within the step
    /// (dense → dilute → dense, or back); it is then dilute until the step ends
    FrozenWhenCycling,
}

/// Convection scheme (MFIX `DISCRETIZE`).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub enum Convection {
    /// first-order upwind (MFIX 0, the default)
    #[default]
    Upwind,
    /// Superbee TVD via deferred correction (MFIX 2)
    Superbee,
}

/// Under-relaxation factors (MFIX `UR_FAC`, docs/model.md §4.10).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Relaxation {
    /// gas pressure correction, `UR_FAC(1)`
    #[serde(default = "ur_pressure")]
    pub pressure: f64,
    /// selective ε_s correction, `UR_FAC(2)`
    #[serde(default = "ur_half")]
    pub eps_s: f64,
    /// momentum, `UR_FAC(3..5)`
    #[serde(default = "ur_half")]
    pub velocity: f64,
    /// granular energy, `UR_FAC(8)`
    #[serde(default = "ur_half")]
    pub theta: f64,
    /// the solids momentum wall closures of the state-dependent walls (Johnson–Jackson,
    /// Li–Benyahia, Jenkins) between outer iterations; default 1 = MFIX, which uses each
    /// iteration's closures as computed. 0.5 removes the period-2 cycles of a specularity-1
    /// floor (S-JJ-phi φ = 1: 3.3× fewer steps) but doubles the steps of the Jenkins flume
    /// (docs/history/performance-log.md, "Relaxed wall closures"), so it is a per-case choice
    #[serde(default = "ur_one")]
    pub wall_closures: f64,
    /// where `wall_closures` applies: at every wall node (default), or only at the nodes
    /// whose closure changed direction between the last two outer iterations (a cycle), so
    /// that floors whose iteration converges monotonically keep MFIX's iteration
    #[serde(default)]
    pub wall_closures_at: WallRelaxationScope,
    /// what the solids momentum rows' relaxation is proportional to: the whole centre
    /// coefficient (MFIX, Patankar) or the row's own part, without its links (docs/model.md
    /// §4.10: a μ(I) plug's rigid motion, which the centre form freezes); default: the
    /// friction model's (own part for μ(I), centre otherwise)
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub solids_velocity_base: Option<SolidsRelaxationBase>,
}

/// What the solids momentum relaxation is proportional to ([`Relaxation::solids_velocity_base`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum SolidsRelaxationBase {
    /// a_P/ω: the whole centre coefficient (MFIX, Patankar)
    Centre,
    /// a_P + (1 − ω)/ω (a_P − Σ a_nb): the row's own part
    OwnPart,
}

/// Where the wall-closure relaxation applies ([`Relaxation::wall_closures_at`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum WallRelaxationScope {
    /// every wall node, every outer iteration
    #[default]
    Everywhere,
    /// a wall node whose slip coefficient moved the other way in the previous outer
    /// iteration
    Oscillating,
}

fn ur_pressure() -> f64 {
    0.8
}

fn ur_half() -> f64 {
    0.5
}

fn ur_one() -> f64 {
    1.0
}

impl Default for Relaxation {
    fn default() -> Self {
        Relaxation {
            pressure: ur_pressure(),
            eps_s: ur_half(),
            velocity: ur_half(),
            theta: ur_half(),
            wall_closures: ur_one(),
            wall_closures_at: WallRelaxationScope::Everywhere,
            solids_velocity_base: None,
        }
    }
}

/// The cheaper fidelities of a case; they change only the grid and the end time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FidelityPresets {
    /// seconds to run: for CI
    pub smoke: Preset,
    /// minutes to run: the README's default sweep
    pub coarse: Preset,
    /// the wall layer resolved: the paper's cells in y, coarsened in x (docs/studies/impact.md);
    /// default [`FidelityPresets::default_wall`]
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wall: Option<Preset>,
}

impl FidelityPresets {
    /// The `wall` preset: as written, or else the coarse preset's coarsening in x and end
    /// time with the paper's cells in y (`coarsen_y: 1`).
    pub fn wall_preset(&self) -> Preset {
        self.wall.clone().unwrap_or_else(|| self.default_wall())
    }

    /// The `wall` preset of a case that writes none.
    pub fn default_wall(&self) -> Preset {
        Preset {
            coarsen: self.coarse.coarsen,
            coarsen_y: Some(1),
            end_time: self.coarse.end_time,
        }
    }
}

/// A fidelity preset.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Preset {
    /// cells are this many times wider in each direction (in x only when `coarsen_y` is
    /// given) [-]
    pub coarsen: u32,
    /// cells are this many times taller in y (default: `coarsen`) [-]
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coarsen_y: Option<u32>,
    /// simulated end time [s]
    pub end_time: f64,
}

impl Preset {
    /// The coarsening factor in y.
    pub fn factor_y(&self) -> u32 {
        self.coarsen_y.unwrap_or(self.coarsen)
    }
}
