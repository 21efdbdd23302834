//! Reading a finished run of the ladder: its gate speeds and its bulk monitor history (each
//! `None` where the run or the case has none; the station profile and numbers are read as
//! the report reads them, [`super::station`]).

use std::path::Path;

use runout_case::Case;

use super::quantity::History;
use runout_post::table::Table;

/// Front speeds per gate of a finished run with a front monitor; none if its front reached
/// no gate (such a run is left out rather than emptying the common gates of the ladder).
pub(super) fn read_gates(dir: &Path, case: &Case) -> Option<Vec<(usize, f64)>> {
    case.monitors.front.as_ref()?;
    let pairs = Table::read(&dir.join("gates.csv"))
        .ok()?
        .pairs("gate", "speed")
        .ok()?;
    let speeds: Vec<(usize, f64)> = pairs
        .into_iter()
        .filter(|(_, v)| v.is_finite())
        .map(|(g, v)| (g as usize, v))
        .collect();
    (!speeds.is_empty()).then_some(speeds)
}

/// The bulk monitor history of a finished run, front positions at the domain's west end (no
/// floor cell reaches the threshold yet) replaced by NaN.
pub(super) fn read_history(dir: &Path, case: &Case, x_start: f64) -> Option<History> {
    case.monitors.bulk.as_ref()?;
    let table = Table::read(&dir.join("bulk.csv")).ok()?;
    let t = table.column("t").ok()?;
    let front_x = table
        .column("front_x")
        .ok()?
        .into_iter()
        .map(|x| if x > x_start { x } else { f64::NAN })
        .collect();
    let mean_u_s = table.column("mean_u_s").ok()?;
    (!t.is_empty()).then_some(History {
        t,
        front_x,
        mean_u_s,
    })
}
