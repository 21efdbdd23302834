//! Nonlinear consolidation of an aerated bed whose aeration is shut off (issue 60 item 3): the
//! reference for a bed that compacts as its gas drains, where [`super::pore_pressure`]'s
//! rigid bed does not hold.
//!
//! A bed of height H on a closed floor, its top at the freeboard's pressure, at rest in a gas
//! at the absolute pressure P0. With the gas's inertia neglected the two-fluid momentum
//! balances of a column are, for the gas and the solids,
//!
//!   0 = −εg ∂P/∂z − εg ρg g − β (u_g − u_s),
//!   0 = −εs ∂P/∂z − ∂σ'/∂z − εs ρs g + β (u_g − u_s),
//!
//! with σ' the solids pressure, Princeton's frictional P_f, which at rest is its critical
//! state pressure P_c(εs) (P_f/P_c = 1 without strain rate). Their sum, with p the excess of
//! P over the gas's hydrostatic column, is ∂σ'/∂z = −∂p/∂z − εs (ρs − ρg) g; with p = σ' = 0
//! at the top,
//!
//!   σ' = σ_tot(z) − p,   σ_tot(z) = ε̄s (ρs − ρg) g (H − z),
//!
//! σ_tot the buoyant weight above z, fixed in time (small strain), spread over the bed at its
//! mean packing ε̄s. The gas's balance is Darcy's law for the superficial flux,
//! q = εg (u_g − u_s) = −M ∂p/∂z with the mobility M = εg²/β, β = 150 εs² μ/(εg d²)
//! (Gidaspow's dense branch at vanishing slip, Ergun's viscous term). The volume balances
//! of the solids, ∂εs/∂t + ∂(εs u_s)/∂z = 0, and of an ideal gas, ρg = P M_w/(R T), divided
//! by ρg with its gradients neglected (p ≪ P0), ∂εg/∂t + (εg/P0) ∂p/∂t + ∂(εg u_g)/∂z = 0,
//! add to (εg/P0) ∂p/∂t + ∂(q + u_s)/∂z = 0. In small strain ∂u_s/∂z = −(1/εs) ∂εs/∂t, and
//! εs = P_c⁻¹(σ') gives ∂εs/∂t = −(1/K) ∂p/∂t with the stiffness K = dP_c/dεs, so
//!
//!   S ∂p/∂t = ∂/∂z (M ∂p/∂z),   S = εg/P0 + 1/(εs K),   εs = P_c⁻¹(σ_tot(z) − p):
//!
//! Terzaghi's consolidation (Terzaghi 1925; Gibson, England & Hussey 1967, Géotechnique 17,
//! 261, in its small-strain limit) with coefficients that vary with the effective stress,
//! plus the gas's compressibility (the storages add: crates/closures/src/pore_pressure.rs,
//! which takes them uniform). K → 0 at the top, where εs → εs,min; S ~ (H − z)^(−1/2) there
//! is integrable. The floor is closed, ∂p/∂z = 0 at z = 0, and p = 0 at z = H. Before the
//! shut-off the floor lets in a superficial q: the steady profile
//!
//!   dp/dz = −q/M(εs(σ_tot − p)),   p(H) = 0
//!
//! ([`aerated_profile`]) is the initial state. Neglected: finite strain (εs moves by ~3e-3, the
//! bed's height by less), the rate dependence of Princeton's P_f/P_c (the 1 atm runs keep it
//! within 0.5 % of 1), the kinetic pressure, the gas's inertia, Ergun's inertial term and the
//! variation of P0 across the bed.
//!
//! P_c (Srivastava & Sundaresan 2003 as MFIX computes it) is written here from its formula,
//! apart from runout_closures: Fr (εs − εs,min)²/(εs,max − εs)⁵ with Fr = 0.05 Pa,
//! εs,min = 0.5, εs,max = 0.65, continued linearly above εs,max − δ, δ = 0.01 (its tests
//! compare it with `PrincetonConstants::critical_pressure`). [`Skeleton::Rigid`] drops the
//! compaction storage and holds εs at ε̄s: the linear problem of [`super::pore_pressure`].
//!
//! Numerics: vertex-centred finite volumes on N uniform cells (nodes z_j = j H/N, a half cell
//! at the floor), each face's mobility at the face's own state; backward Euler with S and M
//! at the new level, Picard-iterated to 1e-11 of the excess, each iterate a tridiagonal solve
//! (Thomas); the time step a fixed fraction of the time scale t* = τ½ H² S/M at mid-depth
//! ([`AeratedBed::time_scale`]); the half time interpolated linearly between steps. The
//! initial profile is integrated by RK4 from the top down in at least 4096 steps.
//! Nearly second order in space (1.8: εs − εs,min ~ √σ' below the top), first in time (the
//! tests measure both).
//!
//! For the 2-D runs of examples/defluidisation/run.sh at 1 atm (q = 2 mm/s; H and ε̄s as the
//! runs measured them, H counting the partly filled top row whole) this gives t½ = 38.3, 81.9
//! and 194.9 ms at H = 0.0525, 0.1025 and 0.2025 m, against 34.1, 78.7 and 179.1 ms measured
//! (ratios 0.89, 0.96, 0.92; the rigid bed's 4.0, 17.1 and 70.5 ms). That top row is filled
//! below εs,min, has no frictional pressure and hangs on the gas (~10 Pa that outlast the
//! drainage); with H the full rows' height at the same solids volume the reference gives
//! 34.4, 77.6 and 189.6 ms (ratios 0.99, 1.01, 0.94; the tallest bed was not yet steady at the
//! shut-off). The `defluidisation` check judges its runs against it with its own H (the
//! solids volume over the mean εs of the rows below the top one): 0.92 at 1 atm and H 0.05 m,
//! 0.97 at 1 kPa and H 0.025 m.

