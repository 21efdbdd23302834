//! Validation of a case's grid at every fidelity: sizes bounded arithmetically before any
//! axis is built, then the built axes' smallest width (and, for the grid as written, the
//! adjacent-width ratio).

use runout_mesh::{AxisSpec, Grid, MeshError};

use crate::checker::Checker;
use crate::limits::{ADJACENT_WIDTH_RATIO, CELL_WIDTH, COORDINATE, DOMAIN_LENGTH, MAX_CELLS};
use crate::schema::Case;
use crate::size::{bytes_for_cells, format_bytes};

/// Checks both axes as written and the grid of every fidelity. Nothing larger than
/// [`runout_mesh::MAX_AXIS_CELLS`] per axis and [`MAX_CELLS`] in all is ever built.
pub(crate) fn check_grids(c: &mut Checker, case: &Case) {
    let x_ok = check_axis(c, "domain.x", &case.domain.x);
    let y_ok = check_axis(c, "domain.y", &case.domain.y);
    if !(x_ok && y_ok) {
        return;
    }
    let wall = case.fidelity.wall_preset();
    let presets = [
        ("smoke", &case.fidelity.smoke),
        ("coarse", &case.fidelity.coarse),
        ("wall", &wall),
    ];
    // the presets only once the grid as written passed, so that one fault is one error
    if !check_fidelity_grid(c, None, &case.domain.x, &case.domain.y) {
        return;
    }
    for (name, preset) in presets {
        let (fx, fy) = (preset.coarsen, preset.factor_y());
        if fx >= 1 && fy >= 1 {
            check_fidelity_grid(
                c,
                Some((name, fx.max(fy))),
                &case.domain.x.coarsened(fx),
                &case.domain.y.coarsened(fy),
            );
        }
    }
}

/// The axis's origin, segments, cell count and length; true when the axis can be built.
fn check_axis(c: &mut Checker, field: &str, axis: &AxisSpec) -> bool {
    let before = c.errors.len();
    c.band(format!("{field}.origin"), axis.origin, &COORDINATE);
    if axis.segments.is_empty() {
        c.fail(format!("{field}.segments"), "[]", "at least one segment");
        return false;
    }
    let mut segments_ok = true;
    for (k, seg) in axis.segments.iter().enumerate() {
        if let Err(e) = seg.validate(&format!("{field}.segments[{k}]")) {
            fail_mesh(c, &format!("{field}.segments[{k}]"), e);
            segments_ok = false;
        }
    }
    if !segments_ok {
        return false;
    }
    if let Err(e) = axis.cell_count() {
        fail_mesh(c, field, e);
        return false;
    }
    let length: f64 = axis.segments.iter().map(|s| s.length()).sum();
    c.band(
        format!("{field}.segments (total length)"),
        length,
        &DOMAIN_LENGTH,
    );
    c.errors.len() == before
}

/// A mesh error as a field error; `field` prefixes the paths the mesh reports relative to
/// an axis (`segments...`) and names the place of the others.
fn fail_mesh(c: &mut Checker, field: &str, e: MeshError) {
    match e {
        MeshError::Invalid {
            field: f,
            value,
            allowed,
        } => {
            let path = if f.starts_with(field) {
                f
            } else {
                format!("{field}.{f}")
            };
            c.fail(path, value, allowed)
        }
        MeshError::Unsolvable(m) => c.fail(
            format!("{field}.segments"),
            "(as given)",
            format!("segments that form a grid: {m}"),
        ),
    }
}

/// One fidelity's grid (`preset` = None for the case as written): the cell count (from the
/// segments, before building), then the built axes' widths; true when all passed.
fn check_fidelity_grid(
    c: &mut Checker,
    preset: Option<(&str, u32)>,
    x: &AxisSpec,
    y: &AxisSpec,
) -> bool {
    let before = c.errors.len();
    // where an error is reported: the domain itself, or the preset's coarsening
    let (size_field, at) = match preset {
        None => ("domain".to_string(), String::new()),
        Some((name, _)) => (
            format!("fidelity.{name}.coarsen"),
            format!(" at fidelity.{name}"),
        ),
    };
    // an axis or grid that does not build, reported on the domain or the preset's factor
    let unbuildable = |c: &mut Checker, e: &dyn std::fmt::Display| {
        let factor = preset.map_or(1, |(_, f)| f);
        c.fail(
            size_field.clone(),
            factor,
            format!("a factor whose grid builds ({e})"),
        );
    };
    let counts = x.cell_count().and_then(|nx| Ok((nx, y.cell_count()?)));
    let (nx, ny) = match counts {
        Ok(n) => n,
        Err(e) => {
            unbuildable(c, &e);
            return false;
        }
    };
    let cells = (nx as u64).saturating_mul(ny as u64);
    if cells > MAX_CELLS as u64 {
        c.fail(
            format!("{size_field} (cells{at})"),
            format!("{nx} x {ny} = {cells}"),
            format!(
                "at most {MAX_CELLS} cells (~{} of memory for the two-fluid solver: \
                 docs/reference/input-validation.md)",
                format_bytes(bytes_for_cells(MAX_CELLS as u64, 1))
            ),
        );
        return false;
    }
    let grid = match Grid::from_specs(x, y) {
        Ok(g) => g,
        Err(e) => {
            unbuildable(c, &e);
            return false;
        }
    };
    for (name, axis) in [("domain.x", &grid.x), ("domain.y", &grid.y)] {
        c.band(
            format!("{name} (smallest cell width{at})"),
            axis.width_range().0,
            &CELL_WIDTH,
        );
        // a preset's jumps follow from coarsening the grid as written, not from the input
        if preset.is_none() {
            c.band(
                format!("{name} (largest adjacent width ratio)"),
                axis.max_adjacent_ratio(),
                &ADJACENT_WIDTH_RATIO,
            );
        }
    }
    c.errors.len() == before
}
