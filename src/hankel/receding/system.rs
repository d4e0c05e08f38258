//! The Fredholm equation of the layer in contact with a rigid base over r ≤ c, discretised by
//! Nyström's method: the numerical core of [`super::contact`] (derivation there).
//!
//! φ(t) + ∫₀^c K(t, s) φ(s) ds − C₀ = f(t) on 0 ≤ t ≤ c,  ∫₀^c φ(s) ds = p̄(0),
//!
//! K(t, s) = (2/π) ∫₀^∞ [k₁(ξD) cos ξt cos ξs + M_p(ξD)(cos ξt − 1)(cos ξs − 1)] dξ,
//! f(t) = (2/π) ∫₀^∞ M_p(ξD) (p̄(ξ) − p̄(0)) (cos ξt − 1) dξ,
//!
//! with k₁ = S − 1 and M_p of [`super::layer`]. Every ξ-integrand is analytic on [0, ∞) and
//! decays like (1 + ξD)e^(−ξD): the ξ-integrals are truncated at ξ = X/D (X from the tolerance)
//! and integrated by 20-point Gauss–Legendre panels no wider than 1.5 periods of the fastest
//! cosine and than 1/D ([`XiRule`]); the s-integral by an n-point Gauss–Legendre rule on
//! [0, c], which converges geometrically because K and f are analytic in a strip of half-width
//! ≈ D about the real axis.
//!
//! # Accuracy
//!
//! Geometric convergence in the basis size and complementarity at the edge:
//! `tests/hankel/receding_contact.rs` (`geometric_convergence_in_the_basis_size`,
//! `complementarity_and_edge_exponents`, `the_displacement_integral_is_flat_on_the_contact_zone`).
//!
//! # Cost
//!
//! One dense solve of the Nyström system per radius; example 06.

use super::layer::Stack;
use crate::hankel::transform::LoadTransform;
use crate::numerics::panel_grid::PanelGrid;
use crate::numerics::quadrature::{gauss_legendre, panel};
use nalgebra::{DMatrix, DVector};
use std::f64::consts::{FRAC_PI_2, PI};

/// ξ-nodes with the kernel weights folded in: a_m = (2/π)w_m k₁(ξ_mD),
/// b_m = (2/π)w_m M_p(ξ_mD), and p̃_m = p̄(ξ_m) − p̄(0).
#[derive(Debug, Clone)]
pub(crate) struct XiRule {
    /// The panels' width (the nodes are [`PanelGrid::equal`]'s from 0).
    h: f64,
    xi: Vec<f64>,
    a: Vec<f64>,
    b: Vec<f64>,
    p_tilde: Vec<f64>,
}

impl XiRule {
    /// Nodes on [0, X/D] resolving cosines of angular frequency up to `omega`, with the tail
    /// beyond X/D below `tol` relative to the integrals' scale.
    pub(crate) fn new(d: f64, transform: &LoadTransform, omega: f64, tol: f64) -> Self {
        Self::stacked(&Stack::single(d), transform, omega, tol)
    }

    /// The same for the weighted kernels of `stack` (two layers in series); D is its thinnest
    /// layer, whose kernels decay slowest in ξ.
    pub(crate) fn stacked(stack: &Stack, transform: &LoadTransform, omega: f64, tol: f64) -> Self {
        Self::capped(stack, transform, omega, tol, 1.0)
    }

