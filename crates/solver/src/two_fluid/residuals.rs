//! Step 6 of the outer iteration (docs/model.md §4.9): the residuals and the convergence of
//! a time step (docs/model.md §4.11, MFIX `calc_resid.f`, `check_convergence.f`).
//!
//! - momentum, per coupled velocity node and phase before relaxation: |r + drag coupling −
//!   a_P φ|, normalised by Σ |a_P| |(U, V)| over the nodes of its class where the phase
//!   moves ([`CoupledNode::residual`], [`ClassedResidual`]): the largest class's per
//!   component (or, as MFIX, pooled over every node and phase), summed over components;
//! - gas and solids continuity: the mean |mass imbalance| before the corrections, each
//!   relative to its value at the step's first outer iteration ([`Convergence`]);
//! - granular energy: Σ |residual| / Σ |a_P θ_P| over the dense cells, per phase.
//!
//! A step has converged when the momentum and continuity sum is at most its tolerance and
//! the θ residual at most its own, after at least two outer iterations; MFIX's
//! `DETECT_STALL` ends a step whose sum does not fall over 5 iterations
//! ([`Convergence::stalled`]).

use super::MAX_SOLIDS_PHASES;

/// Normalised residuals of one outer iteration (docs/model.md §4.11).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TwoFluidResiduals {
    /// momentum: per component the largest class's (or MFIX's pooled), summed
    pub momentum: f64,
    /// mean |gas mass imbalance| before the pressure correction [kg s⁻¹ per m depth]
    pub gas_mass: f64,
    /// mean |solids mass imbalance| before the ε correction, summed over phases
    pub solids_mass: f64,
    /// θ equations, Σ|residual| / Σ|a_P θ_P|, summed over phases
    pub theta: f64,
}

/// The coupled momentum equations of the N phases (the gas and N − 1 ≤
/// [`MAX_SOLIDS_PHASES`] solids phases) at one velocity node, as assembled and before the
/// partial elimination (index 0 the gas, p the solids phase p). N is a constant of the
/// type so that a node of one solids phase is a few registers, not arrays sized for the
/// most phases (the elimination visits every velocity node of every outer iteration).
#[derive(Clone, Copy, Debug)]
pub(super) struct CoupledNode<const N: usize> {
    /// centre coefficients
    pub a_in: [f64; N],
    /// right-hand sides Σ a_nb φ_nb + b
    pub r_in: [f64; N],
    /// current values
    pub phi: [f64; N],
    /// the other velocity component MFIX stores at the node's index (for the speed)
    pub cross: [f64; N],
    /// drag coefficients F_gs V of the solids phases (index q for solids phase q + 1; the
    /// last entry unused)
    pub drag: [f64; N],
    /// whether the node is dilute for each solids phase (indexed as `drag`)
    pub dilute: [bool; N],
    /// the cells beside the node (low, high)
    pub cells: (Option<usize>, Option<usize>),
}

impl<const N: usize> CoupledNode<N> {
    /// A node beside `cells` with every coefficient zero.
    pub fn new(cells: (Option<usize>, Option<usize>)) -> Self {
        const { assert!(N >= 1 && N <= MAX_SOLIDS_PHASES + 1) };
        Self {
            a_in: [0.0; N],
            r_in: [0.0; N],
            phi: [0.0; N],
            cross: [0.0; N],
            drag: [0.0; N],
            dilute: [false; N],
            cells,
        }
    }

    /// The momentum residual of phase p (of m solids phases), its normaliser |a_P| |(U, V)|
    /// and |a_P|, `None` where the phase does not move: |(U, V)| ≤ 1e-15 with U, V the two
    /// face velocities MFIX stores at one index (the east and north faces of the cell west of
    /// a u-node, south of a v-node).
    pub fn residual(&self, p: usize, m: usize) -> Option<(f64, f64, f64)> {
        let (phi, drag) = (&self.phi, &self.drag);
        let speed = (phi[p] * phi[p] + self.cross[p] * self.cross[p]).sqrt();
        if speed <= 1e-15 {
            return None;
        }
        let coupling = if p == 0 {
            (0..m).map(|q| drag[q] * (phi[q + 1] - phi[0])).sum::<f64>()
        } else {
            drag[p - 1] * (phi[0] - phi[p])
        };
        let res = (self.r_in[p] + coupling - self.a_in[p] * phi[p]).abs();
        let a = self.a_in[p].abs();
        Some((res, a * speed, a))
    }
}

