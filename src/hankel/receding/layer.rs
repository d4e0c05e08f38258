//! Hankel kernels of an elastic layer 0 ≤ z ≤ D pressed on both faces: the vertical
//! displacement of its bottom face, for the receding-contact solver [`super::contact`].
//!
//! **Problem.** Top face z = D: σ_z = −p(r), τ_rz = 0; bottom face z = 0: σ_z = −q(r),
//! τ_rz = 0 (p, q > 0 press on the layer; compression negative; w positive upward). With
//! p̄(ξ) = ∫ p J₀(ξr) r dr, q̄ likewise, and x = ξD, the bottom face moves by
//!
//! w(r, 0) = ((1 − ν)/G) ∫₀^∞ [q̄(ξ) M_q(x) − p̄(ξ) M_p(x)] J₀(ξr) dξ,
//!
//! normalised so that M_q → 1 as x → ∞ (the half-space, Boussinesq: w = (1−ν)F/(2πG r) under a
//! point force F).
//!
//! **Derivation.** Split the loads into a part symmetric about the layer's midplane,
//! (p + q)/2 on both faces, and an antisymmetric part ±(p − q)/2. The symmetric part is the
//! slab of [`crate::hankel::kernel`] with half-thickness D/2: its face moves by
//! ((1−ν)/G)∫ s̄ S(x) J₀ dξ with S(x) = (cosh x − 1)/(sinh x + x) (there K_w on the face equals
//! 2(1−ν)·S(2t), t = ξD/2). The antisymmetric part (Love's strain function odd in the
//! midplane coordinate, Timoshenko & Goodier §§ 130–131) bends the layer; its faces move by
//! ((1−ν)/G)∫ ā Λ(x) J₀ dξ with Λ(x) = (cosh x + 1)/(sinh x − x). Adding the two halves at the
//! bottom face:
//!
//! M_q = (Λ + S)/2,  M_p = (Λ − S)/2,  M_q − 1 − M_p = S − 1.
//!
//! Checks: Λ ~ 12/x³ as x → 0, so w̄ → (q̄ − p̄)/(𝒟ξ⁴) with 𝒟 = E D³/(12(1 − ν²)), the
//! Kirchhoff plate; M_p/M_q = 2(sinh x + x cosh x)/(sinh 2x + 2x), the midplane kernel of the
//! slab of half-thickness D ([`crate::hankel::kernel::midplane`]), which is the bilateral limit (two
//! equal plates welded at the interface); and the values of a general four-constant Love
//! solution of the layer (`tests/data/receding_layer_kernels.py`). All three are tests.
//! None of the kernels depends on ν: neither does the receding contact radius.
//!
//! **Overflow-free form.** With e = e^(−x): S − 1 = −2e(1 + x − e)/(1 − e² + 2xe) (taken from
//! the slab's exponentially small face remainder, [`crate::hankel::kernel::face_remainders`]) and
//! Λ − 1 = 2e(1 + x + e)/(2e·(sinh x − x)) with 2e(sinh x − x) = 1 − e² − 2xe for x ≥ 1 and by
//! its power series below (where the difference would cancel). Λ → 1 + 4(1+x)e and
//! M_p → 2(1 + x)e^(−x) as x → ∞; no exponential grows.
//!
//! # Accuracy
//!
//! `tests/hankel/receding_kernels.rs`: the general Love solution, the bilateral limit (the slab's
//! midplane kernel), the Kirchhoff plate, the thick-layer asymptote.
//!
//! # Cost
//!
//! A few exponentials per ξ.
//!
//! ```
//! use boltzone::hankel::receding::layer::{bending, bottom_from_top, symmetric_remainder};
//! // Kirchhoff limit: Λ(x)·x³ → 12
//! assert!((bending(1e-3) * 1e-9 - 12.0).abs() < 1e-4);
//! // exponentially small at large x, never NaN
//! assert!(bottom_from_top(800.0) >= 0.0 && bottom_from_top(800.0) < 1e-300);
//! assert!((symmetric_remainder(1e-9) + 1.0).abs() < 1e-8);
//! ```

