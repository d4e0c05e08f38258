//! One value-with-error type for every result that carries an estimate: the value, its
//! estimated absolute error and whether that error met the tolerance asked for.
//!
//! Every route that computes a separation radius R_o (the slab, the single plate by finite
//! elements or by Hankel transforms, the two-plate model, the receding contact) reports it with
//! the same three fields, `r_o`, `r_o_error` and `converged`; where a result holds several
//! values (the comparison of models, the tables) each is a [`Value`]. `tolerance` means the same
//! everywhere: the wanted error relative to the value, `converged` ⇔ error ≤ tolerance·|value|
//! (and the error finite).
//!
//! Quantities derived from estimated values (differences in per cent, areas) carry the
//! first-order propagation of the estimates and are converged when their inputs are.
//!
//! # Accuracy
//!
//! The propagation is first order in the errors (the sum of |∂f/∂x|·e_x); the doc example
//! checks the `converged` rule. That an estimate bounds the actual error is each solver's
//! claim, measured in its tests (e.g. `tests/contact/two_plate.rs`,
//! `error_estimate_measures_the_actual_error`).
//!
//! # Cost
//!
//! None.
//!
//! ```
//! use boltzone::Value;
//! let r = Value::with_tolerance(0.4, 1e-5, 1e-4); // error 1e-5 ≤ 1e-4 · 0.4
//! assert!(r.converged);
//! let s = Value::with_tolerance(0.5, 1e-3, 1e-4);
//! assert!(!s.converged && !r.percent_difference(s).converged);
//! ```

use serde::Serialize;

/// A value with its estimated absolute error and whether that error met the tolerance.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Value {
    /// The value.
    pub value: f64,
    /// Its estimated absolute error (≥ 0, finite).
    pub error: f64,
    /// Whether `error` met the tolerance the value was computed to.
    pub converged: bool,
}

impl Value {
    /// An exact value (error 0, converged).
    pub fn exact(value: f64) -> Self {
        Self {
            value,
            error: 0.0,
            converged: true,
        }
    }

    /// `value ± error`, converged when `error ≤ tolerance·|value|` (relative tolerance).
    pub fn with_tolerance(value: f64, error: f64, tolerance: f64) -> Self {
        Self {
            value,
            error,
            converged: meets(value, error, tolerance),
        }
    }

    /// This value scaled by `factor` (error by |factor|).
    pub fn scaled(self, factor: f64) -> Self {
        Self {
            value: factor * self.value,
            error: factor.abs() * self.error,
            converged: self.converged,
        }
    }

    /// (self − other)/other·100 with first-order error propagation.
    pub fn percent_difference(self, other: Value) -> Value {
        let (x, y) = (self, other);
        Value {
            value: (x.value - y.value) / y.value * 100.0,
            error: 100.0
                * (x.error / y.value.abs() + x.value.abs() * y.error / (y.value * y.value)),
            converged: x.converged && y.converged,
        }
    }
}

/// Whether `error` meets the relative `tolerance` on `value` (a non-finite error never does).
pub fn meets(value: f64, error: f64, tolerance: f64) -> bool {
    error.is_finite() && error <= tolerance * value.abs()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn convergence_is_the_relative_tolerance() {
        assert!(meets(2.0, 2e-4, 1e-4));
        assert!(!meets(2.0, 2.1e-4, 1e-4));
        assert!(!meets(2.0, f64::INFINITY, 1e-4));
        assert!(!meets(2.0, f64::NAN, 1e-4));
        // propagation: d(x/y) at x = 1.1, y = 1 is 100·(e_x + 1.1·e_y)
        let d = Value::with_tolerance(1.1, 1e-3, 1.0).percent_difference(Value::exact(1.0));
        assert!((d.value - 10.0).abs() < 1e-12 && (d.error - 0.1).abs() < 1e-12);
        assert!(d.converged);
    }
}
