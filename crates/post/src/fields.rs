//! The field files of a run folder: `fields.pvd` lists the `fields_*.vtr` snapshots with
//! their times ([`runout_output::read_pvd`]); a figure or check reads the one nearest a
//! time, or the last.

use std::path::Path;

/// The (time, file name) entries of the run's `fields.pvd`, in its order.
pub fn field_files(dir: &Path) -> std::io::Result<Vec<(f64, String)>> {
    let pvd = std::fs::read_to_string(dir.join("fields.pvd"))?;
    Ok(runout_output::read_pvd(&pvd))
}

/// The entry whose time is nearest `t` (the first of equally near ones).
pub fn nearest(entries: &[(f64, String)], t: f64) -> Option<&(f64, String)> {
    entries
        .iter()
        .min_by(|a, b| (a.0 - t).abs().total_cmp(&(b.0 - t).abs()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_nearest_field_is_chosen_by_time() {
        let entries = vec![(0.0, "a".to_string()), (0.5, "b".into()), (1.0, "c".into())];
        assert_eq!(nearest(&entries, 0.6).unwrap().1, "b");
        assert_eq!(nearest(&entries, 2.0).unwrap().1, "c");
        assert_eq!(nearest(&[], 1.0), None);
        assert!(field_files(Path::new("/nonexistent")).is_err());
    }
}
