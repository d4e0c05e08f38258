//! The member compliance δ_P of the single-plate substitute without a hole, by Hankel
//! transforms: the slab −D ≤ z ≤ D of infinite extent, both faces pressed by a uniform pressure
//! p over A ≤ r ≤ B (A = 0: a disk), δ_P = ∫ p (w_head − w_nut) dA / F² (definition in
//! [`crate::contact::compliance`]). A second method, sharing no code with the finite elements,
//! for the single plate of [`crate::fem::single_compliance`] and for the exact limits.
//!
//! **Method.** A face pressure cos-like in the transform variable ξ loads the slab
//! symmetrically; with the Airy (plane strain) or Love (axisymmetric, the same ODE in z)
//! function f(z) = α cosh ξz + β ξz sinh ξz, shear-free faces and σ_z(±D) = −p̄ give the face
//! displacement toward the midplane
//!
//! w̄(ξ) = (2(1 − ν²)/E) p̄(ξ)/ξ · L(ξD),  L(t) = (cosh 2t − 1)/(sinh 2t + 2t),
//!
//! (L → 1: the half-space; L ≈ t/2: the laterally held sleeve). Parseval's identity for the
//! Hankel transform, ∫ f g r dr = ∫ f̄ ḡ ξ dξ, turns the work of both faces into
//!
//! δ_P = 8π(1 − ν²)/E · ∫₀^∞ p̄(ξ)² L(ξD) dξ / F²,  p̄ = p (B J₁(ξB) − A J₁(ξA))/ξ.
//!
//! The half-space part ∫ p̄² dξ is closed (Weber–Schafheitlin, Gradshteyn & Ryzhik 6.574.2):
//! ∫ (B J₁(ξB) − A J₁(ξA))²/ξ² dξ = (4/3π)[A³ + B³ − B³((1 + k²)E(k) − (1 − k²)K(k))], k = A/B,
//! with the complete elliptic integrals K, E by the arithmetic–geometric mean; the rest,
//! ∫ p̄² (L − 1) dξ, decays like e^(−2ξD) and is summed by Gauss–Legendre panels (20 points,
//! panels no wider than a quarter period of J₁(ξB)² and than 1/(2D)) to ξD = 22
//! (|L − 1| < 1e-17 beyond). Its error estimate is the difference from the 10-point rule on
//! the same panels.
//!
//! Units: any consistent set; δ_P in length per force.
//!
//! # Accuracy
//!
//! `tests/joint/compliance.rs`: the thick limit 3π²/32 and the sleeve limit with their rates,
//! the elliptic closed form against the integral itself, the finite-element single plate at
//! A = 0 within both estimates.
//!
//! # Cost
//!
//! A few thousand Bessel evaluations (ξD up to 22 in panels of a quarter period): tens of
//! microseconds to a few milliseconds for B/D up to 100.
//!
//! ```
//! use boltzone::hankel::slab_compliance::slab_compliance;
//! use boltzone::{FaceLoad, Material};
//! let m = Material::new(1.0, 0.3)?;
//! // a thick slab: close to two half-spaces, k_P (1 − ν²)/(E B) = 3π²/32
//! let d = slab_compliance(1e3, m, &FaceLoad::uniform(0.0, 1.0, 1.0)?)?;
//! let k = (1.0 - 0.09) / d.value;
//! assert!((k / (3.0 * std::f64::consts::PI.powi(2) / 32.0) - 1.0).abs() < 2e-3);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::{positive, InputError};
use crate::load::{FaceLoad, Profile};
use crate::material::Material;
use crate::numerics::quadrature::{gauss_legendre, panel};
use crate::value::Value;
use std::f64::consts::PI;

/// Largest ξD summed: |L − 1| ≈ 2(1 + 2t)e^(−2t) < 1e-17 beyond t = 22.
const T_MAX: f64 = 22.0;

