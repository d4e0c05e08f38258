//! Modified Bessel functions K₀ and K₁ of complex argument, exponentially scaled:
//! `k01_scaled(z)` = (e^z K₀(z), e^z K₁(z)) for Re z > 0.
//!
//! The radial factors of the Papkovich–Fadle eigenfunctions (`hankel::hole::eigen`) are K₀(λr), K₁(λr)
//! with complex λ (|arg λ| < 0.5); the scaling removes the e^(−z) that would underflow for large
//! |z|, so ratios K_ν(λr)/K₁(λA) are formed as scaled ratios times e^(−λ(r−A)).
//!
//! Two methods (DLMF §10.32.9 and §10.40.2):
//! - |z| < 20: the integral e^z K_ν(z) = ∫₀^∞ exp(−2z sinh²(t/2)) cosh(νt) dt by the trapezoid rule.
//!   The integrand is analytic in the strip |Im t| < π/2 − |arg z|, so the rule converges like
//!   e^(−2πd/h) for a strip half-width d (Trefethen & Weideman, SIAM Rev. 56 (2014) 385–458); we take
//!   d = min(0.5, (π/2 − |arg z|)/2) and h = 2πd/42, which makes the discretisation error
//!   ≲ e^(−42)·e^(|z|(1−cos d)) < 1e-17 for |z| < 20, and stop once the integrand is below e^(−42)
//!   of its peak.
//! - |z| ≥ 20: the Hankel asymptotic series e^z K_ν(z) ≈ √(π/2z) Σ_k a_k(ν)/z^k,
//!   a_k = a_{k−1}(4ν² − (2k−1)²)/(8k), summed to its smallest term; for |arg z| ≤ π/2 the error is
//!   below the first omitted term, ≈ e^(−2|z|) < 5e-18.
//!
//! # Accuracy
//!
//! Measured against mpmath at 40 digits (`tests/data/hole_bessel_k.py`,
//! `tests/numerics/bessel_ik.rs`) for |z| ∈ [0.05, 1e5], |arg z| ≤ 1.1.
//!
//! # Cost
//!
//! O(1): at most ~100 trapezoid nodes below |z| = 20, ≲ 20 series terms above; one pair per mode
//! and point of the hole fit (`cargo bench --bench hole`).
//!
//! ```
//! use boltzone::numerics::bessel_k::k01_scaled;
//! use num_complex::Complex64;
//! let (k0, k1) = k01_scaled(Complex64::new(1.0, 0.0));
//! // e·K₀(1) and e·K₁(1) (Abramowitz & Stegun Table 9.8)
//! assert!((k0.re - 1.144_463_079_806_895).abs() < 1e-14);
//! assert!((k1.re - 1.636_153_486_263_258).abs() < 1e-14);
//! ```

use num_complex::Complex64;
use std::f64::consts::{FRAC_PI_2, PI};

/// |z| at and beyond which the asymptotic series is used.
pub(super) const ASYMPTOTIC_FROM: f64 = 20.0;
/// Exponent of the trapezoid rule's target error, e^(−42) ≈ 6e-19.
const TRAPEZOID_DIGITS: f64 = 42.0;

/// (e^z K₀(z), e^z K₁(z)) for Re z > 0 (principal branch). Returns NaN components for
/// Re z ≤ 0 or a non-finite z, which the eigenfunctions never produce.
pub fn k01_scaled(z: Complex64) -> (Complex64, Complex64) {
    if z.re.is_nan() || z.re <= 0.0 || !z.im.is_finite() || !z.re.is_finite() {
        let nan = Complex64::new(f64::NAN, f64::NAN);
        return (nan, nan);
    }
    if z.norm() >= ASYMPTOTIC_FROM {
        asymptotic(z)
    } else {
        trapezoid(z)
    }
}

fn asymptotic(z: Complex64) -> (Complex64, Complex64) {
    let pref = (Complex64::new(FRAC_PI_2, 0.0) / z).sqrt();
    (
        pref * asymptotic_series(z, 0.0, false),
        pref * asymptotic_series(z, 1.0, false),
    )
}

/// Σ_k (±1)^k a_k(ν)/z^k of the Hankel expansions (DLMF 10.40.1–2), a_k = a_{k−1}(4ν² −
/// (2k−1)²)/(8k), summed to its smallest term or to 1e-18 of the sum; `alternating` gives
/// the signs (−1)^k of I_ν's expansion.
pub(super) fn asymptotic_series(z: Complex64, nu: f64, alternating: bool) -> Complex64 {
    let mu = 4.0 * nu * nu;
    let inv = if alternating { -z.inv() } else { z.inv() };
    let mut term = Complex64::new(1.0, 0.0);
    let mut sum = term;
    let mut last = f64::INFINITY;
    for k in 1..200 {
        let kf = k as f64;
        let next = term * inv * ((mu - (2.0 * kf - 1.0).powi(2)) / (8.0 * kf));
        let size = next.norm();
        if size >= last || size < 1e-18 * sum.norm() {
            if size < last {
                sum += next;
            }
            break;
        }
        last = size;
        term = next;
        sum += term;
    }
    sum
}

fn trapezoid(z: Complex64) -> (Complex64, Complex64) {
    let arg = z.im.atan2(z.re).abs();
    let d = (0.5f64).min((FRAC_PI_2 - arg) / 2.0);
    let h = 2.0 * PI * d / TRAPEZOID_DIGITS;
    // exp(−2z sinh²(t/2)) and cosh t: summed until Re z·2 sinh²(t/2) − t exceeds the target.
    let mut k0 = Complex64::new(0.5, 0.0);
    let mut k1 = Complex64::new(0.5, 0.0);
    let mut j = 1u32;
    loop {
        let t = h * f64::from(j);
        let s = (t / 2.0).sinh();
        let c = 2.0 * s * s;
        let e = (-z * c).exp();
        k0 += e;
        k1 += e * t.cosh();
        if z.re * c - t > TRAPEZOID_DIGITS || j > 100_000 {
            break;
        }
        j += 1;
    }
    (k0 * h, k1 * h)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn methods_agree_at_the_switch() {
        // Both methods are accurate at |z| = 20: their difference bounds both errors.
        for arg in [0.0, 0.3, 0.6, 1.0] {
            let z = Complex64::from_polar(ASYMPTOTIC_FROM, arg);
            let (a0, a1) = asymptotic(z);
            let (t0, t1) = trapezoid(z);
            assert!((a0 - t0).norm() < 1e-14 * a0.norm(), "{arg}");
            assert!((a1 - t1).norm() < 1e-14 * a1.norm(), "{arg}");
        }
    }

    #[test]
    fn bad_argument_gives_nan_not_panic() {
        assert!(k01_scaled(Complex64::new(-1.0, 0.0)).0.re.is_nan());
        assert!(k01_scaled(Complex64::new(f64::NAN, 0.0)).1.re.is_nan());
    }
}
