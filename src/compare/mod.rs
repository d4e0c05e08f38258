//! Single-plate substitution against the two-plate model, and both against the rules of thumb:
//! the report's Table 1 (Chapter IV.A), its Table 2 (Chapter IV.B, tests) and a design map.
//!
//! For a symmetric joint — two equal plates D thick, hole radius A, bearing face out to B, plate
//! radius C, Poisson's ratio ν, uniform bearing pressure — [`compare`] computes:
//!
//! - R_o of the **single-plate substitution** (Fernlund: one plate 2D thick, pressed on both
//!   faces; R_o where the midplane σ_z first turns tensile beyond B), by finite elements with the
//!   finite rim C ([`single::single_fem`], an adaptive driver over [`crate::fem::single`]), and
//!   optionally by Hankel transforms with the hole correction for an infinite plate
//!   ([`single::single_hankel`], [`crate::hankel::hole`]) as an independent second method;
//! - R_o of the **two-plate model** (one plate on a frictionless rigid plane, unilateral contact;
//!   [`crate::contact::two_plate`]);
//! - with [`CompareParams::method`] other than the default FE, either model by its
//!   semi-analytic Hankel route on the same finite rim C ([`route`]: [`Method::Hankel`], or
//!   [`Method::Auto`] where the route applies and converges); each value records its method
//!   ([`Route`]);
//! - the report's **discrepancy** (R_single − R_two)/R_two·100 (Table 1's last column) and the
//!   discrepancy in **contact area** π(R_o² − A²): (X_single − X_two)/X_two·100, X = R_o² − A²;
//! - the **rules of thumb** ([`crate::rules`]): Rötscher's 45° cone R = B + D, the VDI 2230
//!   (2003) substitute deformation cone with D′_A = 2C, and a 30° cone; each with its error
//!   (R_rule − R_two)/R_two·100 against the two-plate answer.
//!
//! Every R_o carries an error estimate; derived percentages carry the first-order propagation of
//! those estimates (|∂f/∂R_s|·e_s + |∂f/∂R_t|·e_t). Lengths in any one unit (the tables: inches);
//! R_o does not depend on E or on the load's magnitude. The report's values are never inputs:
//! [`table1`] and [`table2`] only print them beside ours, from [`crate::reference`].
//!
//! # Accuracy
//!
//! Every R_o to the tolerance asked by its own estimate; the estimates are checked in the solvers'
//! tests and examples 13 and 14; the tables end to end in `tests/compare/tables.rs`.
//!
//! # Cost
//!
//! `cargo bench --bench contact` (all of Table 1) and example 13 (per map point).
//!
//! ```
//! use boltzone::compare::{compare, CompareParams, Geometry};
//! let g = Geometry::from_ratios(0.1, 1.0, 3.1, 1.54, 0.3)?; // Table 1, first row
//! let c = compare(&g, &CompareParams { tolerance: 2e-3, ..Default::default() })?;
//! assert!(c.single.value > c.two.value);                 // the substitution overpredicts
//! assert!(c.rules[0].is_some_and(|r| r.radius > c.two.value)); // so does the 45° cone
//! assert!(c.two.error <= 2e-3 * c.two.value);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod comparison;
mod error;
mod geometry;
pub mod map;
pub mod route;
pub mod single;
pub mod table1;
pub mod table2;

pub use crate::value::Value;
pub use comparison::{
    compare, compare_all, percent_difference, show, CompareInfo, CompareParams, Comparison,
    RuleResult,
};
pub use error::CompareError;
pub use geometry::Geometry;
pub use route::{table_reach, two_hankel_reach, two_takes_hankel, Method, Route};
