//! The two-plate model with a finite rim r = C, semi-analytically, for a plate without a hole:
//! the receding contact of [`super::contact`] with each plate ending at a free edge C, as the
//! FE two-plate model meshes it. The holed route ([`super::holed`]) takes the same rim terms
//! once its crack field accepts the displacement right-hand side used here (not done yet).
//!
//! **Problem** (report Ch. II.B; compression positive in p and q, w upward, lengths in the
//! units of D). One plate 0 ≤ r ≤ C, 0 ≤ z ≤ D on a frictionless rigid plane, pressed by p on
//! its top face, in contact on r ≤ R_o, free beyond and on r = C. R_o where the contact
//! pressure ends like √(R_o − r).
//!
//! **Method.** For a trial contact radius c the finite plate is, up to a self-equilibrated
//! traction on r = C that decays inwards (below),
//!
//! S_∞ + β (E + S₂) + ε M,
//!
//! - S_∞: the infinite plate in contact on r ≤ c ([`super::contact`]'s Nyström solve); its
//!   far field at C is log bending, moment M_∞(C), and the membrane force N_∞(C)
//!   ([`super::rim_bending`]: both from the face tractions by reciprocity, exact);
//! - E: the uniform bending state of unit curvature (free faces; [`RimStates`] with A = 0),
//!   whose plane displacement −r²/2 breaks the contact condition;
//! - S₂: the infinite plate with no load, its bottom prescribed to w = r²/2 (+ a rigid
//!   translation) on r ≤ c and free beyond, zero net force: the same Fredholm equation with
//!   the Abel-inverted displacement F(t) = (2G/(π(1−ν)))t² on its right-hand side
//!   (A\[F\] = (G/(1−ν)) r²/2), solved as φ₂ = F + ψ with ψ smooth (module `prescribed`);
//!   its far-field moment M₂(C) by reciprocity;
//! - M: the membrane state, which cancels N_∞(C) and touches neither the plane nor R_o.
//!
//! β = −M_∞(C)/(M_E(C) + M₂(C)) frees the rim of its moment; the shear resultant is zero by
//! equilibrium (C beyond B and c). R_o is the root in c of φ_∞(c) + β(c)φ₂(c), found by the
//! receding solver's scan and Brent's method.
//!
//! **What is left at C** is self-equilibrated (no force, no moment) and decays inwards through
//! the free layer's Papkovich–Fadle modes, the slowest like e^(−4.21(C − r)/D) (symmetric
//! family, sin 2x + 2x = 0, 2x ≈ 4.212 + 2.251i for thickness D). It is not solved for: the
//! record's `decay_bound` is D·e^(−4.21(C − R_o)/D), an order of magnitude (residual traction
//! of order P times one decay over C − R_o; its constant is not verified), added to R_o's
//! estimate.
//!
//! # Accuracy
//!
//! `tests/hankel/two_plate_rim_hankel.rs`, disk load B = D, ν = 0.3: R_o(C) − R_o(∞) =
//! −1.505e-3, −3.781e-4, −9.464e-5 D at C = 8, 16, 32 R_o(∞) (rates 1.993, 1.998:
//! `rim_converges_like_c_to_the_minus_two`); the FE two-plate model meshed to C (sharing no
//! code) at its default tolerance within its bar (`agrees_with_the_fe_meshed_to_the_rim`), and
//! at --tol 1e-5 within 1.3e-6 D (C = 8 R_o) and 1.1e-6 D (16 R_o) of this route, where the
//! rim moves R_o by 1.5e-3 and 3.8e-4 D (`agrees_with_the_fe_at_tight_tolerances`, ignored);
//! the contact force against the load to 3e-16; the estimate (1.4e-9 D) against a run with
//! twice the points (change 6.8e-12 D).
//!
//! # Cost
//!
//! Two Nyström solves per trial radius (S_∞ and S₂ share the ξ-rule), twice the receding
//! solver's: 0.12–0.14 s per R_o with its estimate (B = D, 18 trial radii), timed by the test
//! `rim_converges_like_c_to_the_minus_two`.
//!
//! ```
//! use boltzone::{FaceLoad, Material};
//! use boltzone::hankel::receding::RecedingParams;
//! use boltzone::hankel::receding::rim::rim_contact;
//! let load = FaceLoad::uniform(0.0, 1.0, 1.0)?;
//! let (out, _) = rim_contact(1.0, Material::unit(0.3)?, &load, 12.0, &RecedingParams::default(), 1e-6, &[])?;
//! assert!(out.converged && out.r_o > 1.0 && out.curvature != 0.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::contact::{nodes, RecedingError, RecedingParams};
use super::prescribed::Prescribed;
use super::rim_bending::RimStates;
use super::search::{root, Scan};
use super::system::{integrate, Nystrom, XiRule};
use crate::error::{positive, InputError};
use crate::hankel::transform::LoadTransform;
use crate::load::FaceLoad;
use crate::material::Material;
use std::f64::consts::PI;
use std::time::Instant;

