//! What the paper reports and plots: the numbers of shared/docs/cases.md "What the paper
//! reports" (paper §§2.2–4) with runout's reading of each, and the case sets of its figures.

use crate::metrics::{mse_vs_described, FlowMetrics, FLOW_THRESHOLD};

use runout_post::case_data::{CaseData, Cases};
use runout_post::profile::Profile;

/// Threshold h_w^u of air-cushion formation drawn in paper Fig. 9 [1/m].
pub const CUSHION_LIMIT_H_U: f64 = 70.0;

// ---------------------------------------------------------------------------------------
// What the paper reports (shared/docs/cases.md "What the paper reports", paper §§2.2–4)
// ---------------------------------------------------------------------------------------

/// A quantity the paper reports for one case.
#[derive(Clone, Copy, Debug)]
pub enum Quantity {
    /// εs at the floor below 0.8 × the profile's peak (crate::metrics)
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

/// runout's value of `q` for `data` (the case) in the report's words, or why it is missing.
pub fn reading(
    q: Quantity,
    data: &CaseData,
    cases: &Cases,
    described: &[(usize, f64)],
) -> Result<String, String> {
    value(q, data, cases, described).map(|r| r.to_string())
}

/// runout's value of `q` for `data` (the case), or why it is missing.
pub fn value(
    q: Quantity,
    data: &CaseData,
    cases: &Cases,
    described: &[(usize, f64)],
) -> Result<Reading, String> {
    let metrics = || flow_at_station(data);
    let unknown = || "not defined for this profile".to_string();
    match q {
        Quantity::AirCushion => Ok(Reading::YesNo(metrics()?.air_cushion.ok_or_else(unknown)?)),
        Quantity::FloorEpsS => {
            let p = data.profile.as_ref().map_err(Clone::clone)?;
            Ok(Reading::number(*p.eps_s.first().ok_or_else(unknown)?, 3))
        }
        Quantity::CushionThickness => {
            let m = metrics()?;
            Ok(match m.air_cushion {
                Some(true) => Reading::number(m.cushion_thickness.ok_or_else(unknown)?, 3),
                _ => Reading::noted(0.0, 0, "no cushion".into()),
            })
        }
        Quantity::FloorTheta => {
            let p = data.profile.as_ref().map_err(Clone::clone)?;
            Ok(Reading::number(*p.theta.first().ok_or_else(unknown)?, 3))
        }
        Quantity::MaxUs => Ok(Reading::number(metrics()?.max_u_s.ok_or_else(unknown)?, 2)),
        Quantity::FlowThickness => Ok(Reading::number(
            metrics()?.flow_thickness.ok_or_else(unknown)?,
            3,
        )),
        Quantity::FlowThicknessAbove(other) => {
            let own = metrics()?.flow_thickness.ok_or_else(unknown)?;
            let theirs = flow_at_station(&cases.get(other))
                .map_err(|e| format!("`{other}`: {e}"))?
                .flow_thickness
                .ok_or_else(unknown)?;
            Ok(Reading::number(own - theirs, 3))
        }
        Quantity::ProbeHu => {
            let (t, h) = data.probe_at(data.station_time)?;
            match data
                .run
                .as_ref()
                .ok()
                .and_then(|r| r.ended_before(data.station_time))
            {
                Some(why) => Err(format!("{why}; its last sample: {h:.0} at t = {t:.2} s")),
                None => Ok(Reading::number(h, 0)),
            }
        }
        Quantity::FlumeMse => {
            let (e, gates) = mse_vs_described(&data.gate_pairs()?, described)
                .ok_or_else(|| data.no_gate_reached())?;
            Ok(Reading::noted(
                e,
                2,
                format!("{gates} of {} gates", described.len()),
            ))
        }
        Quantity::FlumeMaxGateSpeed => {
            let gates = data.gates.as_ref().map_err(Clone::clone)?;
            let g = gates
                .iter()
                .max_by(|a, b| a.speed.total_cmp(&b.speed))
                .ok_or_else(|| data.no_gate_reached())?;
            Ok(Reading::noted(g.speed, 2, format!("at L{}", g.gate)))
        }
        Quantity::FlumeLastGateSpeed => {
            let gates = data.gates.as_ref().map_err(Clone::clone)?;
            let g = gates
                .iter()
                .max_by_key(|g| g.gate)
                .ok_or_else(|| data.no_gate_reached())?;
            Ok(Reading::noted(g.speed, 2, format!("at L{}", g.gate)))
        }
    }
}

// ---------------------------------------------------------------------------------------
// Figures
// ---------------------------------------------------------------------------------------

/// A profile variable of the station (the columns of paper Figs. 4, 5, 7, 13, 14).
#[derive(Clone, Copy, Debug)]
pub enum ProfileVar {
    /// εs
    EpsS,
    /// u_s
    Us,
    /// θ
    Theta,
}

impl ProfileVar {
    /// Axis label.
    pub fn axis(self) -> &'static str {
        match self {
            ProfileVar::EpsS => "eps_s [-]",
            ProfileVar::Us => "u_s [m/s]",
            ProfileVar::Theta => "theta [m2/s2]",
        }
    }

