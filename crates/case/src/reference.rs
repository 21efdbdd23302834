//! The case-file reference (docs/guide/case-reference.md): every field of a `Case(...)`
//! file with its type, unit, default, allowed range and meaning, the plausibility bands
//! where validation applies them ([`crate::limits::BAND_FIELDS`]), and where docs/model.md
//! gives the equations of each wall condition and closure.
//!
//! `cargo xtask case-reference` writes the page from [`markdown`]; `--check` (in CI) fails
//! when the checked-in page differs. The tests keep the table honest: every field a shipped
//! case holds is documented, every documented field name exists in the schema's sources,
//! and every band is documented where validation applies it.

use crate::limits::{BANDS, BAND_FIELDS};

/// One documented field. `path` is as a case file nests it, with `[]` for a list element
/// and the variant's name for a field of an enum variant (`gravity.TiltOnImpact.slope`); a
/// type documented once for several places starts its own section (`SolidsWall.…`).
#[derive(Clone, Copy, Debug)]
pub struct Field {
    /// where the field is
    pub path: &'static str,
    /// its type as written in the file; an enum lists its variants
    pub ty: &'static str,
    /// SI unit, `-` for a number without one, empty for a non-number
    pub unit: &'static str,
    /// the value when the field is left out; `required` when it cannot be
    pub default: &'static str,
    /// the range validation accepts besides the plausibility band (empty: any value of
    /// the type, finite for numbers)
    pub range: &'static str,
    /// what it means
    pub doc: &'static str,
}

/// A group of fields: a case file's top level, or a type used in several places.
#[derive(Clone, Copy, Debug)]
pub struct Section {
    /// heading
    pub title: &'static str,
    /// where the type is used
    pub intro: &'static str,
    /// its fields
    pub fields: &'static [Field],
}

const fn f(
    path: &'static str,
    ty: &'static str,
    unit: &'static str,
    default: &'static str,
    range: &'static str,
    doc: &'static str,
) -> Field {
    Field {
        path,
        ty,
        unit,
        default,
        range,
        doc,
    }
}

const REQ: &str = "required";