/// Fr = 0.5 dyn/cm² = 0.05 Pa, the scale of Princeton's P_c (MFIX `constant_mod.f`).
const FR: f64 = 0.05;
/// εs,min [-], below which P_c is 0 (the shipped defluidisation case's friction_min_packing).
pub const EPS_S_MIN: f64 = 0.5;
/// εs,max [-] of P_c's pole (the case's max_packing).
pub const EPS_S_MAX: f64 = 0.65;
/// δ [-]: P_c is continued linearly above εs,max − δ (MFIX).
const DELTA: f64 = 0.01;
/// Standard gravity [m/s²].
const GRAVITY: f64 = 9.81;
/// Molar gas constant [J/(mol K)].
const GAS_CONSTANT: f64 = 8.314_462_618;
/// Air's molar mass [kg/mol] and the runs' temperature [K].
const AIR: (f64, f64) = (0.028_965, 293.15);
/// Air's viscosity [Pa s] in the runs.
const AIR_VISCOSITY: f64 = 1.8e-5;
/// τ½ of the rigid bed (Carslaw & Jaeger 1959), for the time scale only.
const TAU_HALF: f64 = 0.19673;
/// Least number of RK4 steps over the bed for the initial profile.
const RK4_STEPS: usize = 4096;
/// Picard's stopping change, relative to the largest excess.
const PICARD_TOLERANCE: f64 = 1e-11;
/// Picard iterations allowed per step.
const PICARD_ITERATIONS: usize = 200;
/// Safeguarded Newton iterations allowed in [`packing`].
const NEWTON_ITERATIONS: usize = 200;
/// Least stiffness \[Pa\] in the storage (K is 0 at εs,min, where σ' = 0: the top node, held
/// at p = 0, or an iterate that overshoots).
const MIN_STIFFNESS: f64 = 1e-9;
/// Time steps per cell and per time scale in [`basal_half_time`].
pub const STEPS_PER_CELL: usize = 4;
/// Time scales [`basal_half_time_with`] runs for before giving up.
const MAX_TIME_SCALES: usize = 100;

/// Fr (εs − εs,min)²/(εs,max − εs)⁵ \[Pa\].
fn power_law(eps_s: f64) -> f64 {
    FR * (eps_s - EPS_S_MIN).powi(2) / (EPS_S_MAX - eps_s).powi(5)
}

