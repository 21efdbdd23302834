//! The RON schema of a case file: everything a run of the paper's case matrix states.
//!
//! Units are SI; angles are in degrees in files (converted to radians inside the solver).
//! Every struct denies unknown fields, so a typo is an error, never silently ignored.
//! Defaults are MFIX 21.3.2's (docs/model.md §5) unless a field says otherwise.

pub use runout_closures::{Drag, FrictionModel, RadialDistribution};
use runout_mesh::{AxisSpec, Side, Sides};
use serde::{Deserialize, Serialize};

use crate::run_control::{FidelityPresets, Numerics, RunControl};

pub use crate::bed::{path_arcs, transect_arcs, Bed, BedPiece};
pub use crate::gas_inlet::{GasInlet, InletRate};
pub use crate::release::{Gate, GateOpening, Polygon};
pub use crate::sidewalls::{GasSidewall, Sidewalls};
/// A side's solids condition: the wall crate's type, with its validation
/// ([`SolidsWall::model`]).
pub use runout_walls::SolidsWall;

/// One simulation case (a `Case(...)` file).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Case {
    /// Case name: letters, digits and `-_.=`, used as the run folder name.
    pub name: String,
    /// Free text: the paper figure, what varies, assumptions.
    #[serde(default)]
    pub description: String,
    /// The rectangular domain and its grid.
    pub domain: Domain,
    /// The gas phase; `None` for a dry granular case (no gas momentum, no drag).
    #[serde(default)]
    pub gas: Option<Gas>,
    /// Solids phases 1..M (the paper has M = 1; nothing assumes it). Empty for a
    /// single-phase (gas only) case.
    #[serde(default)]
    pub solids: Vec<Solids>,
    /// Closure choices.
    #[serde(default)]
    pub models: Models,
    /// Boundary condition of each side; the floor is `south`.
    pub boundaries: Sides<Boundary>,
    /// Two side walls in the plane of the slice, a channel width apart, as a width-averaged
    /// friction (docs/model.md §8); none (the default): a plane 2-D flow.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sidewalls: Option<Sidewalls>,
    /// Initial state.
    pub initial: Initial,
    /// Gravity and its schedule.
    pub gravity: Gravity,
    /// The floor's shape: plane (the default) or a slope whose foot turns onto a run-out
    /// (docs/model.md §9).
    #[serde(default, skip_serializing_if = "Bed::is_plane")]
    pub bed: Bed,
    /// Walls across the flow that hold the release until they open (none by default).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub gates: Vec<Gate>,
    /// Segments of wall sides that let gas in, on a schedule (none by default).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub gas_inlets: Vec<GasInlet>,
    /// What is recorded during the run.
    #[serde(default)]
    pub monitors: Monitors,
    /// Time stepping, tolerances and output.
    pub run: RunControl,
    /// Discretisation and iteration settings.
    #[serde(default)]
    pub numerics: Numerics,
    /// The cheaper fidelities of this case (the paper fidelity is the case as written).
    pub fidelity: FidelityPresets,
}

/// The domain rectangle, as a grid description per direction.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Domain {
    /// along the channel (flow goes +x)
    pub x: AxisSpec,
    /// wall-normal; the floor is at the y origin
    pub y: AxisSpec,
}

/// Gas properties (a constant density by default, MFIX `RO_G0`; or an ideal gas, MFIX's
/// default; a constant viscosity, MFIX `MU_G0`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Gas {
    /// density ρ_g [kg m⁻³]; an ideal gas's at `reference_pressure` (its law gives it, and
    /// the value is checked against it)
    pub density: f64,
    /// dynamic viscosity μ_g [Pa s]
    pub viscosity: f64,
    /// reference (ambient) pressure [Pa]
    #[serde(default = "default_reference_pressure")]
    pub reference_pressure: f64,
    /// how ρ_g follows the pressure (docs/model.md §1.4)
    #[serde(default, skip_serializing_if = "GasLaw::is_constant")]
    pub law: GasLaw,
}

