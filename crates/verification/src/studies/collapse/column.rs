//! The initial column of a collapse case (half-width L0, height H0 against the west wall),
//! its aspect ratio and its time and velocity scales.

use crate::references::LAJEUNESSE;
use anyhow::{bail, Context, Result};
use runout_case::{Case, GasSidewall, Gravity, Sidewalls, SolidsWall};
use runout_closures::friction::{FrictionModel, FrictionName};
use runout_mesh::Segment;

/// Cell width of a built column as written, in L0 (L0/20; coarse L0/10, smoke L0/5).
const CELLS_PER_L0: f64 = 20.0;
/// Cell counts of a built column are multiples of this (the smoke preset coarsens by 4).
const CELL_MULTIPLE: usize = 4;
/// A built domain reaches L0 (2 + this × λ(a)), λ(a) Lajeunesse's runout law.
const DOMAIN_RUNOUTS: f64 = 2.5;
/// The end time of a built column in √(H0/g): the check's deadline for a deposit at rest.
pub const REST_DEADLINE: f64 = 10.0;

/// The column of aspect ratio `a` built from `template` (a collapse case): the block's
/// height H0 = a L0, the domain (x to L0 (2 + 2.5 λ(a)), y to 1.1 H0 + L0/2, uniform cells of
/// L0/20 rounded up to a multiple of 4 cells) and the end time 10 √(H0/g) at every
/// fidelity change; the name becomes `<prefix>-a<a>`. Nothing else changes.
pub fn column_case(template: &Case, a: f64) -> Result<Case> {
    if !(a.is_finite() && (0.1..=20.0).contains(&a)) {
        bail!("--aspect {a}: allowed [0.1, 20]");
    }
    let column = Column::of(template)?;
    let (l0, h0) = (column.l0, a * column.l0);
    let mut case = template.clone();
    let prefix = template.name.split("-a").next().unwrap_or(&template.name);
    case.name = format!("{prefix}-a{a}");
    case.initial.regions[0].y.1 = case.initial.regions[0].y.0 + h0;
    let cells = |length: f64| {
        let n = (length / l0 * CELLS_PER_L0).ceil() as usize;
        n.div_ceil(CELL_MULTIPLE) * CELL_MULTIPLE
    };
    let (_, laj_hi) = LAJEUNESSE.runout(a);
    let x_cells = cells(l0 * (2.0 + DOMAIN_RUNOUTS * laj_hi));
    let y_cells = cells(1.1 * h0 + 0.5 * l0);
    let width = l0 / CELLS_PER_L0;
    case.domain.x.segments = vec![Segment::Uniform {
        length: x_cells as f64 * width,
        cells: x_cells,
    }];
    case.domain.y.segments = vec![Segment::Uniform {
        length: y_cells as f64 * width,
        cells: y_cells,
    }];
    let end = REST_DEADLINE * (h0 / column.gravity).sqrt();
    let end = (end * 1e3).ceil() / 1e3;
    case.run.end_time = end;
    case.fidelity.smoke.end_time = end;
    case.fidelity.coarse.end_time = end;
    if let Some(wall) = case.fidelity.wall.as_mut() {
        wall.end_time = end;
    }
    Ok(case)
}

/// The same column with Princeton friction instead of the template's (named `<prefix>P-a<a>`,
/// e.g. CMP-a1 beside CM-a1): the like-for-like closure beside μ(I). Princeton uses the
/// case's δ_int (35° in CM-a1.ron, above the beads' μ_s = tan 20.9°: a Coulomb stress
/// stronger than μ(I)'s at rest, so a Princeton column that still runs further does so by
/// its θ-dependent strain scale, not by weaker friction).
pub fn with_princeton(case: &Case) -> Case {
    let mut twin = case.clone();
    twin.models.friction = FrictionModel::from(FrictionName::Princeton);
    twin.name = match case.name.split_once("-a") {
        Some((prefix, a)) => format!("{prefix}P-a{a}"),
        None => format!("{}P", case.name),
    };
    twin.description = format!("{} (Princeton friction)", case.description);
    twin
}

/// The side walls of a laboratory channel around a built column (`--sidewalls W_L0,MU_W`):
/// width W = `width_in_l0` L0, a Coulomb grain–wall friction μ_w (docs/model.md §3.11, §8),
/// the gas sticking to the walls.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ChannelWalls {
    /// W/L0 [-], > 0
    pub width_in_l0: f64,
    /// μ_w [-]
    pub friction: f64,
}

