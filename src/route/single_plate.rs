//! The single-plate substitute's routes (Fernlund's substitution, report Chapter II.A): which one
//! answers a question, and the semi-analytic route's knobs for a tolerance.
//!
//! - the **Hankel route with the hole correction**
//!   ([`crate::hankel::hole::single_plate_separation`]): R_o alone, a root search of
//!   milliseconds, any rim (bounded where too far to matter, fitted otherwise);
//! - the **finite elements** ([`crate::fem::single`]): also the field, the midplane σ_z curve,
//!   a rigid nut (a uniform displacement) and thermal strains;
//! - the **tables** ([`crate::table::lookup`] with [`Model::SinglePlate`]): the infinite plate,
//!   a rim through its bound ([`crate::table::rim`]), a uniform pressure from the hole, R_o
//!   alone, in microseconds with a bar ([`table_answer`] is their reach and their answer).
//!
//! `auto` takes the finite elements where an output or input asks for them, else the tables
//! where their bar meets the tolerance, else the Hankel route.
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
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! let q = single_plate::Question { method: Method::Auto, ..Default::default() };
//! assert_eq!(single_plate::plan(&q).unwrap().method, Method::Hankel);  // no plate: no tables
//! let field = single_plate::Question { field: true, ..q };
//! assert_eq!(single_plate::plan(&field).unwrap().method, Method::Fem);
//! // Table 1's first row at C = ∞: the tables' bar meets 1e-4
//! let load = FaceLoad::uniform(0.1, 0.31, 1.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Infinite, 0.1, Material::unit(0.3)?, load.clone())?;
//! let q = single_plate::Question { plate: Some(&plate), tolerance: 1e-4, ..q };
//! assert_eq!(single_plate::plan(&q).unwrap().method, Method::Table);
//! // with Table 1's rim C = 1.54 in, 11 D beyond R_o: the rim's bound joins the bar
//! let rimmed = SinglePlate::new(0.1, OuterRadius::Finite(1.54), 0.1, Material::unit(0.3)?, load)?;
//! let infinite = single_plate::table_answer(&q).unwrap();
//! let q = single_plate::Question { plate: Some(&rimmed), ..q };
//! let rim = single_plate::table_answer(&q).unwrap();
//! assert!(rim.converged && rim.error > infinite.error && rim.value == infinite.value);
//! let (search, _hole) = single_plate::hankel_params(1e-6);
//! assert!(search.rel_tol <= 1e-9);
//! # Ok::<(), boltzone::InputError>(())
//! ```

use super::two_plate::{table_blocker, Blocker, Key, Plan};
use super::Method;
use crate::hankel::hole::HoleParams;
use crate::hankel::SeparationParams;
use crate::joint::{OuterRadius, SinglePlate};
use crate::table::rim::single_plate_rim_bound;
use crate::table::Model;
use crate::value::Value;

/// What a single-plate question asks beyond R_o, and by which method.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Question<'a> {
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
    /// The midplane σ_z curve is wanted (the Hankel route and the FE give it, the tables do
    /// not).
    pub curve: bool,
    /// The plate, for the tables' reach (None: not known, so not answered from the tables).
    pub plate: Option<&'a SinglePlate>,
    /// Wanted relative error of R_o, for the tables' bar (0 when not given: not from the
    /// tables).
    pub tolerance: f64,
}

/// The route for `q` (module docs); `table` out of the tables' reach is refused with the
/// input that blocks it.
pub fn plan(q: &Question) -> Result<Plan, Blocker> {
    let (method, why) = match q.method {
        Method::Fem => (Method::Fem, "finite elements (asked)"),
        Method::Hankel => (Method::Hankel, "Hankel + hole correction (asked)"),
        Method::Table => {
            table_answer(q)?;
            (
                Method::Table,
                "tables built by the 1e-8 semi-analytic route (asked)",
            )
        }
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
        Method::Auto if table_answer(q).is_ok_and(|r| r.converged) => (
            Method::Table,
            "tables built by the 1e-8 semi-analytic route: their bar meets the tolerance",
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
    Ok(Plan { method, why })
}

/// The tables' R_o for `q` ([`crate::table::lookup`], [`Model::SinglePlate`]: the infinite
/// plate's, with a rim's bound added to the bar ([`crate::table::rim`]); a uniform pressure
/// from the hole, R_o alone, converged when its bar is within the tolerance), or the first
/// input that keeps the question from them.
pub fn table_answer(q: &Question) -> Result<Value, Blocker> {
    let blocked = |key, reason| Err(Blocker { key, reason });
    let Some(plate) = q.plate else {
        return blocked(
            Key::LoadOuterRadius,
            "the plate is not known to the route layer",
        );
    };
    let load = plate.load();
    if q.field {
        return blocked(
            Key::Field,
            "the tables give R_o alone (the field comes from the FE)",
        );
    }
    if q.curve {
        return blocked(
            Key::Curve,
            "the tables give R_o alone (the curve comes from a solver)",
        );
    }
    if q.rigid_nut {
        return blocked(
            Key::NutDisplacement,
            "the tables load the plate by a pressure",
        );
    }
    if q.thermal {
        return blocked(
            Key::Temperature,
            "the tables' plate carries no temperatures",
        );
    }
    if load.profile() != crate::load::Profile::Uniform || load.inner() != plate.hole_radius() {
        return blocked(
            Key::LoadProfile,
            "the tables take a uniform pressure from the hole's edge to B",
        );
    }
    let (a, b, d) = (plate.hole_radius(), load.outer(), plate.half_thickness());
    let nu = plate.material().poisson_ratio();
    let infinite =
        crate::table::lookup::separation_radius(Model::SinglePlate, a, b, d, nu, q.tolerance)
            .map_err(table_blocker)?;
    let OuterRadius::Finite(c) = plate.outer_radius() else {
        return Ok(infinite);
    };
    // a free rim: its bound joins the bar (crate::table::rim)
    let rim = single_plate_rim_bound(c, infinite.value + infinite.error, d);
    if !rim.is_finite() {
        return blocked(
            Key::OuterRadius,
            "the rim C is inside the infinite plate's contact zone, which the tables cannot bound",
        );
    }
    Ok(Value::with_tolerance(
        infinite.value,
        infinite.error + rim,
        q.tolerance,
    ))
}

/// The tolerance a route works to when none is asked: the Hankel route's root search reaches
/// 1e-6 in milliseconds, and the tables' bar meets it; the finite elements' default is 5e-4
/// (their levels' cost).
pub fn default_tolerance(method: Method) -> f64 {
    match method {
        Method::Hankel | Method::Table => 1e-6,
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
