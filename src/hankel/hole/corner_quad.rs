//! The Hankel integrals of the corner enrichment ([`super::corner`]) at any height, the faces
//! included: a fixed Gauss–Legendre rule on [0, X] plus the tail beyond X in closed form.
//!
//! Every field of a face load with transform T(ξ) is a sum of terms
//! c·∫₀^∞ ξ^q T(ξ) k(ξD, ξz) J_n(ξr) dξ (q, n ∈ {0, 1}, k a slab kernel of [`crate::hankel::kernel`]
//! or [`crate::hankel::kernel_shear`]). Near the corner (small D − z, r = A) these integrands
//! decay only like ξ^(−Re λ) with a NON-oscillating part (the corner's ρ^(λ−1) behaviour, in
//! ξ-space), which partition–extrapolation cannot accelerate. Beyond ξ = X, with XA ≥ max(30, |λ+1|²)
//! and XD ≥ 20, everything has a convergent closed-form expansion:
//!
//! - kernels: k = (α + βu)e^(−u), u = ξ(D − z), the half-space limit (error O(t e^(−2t)) <
//!   e^(−38));
//! - T(ξ) ∝ (ξA)^τ Λ_ν(ξA) and J_n(ξr) by Hankel's expansion (DLMF 10.17.3), so their product is
//!   Σ_(±,±) C·ξ^(e) e^(iκξ) Σ_k c_k ξ^(−k), κ = ±A ± r (30 terms: the last below 1e-16 at
//!   XA ≥ |ν|²);
//! - then ∫_X^∞ ξ^m e^(−ωξ) dξ = X^(m+1) E_(−m)(ωX), ω = (D − z) − iκ, with the generalised
//!   exponential integral E_p(w) = ∫₁^∞ e^(−wt) t^(−p) dt ([`expint`]): its continued fraction for
//!   |w| ≥ 1 (Re w ≥ 0), the series E_p(w) = Γ(1−p)w^(p−1) − Σ_k (−w)^k/(k!(1−p+k)) below
//!   (DLMF 8.19.8, 8.19.17), and E_p(0) = 1/(p − 1).
//!
//! On [0, X] panels no wider than a half-period π/(A + r) of the fastest oscillation and 1.5/D
//! (the kernels' scale) carry a 12-point Gauss–Legendre rule (error ≈ 1e-20 of the amplitude;
//! see `NODES_PER_PANEL` in [`super::corner`]). The transforms Λ_λ(ξA), Λ_(λ+1)(ξA) and J₀, J₁ are shared by
//! every height and component at a node. Checked in `tests/hankel/hole_corner.rs` (E_p against mpmath,
//! face conditions by Hankel inversion, the closed-form face value, equilibrium).
//!
//! # Accuracy
//!
//! The transforms against brute-force quadrature and the tail's independence of where it starts:
//! `tests/hankel/hole_corner.rs` (`transforms_match_brute_force_quadrature`,
//! `fields_do_not_depend_on_where_the_tail_starts`).
//!
//! # Cost
//!
//! A share (25–35 %) of the hole route's time; `cargo bench --bench hole`.
//!
//! ```
//! use boltzone::hankel::hole::corner_quad::{expint, expint_sequence};
//! use num_complex::Complex64;
//! // E₁(1) = 0.21938393439552…, E₂(1) = e^(−1) − E₁(1) (A&S Table 5.1); the continued
//! // fraction near |w| = 1 keeps ~1e-14
//! let one = Complex64::new(1.0, 0.0);
//! let e = expint_sequence(one, 2, one);
//! assert!((e[0].re - 0.219_383_934_395_520_3).abs() < 1e-14);
//! assert!((expint(2.0 * one, one).re - 0.148_495_506_775_922_0).abs() < 1e-14);
//! assert!((e[1] - expint(2.0 * one, one)).norm() < 1e-14);
//! ```

use crate::numerics::bessel_nu::{hankel_coefficients, ln_gamma};
use num_complex::Complex64;
use std::f64::consts::PI;

/// Terms kept in the asymptotic expansion of the Bessel products.
pub const TAIL_TERMS: usize = 30;

