//! Semi-analytic infinite-slab solutions by Hankel transforms (Sneddon 1946).
//!
//! The slab −D ≤ z ≤ D (thickness 2D, no hole) is pressed by the same face load p(r) on both
//! faces: Fernlund's single-plate substitute of a symmetric bolted joint. Split by verb:
//!
//! - [`quadrature`]: ∫₀^∞ f(ξ) dξ for oscillatory f (partition–extrapolation, Wynn's ε);
//! - [`kernel`]: the slab's Hankel kernels in overflow-free form, with their derivation;
//! - [`transform`]: the load's transform p̄(ξ), computed once per slab;
//! - [`field`]: [`Slab`], every stress and displacement at any (r, z) with error estimates;
//! - [`midplane`]: the midplane σ_z(r, 0) fast, on a node set shared by all radii, and the curve;
//! - [`realspace`]: the midplane σ_z of thin slabs by a localised real-space point kernel;
//! - [`separation`]: the separation radius R_o (first upward zero of σ_z(r, 0) beyond B).
//!
//! ```
//! use boltzone::{FaceLoad, Material, hankel::{Slab, SeparationParams}};
//! let slab = Slab::new(0.1, Material::unit(0.3).unwrap(), FaceLoad::uniform(0.1, 0.31, 1.0).unwrap()).unwrap();
//! let sep = slab.separation_radius(&SeparationParams::default()).unwrap();
//! assert!(sep.r_o > 0.31 && sep.error < 1e-9);
//! ```

pub mod field;
pub mod hole;
pub mod kernel;
pub mod midplane;
pub mod quadrature;
pub mod realspace;
pub mod separation;
pub mod transform;

pub use field::{Displacement, Slab, Stress};
pub use midplane::{Midplane, MidplaneCurve, MidplaneRule};
pub use quadrature::{Estimate, QuadParams};
pub use separation::{SeparationInfo, SeparationParams};
