//! Isotropic linear-elastic materials: Young's modulus E and Poisson's ratio ν, with the Lamé
//! constants of the report's eq. (2.3): λ = 2Gν/(1 − 2ν), μ = G = E/(2(1 + ν)).
//!
//! Units are the caller's: any consistent set (the report and the command-line tool use psi and
//! inches). Stresses come out in the unit of the applied pressure; displacements in the length unit
//! times pressure/E.
//!
//! # Accuracy
//!
//! Exact conversions (E, ν ↔ λ, μ); the library steel is the report's constants:
//! `tests/scene/units.rs` (`library_steel_304_is_the_reports_constants`).
//!
//! # Cost
//!
//! None.
//!
//! ```
//! use boltzone::Material;
//! let steel = Material::new(28.0e6, 0.3)?;
//! let (lambda, mu) = steel.lame();
//! assert!((mu - 28.0e6 / 2.6).abs() < 1e-6);
//! assert!((lambda - 2.0 * mu * 0.3 / 0.4).abs() < 1e-6);
//! assert!(Material::new(1.0, 0.5).is_err()); // incompressible: not admitted
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::{positive, InputError};
use serde::{Deserialize, Serialize};

/// An isotropic elastic material.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Material {
    youngs_modulus: f64,
    poisson_ratio: f64,
}

impl Material {
    /// A material with Young's modulus `e` > 0 and Poisson's ratio `nu` in (−1, 0.5).
    pub fn new(e: f64, nu: f64) -> Result<Self, InputError> {
        positive("Young's modulus E", e)?;
        if !nu.is_finite() {
            return Err(InputError::NotFinite {
                field: "Poisson's ratio nu",
                value: nu,
            });
        }
        if !(nu > -1.0 && nu < 0.5) {
            return Err(InputError::PoissonRatio { value: nu });
        }
        Ok(Self {
            youngs_modulus: e,
            poisson_ratio: nu,
        })
    }

    /// Type 304 stainless steel as in the report's experiments: E = 28·10⁶ psi, ν = 0.3.
    pub fn steel_304_psi() -> Self {
        Self {
            youngs_modulus: 28.0e6,
            poisson_ratio: 0.3,
        }
    }

    /// A unit-modulus material with Poisson's ratio ν: results scale with 1/E for displacements
    /// and not at all for stresses under prescribed loads.
    pub fn unit(nu: f64) -> Result<Self, InputError> {
        Self::new(1.0, nu)
    }

    /// Young's modulus E.
    pub fn youngs_modulus(&self) -> f64 {
        self.youngs_modulus
    }

    /// Poisson's ratio ν.
    pub fn poisson_ratio(&self) -> f64 {
        self.poisson_ratio
    }

    /// Shear modulus G = μ = E/(2(1 + ν)).
    pub fn shear_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// Lamé constants (λ, μ), report eq. (2.3).
    pub fn lame(&self) -> (f64, f64) {
        let mu = self.shear_modulus();
        let nu = self.poisson_ratio;
        (2.0 * mu * nu / (1.0 - 2.0 * nu), mu)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_bad_poisson_ratio_and_modulus() {
        for nu in [0.5, -1.0, 0.7, f64::NAN, f64::INFINITY] {
            let err = Material::new(1.0, nu).unwrap_err();
            assert!(err.to_string().contains("nu"), "{err}");
        }
        for e in [0.0, -3.0, f64::NAN] {
            let err = Material::new(e, 0.3).unwrap_err();
            assert!(err.to_string().contains("Young's modulus E"), "{err}");
        }
    }

    #[test]
    fn lame_constants_reproduce_young_and_poisson() {
        // E = μ(3λ + 2μ)/(λ + μ), ν = λ/(2(λ + μ)): the inverse relations, independent of eq. (2.3).
        for nu in [-0.9, 0.0, 0.3, 0.499] {
            let m = Material::new(2.5, nu).unwrap();
            let (l, mu) = m.lame();
            let e = mu * (3.0 * l + 2.0 * mu) / (l + mu);
            assert!((e - 2.5).abs() < 1e-12 * 2.5 / (1.0 - 2.0 * nu));
            assert!((l / (2.0 * (l + mu)) - nu).abs() < 1e-12);
        }
    }
}
