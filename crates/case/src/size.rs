//! Cells, unknowns and memory of a case, computed without building its grid, and the
//! memory the machine has: `runout check` prints them, `runout run` compares them.

use runout_mesh::MeshError;

use crate::schema::Case;

/// Peak memory per cell of the gas (single-phase) solver [bytes]. Measured as the peak
/// resident set (`/usr/bin/time -f %M`, the kernel's VmHWM) of `runout run --end-time 0.02`
/// on examples/cavity-re100.ron at 64², 256² and 512² cells: 9 960, 64 056 and 236 612 KiB,
/// slopes of 902 and 899 B per cell; a run that writes a checkpoint (SIGINT, the sweep's
/// every 10 min) peaks higher: 69 796 KiB at 256², 930 B per cell above 10 MiB
/// (docs/reference/input-validation.md, issue 44); with a margin.
const GAS_BYTES_PER_CELL: u64 = 1050;

/// Peak memory per cell added by each solids phase [bytes]. Measured likewise on every
/// shipped two-fluid case (docs/reference/input-validation.md, issue 44): a run that writes a
/// checkpoint peaks at up to 2 300 B per cell above 10 MiB (S-JJ-phi at the paper grid,
/// 90 000 cells: 212 448 KiB; the stiff cases at `wall` fidelity 2 293); with a margin,
/// the one-phase estimate is 2 600 B per cell (C-a1 at `wall`, 4 000 cells: 2 476 B).
const SOLIDS_PHASE_BYTES_PER_CELL: u64 = 1550;

/// Memory independent of the grid [bytes]: the measured intercepts are 6.2 MiB (gas) and
/// 8.4 MiB (two-fluid); rounded up.
const FIXED_BYTES: u64 = 10 << 20;

/// Unknowns per cell of the gas: u, v and the pressure correction.
const GAS_UNKNOWNS_PER_CELL: u64 = 3;

/// Unknowns per cell of one solids phase: u, v, εs and θ.
const SOLIDS_UNKNOWNS_PER_CELL: u64 = 4;

/// The size of a case's grid as written (call it on [`Case::at_fidelity`] for a preset).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CaseSize {
    /// cells in x
    pub nx: usize,
    /// cells in y
    pub ny: usize,
    /// nx × ny
    pub cells: u64,
    /// discrete unknowns: cells × (3 for the gas + 4 per solids phase)
    pub unknowns: u64,
    /// estimated peak memory of `runout run` [bytes]
    pub memory_bytes: u64,
}

/// The size of `case`'s grid, from the segments' cell counts (nothing is allocated); an
/// error for an axis that does not validate.
pub fn case_size(case: &Case) -> Result<CaseSize, MeshError> {
    let nx = case.domain.x.cell_count()?;
    let ny = case.domain.y.cell_count()?;
    let cells = (nx as u64).saturating_mul(ny as u64);
    let phases = case.solids.len() as u64;
    let unknowns_per_cell =
        GAS_UNKNOWNS_PER_CELL.saturating_add(SOLIDS_UNKNOWNS_PER_CELL.saturating_mul(phases));
    Ok(CaseSize {
        nx,
        ny,
        cells,
        unknowns: cells.saturating_mul(unknowns_per_cell),
        memory_bytes: bytes_for_cells(cells, phases),
    })
}

/// Estimated peak memory of a run on `cells` cells with `phases` solids phases [bytes].
pub(crate) fn bytes_for_cells(cells: u64, phases: u64) -> u64 {
    let per_cell =
        GAS_BYTES_PER_CELL.saturating_add(SOLIDS_PHASE_BYTES_PER_CELL.saturating_mul(phases));
    cells.saturating_mul(per_cell).saturating_add(FIXED_BYTES)
}

/// Estimated peak memory of `runout run` on `case` as written [bytes]: 10 MiB plus, per
/// cell, 1050 B for the gas and 1550 B per solids phase (measured, see the constants);
/// `u64::MAX` when the grid is invalid (it cannot be run).
pub fn estimated_memory_bytes(case: &Case) -> u64 {
    case_size(case).map_or(u64::MAX, |s| s.memory_bytes)
}

/// The environment variable that sets the memory available to a run [bytes], for a
/// scheduler's limit that runout cannot read (and for tests).
pub const AVAILABLE_MEMORY_VAR: &str = "RUNOUT_AVAILABLE_MEMORY";

/// The memory available for new work [bytes]: [`AVAILABLE_MEMORY_VAR`] if set, else the
/// smaller of the kernel's `MemAvailable` (/proc/meminfo) and the room left under this
/// process's cgroup (v2) limit, `memory.max − memory.current` (a Slurm job's limit);
/// `None` where neither can be read (not Linux).
pub fn available_memory_bytes() -> Option<u64> {
    if let Some(v) = std::env::var(AVAILABLE_MEMORY_VAR)
        .ok()
        .and_then(|v| v.trim().parse().ok())
    {
        return Some(v);
    }
    let kernel = std::fs::read_to_string("/proc/meminfo")
        .ok()
        .and_then(|t| mem_available(&t));
    let read = |f: &str| std::fs::read_to_string(format!("/sys/fs/cgroup/{f}")).ok();
    let cgroup = match (read("memory.max"), read("memory.current")) {
        (Some(max), Some(current)) => max
            .trim()
            .parse::<u64>()
            .ok()
            .zip(current.trim().parse::<u64>().ok())
            .map(|(max, current)| max.saturating_sub(current)),
        _ => None, // "max" (no limit) or no cgroup v2
    };
    match (kernel, cgroup) {
        (Some(k), Some(c)) => Some(k.min(c)),
        (k, c) => k.or(c),
    }
}

/// `MemAvailable` of a /proc/meminfo text [bytes].
fn mem_available(meminfo: &str) -> Option<u64> {
    let line = meminfo
        .lines()
        .find_map(|l| l.strip_prefix("MemAvailable:"))?;
    let kib: u64 = line.trim().strip_suffix("kB")?.trim().parse().ok()?;
    kib.checked_mul(1024)
}

/// Bytes in a short human form: `9.5 MiB`, `1.9 GiB`.
pub fn format_bytes(bytes: u64) -> String {
    const UNITS: [&str; 5] = ["B", "KiB", "MiB", "GiB", "TiB"];
    let mut v = bytes as f64;
    let mut unit = 0;
    while v >= 1024.0 && unit + 1 < UNITS.len() {
        v /= 1024.0;
        unit += 1;
    }
    if unit == 0 {
        format!("{bytes} B")
    } else {
        format!("{v:.1} {}", UNITS[unit])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mem_available_reads_kib() {
        let text = "MemTotal:       24000000 kB\nMemFree:  1 kB\nMemAvailable:   23000000 kB\n";
        assert_eq!(mem_available(text), Some(23_000_000 * 1024));
        assert_eq!(mem_available("MemTotal: 1 kB\n"), None);
        assert_eq!(mem_available("MemAvailable: lots\n"), None);
    }

    #[test]
    fn bytes_print_short() {
        assert_eq!(format_bytes(512), "512 B");
        assert_eq!(format_bytes(10 << 20), "10.0 MiB");
        assert_eq!(format_bytes(1_900_000_000_000), "1.7 TiB");
    }
}
