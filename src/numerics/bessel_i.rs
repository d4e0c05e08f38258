//! Modified Bessel functions I₀ and I₁ of complex argument, exponentially scaled:
//! `i01_scaled(z)` = (e^(−z) I₀(z), e^(−z) I₁(z)) for Re z > 0.
//!
//! The radial factors of the Papkovich–Fadle modes that grow outward (`hankel::hole::eigen`, used to
//! free a finite rim r = C) are I₀(λr), I₁(λr) with |arg λ| < 0.5; the scaling removes e^z.
//!
//! - |z| < 20: the power series I_ν(z) = (z/2)^ν Σ_k (z²/4)^k/(k!(k+ν)!) (DLMF 10.25.2). Its terms
//!   have the size of I_ν(|z|), so the relative rounding error grows like ε·e^(|z|(1 − cos arg z)):
//!   below 2e-14 for |arg z| ≤ 0.7 (e^(4.7) at |z| = 20), the domain this module is for.
//! - |z| ≥ 20: the Hankel expansion e^(−z) I_ν(z) ≈ Σ_k (−1)^k a_k(ν)/z^k / √(2πz) (DLMF 10.40.1);
//!   the omitted exponentially small part is ≈ e^(−2 Re z) < 5e-14 for |arg z| ≤ 0.7.
//!
//! # Accuracy
//!
//! Measured against mpmath at 40 digits (`tests/data/hole_bessel_i.py`,
//! `tests/numerics/bessel_ik.rs`).
//!
//! # Cost
//!
//! O(1): ≲ 60 series terms or ≲ 20 asymptotic terms.
//!
//! ```
//! use boltzone::numerics::bessel_i::i01_scaled;
//! use num_complex::Complex64;
//! let (i0, i1) = i01_scaled(Complex64::new(1.0, 0.0));
//! // e^(−1) I₀(1), e^(−1) I₁(1) (Abramowitz & Stegun Table 9.8)
//! assert!((i0.re - 0.465_759_607_593_640_3).abs() < 1e-15);
//! assert!((i1.re - 0.207_910_415_349_708_4).abs() < 1e-15);
//! ```

use super::bessel_k::{asymptotic_series, ASYMPTOTIC_FROM};
use num_complex::Complex64;
use std::f64::consts::PI;

/// (e^(−z) I₀(z), e^(−z) I₁(z)) for Re z > 0; NaN components for Re z ≤ 0 or non-finite z.
pub fn i01_scaled(z: Complex64) -> (Complex64, Complex64) {
    if z.re.is_nan() || z.re <= 0.0 || !z.im.is_finite() || !z.re.is_finite() {
        let nan = Complex64::new(f64::NAN, f64::NAN);
        return (nan, nan);
    }
    if z.norm() >= ASYMPTOTIC_FROM {
        let pref = (Complex64::new(2.0 * PI, 0.0) * z).sqrt().inv();
        return (
            pref * asymptotic_series(z, 0.0, true),
            pref * asymptotic_series(z, 1.0, true),
        );
    }
    let q = z * z / 4.0;
    let (mut t0, mut t1) = (Complex64::new(1.0, 0.0), z / 2.0);
    let (mut s0, mut s1) = (t0, t1);
    for k in 1..200 {
        let kf = k as f64;
        t0 = t0 * q / (kf * kf);
        t1 = t1 * q / (kf * (kf + 1.0));
        s0 += t0;
        s1 += t1;
        if t0.norm() < 1e-18 * s0.norm() && t1.norm() < 1e-18 * s1.norm() {
            break;
        }
    }
    let e = (-z).exp();
    (s0 * e, s1 * e)
}
