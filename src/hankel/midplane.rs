//! The midplane stress σ_z(r, 0) = −∫₀^∞ ξ p̄(ξ) K(ξD) J₀(ξr) dξ fast, for many radii.
//!
//! K(t) = 2(sinh t + t cosh t)/(sinh 2t + 2t) ≤ 2.5(1 + t)e^(−t) ([`super::kernel`]), and
//! |p̄| ≤ min(M, C₁/ξ) with M = ∫|p| r dr and C₁ from
//! [`super::transform::LoadTransform::decay_constant`], so the tail beyond ξ = T/D is at most
//! 2.5 e^(−T) min(M(T² + 3T + 3)/D², C₁(T + 2)/D). [`MidplaneRule`] truncates there with T
//! chosen from the tolerance, cuts [0, T/D] into panels no wider than five half-periods of the
//! fastest oscillation (r_max + B) and no wider than 1.5/D (the kernel's scale), and puts a
//! 20-point Gauss–Legendre rule on each (Gauss's error bound for cos ωξ on 5 half-periods:
//! (5π)^41 (20!)^4/(41·(40!)^3) ≈ 2e-23 of the amplitude; the kernel's poles at Im ξ ≈ 1.1/D
//! give a Bernstein ellipse ρ ≈ 3.3 on panels of 1.5/D, ρ^(−40) ≈ 2e-21). The weights
//! c_i = w_i ξ_i p̄(ξ_i) K(ξ_i D) are computed once, so σ_z(r, 0) = −Σ c_i J₀(ξ_i r) for every
//! r ≤ r_max. The nodes are a [`PanelGrid`]'s (equal panels from 0), so the J₀(ξ_i r) of one r
//! are one row of [`PanelGrid::j0_row`] ([`libm::j0`] below 2, a Chebyshev table to 25, Hankel's
//! expansion beyond with its sines and cosines by the addition theorem across the panels:
//! within a few ulp times ξ_i r of [`libm::j0`], the rounding of the argument itself), summed
//! against the c_i panel by panel ([`PanelGrid::j0_dot`], no row of the rule's size). Error estimate: the tail bound plus a rounding floor 50ε Σ|c_i|; the tests
//! check the rule against the adaptive quadrature of [`Slab::sigma_z`] and the real-space route.
//!
//! σ_z(r, 0) is real-analytic in r (the load is a distance D away): [`MidplaneCurve`]
//! interpolates it by Chebyshev polynomials on panels no wider than 2D, with the last
//! coefficients as the error estimate, so a curve of 1000 radii costs a few dozen rule
//! evaluations per panel.
//!
//! # Accuracy
//!
//! The shared rule and the curve agree with per-point quadrature within their estimates
//! (`tests/hankel/slab.rs`, `fast_midplane_rule_and_curve_match_direct_quadrature`).
//!
//! # Cost
//!
//! `cargo bench --bench hankel` (the 1000-radius curve to 1e-10); example 01. J₀ from the
//! grid's rows instead of [`libm::j0`] per node: the curve built per setup by the
//! holed two-plate route fell from 7.0 % to 1.1 % of the samples of `two --method hankel --a
//! 0.1 --b 0.13 --d 0.1 --tol 1e-6` (one thread, `perf record`); the `slab --curve` values of
//! four geometries moved ≤ 2.3e-15 P, against their estimates of 1.2e-12 P.
//!
//! ```
//! use boltzone::{FaceLoad, Material, hankel::{Slab, MidplaneRule}};
//! let slab = Slab::new(0.1, Material::unit(0.3)?, FaceLoad::uniform(0.1, 0.31, 1.0)?)?;
//! let rule = MidplaneRule::new(&slab, 1.0, 1e-12)?;
//! let direct = slab.sigma_z(0.5, 0.0, &Default::default());
//! let fast = rule.eval(0.5);
//! assert!((direct.value - fast.value).abs() <= direct.error + fast.error);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::field::Slab;
use super::kernel::midplane;
use super::transform::LoadTransform;
use crate::error::{positive, InputError};
use crate::numerics::panel_grid::PanelGrid;
use crate::numerics::quadrature::Estimate;
use std::f64::consts::PI;

/// Largest node count a [`MidplaneRule`] may use (thin slabs with (r_max + B)/D beyond a few
/// thousand exceed it and are refused with [`InputError::Parameter`]).
pub const MAX_NODES: usize = 400_000;

/// Above this node count [`Midplane`] uses the real-space route instead of a [`MidplaneRule`]
/// (one real-space evaluation costs about as much as 50 000 nodes).
pub const SWITCH_NODES: usize = 50_000;

/// Largest number of panels (of width 2D) a [`MidplaneCurve`] may have.
pub const MAX_CURVE_PANELS: usize = 20_000;

/// σ_z(r, 0) by whichever route is cheaper: a shared ξ-rule, or for thin slabs the real-space
/// superposition of [`super::realspace`].
#[derive(Debug, Clone)]
pub enum Midplane {
    /// Shared ξ-nodes (thick and moderate slabs).
    Rule(MidplaneRule),
    /// Real-space point-kernel superposition (thin slabs).
    RealSpace {
        /// The load transform (its pieces are used).
        transform: LoadTransform,
        /// Half-thickness D.
        d: f64,
    },
}

