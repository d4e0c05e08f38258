//! Errors of scenes: bad input located by key and line, and the solvers' own errors.
//!
//! # Accuracy
//!
//! Not numerical: `tests/scene/errors.rs` (errors located by key and line, exit codes 2 and 3).
//!
//! # Cost
//!
//! None.
//!
//! ```
//! let e = boltzone::scene::Scene::parse("units = \"furlongs\"\n").unwrap_err();
//! assert!(e.is_input() && e.line() == Some(1), "{e}");
//! ```

use crate::contact::ContactError;
use crate::error::InputError;
use crate::fem::FemError;
use crate::hankel::receding::RecedingError;
use crate::hankel::separation::SeparationError;

/// Why a scene could not be read or answered.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// Malformed scene: the message says the key, the value and the line.
    #[error("scene line {line}, key `{key}`: {reason}")]
    Invalid {
        /// Key path (`plates[1].thickness`).
        key: String,
        /// 1-based line of the key in the file (of `[sweep]`'s key for a swept value).
        line: usize,
        /// What is wrong, with the value.
        reason: String,
    },
    /// A bad value in a scene built in code ([`super::builder`]): the key path and what is wrong.
    #[error("scene key `{key}`: {reason}")]
    Key {
        /// Key path (`plates[1].thickness`).
        key: String,
        /// What is wrong, with the value.
        reason: String,
    },
    /// A malformed row of a CSV of geometries: the message says the CSV line and column.
    #[error("geometries CSV line {line}, column `{key}`: {reason}")]
    Geometry {
        /// The column's scene key.
        key: String,
        /// 1-based line in the CSV.
        line: usize,
        /// What is wrong, with the value.
        reason: String,
    },
    /// The scene file could not be read.
    #[error("cannot read scene file {path}: {source}")]
    Read {
        /// The path given.
        path: String,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The two-plate solver failed.
    #[error(transparent)]
    Contact(#[from] ContactError),
    /// The finite-element single plate failed.
    #[error(transparent)]
    Fem(#[from] FemError),
    /// A Hankel route failed.
    #[error(transparent)]
    Separation(#[from] SeparationError),
    /// The semi-analytic two-plate route failed.
    #[error(transparent)]
    Receding(#[from] RecedingError),
    /// A library constructor rejected a value.
    #[error(transparent)]
    Input(#[from] InputError),
}

impl SceneError {
    /// Whether the error is bad input (exit 2) rather than a failure of a solver (exit 1).
    pub fn is_input(&self) -> bool {
        match self {
            Self::Invalid { .. }
            | Self::Key { .. }
            | Self::Geometry { .. }
            | Self::Read { .. }
            | Self::Input(_) => true,
            Self::Contact(e) => e.is_input(),
            Self::Fem(e) => e.is_input(),
            Self::Separation(e) => e.is_input(),
            Self::Receding(e) => e.is_input(),
        }
    }

    /// The line of a located error.
    pub fn line(&self) -> Option<usize> {
        match self {
            Self::Invalid { line, .. } | Self::Geometry { line, .. } => Some(*line),
            _ => None,
        }
    }
}
