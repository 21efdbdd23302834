//! The plausibility bands of every dimensional input and the limits on sizes and counts
//! (issue 21): what `runout check` accepts beyond finiteness and sign.
//!
//! The bands are generous: each admits every shipped case and every material or flow the
//! solver's physics can describe, and refuses only what is a typo or a unit error (a
//! 1.8e19 m domain, a gas viscosity of 1e-300 Pa s). The limits keep `check` and `run` from
//! allocating without bound or spinning. docs/reference/input-validation.md has the same table with
//! the same reasons; a test keeps the two in step ([`bands_table`]).

use runout_mesh::short;

/// A closed band [lo, hi] of plausible values of one kind of input, with its unit and
/// the reason for its ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Band {
    /// what the band is for, as in docs/reference/input-validation.md
    pub what: &'static str,
    /// smallest plausible value
    pub lo: f64,
    /// largest plausible value
    pub hi: f64,
    /// SI unit, `-` for a number
    pub unit: &'static str,
    /// why the ends are where they are
    pub reason: &'static str,
}

impl Band {
    /// Whether `v` lies in [lo, hi] (false for NaN).
    pub fn contains(&self, v: f64) -> bool {
        v >= self.lo && v <= self.hi
    }

    /// `[lo, hi] unit`, numbers in short form.
    pub fn describe(&self) -> String {
        let unit = if self.unit == "-" {
            String::new()
        } else {
            format!(" {}", self.unit)
        };
        format!("[{}, {}]{unit}", short(self.lo), short(self.hi))
    }
}

/// Particle diameter `solids[m].diameter` and a sweep's `Diameter`.
pub const DIAMETER: Band = Band {
    what: "particle diameter",
    lo: 1e-6,
    hi: 1.0,
    unit: "m",
    reason: "fine powders (1 µm) to boulders (1 m); a continuum of particles needs many per cell",
};

/// Material density `solids[m].density`.
pub const PARTICLE_DENSITY: Band = Band {
    what: "particle material density",
    lo: 100.0,
    hi: 25_000.0,
    unit: "kg/m³",
    reason: "expanded polymer beads (~100) to the densest metals (osmium 22 600)",
};

/// Gas density `gas.density`.
pub const GAS_DENSITY: Band = Band {
    what: "gas density",
    lo: 1e-3,
    hi: 100.0,
    unit: "kg/m³",
    reason: "air at ~1 mbar to gas at ~100 bar (air at 1 bar: 1.2)",
};

/// An ideal gas's molar mass `gas.law.IdealGas.molar_mass`.
pub const GAS_MOLAR_MASS: Band = Band {
    what: "gas molar mass",
    lo: 1e-3,
    hi: 1.0,
    unit: "kg/mol",
    reason: "hydrogen 0.002 to the heaviest gases (UF6 0.35); air 0.028965",
};

/// An ideal gas's temperature `gas.law.IdealGas.temperature`.
pub const GAS_TEMPERATURE: Band = Band {
    what: "gas temperature",
    lo: 10.0,
    hi: 5000.0,
    unit: "K",
    reason: "cryogenic gas to a pyroclastic current's hottest gas (~1300 K), with margin",
};

/// Gas dynamic viscosity `gas.viscosity`.
pub const GAS_VISCOSITY: Band = Band {
    what: "gas dynamic viscosity",
    lo: 1e-7,
    hi: 1.0,
    unit: "Pa s",
    reason: "every gas lies in 1e-6..1e-4 (air 1.8e-5); up to 1 admits viscous carriers",
};

/// Pressures: `gas.reference_pressure`, outlet pressures, `initial.gas_pressure`.
pub const PRESSURE: Band = Band {
    what: "pressure",
    lo: 1.0,
    hi: 1e9,
    unit: "Pa",
    reason: "a near vacuum (1 Pa) to 10 kbar; the gas is incompressible at the reference value",
};

/// Length of a domain axis (the sum of its segments) and an analytic `depth`.
pub const DOMAIN_LENGTH: Band = Band {
    what: "domain length of an axis, analytic depth",
    lo: 1e-4,
    hi: 1e5,
    unit: "m",
    reason: "a 0.1 mm cell to a 100 km runout",
};

/// An axis `origin`: coordinates are |x| ≤ 1e5 m.
pub const COORDINATE: Band = Band {
    what: "axis origin",
    lo: -1e5,
    hi: 1e5,
    unit: "m",
    reason:
        "with widths ≥ 1e-7 m a face coordinate keeps ≥ 4 digits of a width in double precision",
};

