//! Pore-pressure time scales of a granular bed at rest: how long gas pressure held in the
//! pores outlives its source (docs/model.md §2.8; docs/guide/gas.md).
//!
//! The two-fluid gas momentum at rest with negligible gas inertia and weight, εg ∇p =
//! −F_gs (u_g − u_s), is Darcy's law for the superficial flux q = εg (u_g − u_s):
//!
//!   q = −(k/μ) ∇p,   k/μ = εg²/F_gs   (the mobility, [`mobility`]),
//!
//! with F_gs the drag law's interphase coefficient (§2.6) at the bed's slip. The pores
//! store gas in two ways when their pressure rises by δp: the gas compresses (an ideal gas
//! at the absolute pressure P stores εg/P per pascal; a gas of constant density, none) and
//! the grains move apart (the bed's solids pressure falls by δp, so εs falls by δp/K with
//! K = dP_s/dεs, and a unit volume gains δp/(εs K) of pores: [`compaction_storage`]). Gas
//! mass conservation then gives the diffusion equation ∂p/∂t = D ∂²p/∂z² with
//!
//!   D = (k/μ)/S,   S = εg/P + 1/(εs K)   ([`diffusivity`]):
//!
//! Terzaghi's consolidation equation with the gas's compressibility added (Terzaghi 1925;
//! for aerated powders Geldart & Wong 1985, Chem. Eng. Sci. 40, 653; for fluidised
//! pyroclastic flows Druitt et al. 2007, Geophys. Res. Lett. 34, L03402, Roche 2012, Bull.
//! Volcanol. 74, 1807, who write D = k/(εg μ β_g) for a rigid bed). A bed of height H on an
//! impermeable floor, aerated to a linear excess profile and then closed, keeps half its
//! basal excess after t½ = τ½ H²/D with τ½ = [`TAU_HALF`] (the Fourier series of Carslaw &
//! Jaeger 1959, §3.3; crates/verification/src/references/pore_pressure.rs evaluates it).
//!
//! Valid for a bed at rest or sliding as a plug, with small excess pressures (δp ≪ P), K
//! taken at the bed's mean state. A layer dilated below its packing (by shear, or by
//! fluidisation) is not a bed but a suspension: its gas carries its weight until it has
//! settled, which takes [`settling_time`]; for fine grains that is far longer than the
//! diffusion. SI units.

use crate::drag::{Drag, DragInputs};

/// τ½ = 0.19673 [-]: D t/H² at which the basal excess of a bed drained through its top
/// halves, p(0, t)/p0 = Σ 8/((2n+1)² π²) exp(−(2n+1)² π² τ/4) = 1/2 (Carslaw & Jaeger 1959,
/// §3.3; checked against the series' bisection in crates/verification's pore_pressure).
pub const TAU_HALF: f64 = 0.19673;

/// Standard gravity g = 9.81 m/s², the acceleration the minimum fluidisation balances.
pub const GRAVITY: f64 = 9.81;

/// A relative speed [m/s] small enough to be the zero-slip limit of every drag law (the
/// laws return 0 at exactly zero slip, MFIX `drag_gs.f`); Ergun's inertial part is then
/// ~1e-13 of the viscous one for 80 µm beads.
const VANISHING_SLIP: f64 = 1e-12;

/// Bisections of [`minimum_fluidisation`]'s bracket (2⁻¹⁰⁰ of the viscous limit).
const U_MF_BISECTIONS: usize = 100;

/// A bed of one grain size at rest in a gas.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bed {
    /// solids volume fraction εs [-], 0 < εs < 1
    pub eps_s: f64,
    /// grain diameter d \[m\]
    pub diameter: f64,
    /// grain material density ρs [kg/m³]
    pub solids_density: f64,
    /// gas density ρg [kg/m³]
    pub gas_density: f64,
    /// gas viscosity μg [Pa s]
    pub gas_viscosity: f64,
}

impl Bed {
    /// The drag law's F_gs [kg m⁻³ s⁻¹] at relative speed `slip` [m/s] (§2.6).
    fn drag_coefficient(&self, drag: Drag, slip: f64) -> f64 {
        let inputs = DragInputs {
            eps_g: 1.0 - self.eps_s,
            rho_g: self.gas_density,
            mu_g: self.gas_viscosity,
            slip,
            d_p: self.diameter,
        };
        drag.f_gs(self.eps_s, &inputs)
    }
}

