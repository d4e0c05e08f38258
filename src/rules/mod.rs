//! Rules of thumb for a bolted joint: cones of pressure spreading from the bearing face through
//! the plates, for the contact radius ([`cone_radius`](mod@cone_radius)) and for the clamped
//! parts' stiffness k_P.
//!
//! - [`cone_radius`](mod@cone_radius): Rötscher's 45° cone, any cone, VDI 2230's cone angle, as
//!   contact radii;
//! - [`vdi2230_stiffness`]: VDI 2230 Part 1 (2015) §5.1.2.2, the substitute deformation cone
//!   with sleeve of a through-bolted joint (DSV): φ_D, D_A,Gr and the three cases;
//! - [`shigley`]: Shigley's 30° frusta (Budynas & Nisbett, *Shigley's Mechanical Engineering
//!   Design*, 9th ed., Eqs. 8-18, 8-20, 8-22);
//! - [`wileman`]: the exponential fit of Wileman, Choudury & Green (ASME J. Mech. Des. 113,
//!   1991; Shigley Eq. 8-23, Table 8-8).
//!
//! Without a catalogue bolt the stiffness rules take the bolt diameter d = 2A (the hole's) and
//! the bearing diameter d_W = 2B; with one, the bolt's d, its hole and its head's bearing
//! diameter. The exact k_P they approximate is [`crate::contact::compliance`]'s.
//!
//! # Accuracy
//!
//! Closed forms. `tests/joint/rules.rs` reproduces the published worked examples to their
//! printed digits and checks the VDI closed forms against a quadrature of the cone;
//! `tests/joint/bolt.rs` sets VDI's cone beside the exact k_P of an M10 joint.
//!
//! # Cost
//!
//! O(1): a few logarithms per rule.
//!
//! ```
//! use boltzone::rules::{cone_radius, vdi2230_tan_phi};
//! let r = cone_radius(0.31, 0.1, 45f64.to_radians(), f64::INFINITY)?;
//! assert!((r.radius - 0.41).abs() < 1e-15);
//! assert!((vdi2230_tan_phi(2.0, 1.0)? - 0.362).abs() < 1e-15);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod cone_radius;
pub mod shigley;
pub mod vdi2230_stiffness;
pub mod wileman;

pub use cone_radius::{cone_radius, roetscher, vdi2230, vdi2230_tan_phi, ConeRadius};
