//! The two ways a bolt's head and nut press the plates for the member compliance δ_P, and the
//! estimate of δ_P from a sequence of mesh levels, shared by the two-plate model
//! ([`crate::contact::compliance`], where δ_P is defined) and the single plate
//! ([`super::single_compliance`]).
//!
//! **Method.** A face pressure: the last level and max(|d₃|, |d₂|/4, |d₁|/16) of the last three
//! changes ([`level_estimate`]; the changes shrink about 3× per level). A rigid head: the
//! pressure under a flat punch is singular at its edge (∝ ρ^(−1/2)), so the energy error is
//! first order in the element size there and the changes halve per level; the levels are
//! extrapolated at that rate, Rₖ = 2δₖ − δₖ₋₁. The last Rₖ carries the larger of
//! 2·max(|Rₖ − Rₖ₋₁|, |Rₖ₋₁ − Rₖ₋₂|/2) and the extrapolation's own error at the ratios seen:
//! if the changes dⱼ = δⱼ − δⱼ₋₁ fall by a ratio r per level from k on, δ's limit is δₖ +
//! dₖ/(r − 1), so Rₖ = δₖ + dₖ is off by dₖ·|1/(r − 1) − 1|, taken at the worst of the last three
//! observed ratios dⱼ₋₁/dⱼ (infinite if one of them is ≤ 1: no sign of convergence).
//!
//! Why the ratio term: the ratios are not exactly 2 (1.88–2.11 on the finest levels, where the
//! mesh's growth ratios begin to shrink, `fem::spacing::level_grading`), and Rₖ's changes can
//! nearly vanish by accident; measured on 24 random joints (seed 2230 of
//! `tests/joint/compliance.rs`' study) against their runs to 5e-6, the changes-only form
//! claimed too little at 4 of 208 levels (up to 1.56×, at joint 1 1.6e-7 against 2.5e-7), this
//! one at none (worst 0.83 of it).
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
//! // changes falling 3× per level: R₄ = δ₄ + d₄ overshoots the limit 1 by d₄·|1/(3 − 1) − 1|
//! // = 3⁻⁴, and the estimate covers it
//! let v: Vec<f64> = (0..5).map(|k| 1.0 - 3f64.powi(-k)).collect();
//! let (x, e) = estimate(&v, Head::Rigid);
//! assert!((x - 1.0 - 3f64.powi(-4)).abs() < 1e-15 && e >= 3f64.powi(-4));
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
/// punch edge, Rₖ = 2δₖ − δₖ₋₁, the last of them and the larger of
/// 2·max(|Rₖ − Rₖ₋₁|, |Rₖ₋₁ − Rₖ₋₂|/2) and |dₖ|·max|1/(r − 1) − 1| over the last three observed
/// ratios r of the changes. Infinite error with too few levels (five for a rigid head: three
/// ratios).
pub fn estimate(levels: &[f64], head: Head) -> (f64, f64) {
    let n = levels.len();
    let last = levels.last().copied().unwrap_or(f64::NAN);
    match head {
        Head::Pressure => level_estimate(levels).unwrap_or((last, f64::INFINITY)),
        Head::Rigid if n >= 5 => {
            let r: Vec<f64> = levels.windows(2).map(|w| 2.0 * w[1] - w[0]).collect();
            let m = r.len();
            let changes = 2.0
                * (r[m - 1] - r[m - 2])
                    .abs()
                    .max(0.5 * (r[m - 2] - r[m - 3]).abs());
            let d: Vec<f64> = levels.windows(2).map(|w| w[1] - w[0]).collect();
            // the extrapolation's error at the worst of the last three ratios
            let ratio_term = d[d.len() - 4..]
                .windows(2)
                .map(|w| {
                    let ratio = w[0] / w[1];
                    if ratio > 1.0 {
                        (1.0 / (ratio - 1.0) - 1.0).abs()
                    } else {
                        f64::INFINITY
                    }
                })
                .fold(0.0, f64::max)
                * d[d.len() - 1].abs();
            (r[m - 1], changes.max(ratio_term))
        }
        Head::Rigid => (last, f64::INFINITY),
    }
}
