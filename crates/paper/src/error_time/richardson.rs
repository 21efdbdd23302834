//! The observed order of accuracy from the three finest levels
//! ([`runout_post::convergence::observed_order`]), and whether it lies in the scheme's
//! asymptotic range (which decides whether the Richardson extrapolation of
//! [`super::errors`] is to be trusted).

pub(super) use runout_post::gci::{asymptotic, ASYMPTOTIC_BAND};

/// The observed order of a quantity from the three finest levels.
#[derive(Clone, Debug, PartialEq)]
pub struct Order {
    /// the three levels (indices into the ladder), finest first
    pub levels: [usize; 3],
    /// norm of (level 2 − level 1) and of (level 3 − level 2), in the quantity's unit
    pub d21: f64,
    /// see `d21`
    pub d32: f64,
    /// the observed order, if the differences shrink at a positive rate (p ≤ 20)
    pub p: Option<f64>,
}