/// The slowest decay of the free layer's self-equilibrated modes, Re(2x) of the first root of
/// sin 2x + 2x = 0 (thickness D: e^(−4.212 r/D)).
pub const PAPKOVICH_DECAY: f64 = 4.2120;

/// Cost and accuracy of [`rim_contact`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct RimInfo {
    /// Estimated absolute error of R_o: the change from ⌈3n/4⌉ points, the root tolerance
    /// and `decay_bound`.
    pub r_o_error: f64,
    /// R_o with ⌈3n/4⌉ Nyström points.
    pub r_o_coarse: f64,
    /// D·e^(−4.21(C − R_o)/D): the order of the rim's self-equilibrated residue's effect.
    pub decay_bound: f64,
    /// Nyström points n.
    pub nodes: usize,
    /// Trial radii solved (two Nyström systems each).
    pub solves: usize,
    /// Wall-clock seconds.
    pub seconds: f64,
}

/// R_o of the finite plate and the rim terms at R_o.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct RimContact {
    /// The contact radius R_o.
    pub r_o: f64,
    /// β: the curvature of the rim's bending state E (1/length, in the load's units over G).
    pub curvature: f64,
    /// M_r(C) of the infinite plate's far field (force·length per length), cancelled by β.
    pub rim_moment: f64,
    /// N_r(C) of the infinite plate's far field (force per length), cancelled by the
    /// membrane state.
    pub rim_force: f64,
    /// Whether `info.r_o_error` ≤ the tolerance asked for, relative to R_o.
    pub converged: bool,
    /// Error estimate and cost.
    pub info: RimInfo,
}

/// One trial radius: the scaled edge coefficient and the rim terms.
struct Trial {
    edge: f64,
    beta: f64,
    moment: f64,
    /// S_∞ and ψ of S₂ (for the pressure).
    systems: (Nystrom, Nystrom),
}

/// The finite-rim problem of one plate (module docs).
struct Rim {
    d: f64,
    c_outer: f64,
    states: RimStates,
    /// S₂'s lift r²/2 as the Abel function F(t) = γt².
    lift: Prescribed,
    transform: LoadTransform,
    /// p̄(0) = ∫p r dr and ∫p r³ dr.
    p0: f64,
    p_second: f64,
    quad_tol: f64,
}

impl Rim {
    fn trial(&self, c: f64, n: usize) -> Result<Trial, RecedingError> {
        let omega = 3.0 * c + self.transform.outer();
        let rule = XiRule::new(self.d, &self.transform, omega, self.quad_tol);
        let (xi, a, b) = rule.nodes();
        let f = self.lift.transforms(xi, c);
        let alpha: Vec<f64> = a.iter().zip(&f).map(|(a, f)| -a * f.0).collect();
        let beta: Vec<f64> = b.iter().zip(&f).map(|(b, f)| -b * f.1).collect();
        let singular = RecedingError::Singular { c };
        let f_total = self.lift.integral(c);
        let s2 = Nystrom::solve_general(rule.clone(), c, n, -f_total, &alpha, &beta)
            .ok_or(singular.clone())?;
        let s_inf = Nystrom::solve(rule, c, n, self.p0).ok_or(singular)?;
        // ∫q r³ dr = 2∫₀^c φ t² dt (the t²-terms of q̄ = ∫φ cos ξt dt against J₀(ξr))
        let second = |sys: &Nystrom| 2.0 * integrate(0.0, c, 0.5 * self.d, |t| sys.phi(t) * t * t);
        let k_inf = self
            .states
            .far_field_log(second(&s_inf) - self.p_second, 0.0);
        let k2 = self
            .states
            .far_field_log(second(&s2) + 2.0 * self.lift.moment_t2(c), 0.0);
        let moment = self.states.log_moment(k_inf, self.c_outer);
        let m_t =
            self.states.bending_moment(self.c_outer) + self.states.log_moment(k2, self.c_outer);
        let beta = -moment / m_t;
        let phi2 = self.lift.value(c) + s2.phi(c);
        let edge = c * (s_inf.phi(c) + beta * phi2) / self.p0;
        Ok(Trial {
            edge,
            beta,
            moment,
            systems: (s_inf, s2),
        })
    }

