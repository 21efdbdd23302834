//! Ghia, Ghia & Shin (1982), "High-Re solutions for incompressible flow using the
//! Navier–Stokes equations and a multigrid method", J. Comput. Phys. 48, 387–411, Tables I
//! and II: the centreline velocities of the lid-driven unit cavity (unit lid speed) at
//! Re = 100 and 1000, on their 129 × 129 grid lines. The reference of the `cavity` check.

/// Centreline velocities of the lid-driven unit cavity (unit lid speed): u(0.5, y) at the
/// heights `y` and v(x, 0.5) at the abscissae `x`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CentrelineReference {
    /// citation
    pub source: &'static str,
    /// Reynolds number U L/ν
    pub reynolds: f64,
    /// heights of the u samples on the vertical centreline x = 0.5
    pub y: &'static [f64],
    /// u(0.5, y)
    pub u: &'static [f64],
    /// abscissae of the v samples on the horizontal centreline y = 0.5
    pub x: &'static [f64],
    /// v(x, 0.5)
    pub v: &'static [f64],
}

/// y of Ghia, Ghia & Shin's u samples (their 129-point grid lines), top to bottom.
pub const GHIA_Y: [f64; 17] = [
    1.0, 0.9766, 0.9688, 0.9609, 0.9531, 0.8516, 0.7344, 0.6172, 0.5, 0.4531, 0.2813, 0.1719,
    0.1016, 0.0703, 0.0625, 0.0547, 0.0,
];

/// x of Ghia, Ghia & Shin's v samples, right to left.
pub const GHIA_X: [f64; 17] = [
    1.0, 0.9688, 0.9609, 0.9531, 0.9453, 0.9063, 0.8594, 0.8047, 0.5, 0.2344, 0.2266, 0.1563,
    0.0938, 0.0781, 0.0703, 0.0625, 0.0,
];

const GHIA_CITATION: &str = "Ghia, Ghia & Shin (1982), J. Comput. Phys. 48, 387-411, Tables I-II";

/// Ghia, Ghia & Shin (1982), J. Comput. Phys. 48, 387–411, Tables I and II, Re = 100.
pub const GHIA_RE100: CentrelineReference = CentrelineReference {
    source: GHIA_CITATION,
    reynolds: 100.0,
    y: &GHIA_Y,
    u: &[
        1.0, 0.84123, 0.78871, 0.73722, 0.68717, 0.23151, 0.00332, -0.13641, -0.20581, -0.21090,
        -0.15662, -0.10150, -0.06434, -0.04775, -0.04192, -0.03717, 0.0,
    ],
    x: &GHIA_X,
    v: &[
        0.0, -0.05906, -0.07391, -0.08864, -0.10313, -0.16914, -0.22445, -0.24533, 0.05454,
        0.17527, 0.17507, 0.16077, 0.12317, 0.10890, 0.10091, 0.09233, 0.0,
    ],
};

/// Ghia, Ghia & Shin (1982), Tables I and II, Re = 1000.
pub const GHIA_RE1000: CentrelineReference = CentrelineReference {
    source: GHIA_CITATION,
    reynolds: 1000.0,
    y: &GHIA_Y,
    u: &[
        1.0, 0.65928, 0.57492, 0.51117, 0.46604, 0.33304, 0.18719, 0.05702, -0.06080, -0.10648,
        -0.27805, -0.38289, -0.29730, -0.22220, -0.20196, -0.18109, 0.0,
    ],
    x: &GHIA_X,
    v: &[
        0.0, -0.21388, -0.27669, -0.33714, -0.39188, -0.51550, -0.42665, -0.31966, 0.02526,
        0.32235, 0.33075, 0.37095, 0.32627, 0.30353, 0.29012, 0.27485, 0.0,
    ],
};

/// Ghia's table for `reynolds` (100 or 1000).
pub fn ghia(reynolds: f64) -> Option<&'static CentrelineReference> {
    [&GHIA_RE100, &GHIA_RE1000]
        .into_iter()
        .find(|r| r.reynolds == reynolds)
}
