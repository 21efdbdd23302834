//! The gas's equation of state (docs/model.md §1.4).
//!
//! - `Constant`: ρ_g is the case's `gas.density` everywhere (MFIX with `RO_G0` set).
//! - `IdealGas`: ρ_g = P M / (R T) at a fixed temperature T (MFIX's default, `RO_G0` unset,
//!   with the energy equations off: `EOS_G` with `T_G = T_G0`), P the absolute gas pressure
//!   [Pa], M the molar mass [kg mol⁻¹] and R the molar gas constant. Its derivative
//!   dρ_g/dP = M/(R T) (MFIX `DROODP_G`) is the compressibility the pressure correction carries
//!   (docs/model.md §4.6).
//!
//! Valid for a gas far from condensation at pressures where it is ideal (air at 1 bar: the
//! compressibility factor differs from 1 by 3e-4).

/// The molar gas constant R [J mol⁻¹ K⁻¹] (CODATA 2018, exact).
pub const MOLAR_GAS_CONSTANT: f64 = 8.314_462_618;

/// How the gas density follows the pressure (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum GasLaw {
    /// ρ_g constant [kg m⁻³]
    Constant(f64),
    /// ρ_g = P M/(R T): molar mass M [kg mol⁻¹] and temperature T [K]
    IdealGas {
        /// M [kg mol⁻¹]
        molar_mass: f64,
        /// T [K]
        temperature: f64,
    },
}

impl GasLaw {
    /// dρ_g/dP [s² m⁻²]: M/(R T) for an ideal gas, 0 for a constant density.
    pub fn compressibility(&self) -> f64 {
        match *self {
            GasLaw::Constant(_) => 0.0,
            GasLaw::IdealGas {
                molar_mass,
                temperature,
            } => molar_mass / (MOLAR_GAS_CONSTANT * temperature),
        }
    }

    /// ρ_g [kg m⁻³] at the absolute pressure `p` [Pa].
    pub fn density(&self, p: f64) -> f64 {
        match *self {
            GasLaw::Constant(rho) => rho,
            GasLaw::IdealGas { .. } => self.compressibility() * p,
        }
    }

    /// Whether ρ_g depends on the pressure.
    pub fn is_compressible(&self) -> bool {
        matches!(self, GasLaw::IdealGas { .. })
    }

    /// The isothermal hydrostatic pressure [Pa] at potential energy per mass `work` [J kg⁻¹]
    /// below a point at `p0` [Pa] (work = g·(r − r0) for a uniform field g): P0 + ρ work for a
    /// constant density, P0 exp(M work/(R T)) for an ideal gas (dP = ρ(P) dW integrated).
    pub fn hydrostatic(&self, p0: f64, work: f64) -> f64 {
        match *self {
            GasLaw::Constant(rho) => p0 + rho * work,
            GasLaw::IdealGas { .. } => p0 * (self.compressibility() * work).exp(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const AIR: GasLaw = GasLaw::IdealGas {
        molar_mass: 0.028_965,
        temperature: 293.15,
    };

    #[test]
    fn air_at_one_atmosphere_weighs_1_204_kg_per_cubic_metre() {
        // tabulated dry air at 20 °C and 101 325 Pa: 1.2041 kg m⁻³
        assert!((AIR.density(101_325.0) - 1.2041).abs() < 1e-4);
        assert_eq!(GasLaw::Constant(1.2).density(3e5), 1.2);
        assert_eq!(GasLaw::Constant(1.2).compressibility(), 0.0);
    }

    #[test]
    fn the_hydrostatic_pressure_solves_dp_equals_rho_dw() {
        // dP/dW = ρ(P), checked by a central difference of step 1 J/kg at W = −9.81 J/kg (1 m
        // up; the difference's truncation error is (M h/(R T))²/6 ~ 2e-11)
        for law in [AIR, GasLaw::Constant(1.2)] {
            let (p0, w, h) = (1e5, -9.81, 1.0);
            let dp = (law.hydrostatic(p0, w + h) - law.hydrostatic(p0, w - h)) / (2.0 * h);
            let rho = law.density(law.hydrostatic(p0, w));
            assert!((dp / rho - 1.0).abs() < 1e-8, "{law:?}: {dp} against {rho}");
        }
    }
}