/// The top level of a `Case(...)` file.
#[rustfmt::skip]
const CASE: &[Field] = &[
    f("name", "string", "", REQ, "letters, digits and `-_.=`, at most 100 bytes", "case name; the run folder's name"),
    f("description", "string", "", "\"\"", "", "free text: the figure, what varies, assumptions"),
    f("domain.x", "AxisSpec", "", REQ, "", "grid along the channel (flow goes +x); see AxisSpec"),
    f("domain.y", "AxisSpec", "", REQ, "", "grid normal to the floor, the floor at the y origin; see AxisSpec"),
    f("gas", "optional struct", "", "none", "", "the gas phase; none: a dry granular case (no gas momentum, no drag)"),
    f("gas.density", "number", "kg/m³", REQ, "", "gas density ρ_g (MFIX `RO_G0`)"),
    f("gas.viscosity", "number", "Pa s", REQ, "", "gas dynamic viscosity μ_g (MFIX `MU_G0`)"),
    f("gas.reference_pressure", "number", "Pa", "101325", "", "ambient pressure"),
    f("gas.law", "Constant \\| IdealGas(molar_mass, temperature)", "", "Constant", "", "equation of state: `Constant` keeps ρ_g = `density`; `IdealGas` is ρ_g = P M/(R T) at a fixed temperature (MFIX's default with `RO_G0` unset), `density` then within 1 % of it at `reference_pressure`; two-fluid cases only"),
    f("gas.law.IdealGas.molar_mass", "number", "kg/mol", REQ, "", "molar mass M (air 0.028965; MFIX `MW_AVG`)"),
    f("gas.law.IdealGas.temperature", "number", "K", REQ, "", "temperature T (MFIX `T_G0`)"),
    f("solids", "list of struct", "", "[]", "at most 10 phases; at least one phase unless there is a gas", "solids phases 1..M (the paper has one)"),
    f("solids[].name", "string", "", "\"solids\"", "", "label used in output"),
    f("solids[].diameter", "number", "m", REQ, "", "particle diameter d (MFIX `D_P0`)"),
    f("solids[].density", "number", "kg/m³", REQ, "", "material density ρ_s (MFIX `RO_S0`)"),
    f("solids[].restitution", "number", "-", REQ, "[0, 1]", "particle–particle restitution e (MFIX `C_E`)"),
    f("solids[].max_packing", "number", "-", REQ, "", "maximum packing εs,max (MFIX `EP_STAR` = 1 − this)"),
    f("solids[].friction_min_packing", "number", "-", "0.5", "(0, max_packing)", "εs above which friction acts (MFIX `EPS_F_MIN`)"),
    f("solids[].internal_friction_angle", "number", "deg", REQ, "(0, 90)", "internal friction angle δ_int (MFIX `PHI`)"),
    f("models.kinetic_theory", "Lun1984(alpha) \\| Algebraic", "", "Lun1984(alpha: 1.6)", "", "kinetic theory: Lun et al. 1984 with the granular-energy PDE, or Syamlal's algebraic θ (model.md §2.2)"),
    f("models.kinetic_theory.Lun1984.alpha", "number", "-", "1.6", "", "α of the (2+α)/3 viscosity factor (MFIX `ALPHA`)"),
    f("models.radial_distribution", "CarnahanStarling \\| MaAhmadi", "", "CarnahanStarling", "", "radial distribution function g0 (MFIX `RDF_TYPE`, model.md §2.1)"),
    f("models.friction", "None \\| Schaeffer \\| Princeton \\| MuI(mu_s, mu_2, i_0, shear_rate_floor)", "", "Princeton", "", "frictional stress model (MFIX `FRICTION_MODEL`, model.md §2.4; μ(I) §2.4.4, not in MFIX)"),
    f("models.friction.MuI.mu_s", "number", "-", REQ, "", "μ_s, the friction coefficient at rest"),
    f("models.friction.MuI.mu_2", "number", "-", REQ, "(mu_s, 2]", "μ_2, the friction coefficient at large inertial number"),
    f("models.friction.MuI.i_0", "number", "-", REQ, "", "inertial-number scale I_0"),
    f("models.friction.MuI.shear_rate_floor", "number", "1/s", "1e-3", "", "strain-rate floor γ̇_min that regularises μ(I) at rest"),
    f("models.drag", "SyamlalOBrien(c1, d1) \\| Gidaspow \\| GidaspowBlend \\| WenYu", "", "SyamlalOBrien(c1: 0.8, d1: 2.65)", "", "gas–solids drag law (MFIX `DRAG_TYPE`, model.md §2.6)"),
    f("models.drag.SyamlalOBrien.c1", "number", "-", REQ, "", "MFIX `DRAG_C1`"),
    f("models.drag.SyamlalOBrien.d1", "number", "-", REQ, "", "MFIX `DRAG_D1`"),
    f("boundaries.west", "Boundary", "", REQ, "", "the side x = x0; see Boundary"),
    f("boundaries.east", "Boundary", "", REQ, "", "the side x = x1"),
    f("boundaries.south", "Boundary", "", REQ, "", "the floor y = y0"),
    f("boundaries.north", "Boundary", "", REQ, "", "the top y = y1"),
    f("sidewalls", "optional struct", "", "none", "", "two side walls a channel width apart, as a width-averaged friction (model.md §8); none: a plane 2-D flow"),
    f("sidewalls.width", "number", "m", REQ, "(0, inf)", "channel width W"),
    f("sidewalls.solids", "SolidsWall", "", REQ, "any floor condition, at rest (`u_w` = 0)", "solids condition on both side walls"),
    f("sidewalls.gas", "NoSlip \\| FreeSlip", "", REQ, "", "gas condition on both side walls: NoSlip adds the plane-Poiseuille drag −12 μ_g u/W²"),
    f("initial.theta", "number", "m²/s²", "1e-5", "", "granular temperature outside the blocks"),
    f("initial.gas_velocity", "(number, number)", "m/s", "(0, 0)", "", "initial gas velocity (u, v)"),
    f("initial.gas_pressure", "Hydrostatic \\| Uniform(number)", "Pa", "Hydrostatic", "", "initial gas pressure: hydrostatic under the initial gravity, or one value"),
    f("initial.regions", "list of struct", "", "[]", "", "rectangular blocks of solids; later blocks overwrite earlier ones"),
    f("initial.regions[].x", "(number, number)", "m", REQ, "x0 < x1, both in the domain", "the block's x extent"),
    f("initial.regions[].y", "(number, number)", "m", REQ, "y0 < y1, both in the domain", "the block's y extent"),
    f("initial.regions[].solids", "list of struct", "", REQ, "one entry per solids phase", "the block's state of each phase"),
    f("initial.regions[].solids[].eps_s", "number", "-", REQ, "[0, max_packing) (the sum over phases too)", "volume fraction εs"),
    f("initial.regions[].solids[].velocity", "(number, number)", "m/s", "(0, 0)", "", "solids velocity (u, v)"),
    f("initial.regions[].solids[].theta", "number", "m²/s²", "1e-5", "", "granular temperature θ"),
    f("initial.regions[].fill", "CellCentre \\| CoveredFraction", "", "CellCentre", "", "CellCentre: the cells whose centre is in the block (the released mass depends on the grid); CoveredFraction: εs times the covered fraction of each cell (the same mass on every grid)"),
    f("initial.polygons", "list of struct", "", "[]", "", "regions of solids bounded by polygons in world coordinates (X horizontal, Z elevation, from the floor at the domain's west end, under the final gravity), filled after the blocks by the exact covered fraction of each cell: a pile with a horizontal free surface above a slope, a wedge"),
    f("initial.polygons[].points", "list of (number, number)", "m", REQ, "at least 3 corners, the edges not crossing, an area > 0, every corner above the floor inside the domain", "the corners (X, Z) in order"),
    f("initial.polygons[].solids", "list of struct", "", REQ, "one entry per solids phase", "the region's state of each phase (as `initial.regions[].solids`)"),
    f("initial.polygons[].solids[].eps_s", "number", "-", REQ, "[0, max_packing) (the sum over phases too)", "volume fraction εs"),
    f("initial.polygons[].solids[].velocity", "(number, number)", "m/s", "(0, 0)", "", "solids velocity (u, v) along and normal to the floor"),
    f("initial.polygons[].solids[].theta", "number", "m²/s²", "1e-5", "", "granular temperature θ"),
    f("gates", "list of struct", "", "[]", "needs solids", "walls across the flow, normal to the floor, that hold the release (gas and solids: u = 0 on the faces they cover) until they open; they exert no tangential stress"),
    f("gates[].x", "number", "m", REQ, "inside the domain (the nearest interior u face)", "where the gate stands along the floor"),
    f("gates[].height", "number", "m", REQ, "(0, the domain's height]", "how high it reaches from the floor"),
    f("gates[].open", "Removed(at) \\| Lifted(at, speed)", "", REQ, "", "removed whole at a time, or lifted from the floor at a speed from a time (a run lands a step on the time)"),
    f("gates[].open.Removed.at", "number", "s", REQ, "[0, inf)", "when the gate is removed"),
    f("gates[].open.Lifted.at", "number", "s", REQ, "[0, inf)", "when its lower edge starts to rise"),
    f("gates[].open.Lifted.speed", "number", "m/s", REQ, "(0, inf)", "how fast its lower edge rises"),
    f("gas_inlets", "list of struct", "", "[]", "needs gas; on Wall sides; no two overlapping on one side while open", "segments of wall sides that let gas in (a porous floor, a distributor plate, a vent; MFIX's mass inflow with BC_EP_G = 1), on a schedule; the solids keep the wall's condition there"),
    f("gas_inlets[].side", "West \\| East \\| South \\| North", "", REQ, "a Wall side", "the side it is on"),
    f("gas_inlets[].along", "(number, number)", "m", REQ, "start < end, within the side (x on South/North, y on West/East)", "where along the side; a face covered in part lets in its covered fraction"),
    f("gas_inlets[].rate", "Velocity(v) \\| MassFlux(g)", "", REQ, "", "superficial velocity into the domain [m/s], or mass flux [kg/(m² s)] divided by the gas's density"),
    f("gas_inlets[].rate.Velocity", "number", "m/s", REQ, "(0, inf)", "superficial gas velocity normal to the wall, into the domain"),
    f("gas_inlets[].rate.MassFlux", "number", "kg/(m² s)", REQ, "(0, inf)", "gas mass flux into the domain"),
    f("gas_inlets[].from", "number", "s", "0", "[0, inf)", "when it opens (a run lands a step on it)"),
    f("gas_inlets[].until", "number", "s", "never", "(from, inf)", "when it closes (a run lands a step on it)"),
    f("gravity", "Constant(..) \\| TiltOnImpact(..)", "", REQ, "", "gravity g = (g sin α, −g cos α): tilted from the start, or vertical until the solids reach the floor (paper Fig. 3, docs/studies/impact.md)"),
    f("gravity.Constant.magnitude", "number", "m/s²", "9.80665", "0 or the band", "|g|"),
    f("gravity.Constant.slope", "number", "deg", REQ, "[0, 90)", "slope α"),
    f("gravity.TiltOnImpact.magnitude", "number", "m/s²", "9.80665", "0 or the band", "|g|"),
    f("gravity.TiltOnImpact.slope", "number", "deg", REQ, "[0, 90)", "slope α after the impact"),
    f("gravity.TiltOnImpact.contact_eps_s", "number", "-", "0.01", "(0, 1)", "a floor cell with εs at or above this counts as contact (FloorCell criterion)"),
    f("gravity.TiltOnImpact.criterion", "FloorCell \\| DenseContact(fraction) \\| CentroidDrop \\| FreeFall \\| At(time)", "", "FloorCell", "DenseContact, CentroidDrop and FreeFall need an initial region with solids", "what counts as the impact (docs/studies/impact.md)"),
    f("gravity.TiltOnImpact.criterion.DenseContact.fraction", "number", "-", REQ, "(0, 1]", "a floor cell with εs ≥ fraction × the release's largest εs"),
    f("gravity.TiltOnImpact.criterion.At.time", "number", "s", REQ, "[0, run.end_time]", "the tilt's time"),
    f("gravity.TiltOnImpact.clock", "Start \\| Impact", "", "Start", "Impact only with FreeFall or At", "what the end time and profile times count from (docs/studies/impact.md §4)"),
    f("bed", "Plane \\| Bend(..) \\| Path([..]) \\| Transect(..)", "", "Plane", "all but Plane need solids", "the floor's shape: one plane; a slope whose foot turns onto a run-out; a path of straight pieces joined by arcs; a transect of (x, z) points turned into such a path. All but Plane make x run along the floor and y normal to it (model.md §9)"),
    f("bed.Bend.at", "number", "m", REQ, "inside the domain", "where the arc starts, along the floor"),
    f("bed.Bend.radius", "number", "m", REQ, "(0, inf), the arc ending inside the domain", "arc radius R; the flow must be much thinner than R"),
    f("bed.Bend.slope_after", "number", "deg", "0", "[0, the gravity's slope)", "the run-out's slope after the arc"),
    f("bed.Path", "list of Straight(..) and Arc(..)", "", REQ, "Straight, Arc, Straight, …, Straight from the domain's west end, covering the domain; gravity Constant with slope 0", "the floor as pieces laid end to end; each Arc turns the floor from the Straight before it to the Straight after it"),
    f("bed.Path[].Straight.length", "number", "m", REQ, "(0, inf)", "the straight's length along the floor"),
    f("bed.Path[].Straight.slope", "number", "deg", REQ, "(-90, 90), downhill towards +x positive", "the straight's slope; negative climbs"),
    f("bed.Path[].Arc.radius", "number", "m", REQ, "(0, inf); above the domain's height where the floor turns flatter (else the normals cross: a fold)", "the arc's radius; the flow must be much thinner than it"),
    f("bed.Transect.points", "list of (x, z)", "m", REQ, "at least two, x strictly rising (no vertical or overhanging step), the path covering the domain", "a cut through a terrain model: horizontal distance and elevation; the first point is the domain's west end"),
    f("bed.Transect.radius", "number", "m", REQ, "(0, inf), each arc fitting its two lines (R tan(|Δα|/2) cut off each), above the domain's height where the floor turns flatter", "the radius of the arcs that round each corner of the transect"),
    f("monitors.profiles", "list of struct", "", "[]", "", "wall-normal profiles at a station and times (`profile_x<x>_t<t>.csv`)"),
    f("monitors.profiles[].x", "number", "m", REQ, "in the domain", "station x"),
    f("monitors.profiles[].times", "list of number", "s", REQ, "at least one, increasing, in [0, run.end_time]", "output times"),
    f("monitors.wall_probes", "list of struct", "", "[]", "at most 100", "one wall cell's h_w^u over time (`probe_<side>_<at>.csv`)"),
    f("monitors.wall_probes[].at", "number", "m", REQ, "on the wall", "position along the wall (x on south/north, y on west/east)"),
    f("monitors.wall_probes[].side", "West \\| East \\| South \\| North", "", "South", "a side that is a Wall", "which wall"),
    f("monitors.wall_probes[].interval", "number", "s", REQ, "see Intervals", "sampling interval"),
    f("monitors.front", "optional struct", "", "none", "", "front position and gate times (`front.csv`)"),
    f("monitors.front.threshold", "number", "-", REQ, "(0, 1)", "εs of the front: the largest x whose floor cell has εs ≥ this"),
    f("monitors.front.gate_origin", "number", "m", "0", "in the domain", "x the gate distances count from"),
    f("monitors.front.gates", "list of number", "m", "[]", "increasing, in the domain", "gate distances from `gate_origin`"),
    f("monitors.front.interval", "number", "s", REQ, "see Intervals", "sampling interval"),
    f("monitors.bulk", "optional struct", "", "none", "", "domain totals over time (`bulk.csv`)"),
    f("monitors.bulk.interval", "number", "s", REQ, "see Intervals", "sampling interval"),
    f("monitors.bulk.front_threshold", "number", "-", "0.01", "(0, 1)", "εs of the front position in bulk.csv"),
    f("run.end_time", "number", "s", REQ, "", "simulated end time at the paper fidelity"),
    f("run.dt.initial", "number", "s", REQ, "[min, max]", "first Δt (MFIX `DT`)"),
    f("run.dt.min", "number", "s", REQ, "≤ max, ≥ end_time × 1e-9", "smallest Δt; below it the run stops (MFIX `DT_MIN`)"),
    f("run.dt.max", "number", "s", REQ, "", "largest Δt (MFIX `DT_MAX`)"),
    f("run.dt.factor", "number", "-", "0.9", "(0, 1]", "factor of each Δt change; 1 disables adaptation (MFIX `DT_FAC`, model.md §4.12)"),
    f("run.dt.steps_per_change", "integer", "-", "5", "[1, 10000]", "converged steps per Δt change (MFIX `STEPS_MIN`)"),
    f("run.dt.failure_factor", "optional number", "-", "`factor`", "(0, 1)", "factor of Δt after a failed step"),
    f("run.tolerances.residual", "number", "-", "1e-3", "", "sum of normalised continuity and momentum residuals (MFIX `TOL_RESID`, model.md §4.11)"),
    f("run.tolerances.theta_residual", "number", "-", "1e-4", "", "granular-energy residual (MFIX `TOL_RESID_TH`)"),
    f("run.tolerances.diverge", "number", "-", "1e4", "> residual", "a residual sum above this is divergence (MFIX `TOL_DIVERGE`)"),
    f("run.tolerances.max_iterations", "integer", "-", "500", "[2, 10000]", "outer iterations before a step counts as failed (MFIX `MAX_NIT`)"),
    f("run.tolerances.detect_stall", "bool", "", "true", "", "retry a step whose residual stops falling with a smaller Δt (MFIX `DETECT_STALL`)"),
    f("run.tolerances.momentum_residual", "ByClass \\| Pooled", "", "ByClass", "", "momentum residual normalised per class of node (gas, packed body, loose flow) or pooled over all nodes as MFIX (model.md §4.11)"),
    f("run.output_interval", "number", "s", REQ, "see Intervals", "interval between field outputs (`fields_*.vtr`)"),
    f("run.checkpoint_interval", "optional number", "s", "none", "see Intervals", "interval between checkpoints; none: only on a signal or `--checkpoint-every`"),
    f("run.stop_at_rest", "optional struct", "", "none", "", "end the run once the solids are at rest (docs/reference/deposit.md)"),
    f("run.stop_at_rest.speed", "number", "m/s", REQ, "(0, inf)", "largest εs-weighted mean u_s at rest"),
    f("run.stop_at_rest.duration", "number", "s", REQ, "(0, end_time]", "how long the solids must stay at rest"),
    f("run.stop_at_rest.front_threshold", "number", "-", "0.01", "(0, 1)", "εs of the front that must not move"),
    f("numerics.convection", "Upwind \\| Superbee", "", "Upwind", "", "convection scheme of every equation (MFIX `DISCRETIZE`, model.md §4.2)"),
    f("numerics.relaxation.pressure", "number", "-", "0.8", "", "gas pressure correction (MFIX `UR_FAC(1)`, model.md §4.10)"),
    f("numerics.relaxation.eps_s", "number", "-", "0.5", "", "εs correction (`UR_FAC(2)`)"),
    f("numerics.relaxation.velocity", "number", "-", "0.5", "", "momentum (`UR_FAC(3..5)`)"),
    f("numerics.relaxation.theta", "number", "-", "0.5", "", "granular energy (`UR_FAC(8)`)"),
    f("numerics.relaxation.wall_closures", "number", "-", "1", "", "the state-dependent solids wall closures between outer iterations (1 = MFIX)"),
    f("numerics.relaxation.wall_closures_at", "Everywhere \\| Oscillating", "", "Everywhere", "", "where `wall_closures` applies: every wall node, or the nodes whose closure changed direction"),
    f("numerics.relaxation.solids_velocity_base", "Centre \\| OwnPart", "", "the friction model's", "", "what the solids momentum relaxation is proportional to: the whole centre coefficient (MFIX, Patankar) or the row's own part (model.md §4.10); default OwnPart with μ(I), Centre otherwise"),
    f("numerics.momentum_form", "ContinuitySubtracted \\| Conservative", "", "ContinuitySubtracted", "", "the momentum equations' transient and convection: MFIX's continuity-subtracted form, or the conservative form that adds each momentum cell's continuity remainder (not MFIX; model.md §4.3)"),
    f("numerics.exact_solids_mass", "bool", "", "false", "", "end every converged step with exact discrete solids continuity (not MFIX)"),
    f("numerics.dilute_cells", "EveryIteration \\| FrozenWhenCycling", "", "EveryIteration", "", "how θ rows are classed dilute or dense (model.md §4.8)"),
    f("fidelity.smoke", "Preset", "", REQ, "", "the seconds-long fidelity (CI); see Preset"),
    f("fidelity.coarse", "Preset", "", REQ, "", "the minutes-long fidelity"),
    f("fidelity.wall", "optional Preset", "", "coarse's `coarsen` and `end_time`, `coarsen_y: 1`", "", "the wall layer resolved: the paper's cells in y, coarsened in x"),
];

