//! Homogeneous solutions of the traction-free layer −D ≤ z ≤ D outside a cylinder r = A,
//! symmetric in z and decaying as r → ∞: the Lamé field and the Papkovich–Fadle eigenfunctions.
//!
//! **Derivation** (Love's strain function, the same formulas as [`crate::hankel::kernel`]).
//! Separable biharmonic functions odd in z with a radial factor decaying at infinity are
//! φ = K₀(λr)·[a sin λz + z cos λz] (∇²K₀(λr) = λ²K₀(λr), so (∂²_z + λ²)² annihilates the
//! z-factor). The faces z = ±D are free of σ_z and τ_rz when, with x = λD and α = aλ,
//!
//! (α − (1−2ν)) cos x − x sin x = 0,  (α + 2ν) sin x + x cos x = 0,
//!
//! which have a solution α ≠ 0 only if **sin 2x + 2x = 0** (the symmetric family of Fadle's plane
//! equation: Fadle, *Ing.-Arch.* 11 (1941) 125; for the axisymmetric layer Little & Childs,
//! *Q. Appl. Math.* 25 (1967) 261, and Gregory, *J. Elasticity* 10 (1980) 57). The roots are
//! complex, x_k ≈ ((2k − ½)π + i ln((4k−1)π))/2 for large k (x₁ = 2.10620 + 1.12536i), and
//! α_k = (1 − 2ν) + x_k tan x_k. Dividing by λ² and by K₁(λA) (so that each mode is O(1) on the
//! hole), with Z = λz, R₀ = K₀(λr)/K₁(λA), R₁ = K₁(λr)/K₁(λA), g′ = (α+1) cos Z − Z sin Z:
//!
//! | field | mode k |
//! |---|---|
//! | σ_z | R₀ [(α − 1 + 2ν) cos Z − Z sin Z] |
//! | τ_rz | −R₁ [(α + 2ν) sin Z + Z cos Z] |
//! | σ_r | −R₀ [(α + 1 + 2ν) cos Z − Z sin Z] − R₁ g′/(λr) |
//! | σ_θ | −2ν R₀ cos Z + R₁ g′/(λr) |
//! | 2G u | R₁ g′/λ |
//! | 2G w | R₀ [(α − 2 + 4ν) sin Z + Z cos Z]/λ |
//!
//! Each complex mode F_k gives two real fields, Re F_k and Im F_k (the conjugate root gives
//! nothing new). The **Lamé field** u = A²/(2G r), w = 0 has σ_r = −σ_θ = −A²/r², σ_z = τ_rz = 0:
//! it carries the net radial force on the hole, which the self-equilibrated eigenfunctions
//! cannot. Radial factors are formed from exponentially scaled K ([`super::bessel_k`]) as
//! e^(−λ(r−A))·K̂_ν(λr)/K̂₁(λA), so nothing overflows or underflows for any r ≥ A.
//!
//! Stresses are dimensionless multiples of the mode's (free) amplitude, displacements carry
//! 1/(2G); compression negative.
//!
//! # Accuracy
//!
//! `tests/hankel/hole_eigen.rs`: the roots solve the symmetric Fadle equation, free faces,
//! equilibrium and Hooke's law by differences, each mode self-equilibrated in z, the midplane
//! bound.
//!
//! # Cost
//!
//! One complex K₀, K₁ pair per mode and point.
//!
//! ```
//! use boltzone::hankel::hole::eigen::{symmetric_roots, Mode};
//! let x = symmetric_roots(1)[0];
//! assert!((x.re - 2.106_196).abs() < 1e-6 && (x.im - 1.125_364).abs() < 1e-6);
//! let m = Mode::new(x, 0.1, 0.1, 0.3, 1.0);
//! let f = m.field(0.15, 0.1); // on the face z = D: traction-free
//! assert!(f.sigma_z.norm() < 1e-13 && f.tau_rz.norm() < 1e-13);
//! ```

use crate::numerics::bessel_i::i01_scaled;
use crate::numerics::bessel_k::k01_scaled;
use num_complex::Complex64;
use std::f64::consts::PI;

