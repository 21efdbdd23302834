//! What the paper reports: the numbers of shared/docs/cases.md "What the paper reports"
//! (paper §§2.2–4), a table of data; runout's reading of each is [`super::reading`], the
//! case sets of the paper's figures `figure_sets.rs`.

/// Threshold h_w^u of air-cushion formation drawn in paper Fig. 9 [1/m].
pub const CUSHION_LIMIT_H_U: f64 = 70.0;

// ---------------------------------------------------------------------------------------
// What the paper reports (shared/docs/cases.md "What the paper reports", paper §§2.2–4)
// ---------------------------------------------------------------------------------------

/// A quantity the paper reports for one case.
#[derive(Clone, Copy, Debug)]
pub enum Quantity {
    /// εs at the floor below 0.8 × the profile's peak (runout_post::metrics)
    AirCushion,
    /// εs of the floor cell at the station
    FloorEpsS,
    /// cushion thickness at the station [m]
    CushionThickness,
    /// θ of the floor cell at the station [m²/s²]
    FloorTheta,
    /// largest u_s of the station profile [m/s]
    MaxUs,
    /// flow thickness at the station [m]
    FlowThickness,
    /// flow thickness minus that of another case [m]
    FlowThicknessAbove(&'static str),
    /// h_w^u at the floor probe at t = 1.25 s [1/m]
    ProbeHu,
    /// mean square error of the gate speeds [m²/s²]
    FlumeMse,
    /// largest gate speed [m/s]
    FlumeMaxGateSpeed,
    /// speed at the last gate reached [m/s]
    FlumeLastGateSpeed,
}

impl Quantity {
    /// Table label, with the unit.
    pub fn label(self) -> String {
        match self {
            Quantity::AirCushion => "air cushion at the station".into(),
            Quantity::FloorEpsS => "εs of the floor cell".into(),
            Quantity::CushionThickness => "air-cushion thickness [m]".into(),
            Quantity::FloorTheta => "θ of the floor cell [m²/s²]".into(),
            Quantity::MaxUs => "max u_s at the station [m/s]".into(),
            Quantity::FlowThickness => "flow thickness at the station [m]".into(),
            Quantity::FlowThicknessAbove(other) => {
                format!("flow thickness minus that of `{other}` [m]")
            }
            Quantity::ProbeHu => "h_w^u at the floor probe, t = 1.25 s [1/m]".into(),
            Quantity::FlumeMse => {
                "gate-speed MSE [m²/s²] (paper: vs measured; runout: vs described)".into()
            }
            Quantity::FlumeMaxGateSpeed => "largest gate speed [m/s]".into(),
            Quantity::FlumeLastGateSpeed => "speed at the last gate reached [m/s]".into(),
        }
    }
}

/// One number (or yes/no) the paper reports.
pub struct PaperNumber {
    /// the paper's figure (panel)
    pub figure: &'static str,
    /// what is compared
    pub quantity: Quantity,
    /// runout's case
    pub case: &'static str,
    /// the paper's value, as printed
    pub paper: &'static str,
}

const fn n(
    figure: &'static str,
    quantity: Quantity,
    case: &'static str,
    paper: &'static str,
) -> PaperNumber {
    PaperNumber {
        figure,
        quantity,
        case,
        paper,
    }
}

/// Every number of cases.md "What the paper reports" and of paper §§2.2–4, by case.
pub const PAPER_NUMBERS: &[PaperNumber] = &[
    // §2.2.2, Fig. 4: Johnson–Jackson, φ and d
    n("4a", Quantity::AirCushion, "S-JJ-phi_phi=1", "yes"),
    n("4a", Quantity::AirCushion, "S-JJ-phi_phi=0.1", "yes"),
    n("4a, 10", Quantity::AirCushion, "S-JJ-phi_phi=0.01", "no"),
    n(
        "4d",
        Quantity::AirCushion,
        "S-JJ-d_d=0.0001",
        "yes (thinner for smaller d)",
    ),
    n("4d", Quantity::AirCushion, "S-JJ-d_d=0.0005", "yes"),
    n(
        "4d",
        Quantity::AirCushion,
        "S-JJ-d_d=0.001",
        "yes (thicker for larger d)",
    ),
    n("4a", Quantity::FloorEpsS, "S-JJ-phi_phi=1", "0.03"),
    n("4a", Quantity::FloorEpsS, "S-JJ-phi_phi=0.01", "0.32"),
    n(
        "4a",
        Quantity::CushionThickness,
        "S-JJ-phi_phi=1",
        "0.01–0.03 (range of Fig. 4a)",
    ),
    n(
        "4a",
        Quantity::CushionThickness,
        "S-JJ-phi_phi=0.1",
        "0.01–0.03 (range of Fig. 4a)",
    ),
    n(
        "4c",
        Quantity::FloorTheta,
        "S-JJ-phi_phi=1",
        "2.2 (highest of the φ sweep)",
    ),
    n(
        "4f",
        Quantity::FloorTheta,
        "S-JJ-d_d=0.001",
        "2.5 (highest of the d sweep)",
    ),
    n("4b", Quantity::MaxUs, "S-JJ-phi_phi=1", "8.4–8.5"),
    n("4b", Quantity::MaxUs, "S-JJ-phi_phi=0.1", "8.4–8.5"),
    n("4b", Quantity::MaxUs, "S-JJ-phi_phi=0.01", "8.4–8.5"),
    n("4e", Quantity::MaxUs, "S-JJ-d_d=0.0001", "11.45"),
    n("4e", Quantity::MaxUs, "S-JJ-d_d=0.0005", "8.4–8.5"),
    n("4e", Quantity::MaxUs, "S-JJ-d_d=0.001", "8.4–8.5"),
    // §2.2.3, Fig. 5: Jenkins, d
    n("5a", Quantity::AirCushion, "S-JEN-d_d=0.0001", "no"),
    n("5a", Quantity::AirCushion, "S-JEN-d_d=0.0005", "no"),
    n("5a", Quantity::AirCushion, "S-JEN-d_d=0.001", "no"),
    n(
        "5a",
        Quantity::FlowThickness,
        "S-JEN-d_d=0.0001",
        "0.026 (thickest of 0.020–0.026)",
    ),
    n(
        "5a",
        Quantity::FlowThickness,
        "S-JEN-d_d=0.0005",
        "0.020–0.026",
    ),
    n(
        "5a",
        Quantity::FlowThickness,
        "S-JEN-d_d=0.001",
        "0.020–0.026",
    ),
    n(
        "5b",
        Quantity::MaxUs,
        "S-JEN-d_d=0.0001",
        "8.67 (highest of 8.18–8.67)",
    ),
    n("5b", Quantity::MaxUs, "S-JEN-d_d=0.0005", "8.18–8.67"),
    n("5b", Quantity::MaxUs, "S-JEN-d_d=0.001", "8.18–8.67"),
    // §2.2.4, Fig. 7: user partial slip, h_w^u and d
    n("7a", Quantity::AirCushion, "S-PS-hu_hu=10", "no"),
    n("7a", Quantity::AirCushion, "S-PS-hu_hu=70", "yes"),
    n(
        "7a",
        Quantity::AirCushion,
        "S-PS-hu_hu=100",
        "yes (thickest)",
    ),
    n("7a", Quantity::FlowThickness, "S-PS-hu_hu=10", "0.015"),
    n("7a", Quantity::FlowThickness, "S-PS-hu_hu=100", "0.030"),
    n("7b", Quantity::MaxUs, "S-PS-hu_hu=10", "7.65"),
    n("7b", Quantity::MaxUs, "S-PS-hu_hu=100", "3.59"),
    n(
        "7c",
        Quantity::FloorTheta,
        "S-PS-hu_hu=100",
        "1.86 (highest of the h_w^u sweep)",
    ),
    n("7d", Quantity::FlowThickness, "S-PS-d_d=0.0001", "0.15"),
    n("7d", Quantity::FlowThickness, "S-PS-d_d=0.001", "0.05"),
    n("7e", Quantity::MaxUs, "S-PS-d_d=0.0001", "9.65"),
    n("7e", Quantity::MaxUs, "S-PS-d_d=0.001", "8.15"),
    // §3, Figs. 8–10: the boundary conditions compared
    n(
        "8, 10",
        Quantity::AirCushion,
        "S-RJJ",
        "yes (less developed than JJ φ = 0.1)",
    ),
    n("9", Quantity::ProbeHu, "S-JJ-phi_phi=1", "579"),
    n("9", Quantity::ProbeHu, "S-JJ-phi_phi=0.1", "156"),
    n("9", Quantity::ProbeHu, "S-JJ-phi_phi=0.01", "59"),
    n("9", Quantity::ProbeHu, "S-JEN-d_d=0.0005", "26"),
    n("9", Quantity::ProbeHu, "S-RJJ", "between 70 and 156"),
    // Appendix, Fig. 14 (horizontal channel)
    n(
        "14a",
        Quantity::FlowThicknessAbove("S-PS-cw_cw=0.1_slope=0"),
        "S-PS-cw_cw=10_slope=0",
        "0.014",
    ),
    n(
        "14a",
        Quantity::FlowThicknessAbove("S-PS-cw_cw=1_slope=0"),
        "S-PS-cw_cw=10_slope=0",
        "0.014",
    ),
    // §4, Fig. 12: the flume
    n("12", Quantity::FlumeMse, "F-JJ_phi=0.1", "0.36"),
    n("12", Quantity::FlumeMse, "F-JEN", "0.88"),
    n("12", Quantity::FlumeMse, "F-JJ_phi=0.01", "0.93"),
    n(
        "12",
        Quantity::FlumeMse,
        "F-RJJ",
        "0.53 (§4; §5 prints 0.93)",
    ),
    n("12", Quantity::FlumeMaxGateSpeed, "F-JEN", "6.5"),
    n("12", Quantity::FlumeMaxGateSpeed, "F-JJ_phi=0.1", "6.0"),
    n(
        "12",
        Quantity::FlumeMaxGateSpeed,
        "F-JJ_phi=0.01",
        "6.25 (at L6)",
    ),
    n(
        "12",
        Quantity::FlumeLastGateSpeed,
        "F-RJJ",
        "approaching 4.7",
    ),
];

#[cfg(test)]
mod tests {
    use super::super::figure_sets::*;
    use super::*;

    /// Every case named by the report, with the cases it compares against.
    fn named_cases() -> Vec<&'static str> {
        let mut names: Vec<&str> = PAPER_NUMBERS.iter().map(|p| p.case).collect();
        names.extend(PAPER_NUMBERS.iter().filter_map(|p| match p.quantity {
            Quantity::FlowThicknessAbove(other) => Some(other),
            _ => None,
        }));
        for fig in PROFILE_FIGURES {
            for row in fig.rows {
                names.extend(row.curves.iter().map(|c| c.0));
            }
        }
        names.extend(PROBE_CURVES.iter().map(|c| c.0));
        for fig in FIELD_FIGURES {
            names.extend(fig.panels.iter().map(|c| c.0));
        }
        names.extend(FLUME.iter().map(|c| c.0));
        names.push(MFIX_CASE);
        names
    }

    #[test]
    fn every_case_the_report_names_is_in_the_matrix() {
        let cases = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases");
        let matrix = runout_study::sweep::matrix(&cases).expect("the case matrix loads");
        let known: Vec<&str> = matrix.runs.iter().map(|r| r.case.name.as_str()).collect();
        for name in named_cases() {
            assert!(known.contains(&name), "`{name}` is not a case of cases/");
        }
    }
}
