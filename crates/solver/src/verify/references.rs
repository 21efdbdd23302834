//! Reference data of the lid-driven cavity: the centreline velocities of Ghia, Ghia & Shin
//! (1982) and the spectral values of Botella & Peyret (1998) at the same points.

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

/// Botella & Peyret (1998), "Benchmark spectral results on the lid-driven cavity flow",
/// Computers & Fluids 27(4), 421–433, Tables 9 and 10 (Chebyshev collocation, N = 160),
/// Re = 1000, at Ghia's sample points. Transcribed from public benchmark scripts that
/// quote these tables (several independent copies agree to all digits).
pub const BOTELLA_PEYRET_RE1000: CentrelineReference = CentrelineReference {
    source: "Botella & Peyret (1998), Comput. Fluids 27, 421-433, Tables 9-10",
    reynolds: 1000.0,
    y: &GHIA_Y,
    u: &[
        1.0, 0.6644227, 0.5808359, 0.5169277, 0.4723329, 0.3372212, 0.1886747, 0.0570178,
        -0.0620561, -0.1081999, -0.2803696, -0.3885691, -0.3004561, -0.2228955, -0.2023300,
        -0.1812881, 0.0,
    ],
    x: &GHIA_X,
    v: &[
        0.0, -0.2279225, -0.2936869, -0.3553213, -0.4103754, -0.5264392, -0.4264545, -0.3202137,
        0.0257995, 0.3253592, 0.3339924, 0.3769189, 0.3330442, 0.3099097, 0.2962703, 0.2807056,
        0.0,
    ],
};

/// Extrema of the centreline velocities.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CentrelineExtrema {
    /// minimum of u(0.5, y)
    pub u_min: f64,
    /// where it is
    pub y_u_min: f64,
    /// maximum of v(x, 0.5)
    pub v_max: f64,
    /// where it is
    pub x_v_max: f64,
    /// minimum of v(x, 0.5)
    pub v_min: f64,
    /// where it is
    pub x_v_min: f64,
}

/// Botella & Peyret (1998), Table 7, Re = 1000 (N = 160).
pub const BOTELLA_PEYRET_RE1000_EXTREMA: CentrelineExtrema = CentrelineExtrema {
    u_min: -0.3885698,
    y_u_min: 0.1717,
    v_max: 0.3769447,
    x_v_max: 0.1578,
    v_min: -0.5270771,
    x_v_min: 0.9092,
};

/// Ghia's table for `reynolds` (100 or 1000).
pub fn ghia(reynolds: f64) -> Option<&'static CentrelineReference> {
    [&GHIA_RE100, &GHIA_RE1000]
        .into_iter()
        .find(|r| r.reynolds == reynolds)
}
