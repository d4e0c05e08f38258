//! The two-plate model's routes (report Chapter II.B): which one answers a question, and why.
//!
//! Two routes compute the separation radius R_o of two plates in unilateral contact:
//!
//! - the **finite elements** ([`crate::contact::two_plate`]): any joint the library describes —
//!   welded, frictionless or frictional interface, equal or unequal plates, a hole or none, a
//!   finite rim free or fixed, a pressure or a nut displacement, temperatures, the field; every
//!   estimate carries 2e-5 of R_o (the level sequence's slow component), so they cannot claim a
//!   tolerance below [`AUTO_BELOW`], except where [`Question::fitted_edge`] reads R_o from the
//!   fitted contact edge (bars from 5e-7 of R_o; [`Question::fem_params`] sets it);
//! - the **semi-analytic Hankel routes** ([`crate::hankel::receding`]): with a hole, two equal
//!   plates ([`crate::hankel::receding::holed`], its rim `holed::rim`); without one, the receding
//!   contact of any two plates in series in frictionless contact (`Pair`; equal plates carry no
//!   interface shear, so any interface), with a finite rim equal plates (`rim`); pressed by a
//!   pressure on a free rim, the same bearing face under head and nut (B₂ = B₁; a nut face of
//!   its own, [`Key::NutOuterRadius`], goes to the finite elements), answering R_o and the
//!   interface pressure only, to 1e-8.
//!
//! - the **tables** ([`crate::table::lookup`]): equal plates, infinite or with a free rim at
//!   least 4 plate thicknesses beyond R_o ([`crate::table::rim`]: the rim's shift from its own
//!   table), a uniform pressure from the hole, R_o alone, in microseconds with a bar (the near
//!   table's interpolation bound and build error, the far table's handover bound, the rim
//!   table's); [`table_answer`] is their reach and their answer.
//!
//! [`hankel_blocker`] is the one statement of the semi-analytic routes' reach: the first input of
//! the question that keeps it from them, as a [`Key`] (each front end names it in its own words:
//! a flag, a scene key) and a reason. [`plan`] makes the choice of a [`Method`]: `fem` and
//! `hankel` and `table` as asked (refused with the blocker where out of reach), `auto` the
//! cheapest route that can meet the tolerance and serve the outputs — the tables wherever their
//! bar meets it, else the Hankel routes within reach and below [`AUTO_BELOW`], the finite
//! elements otherwise. Where `auto`'s Hankel run then declines
//! the joint ([`fall_back`]), the finite elements answer and the answer says why.
//!
//! # Accuracy
//!
//! No numerics: the routes' own (their modules). The fronts' agreement on one question:
//! `tests/route/` (the same joint through `two`, `solve` and the comparison, bit for bit).
//!
//! # Cost
//!
//! Microseconds; a pair without a hole checks its basis size (`Pair::basis_size`).
//!
//! ```
//! use boltzone::route::{two_plate, Method};
//! use boltzone::{Joint, Material};
//! let joint = Joint::symmetric(0.1, 0.31, 0.1, Material::new(3e7, 0.3)?)?;
//! let mut q = two_plate::Question::new(&joint, 1e-6);
//! assert_eq!(two_plate::plan(&q).unwrap().method, Method::Hankel);   // below 3e-5
//! q.tolerance = 5e-3;
//! assert_eq!(two_plate::plan(&q).unwrap().method, Method::Table);    // the tables' bar meets it
//! let rim = joint.clone().with_outer_radius(boltzone::OuterRadius::Finite(1.54))?;
//! let q = two_plate::Question::new(&rim, 5e-4);
//! assert_eq!(two_plate::plan(&q).unwrap().method, Method::Table);    // with the rim's shift
//! let near = joint.clone().with_outer_radius(boltzone::OuterRadius::Finite(0.6))?;
//! let q = two_plate::Question::new(&near, 5e-4);
//! assert_eq!(two_plate::plan(&q).unwrap().method, Method::Fem);      // a rim within 4 D of R_o
//! let mut q = two_plate::Question::new(&joint, 5e-4);
//! q.fixed_edge = true;
//! q.method = Method::Hankel;
//! assert_eq!(two_plate::plan(&q).unwrap_err().key, two_plate::Key::OuterEdge);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::Method;
use crate::contact::two_plate::{EdgeSupport, InterfaceModel, Loading, TwoPlateParams};
use crate::hankel::receding::{Pair, RecedingParams, MAX_B_OVER_D, MAX_B_OVER_D_RIM, MIN_A_OVER_D};
use crate::joint::{Joint, OuterRadius, Plate};
use crate::load::FaceLoad;
use crate::material::Material;

