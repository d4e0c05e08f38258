//! Stresses inside an elastic layer 0 ≤ z ≤ D pressed on its bottom face, top face free: the
//! Hankel kernels the two-plate model with a hole ([`super::holed`]) integrates on the hole.
//!
//! **Problem.** Bottom face z = 0: σ_z = −b(r), τ_rz = 0; top face z = D free (b > 0 presses
//! on the layer; compression negative). With b̄(ξ) = ∫ b J₀(ξr) r dr, every stress is a
//! ξ-integral of b̄ times a kernel of (ξ, z):
//!
//! σ_r = ∫ [R₀ J₀(ξr) − R₁ J₁(ξr)/(ξr)] dξ,  τ_rz = ∫ T J₁(ξr) dξ,  σ_z = ∫ Z J₀(ξr) dξ.
//!
//! A top-face pressure gives the same kernels mirrored (z → D − z, τ_rz changing sign).
//!
//! **Derivation** (Love's strain function Φ = ∫ f(ξ, z) J₀(ξr) dξ, Timoshenko & Goodier
//! §§ 130–131: σ_z = ∂_z[(2−ν)∇²Φ − ∂²_zΦ], τ_rz = ∂_r[(1−ν)∇²Φ − ∂²_zΦ],
//! σ_r = ∂_z[ν∇²Φ − ∂²_rΦ]). Split the load about the midplane ζ = z − h, h = D/2, t = ξh:
//! the symmetric half b/2 on both faces (f odd in ζ, f = A sinh ξζ + Bξζ cosh ξζ) and the
//! antisymmetric half (f even, f = A cosh ξζ + Bξζ sinh ξζ). τ_rz = 0 on ζ = h fixes A/B, σ_z
//! on ζ = h the scale; with s = sinh, c = cosh of ξζ and S, C of t, per unit ξb̄:
//!
//! | | symmetric (÷ −(sinh 2t + 2t)) | antisymmetric (÷ (sinh 2t − 2t)) |
//! |---|---|---|
//! | R₀ | (S − tC)c + ξζ S s | (C − tS)s + ξζ C c |
//! | R₁ | ((1−2ν)S − tC)c + ξζ S s | ((1−2ν)C − tS)s + ξζ C c |
//! | T | ξζ S c − tC s | ξζ C s − tS c |
//! | Z | (S + tC)c − ξζ S s | (C + tS)s − ξζ C c |
//!
//! (at ζ = ±h the symmetric Z is −ξb̄/2, the antisymmetric ±ξb̄/2: the faces carry −b and 0).
//! For t > 20 the hyperbolic ratios are replaced by their exponential forms (relative error
//! e^(−2t) < 5e-18), so nothing overflows; for 2t < 1 sinh 2t − 2t is summed as a series.
//!
//! # Accuracy
//!
//! `tests/hankel/two_plate_hole.rs`: the face conditions, and the bilateral
//! limit — a top pressure p with the bottom pressure of the slab of half-thickness D
//! ([`crate::hankel::kernel::midplane`]) reproduces the slab's interior stresses
//! ([`crate::hankel::field::stress_for_transform`]).
//!
//! # Cost
//!
//! A few exponentials per ξ.
//!
//! ```
//! use boltzone::hankel::receding::layer_field::bottom_kernels;
//! // the bottom face carries the load: Z = −ξ per unit b̄, and no shear
//! let k = bottom_kernels(2.0, 1.0, 0.0, 0.3);
//! assert!((k.z + 2.0).abs() < 1e-14 && k.t.abs() < 1e-14);
//! ```

use super::layer::scaled_sinh_minus_x;

/// The kernels (R₀, R₁, T, Z) at one (ξ, z) per unit b̄ (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LayerKernels {
    /// Coefficient of J₀(ξr) in σ_r.
    pub r0: f64,
    /// Coefficient of −J₁(ξr)/(ξr) in σ_r.
    pub r1: f64,
    /// Coefficient of J₁(ξr) in τ_rz.
    pub t: f64,
    /// Coefficient of J₀(ξr) in σ_z.
    pub z: f64,
}

/// sinh 2t − 2t without cancellation at small t (the series of [`super::layer`] below 1).
fn sinh_minus(t2: f64) -> f64 {
    if t2 >= 1.0 {
        t2.sinh() - t2
    } else {
        0.5 * t2.exp() * scaled_sinh_minus_x(t2)
    }
}

/// Kernels at wavenumber `xi` and height `z` (0 ≤ z ≤ `d`) for a unit bottom pressure
/// transform, top face free, Poisson's ratio `nu`.
pub fn bottom_kernels(xi: f64, d: f64, z: f64, nu: f64) -> LayerKernels {
    let h = 0.5 * d;
    let t = xi * h;
    let zeta = z - h;
    let xz = xi * zeta;
    // the ratios S·c/den etc. of the two halves, den_s = sinh 2t + 2t, den_a = sinh 2t − 2t
    let (sc_s, ss_s, cc_s, cs_s, sc_a, ss_a, cc_a, cs_a) = if t > 20.0 {
        // S ≈ C ≈ e^t/2, den ≈ e^(2t)/2: S·cosh(ξζ)/den ≈ (e₁ + e₂)/2 with
        // e₁ = e^(−ξ(h−ζ)) (distance to the top), e₂ = e^(−ξ(h+ζ)) = e^(−ξz)
        let e1 = (-xi * (h - zeta)).exp();
        let e2 = (-xi * (h + zeta)).exp();
        let (p, m) = (0.5 * (e1 + e2), 0.5 * (e1 - e2));
        (p, m, p, m, p, m, p, m)
    } else {
        let (sh, ch) = (t.sinh(), t.cosh());
        let (s, c) = (xz.sinh(), xz.cosh());
        let den_s = (2.0 * t).sinh() + 2.0 * t;
        let den_a = sinh_minus(2.0 * t);
        (
            sh * c / den_s,
            sh * s / den_s,
            ch * c / den_s,
            ch * s / den_s,
            sh * c / den_a,
            sh * s / den_a,
            ch * c / den_a,
            ch * s / den_a,
        )
    };
    let sym = LayerKernels {
        r0: (sc_s - t * cc_s) + xz * ss_s,
        r1: ((1.0 - 2.0 * nu) * sc_s - t * cc_s) + xz * ss_s,
        t: xz * sc_s - t * cs_s,
        z: (sc_s + t * cc_s) - xz * ss_s,
    };
    let anti = LayerKernels {
        r0: (cs_a - t * ss_a) + xz * cc_a,
        r1: ((1.0 - 2.0 * nu) * cs_a - t * ss_a) + xz * cc_a,
        t: xz * cs_a - t * sc_a,
        z: (cs_a + t * ss_a) - xz * cc_a,
    };
    LayerKernels {
        r0: xi * (anti.r0 - sym.r0),
        r1: xi * (anti.r1 - sym.r1),
        t: xi * (anti.t - sym.t),
        z: xi * (anti.z - sym.z),
    }
}

/// Kernels for a unit TOP pressure transform, bottom face free: the bottom kernels mirrored.
pub fn top_kernels(xi: f64, d: f64, z: f64, nu: f64) -> LayerKernels {
    let k = bottom_kernels(xi, d, d - z, nu);
    LayerKernels { t: -k.t, ..k }
}
