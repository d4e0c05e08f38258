//! Failures of the finite-element solver: bad input (naming the field and value) and the ways a
//! model can be defective (a missing support, a pattern of another mesh).
//!
//! # Accuracy
//!
//! Not numerical: `tests/fem/system.rs` (`a_pattern_of_another_dof_map_is_a_named_error`).
//!
//! # Cost
//!
//! None.
//!
//! ```
//! use boltzone::fem::FemError;
//! let e = FemError::Solver("the stiffness matrix is not positive definite".into());
//! assert!(!e.is_input() && e.to_string().contains("positive definite"));
//! ```

use crate::error::InputError;

/// Failures of the finite-element solver.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FemError {
    /// Bad input (names the field and value).
    #[error(transparent)]
    Input(#[from] InputError),
    /// An element refers to a material that was not supplied.
    #[error(
        "element {element} uses material {material} but only {available} materials were given"
    )]
    MissingMaterial {
        /// Element index.
        element: usize,
        /// Material index it refers to.
        material: usize,
        /// Number of materials given.
        available: usize,
    },
    /// An element couples two equations the pattern does not hold (a pattern built for another
    /// mesh or dof map).
    #[error(
        "entry ({row}, {col}) is not in the sparsity pattern (pattern of another mesh or dof map?)"
    )]
    PatternMismatch {
        /// Row equation.
        row: usize,
        /// Column equation.
        col: usize,
    },
    /// The pattern was built for a different number of equations.
    #[error("the sparsity pattern has {pattern} equations but the dof map {equations}")]
    PatternSize {
        /// Equations of the pattern.
        pattern: usize,
        /// Equations of the dof map.
        equations: usize,
    },
    /// K is not positive definite: usually a rigid-body motion left free by the supports.
    #[error("stiffness matrix not positive definite (missing supports?): {0}")]
    NotPositiveDefinite(String),
    /// Any other failure of the sparse solver.
    #[error("sparse solver: {0}")]
    Solver(String),
}

impl FemError {
    /// Whether the failure is bad input (the caller's to fix) rather than a solver failure.
    pub fn is_input(&self) -> bool {
        matches!(self, Self::Input(_))
    }
}