/// `boundaries.west/east/south/north`.
#[rustfmt::skip]
const BOUNDARY: &[Field] = &[
    f("Boundary.Wall.gas", "NoSlip \\| FreeSlip \\| Moving(u_w) \\| PartialSlip(h_u, u_w)", "", REQ, "", "gas tangential-velocity condition (model.md §3.2)"),
    f("Boundary.Wall.gas.Moving.u_w", "number", "m/s", REQ, "", "wall velocity along the wall (a lid)"),
    f("Boundary.Wall.gas.PartialSlip.h_u", "number", "1/m", REQ, "", "h of du/dn + h (u − u_w) = 0"),
    f("Boundary.Wall.gas.PartialSlip.u_w", "number", "m/s", "0", "", "wall velocity"),
    f("Boundary.Wall.solids", "SolidsWall", "", REQ, "", "solids condition; see SolidsWall"),
    f("Boundary.PressureOutlet.pressure", "Uniform(number) \\| Hydrostatic(number)", "Pa", REQ, "only with a gas", "gas pressure held on the outlet: one value, or p0 + ρ_g g·(r − r0) from the outlet's first corner"),
    f("Boundary.PressureOutlet.pressure.Uniform", "number", "Pa", REQ, "", "the pressure"),
    f("Boundary.PressureOutlet.pressure.Hydrostatic", "number", "Pa", REQ, "", "p0 at the outlet's first corner"),
];

