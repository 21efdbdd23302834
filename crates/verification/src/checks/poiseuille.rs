//! The `poiseuille` check (issue 6): plane Poiseuille flow between partial-slip walls (user
//! h_u, paper Eq. 12) against its closed form ([`crate::problems::poiseuille_order`]). The
//! fully developed profile is an exact solution of the discrete x-direction equations, so
//! the error is that of the wall-normal discretisation and the wall closure: the observed
//! order must be ≥ [`POISEUILLE_MIN_ORDER`] on a uniform and a stretched grid (growth 1.2;
//! refinement halves every cell), and every continuity imbalance ≤ [`MASS_TOLERANCE`].
//!
//! - fast: 8, 16, 32 cells (uniform) and 4, 8, 16 per half (stretched);
//! - full: 8 … 128 and 4 … 64.

use runout_solver::Scheme;

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::{poiseuille_order, ChannelGrid, MASS_TOLERANCE};

/// Smallest observed order of the Poiseuille velocity (issue 6).
pub const POISEUILLE_MIN_ORDER: f64 = 1.8;

/// Partial-slip Poiseuille flow against its closed form.
pub struct Poiseuille;

/// The grids and their levels at `size`.
fn studies(size: Size) -> [(ChannelGrid, Vec<usize>); 2] {
    let stretched = ChannelGrid::Stretched { growth: 1.2 };
    match size {
        Size::Fast => [
            (ChannelGrid::Uniform, vec![8, 16, 32]),
            (stretched, vec![4, 8, 16]),
        ],
        Size::Full => [
            (ChannelGrid::Uniform, vec![8, 16, 32, 64, 128]),
            (stretched, vec![4, 8, 16, 32, 64]),
        ],
    }
}

impl Check for Poiseuille {
    fn name(&self) -> &'static str {
        "poiseuille"
    }

    fn description(&self) -> &'static str {
        "partial-slip Poiseuille flow against its closed form: observed order"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        if size == Size::Full {
            println!("plane Poiseuille flow, partial-slip walls, against the closed form");
        }
        for (grid, levels) in studies(size) {
            let study = poiseuille_order(grid, &levels, Scheme::Superbee)?;
            match size {
                Size::Fast => println!(
                    "{}: errors {:?}, observed orders {:?}",
                    study.label, study.errors, study.orders
                ),
                Size::Full => {
                    super::print_study(&study);
                    let ok = study.min_order() >= POISEUILLE_MIN_ORDER
                        && study.worst_mass_ratio() <= MASS_TOLERANCE;
                    println!(
                        "    smallest order {:.3} (target >= {POISEUILLE_MIN_ORDER})  {}",
                        study.min_order(),
                        super::verdict(ok)
                    );
                }
            }
            outcome.measure(
                format!("{}: smallest order", study.label),
                study.min_order(),
                Limit::AtLeast(POISEUILLE_MIN_ORDER),
            );
            outcome.measure(
                format!("{}: worst mass ratio", study.label),
                study.worst_mass_ratio(),
                Limit::AtMost(MASS_TOLERANCE),
            );
        }
        Ok(outcome)
    }
}
