//! What is compared: the quantities (the paper's station and probe numbers, station
//! profiles, gate speeds, front position and mean speed against time), where each comes
//! from, and what one level of a ladder gives.

use runout_case::Case;

use runout_post::profile::Profile;

use super::station::StationValues;

/// The quantities compared.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// air-cushion thickness at the station (0 without a cushion) [m]
    CushionThickness,
    /// flow thickness at the station [m]
    FlowThickness,
    /// εs of the floor cell at the station
    FloorEpsS,
    /// θ of the floor cell at the station [m²/s²]
    FloorTheta,
    /// largest u_s of the station profile [m/s]
    MaxUs,
    /// h_w^u at the floor probe at the profile time [1/m]
    ProbeHu,
    /// εs at the station
    EpsS,
    /// u_s at the station
    UsS,
    /// θ at the station
    Theta,
    /// front speed at the gates
    GateSpeed,
    /// whole-cell front position against time (bulk monitor)
    FrontPosition,
    /// εs-weighted mean solids speed against time (bulk monitor)
    MeanSpeed,
}

/// Where a quantity comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Source {
    /// one number of the station profile or the floor probe, read as the report reads it
    Station,
    /// the station profile
    Profile,
    /// gates.csv
    Gates,
    /// bulk.csv
    History,
}

impl Quantity {
    /// Every quantity.
    pub const ALL: [Quantity; 12] = [
        Quantity::CushionThickness,
        Quantity::FlowThickness,
        Quantity::FloorEpsS,
        Quantity::FloorTheta,
        Quantity::MaxUs,
        Quantity::ProbeHu,
        Quantity::EpsS,
        Quantity::UsS,
        Quantity::Theta,
        Quantity::GateSpeed,
        Quantity::FrontPosition,
        Quantity::MeanSpeed,
    ];

    /// Name in files and the CSV.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::CushionThickness => "cushion_thickness",
            Quantity::FlowThickness => "flow_thickness",
            Quantity::FloorEpsS => "floor_eps_s",
            Quantity::FloorTheta => "floor_theta",
            Quantity::MaxUs => "max_u_s",
            Quantity::ProbeHu => "probe_h_w_u",
            Quantity::EpsS => "eps_s",
            Quantity::UsS => "u_s",
            Quantity::Theta => "theta",
            Quantity::GateSpeed => "gate_speed",
            Quantity::FrontPosition => "front_x",
            Quantity::MeanSpeed => "mean_u_s",
        }
    }

    /// Heading in tables and figures.
    pub(super) fn heading(self) -> &'static str {
        match self {
            Quantity::CushionThickness => "cushion thickness [m]",
            Quantity::FlowThickness => "flow thickness [m]",
            Quantity::FloorEpsS => "floor εs",
            Quantity::FloorTheta => "floor θ [m²/s²]",
            Quantity::MaxUs => "max u_s [m/s]",
            Quantity::ProbeHu => "h_w^u at the probe [1/m]",
            Quantity::EpsS => "εs profile L1/range",
            Quantity::UsS => "u_s profile L1/range",
            Quantity::Theta => "θ profile L1/range",
            Quantity::GateSpeed => "gate speeds RMS [m/s]",
            Quantity::FrontPosition => "front x(t) RMS [m]",
            Quantity::MeanSpeed => "mean u_s(t) RMS [m/s]",
        }
    }

    /// The primary norm's name in the CSV.
    pub(super) fn norm(self) -> &'static str {
        match self {
            Quantity::GateSpeed | Quantity::MeanSpeed => "rms_m_per_s",
            Quantity::FrontPosition => "rms_m",
            Quantity::CushionThickness | Quantity::FlowThickness => "abs_m",
            Quantity::FloorEpsS => "abs",
            Quantity::FloorTheta => "abs_m2_per_s2",
            Quantity::MaxUs => "abs_m_per_s",
            Quantity::ProbeHu => "abs_per_m",
            _ => "l1_over_range",
        }
    }

    pub(super) fn source(self) -> Source {
        match self {
            Quantity::CushionThickness
            | Quantity::FlowThickness
            | Quantity::FloorEpsS
            | Quantity::FloorTheta
            | Quantity::MaxUs
            | Quantity::ProbeHu => Source::Station,
            Quantity::EpsS | Quantity::UsS | Quantity::Theta => Source::Profile,
            Quantity::GateSpeed => Source::Gates,
            Quantity::FrontPosition | Quantity::MeanSpeed => Source::History,
        }
    }

    pub(super) fn is_profile(self) -> bool {
        self.source() == Source::Profile
    }

    /// The values of a history quantity (front positions: NaN where the run has no front).
    pub(super) fn of_history(self, h: &History) -> &[f64] {
        match self {
            Quantity::FrontPosition => &h.front_x,
            Quantity::MeanSpeed => &h.mean_u_s,
            _ => unreachable!("{self:?} is not a history"),
        }
    }

    pub(super) fn of_profile(self, p: &Profile) -> &[f64] {
        match self {
            Quantity::EpsS => &p.eps_s,
            Quantity::UsS => &p.u_s,
            Quantity::Theta => &p.theta,
            _ => unreachable!("{self:?} is not a profile"),
        }
    }
}

/// What one level of a ladder gives to the error computation.
#[derive(Clone, Debug, Default)]
pub struct LevelData {
    /// representative spacing relative to the paper grid, √(paper cells / cells)
    pub h: f64,
    /// station profile, or why it is missing
    pub profile: Option<Profile>,
    /// front speed per gate number, or none
    pub gates: Option<Vec<(usize, f64)>>,
    /// the bulk monitor's history, or none
    pub history: Option<History>,
    /// the paper's station and probe numbers, each with why it is missing
    pub station: StationValues,
}

/// A run's bulk monitor (`bulk.csv`), times increasing.
#[derive(Clone, Debug, Default)]
pub struct History {
    /// sample times [s]
    pub t: Vec<f64>,
    /// whole-cell front position [m]; NaN before the run has a front
    pub front_x: Vec<f64>,
    /// εs-weighted mean solids velocity along x [m/s]
    pub mean_u_s: Vec<f64>,
}

/// The quantities a case's monitors give.
pub(super) fn quantities(case: &Case) -> Vec<Quantity> {
    Quantity::ALL
        .into_iter()
        .filter(|q| match q.source() {
            Source::Station => {
                !case.monitors.profiles.is_empty()
                    && (*q != Quantity::ProbeHu || !case.monitors.wall_probes.is_empty())
            }
            Source::Profile => !case.monitors.profiles.is_empty(),
            Source::Gates => case.monitors.front.is_some(),
            Source::History => case.monitors.bulk.is_some(),
        })
        .collect()
}