impl Midplane {
    /// The evaluator for radii up to `r_max` to absolute tolerance `abs_tol`.
    pub fn new(slab: &Slab, r_max: f64, abs_tol: f64) -> Result<Self, InputError> {
        match MidplaneRule::with_budget(slab, r_max, abs_tol, SWITCH_NODES) {
            Ok(rule) => Ok(Midplane::Rule(rule)),
            Err(InputError::Parameter {
                field: "midplane rule nodes",
                ..
            }) => Ok(Midplane::RealSpace {
                transform: slab.transform().clone(),
                d: slab.half_thickness(),
            }),
            Err(e) => Err(e),
        }
    }

    /// σ_z(r, 0) with its error estimate.
    pub fn eval(&self, r: f64) -> Estimate {
        match self {
            Midplane::Rule(rule) => rule.eval(r),
            Midplane::RealSpace { transform, d } => {
                super::realspace::midplane_sigma_z(transform, *d, r)
            }
        }
    }

    /// ξ-nodes of the rule (0 for the real-space route).
    pub fn nodes(&self) -> usize {
        match self {
            Midplane::Rule(rule) => rule.nodes(),
            Midplane::RealSpace { .. } => 0,
        }
    }
}

/// σ_z(r, 0) for all r ≤ r_max on one shared node set.
#[derive(Debug, Clone)]
pub struct MidplaneRule {
    /// The ξ-nodes: equal 20-point Gauss–Legendre panels from 0.
    grid: PanelGrid,
    c: Vec<f64>,
    r_max: f64,
    error: f64,
}

impl MidplaneRule {
    /// The rule for radii up to `r_max`, truncated so that the tail is below `abs_tol / 2`
    /// (absolute, in the load's pressure units).
    pub fn new(slab: &Slab, r_max: f64, abs_tol: f64) -> Result<Self, InputError> {
        Self::with_budget(slab, r_max, abs_tol, MAX_NODES)
    }

    /// As [`MidplaneRule::new`], refusing rules of more than `max_nodes` nodes.
    pub fn with_budget(
        slab: &Slab,
        r_max: f64,
        abs_tol: f64,
        max_nodes: usize,
    ) -> Result<Self, InputError> {
        positive("midplane rule r_max", r_max)?;
        positive("midplane tolerance", abs_tol)?;
        let d = slab.half_thickness();
        let tr = slab.transform();
        let (m, c1) = (tr.abs_moment(), tr.decay_constant());
        // tail beyond ξ = T/D with |p̄| ≤ M: 2.5 M e^(−T)(T² + 3T + 3)/D²;
        // with |p̄| ≤ C₁/ξ: 2.5 C₁ e^(−T)(T + 2)/D. The smaller bound decides.
        let bound = |t: f64| {
            2.5 * (-t).exp() * (m * (t * t + 3.0 * t + 3.0) / (d * d)).min(c1 * (t + 2.0) / d)
        };
        let mut t: f64 = 1.0;
        while bound(t) > 0.5 * abs_tol && t < 800.0 {
            t += 0.125;
        }
        let xi_max = t / d;
        let width = (5.0 * PI / (r_max + tr.outer())).min(1.5 / d);
        let panels = (xi_max / width).ceil();
        let n = panels * 20.0;
        if n.is_nan() || n > max_nodes as f64 {
            return Err(InputError::Parameter {
                field: "midplane rule nodes",
                value: n,
                reason: "the slab is too thin for the ξ-quadrature at this radius (node budget exceeded)",
            });
        }
        let h = xi_max / panels;
        let grid = PanelGrid::equal(0.0, h, panels as usize);
        let c: Vec<f64> = grid
            .pairs()
            .map(|(s, w)| w * s * tr.eval(s) * midplane(s * d))
            .collect();
        let floor = 50.0 * f64::EPSILON * c.iter().map(|v| v.abs()).sum::<f64>();
        Ok(Self {
            grid,
            c,
            r_max,
            error: bound(t) + floor,
        })
    }

    /// σ_z(r, 0) with its error estimate; for r beyond r_max the error is infinite.
    pub fn eval(&self, r: f64) -> Estimate {
        // J₀(ξ_i r) → 0 as r → ∞: an infinite r is 0 with an infinite error, as beyond r_max
        let s = match r.is_finite() {
            true => self.grid.j0_dot(r.abs(), &self.c),
            false => 0.0,
        };
        Estimate {
            value: -s,
            error: if r.abs() <= self.r_max {
                self.error
            } else {
                f64::INFINITY
            },
            evaluations: self.grid.len(),
        }
    }

    /// Number of ξ-nodes.
    pub fn nodes(&self) -> usize {
        self.grid.len()
    }

    /// Largest radius the rule resolves.
    pub fn r_max(&self) -> f64 {
        self.r_max
    }
}

