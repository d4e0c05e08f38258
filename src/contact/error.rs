//! Errors of the contact solvers: bad input, and the ways an iteration can fail.
//!
//! # Accuracy
//!
//! Not numerical. That every input error is typed, names its field and makes the command exit 2 is
//! checked by `tests/contact/two_plate.rs` (`bad_parameters_are_typed_errors`) and
//! `tests/contact/lcp.rs` (`bad_input_is_a_typed_error`).
//!
//! # Cost
//!
//! None.
//!
//! ```
//! use boltzone::contact::ContactError;
//! let e = ContactError::NotConverged { iterations: 7, violations: 2 };
//! assert!(e.to_string().contains("7 iterations"));
//! ```

use crate::error::InputError;
use crate::fem::FemError;
use thiserror::Error;

/// A contact computation that could not deliver a solution.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ContactError {
    /// Invalid input (geometry, load, material or a numerical parameter).
    #[error(transparent)]
    Input(#[from] InputError),
    /// The active-set iteration hit its iteration bound with sign conditions still violated.
    #[error("contact iteration did not converge in {iterations} iterations ({violations} sign conditions still violated)")]
    NotConverged {
        /// Iterations spent.
        iterations: usize,
        /// Number of violated conditions (negative force in contact or penetration outside).
        violations: usize,
    },
    /// A restricted flexibility matrix was not positive definite (a defective model).
    #[error(
        "the flexibility matrix restricted to {size} contact unknowns is not positive definite"
    )]
    NotPositiveDefinite {
        /// Size of the restricted matrix.
        size: usize,
    },
    /// The finite-element model failed (assembly or factorization: e.g. a support is missing).
    #[error(transparent)]
    Fem(#[from] FemError),
    /// The reference contact node, held down to remove the rigid motion, pulls on the plane.
    #[error("the reference contact node at r = {radius} carries a tensile reaction {reaction}; the load does not press the plates together there")]
    ReferenceInTension {
        /// Radius of the reference node.
        radius: f64,
        /// Its reaction (negative: tension).
        reaction: f64,
    },
    /// The contact zone reached the outer radius of the plate or the candidate window could not grow.
    #[error("the contact zone reaches r = {radius}, the end of the candidate window, which cannot grow further")]
    WindowExhausted {
        /// Radius reached.
        radius: f64,
    },
}

impl ContactError {
    /// Whether the failure is bad input (the caller's to fix) rather than a solver failure.
    pub fn is_input(&self) -> bool {
        match self {
            Self::Input(_) => true,
            Self::Fem(e) => e.is_input(),
            _ => false,
        }
    }
}