/// The momentum residual of one velocity component by class of node: the gas, and for each
/// solids phase its nodes where friction carries most of the viscosity (μ_s > 2 μ_kin in a
/// cell beside the node: the packed body) apart from the rest (the collisional and loose
/// flow, the head of a slide). Each class is normalised by its own Σ |a_P| |(U, V)|
/// (docs/model.md §4.11): pooled as MFIX pools a phase's nodes, the packed body's
/// frictional a_P, orders of magnitude above the head's, hides the head's residual, and the
/// outer iterations stop before the head has moved where the converged step puts it (issue
/// 58: the front of S-JEN-d at `wall` 13.12 m at a pooled 1e-3, 13.76 m at 1e-4 or with
/// the classes).
///
/// A class at rest is normalised by no less than a floor speed times its Σ |a_P|
/// ([`ClassedResidual::largest`]): normalised by its own vanishing speeds, the round-off of a
/// bed at rest never falls below the tolerance, and steps are rejected until Δt is tiny
/// (issue 60: the settled bed of cases/gas/ideal-gas-box.ron at coarse fidelity stalled at a
/// momentum residual of 1.03e-3, in the solids' v at rest, with Δt at 8e-7 s).
#[derive(Clone, Copy, Debug)]
pub(super) struct ClassedResidual {
    /// Σ residual, Σ normaliser and Σ |a_P| per class: 0 the gas, 2p − 1 and 2p solids phase
    /// p's loose and packed nodes
    sums: [(f64, f64, f64); 1 + 2 * MAX_SOLIDS_PHASES],
}

/// Where a solids node sits, for [`ClassedResidual`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum NodeClass {
    /// friction carries most of the viscosity beside the node
    Packed,
    /// the rest: collisional or loose
    Loose,
}

impl NodeClass {
    /// The class of a solids node beside cells whose viscosity and kinetic viscosity are
    /// `(mu, mu_kin)`: packed where the frictional part exceeds the kinetic one in either.
    pub fn of(cells: impl IntoIterator<Item = (f64, f64)>) -> Self {
        if cells.into_iter().any(|(mu, mu_kin)| mu > 2.0 * mu_kin) {
            NodeClass::Packed
        } else {
            NodeClass::Loose
        }
    }
}

impl Default for ClassedResidual {
    fn default() -> Self {
        ClassedResidual {
            sums: [(0.0, 0.0, 0.0); 1 + 2 * MAX_SOLIDS_PHASES],
        }
    }
}

impl ClassedResidual {
    /// Adds a node's residual, normaliser and |a_P| of phase p (0 the gas) in `class`
    /// (ignored for the gas).
    pub fn add(&mut self, p: usize, class: NodeClass, residual: f64, scale: f64, a_p: f64) {
        let k = match (p, class) {
            (0, _) => 0,
            (p, NodeClass::Loose) => 2 * p - 1,
            (p, NodeClass::Packed) => 2 * p,
        };
        self.sums[k].0 += residual;
        self.sums[k].1 += scale;
        self.sums[k].2 += a_p;
    }

    /// The largest class residual, each Σ residual / max(Σ normaliser, `speed_floor` Σ |a_P|)
    /// (a class without moving nodes counts 0): a class whose a_P-weighted mean speed is below
    /// `speed_floor` [m/s] is converged when its velocity error is below the tolerance times
    /// that floor.
    pub fn largest(&self, speed_floor: f64) -> f64 {
        self.sums
            .iter()
            .filter(|(_, den, _)| *den > 0.0)
            .map(|(num, den, a)| num / den.max(speed_floor * a))
            .fold(0.0, f64::max)
    }

    /// MFIX's pooled residual: Σ residual / Σ normaliser over every node and phase.
    pub fn pooled(&self) -> f64 {
        let (num, den) = self
            .sums
            .iter()
            .fold((0.0, 0.0), |(n, d), (a, b, _)| (n + a, d + b));
        if den > 0.0 {
            num / den
        } else {
            num
        }
    }
}

/// The convergence measure of one time step (module doc).
#[derive(Clone, Copy, Debug)]
pub(super) struct Convergence {
    /// normalisers of the gas and solids continuity residuals (their first iteration's)
    gas0: Option<f64>,
    solids0: Option<f64>,
    /// the hydrodynamic sum at the last multiple of 5 iterations (MFIX SUM5_RESID)
    sum5: f64,
}

impl Convergence {
    /// A step's measure before its first outer iteration.
    pub fn new() -> Self {
        Convergence {
            gas0: None,
            solids0: None,
            sum5: f64::INFINITY,
        }
    }

