//! The rules of thumb beside an answer ([`beside`]): Rötscher's 45° cone, the VDI 2230 (2003)
//! substitute deformation cone and a cone of a given half-angle (30° by default), each rule's
//! contact radius with its error against the computed R_o; a rule that cannot be applied to the
//! joint is listed with the reason instead of being dropped. Every front end that prints R_o
//! (`two`, `solve`, the tables, the map, the page) prints these.
//!
//! The cones run from the bearing face's edge B through the upper plate (D₁ thick):
//! R = B + D₁ tan φ, at most the rim C ([`crate::rules`]). VDI's φ needs the outside diameter
//! D′_A = 2C: for an infinite plate it is left out, saying so.
//!
//! # Accuracy
//!
//! Closed forms ([`crate::rules`]); the error in percent carries R_o's error bar
//! ([`Value::percent_difference`]).
//!
//! # Cost
//!
//! Microseconds.
//!
//! ```
//! use boltzone::route::rules_beside::beside;
//! use boltzone::{OuterRadius, Value};
//! let r_o = Value { value: 0.35215, error: 4e-5, converged: true };
//! let rules = beside((0.31, 0.1, 0.1, OuterRadius::Infinite), 30.0, r_o);
//! assert_eq!(rules.rules.len(), 2); // 45° and 30°: VDI needs a finite rim
//! assert!(rules.left_out[0].reason.contains("D'_A"));
//! assert!(rules.rules[0].error_percent.value > 0.0); // the 45° cone overpredicts
//! ```

use crate::joint::OuterRadius;
use crate::rules::{cone_radius, roetscher, vdi2230, ConeRadius};
use crate::value::Value;
use serde::Serialize;

/// A rule of thumb's contact radius and its error against the computed R_o.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RuleResult {
    /// "45° cone" (Rötscher's), "VDI 2230", "30° cone" (or "cone", of another half-angle
    /// asked).
    pub name: &'static str,
    /// Cone half-angle, degrees.
    pub half_angle_degrees: f64,
    /// The rule's contact radius (the joint's length unit).
    pub radius: f64,
    /// Whether the cone reached the rim C (radius = C).
    pub truncated: bool,
    /// (R_rule − R_o)/R_o·100, with R_o's error propagated.
    pub error_percent: Value,
}

/// A rule that could not be applied to the joint, and why.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RuleLeftOut {
    /// The rule's name.
    pub name: &'static str,
    /// Why it was left out.
    pub reason: String,
}

/// The rules beside one R_o: those applied, and those left out with the reason (JSON keys
/// `rules` and `rules_left_out`, the latter only when a rule was left out).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Rules {
    /// The rules applied, in the order 45°, VDI 2230, the cone of the half-angle asked.
    pub rules: Vec<RuleResult>,
    /// The rules that could not be applied.
    #[serde(rename = "rules_left_out", skip_serializing_if = "Vec::is_empty")]
    pub left_out: Vec<RuleLeftOut>,
}

/// The rules' contact radii for a bearing face of radius B on plates D₁ (under the head) and
/// D₂ thick of outer radius C — `(b, d1, d2, c)` — with the extra cone's half-angle
/// `cone_degrees`: the cones applied, in the order 45°, VDI 2230, the extra cone, and those
/// left out with the reason.
pub fn radii(
    (b, d1, d2, c): (f64, f64, f64, OuterRadius),
    cone_degrees: f64,
) -> (Vec<(&'static str, ConeRadius)>, Vec<RuleLeftOut>) {
    let c_rule = match c {
        OuterRadius::Finite(c) => c,
        OuterRadius::Infinite => f64::INFINITY,
    };
    let vdi = match c {
        OuterRadius::Finite(c) => vdi2230(b, d1, d2, c).map_err(|e| e.to_string()),
        OuterRadius::Infinite => Err(
            "its cone angle needs a finite outside diameter D'_A = 2C, and the plates are infinite"
                .to_string(),
        ),
    };
    let cone_name = if cone_degrees == 30.0 {
        "30° cone"
    } else {
        "cone"
    };
    let candidates = [
        (
            "45° cone",
            roetscher(b, d1, c_rule).map_err(|e| e.to_string()),
        ),
        ("VDI 2230", vdi),
        (
            cone_name,
            cone_radius(b, d1, cone_degrees.to_radians(), c_rule).map_err(|e| e.to_string()),
        ),
    ];
    let (mut applied, mut left_out) = (Vec::new(), Vec::new());
    for (name, cone) in candidates {
        match cone {
            Ok(cone) => applied.push((name, cone)),
            Err(reason) => left_out.push(RuleLeftOut { name, reason }),
        }
    }
    (applied, left_out)
}

/// The rules beside `r_o` ([`radii`] with each rule's error against `r_o`).
pub fn beside(joint: (f64, f64, f64, OuterRadius), cone_degrees: f64, r_o: Value) -> Rules {
    let (applied, left_out) = radii(joint, cone_degrees);
    Rules {
        rules: applied
            .into_iter()
            .map(|(name, cone)| result(name, cone, r_o))
            .collect(),
        left_out,
    }
}

/// One rule's result against `r_o`.
fn result(name: &'static str, cone: ConeRadius, r_o: Value) -> RuleResult {
    RuleResult {
        name,
        half_angle_degrees: cone.half_angle.to_degrees(),
        radius: cone.radius,
        truncated: cone.truncated,
        error_percent: Value::exact(cone.radius).percent_difference(r_o),
    }
}
