//! The two gate files: the gates a flume case describes (`cases/flume/gates.csv`: gate name,
//! distance from the channel inlet, described speed, source) and the gate crossings a run
//! writes (`gates.csv` of a run folder: gate number, x, crossing time, front speed), and the
//! front speed at a gate interpolated from the run's front series ([`speed_at_gate`]), the
//! one calibration fits.

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

/// Samples on each side of a front sample over which its speed is differenced (the run's
/// `gates.csv` uses the same stencil).
const SPEED_HALF_STENCIL: usize = 2;

/// The front's crossing of `x_gate` and its speed there from the samples `series` (t, x) of
/// an interpolated front, both continuous in the samples: the crossing time t_g linear
/// between the two samples that bracket the gate, and the speed linear in t between their
/// central differences v_j = (x_(j+2) − x_(j−2))/(t_(j+2) − t_(j−2)) (clamped at the ends).
/// The run's `gates.csv` takes the difference around the first sample past the gate
/// instead, which jumps by a sample when a parameter moves the crossing across one: a
/// misfit that is not smooth in the parameters (issue 48). `None` if the front never reaches
/// the gate or the samples do not advance in time.
pub fn speed_at_gate(series: &[(f64, f64)], x_gate: f64) -> Option<(f64, f64)> {
    let k = series.iter().position(|&(_, x)| x >= x_gate)?;
    let speed = |j: usize| {
        let (lo, hi) = (
            j.saturating_sub(SPEED_HALF_STENCIL),
            (j + SPEED_HALF_STENCIL).min(series.len() - 1),
        );
        let dt = series[hi].0 - series[lo].0;
        (dt > 0.0).then(|| (series[hi].1 - series[lo].1) / dt)
    };
    if k == 0 {
        return Some((series[0].0, speed(0)?));
    }
    let ((t0, x0), (t1, x1)) = (series[k - 1], series[k]);
    // x0 < x_gate <= x1, so x1 > x0
    let w = (x_gate - x0) / (x1 - x0);
    let t_gate = t0 + w * (t1 - t0);
    Some((t_gate, (1.0 - w) * speed(k - 1)? + w * speed(k)?))
}

/// The front speed at each gate the run in `dir` crossed, [`speed_at_gate`] on its front
/// series (`front.csv`, [`crate::front::front_series`]) at the gates' x of its `gates.csv`:
/// (gate number, speed). The error says which file cannot be read.
pub fn interpolated_gate_speeds(dir: &Path) -> Result<Vec<(usize, f64)>, String> {
    let gates = Table::read(&dir.join("gates.csv"))?.pairs("gate", "x")?;
    let (_, series) = crate::front::front_series(dir)?;
    Ok(gates
        .into_iter()
        .filter_map(|(g, x)| Some((g as usize, speed_at_gate(&series, x)?.1)))
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A front x = t²: the central differences are exact (2t) and linear in t, so the speed
    /// at the gate is 2 t_g with t_g the chord's crossing time.
    #[test]
    fn speed_at_a_gate_of_a_uniformly_accelerating_front() {
        let series: Vec<(f64, f64)> = (0..50)
            .map(|k| (0.01 * k as f64, (0.01 * k as f64).powi(2)))
            .collect();
        let (t_g, v) = speed_at_gate(&series, 0.1).unwrap();
        assert!((t_g - 0.316).abs() < 1e-3, "{t_g}");
        assert!((v - 2.0 * t_g).abs() < 1e-12, "{v} {t_g}");
        assert!(speed_at_gate(&series, 1.0).is_none());
    }

    /// Shifting the front so that a sample passes the gate moves the speed continuously
    /// (within the shift's own effect), where the sample-index stencil jumps.
    #[test]
    fn the_speed_at_a_gate_is_continuous_when_a_sample_crosses_it() {
        let front = |shift: f64| -> Vec<(f64, f64)> {
            (0..60)
                .map(|k| {
                    let t = 0.01 * k as f64;
                    // a speed that varies quickly, so a one-sample shift of the stencil shows
                    (t, shift + t + 0.2 * (40.0 * t).sin() / 40.0 + 2.0 * t * t)
                })
                .collect()
        };
        // the sample at t = 0.20 sits exactly on the gate for shift s0
        let x_gate = 0.3;
        let s0 = x_gate - front(0.0)[20].1;
        let (_, below) = speed_at_gate(&front(s0 - 1e-9), x_gate).unwrap();
        let (_, above) = speed_at_gate(&front(s0 + 1e-9), x_gate).unwrap();
        assert!((below - above).abs() < 1e-6, "{below} {above}");
    }

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
