//! Axisymmetric solid elements in the (r, z) half-plane.
//!
//! Displacement (u, w) = (u_r, u_z); strains ε = (ε_r, ε_z, ε_θ, γ_rz) with
//! ε_r = ∂u/∂r, ε_z = ∂w/∂z, ε_θ = u/r, γ_rz = ∂u/∂z + ∂w/∂r (the hoop strain u/r is what makes the
//! problem axisymmetric). Stresses σ = (σ_r, σ_z, σ_θ, τ_rz) = D ε with the isotropic
//! D = [[λ+2μ, λ, λ, 0], [λ, λ+2μ, λ, 0], [λ, λ, λ+2μ, 0], [0, 0, 0, μ]] (report eqs. 2.3, A.5).
//! The stiffness k = ∫ Bᵀ D B dV with dV = 2πr dr dz (A.10): forces are whole-ring forces (the
//! 1970 program used one radian; divide by 2π to compare).
//!
//! Element kinds ([`ElementKind`]), one module each:
//! - [`cst4`]: the report's quadrilateral, four constant-strain triangles around a condensed
//!   centre node (Appendix A, eq. A.21);
//! - [`q4`]: the bilinear isoparametric quadrilateral, 2×2 Gauss, and its B-bar (mean
//!   dilatation) variant for nearly incompressible materials;
//! - [`q9`]: the biquadratic Lagrange quadrilateral, 3×3 Gauss.
//!
//! Quadrature points never lie on the axis r = 0, so u/r is always evaluated where r > 0. Nodes
//! may lie on the axis: there the hoop strain is taken as its limit ∂u/∂r (u = 0 on the axis).
//!
//! Sign convention: tension positive, compression negative.
//!
//! # Accuracy
//!
//! Symmetric stiffness with exactly one rigid-body mode and the patch tests (displacement- and
//! traction-driven, skew rollers) to round-off for every kind (`tests/fem/elements.rs`);
//! convergence orders on the Lamé cylinder (`tests/fem/lame.rs`).
//!
//! # Cost
//!
//! Per element, 4–9 quadrature points; assembly in `cargo bench --bench fem`.
//!
//! ```
//! use boltzone::fem::element::ElementKind;
//! use boltzone::Material;
//! let x = [[1.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0]];
//! let k = ElementKind::Q4.stiffness(&x, &Material::unit(0.3)?);
//! assert!((k[1] - k[8]).abs() < 1e-15 * k[0].abs()); // symmetric
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod common;
pub mod cst4;
mod iso;
mod kind;
pub mod q4;
pub mod q9;
pub mod thermal;

pub(crate) use common::{add_btdb, add_btdb_nodes, apply_d, mirror_upper, strain, GAUSS2, GAUSS3};
pub use common::{elasticity, ElementPoint, Stress};
pub use kind::ElementKind;
