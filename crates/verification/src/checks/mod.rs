//! The checks of the registry ([`crate::registry`]), one per file, each a problem of
//! [`crate::problems`] judged against its reference at a fast and a full size.

mod bed_path;
mod cavity;
mod chute;
mod cooling;
mod coulomb_floor;
mod defluidisation;
mod fluidized_bed;
mod gas_inlet;
mod haff;
mod ideal_gas;
mod incline;
mod poiseuille;
mod relaxation;
mod release;
mod s_jj_phi;
mod settling;
mod taylor_green;

pub use bed_path::BedPath;
pub use cavity::{Cavity, CAVITY_CELLS, CAVITY_FAST_TARGET, CAVITY_TARGET};
pub use chute::{relative_change, Chute, ChuteRun, CHUTE_TOLERANCE, FULL_RUNS};
pub use cooling::Cooling;
pub use coulomb_floor::{CoulombFloor, FRICTION_TOLERANCE};
pub use defluidisation::Defluidisation;
pub use fluidized_bed::FluidizedBed;
pub use gas_inlet::GasInlet;
pub use haff::Haff;
pub use ideal_gas::IdealGas;
pub use incline::{Incline, FULL_CELLS as INCLINE_CELLS, INCLINE_TOLERANCE};
pub use poiseuille::{Poiseuille, POISEUILLE_MIN_ORDER};
pub use relaxation::Relaxation;
pub use release::Release;
pub use s_jj_phi::SJjPhi;
pub use settling::Settling;
pub use taylor_green::TaylorGreen;

use crate::problems::OrderStudy;

/// "PASS" or "FAIL".
pub fn verdict(ok: bool) -> &'static str {
    if ok {
        "PASS"
    } else {
        "FAIL"
    }
}

/// Prints a convergence study level by level: cells, steps, error, order, outer
/// iterations, wall time and mass ratio.
pub fn print_study(study: &OrderStudy) {
    println!("  {}", study.label);
    for (k, level) in study.levels.iter().enumerate() {
        let error = study
            .errors
            .get(k)
            .map_or(String::from("-"), |e| format!("{e:.3e}"));
        let order = if k == 0 {
            String::from("-")
        } else {
            study
                .orders
                .get(k - 1)
                .map_or(String::from("-"), |p| format!("{p:.3}"))
        };
        println!(
            "    cells {:>4} steps {:>3}: error {error:>10}  order {order:>6}  {:>6} outer its  {:>8.3} s  mass {:.1e}",
            level.cells, level.steps, level.outer_iterations, level.wall_time, level.mass_ratio
        );
    }
}