use crate::hankel::kernel::face_remainders;

/// Smallest x used by [`bending`] and [`bottom_from_top`] (their 12/x³ and 6/x³ poles would
/// overflow near x ≈ 1e-103; callers multiply them by factors O(x⁴), so clamping is harmless).
const X_MIN: f64 = 1e-60;

/// Largest x used: e^(−x) is exactly 0 in f64 long before, so every kernel already equals its
/// limit there; clamping keeps products like x·e^(−x) away from ∞·0.
const X_MAX: f64 = 1e4;

/// 2e^(−x)(sinh x − x) = 1 − e^(−2x) − 2x e^(−x), for x ≥ 0, without cancellation.
pub(super) fn scaled_sinh_minus_x(x: f64) -> f64 {
    if x >= 1.0 {
        // at x = 1 the difference keeps all but ~1 digit (0.129 out of terms ≤ 1)
        -(-2.0 * x).exp_m1() - 2.0 * x * (-x).exp()
    } else {
        // sinh x − x = Σ_{k≥1} x^(2k+1)/(2k+1)!: at x < 1 the k = 9 term is < 1/19! ≈ 8e-18
        let x2 = x * x;
        let mut term = x * x2 / 6.0;
        let mut sum = term;
        for k in 2..=9 {
            let n = (2 * k) as f64;
            term *= x2 / (n * (n + 1.0));
            sum += term;
        }
        2.0 * (-x).exp() * sum
    }
}

/// Λ(x) = (cosh x + 1)/(sinh x − x): face displacement kernel of the antisymmetric (bending)
/// load, x = ξD > 0 (clamped below at 1e-60). Λ ~ 12/x³ as x → 0, → 1 as x → ∞.
pub fn bending(x: f64) -> f64 {
    1.0 + bending_remainder(x)
}

/// Λ(x) − 1 = 2e(1 + x + e)/(2e(sinh x − x)), e = e^(−x), without the cancellation of Λ − 1
/// at large x (where it is ≈ 4(1 + x)e^(−x)).
pub fn bending_remainder(x: f64) -> f64 {
    let x = x.clamp(X_MIN, X_MAX);
    let e = (-x).exp();
    2.0 * e * (1.0 + x + e) / scaled_sinh_minus_x(x)
}

/// S(x) − 1 with S(x) = (cosh x − 1)/(sinh x + x): the symmetric (slab of half-thickness D/2)
/// face displacement kernel minus its half-space limit; −1 at x = 0, ≈ −2(1 + x)e^(−x) at
/// large x. Taken from [`crate::hankel::kernel::face_remainders`] (K_w = 2(1−ν)S on the slab's face).
pub fn symmetric_remainder(x: f64) -> f64 {
    // K_w remainder = 2(1−ν)(S − 1) for any ν; ν = 0 picks S − 1 · 2
    face_remainders(0.5 * x.min(X_MAX), 0.0).w / 2.0
}

/// M_p(x) = (Λ − S)/2: bottom-face displacement per unit top pressure (in units of the
/// half-space's (1−ν)/G·q̄), x = ξD > 0 (clamped below at 1e-60); ~ 6/x³ at x → 0,
/// ≈ 2(1 + x)e^(−x) at large x.
pub fn bottom_from_top(x: f64) -> f64 {
    let x = x.clamp(X_MIN, X_MAX);
    0.5 * (bending_remainder(x) - symmetric_remainder(x))
}

/// M_q(x) = (Λ + S)/2: bottom-face displacement per unit bottom pressure, in units of the
/// half-space's; → 1 as x → ∞, ~ 6/x³ at x → 0.
pub fn bottom_from_bottom(x: f64) -> f64 {
    let x = x.clamp(X_MIN, X_MAX);
    1.0 + 0.5 * (bending_remainder(x) + symmetric_remainder(x))
}

