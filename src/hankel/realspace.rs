//! The midplane stress of thin slabs in real space: σ_z(r, 0) = −∬ p(|y|) g(|x − y|/D)/D² dA.
//!
//! A point force F on each face of the slab gives σ_z = −F g(R/D)/D² on the midplane at
//! distance R, with the universal function (the Hankel inverse of the midplane kernel K of
//! [`super::kernel`])
//!
//! g(x) = (1/2π) ∫₀^∞ t K(t) J₀(tx) dt,  g(0) ≈ 0.8225, ∬ g dA = K(0) = 1,
//!
//! which is real-analytic in x (|Im x| < 1, K decays like e^(−t)), has its first zero at
//! x ≈ 1.55 and decays like e^(−2.1x) (the Papkovich–Fadle root t ≈ 2.106 + 1.125i of
//! sinh 2t + 2t = 0): |g(x)| < 1e-17 beyond x = X = 18. Superposing over the load,
//!
//! σ_z(r, 0) = −(2/D²) ∫ p(ρ) ρ ∫₀^{θ_max} g(d/D) dθ dρ, d² = (r − ρ)² + 4rρ sin²(θ/2),
//!
//! over the part of the load within X·D of r. Only a disk of radius 18D around the point
//! matters, so the cost does not grow with B/D or r/D: this is the route for thin slabs, where
//! the ξ-quadrature would need ~(r + B)/D oscillations ([`super::midplane::MidplaneRule`]
//! refuses those). g is tabulated once per process (piecewise Chebyshev, panels of 0.5,
//! 20 points; values from a shared ξ-rule, ≈ 50 ms); the double integral uses 20-point
//! Gauss–Legendre panels no wider than 1.5D in ρ and in the arc length √(rρ)θ (g is analytic
//! in a strip of half-width D, so the rule's error is far below the table's).
//!
//! # Accuracy
//!
//! The point kernel against mpmath (`tests/hankel/separation.rs`, `point_kernel_matches_mpmath`);
//! the real-space and ξ routes agree to ~1e-15 where both run (`real_space_and_xi_routes_agree`);
//! thin slabs reach the strip limit (`thin_slabs_switch_to_real_space_and_reach_the_strip_limit`).
//!
//! # Cost
//!
//! Independent of B/D and r/D (example 01's extremes of the range).
//!
//! ```
//! use boltzone::hankel::realspace::point_kernel;
//! // g(0) = 0.82252072483078143… (mpmath)
//! assert!((point_kernel(0.0) - 0.822_520_724_830_781_4).abs() < 1e-13);
//! ```

use super::kernel::midplane;
use super::transform::LoadTransform;
use crate::numerics::quadrature::{gauss_legendre, Estimate};
use std::f64::consts::PI;
use std::sync::OnceLock;

/// Beyond x = X·D the point kernel is below 1e-17 and is dropped.
pub const X: f64 = 18.0;
const PANEL: f64 = 0.5;
const CHEB: usize = 20;

struct Table {
    coef: Vec<[f64; CHEB]>,
    error: f64,
}

fn table() -> &'static Table {
    static T: OnceLock<Table> = OnceLock::new();
    T.get_or_init(|| {
        // shared ξ-rule for ∫ t K(t) J0(tx) dt / 2π, x ≤ X: truncation at t = 48 leaves
        // 2.5 e^(−48)(48² + 3·48 + 3)/2π ≈ 1.3e-18; panels of 5 half-periods of X, ≤ 1.5
        let t_max = 48.0;
        let width = (5.0 * PI / X).min(1.5);
        let panels = (t_max / width).ceil() as usize;
        let h = t_max / panels as f64;
        let rule = gauss_legendre(20);
        let mut nodes = Vec::with_capacity(panels * 20);
        for k in 0..panels {
            for &(x, w) in rule.iter() {
                let t = (k as f64 + 0.5 + 0.5 * x) * h;
                nodes.push((t, 0.5 * h * w * t * midplane(t) / (2.0 * PI)));
            }
        }
        let abs: f64 = nodes.iter().map(|n| n.1.abs()).sum();
        let g = |x: f64| nodes.iter().map(|&(t, c)| c * libm::j0(t * x)).sum::<f64>();
        let n = (X / PANEL).round() as usize;
        let mut coef = Vec::with_capacity(n);
        let mut tail: f64 = 0.0;
        for k in 0..n {
            let (a, b) = (k as f64 * PANEL, (k + 1) as f64 * PANEL);
            let vals: Vec<f64> = (0..CHEB)
                .map(|j| {
                    g(0.5 * (a + b) + 0.5 * (b - a) * (PI * (j as f64 + 0.5) / CHEB as f64).cos())
                })
                .collect();
            let mut c = [0.0; CHEB];
            for (m, cm) in c.iter_mut().enumerate() {
                *cm = 2.0 / CHEB as f64
                    * (0..CHEB)
                        .map(|j| vals[j] * (PI * m as f64 * (j as f64 + 0.5) / CHEB as f64).cos())
                        .sum::<f64>();
            }
            c[0] *= 0.5;
            tail = tail.max(c[CHEB - 3..].iter().map(|v| v.abs()).sum());
            coef.push(c);
        }
        Table {
            coef,
            error: 1.3e-18 + 50.0 * f64::EPSILON * abs + 2.0 * tail,
        }
    })
}