/// The solids wall conditions (the paper's subject).
#[rustfmt::skip]
const SOLIDS_WALL: &[Field] = &[
    f("SolidsWall", "NoSlip \\| FreeSlip \\| PartialSlip(..) \\| JohnsonJackson(..) \\| RevisitedJohnsonJackson(..) \\| Jenkins(..) \\| Coulomb(..)", "", REQ, "", "NoSlip, FreeSlip: zero velocity or zero stress, zero granular-energy flux (model.md §3.2)"),
    f("SolidsWall.PartialSlip.h_u", "number", "1/m", REQ, "[0, inf)", "h_w^u of du/dn + h_u (u − u_w) = 0 (paper Eq. 12, model.md §3.3; MFIX `BC_HW_S`)"),
    f("SolidsWall.PartialSlip.u_w", "number", "m/s", "0", "", "wall velocity U_w (MFIX `BC_UW_S`)"),
    f("SolidsWall.PartialSlip.h_theta", "number", "1/m", REQ, "[0, inf)", "h_w^θ of dθ/dn + h_θ (θ − θ_w) = c (paper Eq. 13; MFIX `BC_HW_THETA_M`)"),
    f("SolidsWall.PartialSlip.theta_w", "number", "m²/s²", REQ, "[0, inf)", "θ_w (MFIX `BC_THETAW_M`)"),
    f("SolidsWall.PartialSlip.c", "number", "m/s²", REQ, "", "c_w (MFIX `BC_C_THETA_M`)"),
    f("SolidsWall.JohnsonJackson.specularity", "number", "-", REQ, "[0, 1]", "Johnson & Jackson 1987 with constant specularity φ (paper Eqs. 14, 18–19, model.md §3.5–3.6; MFIX `PHIP`)"),
    f("SolidsWall.JohnsonJackson.wall_restitution", "number", "-", REQ, "[0, 1]", "particle–wall restitution e_w (MFIX `E_W`)"),
    f("SolidsWall.JohnsonJackson.wall_friction_angle", "number", "deg", REQ, "[0, 90)", "wall friction angle δ_w (MFIX `PHI_W`)"),
    f("SolidsWall.JohnsonJackson.u_w", "number", "m/s", "0", "", "wall velocity"),
    f("SolidsWall.RevisitedJohnsonJackson.wall_restitution", "number", "-", REQ, "[0, 1]", "Li & Benyahia 2012 specularity φ(r), the paper's revisited JJ (paper Eqs. 16–17, model.md §3.7): e_w"),
    f("SolidsWall.RevisitedJohnsonJackson.wall_friction_angle", "number", "deg", REQ, "[0, 90)", "δ_w"),
    f("SolidsWall.RevisitedJohnsonJackson.phi0", "optional number", "-", "computed from k", "(0, 1]", "φ₀ override (MFIX `PHIP0`)"),
    f("SolidsWall.RevisitedJohnsonJackson.u_w", "number", "m/s", "0", "", "wall velocity"),
    f("SolidsWall.Jenkins.wall_restitution", "number", "-", REQ, "[0, 1]", "Jenkins 1992 small-friction, all-sliding limit (paper Eq. 20, model.md §3.8): e_w"),
    f("SolidsWall.Jenkins.wall_friction_angle", "number", "deg", REQ, "[0, 90)", "δ_w"),
    f("SolidsWall.Jenkins.u_w", "number", "m/s", "0", "", "wall velocity"),
    f("SolidsWall.Coulomb.friction", "number", "-", REQ, "[0, 10]", "Coulomb wall τ_w = μ_w P, regularised at zero slip, zero granular-energy flux (model.md §3.11; not in MFIX): μ_w = tan δ_w"),
    f("SolidsWall.Coulomb.slip_floor", "number", "m/s", "1e-4", "(0, 1]", "slip regularisation u_min: a wall loaded to r < 1 of μ_w P creeps at u_min r/√(1 − r²)"),
];

