//! The Hankel transform p̄(ξ) = ∫ p(r) J₀(ξr) r dr of a piecewise-linear load in closed form,
//! at a cost independent of ξ.
//!
//! On a piece p = α + βr, r₀ ≤ r ≤ r₁, with u = ξr:
//!
//! ∫ (αr + βr²) J₀(ξr) dr = α [u J₁(u)]/ξ² + β [G(u)]/ξ³,  G(u) = ∫₀^u t² J₀(t) dt
//! = u² J₁(u) + u J₀(u) − F(u),  F(u) = ∫₀^u J₀(t) dt
//!
//! (from (uJ₁)′ = uJ₀ and (u²J₁)′ = u²J₀ + uJ₁, (uJ₀)′ = J₀ − uJ₁). F comes from a table of
//! piecewise Chebyshev interpolants on [0, 40] (panels of 2, 24 points, values by 20-point
//! Gauss–Legendre, built once per process) and beyond from DLMF 10.22.2 with the Wronskian:
//! F(x) = 1 + xJ₀ + (πx/2)(J₁M₀ − J₀M₁), M_ν = H_ν − Y_ν the Struve–Neumann difference with its
//! asymptotic series (DLMF 11.6.1), M₀ ~ π⁻² Σ(−1)^k Γ(k+½)²(2/x)^(2k+1),
//! M₁ ~ π⁻² Σ(−1)^k Γ(k+½)²(2/x)^(2k)/(½ − k), whose smallest term at x = 40 is ~e^(−40). G uses
//! its power series for u < 2, where the closed form would cancel.
//!
//! [`crate::hankel::transform`] integrates sloped pieces by Gauss–Legendre over every
//! half-period of J₀(ξr), O(ξ) work per ξ: near a face the hole tractions need ξ up to ~10⁴/D,
//! where that costs ~200 µs per node; this costs ~0.3 µs. For a continuous load the boundary
//! terms of adjacent pieces cancel to the transform's size O(ξ^(−5/2)), losing about
//! log₁₀(ξ·r) digits of the terms' size.
//!
//! ```
//! use boltzone::{FaceLoad, Peak};
//! use boltzone::hankel::hole::linear_transform::{int_j0, LinearTransform};
//! assert!((int_j0(1.0) - 0.919_730_410_089_760_2).abs() < 1e-15);
//! let load = FaceLoad::triangular(0.1, 0.31, 1.0, Peak::AtA).unwrap();
//! let fast = LinearTransform::new(&load);
//! let slow = boltzone::hankel::transform::LoadTransform::new(&load);
//! assert!((fast.eval(37.0) - slow.eval(37.0)).abs() < 1e-15);
//! ```

use crate::hankel::quadrature::gauss_legendre;
use crate::load::FaceLoad;
use std::f64::consts::PI;
use std::sync::OnceLock;

const TABLE_END: f64 = 40.0;
const PANEL: f64 = 2.0;
const CHEB: usize = 24;

/// Chebyshev points (second kind) on [−1, 1], their barycentric weights, and F at the mapped
/// points of every panel.
struct Table {
    t: [f64; CHEB],
    w: [f64; CHEB],
    f: Vec<[f64; CHEB]>,
}

fn table() -> &'static Table {
    static TABLE: OnceLock<Table> = OnceLock::new();
    TABLE.get_or_init(|| {
        let n = CHEB - 1;
        let t: [f64; CHEB] = std::array::from_fn(|j| (PI * j as f64 / n as f64).cos());
        let w: [f64; CHEB] = std::array::from_fn(|j| {
            let s = if j % 2 == 0 { 1.0 } else { -1.0 };
            if j == 0 || j == n {
                0.5 * s
            } else {
                s
            }
        });
        let rule = gauss_legendre(20);
        // ∫ₐᵇ J₀ by 20-point Gauss–Legendre (b − a ≤ 2: error far below ε)
        let gl = |a: f64, b: f64| -> f64 {
            let (m, h) = (0.5 * (a + b), 0.5 * (b - a));
            rule.iter()
                .map(|(x, wt)| wt * libm::j0(m + h * x))
                .sum::<f64>()
                * h
        };
        let panels = (TABLE_END / PANEL) as usize;
        let mut f = Vec::with_capacity(panels);
        let mut start = 0.0; // F at the panel's left end
        for p in 0..panels {
            let a = p as f64 * PANEL;
            let vals: [f64; CHEB] = std::array::from_fn(|j| {
                let x = a + 0.5 * PANEL * (1.0 - t[j]);
                start + gl(a, x)
            });
            start += gl(a, a + PANEL);
            f.push(vals);
        }
        Table { t, w, f }
    })
}

