//! A prescribed displacement of the contact disk as a right-hand side of the layer's Fredholm
//! equation (module `system`): the rim's bending correction S₂ of [`super::rim`] and
//! [`super::holed::rim`] presses the plate onto the plane so that its bottom moves up by
//! w(r) = r²/2 + k ln r (+ a rigid translation) on the contact zone.
//!
//! **Abel form.** With q̄(ξ) = ∫₀^c φ(t) cos ξt dt the half-space part of (G/(1−ν))w is
//! A[φ](r) = ∫₀^r φ(t)/√(r² − t²) dt; A maps (4/π)t² to r² and (2/π) ln 2t to ln r
//! (∫₀^{π/2} ln sin θ dθ = −(π/2) ln 2), so the displacement enters as a known part
//!
//! F(t) = γ(t² + k ln 2t),  γ = 2G/(π(1 − ν)),
//!
//! of φ = F + ψ: ψ solves the same equation with α_m = −a_m∫₀^c F cos ξ_m t dt,
//! β_m = −b_m∫₀^c F (cos ξ_m t − 1) dt and ∫ψ = total − ∫F (ψ is as smooth as for a load: F's
//! log singularity at t = 0, inside the hole, never meets the Nyström rule). The transforms:
//! ∫₀^c t² cos ξt dt and ∫₀^c ln(2t) cos ξt dt = (ln(2c) sin ξc − Si(ξc))/ξ in closed form,
//! Si accumulated along the sorted nodes by Gauss–Legendre panels, and series in ξc below 1
//! for the cos − 1 parts (no cancellation). F's pressure (the formula of [`super::contact`]):
//! q_F(r) = γ[c²/√(c² − r²) − 2√(c² − r²) + k(ln(2c)/√(c² − r²) − arccos(r/c)/r)].
//!
//! # Accuracy
//!
//! Through the routes that use it: `tests/hankel/two_plate_rim_hankel.rs` and
//! `tests/hankel/two_plate_rim_holed.rs` (equilibrium of the pressure from q_F's closed form,
//! the FE meshed to C).
//!
//! # Cost
//!
//! O(nodes) per contact radius (the rim tests time the routes).
//!
//! ```
//! // Internal; reached through the rim route:
//! use boltzone::hankel::receding::rim::rim_contact;
//! let _ = rim_contact;
//! ```

use crate::numerics::quadrature::gauss_legendre;
use std::f64::consts::PI;

/// The Abel function F(t) = γ(t² + k ln 2t) of the prescribed lift r²/2 + k ln r.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Prescribed {
    gamma: f64,
    k: f64,
}

/// ∫₀^c t² cos ξt dt and ∫₀^c t²(cos ξt − 1) dt.
fn t2_transforms(xi: f64, c: f64) -> (f64, f64) {
    let x = xi * c;
    let c3 = c * c * c;
    if x < 1.0 {
        // Σ_{n≥1} (−1)ⁿ x²ⁿ/((2n)!(2n + 3)) c³: 12 terms reach 1e-30
        let (mut term, mut sum) = (1.0, 0.0);
        for n in 1..=12 {
            let k = 2.0 * n as f64;
            term *= -x * x / (k * (k - 1.0));
            sum += term / (k + 3.0);
        }
        (c3 * sum + c3 / 3.0, c3 * sum)
    } else {
        let (s, co) = x.sin_cos();
        let full = c3 * (s / x + 2.0 * co / (x * x) - 2.0 * s / (x * x * x));
        (full, full - c3 / 3.0)
    }
}

impl Prescribed {
    /// The lift r²/2 + k ln r of a material with shear modulus `g` and Poisson's ratio `nu`.
    pub(crate) fn new(g: f64, nu: f64, k: f64) -> Self {
        Self {
            gamma: 2.0 * g / (PI * (1.0 - nu)),
            k,
        }
    }

    /// F(t).
    pub(crate) fn value(&self, t: f64) -> f64 {
        self.gamma * (t * t + self.k * (2.0 * t).ln())
    }

    /// ∫₀^c F dt.
    pub(crate) fn integral(&self, c: f64) -> f64 {
        self.gamma * (c * c * c / 3.0 + self.k * c * ((2.0 * c).ln() - 1.0))
    }

    /// ∫₀^c F t² dt (half of ∫q r³ dr over the disk for φ = F).
    pub(crate) fn moment_t2(&self, c: f64) -> f64 {
        let c5 = c.powi(5);
        self.gamma * (c5 / 5.0 + self.k * c5 * ((2.0 * c).ln() / 5.0 - 1.0 / 25.0))
    }

    /// (∫₀^c F cos ξt dt, ∫₀^c F (cos ξt − 1) dt) at each ξ of `xi` (ascending, ≥ 0).
    pub(crate) fn transforms(&self, xi: &[f64], c: f64) -> Vec<(f64, f64)> {
        let gl = gauss_legendre(20);
        let ln2c = (2.0 * c).ln();
        let zeroth = c * (ln2c - 1.0);
        let (mut si, mut x_prev) = (0.0, 0.0);
        xi.iter()
            .map(|&x| {
                // Si(ξc) accumulated over panels no wider than π (sin t/t is entire)
                let x_now = x * c;
                let k = ((x_now - x_prev) / PI).ceil().max(1.0) as usize;
                let h = (x_now - x_prev) / k as f64;
                for j in 0..k {
                    let mid = x_prev + (j as f64 + 0.5) * h;
                    si += gl
                        .iter()
                        .map(|&(u, w)| {
                            let t = mid + 0.5 * h * u;
                            0.5 * h * w * if t == 0.0 { 1.0 } else { t.sin() / t }
                        })
                        .sum::<f64>();
                }
                x_prev = x_now;
                let (p_full, p_m1) = t2_transforms(x, c);
                let (l_full, l_m1) = if x_now < 1.0 {
                    // Σ_{n≥1} (−1)ⁿ ξ²ⁿ/(2n)! c^{2n+1} [ln 2c/(2n+1) − 1/(2n+1)²]
                    let (mut term, mut sum) = (c, 0.0);
                    for n in 1..=12 {
                        let m = 2.0 * n as f64;
                        term *= -x_now * x_now / (m * (m - 1.0));
                        sum += term * (ln2c / (m + 1.0) - 1.0 / ((m + 1.0) * (m + 1.0)));
                    }
                    (sum + zeroth, sum)
                } else {
                    let full = (ln2c * x_now.sin() - si) / x;
                    (full, full - zeroth)
                };
                (
                    self.gamma * (p_full + self.k * l_full),
                    self.gamma * (p_m1 + self.k * l_m1),
                )
            })
            .collect()
    }

    /// q_F(r) for contact radius c (0 ≤ r < c; zero beyond).
    pub(crate) fn pressure(&self, r: f64, c: f64) -> f64 {
        if r >= c {
            return 0.0;
        }
        let len = ((c - r) * (c + r)).sqrt();
        let log = if self.k == 0.0 {
            0.0
        } else {
            (2.0 * c).ln() / len - (r / c).acos() / r
        };
        self.gamma * (c * c / len - 2.0 * len + self.k * log)
    }
}