/// The gas's equation of state (docs/model.md §1.4).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum GasLaw {
    /// ρ_g = `density` everywhere (MFIX with `RO_G0` set)
    #[default]
    Constant,
    /// ρ_g = P M/(R T) at a fixed temperature (MFIX's default, `RO_G0` unset, with its
    /// energy equations off): molar mass M [kg mol⁻¹] (air 0.028965, MFIX `MW_AVG`),
    /// temperature T [K] (MFIX `T_G0`)
    IdealGas {
        /// M [kg mol⁻¹]
        molar_mass: f64,
        /// T [K]
        temperature: f64,
    },
}

impl GasLaw {
    /// Whether it is the constant density (the default, left out when written).
    pub fn is_constant(&self) -> bool {
        matches!(self, GasLaw::Constant)
    }
}

impl Gas {
    /// The equation of state the solver uses (runout-closures' law).
    pub fn equation_of_state(&self) -> runout_closures::GasLaw {
        match self.law {
            GasLaw::Constant => runout_closures::GasLaw::Constant(self.density),
            GasLaw::IdealGas {
                molar_mass,
                temperature,
            } => runout_closures::GasLaw::IdealGas {
                molar_mass,
                temperature,
            },
        }
    }
}

fn default_reference_pressure() -> f64 {
    101_325.0
}

/// One solids phase: the material and its packing limits.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Solids {
    /// label used in output
    #[serde(default = "default_solids_name")]
    pub name: String,
    /// particle diameter d [m] (MFIX `D_P0`)
    pub diameter: f64,
    /// material density ρ_s [kg m⁻³] (MFIX `RO_S0`)
    pub density: f64,
    /// particle–particle restitution coefficient e [-] (MFIX `C_E`)
    pub restitution: f64,
    /// maximum packing ε_s,max = 1 − ε_g* [-] (MFIX `EP_STAR` = 1 − this)
    pub max_packing: f64,
    /// ε_s,min above which friction acts [-] (MFIX `EPS_F_MIN`, default 0.5)
    #[serde(default = "default_friction_min_packing")]
    pub friction_min_packing: f64,
    /// internal friction angle δ_int [deg] (MFIX `PHI`)
    pub internal_friction_angle: f64,
}

fn default_solids_name() -> String {
    "solids".into()
}

fn default_friction_min_packing() -> f64 {
    0.5
}

/// Closure choices (docs/model.md §2).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Models {
    /// kinetic theory of the solids stresses
    #[serde(default)]
    pub kinetic_theory: KineticTheory,
    /// radial distribution function at contact
    #[serde(default)]
    pub radial_distribution: RadialDistribution,
    /// frictional stress model
    #[serde(default)]
    pub friction: FrictionModel,
    /// gas–solids drag
    #[serde(default)]
    pub drag: Drag,
}

impl Default for Models {
    /// The paper's models: Lun 1984 with the θ PDE, Carnahan–Starling, Princeton friction,
    /// Syamlal–O'Brien drag (MFIX's default drag; the paper does not state one).
    fn default() -> Self {
        Models {
            kinetic_theory: KineticTheory::default(),
            radial_distribution: RadialDistribution::default(),
            friction: FrictionModel::default(),
            drag: Drag::default(),
        }
    }
}

/// Kinetic theory (MFIX `KT_TYPE`, docs/model.md §2.2).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum KineticTheory {
    /// Lun et al. (1984) as MFIX codes it (Agrawal), with the granular-energy PDE
    /// (paper Eq. 11). `alpha` is MFIX's `ALPHA` in the (2+α)/3 factor.
    Lun1984 {
        /// the (2+α)/3 viscosity factor's α [-] (MFIX parameter, 1.6)
        #[serde(default = "default_alpha")]
        alpha: f64,
    },
    /// Syamlal (1987) algebraic θ (production = dissipation), no PDE (MFIX 21.3.2 default).
    Algebraic,
}

fn default_alpha() -> f64 {
    1.6
}

