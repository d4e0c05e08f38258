//! Axisymmetric finite elements (report Appendices A and B, rebuilt).
//!
//! Linear elasticity of solids of revolution under axisymmetric load, in the (r, z) half-plane:
//! find u = (u_r, u_z) with ∫ ε(v)ᵀ D ε(u) 2πr dr dz = ∫ v·t 2πr ds for all admissible v
//! (eqs. A.6–A.15), ε = (∂u/∂r, ∂w/∂z, u/r, ∂u/∂z + ∂w/∂r). Forces are whole-ring forces
//! (2π × the report's per-radian forces); stresses are tension positive (a face pressure p > 0
//! gives σ_z = −p); units are the caller's.
//!
//! The pipeline, one module per verb:
//! - [`spacing`], [`mesh`]: graded structured meshes of one plate or a stack of plates, and
//!   meshes of any topology ([`Mesh::from_elements`], e.g. a 1970 card deck, [`crate::io::deck`]);
//! - [`element`]: the report's 4-CST quadrilateral, Q4 (and B-bar), Q9;
//! - [`dofs`]: supports (rollers, fixed, prescribed, the report's skew rollers) and the
//!   (node, component) → equation map;
//! - [`loads`]: consistent nodal forces of face pressures and point loads;
//! - [`assemble`](mod@assemble), [`ordering`], [`solve`]: sparse symmetric K with a fixed pattern, a
//!   nested-dissection ordering of structured meshes, faer's sparse Cholesky (one symbolic
//!   analysis, numeric refactorization, many right-hand sides);
//! - [`recover`]: stresses at Gauss points, element centres and nodes; reactions; the traction
//!   along a supported line;
//! - [`thermal`]: temperatures per node, E(T), ν(T), α(T), thermal loads and stresses
//!   σ = D (ε − ε_th) (Appendix C on every element);
//! - [`single`]: the single-plate model (Fernlund's substitution) and its separation radius R_o;
//!   [`single_compliance`]: its member compliance δ_P, with the level estimate of
//!   [`compliance_estimate`] shared with the two-plate model;
//! - [`lame`]: the Lamé cylinder, the closed-form check of the elements;
//! - [`error`]: [`FemError`], the failures of all of the above.
//!
//! For a contact model: build a stack with [`Mesh::structured`] (each plate has its own
//! interface nodes, [`Mesh::top`]/[`Mesh::bottom`] sorted by r), constrain with [`Supports`],
//! number with [`DofMap`], assemble once ([`Pattern`], [`assemble()`](fn@assemble)), factor once
//! ([`Factorization`]), form flexibilities with [`Factorization::solve_many`], and read interface
//! forces with [`reactions`] and tractions with [`line_traction`].
//!
//! # Accuracy
//!
//! The Lamé cylinder converges at order 2 (linear elements) and 3 (Q9), and B-bar and Q9 do not
//! lock at ν = 0.499 (`tests/fem/lame.rs`, example 02); patch tests and assembly in
//! `tests/fem/elements.rs`, `tests/fem/system.rs`; the single plate against the Hankel routes in
//! `tests/fem/hankel_agreement.rs` and `tests/fem/hole_agreement.rs`.
//!
//! # Cost
//!
//! Mesh, assembly, factorization and solve against size: `cargo bench --bench fem` (10⁴, 10⁵
//! equations) and example 08 (to 10⁶).
//!
//! ```
//! use boltzone::fem::single::{single_plate_r_o, SingleParams};
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! let load = FaceLoad::uniform(0.1, 0.31, 1.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Finite(1.54), 0.1,
//!                              Material::unit(0.3)?, load)?;
//! let params = SingleParams { levels: 3, ..SingleParams::default() };
//! let (r_o, info) = single_plate_r_o(&plate, &params)?;
//! assert!(r_o > 0.31 && r_o < 0.6, "{r_o}");
//! assert!(info.error_estimate < 0.01);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod assemble;
pub mod compliance_estimate;
pub mod dofs;
pub mod element;
pub mod error;
pub mod exterior;
pub mod lame;
pub mod loads;
pub mod mesh;
pub mod midplane_crossing;
pub mod ordering;
pub mod plate_temperature;
pub mod recover;
pub mod single;
pub mod single_compliance;
pub mod single_levels;
pub mod single_temperature;
pub mod single_thermal;
pub mod solve;
pub mod spacing;
pub mod thermal;

pub use assemble::{assemble, Pattern, Stiffness};
pub use dofs::{Component, DofMap, NodeSupport, Supports};
pub use element::{ElementKind, ElementPoint, Stress};
pub use error::FemError;
pub use loads::Loads;
pub use mesh::{Mesh, PlateSpec};
pub use ordering::{nested_dissection, node_dissection};
pub use recover::{
    centre_stresses, gauss_stresses, internal_forces, line_traction, nodal_mean, nodal_stresses,
    reactions,
};
pub use solve::{Factorization, SolveParams};
pub use spacing::Spacing;
