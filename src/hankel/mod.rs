//! Semi-analytic solutions by Hankel transforms (Sneddon 1946): the infinite slab, the slab with
//! a hole (`hole/`), the receding contact of a layer (`receding/`).
//!
//! **What.** The slab −D ≤ z ≤ D (thickness 2D, no hole) pressed by the same face load p(r) on
//! both faces: Fernlund's single-plate substitute of a symmetric bolted joint (report Ch. II.A,
//! Fig. 3). Every stress and displacement at any (r, z), and the separation radius R_o, the
//! first upward zero of the midplane σ_z(r, 0) beyond B. Compression negative; any consistent
//! units.
//!
//! - [`kernel`]: the slab's Hankel kernels in overflow-free form, with their derivation;
//!   [`kernel_shear`]: the same for a radial shear traction on the faces (the hole's corner
//!   enrichment loads the faces by both);
//! - [`transform`]: the load's transform p̄(ξ), computed once per slab;
//! - [`field`]: [`Slab`], every stress and displacement at any (r, z) with error estimates;
//! - [`midplane`]: the midplane σ_z(r, 0) fast, on a node set shared by all radii, and the curve;
//! - [`realspace`]: the midplane σ_z of thin slabs by a localised real-space point kernel;
//! - [`separation`]: the separation radius R_o; [`slab_compliance`]: the member compliance of
//!   the slab without a hole (the single-plate substitute);
//! - [`hole`]: the single plate with a hole (and a finite rim): Lamé and Papkovich–Fadle modes
//!   fitted on r = A (and r = C), R_o with the hole residual as its error measure;
//! - [`receding`]: the receding contact of a layer on a frictionless rigid base — the two-plate
//!   model solved semi-analytically, an independent check of the FE contact solver.
//!
//! The generic numerics they use (oscillatory quadrature, Brent, Bessel functions, Chebyshev
//! interpolation) live in [`crate::numerics`].
//!
//! **Method.** Any field at any (r, z): one adaptive partition–extrapolation per point
//! ([`Slab::stress`], [`Slab::displacement`]); when the panel budget
//! ([`QuadParams::max_panels`]) runs out the value comes back with an error estimate that
//! includes the gap between extrapolation and plain partial sum — large, never silent. Midplane
//! σ_z at many radii ([`Midplane`]): a shared ξ-node rule ([`MidplaneRule`]; a few hundred to
//! 50 000 nodes, cost ∝ (r_max + B)/D), or, for thin slabs where that would need more, the
//! real-space superposition of a point kernel localised within 18D ([`realspace`]), whose cost
//! does not grow with B/D or r/D. R_o ([`Slab::separation_radius`]): a scan and Brent's method
//! on one [`Midplane`] evaluator.
//!
//! # Accuracy
//!
//! Every error estimate covers the actual error on closed forms (Boussinesq on the axis, the
//! wide-load limit, equilibrium, compatibility; `tests/hankel/slab.rs`,
//! `field_error_estimates_cover_the_actual_error`). The two midplane routes agree to ~1e-15 where
//! both run (`tests/hankel/separation.rs`, `real_space_and_xi_routes_agree`), which keeps D/A ∈
//! [1e-3, 1e3], B/A ∈ [1.001, 1e3] and r ≤ 10³B finite and accurate; R_o's achieved error is below
//! its estimate for tolerances 1e-4 … 1e-12 (example 01).
//!
//! # Cost
//!
//! Per field point, grows with (r + B)·(decay length)⁻¹; R_o to 1e-10 and the 1000-radius midplane
//! curve: `cargo bench --bench hankel`; time against error: example 01.
//!
//! ```
//! use boltzone::{FaceLoad, Material, hankel::{Slab, SeparationParams}};
//! let slab = Slab::new(0.1, Material::unit(0.3)?, FaceLoad::uniform(0.1, 0.31, 1.0)?)?;
//! let sep = slab.separation_radius(&SeparationParams::default())?;
//! assert!(sep.r_o > 0.31 && sep.r_o_error < 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod field;
pub mod hole;
pub mod kernel;
pub mod kernel_shear;
pub mod midplane;
pub mod realspace;
pub mod receding;
pub mod separation;
pub mod slab_compliance;
pub mod transform;

// Former homes, kept so that old paths work.
pub use crate::numerics::{quadrature, root};
pub use receding::layer;

pub use crate::numerics::quadrature::{Estimate, QuadParams};
pub use field::{
    displacement_for_transform, ring_load, stress_for_transform, Displacement, Slab, StressEstimate,
};
pub use midplane::{Midplane, MidplaneCurve, MidplaneRule};
pub use separation::{SeparationInfo, SeparationParams};
