//! The `coulomb-floor` check (issue 61): the Coulomb wall's friction is μ_w times the
//! solids' normal load on it ([`crate::problems::coulomb_floor`]):
//! - a μ(I) block released sliding at 1 m/s down a 20° Coulomb floor accelerates at
//!   g (sin θ − μ_w cos θ): the μ_w its acceleration implies within 2 % of μ_w, in a thin
//!   pore gas (in air the pore gas carries part of the weight; printed, not judged);
//! - a packed layer released at rest on a Coulomb floor with μ_f = 0.5 above tan θ stays at
//!   rest (its mean speed below 2e-3 m/s; the regularisation creeps at 1.1e-4 m/s), and with
//!   μ_f = 0.3 below tan θ it slides (above 0.03 m/s in 0.1 s) — a layer uniform along the
//!   slope, since a block's free faces slump whatever the floor;
//! - a packed layer sliding on a Coulomb floor between Coulomb side walls accelerates at
//!   g sin θ − μ_f g cos θ − (2 μ_sw/W) g cos θ y_c: the friction it feels within 2 % of that.
//!
//! - a block released at rest on a 30° slope that turns onto a flat floor, μ_w = 0.3, comes
//!   to rest on the flat (its mean speed over the last 0.5 s below `runout post`'s rest
//!   speed) with its centre's drop over its horizontal travel at least μ_w.
//!
//! - the block's momentum against its forces (gravity, the friction μ_w N_w the floor read,
//!   the drag, the buoyancy): equal within 0.5 % of μ_w in the conservative form of the
//!   momentum equations (docs/model.md §4.3), which the block is run in; MFIX's
//!   continuity-subtracted form is printed beside it.
//!
//! - fast: the block at μ_w = 0.2 on 60 × 8 and 120 × 16 cells, its budget at μ_w = 0.1 on
//!   120 × 16, the layer on 25 cells, the energy line on 60 × 8;
//! - full: the block at μ_w = 0.1, 0.2, 0.3 and 0.5 (above tan θ: it slows) on 60 × 8,
//!   120 × 16 and 240 × 32 cells, its budget at μ_w = 0.1 on 120 × 16 and 240 × 32 in both
//!   forms, the layer on 12, 25 and 50 cells, the energy line on 60 × 8
//!   and 120 × 16, and the block in air at μ_w = 0.2 on 120 × 16 (printed).

use crate::check::{Check, Limit, Outcome, Size};
use crate::problems::coulomb_floor::{
    block_momentum_budget, layer_at_rest, run_block, run_energy_line, run_layer, PoreGas,
    ENERGY_LINE_BED, JUDGED_FORM, LATE_WINDOW, LAYER_WALLS, REST_SPEEDS, SLOPE_DEG,
};
use runout_case::MomentumForm;

/// The largest relative error of the implied friction [-] (issue 61).
pub const FRICTION_TOLERANCE: f64 = 0.02;

/// The largest gap between the μ_w the block's momentum implies and the μ_w its forces
/// imply, relative to μ_w [-]: the discretisation's momentum conservation (docs/model.md
/// §4.3).
pub const BUDGET_TOLERANCE: f64 = 0.005;

/// The block and the layer against the sliding-block law.
pub struct CoulombFloor;

