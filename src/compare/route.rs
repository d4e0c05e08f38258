//! Which method computes each model's R_o in a comparison ([`Method`]: finite elements, the
//! semi-analytic Hankel routes, or the Hankel routes where they apply), and the per-model
//! choice that [`super::compare`] makes ([`Route`]).
//!
//! Both models are solved on the comparison's plates with their finite rim C:
//!
//! - **single plate** (2D thick, both faces pressed): by FE, [`super::single::single_fem`]; by
//!   Hankel, [`crate::hankel::hole::single_plate_separation`] with `OuterRadius::Finite(C)` and
//!   the route layer's knobs for the tolerance ([`single_plate::hankel_params`], what
//!   `single --method hankel` and the scenes use): the rim
//!   is bounded when it is too far to move R_o by a tenth of the tolerance and fitted
//!   otherwise ([`crate::hankel::hole::rim`]), so the route has no reach limit of its own;
//! - **two plates** (frictionless, equal): by FE, [`crate::contact::two_plate::solve`]; by
//!   Hankel, [`crate::hankel::receding::holed::two_plate_hole_to`] with its rim C (module
//!   `holed::rim`): the knobs for the tolerance, tighter ones when they fall short. Its reach
//!   ([`two_hankel_reach`]) is the route layer's [`two_plate::hankel_blocker`], named by the
//!   ratio that blocks it.
//!
//! [`Method::Auto`] takes the single plate's Hankel route, and the two plates' Hankel route
//! where it applies and below a tolerance of [`two_plate::AUTO_BELOW`] (3e-5), the route layer's
//! choice ([`two_plate::takes_hankel`], as `two` and a scene's `method = "auto"`: above it the
//! FE is several times faster and claims the tolerance);
//! it falls back to the FE when a Hankel route fails or returns an estimate above the tolerance
//! (`converged = false`). [`Method::Hankel`] refuses a point out of reach as bad
//! input naming the point ([`super::CompareError::OutOfReach`]) and keeps a not-converged
//! answer, flagged. R_o in the geometry's length unit; compression negative throughout.
//!
//! # Accuracy
//!
//! Each route's own estimate (the solvers' tests); the two methods agree within the sum of
//! their estimates on a small map (`tests/compare/map_method.rs`) and over the map (example 13).
//! `auto`'s fallback where the two-plate route is tried (below [`two_plate::AUTO_BELOW`], within reach)
//! and does not converge: `tests/compare/map_fallback.rs` (a rim 2.45 D beyond the load at
//! 2.9e-5: the route's estimate 3.5e-4 R_o, the FE's value taken bit for bit).
//!
//! # Cost
//!
//! Example 13 (per point and per map, by method; `map 10` at 1e-3, each point alone, CPU of
//! the process). The FE takes ~10 ms (single) and ~26 ms (two plates) per point; the Hankel single
//! plate about 10 ms (1 % of the auto map); the Hankel two plates with the rim 1.1 s (B/D ≤ 2),
//! 1.5 s (2–4) and 3.2 s (4–8) on average — 77 % of the auto map. Where that route returns an
//! estimate above the tolerance `auto` has paid for it before taking the FE: 18 of 100 points at
//! 1e-3 (15 on the A/D = 0.2 and 0.29 rows, whose rim lies within 4.4D of B, 3 near B/D = 8), with
//! estimates of 1.0e-3 to 5.3e-3 R_o there (0.39 R_o at A/D 0.2, B/A 1.1), another 23 % of the map.
//! The rim is most of it: on four points `two --method hankel --tol 1e-3` with C = 15.4A tried 25
//! contact radii where the infinite plate tried 7, and took 5–12× its CPU (1.0 s against 0.19 s
//! at A/D 1.2, B/A 1.1; 4.6 s against 0.39 s at A/D 1.7, B/A 4.2, where the rim's estimate also
//! missed 1e-3); R_o(C) − R_o(∞) was −5e-5 to −8e-4 of R_o there, up to the size of the
//! tolerance, so the rim cannot simply be left out at 1e-3.
//!
//! ```
//! use boltzone::compare::{two_hankel_reach, Geometry, Method};
//! assert_eq!(Method::default(), Method::Auto);
//! let g = Geometry::from_ratios(0.1, 1.0, 2.2, 1.54, 0.3)?;        // B/D = 2.2
//! assert!(two_hankel_reach(&g).is_ok());
//! let wide = Geometry::from_ratios(0.1, 5.0, 2.2, 1.54, 0.3)?;     // B/D = 11 with a rim
//! assert!(two_hankel_reach(&wide).unwrap_err().contains("B/D"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::single::{single_fem, FemStudy};
use super::{CompareError, Geometry};
use crate::contact::two_plate::solve as solve_two;
use crate::hankel::hole::single_plate_separation;
use crate::hankel::receding::holed::two_plate_hole_to;
use crate::route::single_plate;
use crate::route::two_plate::{self, Blocker, Key};
use crate::value::Value;

