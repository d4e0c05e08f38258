//! The record of the semi-analytic two-plate route with the hole ([`super`]): R_o with
//! its error estimate and cost ([`HoledContact`], [`HoledInfo`]) and, with a finite outer
//! radius, the rim's terms ([`RimRecord`], module `rim`). Lengths in the units of the
//! plate; serialized into `two --method hankel --json` as `hankel`.
//!
//! # Accuracy
//!
//! What the estimate covers and how it was checked: [`super`] and module `rim`.
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

/// What [`two_plate_hole`](super::two_plate_hole) did and how well.
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
    /// Whether that residual met the hole modes' target (`HoleParams::residual_target`; true
    /// with a fixed number of modes): where the modes stopped at their cap short of it, the
    /// variants' estimate is not to be trusted and [`HoledContact::meets`] claims no tolerance.
    /// Narrow loads on small holes, where the modes converge slowly
    /// (`tests/hankel/two_plate_hole_reach_survey.rs`): on (A/D, B/A, ν) = (0.206, 1.022,
    /// 0.263) the tier for 1e-5, its modes then at most 64, left 1.6e-3 P and estimated
    /// 9.7e-6 R_o for an error of 9.4e-6 against a run to 256 modes (itself 9.4e-5 P); the tier
    /// for 1e-8 (128 modes) left 6.6e-4 P on (0.077, 1.053, −0.744) and estimated 2.5e-7 R_o for
    /// an error of 2.7e-7.
    pub hole_resolved: bool,
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
    /// With a finite outer radius C: the rim's terms (module `rim`); `None` for C = ∞.
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

impl HoledContact {
    /// Whether R_o meets the relative tolerance `tol`: its estimate within `tol`·R_o, and the
    /// hole resolved to its modes' target ([`HoledInfo::hole_resolved`]).
    pub fn meets(&self, tol: f64) -> bool {
        self.info.hole_resolved && crate::value::meets(self.r_o, self.info.r_o_error, tol)
    }
}

/// The rim's part of the record of [`super::two_plate_hole`] with a finite C.
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