/// `domain.x`, `domain.y`.
#[rustfmt::skip]
const AXIS: &[Field] = &[
    f("AxisSpec.origin", "number", "m", "0", "", "coordinate of the first face"),
    f("AxisSpec.segments", "list of Segment", "", REQ, "at least one; the smallest cell and the adjacent-width ratio in their bands at every fidelity", "consecutive segments, lowest coordinate first (model.md §4.1)"),
    f("AxisSpec.segments[].Uniform.length", "number", "m", REQ, "(0, inf)", "`Uniform(length, cells)`: equal cells"),
    f("AxisSpec.segments[].Uniform.cells", "integer", "-", REQ, "[1, 1000000]", "number of cells"),
    f("AxisSpec.segments[].Geometric.length", "number", "m", REQ, "(0, inf)", "`Geometric(length, cells, growth)`: widths growing by `growth` from cell to cell"),
    f("AxisSpec.segments[].Geometric.cells", "integer", "-", REQ, "[1, 1000000]", "number of cells"),
    f("AxisSpec.segments[].Geometric.growth", "number", "-", REQ, "(0, inf)", "adjacent width ratio w[i+1]/w[i]"),
    f("AxisSpec.segments[].FirstWidth.length", "number", "m", REQ, "(0, inf)", "`FirstWidth(length, cells, first)`: growth solved from the first width (MFIX `FIRST_DX`)"),
    f("AxisSpec.segments[].FirstWidth.cells", "integer", "-", REQ, "[1, 1000000]", "number of cells"),
    f("AxisSpec.segments[].FirstWidth.first", "number", "m", REQ, "(0, length]", "width of the lowest-coordinate cell"),
    f("AxisSpec.segments[].LastWidth.length", "number", "m", REQ, "(0, inf)", "`LastWidth(length, cells, last)`: growth solved from the last width (MFIX `LAST_DX`)"),
    f("AxisSpec.segments[].LastWidth.cells", "integer", "-", REQ, "[1, 1000000]", "number of cells"),
    f("AxisSpec.segments[].LastWidth.last", "number", "m", REQ, "(0, length]", "width of the highest-coordinate cell"),
    f("AxisSpec.segments[].EndWidths.length", "number", "m", REQ, "(0, inf)", "`EndWidths(length, first, last)`: geometric cells from `first` to `last`, the count solved, the smaller end exact"),
    f("AxisSpec.segments[].EndWidths.first", "number", "m", REQ, "(0, length]", "width of the first cell"),
    f("AxisSpec.segments[].EndWidths.last", "number", "m", REQ, "(0, length]", "width of the last cell"),
];