pub use crate::route::{Method, Route};

/// Why the two-plate Hankel route with a rim does not reach `g` (the route layer's
/// [`two_plate::hankel_blocker`], named by the ratio that blocks it), or Ok.
pub fn two_hankel_reach(g: &Geometry) -> Result<(), String> {
    let joint = g.joint().map_err(|e| e.to_string())?;
    let q = two_plate::Question {
        method: Method::Hankel,
        ..two_plate::Question::new(&joint, 1e-3)
    };
    two_plate::hankel_blocker(&q).map_or(Ok(()), |b| Err(reach_message(g, b)))
}

/// Why the tables do not answer `g` at tolerance `tol` (the route layer's
/// [`single_plate::table_answer`] and [`two_plate::table_answer`]): the model and the ratio
/// that blocks it, or Ok.
pub fn table_reach(g: &Geometry, tol: f64) -> Result<(), (&'static str, String)> {
    let joint = g.joint().map_err(|e| ("two-plate", e.to_string()))?;
    let two = two_plate::Question::new(&joint, tol);
    two_plate::table_answer(&two).map_err(|b| ("two-plate", reach_message(g, b)))?;
    let plate = g
        .single_plate(g.outer_radius())
        .map_err(|e| ("single-plate", e.to_string()))?;
    let single = single_plate::Question {
        plate: Some(&plate),
        tolerance: tol,
        ..Default::default()
    };
    single_plate::table_answer(&single).map_err(|b| ("single-plate", reach_message(g, b)))?;
    Ok(())
}

/// The route layer's blocker `b` on `g`, named by the ratio or length that blocks it.
fn reach_message(g: &Geometry, b: Blocker) -> String {
    let what = match b.key {
        Key::HoleRadius => format!("A/D = {}", g.a / g.d),
        Key::LoadOuterRadius => format!("B/D = {}", g.b / g.d),
        Key::OuterRadius => format!("C = {} (B = {}, D = {})", g.c, g.b, g.d),
        Key::Poisson => format!("nu = {}", g.nu),
        other => format!("{other:?}"),
    };
    format!("{what}: {}", b.reason)
}

/// One model's R_o, the route that produced it, and the FE study's sizes (zero for Hankel).
pub(super) struct ModelResult {
    pub value: Value,
    pub route: Route,
    pub levels: usize,
    pub dofs: usize,
    pub model: &'static str,
}

/// A Hankel route's outcome under `method`: kept by [`Method::Hankel`] (its failure as the
/// comparison's error, `error`), kept by `auto` only when it converged (else None: the FE,
/// [`two_plate::fall_back`]).
fn keep<E>(
    method: Method,
    outcome: Result<ModelResult, E>,
    error: impl FnOnce(E) -> CompareError,
) -> Result<Option<ModelResult>, CompareError> {
    let (failed, trusted) = match &outcome {
        Ok(r) => (false, r.value.converged),
        Err(_) => (true, false),
    };
    if two_plate::fall_back(method, failed, trusted) {
        return Ok(None);
    }
    outcome.map(Some).map_err(error)
}