    /// The contact pressure q(r) ≥ 0 of `trial` (at contact radius c): q_∞ + β(q_F + q_ψ),
    /// q_F the pressure of F (module `prescribed`); zero for r ≥ c.
    fn pressure(&self, trial: &Trial, r: f64) -> f64 {
        let (s_inf, s2) = &trial.systems;
        let c = s_inf.radius();
        if r >= c {
            return 0.0;
        }
        let q_f = self.lift.pressure(r, c);
        s_inf.pressure(r, self.d) + trial.beta * (q_f + s2.pressure(r, self.d))
    }
}

/// R_o of two equal plates without a hole, each `d` thick and ending at a free rim
/// `c_outer`, of `material`, pressed by `load` (module docs); `converged` when the estimate
/// is within `tolerance`·R_o; and the contact pressure q(r) ≥ 0 (compression positive, the
/// load's units) at each radius of `at` (0 ≤ r; zero beyond R_o): pairs (r, q).
pub fn rim_contact(
    d: f64,
    material: Material,
    load: &FaceLoad,
    c_outer: f64,
    params: &RecedingParams,
    tolerance: f64,
    at: &[f64],
) -> Result<(RimContact, Vec<(f64, f64)>), RecedingError> {
    if let Some(&r) = at.iter().find(|r| !(r.is_finite() && **r >= 0.0)) {
        return Err(InputError::Parameter {
            field: "pressure radius",
            value: r,
            reason: "finite and at least 0",
        }
        .into());
    }
    let start = Instant::now();
    positive("plate thickness D", d)?;
    positive("tolerance", tolerance)?;
    let b = load.outer();
    if !(c_outer.is_finite() && c_outer > b + d) {
        return Err(InputError::Parameter {
            field: "outer radius C",
            value: c_outer,
            reason: "finite and beyond the load's outer radius B by more than D",
        }
        .into());
    }
    let transform = LoadTransform::new(load);
    let p_second = load
        .segments()
        .map(|s| {
            // p linear times r³: 3-point Gauss–Legendre is exact (degree 4 ≤ 5)
            crate::numerics::quadrature::gauss_legendre(3)
                .iter()
                .map(|&(x, w)| {
                    let r = 0.5 * (s.r0 + s.r1) + 0.5 * (s.r1 - s.r0) * x;
                    0.5 * (s.r1 - s.r0) * w * s.at(r) * r.powi(3)
                })
                .sum::<f64>()
        })
        .sum();
    let rim = Rim {
        d,
        c_outer,
        states: RimStates::new(0.0, d, material)?,
        lift: Prescribed::new(material.shear_modulus(), material.poisson_ratio(), 0.0),
        p0: transform.eval(0.0),
        transform,
        p_second,
        quad_tol: params.quad_tol,
    };
    let n = nodes(params, b / d + 2.0)?;
    let coarse_n = (3 * n).div_ceil(4).max(4);
    let scan = Scan {
        b,
        d,
        step: params.step * d,
        end: (b + params.reach * d).min(c_outer),
        tol: params.rel_tol * d,
        max_iterations: params.max_iterations,
    };
    let not_found = RecedingError::NotFound {
        from: b,
        to: scan.end,
    };
    let mut solves = 0;
    let mut root_with = |n: usize, near: Option<f64>| {
        let mut edge = |c: f64| {
            solves += 1;
            rim.trial(c, n).map(|t| t.edge)
        };
        root(&mut edge, &scan, near)?.ok_or_else(|| not_found.clone())
    };
    let r_o = root_with(n, None)?;
    let coarse = root_with(coarse_n, Some(r_o))?;
    let last = rim.trial(r_o, n)?;
    let decay_bound = d * (-PAPKOVICH_DECAY * (c_outer - r_o) / d).exp();
    let r_o_error = (r_o - coarse).abs() + params.rel_tol * d + decay_bound;
    let curve = at.iter().map(|&r| (r, rim.pressure(&last, r))).collect();
    let out = RimContact {
        r_o,
        curvature: last.beta,
        rim_moment: last.moment,
        rim_force: rim.states.far_field_force(2.0 * PI * rim.p0, c_outer),
        converged: r_o_error <= tolerance * r_o,
        info: RimInfo {
            r_o_error,
            r_o_coarse: coarse,
            decay_bound,
            nodes: n,
            solves: solves + 1,
            seconds: start.elapsed().as_secs_f64(),
        },
    };
    Ok((out, curve))
}