/// The first `n` roots x_k (Re, Im > 0, increasing real part) of sin 2x + 2x = 0, by Newton's
/// method from the asymptotic estimate; each converged to a relative step below 1e-15.
pub fn symmetric_roots(n: usize) -> Vec<Complex64> {
    (1..=n)
        .map(|k| {
            let kf = k as f64;
            // w = 2x solves sin w + w = 0.
            let mut w = Complex64::new((2.0 * kf - 0.5) * PI, ((4.0 * kf - 1.0) * PI).ln());
            for _ in 0..50 {
                let step = (w.sin() + w) / (w.cos() + 1.0);
                w -= step;
                if step.norm() <= 1e-15 * w.norm() {
                    break;
                }
            }
            w / 2.0
        })
        .collect()
}

/// A field's axisymmetric components at one point (complex for a Papkovich–Fadle mode, whose
/// real and imaginary parts are two real solutions).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ModeField<T> {
    /// σ_r.
    pub sigma_r: T,
    /// σ_θ.
    pub sigma_theta: T,
    /// σ_z.
    pub sigma_z: T,
    /// τ_rz.
    pub tau_rz: T,
    /// Radial displacement u.
    pub u: T,
    /// Axial displacement w.
    pub w: T,
}

/// One symmetric Papkovich–Fadle mode of the layer −D ≤ z ≤ D: decaying outward (K₀, K₁,
/// normalised on the hole r = A) or growing outward (I₀, I₁, normalised on a rim r = C).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mode {
    lam: Complex64,
    alpha: Complex64,
    nu: f64,
    /// The radius the mode is normalised on (A, or C for a growing mode).
    a: f64,
    two_g: f64,
    /// e^{λA}K₁(λA) (decaying) or e^{−λC}I₁(λC) (growing), the scaled normaliser.
    k1a: Complex64,
    growing: bool,
}

impl Mode {
    /// The mode of root `x` (= λD) for hole radius `a` > 0, half-thickness `d`, Poisson's ratio
    /// `nu` and shear modulus `g`.
    pub fn new(x: Complex64, a: f64, d: f64, nu: f64, g: f64) -> Self {
        let lam = x / d;
        let alpha = (1.0 - 2.0 * nu) + x * x.tan();
        let (_, k1a) = k01_scaled(lam * a);
        Self {
            lam,
            alpha,
            nu,
            a,
            two_g: 2.0 * g,
            k1a,
            growing: false,
        }
    }

    /// The mode of root `x` growing outward, normalised on the rim r = `c`: K₀ → I₀ and
    /// K₁ → −I₁ in every formula (d/dx K₀ = −K₁ but d/dx I₀ = I₁), for r ≤ C.
    pub fn growing(x: Complex64, c: f64, d: f64, nu: f64, g: f64) -> Self {
        let lam = x / d;
        let (_, i1c) = i01_scaled(lam * c);
        Self {
            lam,
            alpha: (1.0 - 2.0 * nu) + x * x.tan(),
            nu,
            a: c,
            two_g: 2.0 * g,
            k1a: i1c,
            growing: true,
        }
    }

    /// λ = x/D.
    pub fn lambda(&self) -> Complex64 {
        self.lam
    }

    /// Radial factors (R₀, R₁) at r (r ≥ A for a decaying mode, r ≤ C for a growing one): the
    /// costly part of a field, shared by every height at that radius (see [`Self::field_at`]).
    pub fn radial(&self, r: f64) -> (Complex64, Complex64) {
        if self.growing {
            let (i0, i1) = i01_scaled(self.lam * r);
            let e = (self.lam * (r - self.a)).exp() / self.k1a;
            (i0 * e, -i1 * e)
        } else {
            let (k0, k1) = k01_scaled(self.lam * r);
            let e = (-self.lam * (r - self.a)).exp() / self.k1a;
            (k0 * e, k1 * e)
        }
    }

    /// σ_r and τ_rz on the cylinder of radius r at height z (the traction the fit matches).
    pub fn traction(&self, r: f64, z: f64) -> (Complex64, Complex64) {
        self.traction_at(self.radial(r), r, z)
    }

