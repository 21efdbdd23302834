//! The coefficients of every solids phase per cell, as a struct of arrays: the closure
//! values (docs/model.md §2), filled in place by the parallel closure pass
//! ([`super::closures`]); the strain rates they were evaluated with (§4.4); the explicit
//! stress sources of the momentum equations, once per step (§4.4, [`crate::stress`]); and
//! the side walls' terms (§8, [`super::sidewalls`]).

use rayon::prelude::*;

use super::{CellClosures, SidewallTerms};
use crate::kinematics::Strain;

/// The coefficients of one solids phase (module doc).
#[derive(Clone, Debug)]
pub(crate) struct PhaseCoefficients {
    /// solids pressure P_s = P_kin + P_fric per cell [Pa]
    pub p_s: Vec<f64>,
    /// Schaeffer plastic pressure P* per cell [Pa] (docs/model.md §2.4.1), all 0 with other
    /// friction models; in the solids momentum only, as −∇P* (§4.4)
    pub p_star: Vec<f64>,
    /// μ_s [Pa s]
    pub mu: Vec<f64>,
    /// λ_s [Pa s]
    pub lambda: Vec<f64>,
    /// κ_s [kg m⁻¹ s⁻¹]
    pub kappa: Vec<f64>,
    /// K_cp = dP_s/dεs [Pa] (docs/model.md §2.5)
    pub k_cp: Vec<f64>,
    /// F_gs [kg m⁻³ s⁻¹]
    pub f_gs: Vec<f64>,
    /// the θ sources (docs/model.md §4.8): P_kin/θ, μ_kin, λ_kin, γ/θ and J_slip
    pub p_kin_over_theta: Vec<f64>,
    pub mu_kin: Vec<f64>,
    pub lambda_kin: Vec<f64>,
    pub gamma_over_theta: Vec<f64>,
    pub j_slip: Vec<f64>,
    /// strain rates per cell, with the wall face velocities in the wall cells (§4.4)
    pub strain: Vec<Strain>,
    /// tr D and tr(D²) of the closure pass
    pub tr_d: Vec<f64>,
    pub tr_d2: Vec<f64>,
    /// explicit stress sources of the u and v equations, once per step (docs/model.md §4.4)
    pub tau_u: Vec<f64>,
    pub tau_v: Vec<f64>,
    /// the side walls' terms per cell (docs/model.md §8; all zero without side walls)
    pub sidewall: Vec<SidewallTerms>,
}

/// One row of the per-cell closure values, written by one task of the closure pass.
pub(crate) struct ClosureRow<'a> {
    p_s: &'a mut [f64],
    p_star: &'a mut [f64],
    mu: &'a mut [f64],
    lambda: &'a mut [f64],
    kappa: &'a mut [f64],
    k_cp: &'a mut [f64],
    f_gs: &'a mut [f64],
    p_kin_over_theta: &'a mut [f64],
    mu_kin: &'a mut [f64],
    lambda_kin: &'a mut [f64],
    gamma_over_theta: &'a mut [f64],
    j_slip: &'a mut [f64],
}

impl ClosureRow<'_> {
    /// Stores the closure values `c` of cell i of the row.
    pub fn put(&mut self, i: usize, c: &CellClosures) {
        self.p_s[i] = c.p_s;
        self.p_star[i] = c.p_star; // P* from the current εs (docs/model.md §2.4.1)
        self.mu[i] = c.mu;
        self.lambda[i] = c.lambda;
        self.kappa[i] = c.kappa;
        self.k_cp[i] = c.k_cp;
        self.f_gs[i] = c.f_gs;
        self.p_kin_over_theta[i] = c.p_kin_over_theta;
        self.mu_kin[i] = c.mu_kin;
        self.lambda_kin[i] = c.lambda_kin;
        self.gamma_over_theta[i] = c.gamma_over_theta;
        self.j_slip[i] = c.j_slip;
    }
}

impl PhaseCoefficients {
    /// Zero coefficients on an nx × ny grid.
    pub fn new((nx, ny): (usize, usize)) -> Self {
        let n = nx * ny;
        PhaseCoefficients {
            p_s: vec![0.0; n],
            p_star: vec![0.0; n],
            mu: vec![0.0; n],
            lambda: vec![0.0; n],
            kappa: vec![0.0; n],
            k_cp: vec![0.0; n],
            f_gs: vec![0.0; n],
            p_kin_over_theta: vec![0.0; n],
            mu_kin: vec![0.0; n],
            lambda_kin: vec![0.0; n],
            gamma_over_theta: vec![0.0; n],
            j_slip: vec![0.0; n],
            strain: vec![Strain::default(); n],
            tr_d: vec![0.0; n],
            tr_d2: vec![0.0; n],
            tau_u: vec![0.0; (nx + 1) * ny],
            tau_v: vec![0.0; nx * (ny + 1)],
            sidewall: vec![SidewallTerms::default(); n],
        }
    }

    /// The closure values row by row (rows of `nx` cells), for the parallel closure pass,
    /// with the strain rates to read.
    pub fn closure_rows(
        &mut self,
        nx: usize,
    ) -> (
        &[Strain],
        impl IndexedParallelIterator<Item = ClosureRow<'_>>,
    ) {
        let rows = (
            self.p_s.par_chunks_mut(nx),
            self.p_star.par_chunks_mut(nx),
            self.mu.par_chunks_mut(nx),
            self.lambda.par_chunks_mut(nx),
            self.kappa.par_chunks_mut(nx),
            self.k_cp.par_chunks_mut(nx),
            self.f_gs.par_chunks_mut(nx),
            self.p_kin_over_theta.par_chunks_mut(nx),
            self.mu_kin.par_chunks_mut(nx),
            self.lambda_kin.par_chunks_mut(nx),
            self.gamma_over_theta.par_chunks_mut(nx),
            self.j_slip.par_chunks_mut(nx),
        )
            .into_par_iter()
            .map(|r| ClosureRow {
                p_s: r.0,
                p_star: r.1,
                mu: r.2,
                lambda: r.3,
                kappa: r.4,
                k_cp: r.5,
                f_gs: r.6,
                p_kin_over_theta: r.7,
                mu_kin: r.8,
                lambda_kin: r.9,
                gamma_over_theta: r.10,
                j_slip: r.11,
            });
        (&self.strain, rows)
    }

    /// tr D and tr(D²) of the strain rates of the closure pass.
    pub fn keep_strain_traces(&mut self) {
        for (k, st) in self.strain.iter().enumerate() {
            self.tr_d[k] = st.tr_d;
            self.tr_d2[k] = st.tr_d2;
        }
    }
}
