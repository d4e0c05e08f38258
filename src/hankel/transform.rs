//! The zeroth-order Hankel transform of a face load, p̄(ξ) = ∫₀^∞ p(r) J₀(ξr) r dr.
//!
//! p(r) is piecewise linear on knots A = r₀ < … < rₙ = B (see [`crate::load`]). A constant piece
//! P on [r₀, r₁] has the closed form P[r₁J₁(ξr₁) − r₀J₁(ξr₀)]/ξ (from d(xJ₁)/dx = xJ₀), so the
//! uniform annulus gives P[B J₁(ξB) − A J₁(ξA)]/ξ. A sloped piece needs ∫x²J₀ = x²J₁ + xJ₀ −
//! Ji₀ with Ji₀(x) = ∫₀^x J₀ ([`crate::numerics::integral_j0`]: series, a Chebyshev table, or its asymptotic expansion), so
//! every p̄(ξ) costs O(1) Bessel calls whatever ξ (small ξ: one Gauss rule on the piece). The transform is built once per slab and
//! shared by every evaluation point. Units: pressure × length².
//!
//! # Accuracy
//!
//! Against brute-force Gauss–Legendre over r, which shares none of the closed forms
//! (`tests/hankel/transform.rs`); bounds and the small-ξ limit in `tests/hankel/slab.rs`
//! (`load_transform_obeys_its_bounds_and_small_argument_limit`).
//!
//! # Cost
//!
//! O(1) Bessel calls per ξ and load piece.
//!
//! ```
//! use boltzone::{FaceLoad, hankel::transform::LoadTransform};
//! let t = LoadTransform::new(&FaceLoad::uniform(0.1, 0.31, 1.0)?);
//! // p̄(0) = ∫ p r dr = (B² − A²)/2
//! assert!((t.eval(0.0) - (0.31f64.powi(2) - 0.01) / 2.0).abs() < 1e-16);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::load::{FaceLoad, Segment};
use crate::numerics::integral_j0::integral_j0;
use crate::numerics::quadrature::{gauss_legendre, panel, Estimate};
use crate::numerics::tanh_sinh::tanh_sinh;

/// p̄(ξ) of a face load, with the few load integrals the face fields need.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadTransform {
    segments: Vec<Segment>,
    abs_moment: f64,
}

/// r J₁(ξr)/ξ, the antiderivative of r J₀(ξr) (→ r²/2 as ξ → 0).
fn r_j1_over_xi(r: f64, xi: f64) -> f64 {
    let x = xi * r;
    if x < 1e-8 {
        r * r / 2.0
    } else {
        r * libm::j1(x) / xi
    }
}

impl LoadTransform {
    /// Builds the transform of `load`.
    pub fn new(load: &FaceLoad) -> Self {
        let segments: Vec<Segment> = load.segments().collect();
        let abs_moment = segments
            .iter()
            .map(|s| {
                Segment {
                    p0: s.p0.abs(),
                    p1: s.p1.abs(),
                    ..*s
                }
                .moment()
            })
            .sum();
        Self {
            segments,
            abs_moment,
        }
    }

    /// p̄(ξ) for ξ ≥ 0.
    pub fn eval(&self, xi: f64) -> f64 {
        self.segments.iter().map(|s| segment(s, xi)).sum()
    }

    /// The load's linear pieces.
    pub fn segments(&self) -> &[Segment] {
        &self.segments
    }

    /// ∫₀^∞ |p(r)| r dr, a bound of |p̄(ξ)| for every ξ (|J₀| ≤ 1).
    pub fn abs_moment(&self) -> f64 {
        self.abs_moment
    }

    /// C₁ with |p̄(ξ)| ≤ C₁/ξ: integrating by parts, ∫ p ρ J₀(ξρ) dρ over a piece is
    /// [p ρ J₁(ξρ)]/ξ − ∫ p′ ρ J₁(ξρ) dρ/ξ, and |J₁| ≤ 0.5819 (its maximum, 0.58187 at 1.8412).
    pub fn decay_constant(&self) -> f64 {
        0.5819
            * self
                .segments
                .iter()
                .map(|s| {
                    let slope = (s.p1 - s.p0) / (s.r1 - s.r0);
                    s.p0.abs() * s.r0
                        + s.p1.abs() * s.r1
                        + slope.abs() * (s.r1 * s.r1 - s.r0 * s.r0) / 2.0
                })
                .sum::<f64>()
    }