/// δ_P of the slab 2`d` thick (half-thickness `d`) of `material` under the uniform `load` on
/// both faces (module docs), with its quadrature error; converged when that error is below
/// 1e-12 of the value.
pub fn slab_compliance(d: f64, material: Material, load: &FaceLoad) -> Result<Value, InputError> {
    positive("plate thickness D", d)?;
    if load.profile() != Profile::Uniform {
        return Err(InputError::Parameter {
            field: "face load profile",
            value: load.mean_pressure(),
            reason: "the slab's member compliance is implemented for a uniform pressure only",
        });
    }
    let (a, b) = (load.inner(), load.outer());
    let g = |xi: f64| {
        let v = (b * libm::j1(xi * b) - a * libm::j1(xi * a)) / xi;
        if xi > 0.0 {
            v * v
        } else {
            0.25 * (b * b - a * a).powi(2)
        }
    };
    let half_space = half_space_integral(a, b);
    let width = (0.5 * PI / (2.0 * b)).min(0.5 / d);
    let x_max = T_MAX / d;
    let n = (x_max / width).ceil().max(1.0) as usize;
    let h = x_max / n as f64;
    let (g20, g10) = (gauss_legendre(20), gauss_legendre(10));
    let mut f = |xi: f64| g(xi) * l_minus_one(xi * d);
    let (mut s20, mut s10) = (0.0, 0.0);
    for k in 0..n {
        let (x0, x1) = (k as f64 * h, (k + 1) as f64 * h);
        s20 += panel(&g20, x0, x1, &mut f).0;
        s10 += panel(&g10, x0, x1, &mut f).0;
    }
    let force = PI * (b * b - a * a);
    let scale = 8.0 * PI * (1.0 - material.poisson_ratio().powi(2))
        / material.youngs_modulus()
        / (force * force);
    let value = scale * (half_space + s20);
    // round-off of the sum and of the closed form, plus the rule difference
    let error = scale * ((s20 - s10).abs() + 1e-15 * (half_space.abs() + s20.abs()));
    Ok(Value::with_tolerance(value, error, 1e-12))
}

/// L(t) − 1 = −2e^(−2t)(1 + 2t − e^(−2t)) / (1 − e^(−4t) + 4t e^(−2t)), overflow-free.
pub fn l_minus_one(t: f64) -> f64 {
    if t < 1e-8 {
        // L(t) = t/2 + O(t³)
        return 0.5 * t - 1.0;
    }
    let e2 = (-2.0 * t).exp();
    -2.0 * e2 * (2.0 * t - (-2.0 * t).exp_m1()) / (4.0 * t * e2 - (-4.0 * t).exp_m1())
}

/// ∫₀^∞ (B J₁(ξB) − A J₁(ξA))²/ξ² dξ in closed form (module docs), 0 ≤ A < B.
pub fn half_space_integral(a: f64, b: f64) -> f64 {
    let k = a / b;
    let (kk, ee) = elliptic_ke(k);
    4.0 / (3.0 * PI)
        * (a.powi(3) + b.powi(3) - b.powi(3) * ((1.0 + k * k) * ee - (1.0 - k * k) * kk))
}

/// The complete elliptic integrals K(k), E(k) of modulus 0 ≤ k < 1 by the arithmetic–geometric
/// mean (Abramowitz & Stegun 17.6): K = π/(2 a_N), E = K (1 − Σ 2^(n−1) c_n²).
pub fn elliptic_ke(k: f64) -> (f64, f64) {
    let (mut a, mut g) = (1.0, (1.0 - k * k).sqrt());
    let mut sum = 0.5 * k * k;
    let mut pow = 0.5;
    for _ in 0..40 {
        let c = 0.5 * (a - g);
        pow *= 2.0;
        sum += pow * c * c;
        let an = 0.5 * (a + g);
        g = (a * g).sqrt();
        a = an;
        if c.abs() <= 1e-17 * a {
            break;
        }
    }
    let kk = PI / (2.0 * a);
    (kk, kk * (1.0 - sum))
}