/// `fidelity.smoke`, `fidelity.coarse`, `fidelity.wall`.
#[rustfmt::skip]
const PRESET: &[Field] = &[
    f("Preset.coarsen", "integer", "-", REQ, "≥ 1", "cells this many times wider (in x only when `coarsen_y` is given)"),
    f("Preset.coarsen_y", "optional integer", "-", "`coarsen`", "≥ 1", "cells this many times taller in y"),
    f("Preset.end_time", "number", "s", REQ, "(0, run.end_time]", "simulated end time at this fidelity"),
];

/// Every section of the reference, in page order.
pub const SECTIONS: [Section; 5] = [
    Section {
        title: "Case",
        intro: "The top level of a `Case(...)` file.",
        fields: CASE,
    },
    Section {
        title: "Boundary",
        intro: "Each of `boundaries.west`, `east`, `south` (the floor) and `north`: \
                `Wall(gas: .., solids: ..)` or `PressureOutlet(pressure: ..)`.",
        fields: BOUNDARY,
    },
    Section {
        title: "SolidsWall",
        intro: "The solids condition of a wall (`Boundary.Wall.solids`) and of the side walls \
                (`sidewalls.solids`): the paper's subject. Written as `NoSlip`, `FreeSlip` or \
                `Variant(field: value, ..)`.",
        fields: SOLIDS_WALL,
    },
    Section {
        title: "AxisSpec",
        intro:
            "The grid of one direction (`domain.x`, `domain.y`): `(origin: .., segments: [..])`.",
        fields: AXIS,
    },
    Section {
        title: "Preset",
        intro: "A cheaper fidelity (`fidelity.smoke`, `coarse`, `wall`): only the grid and the \
                end time change. `--fidelity paper` runs the case as written.",
        fields: PRESET,
    },
];

