//! The case sets of the paper's figures: which cases, labels and variables each profile,
//! probe, field and flume figure draws, and family M's MFIX numbers.

use runout_post::profile::Profile;

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
