//! Stresses and displacements anywhere in the infinite slab −D ≤ z ≤ D, no hole, pressed by
//! p(r) on both faces: [`Slab`].
//!
//! Each field is a Hankel integral of the load transform p̄(ξ) ([`super::transform`]) times a
//! kernel of [`super::kernel`] times J₀(ξr) or J₁(ξr), integrated by partition–extrapolation
//! ([`super::quadrature`]) with panels of a half-period π/(r + B). Inside the slab the integrands
//! decay like e^(−ξ(D−|z|)); on a face (|z| = D) they do not, so there the large-ξ limits of the
//! kernels (the half-space surface values) are integrated analytically:
//! σ_z = −p(r), τ_rz = 0, σ_r = −p + (1−2ν)m(r)/r², σ_θ = −2νp − (1−2ν)m(r)/r²,
//! u = −(1−2ν)m(r)/(2G r) with m(r) = ∫₀^r p ρ dρ, and only exponentially decaying remainders are
//! integrated numerically. w keeps the half-space surface deflection ∫ p̄ J₀ dξ, which decays
//! only like ξ^(−2) at a load edge; it is evaluated in real space with the elliptic kernel
//! ([`super::transform::LoadTransform::surface_integral`]).
//! Compression negative; stresses in the load's pressure units, displacements in length units
//! when E is in pressure units.
//!
//! # Accuracy
//!
//! Every value carries the quadrature's error estimate, never below the actual error on the closed
//! forms of `tests/hankel/slab.rs` (Boussinesq on the axis of a thick slab, the wide-load limit σ_z
//! = −p, equilibrium and compatibility by finite differences, the face conditions from inside, ring
//! loads superposing to the annulus; `field_error_estimates_cover_the_actual_error`).
//!
//! # Cost
//!
//! One partition–extrapolation per point, growing with (r + B)/(distance to the face): `cargo bench
//! --bench hankel`.
//!
//! ```
//! use boltzone::{FaceLoad, Material, hankel::Slab};
//! let slab = Slab::new(0.1, Material::unit(0.3)?, FaceLoad::uniform(0.1, 0.31, 1.0)?)?;
//! let s = slab.stress(0.2, 0.1, &Default::default());
//! assert!((s.sigma_z.value + 1.0).abs() < 1e-12 && s.tau_rz.value.abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::kernel::{face_remainders, Kernels};
use super::transform::LoadTransform;
use crate::error::{positive, InputError};
use crate::load::FaceLoad;
use crate::material::Material;
use crate::numerics::quadrature::{integrate_oscillatory_vec, Estimate, QuadParams};

/// The infinite slab of half-thickness D (thickness 2D), no hole, loaded by the same p(r) on
/// both faces.
#[derive(Debug, Clone)]
pub struct Slab {
    d: f64,
    material: Material,
    load: FaceLoad,
    transform: LoadTransform,
}

/// The stress tensor's axisymmetric components at one point, each with its error estimate.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StressEstimate {
    /// Radial normal stress σ_r.
    pub sigma_r: Estimate,
    /// Hoop stress σ_θ.
    pub sigma_theta: Estimate,
    /// Axial normal stress σ_z.
    pub sigma_z: Estimate,
    /// Shear stress τ_rz.
    pub tau_rz: Estimate,
}

/// Displacements (u radial, w axial, positive outward / upward) with error estimates.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Displacement {
    /// Radial displacement u.
    pub u: Estimate,
    /// Axial displacement w.
    pub w: Estimate,
}

/// J₁(x)/x, continuous at 0.
fn j1_over_x(x: f64) -> f64 {
    if x < 1e-8 {
        0.5 - x * x / 16.0
    } else {
        libm::j1(x) / x
    }
}

impl Slab {
    /// A slab of half-thickness `d` (> 0) of `material`, with `load` on both faces.
    pub fn new(d: f64, material: Material, load: FaceLoad) -> Result<Self, InputError> {
        positive("half-thickness D", d)?;
        let transform = LoadTransform::new(&load);
        Ok(Self {
            d,
            material,
            load,
            transform,
        })
    }

    /// Half-thickness D.
    pub fn half_thickness(&self) -> f64 {
        self.d
    }

    /// The material.
    pub fn material(&self) -> Material {
        self.material
    }

    /// The face load.
    pub fn load(&self) -> &FaceLoad {
        &self.load
    }

