//! The two-fluid state: the fields of the gas and of every solids phase, at the current
//! iterate and at the old time level (docs/model.md §1, §4.9).
//!
//! It keeps two invariants (docs/model.md §1.1): εg = 1 − Σεs in every cell, and the bulk
//! densities ρε of every phase equal to its material density times its volume fraction; the
//! gas's material density follows its pressure by its [`GasLaw`] (docs/model.md §1.4). The
//! volume fractions are private: εs changes only through [`State::set_solids_fraction`],
//! [`State::update_solids`] and [`State::update_all_solids`], which restore both invariants.
//! Velocities, θ and P_g are plain public arrays.

use runout_closures::GasLaw;

/// The old time level of the gas (the start of the step, [`State::begin_step`]).
#[derive(Clone, Debug)]
pub struct GasOld {
    /// εg per cell
    pub eps: Vec<f64>,
    /// u on x-faces
    pub u: Vec<f64>,
    /// v on y-faces
    pub v: Vec<f64>,
    /// ρ_g εg per cell
    pub rho_eps: Vec<f64>,
}

/// The gas's fields.
#[derive(Clone, Debug)]
pub struct GasState {
    eps: Vec<f64>,
    rho_eps: Vec<f64>,
    /// ρ_g per cell, by `law` from `p`
    rho: Vec<f64>,
    law: GasLaw,
    old: GasOld,
    /// gas pressure per cell [Pa]
    pub p: Vec<f64>,
    /// u on x-faces [m s⁻¹]
    pub u: Vec<f64>,
    /// v on y-faces [m s⁻¹]
    pub v: Vec<f64>,
}

impl GasState {
    /// εg per cell.
    pub fn eps(&self) -> &[f64] {
        &self.eps
    }

    /// The bulk density ρ_g εg per cell [kg m⁻³].
    pub fn bulk_density(&self) -> &[f64] {
        &self.rho_eps
    }

    /// The material density ρ_g per cell [kg m⁻³] (its law at the cell's pressure, as of the
    /// last pressure update).
    pub fn density(&self) -> &[f64] {
        &self.rho
    }

    /// The equation of state.
    pub fn law(&self) -> GasLaw {
        self.law
    }

    /// The old time level.
    pub fn old(&self) -> &GasOld {
        &self.old
    }
}

/// The old time level of one solids phase (the start of the step, [`State::begin_step`]).
#[derive(Clone, Debug)]
pub struct PhaseOld {
    /// εs per cell
    pub eps: Vec<f64>,
    /// u on x-faces
    pub u: Vec<f64>,
    /// v on y-faces
    pub v: Vec<f64>,
    /// θ per cell
    pub theta: Vec<f64>,
    /// ρ_s εs per cell
    pub rho_eps: Vec<f64>,
}

/// The fields of one solids phase.
#[derive(Clone, Debug)]
pub struct PhaseState {
    eps: Vec<f64>,
    rho_eps: Vec<f64>,
    density: f64,
    old: PhaseOld,
    /// u on x-faces [m s⁻¹]
    pub u: Vec<f64>,
    /// v on y-faces [m s⁻¹]
    pub v: Vec<f64>,
    /// granular temperature θ per cell [m² s⁻²]
    pub theta: Vec<f64>,
}

impl PhaseState {
    /// εs per cell.
    pub fn eps(&self) -> &[f64] {
        &self.eps
    }

    /// The bulk density ρ_s εs per cell [kg m⁻³].
    pub fn bulk_density(&self) -> &[f64] {
        &self.rho_eps
    }

    /// The old time level.
    pub fn old(&self) -> &PhaseOld {
        &self.old
    }

    /// The material density ρ_s [kg m⁻³].
    pub fn density(&self) -> f64 {
        self.density
    }
}

/// One solids phase open for change inside [`State::update_solids`]: εs, u, v and θ
/// writable, the old time level readable.
pub struct PhaseMut<'a> {
    /// εs per cell
    pub eps: &'a mut [f64],
    /// u on x-faces
    pub u: &'a mut [f64],
    /// v on y-faces
    pub v: &'a mut [f64],
    /// θ per cell
    pub theta: &'a mut [f64],
    /// the old time level
    pub old: &'a PhaseOld,
}

impl PhaseState {
    fn open(&mut self) -> PhaseMut<'_> {
        PhaseMut {
            eps: &mut self.eps,
            u: &mut self.u,
            v: &mut self.v,
            theta: &mut self.theta,
            old: &self.old,
        }
    }
}

