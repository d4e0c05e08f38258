//! Heat through a bolted joint (report Chapter I eq. 1.1–1.6, Chapter V, Appendix D): contact
//! conductance from the interface pressure, the joint's conductance over its contact zone, and
//! the conductance network of Appendix D with a reader for its card decks.
//!
//! - [`units`]: SI newtypes with the report's units (Btu/hr·ft·°F, in, psi, µin) as named
//!   conversions;
//! - [`correlation`]: h_c(P) of Cooper, Mikic & Yovanovich 1969 (eq. 1.1), Yovanovich 1982,
//!   Mikic's elastic form and a user power law; h_f of an interstitial fluid (eq. 1.6), gas-gap
//!   conduction and radiation;
//! - [`joint`]: ∫ h_c(p(r)) 2πr dr over the contact zone of a two-plate solution, ring by ring as
//!   the Chapter V table, plus gas and radiation across the open gap;
//! - [`network`]: the steady conductance-network solver of Appendix D; [`deck`]: its card decks
//!   (fields per [`crate::fortran`]);
//! - [`lap`]: Chapter V's lap joint as such a network, with the geometry it assumes;
//! - [`conduction`]: steady axisymmetric conduction on the [`crate::fem`] meshes, plates joined
//!   by an interface conductance h(r); [`zone`]: a joint's contact-zone resistance by it.
//! - [`coupled`]: the two-plate joint under the temperature its own heat flow sets (contact →
//!   h_c(p) → conduction → thermal contact, to a fixed point: a scene's `from_heat`).
//!
//! Sign convention: interface pressure p > 0 in compression (σ_z = −p); heat flows toward a node
//! are positive.
//!
//! # Accuracy
//!
//! Each file's Accuracy section; the test crate is `tests/heat/`.
//!
//! # Cost
//!
//! Each file's Cost section; example 15 (the lap joint).
//!
//! ```
//! use boltzone::heat::units::{Conductance, Resistance};
//! let g = Conductance::btu_per_hr_f(1.0);
//! let r = Resistance::from_si(1.0 / g.si());
//! assert!((r.to_f_hr_per_btu() - 1.0).abs() < 1e-12);
//! ```

pub mod conduction;
pub mod correlation;
pub mod coupled;
pub mod deck;
pub mod joint;
pub mod lap;
pub mod network;
pub mod units;
pub mod zone;
