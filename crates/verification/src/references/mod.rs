//! Reference solutions, kept apart from the code they judge: published tables, closed forms
//! and other codes' numbers, each with its citation. The 1-D chute reference solver is a
//! computed reference of its own ([`crate::chute1d`]).
//!
//! - [`ghia`]: the lid-driven cavity's centreline velocities, Ghia, Ghia & Shin (1982);
//! - [`botella_peyret`]: the same at Re = 1000 from the spectral solution of Botella &
//!   Peyret (1998), with the centreline extrema;
//! - [`haff`]: homogeneous cooling, Haff's law (1983) and its form with viscous damping;
//! - [`runout_laws`]: the laboratory runout laws of the column collapse, Lajeunesse et al.
//!   (2005) and Lube et al. (2005);
//! - [`mfix_family_m`]: MFIX 21.3.2's front, mean velocity and cost for family M.
//! - [`pore_pressure`]: pore-pressure diffusion in a rigid bed whose aeration is shut off
//!   (Carslaw & Jaeger 1959);
//! - [`consolidation`]: the same bed compacting by Princeton's P_c as its gas drains, the
//!   nonlinear consolidation (Terzaghi 1925) with the gas's storage, solved in 1-D.
//!
//! The closed forms of the single-phase problems (the partial-slip Poiseuille profile, the
//! decaying Taylor–Green vortex) sit beside their problems in [`crate::problems`], where
//! their derivations are.

pub mod botella_peyret;
pub mod consolidation;
pub mod ghia;
pub mod haff;
pub mod mfix_family_m;
pub mod pore_pressure;
pub mod runout_laws;

pub use botella_peyret::*;
pub use ghia::*;
pub use haff::*;
pub use mfix_family_m::*;
pub use runout_laws::*;