impl Default for KineticTheory {
    fn default() -> Self {
        KineticTheory::Lun1984 {
            alpha: default_alpha(),
        }
    }
}

/// What one side of the domain is.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Boundary {
    /// An impermeable wall with a condition for the gas and one for the solids.
    Wall {
        /// gas tangential-velocity condition
        gas: GasWall,
        /// solids tangential-velocity and granular-temperature condition
        solids: SolidsWall,
    },
    /// A pressure outlet (gas and solids may leave or enter; zero normal gradients).
    PressureOutlet {
        /// the gas pressure held on the outlet
        pressure: OutletPressure,
    },
}

/// Gas condition on a wall (MFIX `NSW`, `FSW`, `PSW` with `BC_HW_G`, `BC_UW_G`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum GasWall {
    /// zero velocity on the wall
    NoSlip,
    /// zero tangential stress
    FreeSlip,
    /// face velocity held at `u_w` (a moving wall, e.g. a cavity lid; MFIX PSW without
    /// `BC_HW_G`, docs/model.md §3.2)
    Moving {
        /// wall velocity along the wall [m s⁻¹]
        u_w: f64,
    },
    /// du/dn + h (u − u_w) = 0 (paper Eq. 12 for the gas)
    PartialSlip {
        /// h [m⁻¹]
        h_u: f64,
        /// wall velocity [m s⁻¹]
        #[serde(default)]
        u_w: f64,
    },
}

/// Gas pressure held on an outlet.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum OutletPressure {
    /// one pressure along the whole outlet [Pa]
    Uniform(f64),
    /// the gas's hydrostatic pressure along the outlet, p(r) = p0 + ρ_g g·(r − r0), with r0
    /// the outlet's first corner (the west end of a north outlet); it follows the gravity
    /// schedule (cases.md "Top outlet under tilted gravity"). The value is p0 [Pa].
    Hydrostatic(f64),
}

/// Initial state: gas everywhere, solids in blocks.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Initial {
    /// granular temperature outside the blocks [m² s⁻²]
    #[serde(default = "default_initial_theta")]
    pub theta: f64,
    /// initial gas velocity (u, v) [m s⁻¹]
    #[serde(default)]
    pub gas_velocity: (f64, f64),
    /// initial gas pressure field
    #[serde(default)]
    pub gas_pressure: InitialPressure,
    /// rectangular blocks of solids, later blocks overwrite earlier ones
    #[serde(default)]
    pub regions: Vec<Block>,
    /// regions of solids bounded by polygons in world coordinates, after the blocks
    /// (crates/case/src/release.rs)
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub polygons: Vec<Polygon>,
}

fn default_initial_theta() -> f64 {
    1e-5
}

/// Initial gas pressure.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub enum InitialPressure {
    /// hydrostatic under the initial gravity, matching the top outlet
    #[default]
    Hydrostatic,
    /// one value everywhere [Pa]
    Uniform(f64),
}

/// A rectangle of solids.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Block {
    /// (x0, x1) [m]
    pub x: (f64, f64),
    /// (y0, y1) [m]
    pub y: (f64, f64),
    /// one entry per solids phase
    pub solids: Vec<BlockSolids>,
    /// which cells the block fills and how much (default `CellCentre`)
    #[serde(default, skip_serializing_if = "Fill::is_cell_centre")]
    pub fill: Fill,
}

/// How an initial block fills the grid's cells.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Fill {
    /// every cell whose centre lies in the block (edges included) takes the block's state:
    /// the released mass depends on the grid (S slide: 117.8 / 149.8 / 131.8 kg/m at smoke
    /// / coarse / paper against 120 kg/m)
    #[default]
    CellCentre,
    /// every cell takes the block's ε_s times the fraction of its area inside the block
    /// (exact rectangle overlap) over what it held before, so the released mass is the
    /// block's area × ε_s × ρ_s on every grid; a cell it overlaps at all takes the block's
    /// velocity and its θ weighted by ε_s
    CoveredFraction,
}