pub use crate::hankel::receding::AUTO_BELOW;

/// The most mesh levels of a fitted-edge study ([`Question::fitted_edge`]): the tenth has
/// h = D/2048 at R_o (D the thinner plate's). Its estimate falls about 2× per level, so 1e-6 of
/// R_o takes 9–10 levels; below D/2048 the edge-force root stops halving and its extrapolation
/// moves away from R_o (docs/fem.md, "Through the front ends").
pub const FITTED_MAX_LEVELS: usize = 10;

/// A two-plate question: the joint (any consistent units), how it is loaded and supported, the
/// outputs wanted beyond R_o, the method and the tolerance (relative, on R_o).
#[derive(Debug, Clone, Copy)]
pub struct Question<'a> {
    /// The plates, hole, rim and bearing pressure.
    pub joint: &'a Joint,
    /// The interface between the plates.
    pub interface: InterfaceModel,
    /// A face pressure, or a nut displacement.
    pub loading: Loading,
    /// The outer edge is fixed (report Fig. 20(c)) rather than free.
    pub fixed_edge: bool,
    /// The plates carry temperatures (thermal strains).
    pub thermal: bool,
    /// The finite elements' field (or a figure drawn from it) is wanted.
    pub field: bool,
    /// The joint conductance (an integral of the FE interface pressure) is wanted.
    pub conductance: bool,
    /// The member stiffness k_P (from the FE displacements, [`super::joint`]) is wanted.
    pub stiffness: bool,
    /// The interface pressure curve is wanted (the solvers give it, the tables do not).
    pub curve: bool,
    /// The method asked for.
    pub method: Method,
    /// Wanted relative error of R_o.
    pub tolerance: f64,
}

impl<'a> Question<'a> {
    /// R_o of `joint` under its face pressure, frictionless, free rim, by `auto`.
    pub fn new(joint: &'a Joint, tolerance: f64) -> Self {
        Self {
            joint,
            interface: InterfaceModel::Frictionless,
            loading: Loading::Pressure,
            fixed_edge: false,
            thermal: false,
            field: false,
            conductance: false,
            stiffness: false,
            curve: false,
            method: Method::Auto,
            tolerance,
        }
    }

    /// The finite elements' parameters for this question (Q9, the tolerance, the interface,
    /// loading and edge asked; the fitted contact edge and up to [`FITTED_MAX_LEVELS`] levels
    /// where [`Question::fitted_edge`] says so).
    pub fn fem_params(&self) -> TwoPlateParams {
        let fitted = self.fitted_edge();
        let default = TwoPlateParams::default();
        TwoPlateParams {
            interface: self.interface,
            loading: self.loading,
            edge: if self.fixed_edge {
                EdgeSupport::Fixed
            } else {
                EdgeSupport::Free
            },
            tolerance: self.tolerance,
            fitted_edge: fitted,
            max_levels: if fitted {
                FITTED_MAX_LEVELS
            } else {
                default.max_levels
            },
            ..default
        }
    }

    /// Whether the finite elements read R_o from the fitted contact edge
    /// ([`TwoPlateParams::fitted_edge`], a floor of 5e-7 of R_o instead of 2e-5, so
    /// tolerances from 1e-6): below
    /// [`AUTO_BELOW`], for the joints its bars were measured on (docs/fem.md) — a face
    /// pressure, a free rim, no temperatures, the same bearing face under head and nut, and
    /// equal plates (any interface: the symmetric model) or a frictionless interface.
    pub fn fitted_edge(&self) -> bool {
        self.tolerance < AUTO_BELOW
            && self.loading == Loading::Pressure
            && !self.fixed_edge
            && !self.thermal
            && !self.joint.has_own_nut_load()
            && (self.interface == InterfaceModel::Frictionless || self.equal_plates())
    }

