//! A [`RunRecord`] as one row of the ledger's CSV, and back: a fixed column order
//! ([`columns`]), numbers written with Rust's shortest round-trip form (`{:?}`) so a row
//! reads back to the same `f64`, an empty cell where the run has no value. Rows are read
//! by column name, so a ledger written before a column existed still reads (the column is
//! empty).

use std::collections::HashMap;

use runout_case::Fidelity;

use super::record::{RunRecord, Source, Station, BULK_TIMES, GATES};

/// The identifying columns, in order.
const IDENTITY: [&str; 13] = [
    "case",
    "fidelity",
    "nx",
    "ny",
    "end_time_s",
    "status",
    "solver",
    "date",
    "steps",
    "rejected_steps",
    "outer_iterations",
    "wall_time_s",
    "station_time_s",
];

/// The station and probe columns, in order.
const STATION: [&str; 9] = [
    "peak_eps_s",
    "floor_eps_s",
    "floor_theta",
    "air_cushion",
    "cushion_thickness_m",
    "flow_thickness_m",
    "max_u_s",
    "probe_t_s",
    "probe_h_wu",
];

/// Every column of a ledger row, in the order written.
pub fn columns() -> Vec<String> {
    let mut c: Vec<String> = IDENTITY
        .iter()
        .chain(&STATION)
        .map(|s| s.to_string())
        .collect();
    c.extend((1..=GATES).map(|g| format!("gate_L{g}_speed")));
    for t in BULK_TIMES {
        c.push(format!("front_x_t{t}"));
        c.push(format!("mean_u_s_t{t}"));
    }
    c.push("front_x_station".into());
    c.push("mean_u_s_station".into());
    c.push("front_x_end".into());
    c.push("mean_u_s_end".into());
    c
}

/// A number as written: the shortest form that reads back to the same `f64`.
fn num(v: f64) -> String {
    format!("{v:?}")
}

fn opt(v: Option<f64>) -> String {
    v.map_or(String::new(), num)
}

fn yes_no(v: Option<bool>) -> String {
    v.map_or(String::new(), |b| if b { "yes" } else { "no" }.into())
}

/// The record as cells in [`columns`] order.
pub fn to_row(r: &RunRecord) -> Vec<String> {
    let mut row = vec![
        r.case.clone(),
        r.fidelity.to_string(),
        r.cells.0.to_string(),
        r.cells.1.to_string(),
        num(r.end_time),
        r.status.clone(),
        r.solver.clone(),
        r.date.clone(),
        r.steps.to_string(),
        r.rejected_steps.to_string(),
        r.outer_iterations.to_string(),
        num(r.wall_time),
        num(r.station_time),
    ];
    let s = r.station.as_ref().ok();
    row.extend([
        opt(s.map(|s| s.peak_eps_s)),
        opt(s.map(|s| s.floor_eps_s)),
        opt(s.map(|s| s.floor_theta)),
        yes_no(s.and_then(|s| s.air_cushion)),
        opt(s.and_then(|s| s.cushion_thickness)),
        opt(s.and_then(|s| s.flow_thickness)),
        opt(s.and_then(|s| s.max_u_s)),
        opt(r.probe.as_ref().ok().map(|p| p.0)),
        opt(r.probe.as_ref().ok().map(|p| p.1)),
    ]);
    let gates = r.gates.as_ref().ok();
    row.extend(
        (1..=GATES)
            .map(|g| opt(gates.and_then(|list| list.iter().find(|p| p.0 == g).map(|p| p.1)))),
    );
    for b in r.bulk.iter().chain([&r.bulk_station, &r.bulk_end]) {
        let b = b.as_ref().ok();
        row.push(opt(b.map(|b| b.0)));
        row.push(opt(b.map(|b| b.1)));
    }
    row
}

/// The cells of one CSV row by column name.
pub struct Cells<'a> {
    by_name: HashMap<&'a str, &'a str>,
}

impl<'a> Cells<'a> {
    /// Pairs a row with its header.
    pub fn new(header: &'a csv::StringRecord, row: &'a csv::StringRecord) -> Cells<'a> {
        Cells {
            by_name: header.iter().zip(row.iter()).collect(),
        }
    }

    /// The text of a column, empty if the column is absent.
    fn text(&self, name: &str) -> &'a str {
        self.by_name.get(name).copied().unwrap_or("").trim()
    }

    /// A required value.
    fn required<T: std::str::FromStr>(&self, name: &str) -> Result<T, String> {
        self.text(name)
            .parse()
            .map_err(|_| format!("column `{name}`: `{}` is not a value", self.text(name)))
    }

    /// An optional number: empty is `None`.
    fn number(&self, name: &str) -> Result<Option<f64>, String> {
        match self.text(name) {
            "" => Ok(None),
            t => t
                .parse()
                .map(Some)
                .map_err(|_| format!("column `{name}`: `{t}` is not a number")),
        }
    }

    /// An optional yes/no: empty is `None`.
    fn yes_no(&self, name: &str) -> Result<Option<bool>, String> {
        match self.text(name) {
            "" => Ok(None),
            "yes" => Ok(Some(true)),
            "no" => Ok(Some(false)),
            t => Err(format!("column `{name}`: `{t}` is not yes or no")),
        }
    }
}

