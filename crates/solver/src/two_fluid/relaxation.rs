//! Under-relaxation of the momentum rows (docs/model.md §4.10): how far one outer iteration
//! moves a velocity towards the solution of its linearised equation.
//!
//! Patankar's form (MFIX `under_relax.f`) divides the whole centre coefficient by ω and adds
//! the difference times the last iterate to the source:
//!
//!   (a_P/ω) φ = Σ a_nb φ_nb + b + (1 − ω)/ω a_P φ*                                  (1)
//!
//! Written as a_P φ + R (φ − φ*) = Σ a_nb φ_nb + b, the relaxation R = (1 − ω)/ω a_P is a
//! false inertia. a_P counts the links a_nb, so where the links dwarf the row's own part
//! a_0 = a_P − Σ a_nb (the inertia ρ εs V/Δt, the drag, the wall and side-wall sinks), a
//! motion that leaves the links idle — the rigid motion of a layer whose regularised μ(I)
//! viscosity μ_s P/γ̇_min makes Σ a_nb about 1e4 a_0 — moves each outer iteration by about
//! ω a_0/((1 − ω) Σ a_nb) of its way, and the normalised residual Σ|r|/Σ|a_P φ| is below any
//! tolerance long before it arrives: the step ends with the layer still. The own-part form
//! relaxes with the row's own part only:
//!
//!   R = (1 − ω)/ω (a_P − Σ a_nb)                                                       (2)
//!
//! so every motion, rigid or not, moves ω of its way against the inertia (a false time step
//! Δt ω/(1 − ω) on top of Δt), and the converged step is the same as with (1).

use serde::{Deserialize, Serialize};

/// What a momentum row's under-relaxation is proportional to (module doc).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum RelaxationBase {
    /// Patankar's (1): the whole centre coefficient a_P (MFIX)
    #[default]
    Centre,
    /// (2): the row's own part a_P − Σ a_nb
    OwnPart,
}

impl RelaxationBase {
    /// The base of a solids phase's rows: `chosen` if given, else the one its friction
    /// model asks for (module doc).
    pub fn for_phase(chosen: Option<Self>, friction: &runout_closures::FrictionModel) -> Self {
        chosen.unwrap_or(if friction.relaxes_momentum_by_own_part() {
            RelaxationBase::OwnPart
        } else {
            RelaxationBase::Centre
        })
    }

    /// The relaxed centre coefficient a_P + R of a row with centre coefficient `centre` and
    /// links summing to `links`, at relaxation `omega` ∈ (0, 1] (module doc).
    #[inline]
    pub fn relaxed_centre(self, centre: f64, links: f64, omega: f64) -> f64 {
        match self {
            RelaxationBase::Centre => centre / omega,
            RelaxationBase::OwnPart => centre + (1.0 - omega) / omega * (centre - links).max(0.0),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A row of inertia a_0 between two links a: the rigid motion (φ_nb moving with φ)
    /// advances by r/(a_0 + R) towards the root of a_0 φ = r, i.e. by a_0/(a_0 + R) of its
    /// way; Patankar's R = (1 − ω)/ω (a_0 + 2a), the own part's (1 − ω)/ω a_0.
    #[test]
    fn the_own_part_moves_a_rigid_motion_by_omega_of_its_way() {
        let (a0, link, omega) = (1.0, 1e4, 0.5);
        let centre = a0 + 2.0 * link;
        let fraction = |base: RelaxationBase| {
            let relaxed = base.relaxed_centre(centre, 2.0 * link, omega);
            a0 / (relaxed - 2.0 * link)
        };
        assert!((fraction(RelaxationBase::OwnPart) - omega).abs() < 1e-12);
        let patankar = fraction(RelaxationBase::Centre);
        assert!(patankar < 1e-4, "{patankar}");
        // ω = 1: no relaxation in either form
        for base in [RelaxationBase::Centre, RelaxationBase::OwnPart] {
            assert_eq!(base.relaxed_centre(centre, 2.0 * link, 1.0), centre);
        }
    }
}
