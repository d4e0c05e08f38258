//! Hankel-transform kernels of the infinite slab −D ≤ z ≤ D under a symmetric radial SHEAR
//! traction on both faces: τ_rz(r, ±D) = ±s(r), σ_z(r, ±D) = 0 (the companion of
//! [`super::kernel`]'s pressure load; used by the hole's corner enrichment, [`super::hole`]).
//!
//! **Derivation** (Love's strain function, the formulas and sign conventions of
//! [`super::kernel`]). With φ = ∫₀^∞ [a(ξ) sinh ξz + b(ξ) ξz cosh ξz] J₀(ξr) dξ (odd in z, so
//! σ_z, σ_r, σ_θ, u are even and τ_rz, w odd — the load is symmetric about the midplane), s = ξz:
//!
//! σ_z = ξ³[((1−2ν)b − a) cosh s − b s sinh s] J₀,  τ_rz = ξ³[(a + 2νb) sinh s + b s cosh s] J₁.
//!
//! σ_z(±D) = 0 gives a = b[(1 − 2ν) − t tanh t]; then τ_rz(D) = ξ³ b Δ/(2 cosh t), Δ = sinh 2t + 2t,
//! and with s(r) = ∫₀^∞ ξ s̄(ξ) J₁(ξr) dξ, s̄(ξ) = ∫₀^∞ s(ρ) J₁(ξρ) ρ dρ (order-one Hankel
//! transform), b = 2s̄ cosh t/(ξ²Δ), t = ξD. The fields:
//!
//! | field | integral | kernel |
//! |---|---|---|
//! | σ_z | ∫ ξs̄ L_z J₀(ξr) dξ | L_z = 2[t sinh t cosh s − s cosh t sinh s]/Δ |
//! | τ_rz | ∫ ξs̄ L_τ J₁(ξr) dξ | L_τ = 2[(cosh t − t sinh t) sinh s + s cosh t cosh s]/Δ |
//! | σ_r | ∫ ξs̄ [L_r J₀ − L_m J₁(ξr)/(ξr)] dξ | L_r = 2[(2 cosh t − t sinh t) cosh s + s cosh t sinh s]/Δ |
//! | σ_θ | ∫ ξs̄ [L_n J₀ + L_m J₁(ξr)/(ξr)] dξ | L_m = 2[((2−2ν) cosh t − t sinh t) cosh s + s cosh t sinh s]/Δ, L_n = 4ν cosh t cosh s/Δ |
//! | u | (1/2G) ∫ s̄ L_m J₁(ξr) dξ | |
//! | w | (1/2G) ∫ s̄ L_w J₀(ξr) dξ | L_w = 2[((1−2ν) cosh t + t sinh t) sinh s − s cosh t cosh s]/Δ |
//!
//! On a face (s = t): L_z = 0 and L_τ = 1 exactly; L_r = 4cosh²t/Δ = 2 + 4e^(−2t)(1 + e^(−2t) − 2t)/Q,
//! L_m = (1−ν)L_r, L_n = νL_r, L_w = (1−2ν) − 4(1−ν)t/Δ ([`shear_face_remainders`]). Deep in a
//! thick slab (t → ∞ at fixed u = t − s) the half-space kernels: L_z → u e^(−u),
//! L_τ → (1 − u)e^(−u), L_r → (2 − u)e^(−u), L_m → (2(1−ν) − u)e^(−u), L_n → 2ν e^(−u),
//! L_w → ((1−2ν) + u)e^(−u). As t → 0, L_r, L_m, L_n ~ 1/t (times s̄ ~ ξ: integrable).
//!
//! **Overflow-free form.** As in [`super::kernel`]: every kernel is 4e^(s−t)·(polynomial in the
//! scaled S, C, s, t)/Q with Q = e^(−2t)·2Δ, so nothing overflows for any t and 0 ≤ s ≤ t.
//!
//! Checked in `tests/hankel/shear_kernels.rs`: face conditions, equilibrium and Hooke's law
//! (stresses from the displacements) by finite differences at fixed ξ, the half-space limits,
//! and an exact-rational solution of the two face conditions (sympy,
//! `tests/data/shear_kernels.py`).
//!
//! # Accuracy
//!
//! Against the symbolic derivation (`tests/hankel/shear_kernels.rs`,
//! `kernels_match_the_symbolic_derivation`), the face remainders and half-space limits, and
//! equilibrium and Hooke's law by differences.
//!
//! # Cost
//!
//! Shares [`super::kernel::KernelNode`] and [`super::kernel::KernelHeight`] with the pressure
//! kernels: a few products per height.
//!
//! ```
//! use boltzone::hankel::kernel_shear::ShearKernels;
//! let k = ShearKernels::at(2.0, 2.0, 0.3); // on the face
//! assert!(k.z.abs() < 1e-15 && (k.tau - 1.0).abs() < 1e-15);
//! ```

