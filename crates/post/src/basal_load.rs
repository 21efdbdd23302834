//! Who carries a flow's weight at its base: the gas's excess pressure, the solids pressure,
//! or neither (`runout post RUN_DIR --basal-load CSV`; docs/reference/deposit.md, "The
//! basal load"; issue 60).
//!
//! In a column of the flow, the load at the centre of its floor cell is the buoyant weight
//! of the mixture above that point,
//!
//!    W = Σ_j εs,j (ρs − ρg) g_n Δy_j, the floor cell counted to its centre (Δy_0/2),
//!
//! with g_n = g cos α the gravity normal to the floor (α the slope of a tilted gravity or
//! the bent floor's angle at the column). It is shared:
//!
//! - **gas**: the pore pressure in excess of the gas's own hydrostatic column,
//!   p_e = p_g,0 − p_g,top − ρg g_n (y_top − y_0), between the floor cell's centre and the
//!   column's top cell's; λ_g = p_e/W is the pore-pressure ratio of debris-flow studies
//!   (Iverson 1997, Rev. Geophys. 35: a λ near 1 is a flow carried by its fluid);
//! - **solids**: the solids pressure of the floor cell, λ_s = P_s,0/W;
//! - the rest, 1 − λ_g − λ_s, is carried by the normal and shear stresses across the
//!   column's sides and by the column's acceleration normal to the floor.
//!
//! ρg is the case's gas density (0, and p_e = 0, in a dry case): for an ideal gas, its density at the reference pressure,
//! which differs from the column's by p_e/P ≈ 1e-2 at most in these flows, an error of
//! that fraction of ρg g_n H, below 0.1 Pa. A column counts as part of the flow where its
//! solids height Σ εs Δy is at least one grain diameter (the deposit's grain edge,
//! [`crate::deposit::GRAIN_EDGE_DIAMETERS`]).

use std::path::Path;

use runout_case::{Case, Gravity};
use serde::Serialize;

use crate::deposit::GRAIN_EDGE_DIAMETERS;
use crate::fields::field_files;

/// One column's load and its shares (module doc).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct BasalColumn {
    /// the column's centre [m]
    pub x: f64,
    /// the column's width Δx [m]
    pub width: f64,
    /// W, the buoyant weight above the floor cell's centre [Pa]
    pub load: f64,
    /// λ_g = p_e/W [-]
    pub gas_share: f64,
    /// λ_s = P_s,0/W [-]
    pub solids_share: f64,
}

/// The whole flow's shares at one time: each column's share weighted by its load and width.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FlowLoad {
    /// the field file's time [s]
    pub time: f64,
    /// Σ W Δx, the flow's buoyant weight per unit width [N/m]
    pub load: f64,
    /// Σ p_e Δx / Σ W Δx [-]
    pub gas_share: f64,
    /// Σ P_s,0 Δx / Σ W Δx [-]
    pub solids_share: f64,
    /// the largest λ_g of a column carrying at least a tenth of the heaviest column's W [-]
    pub peak_gas_share: f64,
    /// that column's centre [m]
    pub peak_gas_share_x: f64,
}

/// The fields of one snapshot a column's load is read from (cells k = i + nx·j).
pub struct BaseFields<'a> {
    pub eps_s: &'a [f64],
    pub p_g: &'a [f64],
    pub p_s: &'a [f64],
}

/// The densities and grain size the load needs.
#[derive(Clone, Copy, Debug)]
pub struct Material {
    /// ρs [kg m⁻³]
    pub solids_density: f64,
    /// ρg [kg m⁻³]
    pub gas_density: f64,
    /// d [m]
    pub diameter: f64,
}