/// F(x) = ∫₀^x J₀(t) dt for x ≥ 0 (odd in x).
pub fn int_j0(x: f64) -> f64 {
    if x < 0.0 {
        return -int_j0(-x);
    }
    if x < TABLE_END {
        let tab = table();
        let p = ((x / PANEL) as usize).min(tab.f.len() - 1);
        let a = p as f64 * PANEL;
        let s = 1.0 - 2.0 * (x - a) / PANEL; // the panel's Chebyshev variable (t₀ = 1 ↔ a)
        let (mut num, mut den) = (0.0, 0.0);
        for j in 0..CHEB {
            let d = s - tab.t[j];
            if d == 0.0 {
                return tab.f[p][j];
            }
            let c = tab.w[j] / d;
            num += c * tab.f[p][j];
            den += c;
        }
        return num / den;
    }
    let (j0, j1) = (libm::j0(x), libm::j1(x));
    let q = 2.0 / x;
    let (mut m0, mut m1) = (0.0, 0.0);
    let mut g = PI; // Γ(k + ½)²
    let mut qk = 1.0; // (2/x)^(2k)
    let mut last = f64::INFINITY;
    for k in 0..60 {
        let kf = k as f64;
        if k > 0 {
            g *= (kf - 0.5) * (kf - 0.5);
            qk *= q * q;
        }
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        let t0 = sign * g * qk * q;
        let t1 = sign * g * qk / (0.5 - kf);
        if t1.abs() > last {
            break;
        }
        last = t1.abs();
        m0 += t0;
        m1 += t1;
        if t1.abs() < 1e-18 {
            break;
        }
    }
    m0 /= PI * PI;
    m1 /= PI * PI;
    1.0 + x * j0 + 0.5 * PI * x * (j1 * m0 - j0 * m1)
}

/// G(u) = ∫₀^u t² J₀(t) dt.
fn int_t2_j0(u: f64) -> f64 {
    if u < 2.0 {
        // Σ (−1)^k u^(2k+3) / ((2k+3) 4^k (k!)²): terms fall by u²/4k² < 1/k²
        let (mut term, mut sum) = (u * u * u, 0.0);
        for k in 0..40 {
            let kf = k as f64;
            if k > 0 {
                term *= -u * u / (4.0 * kf * kf);
            }
            sum += term / (2.0 * kf + 3.0);
            if term.abs() < 1e-18 * sum.abs() {
                break;
            }
        }
        return sum;
    }
    u * u * libm::j1(u) + u * libm::j0(u) - int_j0(u)
}

/// p̄(ξ) of a piecewise-linear load, each piece as (r₀, r₁, α, β) with p = α + βr.
#[derive(Debug, Clone, PartialEq)]
pub struct LinearTransform {
    pieces: Vec<(f64, f64, f64, f64)>,
}

impl LinearTransform {
    /// The transform of `load`.
    pub fn new(load: &FaceLoad) -> Self {
        let pieces = load
            .segments()
            .map(|s| {
                let beta = (s.p1 - s.p0) / (s.r1 - s.r0);
                (s.r0, s.r1, s.p0 - beta * s.r0, beta)
            })
            .collect();
        Self { pieces }
    }

    /// p̄(ξ) for ξ ≥ 0.
    pub fn eval(&self, xi: f64) -> f64 {
        if xi <= 0.0 {
            return self
                .pieces
                .iter()
                .map(|&(r0, r1, al, be)| {
                    al * (r1 * r1 - r0 * r0) / 2.0 + be * (r1 * r1 * r1 - r0 * r0 * r0) / 3.0
                })
                .sum();
        }
        let (x2, x3) = (xi * xi, xi * xi * xi);
        self.pieces
            .iter()
            .map(|&(r0, r1, al, be)| {
                let (u0, u1) = (xi * r0, xi * r1);
                let mut v = al * (u1 * libm::j1(u1) - u0 * libm::j1(u0)) / x2;
                if be != 0.0 {
                    v += be * (int_t2_j0(u1) - int_t2_j0(u0)) / x3;
                }
                v
            })
            .sum()
    }
}