/// The station of a row; `None` when its profile columns are empty.
fn station_of(c: &Cells) -> Result<Option<Station>, String> {
    let (Some(peak_eps_s), Some(floor_eps_s), Some(floor_theta)) = (
        c.number("peak_eps_s")?,
        c.number("floor_eps_s")?,
        c.number("floor_theta")?,
    ) else {
        return Ok(None);
    };
    Ok(Some(Station {
        peak_eps_s,
        floor_eps_s,
        floor_theta,
        air_cushion: c.yes_no("air_cushion")?,
        cushion_thickness: c.number("cushion_thickness_m")?,
        flow_thickness: c.number("flow_thickness_m")?,
        max_u_s: c.number("max_u_s")?,
    }))
}

/// A (front x, mean u_s) pair of two columns, or why the row has none.
fn bulk_pair(
    c: &Cells,
    front: &str,
    mean: &str,
    why: impl Fn() -> String,
) -> Result<Result<(f64, f64), String>, String> {
    Ok(match (c.number(front)?, c.number(mean)?) {
        (Some(x), Some(u)) => Ok((x, u)),
        _ => Err(why()),
    })
}

/// The record of a ledger row; an empty cell becomes a value the run does not have, with
/// the reason rebuilt from the row.
pub fn from_row(c: &Cells) -> Result<RunRecord, String> {
    let fidelity: Fidelity = c.text("fidelity").parse()?;
    let mut r = RunRecord {
        case: c.text("case").to_string(),
        fidelity,
        cells: (c.required("nx")?, c.required("ny")?),
        end_time: c.required("end_time_s")?,
        status: c.text("status").to_string(),
        solver: c.text("solver").to_string(),
        date: c.text("date").to_string(),
        steps: c.required("steps")?,
        rejected_steps: c.required("rejected_steps")?,
        outer_iterations: c.required("outer_iterations")?,
        wall_time: c.required("wall_time_s")?,
        station_time: c.required("station_time_s")?,
        station: Err(String::new()),
        probe: Err(String::new()),
        gates: Ok(Vec::new()),
        bulk: Vec::new(),
        bulk_station: Err(String::new()),
        bulk_end: Err(String::new()),
        source: Source::Ledger,
    };
    let at = r.station_time;
    let ended = r.clone();
    let missing = |what: &str, t: f64| {
        ended
            .ended_before(t)
            .unwrap_or_else(|| format!("the {fidelity} run's ledger row has no {what}"))
    };
    r.station = station_of(c)?.ok_or_else(|| missing("station profile", at));
    r.probe = match (c.number("probe_t_s")?, c.number("probe_h_wu")?) {
        (Some(t), Some(h)) => Ok((t, h)),
        _ => Err(format!(
            "the {fidelity} run's ledger row has no floor-probe sample at or before t = {at:.4} s"
        )),
    };
    let mut gates = Vec::new();
    for g in 1..=GATES {
        if let Some(v) = c.number(&format!("gate_L{g}_speed"))? {
            gates.push((g, v));
        }
    }
    r.gates = Ok(gates);
    let mut bulk = Vec::new();
    for t in BULK_TIMES {
        let (front, mean) = (format!("front_x_t{t}"), format!("mean_u_s_t{t}"));
        bulk.push(bulk_pair(c, &front, &mean, || {
            missing(&format!("bulk sample at t = {t} s"), t)
        })?);
    }
    r.bulk_station = bulk_pair(c, "front_x_station", "mean_u_s_station", || {
        missing("bulk sample at the station time", at)
    })?;
    r.bulk_end = bulk_pair(c, "front_x_end", "mean_u_s_end", || {
        format!("the {fidelity} run's ledger row has no bulk sample at its end")
    })?;
    r.bulk = bulk;
    Ok(r)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A record with every value, at awkward f64s.
    fn full() -> RunRecord {
        RunRecord {
            case: "S-JJ-phi_phi=0.1".into(),
            fidelity: Fidelity::Paper,
            cells: (1000, 90),
            end_time: 1.5356,
            status: "completed".into(),
            solver: "v0.2.0-41-gfbf3b09".into(),
            date: "2026-12-06".into(),
            steps: 1572,
            rejected_steps: 3,
            outer_iterations: 18_001,
            wall_time: 7_050.123_456_789,
            station_time: 1.5356,
            station: Ok(Station {
                peak_eps_s: 0.6 - 1e-17,
                floor_eps_s: 0.1 + 0.2,
                floor_theta: 1.0 / 3.0,
                air_cushion: Some(true),
                cushion_thickness: Some(0.005_000_000_000_001),
                flow_thickness: Some(2.0e-2),
                max_u_s: Some(8.351_234_567_890_123),
            }),
            probe: Ok((1.535_000_000_000_000_1, 2_221.000_000_000_5)),
            gates: Ok(vec![(1, 9.0), (3, 3.5e-300), (7, 5.4)]),
            bulk: vec![
                Ok((1.059, 1.25)),
                Err("x".into()),
                Ok((2.897, f64::MIN_POSITIVE)),
            ],
            bulk_station: Ok((13.0, 4.1)),
            bulk_end: Ok((13.0, 4.1)),
            source: Source::Ledger,
        }
    }

    /// Writes rows through the csv crate and reads them back.
    fn round_trip(records: &[RunRecord]) -> Vec<RunRecord> {
        let mut w = csv::Writer::from_writer(Vec::new());
        w.write_record(columns()).unwrap();
        for r in records {
            w.write_record(to_row(r)).unwrap();
        }
        let bytes = w.into_inner().unwrap();
        let mut rd = csv::Reader::from_reader(bytes.as_slice());
        let header = rd.headers().unwrap().clone();
        rd.records()
            .map(|row| from_row(&Cells::new(&header, &row.unwrap())).unwrap())
            .collect()
    }

    #[test]
    fn a_record_reads_back_bit_for_bit() {
        let r = full();
        let back = round_trip(std::slice::from_ref(&r)).remove(0);
        assert_eq!(back.station, r.station);
        assert_eq!(back.probe, r.probe);
        assert_eq!(back.gates, r.gates);
        assert_eq!(back.bulk[0], r.bulk[0]);
        assert_eq!(back.bulk[2], r.bulk[2]);
        assert_eq!(back.bulk_station, r.bulk_station);
        assert_eq!(back.bulk_end, r.bulk_end);
        assert!(back.bulk[1].is_err());
        // everything else, with the rebuilt reason in place of the original one
        let mut expect = r.clone();
        expect.bulk[1] = back.bulk[1].clone();
        assert_eq!(back, expect);
        assert_eq!(
            to_row(&back),
            to_row(&r),
            "the row is the same when written again"
        );
        assert_eq!(to_row(&r).len(), columns().len());
    }

    #[test]
    fn missing_values_read_back_missing_with_a_reason() {
        let mut r = full();
        r.end_time = 0.4;
        r.status = "diverged".into();
        r.station = Err("gone".into());
        r.probe = Err("gone".into());
        r.gates = Err("the smoke run has no gates.csv".into());
        r.bulk = vec![Err("a".into()), Err("b".into()), Err("c".into())];
        r.bulk_station = Err("d".into());
        r.bulk_end = Err("e".into());
        let back = round_trip(&[r]).remove(0);
        assert_eq!(
            back.station.unwrap_err(),
            "the paper run ends at t = 0.40 s (diverged), before t = 1.5356 s"
        );
        assert_eq!(
            back.probe.unwrap_err(),
            "the paper run's ledger row has no floor-probe sample at or before t = 1.5356 s"
        );
        assert_eq!(back.gates, Ok(Vec::new()));
        assert_eq!(
            back.bulk[0].as_ref().unwrap_err(),
            "the paper run's ledger row has no bulk sample at t = 0.3 s"
        );
    }

    #[test]
    fn a_row_without_later_columns_still_reads() {
        let data = "case,fidelity,nx,ny,end_time_s,status,solver,date,steps,rejected_steps,\
                    outer_iterations,wall_time_s,station_time_s,floor_eps_s\n\
                    A,coarse,10,4,1.25,completed,unknown,2026-12-06,10,0,50,1.0,1.25,0.5\n";
        let mut rd = csv::Reader::from_reader(data.as_bytes());
        let header = rd.headers().unwrap().clone();
        let row = rd.records().next().unwrap().unwrap();
        let r = from_row(&Cells::new(&header, &row)).unwrap();
        assert_eq!(r.cells, (10, 4));
        assert!(r.station.is_err(), "no peak εs: no station");
        assert_eq!(r.gates, Ok(Vec::new()));
    }
}