/// The columns of one snapshot that hold at least a grain's height of solids, with their
/// load and shares (module doc); `normal_gravity(x)` is g_n at a column's centre.
pub fn basal_columns(
    fields: &BaseFields<'_>,
    (xf, yf): (&[f64], &[f64]),
    material: Material,
    normal_gravity: impl Fn(f64) -> f64,
) -> Vec<BasalColumn> {
    let (nx, ny) = (xf.len() - 1, yf.len() - 1);
    let dy = |j: usize| yf[j + 1] - yf[j];
    let centre = |j: usize| 0.5 * (yf[j] + yf[j + 1]);
    let (rho_s, rho_g) = (material.solids_density, material.gas_density);
    (0..nx)
        .filter_map(|i| {
            let eps = |j: usize| fields.eps_s[i + nx * j];
            let solids_height: f64 = (0..ny).map(|j| eps(j) * dy(j)).sum();
            if solids_height < GRAIN_EDGE_DIAMETERS * material.diameter {
                return None;
            }
            let x = 0.5 * (xf[i] + xf[i + 1]);
            let g_n = normal_gravity(x);
            let above_centre = solids_height - 0.5 * eps(0) * dy(0);
            let load = above_centre * (rho_s - rho_g) * g_n;
            let top = i + nx * (ny - 1);
            let excess =
                fields.p_g[i] - fields.p_g[top] - rho_g * g_n * (centre(ny - 1) - centre(0));
            Some(BasalColumn {
                x,
                width: xf[i + 1] - xf[i],
                load,
                gas_share: excess / load,
                solids_share: fields.p_s[i] / load,
            })
        })
        .collect()
}

/// The flow's shares from its columns; `None` without a column.
pub fn flow_load(time: f64, columns: &[BasalColumn]) -> Option<FlowLoad> {
    let heaviest = columns.iter().map(|c| c.load).fold(0.0, f64::max);
    let (mut load, mut gas, mut solids) = (0.0, 0.0, 0.0);
    for c in columns {
        let w = c.width;
        load += c.load * w;
        gas += c.gas_share * c.load * w;
        solids += c.solids_share * c.load * w;
    }
    let peak = columns
        .iter()
        .filter(|c| c.load >= 0.1 * heaviest)
        .max_by(|a, b| a.gas_share.total_cmp(&b.gas_share))?;
    Some(FlowLoad {
        time,
        load,
        gas_share: gas / load,
        solids_share: solids / load,
        peak_gas_share: peak.gas_share,
        peak_gas_share_x: peak.x,
    })
}

/// Every field file of the run in `dir`: its time and its columns (module doc).
pub fn read_basal_load(dir: &Path, case: &Case) -> Result<Vec<(f64, Vec<BasalColumn>)>, String> {
    let grid = case.grid().map_err(|e| format!("{}: {e}", dir.display()))?;
    let (xf, yf) = (grid.x.faces().to_vec(), grid.y.faces().to_vec());
    let solids = case
        .solids
        .first()
        .ok_or_else(|| format!("{}: the case has no solids phase", dir.display()))?;
    let material = Material {
        solids_density: solids.density,
        gas_density: case.gas.as_ref().map_or(0.0, |g| g.density),
        diameter: solids.diameter,
    };
    let floor = case.bent_floor().map_err(|e| e.to_string())?;
    let plane_g_n = match case.gravity {
        Gravity::Constant { magnitude, slope }
        | Gravity::TiltOnImpact {
            magnitude, slope, ..
        } => magnitude * slope.to_radians().cos(),
    };
    let normal_gravity = |x: f64| floor.as_ref().map_or(plane_g_n, |f| -f.force(x, 0.0).1);
    let files =
        field_files(dir).map_err(|e| format!("{}: {e}", dir.join("fields.pvd").display()))?;
    let cells = (xf.len() - 1) * (yf.len() - 1);
    files
        .iter()
        .map(|(time, name)| {
            let path = dir.join(name);
            let xml =
                std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
            let array = |field: &str| {
                runout_output::read_vtr_array(&xml, field)
                    .filter(|a| a.len() == cells)
                    .ok_or_else(|| format!("{}: no {field} array of {cells} cells", path.display()))
            };
            // a dry case (no gas) writes no p_g: its gas carries nothing
            let p_g = match case.gas {
                Some(_) => array("p_g")?,
                None => vec![0.0; cells],
            };
            let (eps_s, p_s) = (array("eps_s")?, array("p_s")?);
            let fields = BaseFields {
                eps_s: &eps_s,
                p_g: &p_g,
                p_s: &p_s,
            };
            Ok((
                *time,
                basal_columns(&fields, (&xf, &yf), material, normal_gravity),
            ))
        })
        .collect()
}