    /// The profile's values of this variable.
    pub fn values(self, p: &Profile) -> &[f64] {
        match self {
            ProfileVar::EpsS => &p.eps_s,
            ProfileVar::Us => &p.u_s,
            ProfileVar::Theta => &p.theta,
        }
    }
}

/// One row of panels: one set of cases, one panel per variable.
pub struct ProfileRow {
    /// panel title
    pub title: &'static str,
    /// (case, legend label)
    pub curves: &'static [(&'static str, &'static str)],
}

/// A figure of station profiles at t = 1.25 s.
pub struct ProfileFigure {
    /// the paper's figure number
    pub number: &'static str,
    /// SVG file name
    pub file: &'static str,
    /// what it shows, for the caption
    pub what: &'static str,
    /// rows of panels
    pub rows: &'static [ProfileRow],
    /// one panel per variable in each row
    pub vars: &'static [ProfileVar],
}

const ALL_VARS: &[ProfileVar] = &[ProfileVar::EpsS, ProfileVar::Us, ProfileVar::Theta];

const JJ_PHI: &[(&str, &str)] = &[
    ("S-JJ-phi_phi=1", "phi = 1"),
    ("S-JJ-phi_phi=0.1", "phi = 0.1"),
    ("S-JJ-phi_phi=0.01", "phi = 0.01"),
];
const JJ_D: &[(&str, &str)] = &[
    ("S-JJ-d_d=0.0001", "d = 0.1 mm"),
    ("S-JJ-d_d=0.0005", "d = 0.5 mm"),
    ("S-JJ-d_d=0.001", "d = 1 mm"),
];
const JEN_D: &[(&str, &str)] = &[
    ("S-JEN-d_d=0.0001", "d = 0.1 mm"),
    ("S-JEN-d_d=0.0005", "d = 0.5 mm"),
    ("S-JEN-d_d=0.001", "d = 1 mm"),
];
const PS_HU: &[(&str, &str)] = &[
    ("S-PS-hu_hu=1", "h_u = 1 1/m"),
    ("S-PS-hu_hu=10", "h_u = 10 1/m"),
    ("S-PS-hu_hu=40", "h_u = 40 1/m"),
    ("S-PS-hu_hu=70", "h_u = 70 1/m"),
    ("S-PS-hu_hu=100", "h_u = 100 1/m"),
];
const PS_D: &[(&str, &str)] = &[
    ("S-PS-d_d=0.0001", "d = 0.1 mm"),
    ("S-PS-d_d=0.0005", "d = 0.5 mm"),
    ("S-PS-d_d=0.001", "d = 1 mm"),
];
const BCS_D05: &[(&str, &str)] = &[
    ("S-JJ-phi_phi=1", "JJ phi = 1"),
    ("S-JJ-phi_phi=0.1", "JJ phi = 0.1"),
    ("S-JJ-phi_phi=0.01", "JJ phi = 0.01"),
    ("S-RJJ", "revisited JJ"),
    ("S-JEN-d_d=0.0005", "Jenkins"),
    ("S-PS-hu_hu=10", "user h_u = 10"),
    ("S-PS-hu_hu=70", "user h_u = 70"),
    ("S-PS-hu_hu=100", "user h_u = 100"),
];
const PS_HORIZONTAL: &[(&str, &str)] = &[
    ("S-PS-htheta_htheta=1_slope=0", "h_theta = 1"),
    ("S-PS-htheta_htheta=10_slope=0", "h_theta = 10"),
    ("S-PS-htheta_htheta=100_slope=0", "h_theta = 100"),
    ("S-PS-cw_cw=0.1_slope=0", "c_w = 0.1"),
    ("S-PS-cw_cw=1_slope=0", "c_w = 1"),
    ("S-PS-cw_cw=10_slope=0", "c_w = 10"),
];
const PS_SLOPED: &[(&str, &str)] = &[
    ("S-PS-htheta_htheta=1_slope=40", "h_theta = 1"),
    ("S-PS-htheta_htheta=10_slope=40", "h_theta = 10"),
    ("S-PS-htheta_htheta=100_slope=40", "h_theta = 100"),
    ("S-PS-cw_cw=0.1_slope=40", "c_w = 0.1"),
    ("S-PS-cw_cw=1_slope=40", "c_w = 1"),
    ("S-PS-cw_cw=10_slope=40", "c_w = 10"),
];