impl Fill {
    /// Whether this is the default fill (then not written to resolved cases).
    pub fn is_cell_centre(&self) -> bool {
        *self == Fill::CellCentre
    }
}

/// The state of one solids phase inside a block.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BlockSolids {
    /// volume fraction ε_s [-]
    pub eps_s: f64,
    /// velocity (u, v) [m s⁻¹]
    #[serde(default)]
    pub velocity: (f64, f64),
    /// granular temperature θ [m² s⁻²]
    #[serde(default = "default_initial_theta")]
    pub theta: f64,
}

/// Gravity. A slope is emulated by tilting gravity: g = (g sin α, −g cos α).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum Gravity {
    /// Tilted by `slope` from the start.
    Constant {
        /// |g| [m s⁻²]
        #[serde(default = "default_gravity")]
        magnitude: f64,
        /// slope α [deg]
        slope: f64,
    },
    /// Vertical until solids first reach the floor, then tilted to `slope` (paper Fig. 3).
    TiltOnImpact {
        /// |g| [m s⁻²]
        #[serde(default = "default_gravity")]
        magnitude: f64,
        /// slope α after impact [deg]
        slope: f64,
        /// a floor cell with ε_s at or above this counts as contact [-]
        /// (assumed; the paper does not define "impact")
        #[serde(default = "default_contact_eps_s")]
        contact_eps_s: f64,
        /// what counts as the impact (default `FloorCell`: a floor cell with ε_s at or
        /// above `contact_eps_s`; the other criteria ignore `contact_eps_s`)
        #[serde(default, skip_serializing_if = "ImpactCriterion::is_floor_cell")]
        criterion: ImpactCriterion,
        /// what the case's end time and profile times count from (default `Start`;
        /// `Impact` needs a criterion whose time is known in advance, docs/studies/impact.md §4)
        #[serde(default, skip_serializing_if = "Clock::is_start")]
        clock: Clock,
    },
}

/// What the times of a case with a tilt-on-impact gravity count from. The paper reports
/// its profiles "at a simulation time (t) of 1.25 s" of a run whose gravity was tilted at
/// the impact, which may be the time since the start or since the tilt (docs/studies/impact.md §4).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Clock {
    /// from the start of the run (t = 0 at the release)
    #[default]
    Start,
    /// from the tilt: the end time and the profile times are the tilt time later; a run
    /// resolves them to times from the start ([`crate::Case::at_fidelity`])
    Impact,
}

impl Clock {
    /// Whether this is the default clock (then not written to resolved cases).
    pub fn is_start(&self) -> bool {
        *self == Clock::Start
    }
}

/// When a [`Gravity::TiltOnImpact`] schedule tilts gravity (docs/studies/impact.md). The paper tilts
/// at "the instant of impacting" without defining it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum ImpactCriterion {
    /// The first floor cell with ε_s ≥ `contact_eps_s`. First-order upwind smears the
    /// block's lower edge over cells, so on a coarse grid a dilute precursor fires it early
    /// (coarse S slide: t ≈ 0.19 s against a free fall of 0.286 s): grid dependent.
    #[default]
    FloorCell,
    /// The dense part of the block reaching the floor: the first floor cell with ε_s ≥
    /// `fraction` × the largest ε_s of the initial regions (summed over phases), so the
    /// smeared dilute edge does not fire it.
    DenseContact {
        /// fraction of the release's ε_s, in (0, 1] [-]
        fraction: f64,
    },
    /// The solids' centre of mass has fallen by h, the height of the lowest initial
    /// region's bottom above the floor: where a rigid block would touch the floor. Upwind
    /// smearing spreads the block about its centre of mass without moving it, so this
    /// follows the fall (with the gas's drag) nearly independently of the grid.
    CentroidDrop,
    /// At the free-fall time t = sqrt(2 h / g) of the lowest initial region's bottom, h
    /// above the floor: independent of the grid by construction (it ignores the gas).
    FreeFall,
    /// At a given time [s].
    At {
        /// time of the tilt [s]
        time: f64,
    },
}