/// The columns as CSV: `t,x,load,gas_share,solids_share` (s, m, Pa, -, -).
pub fn columns_csv(snapshots: &[(f64, Vec<BasalColumn>)]) -> String {
    let mut s = String::from("t,x,load,gas_share,solids_share\n");
    for (time, columns) in snapshots {
        for c in columns {
            s.push_str(&format!(
                "{time},{},{},{},{}\n",
                c.x, c.load, c.gas_share, c.solids_share
            ));
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A layer of εs = 0.5 four cells deep on a 30° slope, its gas pressure rising λ of the
    /// load toward the floor above the gas's hydrostatic column, its solids pressure carrying
    /// 1 − λ: the shares come back as λ and 1 − λ; a column without solids is left out.
    #[test]
    fn a_layer_whose_gas_carries_a_known_share_gives_it_back() {
        let (nx, ny) = (3, 6);
        let xf = [0.0, 0.1, 0.2, 0.3];
        let yf: Vec<f64> = (0..=ny).map(|j| 0.01 * (j * j) as f64).collect();
        let (rho_s, rho_g, g_n) = (2500.0, 1.2, 9.81 * 30f64.to_radians().cos());
        let depth = 4;
        let mut eps_s = vec![0.0; nx * ny];
        for i in 0..2 {
            for j in 0..depth {
                eps_s[i + nx * j] = 0.5;
            }
        }
        let centre = |j: usize| 0.5 * (yf[j] + yf[j + 1]);
        // the buoyant weight above y: εs (ρs − ρg) g_n (y_layer − y)
        let above = |y: f64| 0.5 * (rho_s - rho_g) * g_n * (yf[depth] - y).max(0.0);
        let lambda = [0.3, 0.9];
        let (mut p_g, mut p_s) = (vec![0.0; nx * ny], vec![0.0; nx * ny]);
        for i in 0..nx {
            for j in 0..ny {
                let l = lambda.get(i).copied().unwrap_or(0.0);
                p_g[i + nx * j] = 1e5 + rho_g * g_n * (yf[ny] - centre(j)) + l * above(centre(j));
                p_s[i + nx * j] = (1.0 - l) * above(centre(j));
            }
        }
        let fields = BaseFields {
            eps_s: &eps_s,
            p_g: &p_g,
            p_s: &p_s,
        };
        let material = Material {
            solids_density: rho_s,
            gas_density: rho_g,
            diameter: 5e-4,
        };
        let columns = basal_columns(&fields, (&xf, &yf), material, |_| g_n);
        assert_eq!(columns.len(), 2);
        for (c, l) in columns.iter().zip(lambda) {
            assert!((c.load - above(centre(0))).abs() < 1e-9 * c.load);
            assert!((c.gas_share - l).abs() < 1e-12, "{c:?}");
            assert!((c.solids_share - (1.0 - l)).abs() < 1e-12, "{c:?}");
        }
        let flow = flow_load(1.0, &columns).unwrap();
        assert!((flow.gas_share - 0.6).abs() < 1e-12);
        assert!((flow.solids_share - 0.4).abs() < 1e-12);
        assert!((flow.peak_gas_share - 0.9).abs() < 1e-12);
        assert!((flow.peak_gas_share_x - 0.15).abs() < 1e-12);
        assert!(flow_load(1.0, &[]).is_none());
    }
}