/// The profile figures (cases.md family S table, "paper figure" column).
pub const PROFILE_FIGURES: &[ProfileFigure] = &[
    ProfileFigure {
        number: "4",
        file: "fig4.svg",
        what: "Johnson–Jackson floor: (a–c) φ ∈ {1, 0.1, 0.01} at d = 0.5 mm; (d–f) \
               d ∈ {0.1, 0.5, 1} mm at φ = 0.1",
        rows: &[
            ProfileRow {
                title: "Johnson-Jackson, d = 0.5 mm",
                curves: JJ_PHI,
            },
            ProfileRow {
                title: "Johnson-Jackson, phi = 0.1",
                curves: JJ_D,
            },
        ],
        vars: ALL_VARS,
    },
    ProfileFigure {
        number: "5",
        file: "fig5.svg",
        what: "Jenkins floor, d ∈ {0.1, 0.5, 1} mm",
        rows: &[ProfileRow {
            title: "Jenkins",
            curves: JEN_D,
        }],
        vars: ALL_VARS,
    },
    ProfileFigure {
        number: "7",
        file: "fig7.svg",
        what: "user partial slip (h_w^θ = 10, c_w = 0.1): (a–c) h_w^u ∈ {1, 10, 40, 70, 100} m⁻¹ \
               at d = 0.5 mm (the paper names 10, 70, 100); (d–f) d ∈ {0.1, 0.5, 1} mm at \
               h_w^u = 10 m⁻¹",
        rows: &[
            ProfileRow {
                title: "user partial slip, d = 0.5 mm",
                curves: PS_HU,
            },
            ProfileRow {
                title: "user partial slip, h_u = 10 1/m",
                curves: PS_D,
            },
        ],
        vars: ALL_VARS,
    },
    ProfileFigure {
        number: "8",
        file: "fig8.svg",
        what: "εs for the floor conditions compared at d = 0.5 mm (JJ = Johnson–Jackson)",
        rows: &[ProfileRow {
            title: "floor conditions, d = 0.5 mm",
            curves: BCS_D05,
        }],
        vars: &[ProfileVar::EpsS],
    },
    ProfileFigure {
        number: "13",
        file: "fig13.svg",
        what: "user partial slip, h_w^u = 10 m⁻¹, d ∈ {0.1, 0.5, 1} mm (the same runs as \
               Fig. 7d–f: runout has one sweep, S-PS-d, for both)",
        rows: &[ProfileRow {
            title: "user partial slip, h_u = 10 1/m",
            curves: PS_D,
        }],
        vars: ALL_VARS,
    },
    ProfileFigure {
        number: "14",
        file: "fig14.svg",
        what: "user partial slip (h_w^u = 10, d = 0.5 mm), h_w^θ ∈ {1, 10, 100} at c_w = 0.1 and \
               c_w ∈ {0.1, 1, 10} at h_w^θ = 10: (a–c) the horizontal channel the paper plots; \
               (d–f) the 40° slope it ran but did not plot (h_w^θ = 10 and c_w = 0.1 are the \
               same case, twice)",
        rows: &[
            ProfileRow {
                title: "user partial slip, horizontal",
                curves: PS_HORIZONTAL,
            },
            ProfileRow {
                title: "user partial slip, slope 40 deg",
                curves: PS_SLOPED,
            },
        ],
        vars: ALL_VARS,
    },
];

/// Paper Fig. 9: the floor probe's h_w^u against time, d = 0.5 mm.
pub const PROBE_CURVES: &[(&str, &str)] = &[
    ("S-JJ-phi_phi=1", "JJ phi = 1"),
    ("S-JJ-phi_phi=0.1", "JJ phi = 0.1"),
    ("S-JJ-phi_phi=0.01", "JJ phi = 0.01"),
    ("S-RJJ", "revisited JJ"),
    ("S-JEN-d_d=0.0005", "Jenkins"),
];

/// A figure of gas-volume-fraction maps near the station (paper Figs. 6 and 10).
pub struct FieldFigure {
    /// the paper's figure number
    pub number: &'static str,
    /// SVG file name
    pub file: &'static str,
    /// what it shows, for the caption
    pub what: &'static str,
    /// (case, panel title), top to bottom
    pub panels: &'static [(&'static str, &'static str)],
}

