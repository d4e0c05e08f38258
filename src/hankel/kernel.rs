//! Hankel-transform kernels of the infinite slab −D ≤ z ≤ D pressed by p(r) on both faces.
//!
//! **Problem.** σ_z(r, ±D) = −p(r), τ_rz(r, ±D) = 0 (compression negative), no body force;
//! the load is symmetric about the midplane z = 0, so σ_z, σ_r, σ_θ, u are even in z and
//! τ_rz, w odd.
//!
//! **Derivation** (Love's strain function; Sneddon 1946, *Proc. Camb. Phil. Soc.* 42, 29–39;
//! Timoshenko & Goodier, *Theory of Elasticity*, 3rd ed., §§ 130–131). With a biharmonic φ(r, z),
//! ∇² = ∂²_r + ∂_r/r + ∂²_z,
//!
//! σ_z = ∂_z[(2−ν)∇²φ − ∂²_zφ], σ_r = ∂_z[ν∇²φ − ∂²_rφ], σ_θ = ∂_z[ν∇²φ − ∂_rφ/r],
//! τ_rz = ∂_r[(1−ν)∇²φ − ∂²_zφ], 2G u = −∂²_{rz}φ, 2G w = 2(1−ν)∇²φ − ∂²_zφ.
//!
//! Take φ = ∫₀^∞ [a(ξ) sinh ξz + b(ξ) ξz cosh ξz] J₀(ξr) dξ (odd in z, biharmonic). The two face
//! conditions, with p(r) = ∫₀^∞ ξ p̄(ξ) J₀(ξr) dξ and p̄(ξ) = ∫₀^∞ p(r) J₀(ξr) r dr, give
//! a = −b(2ν + t coth t), b = −2p̄ sinh t /(ξ²Δ), with t = ξD, Δ(t) = sinh 2t + 2t. With s = ξz:
//!
//! | field | integral | kernel |
//! |---|---|---|
//! | σ_z | −∫ ξp̄ K_z J₀(ξr) dξ | K_z = 2[(sinh t + t cosh t) cosh s − s sinh t sinh s]/Δ |
//! | τ_rz | −∫ ξp̄ K_τ J₁(ξr) dξ | K_τ = 2[s sinh t cosh s − t cosh t sinh s]/Δ |
//! | σ_r | −∫ ξp̄ [K_r J₀(ξr) − K_m J₁(ξr)/(ξr)] dξ | K_r = 2[(sinh t − t cosh t) cosh s + s sinh t sinh s]/Δ |
//! | σ_θ | −∫ ξp̄ [K_n J₀(ξr) + K_m J₁(ξr)/(ξr)] dξ | K_m = 2[((1−2ν) sinh t − t cosh t) cosh s + s sinh t sinh s]/Δ, K_n = 4ν sinh t cosh s/Δ |
//! | u | −(1/2G) ∫ p̄ K_m J₁(ξr) dξ | |
//! | w | −(1/2G) ∫ p̄ K_w J₀(ξr) dξ | K_w = 2[(2(1−ν) sinh t + t cosh t) sinh s − s sinh t cosh s]/Δ |
//!
//! On the midplane K_z(t, 0) = 2(sinh t + t cosh t)/(sinh 2t + 2t) = K(t): K(0) = 1,
//! K ~ 2t e^(−t); σ_z and τ_rz do not depend on ν. On a face (s = t): K_z = 1, K_τ = 0 exactly,
//! K_r = 1 − 4t/Δ, K_m = (1−2ν) − 4(1−ν)t/Δ, K_n = 2ν(1 − 2t/Δ),
//! K_w = 2(1−ν)[1 − (1 + 2t − e^(−2t))/Δ]: the half-space surface values (Boussinesq) plus
//! exponentially small remainders, which [`face_remainders`] returns.
//!
//! **Overflow-free form.** With sinh x = eˣ S(x), cosh x = eˣ C(x), S = −expm1(−2x)/2,
//! C = (1 + e^(−2x))/2 and Δ = e^(2t) Q/2, Q = −expm1(−4t) + 4t e^(−2t), every kernel is
//! 4e^(s−t)·(polynomial in S, C, s, t)/Q with 0 ≤ s ≤ t: no exponential grows, and expm1 keeps
//! full relative accuracy as t → 0 (Q ≈ 8t). [`KernelNode`] and [`KernelHeight`] hold the t- and
//! s-dependent factors, so many heights at one ξ (and the shear kernels of
//! [`super::kernel_shear`] at the same point) share them.
//!
//! # Accuracy
//!
//! The face conditions to 8ε(1 + t) for t from 1e-6 to 440, the midplane kernel within its bound
//! and equal to the textbook form where that is safe (t < 20), finite at t = 1e4
//! (`tests/hankel/slab.rs`, `kernels_meet_the_face_conditions_and_bound`).
//!
//! # Cost
//!
//! A few exponentials per ξ-node, shared by all heights.
//!
//! ```
//! use boltzone::hankel::kernel::{midplane, Kernels};
//! assert!((midplane(1e-9) - 1.0).abs() < 1e-8);
//! assert!(midplane(800.0) >= 0.0 && midplane(800.0) < 1e-300);
//! let k = Kernels::at(3.0, 3.0, 0.3);
//! assert!((k.z - 1.0).abs() < 1e-15 && k.tau.abs() < 1e-15);
//! ```