/// Its derivative, Fr [2 (εs − εs,min)/(εs,max − εs)⁵ + 5 (εs − εs,min)²/(εs,max − εs)⁶] \[Pa\].
fn power_law_slope(eps_s: f64) -> f64 {
    let (above, below) = (eps_s - EPS_S_MIN, EPS_S_MAX - eps_s);
    FR * (2.0 * above / below.powi(5) + 5.0 * above * above / below.powi(6))
}

/// Princeton's critical pressure P_c(εs) \[Pa\] (module doc): 0 at or below εs,min, the power
/// law up to εs,max − δ, its tangent there beyond.
pub fn critical_pressure(eps_s: f64) -> f64 {
    let at = EPS_S_MAX - DELTA;
    if eps_s <= EPS_S_MIN {
        0.0
    } else if eps_s > at {
        power_law(at) + power_law_slope(at) * (eps_s - at)
    } else {
        power_law(eps_s)
    }
}

/// The stiffness K = dP_c/dεs \[Pa\]: 0 at or below εs,min, constant above εs,max − δ.
pub fn stiffness(eps_s: f64) -> f64 {
    if eps_s <= EPS_S_MIN {
        0.0
    } else {
        power_law_slope(eps_s.min(EPS_S_MAX - DELTA))
    }
}

/// εs = P_c⁻¹(σ') [-] for the effective stress σ' \[Pa\]: εs,min at σ' ≤ 0, the linear branch in
/// closed form, else Newton's method on ln P_c kept inside a shrinking bracket (bisection
/// where a step would leave it), to 1e-15 in εs.
pub fn packing(stress: f64) -> f64 {
    let at = EPS_S_MAX - DELTA;
    if stress <= 0.0 {
        return EPS_S_MIN;
    }
    let top = power_law(at);
    if stress >= top {
        return at + (stress - top) / power_law_slope(at);
    }
    let (mut lo, mut hi) = (EPS_S_MIN, at);
    let mut eps = 0.5 * (lo + hi);
    for _ in 0..NEWTON_ITERATIONS {
        let p_c = power_law(eps);
        if p_c > stress {
            hi = eps;
        } else {
            lo = eps;
        }
        let newton = eps - (p_c / stress).ln() * p_c / power_law_slope(eps);
        let next = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (next - eps).abs() <= 1e-15 || hi - lo <= 1e-15 {
            return next;
        }
        eps = next;
    }
    eps
}

/// How the grains respond to the effective stress.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Skeleton {
    /// εs = ε̄s everywhere, no compaction storage: rigid-bed pore-pressure diffusion
    Rigid,
    /// εs = P_c⁻¹(σ'), the compaction storage 1/(εs K) (module doc)
    Princeton,
}

/// A bed of one grain size on a closed floor, aerated from below (module doc). SI units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AeratedBed {
    /// bed height H \[m\]
    pub height: f64,
    /// the bed's mean solids fraction ε̄s [-] (its weight; the rigid bed's εs)
    pub eps_s: f64,
    /// superficial gas inflow q through the floor before the shut-off [m/s]
    pub inflow: f64,
    /// the gas's absolute pressure P0 \[Pa\]
    pub pressure: f64,
    /// grain diameter d \[m\]
    pub diameter: f64,
    /// grain material density ρs [kg/m³]
    pub solids_density: f64,
    /// gas density ρg [kg/m³]
    pub gas_density: f64,
    /// gas viscosity μ [Pa s]
    pub gas_viscosity: f64,
    /// the grains' response
    pub skeleton: Skeleton,
}

impl AeratedBed {
    /// The runs' 80 µm glass beads (2500 kg/m³) in air (μ 1.8e-5 Pa s, ideal at 293.15 K,
    /// M 0.028965 kg/mol, so ρg = P0 M/(R T)), compacting by Princeton's P_c.
    pub fn glass_beads(height: f64, eps_s: f64, pressure: f64, inflow: f64) -> Self {
        Self {
            height,
            eps_s,
            inflow,
            pressure,
            diameter: 8e-5,
            solids_density: 2500.0,
            gas_density: pressure * AIR.0 / (GAS_CONSTANT * AIR.1),
            gas_viscosity: AIR_VISCOSITY,
            skeleton: Skeleton::Princeton,
        }
    }

