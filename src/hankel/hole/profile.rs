//! The slab's traction on a cylinder r = R (the hole r = A, or the rim r = C) as a function of
//! the height: sampled once at a few Chebyshev heights, interpolated everywhere else.
//!
//! **Why it works.** The fictitious slab is loaded by p(r) continued smoothly into the hole
//! ([`super::plate::extended_load`]), so σ_r(R, z) and τ_rz(R, z) are real-analytic in z on
//! [−D, D], faces included: the field is singular only at the face points (k, ±D) where the
//! load has a knot k (a jump or a kink), and continued to complex z it is singular first at
//! z = ±D ± iδ, δ = min |k − R|. Chebyshev coefficients on [−D, D] therefore fall like ρ^(−k),
//! with ρ = |x + √(x² − 1)| at x = 1 + iδ/D (the Bernstein ellipse through the singularity):
//! ρ ≈ 4.8 for A/D = 1, B/A = 3.1 and ρ ≈ 1.48 for A/D = 0.5, B/A = 1.3 (δ/D = 0.15), the
//! narrowest of Table 1. σ_r is even and τ_rz odd in z, so only the upper half of the
//! Chebyshev–Lobatto grid z_j = D cos(πj/M), j = 0…M/2, is sampled; the face point z = D is
//! [`crate::hankel::Slab::stress`]'s analytic half-space route, the others share ξ-nodes in
//! batches ([`super::traction::hole_tractions`]). A height ζ below the face costs ~ζ^(−1/2)
//! nodes, and the grid's nearest interior point is ζ = D(1 − cos(π/M)) ≈ 5D/M²: M is kept as
//! small as the tolerance allows.
//!
//! **Choosing M.** M is predicted from ρ (the coefficients must fall from the load's scale S =
//! max|p| to the tolerance: M = 10 + ln(4S/(tol (1 − ρ⁻²)))/ln ρ, rounded up to a multiple of
//! 8, at least 16; the 10 covers the estimate's look-back over the last eight coefficients),
//! then checked on the computed coefficients; if the truncation part of the check fails M
//! doubles (the grids nest, so every sample is reused). A failed check costs ~2.5× a first
//! guess that passes (the new heights lie closer to the face), hence the generous prediction:
//! on Table 1 every first guess passed (M = 24–72).
//!
//! **Error estimate.** Interpolation error ≤ 2 Σ_{k>M} |c_k| (Chebyshev aliasing); with r the
//! observed decay per nonzero coefficient over the last eight (c_k of one parity vanish), the
//! tail is estimated as 2 c_tail · max(1, r/(1 − r)), c_tail the largest of the last four
//! nonzero coefficients (r capped at 0.95); coefficients at the samples' own error level are
//! noise and count once (2 c_tail). The samples' quadrature error enters amplified by the
//! Lebesgue constant of the grid, Λ_M ≤ 1 + (2/π) ln(M + 1). The tests check the estimate
//! against direct Hankel values at heights off the grid.
//!
//! Units: the load's pressure units; compression negative.
//!
//! # Accuracy
//!
//! The profile matches direct integrals off its grid; its coefficients fall at the predicted rate
//! of the nearest load edge; R_o through the profile equals the direct route
//! (`tests/hankel/hole_profile.rs`).
//!
//! # Cost
//!
//! ~30 % of a hole run, 1.1–3.0 ms on Table 1 (`cargo bench --bench hole`, the profile alone).
//!
//! ```
//! use boltzone::{FaceLoad, Material, hankel::{QuadParams, Slab}};
//! use boltzone::hankel::hole::profile::TractionProfile;
//! use boltzone::hankel::hole::traction::hole_tractions;
//! let slab = Slab::new(0.1, Material::unit(0.3)?, FaceLoad::uniform(0.0, 0.31, 1.0)?)?;
//! let p = TractionProfile::new(&slab, 0.1, 1e-8, &QuadParams::default());
//! assert!(p.error() <= 1e-8);
//! let q = QuadParams { rel_tol: 1e-13, abs_tol: 1e-13, ..QuadParams::default() };
//! let (direct, _) = hole_tractions(&slab, 0.1, &[0.0737], &q);
//! let (sr, tau) = p.eval(0.0737);
//! assert!((sr - direct[0].sigma_r).abs() <= p.error() && (tau - direct[0].tau_rz).abs() <= p.error());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::traction::{hole_tractions, HoleTraction};
use crate::hankel::field::Slab;
use crate::load::FaceLoad;
use crate::numerics::chebyshev::{clenshaw, lobatto_coefficients, lobatto_points};
use crate::numerics::quadrature::QuadParams;
use num_complex::Complex64;
use std::f64::consts::PI;