    /// Whether the two plates are alike (thickness and material).
    pub fn equal_plates(&self) -> bool {
        let (up, lo) = (self.joint.upper(), self.joint.lower());
        up.thickness() == lo.thickness() && up.material() == lo.material()
    }
}

/// The input of a question that keeps it from the Hankel routes (each front end names it: a
/// flag, a scene key).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Key {
    /// The lower plate's thickness differs from the upper plate's.
    LowerThickness,
    /// The lower plate's Young's modulus differs.
    LowerModulus,
    /// The lower plate's Poisson's ratio differs.
    LowerPoisson,
    /// The interface model.
    Interface,
    /// The plates' outer radius C.
    OuterRadius,
    /// The hole radius A.
    HoleRadius,
    /// The bearing face's outer radius B.
    LoadOuterRadius,
    /// The nut's own bearing face (B₂ ≠ B₁: [`crate::Joint::with_nut_load`]).
    NutOuterRadius,
    /// The nut displacement (instead of a pressure).
    NutDisplacement,
    /// The fixed outer edge.
    OuterEdge,
    /// The plates' temperatures.
    Temperature,
    /// The field (or figures drawn from it).
    Field,
    /// The joint conductance.
    Conductance,
    /// The member stiffness.
    Stiffness,
    /// The upper plate's Poisson's ratio (the tables span 0..0.5).
    Poisson,
    /// The shape of the bearing pressure (the tables take a uniform pressure from the hole).
    LoadProfile,
    /// The interface pressure curve (the tables give R_o alone).
    Curve,
    /// The tolerance (the tables need a positive one for their bar).
    Tolerance,
}

/// Why the Hankel routes do not take a question: the input that blocks them and the reason.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Blocker {
    /// The input that blocks the route.
    pub key: Key,
    /// Why (a sentence fragment: "needs two equal plates with a hole").
    pub reason: &'static str,
}

/// The route chosen for a question, and why.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Plan {
    /// [`Method::Fem`], [`Method::Hankel`] or [`Method::Table`] (never `Auto`).
    pub method: Method,
    /// The reason, for the answer's plan or text.
    pub why: &'static str,
}

/// The semi-analytic solver that answers a joint the Hankel route takes: the route layer's
/// choice, which every front end runs and words in its own output.
///
/// ```
/// use boltzone::route::two_plate::{hankel_solver, HankelSolver};
/// use boltzone::{Joint, Material, OuterRadius};
/// let joint = Joint::symmetric(0.1, 0.31, 0.1, Material::new(3e7, 0.3)?)?;
/// assert_eq!(hankel_solver(&joint), HankelSolver::Holed);
/// let solid = Joint::symmetric(0.0, 0.31, 0.1, Material::new(3e7, 0.3)?)?;
/// assert_eq!(hankel_solver(&solid), HankelSolver::Pair);
/// let rim = solid.with_outer_radius(OuterRadius::Finite(1.54))?;
/// assert_eq!(hankel_solver(&rim), HankelSolver::Rim(1.54));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum HankelSolver {
    /// No hole, infinite plates: the receding contact of the pair in series
    /// ([`Pair::receding_contact`]).
    Pair,
    /// No hole, equal plates with a finite rim C: [`crate::hankel::receding::rim::rim_contact`].
    Rim(f64),
    /// A hole, equal plates (a rim too): [`crate::hankel::receding::holed::two_plate_hole_to`].
    Holed,
}

/// Which semi-analytic solver answers `joint` (within [`hankel_blocker`]'s reach).
pub fn hankel_solver(joint: &Joint) -> HankelSolver {
    match (joint.hole_radius() > 0.0, joint.outer_radius()) {
        (true, _) => HankelSolver::Holed,
        (false, OuterRadius::Finite(c)) => HankelSolver::Rim(c),
        (false, OuterRadius::Infinite) => HankelSolver::Pair,
    }
}

