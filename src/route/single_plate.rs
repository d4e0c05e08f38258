//! The single-plate substitute's routes (Fernlund's substitution, report Chapter II.A): which one
//! answers a question, and the semi-analytic route's knobs for a tolerance.
//!
//! - the **Hankel route with the hole correction**
//!   ([`crate::hankel::hole::single_plate_separation`]): R_o alone, a root search of
//!   milliseconds, any rim (bounded where too far to matter, fitted otherwise);
//! - the **finite elements** ([`crate::fem::single`]): also the field, the midplane σ_z curve,
//!   a rigid nut (a uniform displacement) and thermal strains.
//!
//! `auto` takes the Hankel route unless an output or input asks for the finite elements.
//!
//! # Accuracy
//!
//! No numerics; the routes' own.
//!
//! # Cost
//!
//! None.
//!
//! ```
//! use boltzone::route::{single_plate, Method};
//! let q = single_plate::Question { method: Method::Auto, ..Default::default() };
//! assert_eq!(single_plate::plan(&q).method, Method::Hankel);
//! let field = single_plate::Question { field: true, ..q };
//! assert_eq!(single_plate::plan(&field).method, Method::Fem);
//! let (search, _hole) = single_plate::hankel_params(1e-6);
//! assert!(search.rel_tol <= 1e-9);
//! ```

use super::two_plate::Plan;
use super::Method;
use crate::hankel::hole::HoleParams;
use crate::hankel::SeparationParams;

/// What a single-plate question asks beyond R_o, and by which method.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Question {
    /// The method asked for.
    pub method: Method,
    /// The field or the midplane σ_z curve from the finite elements' levels is wanted.
    pub field: bool,
    /// The faces are loaded by a rigid nut (a uniform displacement), not a pressure.
    pub rigid_nut: bool,
    /// The plate carries temperatures (thermal strains).
    pub thermal: bool,
    /// The bearing face's reach B/D (D the plate's half-thickness; 0 when not known): beyond
    /// [`super::reach::B_OVER_D_SINGLE_HANKEL`] `auto` takes the finite elements.
    pub b_over_d: f64,
}

/// The route for `q` (module docs).
pub fn plan(q: &Question) -> Plan {
    let (method, why) = match q.method {
        Method::Fem => (Method::Fem, "finite elements (asked)"),
        Method::Hankel => (Method::Hankel, "Hankel + hole correction (asked)"),
        Method::Table => (
            Method::Hankel,
            "Hankel + hole correction: the tables are the two-plate model's (milliseconds here)",
        ),
        Method::Auto if q.thermal => (
            Method::Fem,
            "finite elements: the thermal strains are in the FE model only",
        ),
        Method::Auto if q.field => (
            Method::Fem,
            "finite elements: the field or midplane asked comes from the FE levels (Hankel gives R_o alone)",
        ),
        Method::Auto if q.rigid_nut => (
            Method::Fem,
            "finite elements: the Hankel route loads the faces by a pressure only",
        ),
        Method::Auto if q.b_over_d > super::reach::B_OVER_D_SINGLE_HANKEL => (
            Method::Fem,
            "finite elements: the bearing face is beyond the Hankel route's reach",
        ),
        Method::Auto => (
            Method::Hankel,
            "Hankel + hole correction: R_o alone is a root search of milliseconds, no FE solve",
        ),
    };
    Plan { method, why }
}

/// The tolerance a route works to when none is asked: the Hankel route's root search reaches
/// 1e-6 in milliseconds; the finite elements' default is 5e-4 (their levels' cost).
pub fn default_tolerance(method: Method) -> f64 {
    match method {
        Method::Hankel => 1e-6,
        _ => 5e-4,
    }
}

/// The Hankel search and hole parameters the single-plate route uses at relative tolerance
/// `tolerance` (the root search a thousand times tighter than the tolerance, at least as tight
/// as its default; the hole's modes by [`HoleParams::for_tolerance`]).
pub fn hankel_params(tolerance: f64) -> (SeparationParams, HoleParams) {
    let search = SeparationParams {
        rel_tol: SeparationParams::default().rel_tol.max(1e-3 * tolerance),
        ..SeparationParams::default()
    };
    (search, HoleParams::for_tolerance(tolerance))
}