/// The closures and wall conditions a case chooses, with the section of docs/model.md
/// that gives their equations: (case-file value, what it is, section).
#[rustfmt::skip]
pub const MODEL_SECTIONS: &[(&str, &str, &str)] = &[
    ("models.radial_distribution", "radial distribution g0", "§2.1"),
    ("models.kinetic_theory", "kinetic theory", "§2.2"),
    ("models.friction: Schaeffer", "Schaeffer friction", "§2.4.1"),
    ("models.friction: Princeton", "Princeton friction (the paper's)", "§2.4.2"),
    ("models.friction: MuI(..)", "μ(I) friction (not in MFIX)", "§2.4.4"),
    ("models.drag", "gas–solids drag", "§2.6"),
    ("NoSlip, FreeSlip, gas PartialSlip, Moving", "discrete Robin condition on a wall face", "§3.2"),
    ("SolidsWall PartialSlip", "user-set partial slip (paper Eqs. 12–13)", "§3.3"),
    ("SolidsWall JohnsonJackson", "Johnson–Jackson momentum and energy (paper Eqs. 14, 18–19)", "§3.5–3.6"),
    ("SolidsWall RevisitedJohnsonJackson", "Li & Benyahia φ(r) (paper Eqs. 16–17)", "§3.7"),
    ("SolidsWall Jenkins", "Jenkins small-friction limit (paper Eq. 20)", "§3.8"),
    ("SolidsWall Coulomb", "Coulomb wall τ_w = μ_w P (not in MFIX)", "§3.11"),
    ("sidewalls", "width-averaged side-wall friction", "§8"),
    ("bed: Bend(..)", "a slope whose foot turns (bed-following coordinates)", "§9"),
    ("bed: Path([..]), bed: Transect(..)", "a floor of several bends, or a terrain transect (bed-following coordinates)", "§9"),
    ("numerics.relaxation", "under-relaxation", "§4.10"),
    ("run.tolerances", "residuals and convergence", "§4.11"),
    ("run.dt", "adaptive time step", "§4.12"),
];

