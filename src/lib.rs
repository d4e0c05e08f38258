//! # boltzone
//!
//! Where do two bolted plates stay in contact, and under what pressure? boltzone rebuilds the
//! system of Gould & Mikic, *Areas of contact and pressure distribution in bolted joints* (MIT
//! Engineering Projects Laboratory, Report DSR 71821-68, 1970) and goes beyond it: the report's finite-element models, an
//! independent semi-analytic route for each, error estimates on every result, and the rules of
//! thumb compared with both.
//!
//! ## Layers, top to bottom
//!
//! A module imports only modules of the layers below it, and siblings on one layer do not
//! import each other: the import graph has no circles and no upward arrow. Each folder's
//! `mod.rs` opens with what the folder computes and lists its files.
//!
//! 1. the `boltzone` command (`src/cli/`, `src/main.rs`): one module per subcommand, no
//!    numerics;
//! 2. [`figures`] | [`scene`]: the report's Figs. 12–29 recomputed | scene files: a joint and
//!    the question in the user's units, answered with what the layers below offer (`boltzone
//!    solve`, its heat and field outputs);
//! 3. [`compare`] | [`heat`] | [`io`]: single- vs two-plate R_o and the rules of thumb: Tables 1
//!    and 2 recomputed, the design map | heat through the joint: contact conductance, the
//!    Appendix D network, conduction | the 1970 card decks of Appendices B and C, read, run and
//!    written, and the VTU field writer;
//! 4. [`route`]: the route layer: one typed question (joint, load, interface, outputs,
//!    [`route::Method`], tolerance) → the route that answers it and why; each route's reach and
//!    the `auto` choice are stated here and nowhere else, and every front end asks it;
//! 5. [`contact`]: the report's two-plate model on the finite elements, unilateral contact
//!    found automatically, R_o resolved below one element (`boltzone two`);
//! 6. [`hankel`] | [`fem`] | [`table`]: the semi-analytic slab solutions (the slab,
//!    `hankel::hole`, the receding contact `hankel::receding`) | the axisymmetric finite
//!    elements (the report's Appendices A and B, the single plate) | R_o from tables built
//!    offline by the semi-analytic routes, with error bars (the far region, the decay law);
//! 7. [`joint`]: the plates and the joint; [`bolt`]: the bolt's thread, resilience, load factor
//!    and preload (VDI 2230);
//! 8. [`material`], [`load`], [`rules`] (the 45° cone of Rötscher, the VDI 2230 cone and other
//!    cone rules), [`plot`] (SVG/PNG figures);
//! 9. [`numerics`] (quadrature, roots, special functions, interpolation, convergence
//!    estimates), [`fortran`] (the 1970 punched cards: one fixed-column field reader, one blank
//!    policy, the one deck error type [`fortran::DeckError`]), [`error`] (typed input
//!    errors), [`reference`](mod@reference) (the report's Tables 1 and 2 and the Chapter V
//!    table, as data), [`fsutil`] (files written whole or not at all), [`value`] (the one
//!    value-with-error type [`Value`]: value, error, converged), [`units`] (the three unit
//!    systems and their exact factors).
//!
//! Sign convention throughout: compression negative (σ_z = −p under a face pressure p > 0); z is
//! measured from the midplane (single plate) or the interface (joint); lengths and stresses in
//! any consistent units (the command-line tool uses inches and psi unless `--units` says
//! otherwise; scenes are solved in SI).
//!
//! # Accuracy
//!
//! Each module's Accuracy section names the test or example that re-measures it; one test crate per
//! folder under `tests/`, every example run at a quick size by `tests/examples/`.
//!
//! # Cost
//!
//! Each module's Cost section; `cargo bench` (benches `hankel`, `fem`, `contact`, `hole`).
//!
//! ```
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! let load = FaceLoad::uniform(0.1, 0.31, 1.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Infinite, 0.1, Material::unit(0.3)?, load);
//! assert!(plate.is_ok());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
#![warn(missing_docs)]

pub mod bolt;
pub mod compare;
pub mod contact;
pub mod error;
pub mod fem;
pub mod figures;
pub mod fortran;
pub mod fsutil;
pub mod hankel;
pub mod heat;
pub mod io;
pub mod joint;
pub mod load;
pub mod material;
pub mod numerics;
pub mod plot;
pub mod reference;
pub mod route;
pub mod rules;
pub mod scene;
pub mod table;
pub mod units;
pub mod value;

/// README.md's Rust example, compiled and run as a doctest.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;

pub use error::InputError;
pub use joint::{Joint, OuterRadius, Plate, SinglePlate};
pub use load::{FaceLoad, Peak, Profile, Segment};
pub use material::Material;
pub use scene::solve;
pub use value::Value;