/// The gas and the solids phases (module doc).
#[derive(Clone, Debug)]
pub struct State {
    gas: GasState,
    solids: Vec<PhaseState>,
}

impl State {
    /// Gas at rest filling every cell at zero pressure, phases of the given material
    /// densities without solids (εs = 0, at rest, θ = `theta`).
    pub(super) fn new(
        (nx, ny): (usize, usize),
        gas_density: f64,
        densities: impl IntoIterator<Item = f64>,
        theta: f64,
    ) -> Self {
        let n = nx * ny;
        let (nu, nv) = ((nx + 1) * ny, nx * (ny + 1));
        let gas = GasState {
            eps: vec![1.0; n],
            rho_eps: vec![gas_density; n],
            rho: vec![gas_density; n],
            law: GasLaw::Constant(gas_density),
            old: GasOld {
                eps: vec![1.0; n],
                u: vec![0.0; nu],
                v: vec![0.0; nv],
                rho_eps: vec![gas_density; n],
            },
            p: vec![0.0; n],
            u: vec![0.0; nu],
            v: vec![0.0; nv],
        };
        let solids = densities
            .into_iter()
            .map(|density| PhaseState {
                eps: vec![0.0; n],
                rho_eps: vec![0.0; n],
                density,
                old: PhaseOld {
                    eps: vec![0.0; n],
                    u: vec![0.0; nu],
                    v: vec![0.0; nv],
                    theta: vec![theta; n],
                    rho_eps: vec![0.0; n],
                },
                u: vec![0.0; nu],
                v: vec![0.0; nv],
                theta: vec![theta; n],
            })
            .collect();
        State { gas, solids }
    }

    /// The gas.
    pub fn gas(&self) -> &GasState {
        &self.gas
    }

    /// The gas, for its pressure and velocities (εg follows the solids).
    pub fn gas_mut(&mut self) -> &mut GasState {
        &mut self.gas
    }

    /// Solids phase `m`.
    pub fn solids(&self, m: usize) -> &PhaseState {
        &self.solids[m]
    }

    /// Solids phase `m`, for its velocities and θ (εs through [`State::update_solids`]).
    pub fn solids_mut(&mut self, m: usize) -> &mut PhaseState {
        &mut self.solids[m]
    }

    /// Every solids phase.
    pub fn phases(&self) -> &[PhaseState] {
        &self.solids
    }

    /// Every solids phase, for velocities and θ.
    pub fn phases_mut(&mut self) -> &mut [PhaseState] {
        &mut self.solids
    }

    /// The gas beside every solids phase, all writable (their velocities solved side by
    /// side).
    pub fn gas_mut_and_phases_mut(&mut self) -> (&mut GasState, &mut [PhaseState]) {
        (&mut self.gas, &mut self.solids)
    }

    /// The gas (read) beside every solids phase (velocities and θ writable).
    pub fn gas_and_phases_mut(&mut self) -> (&GasState, &mut [PhaseState]) {
        (&self.gas, &mut self.solids)
    }

    /// The number of solids phases.
    pub fn n_solids(&self) -> usize {
        self.solids.len()
    }

    /// Sets εs of phase `m` in cell `k`; εg and the bulk densities of the cell follow.
    pub fn set_solids_fraction(&mut self, m: usize, k: usize, value: f64) {
        self.solids[m].eps[k] = value;
        self.sync_cell(k);
    }