/// The midplane point kernel g(x) (x = R/D), zero beyond [`X`].
pub fn point_kernel(x: f64) -> f64 {
    let x = x.abs();
    if x >= X {
        return 0.0;
    }
    let t = table();
    let k = ((x / PANEL) as usize).min(t.coef.len() - 1);
    let u = (2.0 * x - (2 * k + 1) as f64 * PANEL) / PANEL;
    let c = &t.coef[k];
    let (mut b1, mut b2) = (0.0, 0.0);
    for &cm in c.iter().skip(1).rev() {
        let b0 = 2.0 * u * b1 - b2 + cm;
        b2 = b1;
        b1 = b0;
    }
    u * b1 - b2 + c[0]
}

/// Absolute error estimate of [`point_kernel`] (truncation, rounding, interpolation).
pub fn point_kernel_error() -> f64 {
    table().error
}

/// σ_z(r, 0) of the slab of half-thickness `d` under the load `tr`, by the real-space route.
pub fn midplane_sigma_z(tr: &LoadTransform, d: f64, r: f64) -> Estimate {
    let rule = gauss_legendre(20);
    let r = r.abs();
    let reach = X * d;
    let (mut sum, mut abs, mut area) = (0.0, 0.0, 0.0);
    let mut evaluations = 0;
    for s in tr.segments() {
        let (lo, hi) = (s.r0.max(r - reach), s.r1.min(r + reach));
        if hi <= lo {
            continue;
        }
        let n_rho = ((hi - lo) / (1.5 * d)).ceil().max(1.0) as usize;
        let h_rho = (hi - lo) / n_rho as f64;
        for i in 0..n_rho {
            for &(xr, wr) in rule.iter() {
                let rho = lo + (i as f64 + 0.5 + 0.5 * xr) * h_rho;
                let w_rho = 0.5 * h_rho * wr * s.at(rho) * rho;
                // θ range: d(θ) ≤ X·D
                let rr = 4.0 * r * rho;
                let gap = (r - rho) * (r - rho);
                let theta_max = if rr <= 0.0 || reach * reach - gap >= rr {
                    PI
                } else {
                    2.0 * ((reach * reach - gap).max(0.0) / rr).sqrt().min(1.0).asin()
                };
                let n_t = (theta_max * (r * rho).sqrt() / (1.5 * d)).ceil().max(1.0) as usize;
                let h_t = theta_max / n_t as f64;
                let mut ring = 0.0;
                for j in 0..n_t {
                    for &(xt, wt) in rule.iter() {
                        let th = (j as f64 + 0.5 + 0.5 * xt) * h_t;
                        let sn = (0.5 * th).sin();
                        let dist = (gap + rr * sn * sn).sqrt();
                        ring += 0.5 * h_t * wt * point_kernel(dist / d);
                    }
                }
                evaluations += n_t * rule.len();
                sum += w_rho * ring;
                abs += (w_rho * ring).abs();
                area += w_rho.abs() * theta_max;
            }
        }
    }
    let f = 2.0 / (d * d);
    Estimate {
        value: -f * sum,
        error: f * (area * point_kernel_error() + 50.0 * f64::EPSILON * abs),
        evaluations,
    }
}
