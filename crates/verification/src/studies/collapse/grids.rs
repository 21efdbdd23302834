//! The grid study of the μ(I) columns: each column's runout and H∞ at every fidelity whose
//! finished run the store holds (smoke L0/5, coarse L0/10, paper L0/20), with the observed
//! order and the Richardson extrapolation of the runout where three levels converge
//! monotonically (`runout_post::convergence`; Roache 1998 ch. 5).

use std::fmt::Write as _;
use std::path::Path;

use anyhow::Result;
use runout_case::{Case, Fidelity};
use runout_post::convergence::{observed_order, richardson};

use super::run::{finished, Outcome};
use crate::references::LAJEUNESSE;

/// The fidelities of the study, coarsest first.
const LEVELS: [Fidelity; 3] = [Fidelity::Smoke, Fidelity::Coarse, Fidelity::Paper];

/// One level of a column's grid study.
pub(super) struct Level {
    /// cells per L0 in x
    cells_per_l0: f64,
    /// grain-edge runout (L∞ − L0)/L0
    runout: f64,
    /// H∞/L0
    height: f64,
    /// at rest by the end of the run
    at_rest: bool,
}

/// One μ(I) column on the grids the store holds.
pub(super) struct GridStudy {
    name: String,
    aspect: f64,
    levels: Vec<Level>,
}

/// The grid studies of the μ(I) `cases`: `outcomes` (this check's runs at `fidelity`) and
/// the store's finished runs of the same cases at the other fidelities.
pub(super) fn gather(
    root: &Path,
    cases: &[Case],
    fidelity: Fidelity,
    outcomes: &[Outcome],
) -> Result<Vec<GridStudy>> {
    let mut studies = Vec::new();
    for (case, outcome) in cases.iter().zip(outcomes).filter(|(_, o)| o.mu_i) {
        let mut levels = Vec::new();
        for level in LEVELS {
            let measured = if level == fidelity {
                None
            } else {
                finished(root, case, level)?
            };
            let Some(o) = (if level == fidelity {
                Some(outcome)
            } else {
                measured.as_ref()
            }) else {
                continue;
            };
            let grid = case.at_fidelity(level).grid()?;
            let dx = (grid.x.end() - grid.x.start()) / grid.nx() as f64;
            levels.push(Level {
                cells_per_l0: o.column.l0 / dx,
                runout: o.grain_runout,
                height: o.height,
                at_rest: o.front.rest_time.is_some(),
            });
        }
        studies.push(GridStudy {
            name: case.name.clone(),
            aspect: outcome.column.aspect(),
            levels,
        });
    }
    Ok(studies)
}

/// The observed order and the Richardson value of the three finest levels' runouts, if
/// they converge monotonically.
fn convergence(levels: &[Level]) -> Option<(f64, f64)> {
    let n = levels.len();
    if n < 3 {
        return None;
    }
    let [l3, l2, l1] = [&levels[n - 3], &levels[n - 2], &levels[n - 1]];
    let (d32, d21) = (l2.runout - l3.runout, l1.runout - l2.runout);
    if d32 * d21 <= 0.0 {
        return None;
    }
    let h = [
        1.0 / l1.cells_per_l0,
        1.0 / l2.cells_per_l0,
        1.0 / l3.cells_per_l0,
    ];
    let p = observed_order(d32.abs(), d21.abs(), h)?;
    let extrapolated = richardson(&[l1.runout], &[l2.runout], [h[0], h[1]], p)[0];
    Some((p, extrapolated))
}

/// The grid studies as a Markdown section (empty if no column has two levels).
pub(super) fn markdown(studies: &[GridStudy]) -> String {
    let mut s = String::new();
    if studies.iter().all(|g| g.levels.len() < 2) {
        return s;
    }
    s.push_str(
        "**The μ(I) columns on each grid the store holds** (grain-edge runout, H∞/L0; `*`: \
         not at rest by 10 √(H0/g); observed order and Richardson value from the three finest \
         levels where they converge monotonically):\n\n\
         | case | L0/5 | L0/10 | L0/20 | observed order | Richardson | Lajeunesse |\n\
         |---|---|---|---|---|---|---|\n",
    );
    for g in studies.iter().filter(|g| g.levels.len() >= 2) {
        let cell = |per_l0: f64| {
            g.levels
                .iter()
                .find(|l| (l.cells_per_l0 - per_l0).abs() < 0.5)
                .map_or("—".to_string(), |l| {
                    format!(
                        "{:.2}{}, {:.2}",
                        l.runout,
                        if l.at_rest { "" } else { "*" },
                        l.height
                    )
                })
        };
        let (order, extrapolated) = match convergence(&g.levels) {
            Some((p, r)) => (format!("{p:.2}"), format!("{r:.2}")),
            None if g.levels.len() >= 3 => ("not monotone".to_string(), "—".to_string()),
            None => ("—".to_string(), "—".to_string()),
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {order} | {extrapolated} | {} |",
            g.name,
            cell(5.0),
            cell(10.0),
            cell(20.0),
            LAJEUNESSE.label(g.aspect)
        );
    }
    s.push('\n');
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn level(cells_per_l0: f64, runout: f64) -> Level {
        Level {
            cells_per_l0,
            runout,
            height: 1.0,
            at_rest: true,
        }
    }

    /// Runouts r = 2 + h² on L0/5, L0/10, L0/20 give order 2 and the limit 2; a
    /// non-monotone ladder gives none.
    #[test]
    fn order_and_richardson_of_a_second_order_ladder() {
        let r = |n: f64| 2.0 + (1.0 / n).powi(2);
        let levels = [
            level(5.0, r(5.0)),
            level(10.0, r(10.0)),
            level(20.0, r(20.0)),
        ];
        let (p, limit) = convergence(&levels).unwrap();
        assert!((p - 2.0).abs() < 1e-9, "{p}");
        assert!((limit - 2.0).abs() < 1e-12, "{limit}");
        let zigzag = [level(5.0, 3.0), level(10.0, 2.0), level(20.0, 2.5)];
        assert!(convergence(&zigzag).is_none());
    }
}
