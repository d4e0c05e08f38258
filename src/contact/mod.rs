//! Unilateral contact of bolted plates: the report's two-plate model (Chapter II.B).
//!
//! Two plates pressed together by a bolt touch only near the bolt, for A ≤ r ≤ R_o. The contact
//! zone is unknown; it follows from the Signorini conditions on the interface (report eq. 2.7):
//! gap g ≥ 0, interface pressure p ≥ 0, g·p = 0. Sign convention: p > 0 is compression
//! (σ_z = −p on the interface), g > 0 an open gap.
//!
//! - [`lcp`]: the interface LCP g = g⁰ + Fλ solved by primal–dual active sets (semismooth Newton)
//!   with a Murty fallback; [`pgs`]: projected Gauss–Seidel as an independent check;
//! - [`friction`]: Coulomb friction on the interface (open, stick and slip states);
//! - [`separation`]: R_o finer than one element from the √(R_o − r) pressure and the
//!   (r − R_o)^{3/2} gap of a smooth separation;
//! - [`params`]: the model's input (interface model, loading, edge support, study knobs);
//! - [`two_plate`]: the model (symmetric pair on a rigid plane, unequal or dissimilar pairs
//!   welded or frictionless, the report's load variants), level after level of a mesh refined at
//!   R_o; [`level`]: one mesh level on [`crate::fem`] (one factorization, a Schur complement on
//!   the interface window, the LCP); [`tie`]: tied unknowns of closed pairs;
//! - [`compliance`]: the member compliance δ_P and stiffness k_P of the joint from the contact
//!   solution;
//! - `level_compliance`: δ_P of one solved level (by work, or the rigid head's reaction);
//! - [`thermal`]: the model with a temperature field (uniform, linear through each plate, or
//!   from heat conduction) and thermal strains.
//!
//! The semi-analytic check of the symmetric case is [`crate::hankel::receding`].
//!
//! # Accuracy
//!
//! `tests/contact/`: the LCP solver against brute-force enumeration of active sets, projected
//! Gauss–Seidel and the KKT conditions (`lcp.rs`); the R_o estimators on synthetic data with a
//! known R_o (`separation.rs`); the model's equilibrium, complementarity, observed order and error
//! estimate (`two_plate.rs`); the semi-analytic receding contact (`receding_vs_fe.rs`).
//!
//! # Cost
//!
//! `cargo bench --bench contact`.
//!
//! ```
//! use boltzone::contact::{solve_lcp, Lcp, LcpParams};
//! use nalgebra::{DMatrix, DVector};
//! let lcp = Lcp::frictionless(DMatrix::identity(1, 1), DVector::from_vec(vec![-2.0]));
//! assert_eq!(solve_lcp(&lcp, &LcpParams::default())?.force[0], 2.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod compliance;
mod cut;
pub mod edge_fit;
mod error;
pub mod field;
pub mod friction;
mod friction_level;
pub mod lcp;
pub mod level;
mod level_compliance;
mod level_types;
pub mod params;
pub mod pgs;
mod refine;
pub mod separation;
mod temperature;
pub mod thermal;
pub mod tie;
pub mod two_plate;
mod two_plate_level;

pub use error::ContactError;
pub use lcp::{solve_lcp, solve_lcp_from, Lcp, LcpInfo, LcpParams, LcpSolution};
pub use pgs::projected_gauss_seidel;
