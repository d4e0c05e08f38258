//! Which method computes each model's R_o in a comparison ([`Method`]: finite elements, the
//! semi-analytic Hankel routes, or the Hankel routes where they apply), and the per-model
//! choice that [`super::compare`] makes ([`Route`]).
//!
//! Both models are solved on the comparison's plates with their finite rim C:
//!
//! - **single plate** (2D thick, both faces pressed): by FE, [`super::single::single_fem`]; by
//!   Hankel, [`crate::hankel::hole::single_plate_separation`] with `OuterRadius::Finite(C)` and
//!   [`HoleParams::for_tolerance`] (what `single --method hankel` and the scenes use): the rim
//!   is bounded when it is too far to move R_o by a tenth of the tolerance and fitted
//!   otherwise ([`crate::hankel::hole::rim`]), so the route has no reach limit of its own;
//! - **two plates** (frictionless, equal): by FE, [`crate::contact::two_plate::solve`]; by
//!   Hankel, [`crate::hankel::receding::holed::two_plate_hole_to`] with its rim C (module
//!   `rim_holed`): the knobs for the tolerance, tighter ones when they fall short. Its reach
//!   ([`two_hankel_reach`]): A/D ≥ [`MIN_A_OVER_D`], B/D ≤ [`MAX_B_OVER_D_RIM`] (a finite
//!   rim), C > B + D.
//!
//! [`Method::Auto`] takes the single plate's Hankel route, and the two plates' Hankel route
//! where it applies — decided up front by the reach above — and below a tolerance of
//! [`AUTO_BELOW`] (3e-5), as `two --method auto` and a scene's `method = "auto"` do
//! ([`two_takes_hankel`]: above it the FE is several times faster and claims the tolerance);
//! it falls back to the FE when a Hankel route fails or returns an estimate above the tolerance
//! (`converged = false`). [`Method::Hankel`] refuses a point out of reach as bad
//! input naming the point ([`super::CompareError::OutOfReach`]) and keeps a not-converged
//! answer, flagged. R_o in the geometry's length unit; compression negative throughout.
//!
//! # Accuracy
//!
//! Each route's own estimate (the solvers' tests); the two methods agree within the sum of
//! their estimates on a small map (`tests/compare/map_method.rs`) and over the map (example 13).
//! `auto`'s fallback where the two-plate route is tried (below [`AUTO_BELOW`], within reach)
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
//! assert_eq!(Method::default(), Method::Fem);
//! let g = Geometry::from_ratios(0.1, 1.0, 2.2, 1.54, 0.3)?;        // B/D = 2.2
//! assert!(two_hankel_reach(&g).is_ok());
//! let wide = Geometry::from_ratios(0.1, 5.0, 2.2, 1.54, 0.3)?;     // B/D = 11 with a rim
//! assert!(two_hankel_reach(&wide).unwrap_err().contains("B/D"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::single::{single_fem, FemStudy};
use super::{CompareError, Geometry};
use crate::contact::two_plate::{solve as solve_two, TwoPlateParams};
use crate::hankel::hole::{single_plate_separation, HoleParams};
use crate::hankel::receding::holed::two_plate_hole_to;
use crate::hankel::receding::{AUTO_BELOW, MAX_B_OVER_D_RIM, MIN_A_OVER_D};
use crate::hankel::separation::SeparationParams;
use crate::joint::OuterRadius;
use crate::value::Value;
use serde::Serialize;

/// How a comparison computes each model's R_o (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Finite elements for both models (the default).
    #[default]
    Fem,
    /// The Hankel routes for both models; a point beyond a route's reach is refused.
    Hankel,
    /// Each model's Hankel route where it applies and converges, else the FE.
    Auto,
}

/// The method that produced one model's value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Route {
    /// Finite elements.
    Fem,
    /// The semi-analytic Hankel route.
    Hankel,
}

impl Route {
    /// "fem" or "hankel" (the CSV's spelling).
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Fem => "fem",
            Self::Hankel => "hankel",
        }
    }
}

/// Why the two-plate Hankel route with a rim does not reach `g` (module docs), or Ok.
pub fn two_hankel_reach(g: &Geometry) -> Result<(), String> {
    let (ad, bd) = (g.a / g.d, g.b / g.d);
    if ad < MIN_A_OVER_D {
        return Err(format!(
            "A/D = {ad} is below the two-plate Hankel route's smallest hole ({MIN_A_OVER_D})"
        ));
    }
    if bd > MAX_B_OVER_D_RIM {
        return Err(format!(
            "B/D = {bd} is beyond the two-plate Hankel route's reach with a finite rim \
             (at most {MAX_B_OVER_D_RIM})"
        ));
    }
    if g.c <= g.b + g.d {
        return Err(format!(
            "C = {} is within one plate thickness of B = {} (the two-plate Hankel route's \
             rim needs C > B + D)",
            g.c, g.b
        ));
    }
    Ok(())
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
/// comparison's error, `error`), kept by `auto` only when it converged (else None: the FE).
fn keep<E>(
    method: Method,
    outcome: Result<ModelResult, E>,
    error: impl FnOnce(E) -> CompareError,
) -> Result<Option<ModelResult>, CompareError> {
    match outcome {
        Ok(r) if method == Method::Hankel || r.value.converged => Ok(Some(r)),
        Err(e) if method == Method::Hankel => Err(error(e)),
        _ => Ok(None),
    }
}

/// The single plate's R_o by `method` at relative tolerance `tol` (module docs).
pub(super) fn single(g: &Geometry, method: Method, tol: f64) -> Result<ModelResult, CompareError> {
    let plate = g.single_plate(OuterRadius::Finite(g.c))?;
    if method != Method::Fem {
        let hole = HoleParams::for_tolerance(tol);
        let sep = SeparationParams {
            rel_tol: SeparationParams::default().rel_tol.max(1e-3 * tol),
            ..Default::default()
        };
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

/// Whether `method` tries the two-plate Hankel route at tolerance `tol` on a point it reaches
/// (`in_reach`) or not: `hankel` always (a point out of reach is refused before), `auto` within
/// reach and below [`AUTO_BELOW`], as `two --method auto` and a scene's `method = "auto"` (above
/// it the FE is faster and claims the tolerance), `fem` never.
pub fn two_takes_hankel(method: Method, tol: f64, in_reach: bool) -> bool {
    match method {
        Method::Fem => false,
        Method::Hankel => true,
        Method::Auto => in_reach && tol < AUTO_BELOW,
    }
}

/// The two-plate R_o by `method` at relative tolerance `tol` (module docs).
pub(super) fn two(g: &Geometry, method: Method, tol: f64) -> Result<ModelResult, CompareError> {
    let reach = two_hankel_reach(g);
    if let (Method::Hankel, Err(reason)) = (method, &reach) {
        return Err(CompareError::OutOfReach {
            geometry: g.label(),
            model: "two-plate",
            reason: reason.clone(),
        });
    }
    if two_takes_hankel(method, tol, reach.is_ok()) {
        let plate = g.single_plate(OuterRadius::Finite(g.c))?;
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
    let params = TwoPlateParams {
        tolerance: tol,
        ..Default::default()
    };
    let sol = solve_two(&g.joint()?, &params).map_err(|source| CompareError::Two {
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
