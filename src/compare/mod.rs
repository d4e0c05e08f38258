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
//! **Accuracy.** Every R_o to the tolerance asked by its own estimate; the estimates are
//! checked in the solvers' tests and examples 13 and 14; the tables end to end in
//! `tests/compare/tables.rs`. **Cost.** `cargo bench --bench contact` (all of Table 1) and
//! example 13 (per map point).
//!
//! ```
//! use boltzone::compare::{compare, CompareParams, Geometry};
//! let g = Geometry::from_ratios(0.1, 1.0, 3.1, 1.54, 0.3)?; // Table 1, first row
//! let c = compare(&g, &CompareParams { tolerance: 2e-3, ..Default::default() })?;
//! assert!(c.single.value > c.two.value);                 // the substitution overpredicts
//! assert!(c.rules[0].radius > c.two.value);              // so does the 45° cone
//! assert!(c.two.error <= 2e-3 * c.two.value);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod map;
pub mod single;
pub mod table1;
pub mod table2;

use crate::contact::two_plate::{solve as solve_two, TwoPlateParams};
use crate::contact::ContactError;
use crate::error::{positive, InputError};
use crate::fem::FemError;
use crate::hankel::separation::SeparationError;
use crate::joint::{Joint, OuterRadius, SinglePlate};
use crate::load::FaceLoad;
use crate::material::Material;
use crate::rules;
use rayon::prelude::*;
use serde::Serialize;
use std::time::Instant;

/// Failures of a comparison; each names the geometry it failed on.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CompareError {
    /// Bad input (names the field and value).
    #[error(transparent)]
    Input(#[from] InputError),
    /// The single-plate FE model failed.
    #[error("single-plate FE model at {geometry}: {source}")]
    Single {
        /// The geometry.
        geometry: String,
        /// What failed.
        source: FemError,
    },
    /// The single-plate Hankel model failed.
    #[error("single-plate Hankel model at {geometry}: {source}")]
    Hankel {
        /// The geometry.
        geometry: String,
        /// What failed.
        source: SeparationError,
    },
    /// The two-plate contact model failed.
    #[error("two-plate model at {geometry}: {source}")]
    Two {
        /// The geometry.
        geometry: String,
        /// What failed.
        source: ContactError,
    },
}

impl CompareError {
    /// Whether the failure is bad input (the caller's to fix) rather than a solver failure.
    pub fn is_input(&self) -> bool {
        match self {
            Self::Input(_) => true,
            Self::Single { source, .. } => source.is_input(),
            Self::Hankel { source, .. } => source.is_input(),
            Self::Two { source, .. } => source.is_input(),
        }
    }
}

pub use crate::value::Value;

/// A symmetric joint: two equal plates of one material, uniform bearing pressure on A ≤ r ≤ B.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Geometry {
    /// Hole radius A.
    pub a: f64,
    /// Bearing-face outer radius B.
    pub b: f64,
    /// Thickness D of one plate.
    pub d: f64,
    /// Plate outer radius C (finite: the rim is part of the report's model and of VDI's cone).
    pub c: f64,
    /// Poisson's ratio.
    pub nu: f64,
}

impl Geometry {
    /// Checked geometry from lengths.
    pub fn new(a: f64, b: f64, d: f64, c: f64, nu: f64) -> Result<Self, InputError> {
        positive("hole radius A", a)?;
        positive("plate thickness D", d)?;
        if !b.is_finite() || b <= a {
            return Err(InputError::Parameter {
                field: "load outer radius B",
                value: b,
                reason: "must be finite and exceed the hole radius A",
            });
        }
        if !c.is_finite() || c <= b {
            return Err(InputError::OuterRadius { b, c });
        }
        Material::unit(nu)?;
        Ok(Self { a, b, d, c, nu })
    }

    /// Geometry from the report's ratios: D = A/(A/D), B = A·(B/A).
    pub fn from_ratios(
        a: f64,
        a_over_d: f64,
        b_over_a: f64,
        c: f64,
        nu: f64,
    ) -> Result<Self, InputError> {
        positive("A/D", a_over_d)?;
        positive("B/A", b_over_a)?;
        Self::new(a, a * b_over_a, a / a_over_d, c, nu)
    }

    /// The twelve geometries of Table 1 (A = 0.1 in, C = 1.54 in, ν = 0.3), in printed order.
    pub fn table1() -> Vec<Self> {
        use crate::reference::{table1, TABLE1_HOLE_RADIUS, TABLE1_OUTER_RADIUS, TABLE1_POISSON};
        table1()
            .iter()
            .map(|r| {
                Self::from_ratios(
                    TABLE1_HOLE_RADIUS,
                    r.a_over_d,
                    r.b_over_a,
                    TABLE1_OUTER_RADIUS,
                    TABLE1_POISSON,
                )
                .expect("Table 1's geometries are valid")
            })
            .collect()
    }