impl Check for CoulombFloor {
    fn name(&self) -> &'static str {
        "coulomb-floor"
    }

    fn description(&self) -> &'static str {
        "a block on a Coulomb floor and a layer between Coulomb side walls: a = g (sin θ − μ_w cos θ)"
    }

    fn run(&self, size: Size) -> anyhow::Result<Outcome> {
        let mut outcome = Outcome::new(self.name(), size);
        type Sizes = (&'static [(usize, usize)], &'static [f64], &'static [usize]);
        let ((grids, frictions, layers), energy_grids): (Sizes, &[(usize, usize)]) = match size {
            Size::Fast => ((&[(60, 8), (120, 16)], &[0.2], &[25]), &[(60, 8)]),
            Size::Full => (
                (
                    &[(60, 8), (120, 16), (240, 32)],
                    &[0.1, 0.2, 0.3, 0.5],
                    &[12, 25, 50],
                ),
                &[(60, 8), (120, 16)],
            ),
        };
        println!("block in a thin pore gas on a {SLOPE_DEG}° Coulomb floor, released at 1 m/s:");
        for &mu_w in frictions {
            for &(nx, ny) in grids {
                let r = run_block(nx, ny, mu_w, PoreGas::Thin, JUDGED_FORM)?;
                println!(
                    "  μ_w {mu_w:.2}, {nx:>3} × {ny:<2}: a = {:.4} m/s² (law {:.4}), implied μ_w {:.4} \
                     ({:+.2} %), {:.1} s wall",
                    r.acceleration,
                    r.expected,
                    r.effective_mu_w,
                    100.0 * (r.effective_mu_w / mu_w - 1.0),
                    r.wall_time
                );
                outcome.measure(
                    format!("block μ_w {mu_w} on {nx} × {ny}: |implied μ_w/μ_w − 1|"),
                    (r.effective_mu_w / mu_w - 1.0).abs(),
                    Limit::AtMost(FRICTION_TOLERANCE),
                );
            }
        }
        block_budgets(size, &mut outcome)?;
        let (at_rest, sliding) = REST_SPEEDS;
        for (mu_f, limit) in [
            (0.5, Limit::AtMost(at_rest)),
            (0.3, Limit::AtLeast(sliding)),
        ] {
            let speed = layer_at_rest(layers[0], mu_f)?;
            println!(
                "  a packed layer released at rest on a Coulomb floor μ_f {mu_f} (tan {SLOPE_DEG}° = {:.3}), {} cells: largest mean speed {speed:.2e} m/s",
                SLOPE_DEG.to_radians().tan(),
                layers[0]
            );
            outcome.measure(
                format!("layer released at rest, μ_f {mu_f}: largest mean speed [m/s]"),
                speed,
                limit,
            );
        }
        if size == Size::Full {
            let (mu_w, nx, ny) = (0.2, 120, 16);
            let r = run_block(nx, ny, mu_w, PoreGas::Air, JUDGED_FORM)?;
            println!(
                "the same block in air, μ_w {mu_w:.2}, {nx} × {ny}: a = {:.4} m/s², implied μ_w {:.4} \
                 ({:+.2} %): the pore gas's share of the weight (not judged)",
                r.acceleration,
                r.effective_mu_w,
                100.0 * (r.effective_mu_w / mu_w - 1.0),
            );
        }
        let (mu_f, mu_sw, width) = LAYER_WALLS;
        println!("layer on a Coulomb floor μ_f {mu_f} between Coulomb side walls μ_sw {mu_sw}, W = {width} m:");
        for &cells in layers {
            let r = run_layer(cells)?;
            println!(
                "  {cells:>3} cells: a = {:.4} m/s² (law {:.4}), friction measured/law {:.4}",
                r.acceleration, r.expected, r.friction_ratio
            );
            outcome.measure(
                format!("layer on {cells} cells: |friction/law − 1|"),
                (r.friction_ratio - 1.0).abs(),
                Limit::AtMost(FRICTION_TOLERANCE),
            );
        }
        let (slope, _, _, end) = ENERGY_LINE_BED;
        let mu_w = 0.3;
        println!("block released on a {slope}° slope onto a flat Coulomb floor, μ_w {mu_w}:");
        for &(nx, ny) in energy_grids {
            let r = run_energy_line(nx, ny, mu_w)?;
            println!(
                "  {nx:>3} × {ny:<2}: centre's drop/travel {:.4}, Heim's ratio {:.4}, grain edge \
                 {:.3} m past the foot, mean speed over the last {LATE_WINDOW} s at most {:.1e} m/s \
                 (rest speed {:.1e}), at rest from {} by `runout post`",
                r.centre_ratio,
                r.heim_ratio,
                r.past_foot,
                r.late_speed,
                r.rest_speed,
                r.rest_time
                    .map_or(String::from("never"), |t| format!("{t:.3} s"))
            );
            outcome.measure(
                format!("energy line on {nx} × {ny}: centre's drop/travel"),
                r.centre_ratio,
                Limit::AtLeast(mu_w),
            );
            outcome.measure(
                format!(
                    "energy line on {nx} × {ny}: largest |mean u_s| over the last {LATE_WINDOW} \
                     s before {end} s [m/s]"
                ),
                r.late_speed,
                Limit::AtMost(r.rest_speed),
            );
        }
        Ok(outcome)
    }
}

/// The block's momentum against its forces in the judged form (and, in the full size,
/// MFIX's form printed beside it), μ_w = 0.1 (module doc).
fn block_budgets(size: Size, outcome: &mut Outcome) -> anyhow::Result<()> {
    let mu_w = 0.1;
    println!("the block's momentum against its forces, μ_w {mu_w}:");
    let budget_grids: &[(usize, usize)] = match size {
        Size::Fast => &[(120, 16)],
        Size::Full => &[(120, 16), (240, 32)],
    };
    for &cells in budget_grids {
        let forms: &[MomentumForm] = match size {
            Size::Fast => &[JUDGED_FORM],
            Size::Full => &[JUDGED_FORM, MomentumForm::ContinuitySubtracted],
        };
        for &form in forms {
            let b = block_momentum_budget(cells, mu_w, form)?;
            let gap = (b.effective_mu_w.0 - b.effective_mu_w.1).abs() / mu_w;
            println!(
                "  {:>3} × {:<2}, {form:?}: the momentum implies μ_w {:.4}, the forces {:.4} \
                 (gap {:.2} % of μ_w)",
                cells.0,
                cells.1,
                b.effective_mu_w.0,
                b.effective_mu_w.1,
                100.0 * gap
            );
            if form == JUDGED_FORM {
                outcome.measure(
                    format!(
                        "block μ_w {mu_w} on {} × {}: |momentum's μ_w − forces' μ_w|/μ_w",
                        cells.0, cells.1
                    ),
                    gap,
                    Limit::AtMost(BUDGET_TOLERANCE),
                );
            }
        }
    }
    Ok(())
}