    /// Outer radius of the load, B.
    pub fn outer(&self) -> f64 {
        self.segments.last().map_or(0.0, |s| s.r1)
    }

    /// p(r) (zero outside the load; the right-hand piece at a knot).
    pub fn pressure(&self, r: f64) -> f64 {
        self.segments
            .iter()
            .rev()
            .find(|s| r >= s.r0 && r <= s.r1)
            .map_or(0.0, |s| s.at(r))
    }

    /// m(r)/r² with m(r) = ∫₀^r p(ρ) ρ dρ (the face value of ∫ p̄ J₁(ξr) dξ / r); p(0)/2 at r = 0.
    pub fn moment_within_over_r2(&self, r: f64) -> f64 {
        if r <= 0.0 {
            return self.pressure(0.0) / 2.0;
        }
        let m: f64 = self
            .segments
            .iter()
            .filter(|s| s.r0 < r)
            .map(|s| {
                if s.r1 <= r {
                    s.moment()
                } else {
                    Segment {
                        r1: r,
                        p1: s.at(r),
                        ..*s
                    }
                    .moment()
                }
            })
            .sum();
        m / (r * r)
    }
}

/// The arithmetic–geometric mean of a, b ≥ 0.
fn agm(mut a: f64, mut b: f64) -> f64 {
    for _ in 0..64 {
        if (a - b).abs() <= 2.0 * f64::EPSILON * a {
            break;
        }
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    0.5 * (a + b)
}

impl LoadTransform {
    /// W(r) = ∫₀^∞ p̄(ξ) J₀(ξr) dξ in real space: ∫ p(ρ) ρ G(r, ρ) dρ with
    /// G = ∫₀^∞ J₀(ξr)J₀(ξρ) dξ = 2K(k)/(π(r+ρ)), k = 2√(rρ)/(r+ρ) (Gradshteyn & Ryzhik
    /// 6.512.1), i.e. G = 1/AGM(r+ρ, |r−ρ|) (Gauss: K(k) = π/(2 AGM(1, k′))). The log
    /// singularity at ρ = r is an end point of a tanh–sinh piece. This is the slowly decaying
    /// part of the face displacement w (the half-space surface deflection integral).
    pub fn surface_integral(&self, r: f64, tol: f64) -> Estimate {
        let r = r.abs();
        let g = |rho: f64| 1.0 / agm(r + rho, (r - rho).abs());
        let mut out = Estimate::default();
        for s in &self.segments {
            let mut pieces = vec![(s.r0, s.r1)];
            if s.r0 < r && r < s.r1 {
                pieces = vec![(s.r0, r), (r, s.r1)];
            }
            for (a, b) in pieces {
                let (v, e, n) = tanh_sinh(a, b, tol, |rho| s.at(rho) * rho * g(rho));
                out = out.plus(Estimate {
                    value: v,
                    error: e,
                    evaluations: n,
                });
            }
        }
        out
    }
}

/// ∫ p(ρ) J₀(ξρ) ρ dρ over one linear piece p = α + βρ: α[ρJ₁(ξρ)/ξ] plus, from
/// ∫x²J₀ = x²J₁ + xJ₀ − ∫J₀, β[x²J₁(x) + xJ₀(x) − Ji₀(x)]/ξ³ between x = ξr₀ and ξr₁. Where
/// ξr₁ ≤ 4 that difference cancels (it is O(x³) from O(x) terms) and one 20-point Gauss rule
/// on the piece (≤ 1.3 half-periods) is used instead.
fn segment(s: &Segment, xi: f64) -> f64 {
    if s.p0 == s.p1 {
        return s.p0 * (r_j1_over_xi(s.r1, xi) - r_j1_over_xi(s.r0, xi));
    }
    let beta = (s.p1 - s.p0) / (s.r1 - s.r0);
    let alpha = s.p0 - beta * s.r0;
    if xi * s.r1 <= 4.0 {
        let rule = gauss_legendre(20);
        let mut f = |rho: f64| s.at(rho) * rho * libm::j0(xi * rho);
        return panel(&rule, s.r0, s.r1, &mut f).0;
    }
    let cubic = |r: f64| {
        let x = xi * r;
        x * x * libm::j1(x) + x * libm::j0(x) - integral_j0(x)
    };
    alpha * (r_j1_over_xi(s.r1, xi) - r_j1_over_xi(s.r0, xi))
        + beta * (cubic(s.r1) - cubic(s.r0)) / (xi * xi * xi)
}