impl ImpactCriterion {
    /// Whether this is the default criterion (it is then not written to resolved cases, so
    /// that cases and run folders from before the criterion existed are unchanged).
    pub fn is_floor_cell(&self) -> bool {
        *self == ImpactCriterion::FloorCell
    }
}

fn default_gravity() -> f64 {
    9.80665
}

fn default_contact_eps_s() -> f64 {
    0.01
}

impl Gravity {
    /// The final slope [deg].
    pub fn slope(&self) -> f64 {
        match *self {
            Gravity::Constant { slope, .. } | Gravity::TiltOnImpact { slope, .. } => slope,
        }
    }
}

/// Monitors (cases.md "stations and outputs").
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Monitors {
    /// wall-normal profiles of ε_s, u_s, θ at a station and times
    #[serde(default)]
    pub profiles: Vec<Profile>,
    /// wall coefficients (h_w^u, φ, COL, FRI, slip) of one wall cell over time
    #[serde(default)]
    pub wall_probes: Vec<WallProbe>,
    /// front position and speed at gates
    #[serde(default)]
    pub front: Option<FrontTracker>,
    /// domain totals over time: solids mass, ε_s-weighted mean u_s, front position
    #[serde(default)]
    pub bulk: Option<BulkSeries>,
}

/// Profiles against distance from the floor at one station.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Profile {
    /// station x [m]
    pub x: f64,
    /// output times [s], increasing
    pub times: Vec<f64>,
}

/// A probe of one wall cell's boundary coefficients over time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WallProbe {
    /// position along the wall [m] (x for south/north walls, y for west/east)
    pub at: f64,
    /// which wall
    #[serde(default = "default_probe_side")]
    pub side: Side,
    /// sampling interval [s]
    pub interval: f64,
}

fn default_probe_side() -> Side {
    Side::South
}

/// Front tracking (cases.md family F): the front is the largest x whose floor-adjacent cell
/// has ε_s ≥ `threshold`; the speed is recorded as the front crosses each gate.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrontTracker {
    /// ε_s threshold [-] (assumed 0.01 in cases.md)
    pub threshold: f64,
    /// x of the point gates are measured from [m]
    #[serde(default)]
    pub gate_origin: f64,
    /// gate distances from `gate_origin` [m], strictly increasing
    #[serde(default)]
    pub gates: Vec<f64>,
    /// sampling interval of the front position [s]
    pub interval: f64,
}

/// Domain totals over time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BulkSeries {
    /// sampling interval [s]
    pub interval: f64,
    /// ε_s threshold of the front position in this series [-]
    #[serde(default = "default_front_threshold")]
    pub front_threshold: f64,
}

fn default_front_threshold() -> f64 {
    0.01
}

/// Family A of cases.md: closed-form profiles of paper Eqs. 12–13 (no flow solver).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Analytic {
    /// name of the family
    pub name: String,
    /// free text
    #[serde(default)]
    pub description: String,
    /// distance over which the profiles are drawn, from the wall into the flow [m]
    pub depth: f64,
    /// velocity profiles of paper Eq. 12
    pub velocity: AnalyticVelocity,
    /// granular-temperature profiles of paper Eq. 13
    pub temperature: AnalyticTemperature,
}

/// Parameters of the closed-form velocity profiles (paper Eq. 12, Fig. 1).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnalyticVelocity {
    /// flow velocity U away from the wall [m s⁻¹]
    pub bulk: f64,
    /// wall velocity U_w [m s⁻¹]
    pub wall: f64,
    /// h_w^u values, one profile each [m⁻¹]
    pub h_u: Vec<f64>,
}

/// Parameters of the closed-form granular-temperature profiles (paper Eq. 13, Fig. 1).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnalyticTemperature {
    /// θ away from the wall [m² s⁻²]
    pub bulk: f64,
    /// θ_w [m² s⁻²]
    pub wall: f64,
    /// h_w^θ values [m⁻¹]
    pub h_theta: Vec<f64>,
    /// c_w values [m s⁻²]
    pub c: Vec<f64>,
}
