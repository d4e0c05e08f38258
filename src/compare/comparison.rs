//! One comparison ([`compare`]) and many in parallel ([`compare_all`]): the single-plate R_o
//! (finite elements, optionally Hankel with the hole correction), the two-plate R_o, the
//! report's discrepancies in R_o and in contact area, and the rules of thumb, each with its
//! propagated error (the quantities are defined in the [folder's docs](super)).
//!
//! # Accuracy
//!
//! Every R_o to the tolerance asked by its own estimate (the solvers' tests, examples 13 and
//! 14); the tables end to end in `tests/compare/tables.rs`.
//!
//! # Cost
//!
//! `cargo bench --bench contact` (all of Table 1) and example 13 (per map point).
//!
//! ```
//! use boltzone::compare::{percent_difference, show, Value};
//! let d = percent_difference(Value::exact(1.1), Value::exact(1.0));
//! assert!((d.value - 10.0).abs() < 1e-12 && d.error == 0.0);
//! assert_eq!(show(Value::exact(1.5), 2), "1.50 ± 0.0e0");
//! ```

use super::route::{self, Method, Route};
use super::{single, CompareError, Geometry};
use crate::error::positive;
use crate::joint::OuterRadius;
use crate::route::rules_beside;
use crate::value::Value;
use rayon::prelude::*;
use serde::Serialize;
use std::time::Instant;

/// Knobs of [`compare`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompareParams {
    /// Wanted relative error of each model's R_o (default 5e-4 = 0.05 %).
    pub tolerance: f64,
    /// Also compute the single-plate R_o by Hankel transforms with the hole correction for an
    /// infinite plate, as a second method (default false).
    pub hankel_check: bool,
    /// Half-angle of the extra cone rule, degrees (default 30).
    pub cone_degrees: f64,
    /// How each model's R_o is computed (default [`Method::Fem`]; [`super::route`]).
    pub method: Method,
}

impl Default for CompareParams {
    fn default() -> Self {
        Self {
            tolerance: 5e-4,
            hankel_check: false,
            cone_degrees: 30.0,
            method: Method::Fem,
        }
    }
}

/// A rule of thumb's contact radius and its error against the two-plate R_o (the route
/// layer's, as every front end prints them).
pub use crate::route::rules_beside::{RuleLeftOut, RuleResult};

/// Timings and sizes of one comparison.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CompareInfo {
    /// Equations of the finest single-plate FE mesh (0 by the Hankel route).
    pub single_dofs: usize,
    /// FE refinement levels of the single plate (by the Hankel route: the hole's mode counts
    /// tried).
    pub single_levels: usize,
    /// Mesh levels of the two-plate model (by the Hankel route: the contact radii tried).
    pub two_levels: usize,
    /// Which two-plate model ran.
    pub two_model: &'static str,
    /// Seconds: single-plate FE, Hankel check (0 if not run), two-plate, total.
    pub seconds_single: f64,
    /// Seconds of the Hankel check.
    pub seconds_hankel: f64,
    /// Seconds of the two-plate model.
    pub seconds_two: f64,
    /// Total seconds.
    pub seconds: f64,
}

/// One geometry's comparison (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Comparison {
    /// The geometry.
    pub geometry: Geometry,
    /// Single-plate R_o (finite C; by the method in `single_method`).
    pub single: Value,
    /// The method that computed `single`.
    pub single_method: Route,
    /// Single-plate R_o by Hankel transforms (infinite plate), if asked for.
    pub single_hankel: Option<Value>,
    /// Two-plate R_o (finite C; by the method in `two_method`).
    pub two: Value,
    /// The method that computed `two`.
    pub two_method: Route,
    /// (R_single − R_two)/R_two·100.
    pub discrepancy_percent: Value,
    /// Contact-area discrepancy (X_single − X_two)/X_two·100, X = R_o² − A².
    pub area_discrepancy_percent: Value,
    /// 45°, VDI 2230 and the extra cone, in that order; None where the rule does not apply
    /// (VDI 2230 needs a rim: its cone angle takes D'_A = 2C), the reason in
    /// `rules_left_out`.
    pub rules: [Option<RuleResult>; 3],
    /// The rules that do not apply to the geometry, and why.
    pub rules_left_out: Vec<RuleLeftOut>,
    /// Timings and sizes.
    pub info: CompareInfo,
}