    /// The load transform p̄(ξ), shared by all evaluations.
    pub fn transform(&self) -> &LoadTransform {
        &self.transform
    }

    /// Panel frequency for the point r: the fastest oscillation r + B of J(ξr)·p̄(ξ). Panels are
    /// split into sub-panels of 1/D, the scale on which the kernels vary (their poles nearest
    /// the real axis lie at Im ξ ≈ 1.1/D).
    fn omega(&self, r: f64) -> f64 {
        r + self.transform.outer()
    }

    /// Whether r sits on a knot of the load (where p may jump or kink): there the beat
    /// frequency of J(ξr)·p̄(ξ) vanishes and the integrands have a non-oscillating tail.
    fn at_load_edge(&self, r: f64) -> bool {
        self.load
            .knots()
            .iter()
            .any(|&k| (r - k).abs() <= 1e-3 * self.d)
    }

    /// Checks (r, z) and returns (r, |z| clamped to D, sign of z, whether on a face, and the
    /// quadrature parameters for the point: cautious at a load edge, whose integrand decays only
    /// algebraically).
    fn setup(&self, r: f64, z: f64, params: &QuadParams) -> (f64, f64, f64, bool, QuadParams) {
        let sign = if z < 0.0 { -1.0 } else { 1.0 };
        let (r, az) = (r.abs(), z.abs().min(self.d));
        let params = QuadParams {
            algebraic_tail: self.at_load_edge(r),
            ..*params
        };
        (r, az, sign, az >= self.d, params)
    }

    /// σ_r, σ_θ, σ_z, τ_rz at (r, z), |z| ≤ D (larger |z| is clamped to the face).
    pub fn stress(&self, r: f64, z: f64, params: &QuadParams) -> StressEstimate {
        let (r, az, sign, face, params) = self.setup(r, z, params);
        let nu = self.material.poisson_ratio();
        let tr = &self.transform;
        let mut s = stress_integrals(
            self.d,
            nu,
            |xi| tr.eval(xi),
            tr.outer(),
            r,
            az,
            sign,
            face,
            &params,
        );
        if face {
            let p = tr.pressure(r);
            let m = (1.0 - 2.0 * nu) * tr.moment_within_over_r2(r);
            s.sigma_z.value -= p;
            s.tau_rz.value = 0.0;
            s.sigma_r.value += -p + m;
            s.sigma_theta.value += -2.0 * nu * p - m;
        }
        s
    }

    /// σ_z at (r, z) with its error estimate.
    pub fn sigma_z(&self, r: f64, z: f64, params: &QuadParams) -> Estimate {
        if z == 0.0 {
            let (d, tr) = (self.d, &self.transform);
            let [e] = integrate_oscillatory_vec(
                |xi| [-xi * tr.eval(xi) * super::kernel::midplane(xi * d) * libm::j0(xi * r)],
                self.omega(r.abs()),
                1.0 / d,
                params,
            );
            return e;
        }
        self.stress(r, z, params).sigma_z
    }

    /// u and w at (r, z), |z| ≤ D.
    pub fn displacement(&self, r: f64, z: f64, params: &QuadParams) -> Displacement {
        let (r, az, sign, face, params) = self.setup(r, z, params);
        let nu = self.material.poisson_ratio();
        let tr = &self.transform;
        let g = self.material.shear_modulus();
        let mut out = displacement_integrals(
            self.d,
            nu,
            g,
            |xi| tr.eval(xi),
            tr.outer(),
            r,
            az,
            sign,
            face,
            &params,
        );
        if face {
            let c = -1.0 / (2.0 * g);
            // the slowly decaying half-space part of w, in real space (elliptic kernel)
            let w0 = tr.surface_integral(r, params.rel_tol.max(1e-15));
            out.w = out.w.plus(w0.scale(c * sign * 2.0 * (1.0 - nu)));
            out.u.value += c * (1.0 - 2.0 * nu) * r * tr.moment_within_over_r2(r);
        }
        out
    }
}

/// Stresses at an interior point (|z| < D) of the slab of half-thickness `d` and Poisson's
/// ratio `nu` under ANY axisymmetric load on both faces given by its transform `pbar`
/// (p̄(ξ) = ∫ p(ρ) J₀(ξρ) ρ dρ) whose oscillation frequency is at most `load_radius`: the
/// building block for ring loads ([`ring_load`]) and hole corrections. On a face (|z| = D)
/// the integrals do not decay and generally do not converge: use [`Slab`] there.
pub fn stress_for_transform<P: Fn(f64) -> f64>(
    d: f64,
    nu: f64,
    pbar: P,
    load_radius: f64,
    r: f64,
    z: f64,
    params: &QuadParams,
) -> StressEstimate {
    let sign = if z < 0.0 { -1.0 } else { 1.0 };
    let az = z.abs().min(d);
    stress_integrals(d, nu, pbar, load_radius, r.abs(), az, sign, false, params)
}

