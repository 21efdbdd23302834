//! The grid error of where a flow stops (issue 57 item 3): one case run on three or more
//! grids refined by a constant ratio, and for its deposit's runout (the grain edge's L∞),
//! maximum thickness H∞ and centre along the floor, the observed order, the Richardson value
//! and Roache's GCI of the finest grid from the three finest levels ([`crate::gci`]).
//! `runout grid-error CASE` runs the levels and prints this.

use runout_case::Convection;
use serde::Serialize;

use crate::deposit::Deposit;
use crate::gci::{scalar_convergence, ScalarConvergence, Trend};

/// One level of the ladder: its cell size relative to the finest grid's and its deposit.
#[derive(Clone, Debug)]
pub struct Level {
    /// h / h_finest: the coarsening factor of the level
    pub spacing: f64,
    /// the deposit its run left
    pub deposit: Deposit,
}

/// One deposit quantity over the ladder and its convergence.
#[derive(Clone, Debug, Serialize)]
pub struct QuantityError {
    /// what it is
    pub name: &'static str,
    /// its unit
    pub unit: &'static str,
    /// its value on each level, finest first
    pub values: Vec<f64>,
    /// the three finest levels' GCI study
    #[serde(skip)]
    pub convergence: ScalarConvergence,
}

impl QuantityError {
    /// One line of text: the values, the trend, the order, the Richardson value and the GCI.
    pub fn line(&self) -> String {
        let c = &self.convergence;
        let values: Vec<String> = self.values.iter().map(|v| format!("{v:.4}")).collect();
        let trend = match c.trend {
            Trend::Monotone => "monotone",
            Trend::Oscillatory => "oscillatory",
            Trend::Diverging => "not converging",
        };
        let order = match (c.observed_order, c.asymptotic) {
            (Some(p), true) => format!("observed order {p:.2}"),
            (Some(p), false) => format!(
                "observed order {p:.2} (outside the asymptotic range: nominal {:.0} used)",
                c.gci_order
            ),
            (None, _) => format!("no observed order (nominal {:.0} used)", c.gci_order),
        };
        format!(
            "{} [{}]: {} (finest first); {trend}, {order}; Richardson {:.4}; GCI of the finest {:.4} {} ({:.1} %, Fs {})",
            self.name,
            self.unit,
            values.join(", "),
            c.extrapolated,
            c.gci_fine_absolute,
            self.unit,
            100.0 * c.gci_fine,
            c.safety_factor
        )
    }
}

/// A deposit quantity: its name, its unit and how a deposit gives it.
type Quantity = (&'static str, &'static str, fn(&Deposit) -> f64);

/// The deposit's runout, maximum thickness and centre over `levels` (finest first, at least
/// three, the three finest judged) run with `scheme`.
pub fn deposit_errors(levels: &[Level], scheme: &Convection) -> Result<Vec<QuantityError>, String> {
    if levels.len() < 3 {
        return Err(format!(
            "{} levels: a grid error needs three or more",
            levels.len()
        ));
    }
    let h = [levels[0].spacing, levels[1].spacing, levels[2].spacing];
    if !(h[0] < h[1] && h[1] < h[2]) {
        return Err(format!(
            "spacings {h:?}: the levels must coarsen, finest first"
        ));
    }
    let quantities: [Quantity; 3] = [
        ("runout L∞ (grain edge)", "m", |d| d.runout_grain),
        ("maximum thickness H∞", "m", |d| d.max_thickness),
        ("deposit centre x", "m", |d| d.centre_x),
    ];
    Ok(quantities
        .into_iter()
        .map(|(name, unit, of)| {
            let values: Vec<f64> = levels.iter().map(|l| of(&l.deposit)).collect();
            QuantityError {
                name,
                unit,
                convergence: scalar_convergence([values[0], values[1], values[2]], h, scheme),
                values,
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn deposit(runout: f64, thickness: f64, centre: f64) -> Deposit {
        Deposit {
            time: 1.0,
            rest_speed: 0.01,
            at_rest: true,
            rest_time: Some(0.9),
            final_mean_u_s: 0.0,
            release_edge_x: 0.0,
            distal_edge_dilute: runout,
            distal_edge_dense: runout,
            runout_dilute: runout,
            distal_edge_grain: runout,
            runout_grain: runout,
            runout_dense: runout,
            max_thickness: thickness,
            max_thickness_x: 0.0,
            max_thickness_cells: 5,
            centre_x: centre,
            thin: None,
            on_the_run_out: None,
        }
    }

    /// A ladder built from q(h) = q* + c h² (second order, ratio 2) gives back q*, the order
    /// 2 and Fs 1.25 for every quantity; two levels are refused.
    #[test]
    fn a_second_order_ladder_gives_back_its_limit() {
        let q = |limit: f64, c: f64, h: f64| limit + c * h * h;
        let levels: Vec<Level> = [1.0, 2.0, 4.0]
            .iter()
            .map(|&h| Level {
                spacing: h,
                deposit: deposit(q(0.5, 0.01, h), q(0.02, -0.001, h), q(0.3, 0.002, h)),
            })
            .collect();
        let errors = deposit_errors(&levels, &Convection::Superbee).unwrap();
        for (e, limit) in errors.iter().zip([0.5, 0.02, 0.3]) {
            let c = &e.convergence;
            assert!((c.observed_order.unwrap() - 2.0).abs() < 1e-9, "{}", e.name);
            assert!((c.extrapolated - limit).abs() < 1e-12, "{}", e.name);
            assert_eq!(c.safety_factor, 1.25);
            assert!(e.line().contains("observed order 2.00"));
        }
        assert!(deposit_errors(&levels[..2], &Convection::Superbee).is_err());
    }
}