/// The kernels at t = ξD and s = ξ|z| (0 ≤ s ≤ t), for Poisson's ratio ν. Odd kernels (τ, w)
/// are returned for z ≥ 0; the caller applies the sign of z.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kernels {
    /// K_z (σ_z, with J₀).
    pub z: f64,
    /// K_τ (τ_rz, with J₁).
    pub tau: f64,
    /// K_r (σ_r, with J₀).
    pub r: f64,
    /// K_m (σ_r, σ_θ with J₁(ξr)/(ξr); u with J₁).
    pub m: f64,
    /// K_n (σ_θ, with J₀).
    pub n: f64,
    /// K_w (w, with J₀).
    pub w: f64,
}

/// Smallest t used (kernels are continuous at t = 0; this avoids 0/0).
pub(crate) const T_MIN: f64 = 1e-300;

/// Scaled sinh and cosh: (S, C) with sinh x = eˣ S, cosh x = eˣ C, for x ≥ 0.
pub(crate) fn scaled(x: f64) -> (f64, f64) {
    let e2 = (-2.0 * x).exp();
    (-0.5 * (-2.0 * x).exp_m1(), 0.5 * (1.0 + e2))
}

/// Q(t) = e^(−2t)·2Δ(t) = 1 − e^(−4t) + 4t e^(−2t).
pub(crate) fn q(t: f64) -> f64 {
    -(-4.0 * t).exp_m1() + 4.0 * t * (-2.0 * t).exp()
}

/// The midplane kernel K(t) = 2(sinh t + t cosh t)/(sinh 2t + 2t) of σ_z(r, 0), for t ≥ 0.
pub fn midplane(t: f64) -> f64 {
    let t = t.max(T_MIN);
    let (st, ct) = scaled(t);
    4.0 * (-t).exp() * (st + t * ct) / q(t)
}

/// An upper bound of |K(t)| for t ≥ 0, used to truncate midplane integrals:
/// K(t) → 2(1 + t)e^(−t) as t → ∞ and K ≤ 1; 2.5(1 + t)e^(−t) bounds both (checked in the
/// tests on a fine grid).
pub fn midplane_bound(t: f64) -> f64 {
    2.5 * (1.0 + t) * (-t).exp()
}

/// The t-dependent factors of every kernel at one ξ (shared by all heights there): t = ξD,
/// the scaled S(t), C(t) and 4/Q(t).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KernelNode {
    /// t = ξD (at least 1e-300, so that every division by t stays finite).
    pub t: f64,
    /// S(t) = sinh t·e^(−t).
    pub st: f64,
    /// C(t) = cosh t·e^(−t).
    pub ct: f64,
    /// 4/Q(t).
    pub four_over_q: f64,
}

impl KernelNode {
    /// The factors at t = ξD.
    pub fn new(t: f64) -> Self {
        let t = t.max(T_MIN);
        let (st, ct) = scaled(t);
        Self {
            t,
            st,
            ct,
            four_over_q: 4.0 / q(t),
        }
    }

    /// The s-dependent factors at s = ξ|z| (three exponentials), shared by the pressure and
    /// shear kernels of one point.
    pub fn height(&self, s: f64) -> KernelHeight {
        let s = s.clamp(0.0, self.t);
        let (ss, cs) = scaled(s);
        KernelHeight {
            s,
            ss,
            cs,
            f: self.four_over_q * (s - self.t).exp(),
        }
    }
}

/// The s-dependent factors of every kernel at one ξ and height ([`KernelNode::height`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KernelHeight {
    /// s = ξ|z| clamped to [0, t].
    pub s: f64,
    /// S(s).
    pub ss: f64,
    /// C(s).
    pub cs: f64,
    /// 4e^(s−t)/Q(t).
    pub f: f64,
}

impl Kernels {
    /// All kernels at t = ξD, s = ξ|z| (s is clamped to [0, t]), Poisson's ratio `nu`.
    pub fn at(t: f64, s: f64, nu: f64) -> Kernels {
        Self::at_node(&KernelNode::new(t), s, nu)
    }

    /// [`Self::at`] with the t-dependent factors given (many heights at one ξ).
    pub fn at_node(node: &KernelNode, s: f64, nu: f64) -> Kernels {
        Self::at_height(node, &node.height(s), nu)
    }

    /// [`Self::at`] with the t- and s-dependent factors given.
    pub fn at_height(node: &KernelNode, h: &KernelHeight, nu: f64) -> Kernels {
        let (t, st, ct) = (node.t, node.st, node.ct);
        let (s, ss, cs, f) = (h.s, h.ss, h.cs, h.f);
        Kernels {
            z: f * ((st + t * ct) * cs - s * st * ss),
            tau: f * (s * st * cs - t * ct * ss),
            r: f * ((st - t * ct) * cs + s * st * ss),
            m: f * (((1.0 - 2.0 * nu) * st - t * ct) * cs + s * st * ss),
            n: 2.0 * nu * f * st * cs,
            w: f * ((2.0 * (1.0 - nu) * st + t * ct) * ss - s * st * cs),
        }
    }
}

/// Face kernels minus their large-t limits (the half-space surface values), all O(t e^(−2t)):
/// K_r − 1, K_m − (1−2ν), K_n − 2ν, K_w − 2(1−ν) at s = t. (K_z − 1 = K_τ = 0 exactly.)
pub fn face_remainders(t: f64, nu: f64) -> Kernels {
    let t = t.max(T_MIN);
    let g = 2.0 * (-2.0 * t).exp() / q(t); // 1/Δ
    Kernels {
        z: 0.0,
        tau: 0.0,
        r: -4.0 * t * g,
        m: -4.0 * (1.0 - nu) * t * g,
        n: -4.0 * nu * t * g,
        w: 2.0 * (1.0 - nu) * ((-2.0 * t).exp_m1() - 2.0 * t) * g,
    }
}
