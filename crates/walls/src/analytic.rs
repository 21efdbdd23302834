//! Family A (`shared/docs/cases.md`): closed-form profiles of the user partial-slip
//! conditions, paper Eqs. 12–13 and Fig. 1.
//!
//! # Which problem the closed form solves
//!
//! The paper "analytically solved Eqs. 12 and 13" with U = 5 m/s, U_w = 0, θ = 0.5 m²/s²,
//! θ_w = 0.01 m²/s², and describes curved profiles (h_w^u = 1–10 m⁻¹ concave, 0.1 m⁻¹ nearly
//! straight, 100 m⁻¹ reaching U_w at the wall). A Robin condition alone fixes no profile, so
//! runout reads the equations the only way that yields such curves: as first-order ODEs along
//! the fluid-to-wall normal n, started from the bulk value a depth L inside the flow
//! (n = 0) and integrated to the wall (n = L):
//!
//! dφ/dn = c − h (φ − φ_w), φ(0) = φ_b  ⇒  φ(n) = φ_∞ + (φ_b − φ_∞) e^{−h n},
//! φ_∞ = φ_w + c/h (h > 0);  φ(n) = φ_b + c n (h = 0),
//!
//! with (h, φ_w, c) = (h_w^u, U_w, 0) for Eq. 12 and (h_w^θ, θ_w, c_w) for Eq. 13, in MFIX's
//! manual units (h in m⁻¹, c in m s⁻², docs/model.md §3.3). Equivalently, φ is the unique
//! solution of the boundary-value problem
//!
//! φ'' = h² (φ − φ_∞) on 0 < n < L,  φ(0) = φ_b,  dφ/dn + h (φ − φ_w) = c at n = L,
//!
//! (general solution φ_∞ + A e^{−hn} + B e^{hn}; the Robin condition forces B = 0): a
//! diffusion layer whose decay length 1/h is the slip length of the wall condition, so Eq. 12
//! holds at every depth, not only at the wall. [`RobinProfile::discrete`] solves this BVP with
//! the solver's wall-face closure ([`crate::RobinFace`], docs/model.md §3.2) on a uniform
//! cell-centred grid; it converges to the closed form at second order.
//!
//! L = 0.1 m (the case file's `depth`, assumed: Fig. 1's axis range is not in the text) is
//! the depth that matches all of the paper's sentences at once: h = 0.1 m⁻¹ falls by 1 % (a
//! nearly straight profile close to 5 m/s), h = 100 m⁻¹ reaches U_w within 0.05 m, h = 1 and
//! 10 m⁻¹ are visibly curved but still far from U_w (5 → 4.52 and 5 → 1.84 m/s).

use crate::face::RobinFace;

/// ∫₀ⁿ e^{−h s} ds = (1 − e^{−h n})/h \[m\], = n at h = 0 (evaluated with `exp_m1`, no
/// cancellation for small h n).
#[inline]
fn relaxation_length(h: f64, n: f64) -> f64 {
    if h == 0.0 {
        n
    } else {
        -(-h * n).exp_m1() / h
    }
}

/// A closed-form profile of paper Eq. 12 or 13: dφ/dn = c − h(φ − φ_w) from φ(0) = φ_b.
/// Stored as the bulk value and the Robin face g = 1, h, c_face = c + h φ_w of the wall
/// condition, so that dφ/dn = c_face − h φ.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RobinProfile {
    /// φ_b: the value a depth L inside the flow (n = 0)
    pub bulk: f64,
    /// the wall condition as a face closure (g = 1)
    pub face: RobinFace,
}

/// The discrete solution of the BVP on a uniform cell-centred grid ([`RobinProfile::discrete`]).
#[derive(Clone, Debug, PartialEq)]
pub struct DiscreteProfile {
    /// cell-centre positions n_i = (i + ½) Δ \[m\], n = 0 in the bulk, n = L at the wall
    pub n: Vec<f64>,
    /// cell values
    pub values: Vec<f64>,
    /// the wall-face value (φ_G + φ_F)/2 of the face closure
    pub wall_value: f64,
}

