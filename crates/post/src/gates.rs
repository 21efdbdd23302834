//! The two gate files: the gates a flume case describes (`cases/flume/gates.csv`: gate name,
//! distance from the channel inlet, described speed, source) and the gate crossings a run
//! writes (`gates.csv` of a run folder: gate number, x, crossing time, front speed).

use std::path::Path;

use crate::table::Table;

/// One gate of a described gate file such as cases/flume/gates.csv.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DescribedGate {
    /// gate number (`L1` is 1)
    pub gate: usize,
    /// distance from the channel inlet [m]
    pub distance: f64,
    /// the front speed described at the gate [m/s], if the file gives one
    pub speed: Option<f64>,
}

/// The gates of a described gate file (header `gate,distance_m,speed_m_s,source`; `#` lines
/// are comments; gate names are L1..L7); rows whose gate or distance cannot be read are
/// skipped, and an unreadable file has no gates.
pub fn read_described_gates(path: &Path) -> Vec<DescribedGate> {
    let Ok(text) = std::fs::read_to_string(path) else {
        return Vec::new();
    };
    text.lines()
        .filter(|l| !l.trim_start().starts_with('#'))
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split(',').map(str::trim).collect();
            Some(DescribedGate {
                gate: f.first()?.trim_start_matches('L').parse().ok()?,
                distance: f.get(1)?.parse().ok()?,
                speed: f.get(2).and_then(|s| s.parse().ok()),
            })
        })
        .collect()
}

/// The described gate speeds of a gate file: (gate number, speed) for the rows with a speed.
pub fn described_speeds(gates_csv: &Path) -> Vec<(usize, f64)> {
    speeds_of(&read_described_gates(gates_csv))
}

/// (gate number, speed) of the gates that have a described speed.
pub fn speeds_of(gates: &[DescribedGate]) -> Vec<(usize, f64)> {
    gates
        .iter()
        .filter_map(|g| Some((g.gate, g.speed?)))
        .collect()
}

/// The front speed at each gate a run crossed, from its `gates.csv`: (gate number, speed);
/// a gate without a speed is not a crossing. The error says why the file cannot be read.
pub fn read_gate_speeds(gates_csv: &Path) -> Result<Vec<(usize, f64)>, String> {
    Ok(Table::read(gates_csv)?
        .pairs("gate", "speed")?
        .into_iter()
        .filter(|(_, s)| s.is_finite())
        .map(|(g, speed)| (g as usize, speed))
        .collect())
}

/// The front speeds of the run in `dir` ([`read_gate_speeds`]); `None` without a readable
/// `gates.csv`.
pub fn gate_speeds(dir: &Path) -> Option<Vec<(usize, f64)>> {
    read_gate_speeds(&dir.join("gates.csv")).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn described_gates_keep_rows_without_a_speed() {
        let dir = std::env::temp_dir().join(format!("runout-post-gates-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("gates.csv");
        std::fs::write(
            &file,
            "# comment\ngate,distance_m,speed_m_s,source\nL1,1.65,,described\n\
             L2, 2.10 ,4.0,described\nbad,1,2,x\n",
        )
        .unwrap();
        let gates = read_described_gates(&file);
        assert_eq!(
            gates,
            vec![
                DescribedGate {
                    gate: 1,
                    distance: 1.65,
                    speed: None
                },
                DescribedGate {
                    gate: 2,
                    distance: 2.1,
                    speed: Some(4.0)
                }
            ]
        );
        assert_eq!(described_speeds(&file), vec![(2, 4.0)]);
        std::fs::write(&file, "gate,x,t_cross,speed\n1,2.15,0.5,3.0\n2,2.6,0.6,\n").unwrap();
        assert_eq!(read_gate_speeds(&file).unwrap(), vec![(1, 3.0)]);
        assert_eq!(gate_speeds(&dir.join("none")), None);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
