//! The numbers the paper reports at its station and floor probe, read from one run of the
//! ladder exactly as `cargo xtask report` reads them ([`crate::reading::value`] on the
//! run's [`CaseData`]): the air cushion (yes/no) and its thickness, the flow thickness, εs and
//! θ of the floor cell and the largest u_s at the station at the profile time, and h_w^u at
//! the floor probe then.

use std::path::Path;

use runout_case::Fidelity;
use runout_post::case_data::CaseData;
use runout_post::chosen::Run;
use runout_post::folder::read_summary;

use super::ladder::Level;
use super::quantity::Quantity;
use crate::paper::Quantity as PaperQuantity;
use crate::reading::{value, Reading};
use crate::records::Records;

/// The station and probe numbers of one run, each with why it is missing.
#[derive(Clone, Debug, Default)]
pub struct StationValues {
    /// whether the station profile shows an air cushion
    pub air_cushion: Option<Result<bool, String>>,
    /// (quantity, value) for every station quantity
    pub values: Vec<(Quantity, Result<f64, String>)>,
}

impl StationValues {
    /// The value of `q`, if the run has it.
    pub fn get(&self, q: Quantity) -> Option<f64> {
        self.values
            .iter()
            .find(|(k, _)| *k == q)
            .and_then(|(_, v)| v.as_ref().ok().copied())
    }
}

/// The report's quantity behind a station quantity of the ladder.
fn paper_quantity(q: Quantity) -> Option<PaperQuantity> {
    Some(match q {
        Quantity::CushionThickness => PaperQuantity::CushionThickness,
        Quantity::FlowThickness => PaperQuantity::FlowThickness,
        Quantity::FloorEpsS => PaperQuantity::FloorEpsS,
        Quantity::FloorTheta => PaperQuantity::FloorTheta,
        Quantity::MaxUs => PaperQuantity::MaxUs,
        Quantity::ProbeHu => PaperQuantity::ProbeHu,
        _ => return None,
    })
}

/// The fidelity a level's run is described as in the report's messages ("the coarse run
/// ends at …"): the preset it uses, else paper.
fn described_fidelity(level: Level) -> Fidelity {
    match level {
        Level::Tiny | Level::Smoke => Fidelity::Smoke,
        Level::Coarse => Fidelity::Coarse,
        Level::Half | Level::Paper | Level::Finer => Fidelity::Paper,
    }
}

/// What the report reads of the finished run in `dir` (every part missing, with the reason,
/// if the folder holds no finished run).
pub fn case_data(dir: &Path, level: Level) -> CaseData {
    let run = match read_summary(dir) {
        Some(Ok(summary)) => Ok(Run {
            fidelity: described_fidelity(level),
            dir: dir.to_path_buf(),
            summary,
        }),
        Some(Err(e)) => Err(format!("{level} run: {e}")),
        None => Err(format!("no finished {level} run")),
    };
    match run {
        Ok(run) => CaseData::of_run(run),
        Err(why) => CaseData::missing(&why),
    }
}

/// The name a ladder level's run has in its one-run [`Records`].
const LEVEL_RUN: &str = "level";

/// The station and probe numbers of `data`, as the report reads them.
pub fn station_values(data: &CaseData) -> StationValues {
    let records = Records::of_one(LEVEL_RUN, data);
    let number = |q: PaperQuantity| match value(q, LEVEL_RUN, &records, &[])? {
        Reading::Number { value, .. } => Ok(value),
        Reading::YesNo(_) => Err("a yes/no reading".to_string()),
    };
    StationValues {
        air_cushion: Some(
            value(PaperQuantity::AirCushion, LEVEL_RUN, &records, &[]).and_then(|r| match r {
                Reading::YesNo(b) => Ok(b),
                Reading::Number { .. } => Err("not a yes/no reading".to_string()),
            }),
        ),
        values: Quantity::ALL
            .into_iter()
            .filter_map(|q| Some((q, number(paper_quantity(q)?))))
            .collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_post::fixture::*;

    #[test]
    fn a_run_folder_gives_the_reports_station_numbers() {
        let tmp = TempDir::new("station");
        let runs = tmp.0.join("runs");
        write_run(
            &runs,
            "case",
            "half-upwind",
            1.25,
            &[
                ("profile_x11_t1.25.csv", CUSHION_PROFILE),
                ("wall_probe_south_x11.csv", "t,h_w_u\n1.2,100\n1.25,150\n"),
            ],
        );
        let data = case_data(&runs.join("case").join("half-upwind"), Level::Half);
        let s = station_values(&data);
        let report = data.profile.as_ref().unwrap().metrics();
        assert_eq!(s.air_cushion, Some(Ok(true)));
        assert_eq!(s.get(Quantity::CushionThickness), report.cushion_thickness);
        assert_eq!(s.get(Quantity::FlowThickness), report.flow_thickness);
        assert_eq!(s.get(Quantity::MaxUs), report.max_u_s);
        assert_eq!(s.get(Quantity::FloorEpsS), Some(0.05));
        assert_eq!(s.get(Quantity::ProbeHu), Some(150.0));
        let missing = station_values(&case_data(&runs.join("none"), Level::Paper));
        assert!(missing.get(Quantity::MaxUs).is_none());
    }
}
