//! The receding contact of an elastic layer on a frictionless rigid base: the report's
//! two-plate model (Ch. II.B, two equal plates) solved semi-analytically, an independent check
//! of the finite-element contact solver ([`crate::contact`]) that shares no FE code.
//!
//! - [`layer`]: the layer's Hankel kernels (bottom-face displacement under face pressures);
//! - `system`: the Fredholm equation of a contact disk r ≤ c, by Nyström's method;
//! - `search`: the scan and root search for R_o and the check of the unilateral conditions;
//! - [`contact`]: the solver ([`Layer::receding_contact`]) and its results (derivation,
//!   accuracy and cost there);
//! - [`pair`]: two unequal plates without a hole (the kernels of both in series, [`layer::Stack`]);
//! - [`layer_field`]: the layer's stresses at any height under a bottom (or top) pressure;
//! - [`rim_bending`]: the exact non-decaying states (membrane, bending) and the far field by
//!   reciprocity; [`rim`]: the finite rim r = C of the plate without a hole; `prescribed`: a
//!   prescribed displacement of the contact disk as a right-hand side (the rim's correction);
//! - [`holed`]: the two-plate model with the hole (bilateral holed plate + crack field + its
//!   hole correction, iterated), a folder of its own whose module docs list its files.
//!
//! # Accuracy
//!
//! `tests/hankel/receding_contact.rs` (force balance, complementarity, geometric convergence in the
//! basis size, the bilateral limit against the slab) and `tests/hankel/receding_kernels.rs`
//! (kernels against the general Love solution and its limits); against the finite elements in
//! `tests/contact/receding_vs_fe.rs`; two unequal plates in `tests/hankel/receding_pair.rs`
//! (and against the FE over 200 random pairs: example 16, route `two0u`).
//!
//! # Cost
//!
//! Example 06 times the contact radius against its error.
//!
//! ```
//! use boltzone::{FaceLoad, Material};
//! use boltzone::hankel::receding::{Layer, RecedingParams};
//! let layer = Layer::new(1.0, Material::unit(0.3)?, FaceLoad::uniform(0.0, 1.0, 1.0)?)?;
//! let contact = layer.receding_contact(&RecedingParams::default())?;
//! assert!(contact.r_o > 1.0 && contact.info.r_o_error < 1e-8);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod contact;
pub mod holed;
pub mod layer;
pub mod layer_field;
pub mod pair;
mod prescribed;
pub mod rim;
pub mod rim_bending;
mod search;
mod system;

pub use contact::{
    contact_radius, nodes, ContactSolution, Layer, RecedingContact, RecedingError, RecedingInfo,
    RecedingParams,
};
pub use holed::{AUTO_BELOW, MAX_B_OVER_D, MAX_B_OVER_D_RIM, MIN_A_OVER_D};
pub use pair::Pair;
