//! # boltzone
//!
//! Where do two bolted plates stay in contact, and under what pressure? boltzone rebuilds the
//! system of Gould & Mikic, *Areas of contact and pressure distribution in bolted joints* (MIT
//! Engineering Projects Laboratory, Report DSR 71821-68, 1970) and goes beyond it:
//!
//! - [`hankel`]: the semi-analytic infinite-slab solution (Sneddon 1946) of a plate loaded
//!   symmetrically on both faces, with its own oscillatory quadrature and error estimates; the
//!   single-plate separation radius R_o of Fernlund's substitution;
//! - [`fem`]: an axisymmetric finite-element solver (the report's Appendices A and B);
//! - [`contact`]: the report's two-plate model, unilateral contact found automatically, R_o
//!   resolved below one element (`boltzone two`);
//! - [`material`], [`load`], [`joint`]: the input types, validated with typed errors ([`error`]);
//! - [`reference`]: the report's Tables 1 and 2 and the Chapter V table, as data.
//! - [`compare`]: single- vs two-plate R_o and the rules of thumb: Tables 1 and 2 recomputed,
//!   the design map; [`plot`]: SVG/PNG figures.
//! - [`rules`]: the 45° cone of Rötscher, the VDI 2230 deformation cone and other cone rules.
//!
//! Sign convention throughout: compression negative (σ_z = −p under a face pressure p > 0); z is
//! measured from the midplane (single plate) or the interface (joint); lengths and stresses in
//! any consistent units (the command-line tool uses inches and psi).
//!
//! ```
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! let load = FaceLoad::uniform(0.1, 0.31, 1.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Infinite, 0.1, Material::unit(0.3)?, load);
//! assert!(plate.is_ok());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![warn(missing_docs)]

pub mod compare;
pub mod contact;
pub mod error;
pub mod fem;
pub mod hankel;
pub mod heat;
pub mod joint;
pub mod load;
pub mod material;
pub mod plot;
pub mod reference;
pub mod rules;

pub use error::InputError;
pub use joint::{Joint, OuterRadius, Plate, SinglePlate};
pub use load::{FaceLoad, Peak, Profile, Segment};
pub use material::Material;