    /// σ_tot(z) = ε̄s (ρs − ρg) g (H − z) \[Pa\], the buoyant weight above z.
    pub fn overburden(&self, z: f64) -> f64 {
        self.eps_s * (self.solids_density - self.gas_density) * GRAVITY * (self.height - z)
    }

    /// εs at height z under the excess p: P_c⁻¹(σ_tot(z) − p), or ε̄s for a rigid bed.
    pub fn eps_s_at(&self, z: f64, excess: f64) -> f64 {
        match self.skeleton {
            Skeleton::Rigid => self.eps_s,
            Skeleton::Princeton => packing(self.overburden(z) - excess),
        }
    }

    /// The Darcy mobility M = εg²/β = εg³ d²/(150 εs² μ) [m² Pa⁻¹ s⁻¹].
    pub fn mobility(&self, eps_s: f64) -> f64 {
        let eps_g = 1.0 - eps_s;
        eps_g.powi(3) * self.diameter * self.diameter / (150.0 * eps_s * eps_s * self.gas_viscosity)
    }

    /// The storage S = εg/P0 + 1/(εs K) [Pa⁻¹] (the second term only for Princeton's skeleton).
    pub fn storage(&self, eps_s: f64) -> f64 {
        let gas = (1.0 - eps_s) / self.pressure;
        match self.skeleton {
            Skeleton::Rigid => gas,
            Skeleton::Princeton => gas + 1.0 / (eps_s * stiffness(eps_s).max(MIN_STIFFNESS)),
        }
    }

    /// t* = τ½ H² S/M \[s\] at mid-depth, where σ' = σ_tot(H/2) − q H/(2 M(ε̄s)): the time
    /// steps' unit (the rigid bed's half time exactly, about twice the compacting bed's).
    pub fn time_scale(&self) -> f64 {
        let mid = 0.5 * self.height;
        let eps_s = self.eps_s_at(mid, self.inflow * mid / self.mobility(self.eps_s));
        TAU_HALF * self.height * self.height * self.storage(eps_s) / self.mobility(eps_s)
    }
}

/// The steady aerated excess p(z_j) \[Pa\] at the nodes z_j = j H/N, j = 0..=N (p_N = 0), for
/// the inflow q: dp/dz = −q/M, integrated by RK4 from the top down (module doc). Panics if
/// the excess reaches the overburden below the top (the inflow fluidises the bed).
pub fn aerated_profile(bed: &AeratedBed, cells: usize) -> Vec<f64> {
    let dz = bed.height / cells as f64;
    let sub = RK4_STEPS.div_ceil(cells);
    let h = -dz / sub as f64;
    let slope = |z: f64, p: f64| -bed.inflow / bed.mobility(bed.eps_s_at(z, p));
    let mut profile = vec![0.0; cells + 1];
    let mut p = 0.0;
    for j in (0..cells).rev() {
        let mut z = (j + 1) as f64 * dz;
        for _ in 0..sub {
            let k1 = slope(z, p);
            let k2 = slope(z + 0.5 * h, p + 0.5 * h * k1);
            let k3 = slope(z + 0.5 * h, p + 0.5 * h * k2);
            let k4 = slope(z + h, p + h * k3);
            p += h * (k1 + 2.0 * k2 + 2.0 * k3 + k4) / 6.0;
            z += h;
        }
        let z = j as f64 * dz;
        assert!(
            bed.skeleton == Skeleton::Rigid || p < bed.overburden(z),
            "the inflow {} m/s fluidises the bed at z = {z} m",
            bed.inflow
        );
        profile[j] = p;
    }
    profile
}