    /// [`Self::traction`] with the radial factors of r given.
    pub fn traction_at(
        &self,
        radial: (Complex64, Complex64),
        r: f64,
        z: f64,
    ) -> (Complex64, Complex64) {
        let f = self.field_at(radial, r, z);
        (f.sigma_r, f.tau_rz)
    }

    /// σ_z(r, 0) on the midplane.
    pub fn midplane_sigma_z(&self, r: f64) -> Complex64 {
        let (r0, _) = self.radial(r);
        r0 * (self.alpha - (1.0 - 2.0 * self.nu))
    }

    /// An upper bound of |[`Self::midplane_sigma_z`]| at r ≥ A for a decaying mode:
    /// 2|α − (1 − 2ν)|e^(−Re λ (r − A)) (the scaled K₀(λr)/K₁(λA) is at most 1 in size —
    /// Hankel's expansions, √(A/r)(1 + O(1/λA)), and K₀ < K₁ at small λA — the 2 a margin;
    /// checked in `tests/hankel/hole_eigen.rs`), ∞ for a growing mode. Sums skip modes whose bound
    /// times their amplitude is negligible.
    pub fn midplane_bound(&self, r: f64) -> f64 {
        if self.growing {
            return f64::INFINITY;
        }
        let f = (self.alpha - (1.0 - 2.0 * self.nu)).norm();
        2.0 * f * (-self.lam.re * (r - self.a).max(0.0)).exp()
    }

    /// Every field at (r, z), r ≥ A, |z| ≤ D.
    pub fn field(&self, r: f64, z: f64) -> ModeField<Complex64> {
        self.field_at(self.radial(r), r, z)
    }

    /// [`Self::field`] with the radial factors `(r0, r1)` = [`Self::radial`]`(r)` given.
    pub fn field_at(
        &self,
        (r0, r1): (Complex64, Complex64),
        r: f64,
        z: f64,
    ) -> ModeField<Complex64> {
        let (nu, al, lam) = (self.nu, self.alpha, self.lam);
        let zz = lam * z;
        let (s, c) = (zz.sin(), zz.cos());
        let gp = (al + 1.0) * c - zz * s;
        let q = r1 * gp / (lam * r);
        ModeField {
            sigma_z: r0 * ((al - 1.0 + 2.0 * nu) * c - zz * s),
            tau_rz: -r1 * ((al + 2.0 * nu) * s + zz * c),
            sigma_r: -r0 * ((al + 1.0 + 2.0 * nu) * c - zz * s) - q,
            sigma_theta: -2.0 * nu * r0 * c + q,
            u: r1 * gp / (lam * self.two_g),
            w: r0 * ((al - 2.0 + 4.0 * nu) * s + zz * c) / (lam * self.two_g),
        }
    }
}

/// The Lamé field of a hole of radius `a` in a material of shear modulus `g`, unit amplitude:
/// σ_r = −(A/r)², σ_θ = (A/r)², u = A²/(2G r).
pub fn lame_field(a: f64, g: f64, r: f64) -> ModeField<f64> {
    let q = (a / r) * (a / r);
    ModeField {
        sigma_r: -q,
        sigma_theta: q,
        sigma_z: 0.0,
        tau_rz: 0.0,
        u: q * r / (2.0 * g),
        w: 0.0,
    }
}

/// The uniform in-plane state σ_r = σ_θ = 1, σ_z = τ_rz = 0 (a free rim's Lamé companion), with
/// u = (1 − ν)r/E, w = −2νz/E, E = 2G(1 + ν).
pub fn uniform_field(nu: f64, g: f64, r: f64, z: f64) -> ModeField<f64> {
    let e = 2.0 * g * (1.0 + nu);
    ModeField {
        sigma_r: 1.0,
        sigma_theta: 1.0,
        sigma_z: 0.0,
        tau_rz: 0.0,
        u: (1.0 - nu) * r / e,
        w: -2.0 * nu * z / e,
    }
}
