//! The last field file of a run: εs and θ per cell, and the median used for the deposit's θ
//! (the floor row's front at a given εs is `runout_post::deposit::distal_edge`).

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

/// The median of `v` (NaN if empty).
pub(super) fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}