/// The single plate's R_o by `method` at relative tolerance `tol` (module docs): the route
/// layer's [`single_plate::plan`].
pub(super) fn single(g: &Geometry, method: Method, tol: f64) -> Result<ModelResult, CompareError> {
    let plate = g.single_plate(g.outer_radius())?;
    let q = single_plate::Question {
        method,
        b_over_d: g.b / g.d,
        plate: Some(&plate),
        tolerance: tol,
        ..Default::default()
    };
    let tables = || single_plate::table_answer(&q);
    let plan = match planned(g, "single-plate", single_plate::plan(&q), tables)? {
        Ok(from_tables) => return Ok(from_tables),
        Err(method) => method,
    };
    if plan == Method::Hankel {
        let (sep, hole) = single_plate::hankel_params(tol);
        let outcome = single_plate_separation(&plate, &sep, &hole).map(|(s, h)| ModelResult {
            value: Value::with_tolerance(s.r_o, s.r_o_error, tol),
            route: Route::Hankel,
            levels: h.history.len(),
            dofs: 0,
            model: "single plate, Hankel route with the hole",
        });
        let error = |source| CompareError::Hankel {
            geometry: g.label(),
            source,
        };
        if let Some(r) = keep(method, outcome, error)? {
            return Ok(r);
        }
    }
    let (value, FemStudy { levels, dofs }) =
        single_fem(&plate, tol).map_err(|source| CompareError::Single {
            geometry: g.label(),
            source,
        })?;
    Ok(ModelResult {
        value,
        route: Route::Fem,
        levels,
        dofs,
        model: "single plate, FE",
    })
}

/// The route layer's `plan` for `model` ("single-plate" or "two-plate") on `g`: refused out of
/// reach ([`CompareError::OutOfReach`] naming the ratio), the tables' answer (`tables`) where
/// it chose them (Ok(Ok)), else the method to run (Ok(Err)).
fn planned(
    g: &Geometry,
    model: &'static str,
    plan: Result<two_plate::Plan, Blocker>,
    tables: impl FnOnce() -> Result<Value, Blocker>,
) -> Result<Result<ModelResult, Method>, CompareError> {
    let plan = plan.map_err(|b| CompareError::OutOfReach {
        geometry: g.label(),
        model,
        reason: reach_message(g, b),
    })?;
    if plan.method != Method::Table {
        return Ok(Err(plan.method));
    }
    match tables() {
        Ok(value) => Ok(Ok(ModelResult {
            value,
            route: Route::Table,
            levels: 0,
            dofs: 0,
            model: match model {
                "single-plate" => "single plate, tables",
                _ => "two plates, tables",
            },
        })),
        // (the plan checked the tables: not reached) the FE answers
        Err(_) => Ok(Err(Method::Fem)),
    }
}

/// Whether `method` tries the two-plate Hankel route at tolerance `tol` on a point it reaches
/// (`in_reach`) or not: the route layer's [`two_plate::takes_hankel`].
pub fn two_takes_hankel(method: Method, tol: f64, in_reach: bool) -> bool {
    two_plate::takes_hankel(method, tol, in_reach)
}

/// The two-plate R_o by `method` at relative tolerance `tol` (module docs): the route layer's
/// [`two_plate::plan`].
pub(super) fn two(g: &Geometry, method: Method, tol: f64) -> Result<ModelResult, CompareError> {
    let joint = g.joint()?;
    let q = two_plate::Question {
        method,
        ..two_plate::Question::new(&joint, tol)
    };
    let tables = || two_plate::table_answer(&q);
    let plan = match planned(g, "two-plate", two_plate::plan(&q), tables)? {
        Ok(from_tables) => return Ok(from_tables),
        Err(method) => method,
    };
    if plan == Method::Hankel {
        let plate = g.single_plate(g.outer_radius())?;
        let outcome = two_plate_hole_to(&plate, tol, &[]).map(|(out, _)| ModelResult {
            value: Value {
                converged: out.meets(tol),
                ..Value::with_tolerance(out.r_o, out.info.r_o_error, tol)
            },
            route: Route::Hankel,
            levels: out.info.solves,
            dofs: 0,
            model: "two plates, Hankel route with the hole and rim",
        });
        let error = |source| CompareError::TwoHankel {
            geometry: g.label(),
            source,
        };
        if let Some(r) = keep(method, outcome, error)? {
            return Ok(r);
        }
    }
    let sol = solve_two(&joint, &q.fem_params()).map_err(|source| CompareError::Two {
        geometry: g.label(),
        source,
    })?;
    Ok(ModelResult {
        value: Value {
            value: sol.r_o,
            error: sol.r_o_error,
            converged: sol.converged,
        },
        route: Route::Fem,
        levels: sol.info.levels.len(),
        dofs: 0,
        model: sol.info.model,
    })
}