    /// As [`Self::stacked`] with panels no wider than `cap`/D (instead of 1/D) where the
    /// cosines allow it.
    pub(crate) fn capped(
        stack: &Stack,
        transform: &LoadTransform,
        omega: f64,
        tol: f64,
        cap: f64,
    ) -> Self {
        let d = stack.thinnest();
        // tail: |k₁|, M_p ≤ 2.5(1 + x)e^(−x) for x ≥ 30 (both → 2(1 + x)e^(−x)); the cosine factors
        // are ≤ 4 and the loads' transforms ≤ 2p̄(0), so ∫_X^∞ ≤ 20(2 + X)e^(−X)·p̄(0)/D,
        // against the integrals' scale p̄(0)/(ωD ∨ 1)/D. For a stack the weights sum to 1 and the
        // thicker layer's kernels are smaller there ((1 + x)e^(−x) falls): D = D_min bounds both.
        let scale = 20.0 * (omega * d).max(1.0);
        let mut x_max: f64 = 30.0;
        for _ in 0..20 {
            x_max = (scale * (2.0 + x_max) / tol).ln().max(1.0);
        }
        // 1.5 periods per 20-point panel: Gauss–Legendre's error on e^(iωξ) there is
        // ≈ (e·ωh/80)^40 ≈ 1e-20 (ωh = 3π)
        let width = (3.0 * PI / omega).min(cap / d);
        let panels = ((x_max / d) / width).ceil() as usize;
        let h = x_max / d / panels as f64;
        let rule = gauss_legendre(20);
        let p0 = transform.eval(0.0);
        let n = panels * rule.len();
        let (mut xi, mut a, mut b, mut p_tilde) = (
            Vec::with_capacity(n),
            Vec::with_capacity(n),
            Vec::with_capacity(n),
            Vec::with_capacity(n),
        );
        for k in 0..panels {
            let c = (k as f64 + 0.5) * h;
            for &(x, w) in rule.iter() {
                let z = c + 0.5 * h * x;
                let wz = 0.5 * h * w / FRAC_PI_2;
                xi.push(z);
                a.push(wz * stack.symmetric_remainder(z));
                b.push(wz * stack.bottom_from_top(z));
                p_tilde.push(transform.eval(z) - p0);
            }
        }
        Self {
            h,
            xi,
            a,
            b,
            p_tilde,
        }
    }

    /// The nodes as a panel grid, the same floating-point values (its rows of cos ξt by the
    /// addition theorem along ξ: module `numerics::panel_grid`).
    pub(crate) fn grid(&self) -> PanelGrid {
        PanelGrid::equal(0.0, self.h, self.xi.len() / 20)
    }

    /// Number of ξ-nodes.
    pub(crate) fn len(&self) -> usize {
        self.xi.len()
    }

    /// The nodes ξ_m and the weights a_m (of k₁) and b_m (of M_p).
    pub(crate) fn nodes(&self) -> (&[f64], &[f64], &[f64]) {
        (&self.xi, &self.a, &self.b)
    }
}

/// −2 sin²(x/2) = cos x − 1 without cancellation at small x.
pub(crate) fn cos_m1(x: f64) -> f64 {
    let s = (0.5 * x).sin();
    -2.0 * s * s
}

/// The Nyström system's matrix for one rule, contact radius c and n-point s-rule, factored
/// once: [`Self::solve`] takes any right-hand side of [`Nystrom::solve_general`]'s form (the
/// holed route's crack iteration changes only α, β and the total between its solves).
pub(crate) struct NystromMatrix {
    rule: XiRule,
    c: f64,
    /// The s-rule's weights ω_j, and cos ξ_k s_j, cos ξ_k s_j − 1 (row j, column k).
    om: Vec<f64>,
    cm: DMatrix<f64>,
    vm: DMatrix<f64>,
    lu: nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>,
}

impl NystromMatrix {
    /// The matrix of the discretised equation (the bordered system of φ_j and C₀), LU-factored.
    pub(crate) fn new(rule: XiRule, c: f64, n: usize) -> Self {
        let gl = gauss_legendre(n);
        let s: Vec<f64> = gl.iter().map(|&(x, _)| 0.5 * c * (1.0 + x)).collect();
        let om: Vec<f64> = gl.iter().map(|&(_, w)| 0.5 * c * w).collect();
        let m = rule.len();
        let cm = DMatrix::from_fn(n, m, |i, k| (rule.xi[k] * s[i]).cos());
        let vm = DMatrix::from_fn(n, m, |i, k| cos_m1(rule.xi[k] * s[i]));
        let mut ca = cm.clone();
        let mut vb = vm.clone();
        for k in 0..m {
            ca.column_mut(k).scale_mut(rule.a[k]);
            vb.column_mut(k).scale_mut(rule.b[k]);
        }
        let kmat = &ca * cm.transpose() + &vb * vm.transpose();
        let mut sys = DMatrix::zeros(n + 1, n + 1);
        for i in 0..n {
            for j in 0..n {
                sys[(i, j)] = kmat[(i, j)] * om[j];
            }
            sys[(i, i)] += 1.0;
            sys[(i, n)] = -1.0;
            sys[(n, i)] = om[i];
        }
        Self {
            rule,
            c,
            om,
            cm,
            vm,
            lu: sys.lu(),
        }
    }

