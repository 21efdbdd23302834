//! The laboratory runout laws of the granular column collapse (`cargo xtask verify collapse`,
//! docs/collapse.md): (L∞ − L0)/L0 = λ1 a below the
//! crossover aspect ratio, λ2 a^{2/3} above it, after Lajeunesse et al. (2005) and Lube et
//! al. (2005).

/// A planar runout law (L∞ − L0)/L0 = λ1 a below the crossover, λ2 a^{2/3} above it
/// (verification-notes.md §2f, compiled from Lagrée, Staron & Popinet 2011 Eqs. 3.1–3.2;
/// not re-checked against the originals).
#[derive(Clone, Copy, Debug)]
pub struct ScalingLaw {
    /// short citation
    pub name: &'static str,
    /// what was collapsed
    pub material: &'static str,
    /// slope of the linear branch
    pub lambda1: f64,
    /// prefactor of the power branch
    pub lambda2: f64,
    /// exponent of the power branch (2/3 for the laboratory laws)
    pub exponent: f64,
    /// the crossover aspect ratio, as a range (a0_low, a0_high)
    pub a0: (f64, f64),
}

/// Lajeunesse, Monnier & Homsy (2005), Phys. Fluids 17:103302 (glass beads).
pub const LAJEUNESSE: ScalingLaw = ScalingLaw {
    name: "Lajeunesse et al. 2005",
    material: "glass beads",
    lambda1: 1.8,
    lambda2: 2.3,
    exponent: 2.0 / 3.0,
    a0: (3.0, 3.0),
};

/// Lube, Huppert, Sparks & Freundt (2005), Phys. Rev. E (sand, rice, sugar).
pub const LUBE: ScalingLaw = ScalingLaw {
    name: "Lube et al. 2005",
    material: "sand, rice, sugar",
    lambda1: 1.2,
    lambda2: 1.9,
    exponent: 2.0 / 3.0,
    a0: (1.8, 2.8),
};

/// The 2-D μ(I) continuum of Lagrée, Staron & Popinet (2011), J. Fluid Mech. 686:378
/// (their Eqs. 3.1–3.2 as verification-notes.md §2f compiles them; not re-checked against the
/// original): 2.2 a below a ≈ 7, 3.9 a^0.7 above. A simulation, not an experiment: the
/// like-for-like reference of a μ(I) continuum.
pub const LAGREE_CONTINUUM: ScalingLaw = ScalingLaw {
    name: "Lagrée et al. 2011 (2-D μ(I))",
    material: "μ(I) continuum",
    lambda1: 2.2,
    lambda2: 3.9,
    exponent: 0.7,
    a0: (7.0, 7.0),
};

impl ScalingLaw {
    /// The linear branch λ1 a.
    pub fn linear(&self, a: f64) -> f64 {
        self.lambda1 * a
    }

    /// The power branch λ2 a^exponent.
    pub fn power(&self, a: f64) -> f64 {
        self.lambda2 * a.powf(self.exponent)
    }

    /// (low, high) runout at `a`: one value outside the crossover range, the two branches
    /// inside it (a0_low ≤ a ≤ a0_high).
    pub fn runout(&self, a: f64) -> (f64, f64) {
        if a < self.a0.0 {
            (self.linear(a), self.linear(a))
        } else if a > self.a0.1 {
            (self.power(a), self.power(a))
        } else {
            let (l, p) = (self.linear(a), self.power(a));
            (l.min(p), l.max(p))
        }
    }

    /// The runout as a table entry: one value, or "low–high" in the crossover range.
    pub fn label(&self, a: f64) -> String {
        let (lo, hi) = self.runout(a);
        if hi - lo < 1e-9 {
            format!("{lo:.2}")
        } else {
            format!("{lo:.2}–{hi:.2}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn laws_match_the_notes_at_a_2() {
        // verification-notes.md §2f: "at a = 2" column
        assert!((LUBE.runout(2.0).0 - 2.4).abs() < 1e-12);
        assert!((LUBE.runout(2.0).1 - LUBE.power(2.0)).abs() < 1e-12);
        assert_eq!(LAJEUNESSE.runout(2.0), (3.6, 3.6));
        // the crossover: both branches at a = 3 for Lajeunesse, the power branch for Lube
        let (lo, hi) = LAJEUNESSE.runout(3.0);
        assert!((lo - 2.3 * 3f64.powf(2.0 / 3.0)).abs() < 1e-12 && (hi - 5.4).abs() < 1e-12);
        assert_eq!(LUBE.runout(6.0).0, LUBE.runout(6.0).1);
        // the continuum: the notes' 4.40 at a = 2; its branches meet near a0 = 7
        assert!((LAGREE_CONTINUUM.runout(2.0).0 - 4.4).abs() < 1e-12);
        let (lo, hi) = LAGREE_CONTINUUM.runout(7.0);
        assert!((hi - lo) / hi < 0.02, "{lo} {hi}");
    }
}