/// Chebyshev points per panel of a [`MidplaneCurve`] for an absolute tolerance `tol` relative
/// to the curve's scale: σ_z(r, 0) is analytic in the strip |Im r| < D (the ξ-integrand is
/// bounded by e^(−ξD)·e^(ξ|Im r|)), so on panels of width D the Chebyshev coefficients fall
/// like ρ^(−n) with ρ = 1 + √2 on panels of width 2D (Bernstein ellipse of semi-minor axis D
/// over half-width D; wider panels with more points cost about the same, narrower ones more).
fn cheb_points(tol: f64) -> usize {
    let rho = 1.0 + 2f64.sqrt();
    (((1e3 / tol.clamp(1e-16, 1e-2)).ln() / rho.ln()).ceil() as usize).clamp(8, 56)
}

/// Piecewise Chebyshev interpolant of σ_z(r, 0) on [r₀, r₁], panels of width ≤ 2D.
#[derive(Debug, Clone)]
pub struct MidplaneCurve {
    breaks: Vec<f64>,
    coef: Vec<Vec<f64>>,
    errors: Vec<f64>,
    evaluations: usize,
}

impl MidplaneCurve {
    /// Interpolates σ_z(r, 0) of `slab` on [r0, r1] (0 ≤ r0 < r1) to absolute tolerance
    /// `abs_tol`, with panels no wider than 2D.
    pub fn new(slab: &Slab, r0: f64, r1: f64, abs_tol: f64) -> Result<Self, InputError> {
        crate::error::non_negative("curve start radius", r0)?;
        positive("curve length", r1 - r0)?;
        let rule = Midplane::new(slab, r1, abs_tol / 4.0)?;
        let mut evaluations = 0;
        let d = slab.half_thickness();
        let panels = ((r1 - r0) / (2.0 * d)).ceil().max(1.0);
        if panels > MAX_CURVE_PANELS as f64 {
            return Err(InputError::Parameter {
                field: "midplane curve panels (length / 2D)",
                value: panels,
                reason: "too many panels of width 2D: evaluate the radii directly with Midplane",
            });
        }
        let n = panels as usize;
        let h = (r1 - r0) / n as f64;
        let breaks: Vec<f64> = (0..=n).map(|k| r0 + k as f64 * h).collect();
        let mut coef = Vec::with_capacity(n);
        let mut errors = Vec::with_capacity(n);
        let scale = slab
            .load()
            .values()
            .iter()
            .fold(0.0f64, |m, v| m.max(v.abs()));
        let cheb = cheb_points(abs_tol / scale.max(f64::MIN_POSITIVE));
        for k in 0..n {
            let (a, b) = (breaks[k], breaks[k + 1]);
            // values at Chebyshev points x_j = cos(π(j + ½)/N), then the discrete cosine transform
            let vals: Vec<f64> = (0..cheb)
                .map(|j| {
                    let x = (PI * (j as f64 + 0.5) / cheb as f64).cos();
                    let e = rule.eval(0.5 * (a + b) + 0.5 * (b - a) * x);
                    evaluations += e.evaluations;
                    e.value
                })
                .collect();
            let mut c = vec![0.0; cheb];
            for (m, cm) in c.iter_mut().enumerate() {
                let s: f64 = (0..cheb)
                    .map(|j| vals[j] * (PI * m as f64 * (j as f64 + 0.5) / cheb as f64).cos())
                    .sum();
                *cm = 2.0 * s / cheb as f64;
            }
            c[0] *= 0.5;
            // the last three coefficients bound the truncation; the rule's error adds
            let tail = c[cheb - 3..].iter().map(|v| v.abs()).sum::<f64>();
            errors.push(2.0 * tail + rule.eval(a).error);
            coef.push(c);
        }
        Ok(Self {
            breaks,
            coef,
            errors,
            evaluations,
        })
    }

    /// σ_z(r, 0) by Clenshaw's recurrence on r's panel; infinite error outside [r₀, r₁].
    pub fn eval(&self, r: f64) -> Estimate {
        let n = self.coef.len();
        let (r0, r1) = (self.breaks[0], self.breaks[n]);
        if !(r >= r0 && r <= r1) {
            return Estimate {
                value: 0.0,
                error: f64::INFINITY,
                evaluations: 0,
            };
        }
        let k = (self.breaks.partition_point(|&b| b <= r).max(1) - 1).min(n - 1);
        let (a, b) = (self.breaks[k], self.breaks[k + 1]);
        let x = (2.0 * r - a - b) / (b - a);
        let (mut b1, mut b2) = (0.0, 0.0);
        for &c in self.coef[k].iter().skip(1).rev() {
            let b0 = 2.0 * x * b1 - b2 + c;
            b2 = b1;
            b1 = b0;
        }
        Estimate {
            value: x * b1 - b2 + self.coef[k][0],
            error: self.errors[k],
            evaluations: 0,
        }
    }

    /// Largest error estimate over the panels.
    pub fn max_error(&self) -> f64 {
        self.errors.iter().cloned().fold(0.0, f64::max)
    }

    /// Kernel evaluations spent building the curve (J₀ calls or point-kernel calls).
    pub fn evaluations(&self) -> usize {
        self.evaluations
    }
}