/// Width of the smallest cell of any fidelity's grid (`hi` is not used: a cell is never
/// wider than its axis).
pub const CELL_WIDTH: Band = Band {
    what: "smallest cell width (any fidelity)",
    lo: 1e-7,
    hi: 1e5,
    unit: "m",
    reason: "a tenth of the smallest diameter; a 1e-300 m layer next to 0.05 m cells is a typo",
};

/// Largest ratio of adjacent cell widths of the grid as written (the presets' grids are
/// coarsened from it by the code, not written, and reach 4.9 on the shipped cases).
pub const ADJACENT_WIDTH_RATIO: Band = Band {
    what: "largest adjacent cell-width ratio (grid as written)",
    lo: 1.0,
    hi: 50.0,
    unit: "-",
    reason: "shipped grids reach 1.13, grids coarsened from them 14..37 (xtask error-time's \
             tiny level); 50 is a 1 mm layer next to 5 cm cells",
};

/// |g| `gravity.magnitude` when not 0 (0 is allowed: no gravity, as in the cavity).
pub const GRAVITY: Band = Band {
    what: "gravity magnitude (or exactly 0)",
    lo: 0.01,
    hi: 1000.0,
    unit: "m/s²",
    reason: "small asteroids (~0.01) to a centrifuge at 100 g; 0 turns gravity off",
};

/// Granular temperatures: `initial.theta`, block `theta`, wall `theta_w`, analytic θ.
pub const THETA: Band = Band {
    what: "granular temperature θ",
    lo: 0.0,
    hi: 1e4,
    unit: "m²/s²",
    reason: "θ is a velocity variance: 1e4 is fluctuations of 100 m/s",
};

/// Velocities: initial gas and block velocities, wall velocities `u_w`, analytic ones.
pub const VELOCITY: Band = Band {
    what: "velocity component, wall velocity u_w",
    lo: -1000.0,
    hi: 1000.0,
    unit: "m/s",
    reason: "three times the speed of sound in air; the gas is incompressible",
};

/// Simulated times: `run.end_time`, preset end times; also the upper end of intervals.
pub const TIME: Band = Band {
    what: "end time",
    lo: 1e-6,
    hi: 1e7,
    unit: "s",
    reason: "1 µs to 116 days of simulated time",
};

/// Time steps `run.dt.initial`, `min`, `max` (`min` is also ≥ end time × 1e-9, see
/// [`DT_MIN_PER_END_TIME`]).
pub const TIME_STEP: Band = Band {
    what: "time step Δt (initial, min, max)",
    lo: 1e-10,
    hi: 1e4,
    unit: "s",
    reason: "the shipped cases use 1e-7..0.5 s; below 1e-10 s no granular time scale exists",
};

/// Partial-slip coefficients h_u, h_θ [m⁻¹] of walls and analytic profiles.
pub const SLIP_COEFFICIENT: Band = Band {
    what: "partial-slip coefficient h_u, h_θ",
    lo: 0.0,
    hi: 1e9,
    unit: "1/m",
    reason: "1/h is a slip length: 1 nm (h = 1e9) is no-slip to round-off",
};

/// Granular-energy wall flux c_w [m s⁻²] of walls and analytic profiles.
pub const THETA_FLUX: Band = Band {
    what: "granular-energy wall flux c_w",
    lo: -1e6,
    hi: 1e6,
    unit: "m/s²",
    reason: "the largest θ (1e4) changing over 1 cm; the shipped cases use 0.1..10",
};

/// `models.kinetic_theory.alpha`: the (2+α)/3 viscosity factor.
pub const KT_ALPHA: Band = Band {
    what: "kinetic-theory α of (2+α)/3",
    lo: 0.0,
    hi: 10.0,
    unit: "-",
    reason: "MFIX's value is 1.6; above 10 the factor is a typo",
};

/// Syamlal–O'Brien `c1`.
pub const DRAG_C1: Band = Band {
    what: "Syamlal–O'Brien drag c1",
    lo: 0.01,
    hi: 10.0,
    unit: "-",
    reason: "MFIX's 0.8; published calibrations to u_mf lie in 0.1..1",
};

/// Syamlal–O'Brien `d1`.
pub const DRAG_D1: Band = Band {
    what: "Syamlal–O'Brien drag d1",
    lo: 0.1,
    hi: 100.0,
    unit: "-",
    reason: "MFIX's 2.65; published calibrations lie in 1..30",
};

/// `solids[m].max_packing`.
pub const MAX_PACKING: Band = Band {
    what: "maximum packing εs,max",
    lo: 0.3,
    hi: 0.9,
    unit: "-",
    reason: "loose cohesive powders (~0.3) to wide mixtures (~0.85); spheres pack at 0.64",
};

