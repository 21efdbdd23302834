//! Botella & Peyret (1998), "Benchmark spectral results on the lid-driven cavity flow",
//! Computers & Fluids 27(4), 421–433: the spectral (Chebyshev collocation, N = 160)
//! centreline velocities of the lid-driven cavity at Re = 1000 at Ghia's sample points, and
//! the centreline extrema, for judging Ghia's own accuracy at Re = 1000 (docs/studies/verification.md).

use super::ghia::{CentrelineReference, GHIA_X, GHIA_Y};

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
