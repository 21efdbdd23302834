//! The last field file of a run: εs and θ per cell, the front of the floor row at a given
//! εs, and the median used for the deposit's θ.

use std::path::Path;

use anyhow::{Context, Result};

/// The values of DataArray `name` in a `.vtr` written by runout-output.
fn vtr_array(xml: &str, name: &str) -> Result<Vec<f64>> {
    runout_output::read_vtr_array(xml, name).with_context(|| format!("no readable array `{name}`"))
}

/// The last field file of a run: εs and θ per cell.
pub(super) fn last_fields(run_dir: &Path) -> Result<(Vec<f64>, Vec<f64>)> {
    let (_, last) = runout_post::fields::field_files(run_dir)
        .with_context(|| format!("reading {}", run_dir.join("fields.pvd").display()))?
        .pop()
        .context("fields.pvd lists no file")?;
    let path = run_dir.join(last);
    let xml =
        std::fs::read_to_string(&path).with_context(|| format!("reading {}", path.display()))?;
    Ok((vtr_array(&xml, "eps_s")?, vtr_array(&xml, "theta")?))
}

/// The largest x whose floor cell has εs ≥ `threshold` (the wall if none), like the bulk
/// monitor's front.
pub(super) fn floor_front(eps: &[f64], faces: &[f64], threshold: f64) -> f64 {
    let nx = faces.len() - 1;
    (0..nx)
        .rev()
        .find(|&i| eps[i] >= threshold)
        .map_or(faces[0], |i| faces[i + 1])
}

/// The median of `v` (NaN if empty).
pub(super) fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floor_front_takes_the_last_floor_cell_above_the_threshold() {
        let faces = [0.0, 0.1, 0.2, 0.3, 0.4];
        // floor row then a second row (ignored)
        let eps = [0.6, 0.4, 0.005, 0.0, 0.6, 0.6, 0.6, 0.6];
        assert_eq!(floor_front(&eps, &faces, 0.01), 0.2);
        assert_eq!(floor_front(&eps, &faces, 0.5), 0.1);
        assert_eq!(floor_front(&eps, &faces, 0.7), 0.0);
    }
}
