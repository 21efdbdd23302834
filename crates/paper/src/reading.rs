//! runout's reading of each number the paper reports ([`super::paper::PAPER_NUMBERS`]):
//! the flow metrics of a case's station profile, probe, gates and bulk monitor in the
//! report's words, or why it is missing.

use runout_post::case_data::CaseData;

use super::paper::Quantity;
use super::record::RunRecord;
use super::records::Records;
use runout_post::metrics::{mse_vs_described, FlowMetrics, FLOW_THRESHOLD};

/// The metrics of a case's station profile; a profile without flowing material (which
/// would read as "no cushion, zero thickness") says that there is no flow instead.
pub fn flow_at_station(data: &CaseData) -> Result<FlowMetrics, String> {
    let p = data.profile.as_ref().map_err(Clone::clone)?;
    let peak = p.eps_s.iter().copied().fold(0.0, f64::max);
    if peak < FLOW_THRESHOLD {
        return Err(format!(
            "no flow at the station: the largest εs is {peak:.1e} < {FLOW_THRESHOLD}"
        ));
    }
    Ok(p.metrics())
}

/// runout's value of a quantity: yes/no, or a number with the decimals the report shows and
/// an optional note (e.g. the gate it was read at).
#[derive(Clone, Debug, PartialEq)]
pub enum Reading {
    /// a yes/no finding (the air cushion)
    YesNo(bool),
    /// a number, shown with `decimals` decimals and the note in brackets
    Number {
        /// the value, in the quantity's unit
        value: f64,
        /// decimals shown
        decimals: usize,
        /// shown after the value in brackets
        note: Option<String>,
    },
}

impl Reading {
    fn number(value: f64, decimals: usize) -> Reading {
        Reading::Number {
            value,
            decimals,
            note: None,
        }
    }

    fn noted(value: f64, decimals: usize, note: String) -> Reading {
        Reading::Number {
            value,
            decimals,
            note: Some(note),
        }
    }

    /// The number as the report shows it (rounded to its decimals); `None` for yes/no.
    pub fn shown_value(&self) -> Option<f64> {
        match self {
            Reading::YesNo(_) => None,
            Reading::Number {
                value, decimals, ..
            } => format!("{value:.decimals$}").parse().ok(),
        }
    }
}

impl std::fmt::Display for Reading {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Reading::YesNo(true) => write!(f, "yes"),
            Reading::YesNo(false) => write!(f, "no"),
            Reading::Number {
                value,
                decimals,
                note,
            } => {
                write!(f, "{value:.decimals$}")?;
                match note {
                    Some(n) => write!(f, " ({n})"),
                    None => Ok(()),
                }
            }
        }
    }
}

/// runout's value of `q` for `case` in the report's words, or why it is missing.
pub fn reading(
    q: Quantity,
    case: &str,
    records: &Records,
    described: &[(usize, f64)],
) -> Result<String, String> {
    value(q, case, records, described).map(|r| r.to_string())
}

/// A gate reading: the gate chosen by `pick` among the run's gates, with its number.
fn gate_reading(
    r: &RunRecord,
    pick: impl Fn(&[(usize, f64)]) -> Option<(usize, f64)>,
) -> Result<Reading, String> {
    let gates = r.gates.as_ref().map_err(Clone::clone)?;
    let (gate, speed) = pick(gates).ok_or_else(|| r.no_gate_reached())?;
    Ok(Reading::noted(speed, 2, format!("at L{gate}")))
}

/// runout's value of `q` for `case` (its record in `records`), or why it is missing.
pub fn value(
    q: Quantity,
    case: &str,
    records: &Records,
    described: &[(usize, f64)],
) -> Result<Reading, String> {
    let r = records.get(case)?;
    let station = || r.station.as_ref().map_err(Clone::clone);
    let unknown = || "not defined for this profile".to_string();
    match q {
        Quantity::AirCushion => Ok(Reading::YesNo(r.flow()?.air_cushion.ok_or_else(unknown)?)),
        Quantity::FloorEpsS => Ok(Reading::number(station()?.floor_eps_s, 3)),
        Quantity::CushionThickness => {
            let m = r.flow()?;
            Ok(match m.air_cushion {
                Some(true) => Reading::number(m.cushion_thickness.ok_or_else(unknown)?, 3),
                _ => Reading::noted(0.0, 0, "no cushion".into()),
            })
        }
        Quantity::FloorTheta => Ok(Reading::number(station()?.floor_theta, 3)),
        Quantity::MaxUs => Ok(Reading::number(r.flow()?.max_u_s.ok_or_else(unknown)?, 2)),
        Quantity::FlowThickness => Ok(Reading::number(
            r.flow()?.flow_thickness.ok_or_else(unknown)?,
            3,
        )),
        Quantity::FlowThicknessAbove(other) => {
            let own = r.flow()?.flow_thickness.ok_or_else(unknown)?;
            let theirs = records
                .get(other)
                .and_then(|o| o.flow().map(|s| s.flow_thickness))
                .map_err(|e| format!("`{other}`: {e}"))?
                .ok_or_else(unknown)?;
            Ok(Reading::number(own - theirs, 3))
        }
        Quantity::ProbeHu => {
            let (t, h) = r.probe.clone()?;
            match r.ended_before(r.station_time) {
                Some(why) => Err(format!("{why}; its last sample: {h:.0} at t = {t:.2} s")),
                None => Ok(Reading::number(h, 0)),
            }
        }
        Quantity::FlumeMse => {
            let gates = r.gates.as_ref().map_err(Clone::clone)?;
            let (e, used) =
                mse_vs_described(gates, described).ok_or_else(|| r.no_gate_reached())?;
            Ok(Reading::noted(
                e,
                2,
                format!("{used} of {} gates", described.len()),
            ))
        }
        Quantity::FlumeMaxGateSpeed => {
            gate_reading(r, |g| g.iter().copied().max_by(|a, b| a.1.total_cmp(&b.1)))
        }
        Quantity::FlumeLastGateSpeed => gate_reading(r, |g| g.iter().copied().max_by_key(|p| p.0)),
    }
}