/// Largest M (intervals of the Chebyshev–Lobatto grid on [−D, D]) a profile may use.
pub const MAX_INTERVALS: usize = 512;

/// σ_r(R, z) and τ_rz(R, z) of a slab on |z| ≤ D by Chebyshev interpolation.
#[derive(Debug, Clone)]
pub struct TractionProfile {
    d: f64,
    /// Intervals M of the grid on [−D, D].
    m: usize,
    /// Samples at z_j = D cos(πj/M), j = 0…M/2.
    samples: Vec<HoleTraction>,
    /// Chebyshev coefficients of σ_r (odd ones zero) and τ_rz (even ones zero) in x = z/D.
    sigma: Vec<f64>,
    tau: Vec<f64>,
    error: f64,
    evaluations: usize,
    rho: f64,
}

/// ρ of the Bernstein ellipse of [−1, 1] through x = 1 + i·`gap` (∞ for an infinite gap).
fn bernstein_rho(gap: f64) -> f64 {
    if !gap.is_finite() {
        return f64::INFINITY;
    }
    let x = Complex64::new(1.0, gap);
    let w = (x * x - 1.0).sqrt();
    (x + w).norm().max((x - w).norm())
}

/// The distance from `r` to the nearest radius where `load` is not smooth (a jump or a change of
/// slope; the axis r = 0 excepted), or ∞.
fn singular_distance(load: &FaceLoad, r: f64) -> f64 {
    let (k, v) = (load.knots(), load.values());
    let n = k.len();
    let slope = |i: usize| (v[i + 1] - v[i]) / (k[i + 1] - k[i]);
    (0..n)
        .filter(|&i| {
            // the load is zero outside [k₀, k_{n−1}]: the ends are singular unless p and p′
            // vanish there (or the end is the axis)
            let left = if i == 0 {
                (0.0, 0.0)
            } else {
                (v[i], slope(i - 1))
            };
            let right = if i == n - 1 {
                (0.0, 0.0)
            } else {
                (v[i], slope(i))
            };
            let scale = v.iter().fold(0.0f64, |m, p| m.max(p.abs()));
            let kink = (left.1 - right.1).abs() * (k[n - 1] - k[0]);
            let jump = (left.0 - right.0).abs();
            !(i == 0 && k[0] == 0.0) && (kink + jump > 1e-12 * scale)
        })
        .map(|i| (k[i] - r).abs())
        .fold(f64::INFINITY, f64::min)
}

/// The Lebesgue constant bound of the (M + 1)-point Chebyshev–Lobatto grid.
fn lebesgue(m: usize) -> f64 {
    1.0 + 2.0 / PI * ((m + 1) as f64).ln()
}

impl TractionProfile {
    /// The profile of `slab`'s traction on r = `r` with an estimated error ≤ `tolerance`
    /// (absolute, pressure units) if M ≤ [`MAX_INTERVALS`] and the quadrature allow it (the
    /// estimate says what was reached). The samples are integrated with `quad`, whose absolute
    /// tolerance is set to a fifth of `tolerance` (the Lebesgue constant, 3–5, amplifies their
    /// error).
    pub fn new(slab: &Slab, r: f64, tolerance: f64, quad: &QuadParams) -> Self {
        let d = slab.half_thickness();
        let scale = slab
            .load()
            .values()
            .iter()
            .fold(0.0f64, |m, p| m.max(p.abs()))
            .max(f64::MIN_POSITIVE);
        let tolerance = tolerance.max(1e-15 * scale);
        let quad = QuadParams {
            abs_tol: 0.2 * tolerance,
            ..*quad
        };
        let rho = bernstein_rho(singular_distance(slab.load(), r) / d);
        let predicted = if rho > 1.0 + 1e-9 {
            let need = 10.0 + (4.0 * scale / (tolerance * (1.0 - rho.powi(-2)))).ln() / rho.ln();
            (8.0 * (need / 8.0).ceil()).clamp(16.0, MAX_INTERVALS as f64) as usize
        } else {
            MAX_INTERVALS
        };
        let mut p = Self {
            d,
            m: 0,
            samples: Vec::new(),
            sigma: Vec::new(),
            tau: Vec::new(),
            error: f64::INFINITY,
            evaluations: 0,
            rho,
        };
        let mut m = predicted;
        loop {
            p.sample(slab, r, m, &quad);
            p.coefficients();
            let (truncation, noise) = p.estimate();
            p.error = truncation + noise;
            // Doubling M only helps the truncation; when the samples' own error dominates
            // (heights next to the face integrated at a tolerance the quadrature cannot
            // confirm), a finer grid only adds noisier samples: stop and report it.
            if p.error <= tolerance || truncation <= 0.5 * tolerance || 2 * m > MAX_INTERVALS {
                return p;
            }
            m *= 2;
        }
    }

