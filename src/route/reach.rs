//! The domain of the inputs every route takes, stated once: each front end checks a question
//! against it before any work and names the input its own way (a flag, a scene key and its
//! line). Outside it a route's meshes or quadratures cannot be sized within bounded memory and
//! time in f64, so such input is refused rather than left to run out of either.
//!
//! Lengths are in thicknesses of the (thinner) plate D: a hole A = 0 or within [`A_OVER_D`], a
//! bearing face out to B ≤ [`b_over_d_max`] of the model, the two plates' thicknesses within
//! [`THICKNESS_RATIO`] of each other, Poisson's ratio ≤ [`NU_MAX_FEM`] where the finite
//! elements may answer.
//!
//! # Accuracy and cost
//!
//! Constants and comparisons: the fuzz of every command (`tests/cli/fuzz.rs`) finds no input
//! inside the domain that a route fails on for want of memory or range.
//!
//! ```
//! use boltzone::route::reach::{self, Model};
//! assert_eq!(reach::b_over_d_max(Model::TwoPlate), 1e3);
//! assert!(reach::hole_in_reach(0.1, 0.1) && reach::hole_in_reach(0.0, 0.1));
//! assert!(!reach::hole_in_reach(1e-5, 0.1));
//! ```

/// The three models of the joint, for their reach.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Model {
    /// Two plates in unilateral contact (report Chapter II.B).
    TwoPlate,
    /// The single-plate substitute (Fernlund's substitution, Chapter II.A).
    SinglePlate,
    /// The slab without a hole (Sneddon's problem).
    Slab,
}

/// Widest bearing face of the slab, in plate thicknesses (its real-space route's reach).
pub const B_OVER_D_SLAB: f64 = 1e6;
/// Widest bearing face of the single plate (FE and Hankel), in plate thicknesses.
pub const B_OVER_D_SINGLE: f64 = 1e4;
/// Widest bearing face of the two-plate model, in thicknesses of the thinner plate: beyond it
/// the loaded plate's bending stiffness falls below f64 resolution of its stiffness matrix.
pub const B_OVER_D_TWO: f64 = 1e3;

/// Widest bearing face the single plate's Hankel route takes when asked by name, in plate
/// thicknesses D (the substitute is 2D thick): beyond about 3,850 its midplane ξ-quadrature
/// needs more than its 400,000-node budget ([`crate::hankel::midplane::MAX_NODES`]; measured
/// at A = D, ν = 0.3, tolerances 1e-12 … 1e-3), so it is refused before any work; `auto` takes
/// the finite elements there.
pub const B_OVER_D_SINGLE_HANKEL: f64 = 3e3;

/// The largest Poisson's ratio the finite-element routes take: closer to 0.5 the displacement
/// elements lock and the stiffness matrix loses definiteness in f64.
pub const NU_MAX_FEM: f64 = 0.499;

/// The range of a hole's radius A/D (A = 0, no hole, is also in reach).
pub const A_OVER_D: (f64, f64) = (1e-3, 1e3);

/// The largest ratio of the two plates' thicknesses (either way).
pub const THICKNESS_RATIO: f64 = 1e3;

/// The widest bearing face B/D `model` reaches.
pub fn b_over_d_max(model: Model) -> f64 {
    match model {
        Model::TwoPlate => B_OVER_D_TWO,
        Model::SinglePlate => B_OVER_D_SINGLE,
        Model::Slab => B_OVER_D_SLAB,
    }
}

/// Whether a hole of radius `a` in a plate `d` thick is in reach (no hole, or A/D in
/// [`A_OVER_D`]).
pub fn hole_in_reach(a: f64, d: f64) -> bool {
    a <= 0.0 || (A_OVER_D.0..=A_OVER_D.1).contains(&(a / d))
}
