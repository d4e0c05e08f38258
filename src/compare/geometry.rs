//! The symmetric joint of the comparisons ([`Geometry`]): hole radius A, bearing face out to
//! B, plate thickness D, rim C, Poisson's ratio ν, in any one length unit; built from lengths
//! or from the report's ratios A/D, B/A, and turned into the two-plate [`Joint`] and the
//! single plate 2D thick with a unit uniform pressure on A ≤ r ≤ B (compression negative).
//!
//! # Accuracy
//!
//! Exact (no numerics): `tests/compare/tables.rs` rebuilds Table 1's and Table 2's geometries
//! from their ratios.
//!
//! # Cost
//!
//! None.
//!
//! ```
//! use boltzone::compare::Geometry;
//! let g = Geometry::from_ratios(0.1, 1.0, 3.1, 1.54, 0.3)?; // Table 1, first row
//! assert!((g.b - 0.31).abs() < 1e-15 && (g.d - 0.1).abs() < 1e-15);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::{positive, InputError};
use crate::joint::{Joint, OuterRadius, SinglePlate};
use crate::load::FaceLoad;
use crate::material::Material;
use serde::Serialize;

/// A symmetric joint: two equal plates of one material, uniform bearing pressure on A ≤ r ≤ B.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Geometry {
    /// Hole radius A.
    pub a: f64,
    /// Bearing-face outer radius B.
    pub b: f64,
    /// Thickness D of one plate.
    pub d: f64,
    /// Plate outer radius C (the report's plates have a rim, 1.54 in on Table 1; infinite
    /// plates are `f64::INFINITY`).
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
        if c.is_nan() || c <= b {
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

    /// The plates' outer radius: C, or infinite.
    pub fn outer_radius(&self) -> OuterRadius {
        match self.c.is_finite() {
            true => OuterRadius::Finite(self.c),
            false => OuterRadius::Infinite,
        }
    }

    /// The two-plate joint (unit modulus, unit pressure: R_o depends on neither).
    pub fn joint(&self) -> Result<Joint, InputError> {
        Joint::symmetric(self.a, self.b, self.d, Material::unit(self.nu)?)?
            .with_outer_radius(self.outer_radius())
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

    pub(super) fn label(&self) -> String {
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