use super::kernel::{q, scaled, KernelHeight, KernelNode, T_MIN};

/// The shear-load kernels at t = ξD and s = ξ|z| (0 ≤ s ≤ t), Poisson's ratio ν. Odd kernels
/// (τ, w) are returned for z ≥ 0; the caller applies the sign of z.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShearKernels {
    /// L_z (σ_z, with J₀).
    pub z: f64,
    /// L_τ (τ_rz, with J₁).
    pub tau: f64,
    /// L_r (σ_r, with J₀).
    pub r: f64,
    /// L_m (σ_r, σ_θ with J₁(ξr)/(ξr); u with J₁).
    pub m: f64,
    /// L_n (σ_θ, with J₀).
    pub n: f64,
    /// L_w (w, with J₀).
    pub w: f64,
}

impl ShearKernels {
    /// All kernels at t = ξD, s = ξ|z| (s is clamped to [0, t]), Poisson's ratio `nu`.
    pub fn at(t: f64, s: f64, nu: f64) -> ShearKernels {
        Self::at_node(&KernelNode::new(t), s, nu)
    }

    /// [`Self::at`] with the t-dependent factors given (many heights at one ξ).
    pub fn at_node(node: &KernelNode, s: f64, nu: f64) -> ShearKernels {
        Self::at_height(node, &node.height(s), nu)
    }

    /// [`Self::at`] with the t- and s-dependent factors given (shared with the pressure
    /// kernels of [`super::kernel::Kernels::at_height`]).
    pub fn at_height(node: &KernelNode, h: &KernelHeight, nu: f64) -> ShearKernels {
        let (t, st, ct) = (node.t, node.st, node.ct);
        let (s, ss, cs, f) = (h.s, h.ss, h.cs, h.f);
        ShearKernels {
            z: f * (t * st * cs - s * ct * ss),
            tau: f * ((ct - t * st) * ss + s * ct * cs),
            r: f * ((2.0 * ct - t * st) * cs + s * ct * ss),
            m: f * (((2.0 - 2.0 * nu) * ct - t * st) * cs + s * ct * ss),
            n: 2.0 * nu * f * ct * cs,
            w: f * (((1.0 - 2.0 * nu) * ct + t * st) * ss - s * ct * cs),
        }
    }

    /// The midplane kernel L_z(t, 0) = 2t sinh t/Δ of σ_z(r, 0), for t ≥ 0.
    pub fn midplane(t: f64) -> f64 {
        let t = t.max(T_MIN);
        let (st, _) = scaled(t);
        4.0 * (-t).exp() * t * st / q(t)
    }
}

/// Face kernels (s = t) minus their large-t limits, all O(t e^(−2t)): L_r − 2, L_m − 2(1−ν),
/// L_n − 2ν, L_w − (1−2ν) (L_z = 0 and L_τ = 1 exactly).
pub fn shear_face_remainders(t: f64, nu: f64) -> ShearKernels {
    let t = t.max(T_MIN);
    let e = (-2.0 * t).exp();
    let g = 2.0 * e / q(t); // 1/Δ
    let rr = 4.0 * e * (1.0 + e - 2.0 * t) / q(t);
    ShearKernels {
        z: 0.0,
        tau: 0.0,
        r: rr,
        m: (1.0 - nu) * rr,
        n: nu * rr,
        w: -4.0 * (1.0 - nu) * t * g,
    }
}