    /// The system solved for the right-hand side f(t) = Σ_m [α_m cos ξ_m t + β_m (cos ξ_m t − 1)]
    /// and ∫₀^c φ = `total`; `None` if the matrix is singular.
    pub(crate) fn solve(&self, total: f64, alpha: &[f64], beta: &[f64]) -> Option<Nystrom> {
        let (n, m) = (self.om.len(), self.rule.len());
        let f = &self.vm * DVector::from_column_slice(beta)
            + &self.cm * DVector::from_column_slice(alpha);
        let mut rhs = DVector::zeros(n + 1);
        for i in 0..n {
            rhs[i] = f[i];
        }
        rhs[n] = total;
        let sol = self.lu.solve(&rhs)?;
        let wphi = DVector::from_fn(n, |j, _| self.om[j] * sol[j]);
        let q_bar = self.cm.transpose() * &wphi;
        let w_hat = self.vm.transpose() * &wphi;
        let g = (0..m)
            .map(|k| beta[k] - self.rule.b[k] * w_hat[k])
            .collect();
        let h = (0..m)
            .map(|k| self.rule.a[k] * q_bar[k] - alpha[k])
            .collect();
        Some(Nystrom {
            c: self.c,
            rule: self.rule.clone(),
            c0: sol[n],
            g,
            h,
            abel_rule: std::sync::OnceLock::new(),
        })
    }
}

/// The solved Nyström system for one contact radius c.
#[derive(Debug, Clone)]
pub(crate) struct Nystrom {
    c: f64,
    rule: XiRule,
    /// C₀, the Lagrange multiplier of equilibrium (a rigid translation in disguise).
    c0: f64,
    /// g_m = β_m − b_m Ŵ_m with Ŵ = q̄ − q̄(0) at the nodes (β_m = b_m p̃_m for a top load).
    g: Vec<f64>,
    /// h_m = a_m q̄(ξ_m) − α_m.
    h: Vec<f64>,
    /// The θ-rule of H(r) with φ folded in, (c sin θ_k, w_k φ(c sin θ_k) c cos θ_k), and H(c);
    /// built on first use by [`Self::abel`] (it does not depend on r).
    abel_rule: std::sync::OnceLock<(Vec<(f64, f64)>, f64)>,
}

impl Nystrom {
    /// Solves for contact over r ≤ `c` with an `n`-point rule; `p0` = p̄(0). `None` if the
    /// linear system is singular (never observed; it is a second-kind system).
    pub(crate) fn solve(rule: XiRule, c: f64, n: usize, p0: f64) -> Option<Self> {
        let alpha = vec![0.0; rule.len()];
        let beta: Vec<f64> = (0..rule.len())
            .map(|k| rule.b[k] * rule.p_tilde[k])
            .collect();
        Self::solve_general(rule, c, n, p0, &alpha, &beta)
    }

    /// The same equation with a general right-hand side given as a cosine series on the rule's
    /// nodes, f(t) = Σ_m [α_m cos ξ_m t + β_m (cos ξ_m t − 1)], and ∫₀^c φ = `total`.
    pub(crate) fn solve_general(
        rule: XiRule,
        c: f64,
        n: usize,
        total: f64,
        alpha: &[f64],
        beta: &[f64],
    ) -> Option<Self> {
        NystromMatrix::new(rule, c, n).solve(total, alpha, beta)
    }

    /// The contact radius c this system was solved for.
    pub(crate) fn radius(&self) -> f64 {
        self.c
    }

    /// ξ-nodes used.
    pub(crate) fn xi_nodes(&self) -> usize {
        self.rule.len()
    }