/// The Darcy mobility k/μ = εg²/F_gs [m² Pa⁻¹ s⁻¹] of the bed at vanishing slip (module doc).
pub fn mobility(bed: &Bed, drag: Drag) -> f64 {
    let eps_g = 1.0 - bed.eps_s;
    eps_g * eps_g / bed.drag_coefficient(drag, VANISHING_SLIP)
}

/// The superficial gas speed U_mf [m/s] at which the drag carries the bed's buoyant weight,
/// U F_gs(U/εg)/εg² = εs (ρs − ρg) g, by bisection below the viscous limit (the left side
/// grows with U, and F_gs with the slip); with Gidaspow's dense branch this is Ergun's U_mf
/// at εmf = εg.
pub fn minimum_fluidisation(bed: &Bed, drag: Drag) -> f64 {
    let eps_g = 1.0 - bed.eps_s;
    let weight = bed.eps_s * (bed.solids_density - bed.gas_density) * GRAVITY;
    let carried =
        |u: f64| u * bed.drag_coefficient(drag, (u / eps_g).max(VANISHING_SLIP)) / (eps_g * eps_g);
    let (mut lo, mut hi) = (0.0, weight * mobility(bed, drag));
    for _ in 0..U_MF_BISECTIONS {
        let mid = 0.5 * (lo + hi);
        if carried(mid) < weight {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The gas's storage εg/P [Pa⁻¹] of an ideal gas at absolute pressure P [Pa]; 0 for a gas of
/// constant density (`pressure` None).
pub fn gas_storage(eps_s: f64, pressure: Option<f64>) -> f64 {
    pressure.map_or(0.0, |p| (1.0 - eps_s) / p)
}

/// The bed's compaction storage 1/(εs K) [Pa⁻¹] for a solids-pressure stiffness
/// K = dP_s/dεs [Pa] (module doc); `None` where K ≤ 0 (a bed without stiffness).
pub fn compaction_storage(eps_s: f64, stiffness: f64) -> Option<f64> {
    (stiffness > 0.0).then(|| 1.0 / (eps_s * stiffness))
}

/// The pore-pressure diffusivity D = (k/μ)/S [m²/s] for the total storage S [Pa⁻¹];
/// `None` for a bed that stores nothing (an incompressible gas in a rigid bed: the pressure
/// follows its source at once).
pub fn diffusivity(mobility: f64, storage: f64) -> Option<f64> {
    (storage > 0.0).then(|| mobility / storage)
}

/// The time \[s\] a layer of height H \[m\] dilated to εs,d takes to settle back to the
/// bed's εs on an impermeable floor, its whole weight on the gas meanwhile: H (εs − εs,d)/
/// (εs u) (Kynch 1952: the packed bed grows from the floor at εs,d u/(εs − εs,d) while the
/// top falls at u), with u the suspension's settling speed. Closed floor, so the gas rises
/// as fast as the solids fall: the slip is u/εg and the drag balance u F_gs(u/εg)/εg² =
/// εs,d (ρs − ρg) g is U_mf's: u = [`minimum_fluidisation`] of the dilated layer.
pub fn settling_time(height: f64, dilated: &Bed, eps_s: f64, drag: Drag) -> f64 {
    height * (eps_s - dilated.eps_s) / (eps_s * minimum_fluidisation(dilated, drag))
}

/// t½ = τ½ H²/D \[s\]: the half-life of the basal excess of a bed of height H \[m\].
pub fn half_time(height: f64, diffusivity: f64) -> f64 {
    TAU_HALF * height * height / diffusivity
}

#[cfg(test)]
mod tests {
    use super::*;

    fn beads(diameter: f64) -> Bed {
        Bed {
            eps_s: 0.58,
            diameter,
            solids_density: 2500.0,
            gas_density: 1.2041,
            gas_viscosity: 1.8e-5,
        }
    }

    /// With Gidaspow's dense branch at zero slip, F_gs = 150 εs² μ/(εg d²) (Ergun), so
    /// k/μ = εg³ d²/(150 εs² μ), the Kozeny–Carman form Ergun's viscous term is.
    #[test]
    fn the_mobility_is_kozeny_carman_with_gidaspow() {
        let bed = beads(8e-5);
        let (eg, es) = (0.42_f64, 0.58_f64);
        let kozeny = eg.powi(3) * 8e-5_f64.powi(2) / (150.0 * es * es * 1.8e-5);
        let k = mobility(&bed, Drag::Gidaspow);
        assert!((k / kozeny - 1.0).abs() < 1e-12, "{k} {kozeny}");
    }

    /// U_mf of 80 µm glass beads in air at εmf = 0.42 from Ergun's equation with both
    /// terms, 1.75 ρg U²/(εg³ d) + 150 μ εs U/(εg³ d²) = Δρ g, solved as a quadratic in U.
    #[test]
    fn minimum_fluidisation_solves_ergun() {
        for d in [8e-5, 5e-4, 2e-3] {
            let bed = beads(d);
            let (eg, es) = (0.42_f64, 0.58_f64);
            let a = 1.75 * 1.2041 / (eg.powi(3) * d);
            let b = 150.0 * 1.8e-5 * es / (eg.powi(3) * d * d);
            let c = -(2500.0 - 1.2041) * 9.81;
            let ergun = (-b + (b * b - 4.0 * a * c).sqrt()) / (2.0 * a);
            let u = minimum_fluidisation(&bed, Drag::Gidaspow);
            assert!((u / ergun - 1.0).abs() < 1e-9, "d {d}: {u} against {ergun}");
        }
        // the fine beads' value quoted in examples/fluidised-release (7.4 mm/s)
        let u = minimum_fluidisation(&beads(8e-5), Drag::Gidaspow);
        assert!((u - 7.4e-3).abs() < 1e-4, "{u}");
    }

    /// A rigid bed in an ideal gas: D = P εg/F_gs, the form of the defluidisation check
    /// (crates/verification/src/references/pore_pressure.rs); D ∝ d² in the viscous limit.
    #[test]
    fn the_rigid_bed_diffusivity_is_p_eps_g_over_beta() {
        let bed = beads(8e-5);
        let k = mobility(&bed, Drag::Gidaspow);
        let d = diffusivity(k, gas_storage(0.58, Some(101_325.0))).unwrap();
        let beta = 150.0 * 0.58 * 0.58 * 1.8e-5 / (0.42 * 8e-5 * 8e-5);
        assert!((d / (101_325.0 * 0.42 / beta) - 1.0).abs() < 1e-12);
        let coarse = beads(1.6e-4);
        let d2 = diffusivity(
            mobility(&coarse, Drag::Gidaspow),
            gas_storage(0.58, Some(101_325.0)),
        );
        assert!((d2.unwrap() / d - 4.0).abs() < 1e-12);
    }

    /// Storage adds: compaction slows the diffusion; an incompressible gas in a rigid bed
    /// has no time scale at all; a bed without stiffness has no compaction storage.
    #[test]
    fn the_storages_add() {
        let gas = gas_storage(0.58, Some(1e5));
        let bed = compaction_storage(0.58, 2e4).unwrap();
        let k = 1e-6;
        assert!(diffusivity(k, gas + bed).unwrap() < diffusivity(k, gas).unwrap());
        assert_eq!(diffusivity(k, gas_storage(0.58, None)), None);
        assert_eq!(compaction_storage(0.58, 0.0), None);
        assert!((half_time(0.1, 0.01) - TAU_HALF).abs() < 1e-15);
    }

    /// Settling: the speed balances the suspension's buoyant weight with the drag at the
    /// slip u/εg of a closed floor; viscous Gidaspow gives u = εg³ d² Δρ g/(150 εs μ) in closed
    /// form, and the time is the two-state Kynch solution's.
    #[test]
    fn a_dilated_layer_settles_at_the_kynch_time() {
        let dilated = Bed {
            eps_s: 0.5,
            ..beads(8e-5)
        };
        let (eg, es): (f64, f64) = (0.5, 0.5);
        let viscous =
            eg.powi(3) * 8e-5_f64.powi(2) * (2500.0 - 1.2041) * 9.81 / (150.0 * es * 1.8e-5);
        let u = minimum_fluidisation(&dilated, Drag::Gidaspow);
        assert!((u / viscous - 1.0).abs() < 0.01, "{u} {viscous}"); // inertia ≈ 0.3 %
                                                                    // the packed front and the falling top meet at t: t (front + u) = H
        let (h, packed) = (0.03, 0.58);
        let t = settling_time(h, &dilated, packed, Drag::Gidaspow);
        let front = dilated.eps_s * u / (packed - dilated.eps_s);
        assert!((t * (front + u) / h - 1.0).abs() < 1e-12);
    }
}
