//! The two ways a bolt's head and nut press the plates for the member compliance δ_P, and the
//! estimate of δ_P from a sequence of mesh levels, shared by the two-plate model
//! ([`crate::contact::compliance`], where δ_P is defined) and the single plate
//! ([`super::single_compliance`]).
//!
//! **Method.** A face pressure: the last level and max(|d₃|, |d₂|/4, |d₁|/16) of the last three
//! changes ([`level_estimate`]; the changes shrink about 3× per level). A rigid head: the
//! pressure under a flat punch is singular at its edge (∝ ρ^(−1/2)), so the energy error is
//! first order in the element size there and the changes halve per level; the levels are
//! extrapolated at that rate, Rₖ = 2δₖ − δₖ₋₁, and the last Rₖ carries
//! 2·max(|Rₖ − Rₖ₋₁|, |Rₖ₋₁ − Rₖ₋₂|/2).
//!
//! # Accuracy
//!
//! Against runs of a 100× tighter tolerance over random joints: `tests/joint/compliance.rs`.
//!
//! # Cost
//!
//! O(levels).
//!
//! ```
//! use boltzone::fem::compliance_estimate::{estimate, Head};
//! // changes halving exactly: the rate-1 extrapolation is exact
//! let v: Vec<f64> = (0..5).map(|k| 1.0 - 0.5f64.powi(k)).collect();
//! let (x, e) = estimate(&v, Head::Rigid);
//! assert!((x - 1.0).abs() < 1e-15 && e < 1e-15);
//! ```

use crate::numerics::convergence::level_estimate;
use serde::Serialize;

/// How the head and the nut press the plates.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Head {
    /// The joint's face pressure p(r) on both bearing faces (work-conjugate approach).
    Pressure,
    /// Rigid, frictionless head and nut over A ≤ r ≤ B (their rigid approach).
    Rigid,
}

/// The estimate of δ_P from its levels (module docs): for a pressure the last level and
/// max(|d₃|, |d₂|/4, |d₁|/16); for a rigid head the levels extrapolated at the rate 1 of the
/// punch edge, Rₖ = 2δₖ − δₖ₋₁, the last of them and 2·max(|Rₖ − Rₖ₋₁|, |Rₖ₋₁ − Rₖ₋₂|/2).
/// Infinite error with too few levels.
pub fn estimate(levels: &[f64], head: Head) -> (f64, f64) {
    let n = levels.len();
    let last = levels.last().copied().unwrap_or(f64::NAN);
    match head {
        Head::Pressure => level_estimate(levels).unwrap_or((last, f64::INFINITY)),
        Head::Rigid if n >= 4 => {
            let r: Vec<f64> = levels.windows(2).map(|w| 2.0 * w[1] - w[0]).collect();
            let m = r.len();
            let e = 2.0
                * (r[m - 1] - r[m - 2])
                    .abs()
                    .max(0.5 * (r[m - 2] - r[m - 3]).abs());
            (r[m - 1], e)
        }
        Head::Rigid => (last, f64::INFINITY),
    }
}