    /// φ(t) = C₀ + Σ_m [g_m (cos ξ_m t − 1) − h_m cos ξ_m t]: (C₀, g, h).
    pub(crate) fn series(&self) -> (f64, &[f64], &[f64]) {
        (self.c0, &self.g, &self.h)
    }

    /// φ(t) by Nyström interpolation, 0 ≤ t ≤ c.
    pub(crate) fn phi(&self, t: f64) -> f64 {
        let xi = &self.rule.xi;
        self.c0
            + (0..xi.len())
                .map(|k| self.g[k] * cos_m1(xi[k] * t) - self.h[k] * (xi[k] * t).cos())
                .sum::<f64>()
    }

    /// φ′(t)/t, continuous at t = 0.
    fn dphi_over_t(&self, t: f64) -> f64 {
        let xi = &self.rule.xi;
        (0..xi.len())
            .map(|k| {
                let x = xi[k] * t;
                // sin(x)/t = ξ·sinc(x)
                let sinc = if x.abs() < 1e-8 { 1.0 } else { x.sin() / x };
                (self.h[k] - self.g[k]) * xi[k] * xi[k] * sinc
            })
            .sum()
    }

    /// Contact pressure q(r) = φ(c)/√(c² − r²) − ∫₀^√(c²−r²) φ′(ρ)/ρ dτ, ρ = √(r² + τ²), for
    /// 0 ≤ r < c; zero for r ≥ c. `d` sets the panel width (≤ D/2) of the τ-rule.
    pub(crate) fn pressure(&self, r: f64, d: f64) -> f64 {
        let c = self.c;
        if r >= c {
            return 0.0;
        }
        let len = ((c - r) * (c + r)).sqrt();
        let integral = integrate(0.0, len, 0.5 * d, |tau| {
            self.dphi_over_t((r * r + tau * tau).sqrt())
        });
        self.phi(c) / len - integral
    }

    /// H(r) = ∫₀^c φ(t)/√(r² − t²) dt for r ≥ c, with t = c sin θ (smooth integrand at r = c):
    /// 20-point Gauss–Legendre on 8 panels of [0, π/2], the φ values shared by every r.
    fn abel(&self, r: f64) -> f64 {
        let (rule, _) = self.abel_rule.get_or_init(|| {
            let c = self.c;
            let gl = gauss_legendre(20);
            let h = FRAC_PI_2 / 8.0;
            let rule: Vec<(f64, f64)> = (0..8)
                .flat_map(|k| {
                    let mid = (k as f64 + 0.5) * h;
                    gl.iter()
                        .map(move |&(x, w)| (mid + 0.5 * h * x, 0.5 * h * w))
                        .collect::<Vec<_>>()
                })
                .map(|(th, w)| {
                    let (sn, cs) = th.sin_cos();
                    (c * sn, w * self.phi(c * sn) * c * cs)
                })
                .collect();
            let at_c = rule
                .iter()
                .map(|&(t, wf)| wf / ((c - t) * (c + t)).sqrt())
                .sum();
            (rule, at_c)
        });
        rule.iter()
            .map(|&(t, wf)| wf / ((r - t) * (r + t)).sqrt())
            .sum()
    }

    /// Lift w(r, 0) − w(c, 0) divided by (1 − ν)/G, for 0 ≤ r ≤ 2c (the ξ-rule resolves
    /// J₀(ξr) up to there), from the displacement integral itself: the half-space part
    /// ∫q̄ J₀(ξr) dξ is ∫₀^r φ(t)/√(r² − t²) dt = ∫₀^(π/2) φ(r sin θ) dθ inside c and H(r)
    /// beyond. Inside the contact zone it must vanish: a check of the Abel inversion and of the
    /// discretisation that does not go through the Fredholm equation.
    pub(crate) fn lift_scaled(&self, r: f64) -> f64 {
        let xi = &self.rule.xi;
        let c = self.c;
        let bessel: f64 = (0..xi.len())
            .map(|k| (self.h[k] - self.g[k]) * (libm::j0(xi[k] * r) - libm::j0(xi[k] * c)))
            .sum();
        let h_r = if r >= c {
            self.abel(r)
        } else {
            integrate(0.0, FRAC_PI_2, FRAC_PI_2 / 8.0, |th| self.phi(r * th.sin()))
        };
        self.abel(c); // builds the θ-rule and H(c) on first use
        let h_c = self.abel_rule.get().map_or(0.0, |a| a.1);
        h_r - h_c + FRAC_PI_2 * bessel
    }
}