/// E_p(w) = ∫₁^∞ e^(−wt) t^(−p) dt for Re w ≥ 0 and complex p; p must not be an integer when
/// |w| < 1 (the series then divides by zero: NaN — the corner exponents are never integers),
/// and Re p > 1 when w = 0. Relative accuracy ~1e-14 (the tests compare with mpmath).
pub fn expint(p: Complex64, w: Complex64) -> Complex64 {
    if w.norm() == 0.0 {
        return 1.0 / (p - 1.0);
    }
    if w.norm() < 1.0 {
        let mut sum = Complex64::new(0.0, 0.0);
        let mut pw = Complex64::new(1.0, 0.0); // (−w)^k/k!
        for k in 0..80 {
            let t = pw / (1.0 - p + k as f64);
            sum += t;
            if k > 2 && t.norm_sqr() < 1e-36 * sum.norm_sqr().max(1e-300) {
                break;
            }
            pw *= -w / (k + 1) as f64;
        }
        return (ln_gamma(1.0 - p) + (p - 1.0) * w.ln()).exp() - sum;
    }
    // modified Lentz on the even contraction of the continued fraction
    let l1 = |z: Complex64| z.re.abs() + z.im.abs();
    let tiny = 1e-300;
    let mut b = w + p;
    let mut c = Complex64::new(1.0 / tiny, 0.0);
    let mut d = 1.0 / b;
    let mut h = d;
    for i in 1..5000 {
        let an = -(i as f64) * (p - 1.0 + i as f64);
        b += 2.0;
        d = an * d + b;
        if l1(d) < tiny {
            d = Complex64::new(tiny, 0.0);
        }
        c = b + an / c;
        if l1(c) < tiny {
            c = Complex64::new(tiny, 0.0);
        }
        d = 1.0 / d;
        let del = c * d;
        h *= del;
        if l1(del - 1.0) < 1e-16 {
            break;
        }
    }
    h * (-w).exp()
}

/// E_(p₀+j)(w), j = 0…count − 1, from one direct evaluation and the recurrence
/// p E_(p+1)(w) = e^(−w) − w E_p(w) (DLMF 8.19.12), run upward where |w| < |p| and downward
/// where |w| > |p| — the stable direction either way (each step multiplies an error by
/// |w/p| or |p/w| < 1).
pub fn expint_sequence(p0: Complex64, count: usize, w: Complex64) -> Vec<Complex64> {
    let zero = Complex64::new(0.0, 0.0);
    let mut out = vec![zero; count];
    if count == 0 {
        return out;
    }
    if w.norm() == 0.0 {
        for (j, o) in out.iter_mut().enumerate() {
            *o = 1.0 / (p0 + j as f64 - 1.0);
        }
        return out;
    }
    let ew = (-w).exp();
    let wn = w.norm_sqr();
    // the start: the first index with |p| ≥ |w| (all upward from there), or the last
    let start = (0..count)
        .find(|&j| (p0 + j as f64).norm_sqr() >= wn)
        .unwrap_or(count - 1);
    out[start] = expint(p0 + start as f64, w);
    for j in start..count - 1 {
        let p = p0 + j as f64;
        out[j + 1] = (ew - w * out[j]) / p;
    }
    for j in (0..start).rev() {
        let p = p0 + j as f64;
        out[j] = (ew - p * out[j + 1]) / w;
    }
    out
}

/// The asymptotic form of (ξA)^τ Λ_ν(ξA)·J_n(ξr) = Σ_(s₁,s₂ = ±) C·ξ^(τ−ν−1) e^(iξ(s₁A + s₂r))
/// Σ_k c_k ξ^(−k): for each sign pair (κ, C, c_k).
#[derive(Debug, Clone)]
pub struct ProductSeries {
    /// (κ = s₁A + s₂r, C, coefficients c_k).
    pub parts: Vec<(f64, Complex64, Vec<Complex64>)>,
}