/// The first input of `q` that keeps it from the Hankel routes (module docs), or None.
pub fn hankel_blocker(q: &Question) -> Option<Blocker> {
    let j = q.joint;
    let (up, lo) = (j.upper(), j.lower());
    let (a, b, d) = (j.hole_radius(), j.load().outer(), up.thickness());
    let holed = a > 0.0;
    let equal = q.equal_plates();
    let rim = match j.outer_radius() {
        OuterRadius::Finite(c) => Some(c),
        OuterRadius::Infinite => None,
    };
    let frictionless = matches!(q.interface, InterfaceModel::Frictionless);
    let lower = if lo.thickness() != d {
        Key::LowerThickness
    } else if lo.material().youngs_modulus() != up.material().youngs_modulus() {
        Key::LowerModulus
    } else {
        Key::LowerPoisson
    };
    let checks = [
        (j.has_own_nut_load(), Key::NutOuterRadius, NUT_FACE_REASON),
        (
            holed && !equal,
            lower,
            "with a hole the Hankel route takes two equal plates",
        ),
        (
            !holed && !equal && !frictionless,
            Key::Interface,
            "without a hole the Hankel route takes two unequal plates in frictionless contact \
             only (equal plates carry no interface shear: any interface)",
        ),
        (
            !holed && !equal && rim.is_some(),
            Key::OuterRadius,
            "the Hankel route's finite rim takes two equal plates, with or without a hole",
        ),
        (
            holed && a < MIN_A_OVER_D * d,
            Key::HoleRadius,
            "is below the Hankel route's smallest hole (A at least 0.04 plate thicknesses: \
             smaller holes left residual tractions of 1e1-1e4 P on the hole); or a hole radius \
             0 (the receding contact, within A² of it)",
        ),
        (
            holed && b > MAX_B_OVER_D * d,
            Key::LoadOuterRadius,
            "is beyond the Hankel route's reach with a hole (B at most 16 plate thicknesses: \
             its cost grows like (B/D)², 4.7 s and 0.6 GB at 16)",
        ),
        (
            !holed && rim.is_none() && !pair_reaches(up, lo, b),
            Key::LoadOuterRadius,
            "is beyond the Hankel route's reach without a hole (B + 2D of the thicker plate \
             at most 64 thicknesses of the thinner)",
        ),
        (
            rim.is_some() && b > MAX_B_OVER_D_RIM * d,
            Key::LoadOuterRadius,
            "is beyond the Hankel route's reach with a finite rim (B at most 8 plate \
             thicknesses: the rim's cost grows like (B/D)², with a hole 10.5 s at 8, without \
             one 1.6 s)",
        ),
        (
            rim.is_some_and(|c| c <= b + d),
            Key::OuterRadius,
            "must exceed the bearing radius B by more than the plate thickness D for the \
             Hankel route's finite rim (its rim residue decays over C - R_o)",
        ),
        (
            matches!(q.loading, Loading::NutDisplacement(_)),
            Key::NutDisplacement,
            "the Hankel route loads the plates by a pressure",
        ),
        (
            q.fixed_edge,
            Key::OuterEdge,
            "the Hankel route's rim is free (a fixed edge is in the finite-element model only)",
        ),
    ];
    first(checks.into_iter().chain(finite_elements_only(q)))
}

/// Why a nut face of its own keeps a question from the semi-analytic routes.
pub const NUT_FACE_REASON: &str = "the semi-analytic routes press head and nut over the same \
     bearing face (one B, mirror-symmetric about the interface); with B2 != B1 the finite \
     elements mesh both plates";