    /// Samples the grid of M = `m` intervals, reusing the samples of the current grid (m must
    /// be a multiple of the current M).
    fn sample(&mut self, slab: &Slab, r: f64, m: usize, quad: &QuadParams) {
        let step = m.checked_div(self.m).unwrap_or(0);
        let z: Vec<f64> = lobatto_points(m)[..=m / 2]
            .iter()
            .map(|x| self.d * x)
            .collect();
        let fresh: Vec<usize> = (0..=m / 2).filter(|j| step == 0 || j % step != 0).collect();
        let zf: Vec<f64> = fresh.iter().map(|&j| z[j]).collect();
        let (values, evaluations) = hole_tractions(slab, r, &zf, quad);
        self.evaluations += evaluations;
        let mut old = std::mem::take(&mut self.samples).into_iter();
        let mut new = values.into_iter();
        self.samples = (0..=m / 2)
            .map(|j| {
                if step != 0 && j % step == 0 {
                    old.next().expect("nested grid")
                } else {
                    new.next().expect("one value per fresh height")
                }
            })
            .collect();
        self.m = m;
    }

    /// Chebyshev coefficients from the samples, the lower half of the grid by symmetry
    /// (σ_r even, τ_rz odd); the coefficients of the other parity vanish exactly.
    fn coefficients(&mut self) {
        let m = self.m;
        let full = |odd: bool| -> Vec<f64> {
            (0..=m)
                .map(|j| {
                    let (h, sign) = if j <= m / 2 { (j, 1.0) } else { (m - j, -1.0) };
                    let s = &self.samples[h];
                    if odd {
                        sign * s.tau_rz
                    } else {
                        s.sigma_r
                    }
                })
                .collect()
        };
        let parity = |mut c: Vec<f64>, odd: bool| {
            for (k, ck) in c.iter_mut().enumerate() {
                if (k % 2 == 1) != odd {
                    *ck = 0.0;
                }
            }
            c
        };
        self.sigma = parity(lobatto_coefficients(&full(false)), false);
        self.tau = parity(lobatto_coefficients(&full(true)), true);
    }

    /// The error estimate of the module docs.
    /// (truncation, samples' error × Lebesgue constant).
    fn estimate(&self) -> (f64, f64) {
        let noise = self.samples.iter().map(|s| s.error).fold(0.0, f64::max);
        let tail = |c: &[f64], odd: bool| {
            // nonzero coefficients, highest first
            let nz: Vec<f64> = (0..=self.m)
                .rev()
                .filter(|k| (k % 2 == 1) == odd)
                .map(|k| c[k].abs())
                .collect();
            let last = nz[..4].iter().copied().fold(0.0, f64::max);
            let before = nz[4..8].iter().copied().fold(0.0, f64::max);
            if last <= 2.0 * noise {
                return 2.0 * last;
            }
            let r = (last / before.max(f64::MIN_POSITIVE)).powf(0.25).min(0.95);
            2.0 * last * (r / (1.0 - r)).max(1.0)
        };
        (
            tail(&self.sigma, false).max(tail(&self.tau, true)),
            lebesgue(self.m) * noise,
        )
    }

    /// (σ_r(R, z), τ_rz(R, z)) for |z| ≤ D (Clenshaw's recurrence in x = z/D).
    pub fn eval(&self, z: f64) -> (f64, f64) {
        let x = (z / self.d).clamp(-1.0, 1.0);
        (clenshaw(&self.sigma, x), clenshaw(&self.tau, x))
    }

    /// Estimated largest error of [`Self::eval`] (absolute).
    pub fn error(&self) -> f64 {
        self.error
    }

    /// ξ-nodes spent on the samples.
    pub fn evaluations(&self) -> usize {
        self.evaluations
    }

    /// Intervals M of the Chebyshev–Lobatto grid on [−D, D] (M/2 + 1 heights sampled).
    pub fn intervals(&self) -> usize {
        self.m
    }

    /// ρ of the Bernstein ellipse predicted from the load's knots (∞: no singularity).
    pub fn rho(&self) -> f64 {
        self.rho
    }

    /// The Chebyshev coefficients of σ_r and τ_rz in x = z/D (k = 0…M).
    pub fn coefficients_of(&self) -> (&[f64], &[f64]) {
        (&self.sigma, &self.tau)
    }
}