/// Convergence tolerances `run.tolerances.residual` and `theta_residual`.
pub const TOLERANCE: Band = Band {
    what: "residual tolerance",
    lo: 1e-12,
    hi: 1.0,
    unit: "-",
    reason: "residuals are normalised: below 1e-12 is round-off, never reached",
};

/// Under-relaxation factors `numerics.relaxation.*`.
pub const RELAXATION: Band = Band {
    what: "under-relaxation factor",
    lo: 0.01,
    hi: 1.0,
    unit: "-",
    reason: "MFIX uses 0.5..0.8; below 0.01 the outer iteration cannot converge in its cap",
};

/// μ(I) friction coefficients `models.friction.MuI.mu_s` and `mu_2`.
pub const MU_I_FRICTION: Band = Band {
    what: "μ(I) friction coefficient μ_s or μ_2",
    lo: 0.01,
    hi: 2.0,
    unit: "-",
    reason: "tan 0.6° to tan 63°: measured grains lie in 0.2..1 (glass beads 0.38/0.64)",
};

/// μ(I) inertial-number scale `models.friction.MuI.i_0`.
pub const MU_I_I0: Band = Band {
    what: "μ(I) inertial-number scale I_0",
    lo: 1e-3,
    hi: 10.0,
    unit: "-",
    reason: "published fits lie in 0.1..0.5 (glass beads 0.279)",
};

/// μ(I) regularisation `models.friction.MuI.shear_rate_floor`.
pub const MU_I_SHEAR_RATE_FLOOR: Band = Band {
    what: "μ(I) strain-rate floor γ̇_min",
    lo: 1e-8,
    hi: 1.0,
    unit: "1/s",
    reason: "a deposit creeps at about γ̇_min h: above 1 s⁻¹ it is no deposit, below 1e-8 the viscosity overflows the solves",
};

/// Every band, in the order of docs/reference/input-validation.md.
pub const BANDS: [Band; 27] = [
    DIAMETER,
    PARTICLE_DENSITY,
    GAS_DENSITY,
    GAS_MOLAR_MASS,
    GAS_TEMPERATURE,
    GAS_VISCOSITY,
    PRESSURE,
    DOMAIN_LENGTH,
    COORDINATE,
    CELL_WIDTH,
    ADJACENT_WIDTH_RATIO,
    GRAVITY,
    THETA,
    VELOCITY,
    TIME,
    TIME_STEP,
    SLIP_COEFFICIENT,
    THETA_FLUX,
    KT_ALPHA,
    DRAG_C1,
    DRAG_D1,
    MAX_PACKING,
    TOLERANCE,
    RELAXATION,
    MU_I_FRICTION,
    MU_I_I0,
    MU_I_SHEAR_RATE_FLOOR,
];

/// Where validation applies each band, by the field paths of the case-file reference
/// ([`crate::reference`], docs/guide/case-reference.md). A band added to [`BANDS`] without
/// an entry here fails a test; so does an entry whose field validation does not check.
#[rustfmt::skip]
pub const BAND_FIELDS: &[(&str, Band)] = &[
    ("solids[].diameter", DIAMETER),
    ("solids[].density", PARTICLE_DENSITY),
    ("gas.density", GAS_DENSITY),
    ("gas.law.IdealGas.molar_mass", GAS_MOLAR_MASS),
    ("gas.law.IdealGas.temperature", GAS_TEMPERATURE),
    ("gas.viscosity", GAS_VISCOSITY),
    ("gas.reference_pressure", PRESSURE),
    ("initial.gas_pressure", PRESSURE),
    ("Boundary.PressureOutlet.pressure.Uniform", PRESSURE),
    ("Boundary.PressureOutlet.pressure.Hydrostatic", PRESSURE),
    ("AxisSpec.segments", DOMAIN_LENGTH),
    ("AxisSpec.origin", COORDINATE),
    ("AxisSpec.segments", CELL_WIDTH),
    ("AxisSpec.segments", ADJACENT_WIDTH_RATIO),
    ("gravity.Constant.magnitude", GRAVITY),
    ("gravity.TiltOnImpact.magnitude", GRAVITY),
    ("initial.theta", THETA),
    ("initial.regions[].solids[].theta", THETA),
    ("SolidsWall.PartialSlip.theta_w", THETA),
    ("initial.gas_velocity", VELOCITY),
    ("initial.regions[].solids[].velocity", VELOCITY),
    ("Boundary.Wall.gas.Moving.u_w", VELOCITY),
    ("Boundary.Wall.gas.PartialSlip.u_w", VELOCITY),
    ("SolidsWall.PartialSlip.u_w", VELOCITY),
    ("SolidsWall.JohnsonJackson.u_w", VELOCITY),
    ("SolidsWall.RevisitedJohnsonJackson.u_w", VELOCITY),
    ("SolidsWall.Jenkins.u_w", VELOCITY),
    ("run.stop_at_rest.speed", VELOCITY),
    ("run.end_time", TIME),
    ("Preset.end_time", TIME),
    ("run.dt.initial", TIME_STEP),
    ("run.dt.min", TIME_STEP),
    ("run.dt.max", TIME_STEP),
    ("Boundary.Wall.gas.PartialSlip.h_u", SLIP_COEFFICIENT),
    ("SolidsWall.PartialSlip.h_u", SLIP_COEFFICIENT),
    ("SolidsWall.PartialSlip.h_theta", SLIP_COEFFICIENT),
    ("SolidsWall.PartialSlip.c", THETA_FLUX),
    ("models.kinetic_theory.Lun1984.alpha", KT_ALPHA),
    ("models.drag.SyamlalOBrien.c1", DRAG_C1),
    ("models.drag.SyamlalOBrien.d1", DRAG_D1),
    ("solids[].max_packing", MAX_PACKING),
    ("run.tolerances.residual", TOLERANCE),
    ("run.tolerances.theta_residual", TOLERANCE),
    ("numerics.relaxation.pressure", RELAXATION),
    ("numerics.relaxation.eps_s", RELAXATION),
    ("numerics.relaxation.velocity", RELAXATION),
    ("numerics.relaxation.theta", RELAXATION),
    ("numerics.relaxation.wall_closures", RELAXATION),
    ("models.friction.MuI.mu_s", MU_I_FRICTION),
    ("models.friction.MuI.mu_2", MU_I_FRICTION),
    ("models.friction.MuI.i_0", MU_I_I0),
    ("models.friction.MuI.shear_rate_floor", MU_I_SHEAR_RATE_FLOOR),
];