impl RobinProfile {
    /// Velocity profile of paper Eq. 12: dU/dn + h_u (U − U_w) = 0 from U(0) = `bulk`.
    pub fn velocity(bulk: f64, wall: f64, h_u: f64) -> Self {
        Self {
            bulk,
            face: RobinFace::partial_slip(h_u, wall),
        }
    }

    /// Granular-temperature profile of paper Eq. 13: dθ/dn + h_θ (θ − θ_w) = c from
    /// θ(0) = `bulk` (manual units, docs/model.md §3.3).
    pub fn temperature(bulk: f64, theta_w: f64, h_theta: f64, c: f64) -> Self {
        Self {
            bulk,
            face: RobinFace::user_theta(h_theta, theta_w, c),
        }
    }

    /// φ(n) = φ_b + (c_face − h φ_b)(1 − e^{−hn})/h.
    #[inline]
    pub fn value(&self, n: f64) -> f64 {
        self.bulk + (self.face.c - self.face.h * self.bulk) * relaxation_length(self.face.h, n)
    }

    /// dφ/dn = (c_face − h φ_b) e^{−hn}; equals c_face − h φ(n) (the Robin relation).
    #[inline]
    pub fn slope(&self, n: f64) -> f64 {
        (self.face.c - self.face.h * self.bulk) * (-self.face.h * n).exp()
    }

    /// φ_∞ = φ_w + c/h, the value the profile relaxes to (None for h = 0: linear growth).
    pub fn asymptote(&self) -> Option<f64> {
        (self.face.h > 0.0).then(|| self.face.c / self.face.h)
    }

    /// Solves φ'' = h²(φ − φ_∞) (i.e. −φ'' + h² φ = h c_face) on [0, L] with `cells` uniform
    /// cells, φ = φ_b on the bulk face (a half-cell Dirichlet flux) and the wall face closed
    /// by [`RobinFace::implicit_parts`] with Γ = 1, Δ = L/cells (docs/model.md §3.2): the
    /// discretisation the solver uses. Tridiagonal M-matrix, solved by the Thomas algorithm.
    pub fn discrete(&self, depth: f64, cells: usize) -> DiscreteProfile {
        assert!(cells >= 1 && depth > 0.0, "need cells >= 1 and depth > 0");
        let delta = depth / cells as f64;
        let h = self.face.h;
        let neighbour = 1.0 / delta;
        let (wall_a, wall_b) = self.face.implicit_parts(1.0, delta);
        let mut diag = vec![h * h * delta; cells];
        let mut rhs = vec![h * self.face.c * delta; cells];
        let lower = -neighbour; // a_{i,i−1} = a_{i,i+1}
        for i in 0..cells {
            if i > 0 {
                diag[i] += neighbour;
            } else {
                diag[i] += 2.0 * neighbour;
                rhs[i] += 2.0 * neighbour * self.bulk;
            }
            if i + 1 < cells {
                diag[i] += neighbour;
            } else {
                diag[i] += wall_a;
                rhs[i] += wall_b;
            }
        }
        // Thomas algorithm (forward elimination, back substitution)
        let mut upper = vec![0.0; cells];
        for i in 0..cells {
            let (pivot, carried) = if i == 0 {
                (diag[0], rhs[0])
            } else {
                (diag[i] - lower * upper[i - 1], rhs[i] - lower * rhs[i - 1])
            };
            upper[i] = lower / pivot;
            rhs[i] = carried / pivot;
        }
        for i in (0..cells.saturating_sub(1)).rev() {
            rhs[i] -= upper[i] * rhs[i + 1];
        }
        let values = rhs;
        let wall_value = self.face.face_value(values[cells - 1], delta);
        DiscreteProfile {
            n: (0..cells).map(|i| (i as f64 + 0.5) * delta).collect(),
            values,
            wall_value,
        }
    }
}