    /// Changes phase `m` through `f`; εg and the bulk densities follow.
    pub fn update_solids<R>(&mut self, m: usize, f: impl FnOnce(PhaseMut<'_>) -> R) -> R {
        let out = f(self.solids[m].open());
        self.sync();
        out
    }

    /// Changes every phase in turn through `f(m, phase)`; εg and the bulk densities follow
    /// once all are done.
    pub fn update_all_solids(&mut self, mut f: impl FnMut(usize, PhaseMut<'_>)) {
        for (m, s) in self.solids.iter_mut().enumerate() {
            f(m, s.open());
        }
        self.sync();
    }

    /// As [`State::update_all_solids`], stopping at the first error (εg and the bulk
    /// densities follow the changes made).
    pub fn try_update_all_solids<E>(
        &mut self,
        mut f: impl FnMut(usize, PhaseMut<'_>) -> Result<(), E>,
    ) -> Result<(), E> {
        let out = self
            .solids
            .iter_mut()
            .enumerate()
            .try_for_each(|(m, s)| f(m, s.open()));
        self.sync();
        out
    }

    /// Sets the gas's equation of state and its density from the present pressure.
    pub(super) fn set_gas_law(&mut self, law: GasLaw) {
        self.gas.law = law;
        self.sync_gas_density();
    }

    /// ρ_g of every cell from its pressure, and the gas bulk densities (after P changed);
    /// nothing to do for a constant density.
    pub(super) fn sync_gas_density(&mut self) {
        let g = &mut self.gas;
        if g.law.is_compressible() {
            for k in 0..g.rho.len() {
                g.rho[k] = g.law.density(g.p[k]);
                g.rho_eps[k] = g.rho[k] * g.eps[k];
            }
        }
    }

    /// Stores the current fields as the old time level (the gas density from the pressure
    /// first, which a caller may have set).
    pub(super) fn begin_step(&mut self) {
        self.sync_gas_density();
        let g = &mut self.gas;
        g.old.eps.copy_from_slice(&g.eps);
        g.old.u.copy_from_slice(&g.u);
        g.old.v.copy_from_slice(&g.v);
        g.old.rho_eps.copy_from_slice(&g.rho_eps);
        for s in &mut self.solids {
            s.old.eps.copy_from_slice(&s.eps);
            s.old.u.copy_from_slice(&s.u);
            s.old.v.copy_from_slice(&s.v);
            s.old.theta.copy_from_slice(&s.theta);
            s.old.rho_eps.copy_from_slice(&s.rho_eps);
        }
    }

    /// Restores the fields of the start of the step (not P_g, which is kept).
    pub(super) fn restore_step(&mut self) {
        self.gas.u.copy_from_slice(&self.gas.old.u);
        self.gas.v.copy_from_slice(&self.gas.old.v);
        for s in &mut self.solids {
            s.eps.copy_from_slice(&s.old.eps);
            s.u.copy_from_slice(&s.old.u);
            s.v.copy_from_slice(&s.old.v);
            s.theta.copy_from_slice(&s.old.theta);
        }
        self.sync();
    }

    /// Whether every field of the iterate is finite.
    pub fn all_finite(&self) -> bool {
        let g = &self.gas;
        g.p.iter().chain(&g.u).chain(&g.v).all(|x| x.is_finite())
            && self.solids.iter().all(|p| {
                p.eps
                    .iter()
                    .chain(&p.u)
                    .chain(&p.v)
                    .chain(&p.theta)
                    .all(|x| x.is_finite())
            })
    }

    /// εg = 1 − Σεs and the bulk densities of every cell.
    fn sync(&mut self) {
        for k in 0..self.gas.eps.len() {
            self.sync_gas_cell(k);
        }
        for s in &mut self.solids {
            for k in 0..s.eps.len() {
                s.rho_eps[k] = s.density * s.eps[k];
            }
        }
    }

    /// εg = 1 − Σεs and the bulk densities of cell k.
    fn sync_cell(&mut self, k: usize) {
        self.sync_gas_cell(k);
        for s in &mut self.solids {
            s.rho_eps[k] = s.density * s.eps[k];
        }
    }

    fn sync_gas_cell(&mut self, k: usize) {
        let g = &mut self.gas;
        g.eps[k] = 1.0 - self.solids.iter().map(|s| s.eps[k]).sum::<f64>();
        g.rho_eps[k] = g.rho[k] * g.eps[k];
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_change_of_eps_keeps_eps_g_and_the_bulk_densities() {
        let mut st = State::new((2, 1), 1.2, [2500.0, 1000.0], 1e-12);
        let check = |st: &State| {
            for k in 0..2 {
                let sum: f64 = st.phases().iter().map(|s| s.eps()[k]).sum();
                assert_eq!(st.gas().eps()[k], 1.0 - sum);
                assert_eq!(st.gas().bulk_density()[k], 1.2 * st.gas().eps()[k]);
                for s in st.phases() {
                    assert_eq!(s.bulk_density()[k], s.density() * s.eps()[k]);
                }
            }
        };
        st.set_solids_fraction(0, 1, 0.3);
        check(&st);
        st.update_solids(1, |p| p.eps[0] = 0.2);
        check(&st);
        st.begin_step();
        st.update_all_solids(|m, p| p.eps.iter_mut().for_each(|e| *e += 0.1 * m as f64));
        check(&st);
        assert_eq!(st.solids(1).old().eps, vec![0.2, 0.0]);
        let r: Result<(), ()> = st.try_update_all_solids(|_, p| {
            p.eps[1] = 0.5;
            Err(())
        });
        assert!(r.is_err());
        check(&st);
        st.restore_step();
        check(&st);
        assert_eq!(st.solids(0).eps(), &[0.0, 0.3]);
    }
}