/// Gauss–Legendre panels (20 points) on [a, b] no wider than `width`: (x, w).
pub(super) fn panels(a: f64, b: f64, width: f64) -> Vec<(f64, f64)> {
    let rule = gauss_legendre(20);
    let k = ((b - a) / width).ceil().max(1.0) as usize;
    let h = (b - a) / k as f64;
    (0..k)
        .flat_map(|j| {
            let mid = a + (j as f64 + 0.5) * h;
            rule.iter()
                .map(move |&(x, w)| (mid + 0.5 * h * x, 0.5 * h * w))
                .collect::<Vec<_>>()
        })
        .collect()
}

/// ∫ₐᵇ f by 20-point Gauss–Legendre panels no wider than `max_width`.
pub(crate) fn integrate<F: Fn(f64) -> f64>(a: f64, b: f64, max_width: f64, f: F) -> f64 {
    if b <= a {
        return 0.0;
    }
    let rule = gauss_legendre(20);
    let panels = ((b - a) / max_width).ceil().max(1.0) as usize;
    let h = (b - a) / panels as f64;
    let mut f = f;
    (0..panels)
        .map(|k| panel(&rule, a + k as f64 * h, a + (k + 1) as f64 * h, &mut f).0)
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::load::FaceLoad;

    /// The Nyström kernels' integrals ∫ a(ξ) cos ξt cos ξτ dξ and ∫ b(ξ)(cos ξt − 1)(cos ξτ − 1) dξ
    /// on the rule with panels of 2/D against the rule with panels of 1/D (twice as fine), at
    /// c = 1.2D where the cap decides the width (ω = 3c allows 2.6/D): they agree to rounding
    /// (a sum of 840 terms: at most 840ε ≈ 9e-14 of Σ|terms|; asserted 1e-14). Measured:
    /// 2.8e-15 of Σ|terms|, 420 nodes against 840.
    #[test]
    fn wider_panels_integrate_the_kernels_as_the_finer_rule() {
        let (d, c) = (0.1, 0.12);
        let zero = LoadTransform::new(&FaceLoad::uniform(0.0, c, 0.0).unwrap());
        let fine = XiRule::new(d, &zero, 3.0 * c, 1e-15);
        let wide = XiRule::capped(&Stack::single(d), &zero, 3.0 * c, 1e-15, 2.0);
        assert!(
            2 * wide.len() < fine.len() + 40,
            "{} vs {}",
            wide.len(),
            fine.len()
        );
        let sums = |rule: &XiRule, t: f64, tau: f64| -> (f64, f64, f64) {
            let (xi, a, b) = rule.nodes();
            let mut out = (0.0, 0.0, 0.0);
            for ((&x, &a), &b) in xi.iter().zip(a).zip(b) {
                let (ta, tb) = (
                    a * (x * t).cos() * (x * tau).cos(),
                    b * cos_m1(x * t) * cos_m1(x * tau),
                );
                out.0 += ta;
                out.1 += tb;
                out.2 += ta.abs() + tb.abs();
            }
            out
        };
        let mut worst: f64 = 0.0;
        for i in 0..=6 {
            for j in 0..=i {
                let (t, tau) = (c * i as f64 / 6.0, c * j as f64 / 6.0);
                let (f, w) = (sums(&fine, t, tau), sums(&wide, t, tau));
                let scale = f.2.max(w.2);
                worst = worst.max(((f.0 - w.0).abs() + (f.1 - w.1).abs()) / scale);
            }
        }
        println!(
            "relative difference {worst:e} ({} nodes against {})",
            wide.len(),
            fine.len()
        );
        assert!(worst < 1e-14, "relative difference {worst:e}");
    }
}