impl ChannelWalls {
    /// From `--sidewalls W_L0,MU_W`: two numbers, W/L0 in (0, 1000] and μ_w in [0, 10].
    pub fn parse(values: &[f64]) -> Result<Self> {
        let &[width_in_l0, friction] = values else {
            bail!("--sidewalls takes two numbers, W/L0 and μ_w: got {values:?}");
        };
        if !(width_in_l0 > 0.0 && width_in_l0 <= 1e3) {
            bail!("--sidewalls W/L0 = {width_in_l0}: allowed (0, 1000]");
        }
        if !(0.0..=10.0).contains(&friction) {
            bail!("--sidewalls μ_w = {friction}: allowed [0, 10]");
        }
        Ok(Self {
            width_in_l0,
            friction,
        })
    }

    /// A label for names and folders, e.g. `W5L0-mu0.38`.
    pub fn label(&self) -> String {
        format!("W{}L0-mu{}", self.width_in_l0, self.friction)
    }

    /// `case` between these walls (W from the case's own L0), its name suffixed with
    /// [`ChannelWalls::label`].
    pub fn apply(&self, case: &Case) -> Result<Case> {
        let column = Column::of(case)?;
        let mut walled = case.clone();
        walled.sidewalls = Some(Sidewalls {
            width: self.width_in_l0 * column.l0,
            solids: SolidsWall::Coulomb {
                friction: self.friction,
                slip_floor: None,
            },
            gas: GasSidewall::NoSlip,
        });
        walled.name = format!("{}-{}", case.name, self.label());
        walled.description = format!(
            "{} between Coulomb side walls W = {} L0, μ_w = {}",
            case.description, self.width_in_l0, self.friction
        );
        Ok(walled)
    }
}

/// Whether `case` uses the μ(I) friction law (the closure the check's thresholds judge).
pub fn is_mu_i(case: &Case) -> bool {
    matches!(case.models.friction, FrictionModel::MuI(_))
}

/// The initial column of a collapse case: the first block, standing on the floor against
/// the west wall.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Column {
    /// half-width L0 [m] (the block's x extent, from the west wall)
    pub l0: f64,
    /// height H0 [m]
    pub h0: f64,
    /// x of the west wall [m]
    pub x_wall: f64,
    /// |g| [m s⁻²]
    pub gravity: f64,
}

impl Column {
    /// The column of `case`, or why the case is not a column collapse.
    pub fn of(case: &Case) -> Result<Self> {
        let block = case
            .initial
            .regions
            .first()
            .with_context(|| format!("case `{}` has no initial block", case.name))?;
        let grid = case.grid()?;
        let x_wall = grid.x.start();
        if (block.x.0 - x_wall).abs() > 1e-12 || (block.y.0 - grid.y.start()).abs() > 1e-12 {
            bail!(
                "case `{}`: the column must stand on the floor against the west wall",
                case.name
            );
        }
        let gravity = match case.gravity {
            Gravity::Constant {
                magnitude,
                slope: 0.0,
            } => magnitude,
            _ => bail!(
                "case `{}`: a collapse needs constant gravity straight down",
                case.name
            ),
        };
        Ok(Column {
            l0: block.x.1 - block.x.0,
            h0: block.y.1 - block.y.0,
            x_wall,
            gravity,
        })
    }

    /// The aspect ratio a = H0/L0, rounded to 1e-9 (0.15/0.05 is 2.9999999999999996 in
    /// floating point, which would put a = 3 on the wrong side of a crossover).
    pub fn aspect(&self) -> f64 {
        (self.h0 / self.l0 * 1e9).round() / 1e9
    }

    /// The free-fall time √(H0/g) [s].
    pub fn time_scale(&self) -> f64 {
        (self.h0 / self.gravity).sqrt()
    }

    /// The velocity scale √(g H0) [m s⁻¹].
    pub fn velocity_scale(&self) -> f64 {
        (self.gravity * self.h0).sqrt()
    }

    /// (L∞ − L0)/L0 of a front at `x`.
    pub fn runout(&self, x: f64) -> f64 {
        (x - self.x_wall - self.l0) / self.l0
    }
}
