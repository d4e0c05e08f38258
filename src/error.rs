//! Typed errors for bad input, each naming the offending field and value.
//!
//! Every constructor in [`crate::material`], [`crate::load`] and [`crate::joint`] validates its
//! arguments and returns an [`InputError`] rather than panicking or clamping. Field names use the
//! report's notation (A, B, C, D, E, ν) with a word of explanation, so a message can be shown to a
//! user as it is.
//!
//! # Accuracy
//!
//! Not numerical. Errors name the field and value: `tests/cli/regressions.rs`
//! (`every_bad_value_is_named_by_its_flag`) and the typed-error tests of each solver.
//!
//! # Cost
//!
//! None.
//!
//! ```
//! use boltzone::{FaceLoad, InputError};
//! let err = FaceLoad::uniform(0.2, 0.1, 1.0).unwrap_err();
//! assert!(matches!(err, InputError::LoadRadii { .. }));
//! assert!(err.to_string().contains("B = 0.1"));
//! ```

use thiserror::Error;

/// A rejected input. Displayed messages name the field and the value.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum InputError {
    /// A number that must be finite is NaN or infinite.
    #[error("{field} = {value} is not a finite number")]
    NotFinite {
        /// Which input (report notation).
        field: &'static str,
        /// The value given.
        value: f64,
    },
    /// A number that must be strictly positive is zero or negative.
    #[error("{field} = {value} must be positive")]
    NotPositive {
        /// Which input (report notation).
        field: &'static str,
        /// The value given.
        value: f64,
    },
    /// A number that must be zero or positive is negative.
    #[error("{field} = {value} must not be negative")]
    Negative {
        /// Which input (report notation).
        field: &'static str,
        /// The value given.
        value: f64,
    },
    /// The load's outer radius B does not exceed its inner radius (the hole radius A).
    #[error("load outer radius B = {b} must exceed its inner radius A = {a}")]
    LoadRadii {
        /// Inner radius of the loaded annulus.
        a: f64,
        /// Outer radius of the loaded annulus.
        b: f64,
    },
    /// The plate's outer radius C does not exceed the load's outer radius B.
    #[error("plate outer radius C = {c} must exceed the load's outer radius B = {b}")]
    OuterRadius {
        /// Load outer radius.
        b: f64,
        /// Plate outer radius.
        c: f64,
    },
    /// The load's inner radius differs from the hole radius it should start at.
    #[error("the load starts at r = {load_a} but the hole radius A = {hole_a}: a face load must lie on the plate")]
    LoadOffPlate {
        /// Inner radius of the load.
        load_a: f64,
        /// Hole radius of the plate.
        hole_a: f64,
    },
    /// Poisson's ratio outside the open interval (−1, 0.5) where the elastic energy is positive.
    #[error("Poisson's ratio nu = {value} must lie in the open interval (-1, 0.5)")]
    PoissonRatio {
        /// The value given.
        value: f64,
    },
    /// A tabulated load is malformed.
    #[error("tabulated load: {reason}")]
    Table {
        /// What is wrong, with the offending index and value.
        reason: String,
    },
    /// A numerical parameter (tolerance, mesh size, …) is out of range.
    #[error("{field} = {value}: {reason}")]
    Parameter {
        /// Which parameter.
        field: &'static str,
        /// The value given.
        value: f64,
        /// The admissible range.
        reason: &'static str,
    },
}

/// Checks that `value` is finite.
pub(crate) fn finite(field: &'static str, value: f64) -> Result<f64, InputError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(InputError::NotFinite { field, value })
    }
}

/// Checks that `value` is finite and strictly positive.
pub(crate) fn positive(field: &'static str, value: f64) -> Result<f64, InputError> {
    finite(field, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(InputError::NotPositive { field, value })
    }
}

/// Checks that `value` is finite and not negative.
pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<f64, InputError> {
    finite(field, value)?;
    if value >= 0.0 {
        Ok(value)
    } else {
        Err(InputError::Negative { field, value })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn helpers_name_the_field() {
        let e = positive("thickness D", -1.0).unwrap_err();
        assert_eq!(e.to_string(), "thickness D = -1 must be positive");
        let e = finite("hole radius A", f64::NAN).unwrap_err();
        assert!(e.to_string().starts_with("hole radius A = NaN"));
        assert!(non_negative("hole radius A", 0.0).is_ok());
        assert!(matches!(
            non_negative("hole radius A", -0.0001),
            Err(InputError::Negative { .. })
        ));
    }
}