#[cfg(test)]
mod tests {
    use super::super::records::from_runs;
    use super::*;
    use runout_post::fixture::*;

    #[test]
    fn readings_follow_the_metrics_and_say_why_they_are_missing() {
        let tmp = TempDir::new("readings");
        let runs = tmp.0.join("runs");
        write_run(
            &runs,
            "wide",
            "coarse",
            1.25,
            &[
                ("profile_x11_t1.25.csv", DENSE_PROFILE),
                ("wall_probe_south_x11.csv", "t,h_w_u\n1.245,80\n1.25,81\n"),
            ],
        );
        write_run(
            &runs,
            "cushion",
            "coarse",
            1.25,
            &[("profile_x11_t1.25.csv", CUSHION_PROFILE)],
        );
        write_run(
            &runs,
            "short",
            "smoke",
            0.4,
            &[("wall_probe_south_x11.csv", "t,h_w_u\n0.395,0\n0.4,0\n")],
        );
        write_run(
            &runs,
            "flume",
            "coarse",
            2.5,
            &[(
                "gates.csv",
                "gate,x,t_cross,speed\n1,2.15,0.5,9.0\n2,2.6,0.6,4.5\n3,3.05,0.7,3.5\n",
            )],
        );
        write_run(
            &runs,
            "stuck",
            "smoke",
            0.4,
            &[("gates.csv", "gate,x,t_cross,speed\n")],
        );
        let cases = from_runs(&runs, &["wide", "cushion", "short", "flume", "stuck"], None);
        let described = [(2, 4.0), (3, 4.0), (7, 5.4)];
        let read = |q, case: &str| reading(q, case, &cases, &described);
        assert_eq!(read(Quantity::AirCushion, "cushion").unwrap(), "yes");
        assert_eq!(read(Quantity::AirCushion, "wide").unwrap(), "no");
        assert_eq!(read(Quantity::FloorEpsS, "cushion").unwrap(), "0.050");
        assert_eq!(
            read(Quantity::CushionThickness, "cushion").unwrap(),
            "0.005"
        );
        assert_eq!(
            read(Quantity::CushionThickness, "wide").unwrap(),
            "0 (no cushion)"
        );
        assert_eq!(read(Quantity::FloorTheta, "cushion").unwrap(), "1.500");
        assert_eq!(read(Quantity::MaxUs, "wide").unwrap(), "4.00");
        assert_eq!(read(Quantity::FlowThickness, "wide").unwrap(), "0.025");
        assert_eq!(
            read(Quantity::FlowThicknessAbove("cushion"), "wide").unwrap(),
            "0.010"
        );
        assert_eq!(
            read(Quantity::FlowThicknessAbove("short"), "wide").unwrap_err(),
            "`short`: the smoke run ends at t = 0.40 s, before t = 1.25 s"
        );
        assert_eq!(read(Quantity::ProbeHu, "wide").unwrap(), "81");
        // a probe that stopped at 0.4 s is no reading at 1.25 s
        assert_eq!(
            read(Quantity::ProbeHu, "short").unwrap_err(),
            "the smoke run ends at t = 0.40 s, before t = 1.25 s; its last sample: 0 at t = 0.40 s"
        );
        // L1 has no described speed: the MSE is over L2 and L3, (0.5² + 0.5²)/2
        assert_eq!(
            read(Quantity::FlumeMse, "flume").unwrap(),
            "0.25 (2 of 3 gates)"
        );
        assert_eq!(
            read(Quantity::FlumeMaxGateSpeed, "flume").unwrap(),
            "9.00 (at L1)"
        );
        assert_eq!(
            read(Quantity::FlumeLastGateSpeed, "flume").unwrap(),
            "3.50 (at L3)"
        );
        assert_eq!(
            read(Quantity::FlumeMse, "stuck").unwrap_err(),
            "the smoke run's front reached no gate by t = 0.40 s"
        );
        assert_eq!(
            read(Quantity::MaxUs, "absent").unwrap_err(),
            "not in the case matrix"
        );
        // a dilute profile has no flow quantities, only its floor values
        write_run(
            &runs,
            "dilute",
            "coarse",
            1.25,
            &[(
                "profile_x11_t1.25.csv",
                "y,eps_s,u_s,theta\n0.01,0.002,4.3,1.1\n0.03,0.0,0.0,0.0\n",
            )],
        );
        let cases = from_runs(&runs, &["dilute"], None);
        let read = |q| reading(q, "dilute", &cases, &described);
        assert_eq!(
            read(Quantity::AirCushion).unwrap_err(),
            "no flow at the station: the largest εs is 2.0e-3 < 0.01"
        );
        assert_eq!(read(Quantity::FloorEpsS).unwrap(), "0.002");
        assert_eq!(read(Quantity::FloorTheta).unwrap(), "1.100");
    }
}
