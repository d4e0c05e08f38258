//! The error of a comparison ([`CompareError`]): an input error, a point beyond a Hankel
//! route's reach, or the failure of one of the models, naming the geometry it failed on.
//!
//! # Accuracy
//!
//! Not numerical; `tests/cli/main.rs` checks that input errors exit 2 naming the field.
//!
//! # Cost
//!
//! None.
//!
//! ```
//! use boltzone::compare::{CompareError, Geometry};
//! let e: CompareError = Geometry::new(0.1, 0.05, 0.1, 1.0, 0.3).unwrap_err().into();
//! assert!(e.is_input());
//! ```

use crate::contact::ContactError;
use crate::error::InputError;
use crate::fem::FemError;
use crate::hankel::receding::RecedingError;
use crate::hankel::separation::SeparationError;

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
    /// The two-plate Hankel route failed (`Method::Hankel`).
    #[error("two-plate Hankel route at {geometry}: {source}")]
    TwoHankel {
        /// The geometry.
        geometry: String,
        /// What failed.
        source: RecedingError,
    },
    /// `Method::Hankel` asked of a point beyond a Hankel route's reach (bad input).
    #[error("{model} model at {geometry}: {reason}; use the method fem or auto")]
    OutOfReach {
        /// The geometry.
        geometry: String,
        /// Which model ("two-plate").
        model: &'static str,
        /// Which limit the point breaks, with its value.
        reason: String,
    },
    /// The two-plate contact model failed.
    #[error("two-plate model at {geometry}: {source}")]
    Two {
        /// The geometry.
        geometry: String,
        /// What failed.
        source: ContactError,
    },
    /// A rule of thumb cannot be applied to the geometry (bad input: VDI 2230's correlation
    /// gives no cone there).
    #[error("rules of thumb at {geometry}: {reason}")]
    Rule {
        /// The geometry.
        geometry: String,
        /// The rule and why.
        reason: String,
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
            Self::TwoHankel { source, .. } => source.is_input(),
            Self::OutOfReach { .. } | Self::Rule { .. } => true,
        }
    }
}
