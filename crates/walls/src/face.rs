//! The discrete Robin closure on a wall face (docs/model.md §3.2).
//!
//! For a tangential component φ (a velocity of a phase, or θ) MFIX writes one equation per
//! ghost cell, g (φ_G − φ_F)/Δ + h (φ_G + φ_F)/2 = c: the normal derivative (fluid → wall)
//! as a two-point difference across the face and the face value as the mean of ghost and
//! fluid values; Δ is the distance between the ghost and fluid centres, which equals the
//! fluid cell's width (docs/model.md §3.1). Eliminating φ_G gives the wall-face flux and face
//! value used in the fluid cell's equation, so no ghost unknowns are needed.

/// Robin coefficients of g ∂φ/∂n + h φ_face = c on a wall face (n from the fluid into the
/// wall). Momentum forms use g = 1, c = h U_w (paper Eq. 12); the Johnson–Jackson θ form uses
/// g = κ (docs/model.md §3.6).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct RobinFace {
    /// coefficient of the normal derivative [same units as the conductivity or 1]
    pub g: f64,
    /// coefficient of the face value
    pub h: f64,
    /// right-hand side
    pub c: f64,
}

impl RobinFace {
    /// Zero normal gradient (free slip, zero flux): g = 1, h = c = 0.
    pub const ZERO_GRADIENT: RobinFace = RobinFace {
        g: 1.0,
        h: 0.0,
        c: 0.0,
    };

    /// Face value held at `value` (no-slip for a moving wall, Dirichlet θ): g = 0, h = 1.
    pub fn dirichlet(value: f64) -> RobinFace {
        RobinFace {
            g: 0.0,
            h: 1.0,
            c: value,
        }
    }

    /// Partial slip du/dn + h (u − U_w) = 0 (paper Eq. 12; docs/model.md §3.2): g = 1, c = h U_w.
    pub fn partial_slip(h: f64, wall_value: f64) -> RobinFace {
        RobinFace {
            g: 1.0,
            h,
            c: h * wall_value,
        }
    }

    /// User θ condition dθ/dn + h_θ (θ − θ_w) = C (docs/model.md §3.3): g = 1, c = C + h_θ θ_w.
    pub fn user_theta(h_theta: f64, theta_w: f64, flux: f64) -> RobinFace {
        RobinFace {
            g: 1.0,
            h: h_theta,
            c: flux + h_theta * theta_w,
        }
    }

    /// 1/(g + hΔ/2), the factor of the eliminated closure; the denominator is zero only for
    /// g = h = 0, which no constructor produces. Every method below multiplies by it before
    /// combining terms, so a huge h (the no-slip limit) gives finite results, never ∞/∞.
    #[inline]
    fn inverse_denominator(&self, delta: f64) -> f64 {
        1.0 / (self.g + 0.5 * self.h * delta)
    }

    /// Ghost value φ_G = (c + φ_F (g/Δ − h/2)) / (g/Δ + h/2).
    #[inline]
    pub fn ghost(&self, phi_fluid: f64, delta: f64) -> f64 {
        let s = self.inverse_denominator(delta);
        self.c * delta * s + phi_fluid * (self.g * s - 0.5 * self.h * delta * s)
    }

    /// Face value (φ_G + φ_F)/2 = (c Δ/2 + g φ_F)/(g + hΔ/2).
    #[inline]
    pub fn face_value(&self, phi_fluid: f64, delta: f64) -> f64 {
        let s = self.inverse_denominator(delta);
        0.5 * self.c * delta * s + self.g * s * phi_fluid
    }

    /// Diffusive flux out of the fluid cell through the wall face per unit area,
    /// Γ (φ_F − φ_G)/Δ = Γ (h φ_F − c)/(g + hΔ/2), with Γ the fluid cell's transport
    /// coefficient (docs/model.md §3.1).
    #[inline]
    pub fn flux(&self, gamma: f64, phi_fluid: f64, delta: f64) -> f64 {
        let (a, b) = self.implicit_parts(gamma, delta);
        a * phi_fluid - b
    }

    /// The flux split for implicit assembly: flux = a φ_F − b with
    /// a = Γ h/(g + hΔ/2) ≥ 0 (added to a_P) and b = Γ c/(g + hΔ/2) (added to the source).
    #[inline]
    pub fn implicit_parts(&self, gamma: f64, delta: f64) -> (f64, f64) {
        let s = self.inverse_denominator(delta);
        (gamma * (self.h * s), gamma * (self.c * s))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ghost_satisfies_the_discrete_equation() {
        let f = RobinFace {
            g: 0.7,
            h: 3.0,
            c: 1.1,
        };
        let (phi, delta) = (2.5, 0.01);
        let ghost = f.ghost(phi, delta);
        let lhs = f.g * (ghost - phi) / delta + f.h * 0.5 * (ghost + phi);
        assert!((lhs - f.c).abs() < 1e-12, "{lhs}");
        assert!((f.face_value(phi, delta) - 0.5 * (ghost + phi)).abs() < 1e-12);
        let gamma = 0.3;
        assert!((f.flux(gamma, phi, delta) - gamma * (phi - ghost) / delta).abs() < 1e-10);
        let (a, b) = f.implicit_parts(gamma, delta);
        assert!((a * phi - b - f.flux(gamma, phi, delta)).abs() < 1e-12);
    }

    #[test]
    fn dirichlet_and_zero_gradient() {
        let d = RobinFace::dirichlet(4.0);
        assert_eq!(d.face_value(1.0, 0.2), 4.0);
        // flux through a half cell: Γ (φ_F − φ_w)/(Δ/2)
        assert!((d.flux(2.0, 1.0, 0.2) - 2.0 * (1.0 - 4.0) / 0.1).abs() < 1e-12);
        let z = RobinFace::ZERO_GRADIENT;
        assert_eq!(z.face_value(1.5, 0.2), 1.5);
        assert_eq!(z.flux(2.0, 1.5, 0.2), 0.0);
    }
}