impl Comparison {
    /// R_o/A with its error for a model's value.
    pub fn over_a(&self, v: Value) -> Value {
        v.scaled(1.0 / self.geometry.a)
    }

    /// Whether every R_o of the comparison met its tolerance.
    pub fn converged(&self) -> bool {
        self.single.converged
            && self.two.converged
            && self.single_hankel.is_none_or(|h| h.converged)
    }
}

/// `value ± error` for a table: the value with `decimals` decimals, the error in scientific
/// notation (so that a small error never prints as 0.0000), and ` NOT converged` where the
/// error missed the tolerance.
pub fn show(v: Value, decimals: usize) -> String {
    format!(
        "{:.*} ± {:.1e}{}",
        decimals,
        v.value,
        v.error,
        if v.converged { "" } else { " NOT converged" }
    )
}

/// (x − y)/y·100 with first-order error propagation ([`Value::percent_difference`]).
pub fn percent_difference(x: Value, y: Value) -> Value {
    x.percent_difference(y)
}

/// X = R² − A² (contact area / π) with its error 2R·e.
fn area(r: Value, a: f64) -> Value {
    Value {
        value: r.value * r.value - a * a,
        error: 2.0 * r.value * r.error,
        converged: r.converged,
    }
}

/// Compares the models and rules on one geometry (module docs).
pub fn compare(g: &Geometry, params: &CompareParams) -> Result<Comparison, CompareError> {
    let start = Instant::now();
    let g = Geometry::new(g.a, g.b, g.d, g.c, g.nu)?;
    positive("comparison tolerance", params.tolerance)?;
    let label = || g.label();
    let one = route::single(&g, params.method, params.tolerance)?;
    let single = one.value;
    let seconds_single = start.elapsed().as_secs_f64();
    let t = Instant::now();
    let single_hankel = if params.hankel_check {
        let infinite = g.single_plate(OuterRadius::Infinite)?;
        Some(
            single::single_hankel(&infinite, params.tolerance).map_err(|source| {
                CompareError::Hankel {
                    geometry: label(),
                    source,
                }
            })?,
        )
    } else {
        None
    };
    let seconds_hankel = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let pair = route::two(&g, params.method, params.tolerance)?;
    let two = pair.value;
    let seconds_two = t.elapsed().as_secs_f64();
    let beside = rules_beside::beside((g.b, g.d, g.d, g.outer_radius()), params.cone_degrees, two);
    // every rule applies to plates with a rim; VDI 2230 alone needs one
    let infinite = g.outer_radius() == OuterRadius::Infinite;
    if let Some(r) = beside
        .left_out
        .iter()
        .find(|r| !(infinite && r.name == "VDI 2230"))
    {
        return Err(CompareError::Rule {
            geometry: label(),
            reason: format!("{}: {}", r.name, r.reason),
        });
    }
    let mut rules = [None; 3];
    for r in beside.rules {
        let slot = match r.name {
            "45° cone" => 0,
            "VDI 2230" => 1,
            _ => 2,
        };
        rules[slot] = Some(r);
    }
    Ok(Comparison {
        geometry: g,
        single,
        single_method: one.route,
        single_hankel,
        two,
        two_method: pair.route,
        discrepancy_percent: percent_difference(single, two),
        area_discrepancy_percent: percent_difference(area(single, g.a), area(two, g.a)),
        rules,
        rules_left_out: beside.left_out,
        info: CompareInfo {
            single_dofs: one.dofs,
            single_levels: one.levels,
            two_levels: pair.levels,
            two_model: pair.model,
            seconds_single,
            seconds_hankel,
            seconds_two,
            seconds: start.elapsed().as_secs_f64(),
        },
    })
}

/// [`compare`] on many geometries in parallel (rayon; each FE factorization runs sequentially).
/// `tick` is called once per finished geometry (for a progress bar). Results keep the input order.
pub fn compare_all(
    geometries: &[Geometry],
    params: &CompareParams,
    tick: &(dyn Fn() + Sync),
) -> Vec<Result<Comparison, CompareError>> {
    geometries
        .par_iter()
        .map(|g| {
            let r = compare(g, params);
            tick();
            r
        })
        .collect()
}
