//! Convergence estimates shared by every solver, test and example: the error of the last value
//! of a refinement sequence, least-squares rates fitted to a whole sequence, and observed
//! orders between two levels.
//!
//! - [`level_estimate`]: the last value of a sequence and its error max(|d₃|, |d₂|/4, |d₁|/16)
//!   (d₃ the last change, d₂, d₁ the two before): the last change bounds the remaining error
//!   when each level at least halves it; the earlier changes, shrunk at rate 2 per level, guard
//!   against a last change that is small by accident. Used by the single- and two-plate FE
//!   models for R_o.
//! - [`slope`], [`log_log_slope`]: least-squares slope of y on x, and of ln y on ln x (the
//!   observed order of an error against a mesh size, with its sign).
//! - [`fitted_rate`]: the rate of a sequence refined by a constant factor, from its changes.
//! - [`order_between`]: ln(e₁/e₂)/ln(h₁/h₂) from two levels.
//!
//! # Accuracy
//!
//! Exact on exact power laws (unit tests here); rounding only.
//!
//! # Cost
//!
//! O(n).
//!
//! ```
//! use boltzone::numerics::convergence::{fitted_rate, level_estimate, log_log_slope};
//! // e = 3 h² on h = 1, 1/2, 1/4: slope 2
//! let pts: Vec<(f64, f64)> = [1.0, 0.5, 0.25].iter().map(|&h: &f64| (h, 3.0 * h * h)).collect();
//! assert!((log_log_slope(&pts) - 2.0).abs() < 1e-14);
//! // x_k = 1 + 4^(−k): changes fall 4× per halving, rate 2 for factor 2
//! let v: Vec<f64> = (0..5).map(|k| 1.0 + 4f64.powi(-k)).collect();
//! assert!((fitted_rate(&v, 2.0).unwrap() - 2.0).abs() < 1e-12);
//! let (x, e) = level_estimate(&v).unwrap();
//! assert!((x - 1.0).abs() <= e);
//! ```

/// The last value of a refinement sequence and its estimated error max(|d₃|, |d₂|/4, |d₁|/16),
/// d₃ the last change, d₂ and d₁ the two before; with three values only, max(|d₃|, |d₂|/4).
/// None with fewer than three values. The last change bounds the remaining error when each
/// further level at least halves it; the earlier changes shrunk at rate 2 per level guard
/// against a last change (or two) that is small by accident, as when the crossing stalls for
/// two levels before moving on.
pub fn level_estimate(v: &[f64]) -> Option<(f64, f64)> {
    weighted_changes(v, [1.0, 0.25, 0.0625])
}

/// The last value of `v` and max_k wₖ|dₖ| over its last three changes, last first.
fn weighted_changes(v: &[f64], weights: [f64; 3]) -> Option<(f64, f64)> {
    let n = v.len();
    if n < 3 {
        return None;
    }
    let error = v[n.saturating_sub(4)..]
        .windows(2)
        .rev()
        .zip(weights)
        .map(|(w, f)| f * (w[1] - w[0]).abs())
        .fold(0.0, f64::max);
    Some((v[n - 1], error))
}

/// [`level_estimate`] for sequences whose changes may shrink only 2× per level and may turn:
/// max(2|d₃|, |d₂|, |d₁|/2). The two-plate model's R_o error has a first- and a second-order part
/// of opposite sign that cross (`contact::two_plate`, `TRANSIENT_FLOOR`; on 60 random infinite
/// plates without a hole, its error rose to +8e-6 of R_o at level 7 and fell only 1.8× per level
/// after: +4.3e-6, +2.5e-6 at levels 9 and 10), and at such a turn the last change is small by
/// accident; [`level_estimate`] then claimed 1e-5 on 75 level sequences of those 60 plates and
/// missed on 39 (up to 3.1×), this one on 17 and missed on none
/// (`examples/16_error_bars.rs`, route `two0`, holds it on another 200).
///
/// ```
/// use boltzone::numerics::convergence::cautious_level_estimate;
/// let (x, e) = cautious_level_estimate(&[1.0, 1.5, 1.75, 1.875]).unwrap();
/// assert_eq!((x, e), (1.875, 0.25)); // 2 × 0.125; the limit 2 is 0.125 away
/// ```
pub fn cautious_level_estimate(v: &[f64]) -> Option<(f64, f64)> {
    weighted_changes(v, [2.0, 1.0, 0.5])
}

/// Least-squares slope of y on x through `points` (x, y); NaN with fewer than two distinct x.
pub fn slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let mx = points.iter().map(|p| p.0).sum::<f64>() / n;
    let my = points.iter().map(|p| p.1).sum::<f64>() / n;
    let sxy: f64 = points.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    let sxx: f64 = points.iter().map(|p| (p.0 - mx).powi(2)).sum();
    if sxx > 0.0 {
        sxy / sxx
    } else {
        f64::NAN
    }
}