/// The allowed values of a field: its own range and the bands validation applies to it.
fn allowed(field: &Field) -> String {
    let mut parts: Vec<String> = Vec::new();
    if !field.range.is_empty() {
        parts.push(field.range.to_string());
    }
    for (path, band) in BAND_FIELDS {
        if *path == field.path {
            parts.push(format!("band {}", band.describe()));
        }
    }
    parts.join("; ")
}

/// The page docs/guide/case-reference.md.
pub fn markdown() -> String {
    let mut s = String::new();
    s.push_str(
        "# Case-file reference\n\n\
         <!-- Generated by `cargo xtask case-reference` from crates/case/src/reference.rs and \
         the bands of crates/case/src/limits.rs; CI checks it with `--check`. Do not edit. -->\n\n\
         A case file is RON: `Case(name: \"..\", domain: (..), ..)`. Units are SI, angles in \
         degrees. A struct is written `(field: value, ..)`, an enum variant `Name` or \
         `Name(field: value, ..)`, an optional value as the value itself or `None`. An \
         unknown field is an error, so a typo never passes silently. `runout check CASE` \
         validates a file and names every field out of range; `runout check CASE --explain` \
         prints the case as resolved, defaults filled in.\n\n\
         Columns: **default** is the value when the field is left out (`required`: it cannot \
         be); **allowed** is what validation accepts besides finiteness: a range, and the \
         plausibility **band** of the input's kind (see [Bands](#bands)). A path uses `[]` \
         for a list element and the variant's name for a variant's field \
         (`gravity.TiltOnImpact.slope`).\n\n",
    );
    s.push_str("Sections: ");
    let titles: Vec<String> = SECTIONS
        .iter()
        .map(|x| format!("[{}](#{})", x.title, x.title.to_lowercase()))
        .collect();
    s.push_str(&titles.join(", "));
    s.push_str(", [Closures and wall conditions](#closures-and-wall-conditions), [Bands](#bands), [Intervals and sizes](#intervals-and-sizes).\n\n");
    for section in SECTIONS {
        s.push_str(&format!("## {}\n\n{}\n\n", section.title, section.intro));
        s.push_str(
            "| field | type | unit | default | allowed | meaning |\n|---|---|---|---|---|---|\n",
        );
        for field in section.fields {
            s.push_str(&format!(
                "| `{}` | {} | {} | {} | {} | {} |\n",
                field.path,
                field.ty,
                field.unit,
                field.default,
                allowed(field),
                field.doc
            ));
        }
        s.push('\n');
    }
    s.push_str(
        "## Closures and wall conditions\n\nThe equations of each choice are in \
         [docs/model.md](../model.md):\n\n| in the case file | what | model.md |\n|---|---|---|\n",
    );
    for (value, what, section) in MODEL_SECTIONS {
        s.push_str(&format!(
            "| `{value}` | {what} | [{section}](../model.md) |\n"
        ));
    }
    s.push_str(
        "\n## Bands\n\nEvery dimensional input lies in a plausibility band of its kind: wide \
         enough for any material or flow the model describes, narrow enough to catch a unit \
         error or a typo. Why each end is where it is: \
         [docs/reference/input-validation.md](../reference/input-validation.md).\n\n\
         | input | band | fields |\n|---|---|---|\n",
    );
    for band in BANDS {
        let fields: Vec<String> = BAND_FIELDS
            .iter()
            .filter(|(_, b)| b.what == band.what)
            .map(|(p, _)| format!("`{p}`"))
            .collect();
        s.push_str(&format!(
            "| {} | {} | {} |\n",
            band.what,
            band.describe(),
            fields.join(", ")
        ));
    }
    s.push_str(&format!(
        "\n## Intervals and sizes\n\n\
         - An output, checkpoint or monitor interval is at least {} s and at least the end \
         time / {} (field outputs and checkpoints) or / {} (monitor samples), and at most {} s.\n\
         - A grid has at most {} cells at any fidelity, an axis at most 1000000; a case at most \
         {} solids phases and {} wall probes; iteration counts at most {}.\n\
         - A case file is at most {} bytes; a name at most {} bytes.\n",
        runout_mesh::short(crate::limits::MIN_INTERVAL),
        runout_mesh::short(crate::limits::MAX_OUTPUTS),
        runout_mesh::short(crate::limits::MAX_SAMPLES),
        runout_mesh::short(crate::limits::TIME.hi),
        crate::limits::MAX_CELLS,
        crate::limits::MAX_SOLIDS_PHASES,
        crate::limits::MAX_WALL_PROBES,
        crate::limits::MAX_ITERATIONS,
        crate::limits::MAX_FILE_BYTES,
        crate::limits::MAX_NAME_BYTES,
    ));
    s
}

#[cfg(test)]
mod tests;