impl ProductSeries {
    /// The series of (ξA)^`tau` Λ_`nu`(ξA)·J_`n`(ξr) (n = 0 or 1).
    pub fn new(nu: Complex64, tau: f64, n: usize, a: f64, r: f64) -> Self {
        let an = hankel_coefficients(nu, TAIL_TERMS);
        let bn = hankel_coefficients(Complex64::new(n as f64, 0.0), TAIL_TERMS);
        let i = Complex64::new(0.0, 1.0);
        let phase_nu = 0.5 * PI * nu + 0.25 * PI;
        let phase_n = 0.5 * PI * n as f64 + 0.25 * PI;
        // Γ(ν+1) 2^ν A^(τ−ν−½) (2/π) / (4√r)
        let lead = (ln_gamma(nu + 1.0) + nu * 2f64.ln() + (tau - nu - 0.5) * a.ln()).exp()
            * (2.0 / PI)
            / (4.0 * r.sqrt());
        let mut parts = Vec::with_capacity(4);
        for s1 in [1.0, -1.0] {
            for s2 in [1.0, -1.0] {
                let (i1, i2) = (i * s1, i * s2);
                let p: Vec<Complex64> = (0..TAIL_TERMS)
                    .map(|k| an[k] * i1.powi(k as i32) / a.powi(k as i32))
                    .collect();
                let q: Vec<Complex64> = (0..TAIL_TERMS)
                    .map(|k| bn[k] * i2.powi(k as i32) / r.powi(k as i32))
                    .collect();
                let c: Vec<Complex64> = (0..TAIL_TERMS)
                    .map(|k| (0..=k).map(|j| p[j] * q[k - j]).sum())
                    .collect();
                let phase = (-i * (s1 * phase_nu + s2 * phase_n)).exp();
                parts.push((s1 * a + s2 * r, lead * phase, c));
            }
        }
        Self { parts }
    }
}

/// E_(λ−1+j)(ω_s X) for j = 0…[`TAIL_TERMS`] + 1 and the four ω_s = y − iκ_s of a [`ProductSeries`]
/// (κ depends on r only, so one table serves every series at that radius and height y).
pub fn expint_table(lam: Complex64, y: f64, x: f64, kappas: &[f64]) -> Vec<Vec<Complex64>> {
    expint_table_extended(lam, y, x, kappas, 0)
}

/// [`expint_table`] with `extra` more terms per row: row[j..] is then the table of λ + j for
/// j ≤ `extra` (exponents λ, λ + 1, … share one table).
pub fn expint_table_extended(
    lam: Complex64,
    y: f64,
    x: f64,
    kappas: &[f64],
    extra: usize,
) -> Vec<Vec<Complex64>> {
    let mut out: Vec<Vec<Complex64>> = Vec::with_capacity(kappas.len());
    for (i, &k) in kappas.iter().enumerate() {
        // equal κ (A − r and r − A on the hole, both 0) share one sequence
        let row = match kappas[..i].iter().position(|&q| q == k) {
            Some(j) => out[j].clone(),
            None => expint_sequence(lam - 1.0, TAIL_TERMS + 2 + extra, Complex64::new(y, -k) * x),
        };
        out.push(row);
    }
    out
}

/// ∫_X^∞ (α + βyξ)e^(−yξ) ξ^q (ξA)^τ Λ_ν(ξA) J_n(ξr) dξ from the series `ser` (of that ν, τ, n)
/// with ν − τ = λ, the table `e` = [`expint_table`]`(λ, y, X, κ's)` (its rows, or their
/// tails from j of an extended table of λ − j) and `x_lam` = X^(−λ), for
/// q ∈ {0, 1}.
#[allow(clippy::too_many_arguments)]
pub fn tail(
    ser: &ProductSeries,
    e: &[&[Complex64]],
    x_lam: Complex64,
    q: usize,
    alpha: f64,
    beta: f64,
    y: f64,
    x: f64,
) -> Complex64 {
    // ξ-power of the k-th term: e − k with e = q + τ − ν − 1 = q − λ − 1; ∫ξ^(e−k) e^(−ωξ) =
    // X^(e−k+1) E_(k−e), k − e = λ + (k + 1 − q); the β term has one more power of ξ.
    // X^(q−k−λ) = X^(−λ)·X^q·X^(−k)
    let x_lam = x_lam * if q == 1 { x } else { 1.0 };
    let inv_x = 1.0 / x;
    let beta_y = if y > 0.0 { beta * y * x } else { 0.0 };
    let mut out = Complex64::new(0.0, 0.0);
    for ((_, cc, c), et) in ser.parts.iter().zip(e) {
        let mut s = Complex64::new(0.0, 0.0);
        let mut xk = 1.0;
        for (k, ck) in c.iter().enumerate().take(TAIL_TERMS - 1) {
            // E_(λ−1+j): α needs j = k + 2 − q, β (one more power) j = k + 1 − q
            let mut v = alpha * et[k + 2 - q];
            if beta_y != 0.0 {
                v += beta_y * et[k + 1 - q];
            }
            s += ck * xk * v;
            xk *= inv_x;
        }
        s *= x_lam;
        out += cc * s;
    }
    out
}