/// Least-squares slope of ln y on ln x through `points` (x, y), both positive: for errors
/// e ≈ C hᵖ against mesh sizes h, the observed order p; against counts n (∝ 1/h), −p.
pub fn log_log_slope(points: &[(f64, f64)]) -> f64 {
    let logs: Vec<(f64, f64)> = points.iter().map(|p| (p.0.ln(), p.1.ln())).collect();
    slope(&logs)
}

/// Convergence rate fitted to a whole sequence on meshes refined by the factor f: the
/// least-squares slope of log |x_{k+1} − x_k| against k log f, negated. None with fewer than
/// two changes or a change that vanishes exactly.
pub fn fitted_rate(values: &[f64], factor: f64) -> Option<f64> {
    let pts: Vec<(f64, f64)> = values
        .windows(2)
        .enumerate()
        .map(|(k, w)| (k as f64 * factor.ln(), (w[1] - w[0]).abs().ln()))
        .collect();
    if pts.len() < 2 || pts.iter().any(|p| !p.1.is_finite()) {
        return None;
    }
    Some(-slope(&pts))
}

/// The observed order between two levels: ln(e₁/e₂)/ln(h₁/h₂) for errors e₁, e₂ on mesh sizes
/// h₁, h₂ (or any measure of the error and of the resolution, h ∝ 1/n).
pub fn order_between(h1: f64, e1: f64, h2: f64, e2: f64) -> f64 {
    (e1 / e2).ln() / (h1 / h2).ln()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn level_estimate_is_the_largest_of_the_last_changes_shrunk_at_rate_two() {
        // a last change small by accident: the change before decides
        let (x, e) = level_estimate(&[1.0, 1.1, 1.1 + 1e-6]).unwrap();
        assert_eq!(x, 1.1 + 1e-6);
        assert!((e - 0.025).abs() < 1e-15);
        // oscillating, last change large: the last change decides
        let (_, e) = level_estimate(&[1.0, 1.1, 1.05]).unwrap();
        assert!((e - 0.05).abs() < 1e-15);
        // a stall of two levels (the map's A/D 0.447, B/A 5 at levels 1–3 behaved so): the
        // change three back decides
        let (_, e) = level_estimate(&[0.0, 1.0, 1.0 + 1e-6, 1.0 + 2e-6]).unwrap();
        assert!((e - 1.0 / 16.0).abs() < 1e-15);
        // only the last three changes count
        let (_, e) = level_estimate(&[-100.0, 0.0, 1.0, 1.0 + 1e-6, 1.0 + 2e-6]).unwrap();
        assert!((e - 1.0 / 16.0).abs() < 1e-15);
        // v_l = 1 + 2^(−l) (rate 1): the error 2^(−l) equals the last change exactly
        let v: Vec<f64> = (0..5).map(|l| 1.0 + 2f64.powi(-l)).collect();
        let (x, e) = level_estimate(&v).unwrap();
        assert!((e - (x - 1.0)).abs() < 1e-15);
        assert!(level_estimate(&[1.0, 2.0]).is_none());
    }

    #[test]
    fn slopes_and_orders_are_exact_on_power_laws() {
        // y = 5 − 3x
        let line: Vec<(f64, f64)> = (0..6).map(|k| (k as f64, 5.0 - 3.0 * k as f64)).collect();
        assert!((slope(&line) + 3.0).abs() < 1e-14);
        assert!(slope(&[(1.0, 2.0)]).is_nan());
        // e = 0.7 n^(−1.5) on n = 4, 8, 16, 32
        let pts: Vec<(f64, f64)> = [4.0f64, 8.0, 16.0, 32.0]
            .iter()
            .map(|&n| (n, 0.7 * n.powf(-1.5)))
            .collect();
        assert!((log_log_slope(&pts) + 1.5).abs() < 1e-13);
        assert!((order_between(0.1, 2e-3, 0.05, 2.5e-4) - 3.0).abs() < 1e-13);
        // x_k = 2 + 3·3^(−2k) refined by 3: rate 2; a repeated value gives none
        let v: Vec<f64> = (0..5).map(|k| 2.0 + 3.0 * 9f64.powi(-k)).collect();
        assert!((fitted_rate(&v, 3.0).unwrap() - 2.0).abs() < 1e-10);
        assert!(fitted_rate(&[1.0, 1.0, 2.0], 2.0).is_none());
        assert!(fitted_rate(&[1.0, 2.0], 2.0).is_none());
    }
}