/// Paper Figs. 6 (user partial slip, h_w^u) and 10 (the state-dependent floors).
pub const FIELD_FIGURES: &[FieldFigure] = &[
    FieldFigure {
        number: "6",
        file: "fig6.svg",
        what: "user partial slip (h_w^θ = 10, c_w = 0.1, d = 0.5 mm) at h_w^u ∈ {1, 10, 40, \
               70, 100} m⁻¹ (the paper shows 10, 70 and 100)",
        panels: &[
            ("S-PS-hu_hu=1", "h_w^u = 1 1/m"),
            ("S-PS-hu_hu=10", "h_w^u = 10 1/m"),
            ("S-PS-hu_hu=40", "h_w^u = 40 1/m"),
            ("S-PS-hu_hu=70", "h_w^u = 70 1/m"),
            ("S-PS-hu_hu=100", "h_w^u = 100 1/m"),
        ],
    },
    FieldFigure {
        number: "10",
        file: "fig10.svg",
        what: "Johnson–Jackson at φ ∈ {1, 0.1, 0.01}, revisited Johnson–Jackson and Jenkins, \
               d = 0.5 mm",
        panels: &[
            ("S-JJ-phi_phi=1", "JJ phi = 1"),
            ("S-JJ-phi_phi=0.1", "JJ phi = 0.1"),
            ("S-JJ-phi_phi=0.01", "JJ phi = 0.01"),
            ("S-RJJ", "revisited JJ"),
            ("S-JEN-d_d=0.0005", "Jenkins"),
        ],
    },
];

/// The flume cases: (case, label, the paper's MFIX MSE against the measured speeds).
pub const FLUME: &[(&str, &str, &str)] = &[
    ("F-JJ_phi=0.1", "JJ phi = 0.1", "0.36"),
    ("F-JJ_phi=0.01", "JJ phi = 0.01", "0.93"),
    ("F-JEN", "Jenkins", "0.88"),
    ("F-RJJ", "revisited JJ", "0.53 (§4; §5 prints 0.93)"),
];

/// The flume cases with the channel's side walls, 0.30 m apart with the floor's condition
/// (docs/model.md §8; issue 23): (case, label, the paper's MSE: none, it has no side walls).
pub const FLUME_SIDEWALLS: &[(&str, &str, &str)] = &[
    (
        "FSW-JJ_phi=0.1",
        "JJ phi = 0.1, side walls",
        "— (no side walls in the paper)",
    ),
    (
        "FSW-JJ_phi=0.01",
        "JJ phi = 0.01, side walls",
        "— (no side walls in the paper)",
    ),
    (
        "FSW-JEN",
        "Jenkins, side walls",
        "— (no side walls in the paper)",
    ),
    (
        "FSW-RJJ",
        "revisited JJ, side walls",
        "— (no side walls in the paper)",
    ),
];

/// The family-M case (shared/docs/cases.md).
pub const MFIX_CASE: &str = "M-JJ";

/// Family M: MFIX's (t, front x, mean u_s) of cases.md.
pub const MFIX_SLIDE: &[(f64, f64, f64)] =
    &[(0.3, 1.04, 1.25), (0.5, 1.66, 1.97), (0.8, 2.92, 3.01)];

#[cfg(test)]
mod tests {
    use super::*;
    use runout_post::fixture::*;

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
        let cases = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases");
        let matrix = crate::sweep::matrix(&cases).expect("the case matrix loads");
        let known: Vec<&str> = matrix.runs.iter().map(|r| r.case.name.as_str()).collect();
        for name in named_cases() {
            assert!(known.contains(&name), "`{name}` is not a case of cases/");
        }
    }

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
        let cases = Cases::load(&runs, ["wide", "cushion", "short", "flume", "stuck"], None);
        let described = [(2, 4.0), (3, 4.0), (7, 5.4)];
        let read = |q, case: &str| reading(q, &cases.get(case), &cases, &described);
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
        let cases = Cases::load(&runs, ["dilute"], None);
        let read = |q| reading(q, &cases.get("dilute"), &cases, &described);
        assert_eq!(
            read(Quantity::AirCushion).unwrap_err(),
            "no flow at the station: the largest εs is 2.0e-3 < 0.01"
        );
        assert_eq!(read(Quantity::FloorEpsS).unwrap(), "0.002");
        assert_eq!(read(Quantity::FloorTheta).unwrap(), "1.100");
    }
}
