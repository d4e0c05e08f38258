//! Chebyshev interpolation on the Chebyshev–Lobatto grid x_j = cos(πj/M), j = 0…M, of [−1, 1]:
//! the coefficients of the interpolant p(x) = Σ_{k=0}^{M} c_k T_k(x) by the discrete cosine
//! transform of type I, c_k = (2/M) Σ″_j f(x_j) cos(πjk/M) (first and last terms of the sum
//! halved, and c₀, c_M halved), and p(x) by Clenshaw's recurrence. The grids nest (the grid of
//! M is every other point of the grid of 2M), which is what lets an adaptive interpolant reuse
//! its samples. For f analytic inside the Bernstein ellipse of parameter ρ the coefficients
//! fall like ρ^(−k) (Trefethen, *Approximation Theory and Approximation Practice*, ch. 8), and
//! the interpolation error is at most 2 Σ_{k>M} |c_k| (ch. 4). Used by the hole's slab traction
//! profile (`hankel::hole::profile`) and the separation search's local midplane interpolant.
//!
//! # Accuracy
//!
//! Exact on polynomials of degree ≤ M (the example below); the geometric decay of the coefficients
//! of the slab's traction profile is measured against its predicted ellipse in
//! `tests/hankel/hole_profile.rs`.
//!
//! # Cost
//!
//! O(M²) for the coefficients (a direct cosine sum with one table of cosines; M = 24–72 for the
//! hole profile), O(M) per evaluation.
//!
//! ```
//! use boltzone::numerics::chebyshev::{clenshaw, lobatto_coefficients, lobatto_points};
//! // T₃(x) = 4x³ − 3x is reproduced exactly from its values on the grid of M = 8
//! let v: Vec<f64> = lobatto_points(8).iter().map(|x| 4.0 * x * x * x - 3.0 * x).collect();
//! let c = lobatto_coefficients(&v);
//! assert!((c[3] - 1.0).abs() < 1e-15 && c[1].abs() < 1e-15);
//! assert!((clenshaw(&c, 0.3) - (4.0 * 0.027 - 0.9)).abs() < 1e-15);
//! ```

use std::f64::consts::PI;

/// The grid x_j = cos(πj/m), j = 0…m (from 1 down to −1).
pub fn lobatto_points(m: usize) -> Vec<f64> {
    (0..=m)
        .map(|j| {
            // exact zero in the middle of an even grid
            if 2 * j == m {
                0.0
            } else {
                (PI * j as f64 / m as f64).cos()
            }
        })
        .collect()
}

/// The coefficients c₀…c_M of the interpolant through `values` at [`lobatto_points`]`(M)`,
/// M = values.len() − 1 ≥ 1. O(M²), with one table of M cosines.
pub fn lobatto_coefficients(values: &[f64]) -> Vec<f64> {
    let m = values.len() - 1;
    let cosines: Vec<f64> = (0..2 * m)
        .map(|i| (PI * i as f64 / m as f64).cos())
        .collect();
    (0..=m)
        .map(|k| {
            let s: f64 = values
                .iter()
                .enumerate()
                .map(|(j, v)| {
                    let w = if j == 0 || j == m { 0.5 } else { 1.0 };
                    w * v * cosines[(j * k) % (2 * m)]
                })
                .sum();
            let c = 2.0 * s / m as f64;
            if k == 0 || k == m {
                0.5 * c
            } else {
                c
            }
        })
        .collect()
}

/// The N Chebyshev points of the first kind, s_j = cos(π(j + ½)/N), j = 0…N−1 (from near 1
/// down to near −1; neither end is a point).
pub fn first_kind_points(n: usize) -> Vec<f64> {
    (0..n)
        .map(|j| (PI * (j as f64 + 0.5) / n as f64).cos())
        .collect()
}

/// The coefficients c₀…c_{N−1} of the interpolant through `values` at
/// [`first_kind_points`]`(N)` (the discrete cosine transform of type II, c₀ halved). O(N²).
///
/// ```
/// use boltzone::numerics::chebyshev::{clenshaw, first_kind_coefficients, first_kind_points};
/// let v: Vec<f64> = first_kind_points(6).iter().map(|x| 2.0 * x * x - 1.0).collect();
/// let c = first_kind_coefficients(&v);
/// assert!((c[2] - 1.0).abs() < 1e-15 && c[0].abs() < 1e-15 && c[4].abs() < 1e-15);
/// ```
pub fn first_kind_coefficients(values: &[f64]) -> Vec<f64> {
    let n = values.len();
    (0..n)
        .map(|k| {
            let s: f64 = values
                .iter()
                .enumerate()
                .map(|(j, f)| f * (PI * k as f64 * (j as f64 + 0.5) / n as f64).cos())
                .sum();
            if k == 0 {
                s / n as f64
            } else {
                2.0 * s / n as f64
            }
        })
        .collect()
}

/// Σ c_k T_k(x) by Clenshaw's recurrence (x in [−1, 1]).
pub fn clenshaw(c: &[f64], x: f64) -> f64 {
    let (mut b1, mut b2) = (0.0, 0.0);
    for &ck in c.iter().skip(1).rev() {
        let b0 = 2.0 * x * b1 - b2 + ck;
        b2 = b1;
        b1 = b0;
    }
    x * b1 - b2 + c.first().copied().unwrap_or(0.0)
}