/// What only the finite elements answer: thermal strains, the field, the conductance and the
/// member stiffness (each with the key that asks it and the reason).
fn finite_elements_only(q: &Question) -> [(bool, Key, &'static str); 4] {
    [
        (
            q.thermal,
            Key::Temperature,
            "thermal strains are in the finite-element model only",
        ),
        (
            q.field,
            Key::Field,
            "the field and the figures drawn from it come from the finite elements",
        ),
        (
            q.conductance,
            Key::Conductance,
            "the conductance integrates the finite elements' interface pressure",
        ),
        (
            q.stiffness,
            Key::Stiffness,
            "the member stiffness comes from the finite elements' displacements (the \
             semi-analytic routes and the tables answer R_o)",
        ),
    ]
}

/// The first check that blocks, as a [`Blocker`].
fn first(mut checks: impl Iterator<Item = (bool, Key, &'static str)>) -> Option<Blocker> {
    checks.find_map(|(blocks, key, reason)| blocks.then_some(Blocker { key, reason }))
}

/// Whether the receding solver of two plates without a hole reaches the load width `b`
/// ([`Pair::basis_size`]: it depends on B and the thicknesses only).
fn pair_reaches(up: Plate, lo: Plate, b: f64) -> bool {
    let plate = |p: Plate| Plate::new(p.thickness(), Material::unit(0.3).ok()?).ok();
    match (plate(up), plate(lo), FaceLoad::uniform(0.0, b, 1.0).ok()) {
        (Some(up), Some(lo), Some(load)) => Pair::new(up, lo, load)
            .basis_size(&RecedingParams::default())
            .is_ok(),
        _ => true,
    }
}

/// Whether `method` takes the Hankel routes at relative tolerance `tolerance` for a question
/// they reach (`in_reach`) or not: `hankel` always (out of reach it is refused), `fem` never,
/// `auto` within reach and below [`AUTO_BELOW`].
pub fn takes_hankel(method: Method, tolerance: f64, in_reach: bool) -> bool {
    match method {
        Method::Fem | Method::Table => false,
        Method::Hankel => true,
        Method::Auto => in_reach && tolerance < AUTO_BELOW,
    }
}

/// The route for `q` (module docs); `hankel` or `table` out of reach is refused with the
/// blocker. `auto` takes the tables wherever their bar meets the tolerance ([`table_answer`]).
pub fn plan(q: &Question) -> Result<Plan, Blocker> {
    if q.method == Method::Table {
        return table_answer(q).map(|_| Plan {
            method: Method::Table,
            why: "tables built by the 1e-8 semi-analytic route (asked)",
        });
    }
    if q.method == Method::Auto && table_answer(q).is_ok_and(|r| r.converged) {
        return Ok(Plan {
            method: Method::Table,
            why: "tables built by the 1e-8 semi-analytic route: their bar meets the tolerance",
        });
    }
    let blocker = hankel_blocker(q);
    if q.method == Method::Auto && takes_hankel(q.method, q.tolerance, blocker.is_none()) {
        return Ok(Plan {
            method: Method::Hankel,
            why: "semi-analytic two plates (with a hole, or the receding contact without \
                  one): below a tolerance of 3e-5 the FE cannot claim it",
        });
    }
    match (q.method, blocker) {
        (Method::Fem, _) => Ok(Plan {
            method: Method::Fem,
            why: "finite elements (asked)",
        }),
        (Method::Hankel, Some(b)) => Err(b),
        (Method::Hankel, None) => Ok(Plan {
            method: Method::Hankel,
            why: "semi-analytic two plates (asked; with a hole, or the receding contact \
                  without one): R_o and the interface pressure",
        }),
        (Method::Auto | Method::Table, None) => Ok(Plan {
            method: Method::Fem,
            why: "finite elements: at this tolerance they are the cheaper route",
        }),
        (Method::Auto | Method::Table, Some(_)) => Ok(Plan {
            method: Method::Fem,
            why: "finite elements: the semi-analytic routes do not reach this question",
        }),
    }
}

/// The tables' R_o for `q` ([`crate::table::lookup`]: equal infinite plates, a free rim through
/// the rim table's shift ([`crate::table::rim`]), a uniform pressure from the hole, no field,
/// converged when its bar is within the tolerance), or the first input that keeps the question
/// from them.
pub fn table_answer(q: &Question) -> Result<crate::value::Value, Blocker> {
    let j = q.joint;
    let (up, lo) = (j.upper(), j.lower());
    let load = j.load();
    let lower = if lo.thickness() != up.thickness() {
        Key::LowerThickness
    } else if lo.material().youngs_modulus() != up.material().youngs_modulus() {
        Key::LowerModulus
    } else {
        Key::LowerPoisson
    };
    let checks = [
        (
            j.has_own_nut_load(),
            Key::NutOuterRadius,
            "the tables take the same bearing face under head and nut (B2 = B1)",
        ),
        (!q.equal_plates(), lower, "the tables take two equal plates"),
        (
            load.profile() != crate::load::Profile::Uniform || load.inner() != j.hole_radius(),
            Key::LoadProfile,
            "the tables take a uniform pressure from the hole's edge to B",
        ),
        (
            matches!(q.loading, Loading::NutDisplacement(_)),
            Key::NutDisplacement,
            "the tables load the plates by a pressure",
        ),
        (
            q.fixed_edge,
            Key::OuterEdge,
            "the tables' plates are infinite (a fixed edge is in the finite-element model only)",
        ),
        (
            q.curve,
            Key::Curve,
            "the tables give R_o alone (the interface pressure comes from a solver)",
        ),
    ];
    if let Some(b) = first(checks.into_iter().chain(finite_elements_only(q))) {
        return Err(b);
    }
    let (a, b, d) = (j.hole_radius(), load.outer(), up.thickness());
    let nu = up.material().poisson_ratio();
    let infinite = crate::table::lookup::separation_radius(
        crate::table::Model::TwoPlates,
        a,
        b,
        d,
        nu,
        q.tolerance,
    )
    .map_err(table_blocker)?;
    let OuterRadius::Finite(c) = j.outer_radius() else {
        return Ok(infinite);
    };
    // a free rim: its shift from the rim table (crate::table::rim), its bar added
    let shift = crate::table::rim::two_plates_rim_shift(a, b, d, nu, c, infinite.value)
        .map_err(table_blocker)?;
    Ok(crate::value::Value::with_tolerance(
        infinite.value - shift.value,
        infinite.error + shift.error,
        q.tolerance,
    ))
}

/// The input named by a table lookup's error ([`crate::table::lookup::separation_radius`],
/// [`crate::table::rim::two_plates_rim_shift`]): the rim, Poisson's ratio, the hole or the load
/// width outside the tables.
pub(super) fn table_blocker(e: crate::error::InputError) -> Blocker {
    use crate::error::InputError;
    let field = match &e {
        InputError::Parameter { field, .. }
        | InputError::NotPositive { field, .. }
        | InputError::NotFinite { field, .. } => *field,
        _ => "",
    };
    if field.starts_with("rim") {
        Blocker {
            key: Key::OuterRadius,
            reason: "is within 4 plate thicknesses of the contact edge, nearer than the tables' \
                     rim law reaches",
        }
    } else if field.contains("rim table") {
        Blocker {
            key: Key::LoadOuterRadius,
            reason: "is outside the tables' load widths with a rim ((B - A)/D within 0.15..4)",
        }
    } else if field.starts_with("Poisson") {
        Blocker {
            key: Key::Poisson,
            reason: "is outside the tables' Poisson's ratios (0..0.5)",
        }
    } else if field.starts_with("A/D") {
        Blocker {
            key: Key::HoleRadius,
            reason: "is outside the tables' hole radii (A/D within 0.25..4 near the \
                     contact edge, at most 4 far from it)",
        }
    } else if field.starts_with("tolerance") {
        Blocker {
            key: Key::Tolerance,
            reason: "must be positive for the tables' bar",
        }
    } else {
        Blocker {
            key: Key::LoadOuterRadius,
            reason: "is outside the tables' load widths ((B - A)/D at least 0.1 near the \
                     hole; without a hole B/D at least 2)",
        }
    }
}

/// Why `auto` hands a holed run whose modes stopped short of their residual target to the
/// finite elements: its ± is then no bound, where the FE's is.
pub const UNRESOLVED: &str =
    "the hole modes stopped short of their residual target, so its estimate is not trusted";

/// Whether `method`'s Hankel run, with this outcome, hands the joint to the finite elements:
/// `auto` does when the route failed or its estimate is not trusted (`trusted` false: the hole
/// modes left unresolved; the comparisons, whose every point of a map has the FE value to fall
/// back on, also count a run that missed the tolerance as not trusted); `hankel` never (it
/// reports the failure, or the unconverged value flagged).
pub fn fall_back(method: Method, failed: bool, trusted: bool) -> bool {
    method == Method::Auto && (failed || !trusted)
}