/// Solves the tridiagonal system lower_j x_{j−1} + diag_j x_j + upper_j x_{j+1} = rhs_j
/// (Thomas algorithm; lower_0 and upper_{n−1} unused).
fn thomas(lower: &[f64], diag: &[f64], upper: &[f64], rhs: &[f64]) -> Vec<f64> {
    let n = diag.len();
    let (mut c, mut d) = (vec![0.0; n], vec![0.0; n]);
    for j in 0..n {
        let (l, cp, dp) = if j > 0 {
            (lower[j], c[j - 1], d[j - 1])
        } else {
            (0.0, 0.0, 0.0)
        };
        let denom = diag[j] - l * cp;
        c[j] = upper[j] / denom;
        d[j] = (rhs[j] - l * dp) / denom;
    }
    let mut x = vec![0.0; n];
    for j in (0..n).rev() {
        x[j] = d[j] - if j + 1 < n { c[j] * x[j + 1] } else { 0.0 };
    }
    x
}

/// One backward-Euler step of Δt `dt` \[s\] from the nodal excess `old` (module doc), the floor
/// fed at the superficial `feed` [m/s]: S and the face mobilities at the new level, Picard
/// iterated until no node moves by more than 1e-11 of the largest excess. Panics if Picard
/// does not converge.
fn backward_euler(bed: &AeratedBed, old: &[f64], dt: f64, feed: f64) -> Vec<f64> {
    let n = old.len() - 1;
    let dz = bed.height / n as f64;
    let scale = old.iter().fold(f64::MIN_POSITIVE, |m, v| m.max(v.abs()));
    let mut p = old.to_vec();
    let (mut lower, mut diag, mut upper, mut rhs) =
        (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    for _ in 0..PICARD_ITERATIONS {
        // a_{j+1/2} = M/Δz at the face between nodes j and j + 1 (the last one: the top)
        let faces: Vec<f64> = (0..n)
            .map(|j| {
                let z = (j as f64 + 0.5) * dz;
                bed.mobility(bed.eps_s_at(z, 0.5 * (p[j] + p[j + 1]))) / dz
            })
            .collect();
        for j in 0..n {
            let volume = if j == 0 { 0.5 * dz } else { dz };
            let c = volume * bed.storage(bed.eps_s_at(j as f64 * dz, p[j])) / dt;
            let below = if j > 0 { faces[j - 1] } else { 0.0 };
            lower[j] = -below;
            upper[j] = if j + 1 < n { -faces[j] } else { 0.0 };
            diag[j] = c + below + faces[j];
            rhs[j] = c * old[j] + if j == 0 { feed } else { 0.0 };
        }
        let next = thomas(&lower, &diag, &upper, &rhs);
        let change = next
            .iter()
            .zip(&p)
            .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        p[..n].copy_from_slice(&next);
        if change <= PICARD_TOLERANCE * scale {
            return p;
        }
    }
    panic!("Picard did not converge in {PICARD_ITERATIONS} iterations (Δt {dt} s)");
}

/// The time \[s\] for the basal excess p(0, t) to fall to half of p(0, 0) after the shut-off,
/// from the aerated profile on `cells` cells with [`STEPS_PER_CELL`] × `cells` steps per
/// time scale (module doc).
pub fn basal_half_time(bed: &AeratedBed, cells: usize) -> f64 {
    basal_half_time_with(bed, cells, STEPS_PER_CELL * cells)
}

/// [`basal_half_time`] with Δt = [`AeratedBed::time_scale`]/`steps`. Panics if the excess
/// has not halved after a hundred time scales.
pub fn basal_half_time_with(bed: &AeratedBed, cells: usize, steps: usize) -> f64 {
    let mut p = aerated_profile(bed, cells);
    let target = 0.5 * p[0];
    let dt = bed.time_scale() / steps as f64;
    for n in 0..MAX_TIME_SCALES * steps {
        let next = backward_euler(bed, &p, dt, 0.0);
        if next[0] <= target {
            return (n as f64 + (p[0] - target) / (p[0] - next[0])) * dt;
        }
        p = next;
    }
    panic!("the basal excess has not halved in {MAX_TIME_SCALES} time scales");
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::references::pore_pressure::{diffusivity, tau_half};
    use runout_closures::friction::{FrictionParams, PrincetonConstants};

    /// The 1 atm bed of H = 0.0525 m (examples/defluidisation/run.sh).
    fn one_atmosphere() -> AeratedBed {
        AeratedBed::glass_beads(0.0525, 0.5714, 101_325.0, 2e-3)
    }

    #[test]
    fn the_critical_pressure_is_princetons() {
        let closures = PrincetonConstants::MFIX;
        let params = FrictionParams::new(EPS_S_MAX, EPS_S_MIN, 30.0);
        // 0.45 to 0.66 in steps of 5e-4: below εs,min, the power law and the linear branch
        for k in 0..=420 {
            let eps_s = 0.45 + 5e-4 * f64::from(k);
            let (ours, theirs) = (
                critical_pressure(eps_s),
                closures.critical_pressure(eps_s, &params),
            );
            assert!(
                (ours - theirs).abs() <= 1e-12 * theirs.abs(),
                "εs {eps_s}: {ours} {theirs}"
            );
            let (ours, theirs) = (
                stiffness(eps_s),
                closures.dcritical_pressure_deps(eps_s, &params),
            );
            assert!(
                (ours - theirs).abs() <= 1e-12 * theirs.abs(),
                "εs {eps_s}: K {ours} {theirs}"
            );
            if eps_s > EPS_S_MIN {
                let back = packing(critical_pressure(eps_s));
                assert!((back - eps_s).abs() < 1e-12, "εs {eps_s}: {back}");
            }
        }
        // the paper's values at εs,max − δ: 9.8e6 Pa and a slope of 5.04e9 Pa
        assert!((critical_pressure(0.64) / 9.8e6 - 1.0).abs() < 1e-12);
        assert!((stiffness(0.64) / 5.04e9 - 1.0).abs() < 1e-12);
        assert_eq!(packing(-1.0), EPS_S_MIN);
    }

    /// (a) Without the compaction storage and at uniform εs the problem is the rigid bed's
    /// linear diffusion: the aerated profile is q (H − z)/M and the half time the Fourier
    /// series' τ½ H²/D, D = P εg/β (within 0.5 %), at 1 kPa and at 1 atm.
    #[test]
    fn a_rigid_bed_halves_at_the_fourier_series_time() {
        for (pressure, inflow) in [(1000.0, 1e-4), (101_325.0, 2e-3)] {
            let bed = AeratedBed {
                skeleton: Skeleton::Rigid,
                ..AeratedBed::glass_beads(0.05, 0.58, pressure, inflow)
            };
            let cells = 100;
            let p = aerated_profile(&bed, cells);
            let linear = inflow * bed.height / bed.mobility(0.58);
            assert!((p[0] / linear - 1.0).abs() < 1e-12, "{} {linear}", p[0]);
            assert!((p[cells / 2] / (0.5 * linear) - 1.0).abs() < 1e-12);
            let series =
                tau_half() * bed.height.powi(2) / diffusivity(pressure, 0.58, 1.8e-5, 8e-5);
            let t = basal_half_time(&bed, cells);
            println!("P {pressure} Pa: t½ {t:.6e} s, the series' {series:.6e} s");
            assert!(
                (t / series - 1.0).abs() < 5e-3,
                "P {pressure}: {t} {series}"
            );
            assert!((bed.time_scale() / series - 1.0).abs() < 1e-4);
        }
    }

    /// (c) The initial profile is the scheme's steady state to its truncation error: fed at
    /// q, long steps leave it within 2e-4 of its excess on 100 cells and 2.4× closer on 200
    /// (order 1.3: εs − εs,min ~ √σ' below the top, where the face mobilities sample it).
    #[test]
    fn the_aerated_profile_is_steady() {
        let bed = one_atmosphere();
        let drift = |cells: usize| {
            let start = aerated_profile(&bed, cells);
            let mut p = start.clone();
            for _ in 0..10 {
                p = backward_euler(&bed, &p, bed.time_scale(), bed.inflow);
            }
            let worst = p
                .iter()
                .zip(&start)
                .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
            worst / start[0]
        };
        let (coarse, fine) = (drift(100), drift(200));
        println!("steady drift: {coarse:.3e} (100 cells), {fine:.3e} (200 cells)");
        assert!(coarse < 2e-4, "{coarse}");
        assert!(coarse / fine > 2.2, "{coarse} {fine}");
    }

    /// Observed order log2(|e1 − e2|/|e2 − e3|) of three solutions each refined by 2.
    fn order(a: f64, b: f64, c: f64) -> f64 {
        ((a - b) / (b - c)).abs().log2()
    }

    /// (b) The half time converges under refinement: in space at a fixed Δt (25 to 200 cells,
    /// second order) and in time on a fixed grid (Δt halved three times, first order).
    #[test]
    fn the_half_time_converges() {
        let bed = one_atmosphere();
        let space: Vec<f64> = [25, 50, 100, 200]
            .iter()
            .map(|&cells| basal_half_time_with(&bed, cells, 400))
            .collect();
        let time: Vec<f64> = [50, 100, 200, 400]
            .iter()
            .map(|&steps| basal_half_time_with(&bed, 50, steps))
            .collect();
        let (p_space, p_time) = (
            order(space[1], space[2], space[3]),
            order(time[1], time[2], time[3]),
        );
        println!(
            "t½ [ms] on 25–200 cells: {:?}, order {p_space:.3} ({:.3} on the coarser three)",
            space.iter().map(|t| 1e3 * t).collect::<Vec<_>>(),
            order(space[0], space[1], space[2])
        );
        println!(
            "t½ [ms] at 50–400 steps: {:?}, order {p_time:.3} ({:.3} on the coarser three)",
            time.iter().map(|t| 1e3 * t).collect::<Vec<_>>(),
            order(time[0], time[1], time[2])
        );
        assert!((p_space - 2.0).abs() < 0.3, "space order {p_space}");
        assert!((p_time - 1.0).abs() < 0.15, "time order {p_time}");
        // the default resolution is within 0.2 % of the finest
        let default = basal_half_time(&bed, 100);
        assert!(
            (default / space[3] - 1.0).abs() < 2e-3,
            "{default} {}",
            space[3]
        );
    }

    /// The reference for the 1 atm runs of examples/defluidisation/run.sh (their H as 2.5 mm
    /// rows times the rows of εs > 0.3, ε̄s those rows' mean, and t½; q = 2 mm/s), and again
    /// with H the full rows' height, 2.5 mm less, at the same solids volume ε̄s H (the top
    /// row, filled below εs,min, has no frictional pressure and hangs on the gas): `cargo test
    /// --release -p runout-verification --lib one_atmosphere_runs -- --ignored --nocapture`.
    #[test]
    #[ignore = "prints the comparison with the 1 atm runs"]
    fn one_atmosphere_runs() {
        for (height, eps_s, measured) in [
            (0.0525, 0.5714, 34.12e-3),
            (0.1025, 0.5854, 78.66e-3),
            (0.2025, 0.5926, 179.06e-3),
        ] {
            let bed = AeratedBed::glass_beads(height, eps_s, 101_325.0, 2e-3);
            let p0 = aerated_profile(&bed, 200)[0];
            let reference = basal_half_time(&bed, 200);
            let rigid = tau_half() * height * height / diffusivity(101_325.0, eps_s, 1.8e-5, 8e-5);
            let full = height - 0.0025;
            let rows = AeratedBed::glass_beads(full, eps_s * height / full, 101_325.0, 2e-3);
            let rows_reference = basal_half_time(&rows, 200);
            println!(
                "H {height} m, εs {eps_s}: excess {p0:.1} Pa, t½ {:.2} ms (rigid {:.2} ms, \
                 t* {:.2} ms); measured {:.2} ms, measured/reference {:.3}; with H {full:.4} m: \
                 excess {:.1} Pa, t½ {:.2} ms, measured/reference {:.3}",
                1e3 * reference,
                1e3 * rigid,
                1e3 * bed.time_scale(),
                1e3 * measured,
                measured / reference,
                aerated_profile(&rows, 200)[0],
                1e3 * rows_reference,
                measured / rows_reference
            );
        }
    }
}
