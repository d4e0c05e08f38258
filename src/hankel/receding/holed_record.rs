//! The record of the semi-analytic two-plate route with the hole ([`super::holed`]): R_o with
//! its error estimate and cost ([`HoledContact`], [`HoledInfo`]) and, with a finite outer
//! radius, the rim's terms ([`RimRecord`], module `rim_holed`). Lengths in the units of the
//! plate; serialized into `two --method hankel --json` as `hankel`.
//!
//! # Accuracy
//!
//! What the estimate covers and how it was checked: [`super::holed`] and module `rim_holed`.
//!
//! # Cost
//!
//! None of its own.
//!
//! ```
//! use boltzone::hankel::receding::holed::HoledInfo;
//! let info = HoledInfo::default();
//! assert!(info.rim.is_none()); // C = ∞: no rim terms, and none in the JSON
//! assert!(!serde_json::to_string(&info)?.contains("rim"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

/// What [`two_plate_hole`](super::holed::two_plate_hole) did and how well.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct HoledInfo {
    /// Estimated absolute error of R_o (see the module docs).
    pub r_o_error: f64,
    /// R_o with ⌈3n/4⌉ Nyström points (NaN when not estimated).
    pub r_o_fewer_nodes: f64,
    /// R_o with half the hole modes and 2/3 of the Chebyshev heights (NaN when not estimated).
    pub r_o_half_terms: f64,
    /// Largest residual traction of crack field + its correction on the hole, relative to P.
    pub residual_max: f64,
    /// The bilateral plate's residual traction on the hole, relative to P.
    pub bilateral_residual: f64,
    /// Largest crack-field traction on the hole before correction, relative to P.
    pub crack_traction: f64,
    /// Iterations of the last solve.
    pub iterations: usize,
    /// Crack iterations over every radius of the search (not the estimate's runs).
    pub search_iterations: usize,
    /// Contact radii tried (all runs).
    pub solves: usize,
    /// Wall-clock seconds.
    pub seconds: f64,
    /// With a finite outer radius C: the rim's terms (module `rim_holed`); `None` for C = ∞.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rim: Option<RimRecord>,
}

/// R_o and its record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HoledContact {
    /// The separation radius R_o.
    pub r_o: f64,
    /// Error estimate and cost.
    pub info: HoledInfo,
}

/// The rim's part of the record of [`super::holed::two_plate_hole`] with a finite C.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct RimRecord {
    /// The outer radius C.
    pub outer_radius: f64,
    /// R_o of the infinite plate (the same route with C = ∞).
    pub r_o_infinite: f64,
    /// β: curvature of the rim's bending state (1/length, the load's units over G).
    pub curvature: f64,
    /// M_r(C) of the infinite plate's far field (force·length per length).
    pub rim_moment: f64,
    /// N_r(C) of the infinite plate's far field (force per length), cancelled by the membrane
    /// state.
    pub rim_force: f64,
    /// D·e^(−4.21(C − R_o)/D), included in the estimate.
    pub decay_bound: f64,
    /// The finite-C R_o with ⌈3n/4⌉ Nyström points.
    pub r_o_fewer_nodes: f64,
}