/// Displacements at an interior point for a load given by its transform (see
/// [`stress_for_transform`]); `g` is the shear modulus.
#[allow(clippy::too_many_arguments)]
pub fn displacement_for_transform<P: Fn(f64) -> f64>(
    d: f64,
    nu: f64,
    g: f64,
    pbar: P,
    load_radius: f64,
    r: f64,
    z: f64,
    params: &QuadParams,
) -> Displacement {
    let sign = if z < 0.0 { -1.0 } else { 1.0 };
    let az = z.abs().min(d);
    displacement_integrals(
        d,
        nu,
        g,
        pbar,
        load_radius,
        r.abs(),
        az,
        sign,
        false,
        params,
    )
}

/// Stress and displacement at an interior point (|z| < D) due to a ring load of unit intensity
/// (force per unit length of circumference, total force 2πρ₀ per face) at radius `rho0` on
/// both faces: p̄(ξ) = ρ₀ J₀(ξρ₀). Superposing rings over ρ₀ with weight p(ρ₀) gives the
/// face-load fields (checked in the tests).
pub fn ring_load(
    d: f64,
    material: Material,
    rho0: f64,
    r: f64,
    z: f64,
    params: &QuadParams,
) -> (StressEstimate, Displacement) {
    let nu = material.poisson_ratio();
    let pbar = |xi: f64| rho0 * libm::j0(xi * rho0);
    (
        stress_for_transform(d, nu, pbar, rho0, r, z, params),
        displacement_for_transform(d, nu, material.shear_modulus(), pbar, rho0, r, z, params),
    )
}

/// The stress integrals; on a face (`face`) with the face kernels' limits removed.
#[allow(clippy::too_many_arguments)]
fn stress_integrals<P: Fn(f64) -> f64>(
    d: f64,
    nu: f64,
    pbar: P,
    load_radius: f64,
    r: f64,
    az: f64,
    sign: f64,
    face: bool,
    params: &QuadParams,
) -> StressEstimate {
    let [iz, itau, ir, im, inn] = integrate_oscillatory_vec(
        |xi| {
            let k = if face {
                face_remainders(xi * d, nu)
            } else {
                Kernels::at(xi * d, xi * az, nu)
            };
            let x = xi * r;
            let (j0, j1) = (libm::j0(x), libm::j1(x));
            let q = xi * pbar(xi);
            [
                q * k.z * j0,
                q * k.tau * j1,
                q * k.r * j0,
                q * k.m * j1_over_x(x),
                q * k.n * j0,
            ]
        },
        r + load_radius,
        1.0 / d,
        &QuadParams {
            products: true,
            ..*params
        },
    );
    StressEstimate {
        sigma_r: ir.scale(-1.0).plus(im),
        sigma_theta: inn.scale(-1.0).plus(im.scale(-1.0)),
        sigma_z: iz.scale(-1.0),
        tau_rz: itau.scale(-sign),
    }
}

/// The displacement integrals (w = 0 on the midplane by symmetry).
#[allow(clippy::too_many_arguments)]
fn displacement_integrals<P: Fn(f64) -> f64>(
    d: f64,
    nu: f64,
    g: f64,
    pbar: P,
    load_radius: f64,
    r: f64,
    az: f64,
    sign: f64,
    face: bool,
    params: &QuadParams,
) -> Displacement {
    let [iu, iw] = integrate_oscillatory_vec(
        |xi| {
            let k = if face {
                face_remainders(xi * d, nu)
            } else {
                Kernels::at(xi * d, xi * az, nu)
            };
            let x = xi * r;
            let q = pbar(xi);
            [q * k.m * libm::j1(x), q * k.w * libm::j0(x)]
        },
        r + load_radius,
        1.0 / d,
        &QuadParams {
            products: true,
            ..*params
        },
    );
    let c = -1.0 / (2.0 * g);
    Displacement {
        u: iu.scale(c),
        w: if az == 0.0 {
            Estimate::default()
        } else {
            iw.scale(c * sign)
        },
    }
}