    /// A/D.
    pub fn a_over_d(&self) -> f64 {
        self.a / self.d
    }

    /// B/A.
    pub fn b_over_a(&self) -> f64 {
        self.b / self.a
    }

    /// The two-plate joint (unit modulus, unit pressure: R_o depends on neither).
    pub fn joint(&self) -> Result<Joint, InputError> {
        Joint::symmetric(self.a, self.b, self.d, Material::unit(self.nu)?)?
            .with_outer_radius(OuterRadius::Finite(self.c))
    }

    /// The single-plate substitute, 2D thick, outer radius `c`.
    pub fn single_plate(&self, c: OuterRadius) -> Result<SinglePlate, InputError> {
        SinglePlate::new(
            self.a,
            c,
            self.d,
            Material::unit(self.nu)?,
            FaceLoad::uniform(self.a, self.b, 1.0)?,
        )
    }

    fn label(&self) -> String {
        format!(
            "A = {}, B = {}, D = {}, C = {}, nu = {} (A/D = {:.4}, B/A = {:.4})",
            self.a,
            self.b,
            self.d,
            self.c,
            self.nu,
            self.a_over_d(),
            self.b_over_a()
        )
    }
}

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
}

impl Default for CompareParams {
    fn default() -> Self {
        Self {
            tolerance: 5e-4,
            hankel_check: false,
            cone_degrees: 30.0,
        }
    }
}

/// A rule of thumb's contact radius and its error against the two-plate R_o.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RuleResult {
    /// "45° (Rötscher)", "VDI 2230" or "30° cone".
    pub name: &'static str,
    /// Cone half-angle, degrees.
    pub half_angle_degrees: f64,
    /// The rule's contact radius.
    pub radius: f64,
    /// Whether the cone reached the rim C (radius = C).
    pub truncated: bool,
    /// (R_rule − R_two)/R_two·100, with the two-plate error propagated.
    pub error_percent: Value,
}

/// Timings and sizes of one comparison.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CompareInfo {
    /// Equations of the finest single-plate FE mesh.
    pub single_dofs: usize,
    /// FE refinement levels of the single plate.
    pub single_levels: usize,
    /// Mesh levels of the two-plate model.
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
    /// Single-plate R_o (FE, finite C).
    pub single: Value,
    /// Single-plate R_o by Hankel transforms (infinite plate), if asked for.
    pub single_hankel: Option<Value>,
    /// Two-plate R_o.
    pub two: Value,
    /// (R_single − R_two)/R_two·100.
    pub discrepancy_percent: Value,
    /// Contact-area discrepancy (X_single − X_two)/X_two·100, X = R_o² − A².
    pub area_discrepancy_percent: Value,
    /// 45°, VDI 2230 and the extra cone, in that order.
    pub rules: [RuleResult; 3],
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
    let plate = g.single_plate(OuterRadius::Finite(g.c))?;
    let (single, fem) =
        single::single_fem(&plate, params.tolerance).map_err(|source| CompareError::Single {
            geometry: label(),
            source,
        })?;
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
    let two_params = TwoPlateParams {
        tolerance: params.tolerance,
        ..Default::default()
    };
    let sol = solve_two(&g.joint()?, &two_params).map_err(|source| CompareError::Two {
        geometry: label(),
        source,
    })?;
    let two = Value {
        value: sol.r_o,
        error: sol.r_o_error,
        converged: sol.converged,
    };
    let seconds_two = t.elapsed().as_secs_f64();
    let rule = |name, cone: rules::ConeRadius| RuleResult {
        name,
        half_angle_degrees: cone.half_angle.to_degrees(),
        radius: cone.radius,
        truncated: cone.truncated,
        error_percent: percent_difference(Value::exact(cone.radius), two),
    };
    let rules = [
        rule("45° (Rötscher)", rules::roetscher(g.b, g.d, g.c)?),
        rule("VDI 2230", rules::vdi2230(g.b, g.d, g.d, g.c)?),
        rule(
            "cone",
            rules::cone_radius(g.b, g.d, params.cone_degrees.to_radians(), g.c)?,
        ),
    ];
    Ok(Comparison {
        geometry: g,
        single,
        single_hankel,
        two,
        discrepancy_percent: percent_difference(single, two),
        area_discrepancy_percent: percent_difference(area(single, g.a), area(two, g.a)),
        rules,
        info: CompareInfo {
            single_dofs: fem.dofs,
            single_levels: fem.levels,
            two_levels: sol.info.levels.len(),
            two_model: sol.info.model,
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
