//! The initial column of a collapse case (half-width L0, height H0 against the west wall),
//! its aspect ratio and its time and velocity scales.

use anyhow::{bail, Context, Result};
use runout_case::{Case, Gravity};

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
