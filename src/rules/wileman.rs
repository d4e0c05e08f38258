//! The member stiffness fit of Wileman, Choudury & Green ("Computation of member stiffness in
//! bolted connections", ASME J. Mech. Des. 113, 1991, pp. 432–437; Shigley 9th ed. Eq. 8-23
//! and Table 8-8): from finite-element runs of two equal members,
//! k_m = E d A exp(B d/l), with grip l, bolt diameter d and the material's constants A, B.
//! The fit assumes a bearing face of 1.5 d and plates wide enough for the cone; it does not take
//! the bearing diameter.
//!
//! Units: any consistent set.
//!
//! # Accuracy
//!
//! `tests/joint/rules.rs`: Example 8-2 (c) of Shigley to its printed digits.
//!
//! # Cost
//!
//! One exponential.
//!
//! ```
//! use boltzone::rules::wileman::{member_stiffness, Material};
//! let k = member_stiffness(Material::Steel, 30e6, 0.5, 1.345)?;
//! assert!((k / 14.92e6 - 1.0).abs() < 5e-4);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::{positive, InputError};

/// The members' material (Table 8-8), with its fitted constants.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Material {
    /// Steel (ν = 0.291): A = 0.78715, B = 0.62873.
    Steel,
    /// Aluminium (ν = 0.334): A = 0.79670, B = 0.63816.
    Aluminium,
    /// Copper (ν = 0.326): A = 0.79568, B = 0.63553.
    Copper,
    /// Grey cast iron (ν = 0.211): A = 0.77871, B = 0.61616.
    GreyCastIron,
    /// The general expression: A = 0.78952, B = 0.62914.
    General,
}

impl Material {
    /// The constants (A, B).
    pub fn constants(self) -> (f64, f64) {
        match self {
            Self::Steel => (0.78715, 0.62873),
            Self::Aluminium => (0.79670, 0.63816),
            Self::Copper => (0.79568, 0.63553),
            Self::GreyCastIron => (0.77871, 0.61616),
            Self::General => (0.78952, 0.62914),
        }
    }

    /// The table's material nearest in Poisson's ratio to `nu` (its fits differ through ν).
    pub fn nearest(nu: f64) -> Self {
        [
            (0.291, Self::Steel),
            (0.334, Self::Aluminium),
            (0.326, Self::Copper),
            (0.211, Self::GreyCastIron),
        ]
        .iter()
        .min_by(|a, b| (a.0 - nu).abs().total_cmp(&(b.0 - nu).abs()))
        .map_or(Self::General, |m| m.1)
    }
}

/// k_m = E d A exp(B d/l) (module docs).
pub fn member_stiffness(material: Material, e: f64, d: f64, l: f64) -> Result<f64, InputError> {
    positive("modulus E", e)?;
    positive("bolt diameter d", d)?;
    positive("grip l", l)?;
    let (a, b) = material.constants();
    Ok(e * d * a * (b * d / l).exp())
}