    /// The momentum and continuity residual sum of an outer iteration, and the normalisers
    /// of the gas and solids continuity. The gas residual's normaliser is its first
    /// iteration's value (MFIX's default), but not below `gas_floor`: a step that starts
    /// nearly converged otherwise has to reduce round-off-level imbalances (1e-9 of a mean
    /// cell's gas per step, flipping between two values in a dilute cell) by another 1e3
    /// and never does (S-JJ-phi coarse).
    pub fn sum(&mut self, r: &TwoFluidResiduals, gas_floor: f64) -> (f64, f64, f64) {
        let g = *self.gas0.get_or_insert(if r.gas_mass > f64::MIN_POSITIVE {
            r.gas_mass.max(gas_floor)
        } else {
            1.0
        });
        let s = *self
            .solids0
            .get_or_insert(if r.solids_mass > f64::MIN_POSITIVE {
                r.solids_mass
            } else {
                1.0
            });
        (r.momentum + r.gas_mass / g + r.solids_mass / s, g, s)
    }

    /// MFIX's stall test at outer iteration `nit` (docs/model.md §4.11): at every 5th
    /// iteration after the 10th, a sum not below its value 5 iterations before is a stall;
    /// returns that earlier value.
    pub fn stalled(&mut self, nit: usize, sum: f64) -> Option<f64> {
        if nit.is_multiple_of(5) {
            if nit > 10 && self.sum5 <= sum {
                return Some(self.sum5);
            }
            self.sum5 = sum;
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_head_is_not_hidden_by_the_packed_body() {
        let mut r = ClassedResidual::default();
        // a packed body of large a_P converged to 1e-5, a loose head to 1e-2
        r.add(1, NodeClass::Packed, 1e-5 * 1e6, 1e6, 1e6);
        r.add(1, NodeClass::Loose, 1e-2 * 1.0, 1.0, 1.0);
        r.add(0, NodeClass::Loose, 1e-4 * 10.0, 10.0, 10.0);
        assert!((r.largest(0.0) - 1e-2).abs() < 1e-15);
        // pooled, the head disappears below 1e-3
        assert!(r.pooled() < 2e-5);
        assert_eq!(ClassedResidual::default().largest(1e-6), 0.0);
        assert_eq!(NodeClass::of([(3.0, 1.0), (1.0, 1.0)]), NodeClass::Packed);
        assert_eq!(NodeClass::of([(1.5, 1.0)]), NodeClass::Loose);
    }

    /// A bed at rest (speeds 1e-10 m/s, its round-off 1e-3 of them) is converged against a
    /// floor of 1e-6 m/s; a moving class's residual is the same value, bit for bit.
    #[test]
    fn a_class_at_rest_is_measured_against_the_speed_floor() {
        let mut r = ClassedResidual::default();
        let (a, speed) = (1e6, 1e-10);
        r.add(1, NodeClass::Packed, 1e-3 * a * speed, a * speed, a);
        assert!((r.largest(0.0) / 1e-3 - 1.0).abs() < 1e-12);
        assert!((r.largest(1e-6) / 1e-7 - 1.0).abs() < 1e-12);
        let mut moving = ClassedResidual::default();
        moving.add(1, NodeClass::Loose, 0.37 * 2.5, 2.5, 1.0);
        assert_eq!(moving.largest(1e-6), moving.largest(0.0));
    }

    #[test]
    fn a_stall_is_a_sum_that_did_not_fall_over_five_iterations() {
        let mut c = Convergence::new();
        assert_eq!(c.stalled(5, 1.0), None);
        assert_eq!(c.stalled(7, 2.0), None);
        assert_eq!(c.stalled(10, 0.5), None);
        assert_eq!(c.stalled(15, 0.4), None);
        assert_eq!(c.stalled(20, 0.4), Some(0.4));
    }

    #[test]
    fn continuity_is_relative_to_the_first_iteration() {
        let mut c = Convergence::new();
        let r = |gas_mass, solids_mass| TwoFluidResiduals {
            momentum: 0.25,
            gas_mass,
            solids_mass,
            theta: 0.0,
        };
        assert_eq!(c.sum(&r(2.0, 4.0), 0.5), (2.25, 2.0, 4.0));
        assert_eq!(c.sum(&r(1.0, 1.0), 0.5), (0.25 + 0.5 + 0.25, 2.0, 4.0));
        // the gas normaliser is floored, a vanishing imbalance normalised by 1
        let mut c = Convergence::new();
        assert_eq!(c.sum(&r(0.1, 0.0), 0.5), (0.25 + 0.2, 0.5, 1.0));
    }
}