/// The kernels of two layers in series, Σᵢ λᵢ M(ξDᵢ) with weights λᵢ ≥ 0 summing to 1: the
/// interface of two plates pressed apart by their contact pressure ([`super::pair`]), whose
/// relative displacement is the sum of the two faces' ([`super::pair`] derives it). One layer on
/// a rigid base is the special case λ = (1, 0); equal plates give λ = (½, ½) and, because
/// ½k + ½k = k exactly in floating point, the one layer's kernels bit for bit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stack {
    /// (λᵢ, Dᵢ) of the two layers.
    layers: [(f64, f64); 2],
}

impl Stack {
    /// One layer of thickness `d` (weights (1, 0)).
    pub fn single(d: f64) -> Self {
        Self {
            layers: [(1.0, d), (0.0, d)],
        }
    }

    /// Two layers `d1`, `d2` thick with compliances `c1`, `c2` = (1 − νᵢ)/Gᵢ (> 0): weights
    /// λᵢ = cᵢ/(c₁ + c₂).
    pub fn pair((c1, d1): (f64, f64), (c2, d2): (f64, f64)) -> Self {
        let sum = c1 + c2;
        Self {
            layers: [(c1 / sum, d1), (c2 / sum, d2)],
        }
    }

    /// The thinnest thickness: the length over which the kernels vary (their ξ-decay
    /// e^(−ξD_min) sets the quadrature and the Nyström rule's resolution).
    pub fn thinnest(&self) -> f64 {
        self.layers[0].1.min(self.layers[1].1)
    }

    /// The thickest thickness: the scale of R_o − B (the scan's reach).
    pub fn thickest(&self) -> f64 {
        self.layers[0].1.max(self.layers[1].1)
    }

    fn sum(&self, xi: f64, kernel: fn(f64) -> f64) -> f64 {
        let [(l1, d1), (l2, d2)] = self.layers;
        let second = if l2 == 0.0 { 0.0 } else { l2 * kernel(xi * d2) };
        l1 * kernel(xi * d1) + second
    }

    /// Σ λᵢ (S(ξDᵢ) − 1): the bounded part k₁ of the interface kernel.
    pub fn symmetric_remainder(&self, xi: f64) -> f64 {
        self.sum(xi, symmetric_remainder)
    }

    /// Σ λᵢ M_p(ξDᵢ): the interface's displacement per unit far-face pressure.
    pub fn bottom_from_top(&self, xi: f64) -> f64 {
        self.sum(xi, bottom_from_top)
    }

    /// Σ λᵢ M_q(ξDᵢ): the interface's displacement per unit contact pressure (→ 1 as ξ → ∞).
    pub fn bottom_from_bottom(&self, xi: f64) -> f64 {
        self.sum(xi, bottom_from_bottom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn series_and_direct_forms_agree_at_the_switch() {
        // both branches of 2e(sinh x − x) at x = 1 ± 0: the direct form loses ~1 digit there
        let direct = -(-2.0f64).exp_m1() - 2.0 * (-1.0f64).exp();
        let series = scaled_sinh_minus_x(1.0 - 1e-15);
        assert!(
            (direct - series).abs() < 20.0 * f64::EPSILON,
            "{direct} {series}"
        );
    }

    #[test]
    fn closed_forms_in_the_middle_range() {
        // direct hyperbolic forms are accurate for moderate x: 1e-13 covers their rounding
        for &x in &[0.5f64, 1.0, 2.0, 5.0, 10.0] {
            let s = (x.cosh() - 1.0) / (x.sinh() + x);
            let l = (x.cosh() + 1.0) / (x.sinh() - x);
            assert!((symmetric_remainder(x) - (s - 1.0)).abs() < 1e-13 * l);
            assert!((bending(x) - l).abs() < 1e-13 * l, "{x}");
        }
    }
}