/// Most cells of a case's grid at any fidelity: 10 million, 110 times the paper's finest
/// grid (1000 × 90) and ≈ 23 GiB for the two-fluid solver at the measured bytes per cell
/// ([`crate::estimated_memory_bytes`]). A 40 000 × 25 000 grid (1e9 cells, ~1.8 TiB) used
/// to pass `check` and be killed for memory a second into `run`.
pub const MAX_CELLS: usize = 10_000_000;

/// Most field outputs of a run: end time / `run.output_interval` ≤ 100 000. Each output
/// writes the whole grid; the bound also keeps `next += interval` advancing (an interval of
/// 1e-300 s never moved `next` past t, and `run` spun forever).
pub const MAX_OUTPUTS: f64 = 1e5;

/// Most samples of a monitor series: end time / interval ≤ 1 000 000 for the bulk, wall
/// probe and front intervals (one CSV row per sample), for the same reason as
/// [`MAX_OUTPUTS`].
pub const MAX_SAMPLES: f64 = 1e6;

/// Smallest output or monitor interval whatever the end time [s]: 1 ns, below any time
/// step the solver takes ([`TIME_STEP`]).
pub const MIN_INTERVAL: f64 = 1e-9;

/// `run.dt.min` ≥ end time × this: a step then still changes t in its 7th significant
/// digit (a double has 16), so t + Δt advances t, and a run at the smallest Δt has at
/// most 1e9 steps.
pub const DT_MIN_PER_END_TIME: f64 = 1e-9;

/// Most solids phases: MFIX's `DIM_M` (10); memory grows with each.
pub const MAX_SOLIDS_PHASES: usize = 10;

/// Most wall probes: each keeps a CSV file open for the whole run; 100 is far below the
/// usual limit of 1024 open files.
pub const MAX_WALL_PROBES: usize = 100;

/// Most outer iterations per step and converged steps per Δt change: 10 000 (MFIX's
/// `MAX_NIT` default is 500), so that one step ends in bounded time.
pub const MAX_ITERATIONS: u64 = 10_000;

/// Most cases one sweep expands to: 1000 (the largest shipped sweep has 6). The product of
/// its `vary` lists is computed before anything is expanded.
pub const MAX_SWEEP_CASES: usize = 1000;

/// Largest case, sweep or analytic file: 1 MiB (the largest shipped file is ~5 KB),
/// checked from its metadata before it is read, and by reading at most one byte more.
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// Longest case or sweep name: 100 bytes, the name of a folder under `runs/`.
pub const MAX_NAME_BYTES: usize = 100;

/// The bands as the markdown table of docs/reference/input-validation.md.
pub fn bands_table() -> String {
    let mut s = String::from("| input | band | reason |\n|---|---|---|\n");
    for b in BANDS {
        s.push_str(&format!(
            "| {} | {} | {} |\n",
            b.what,
            b.describe(),
            b.reason
        ));
    }
    s
}
