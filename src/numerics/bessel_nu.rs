//! The normalised Bessel function of complex order on the real axis,
//! Λ_ν(x) = Γ(ν + 1)(x/2)^(−ν) J_ν(x) = ₀F₁(; ν + 1; −x²/4) (entire in x, Λ_ν(0) = 1), and the
//! complex log-Gamma function it needs.
//!
//! The corner enrichment of the hole correction (`hankel::hole::corner`) loads the slab inside the
//! hole by (1 − r²/A²)^(λ−1) with λ a complex Williams exponent; Sonine's first finite integral
//! (DLMF 10.22.19, Watson § 12.11) gives its Hankel transforms in closed form through Λ_λ(ξA)
//! and Λ_(λ+1)(ξA). For Re ν > 0, x ≥ 0:
//!
//! - x ≤ 2: the power series Σ_k (−x²/4)^k/(k!(ν + 1)_k) (terms below e^x of the sum: no loss);
//! - 2 < x < x_a = max(25, |ν|²): Miller's backward recurrence y_(k−1) = 2(ν + k)/x·y_k − y_(k+1)
//!   (J_(ν+k) is the minimal solution, DLMF 10.74(iv)) from k = K ≈ x + 6x^(1/3) + 16, with the
//!   Neumann normalisation (x/2)^ν = Σ_m (ν + 2m)Γ(ν + m)/m!·J_(ν+2m)(x) (DLMF 10.23.E2 at z = 0,
//!   A&S 9.1.87), which gives Λ_ν = ν y₀ / Σ_m (ν + 2m)(ν)_m/m!·y_(2m) without any Γ;
//! - x ≥ x_a: Hankel's expansion J_ν = ½(H⁽¹⁾ + H⁽²⁾), H^(1,2) ≈ √(2/(πx)) e^(±iω)
//!   Σ_k (±i)^k a_k(ν)/x^k, ω = x − νπ/2 − π/4 (DLMF 10.17.3), summed to its smallest term
//!   (x ≥ |ν|² makes the terms fall from the first), times Γ(ν + 1)(x/2)^(−ν).
//!
//! ln Γ(z): Stirling's series with seven Bernoulli terms at Re z ≥ 15 (last term < 1e-17),
//! shifted by the recurrence Γ(z) = Γ(z + n)/(z(z + 1)…(z + n − 1)) (any non-integer z ≤ 0 too;
//! the imaginary part is correct modulo 2π, which is all exp needs).
//!
//! # Accuracy
//!
//! Checked against mpmath's `hyp0f1` and `loggamma` at 40 digits (`tests/data/hole_bessel_nu.py`,
//! `tests/hankel/hole_corner.rs`, `normal_bessel_gamma_and_roots_match_mpmath`): relative error
//! below 1e-13 over x ∈ [0, 1e6] for the orders used.
//!
//! # Cost
//!
//! O(x) recurrence steps for 2 < x < x_a, O(1) elsewhere; families of orders ν + j share one
//! recurrence (the corner fields' share of `cargo bench --bench hole`).
//!
//! ```
//! use boltzone::numerics::bessel_nu::NormalBessel;
//! use num_complex::Complex64;
//! // ν = ½: Λ_½(x) = sin x / x
//! let b = NormalBessel::new(Complex64::new(0.5, 0.0));
//! for x in [0.3, 5.0, 40.0] {
//!     assert!((b.eval(x).re - x.sin() / x).abs() < 1e-14);
//! }
//! ```

use num_complex::Complex64;
use std::f64::consts::PI;

/// Terms of the Hankel expansion kept (the series is summed to its smallest term or to these).
const HANKEL_TERMS: usize = 40;

/// ln Γ(z) for complex z not a non-positive integer (imaginary part modulo 2π).
pub fn ln_gamma(z: Complex64) -> Complex64 {
    let mut shift = Complex64::new(0.0, 0.0);
    let mut w = z;
    while w.re < 15.0 {
        shift += w.ln();
        w += 1.0;
    }
    // Bernoulli numbers B_2k / (2k(2k − 1)), k = 1…7
    const C: [f64; 7] = [
        1.0 / 12.0,
        -1.0 / 360.0,
        1.0 / 1260.0,
        -1.0 / 1680.0,
        1.0 / 1188.0,
        -691.0 / 360360.0,
        1.0 / 156.0,
    ];
    let inv = 1.0 / w;
    let inv2 = inv * inv;
    let mut series = Complex64::new(0.0, 0.0);
    let mut p = inv;
    for c in C {
        series += c * p;
        p *= inv2;
    }
    (w - 0.5) * w.ln() - w + 0.5 * (2.0 * PI).ln() + series - shift
}

/// Γ(z) for complex z not a non-positive integer.
pub fn gamma(z: Complex64) -> Complex64 {
    ln_gamma(z).exp()
}

/// Λ_ν(x) = Γ(ν + 1)(x/2)^(−ν) J_ν(x) for one complex order ν (Re ν > 0), with the order's
/// constants (Γ(ν + 1), Hankel coefficients) computed once.
#[derive(Debug, Clone)]
pub struct NormalBessel {
    nu: Complex64,
    gamma1: Complex64,
    hankel: Vec<Complex64>,
    x_a: f64,
    /// Neumann weights (ν)_m/m!, m = 0…[`WEIGHTS`] − 1, for Miller's normalisation.
    weights: Vec<Complex64>,
}

/// Neumann weights kept per order: Miller's start m_top = (x + 6x^(1/3) + 16)/2 stays below
/// this for x < 98 (the recurrence's range ends at x_a = max(25, |ν|²)); beyond, computed.
const WEIGHTS: usize = 72;

/// The first `terms` Hankel-expansion coefficients a_k(ν) of DLMF 10.17.1:
/// a_0 = 1, a_(k+1) = a_k (4ν² − (2k + 1)²)/(8(k + 1)).
pub fn hankel_coefficients(nu: Complex64, terms: usize) -> Vec<Complex64> {
    let mut out = Vec::with_capacity(terms);
    let mut a = Complex64::new(1.0, 0.0);
    for k in 0..terms {
        out.push(a);
        let j = (2 * k + 1) as f64;
        a = a * (4.0 * nu * nu - j * j) / (8.0 * (k + 1) as f64);
    }
    out
}

impl NormalBessel {
    /// The function of order `nu` (Re ν > 0).
    pub fn new(nu: Complex64) -> Self {
        let hankel = hankel_coefficients(nu, HANKEL_TERMS);
        let mut weights = Vec::with_capacity(WEIGHTS);
        let mut w = Complex64::new(1.0, 0.0);
        for m in 0..WEIGHTS {
            weights.push(w);
            w = w * (nu + m as f64) / (m + 1) as f64;
        }
        Self {
            nu,
            gamma1: gamma(nu + 1.0),
            hankel,
            x_a: nu.norm_sqr().max(25.0),
            weights,
        }
    }

    /// The order ν.
    pub fn order(&self) -> Complex64 {
        self.nu
    }

    /// Λ_ν(x) for x ≥ 0 (even in x: |x| is used).
    pub fn eval(&self, x: f64) -> Complex64 {
        let x = x.abs();
        if x <= 2.0 {
            self.series(x)
        } else if x < self.x_a {
            self.miller(x)
        } else {
            self.asymptotic(x)
        }
    }

    /// (Λ_ν(x), Λ_(ν+1)(x)) with `next` the function of order ν + 1: in the recurrence's range
    /// one backward run gives both, Λ_(ν+1) = (ν + 1)(2/x)(y₁/y₀)Λ_ν.
    pub fn eval_pair(&self, next: &NormalBessel, x: f64) -> (Complex64, Complex64) {
        let x = x.abs();
        if x <= 2.0 || x >= next.x_a.max(self.x_a) {
            return (self.eval(x), next.eval(x));
        }
        let (l0, y1_over_y0) = self.miller_ratio(x);
        (l0, (self.nu + 1.0) * (2.0 / x) * y1_over_y0 * l0)
    }

    fn series(&self, x: f64) -> Complex64 {
        let q = -0.25 * x * x;
        let mut term = Complex64::new(1.0, 0.0);
        let mut sum = term;
        for k in 1..60 {
            term = term * q / (k as f64 * (self.nu + k as f64));
            sum += term;
            if term.norm_sqr() <= 1e-34 * sum.norm_sqr() {
                break;
            }
        }
        sum
    }

    fn miller(&self, x: f64) -> Complex64 {
        self.miller_ratios(x, 1).0
    }

    fn miller_ratio(&self, x: f64) -> (Complex64, Complex64) {
        let (l0, r) = self.miller_ratios(x, 2);
        (l0, r[1])
    }

    /// Λ_(ν+j)(x), j = 0…len − 1, with `family[j]` the function of order ν + j (`family[0]`
    /// = self): in the recurrence's range one backward run gives all,
    /// Λ_(ν+j) = (ν + 1)_j (2/x)^j (y_j/y₀)Λ_ν; elsewhere each order's own route.
    pub fn eval_family(family: &[NormalBessel], x: f64) -> Vec<Complex64> {
        let x = x.abs();
        let x_a = family.iter().fold(0.0f64, |m, f| m.max(f.x_a));
        if family.is_empty() || x <= 2.0 || x >= x_a {
            return family.iter().map(|f| f.eval(x)).collect();
        }
        let nu = family[0].nu;
        let (l0, ratios) = family[0].miller_ratios(x, family.len());
        let mut factor = Complex64::new(1.0, 0.0);
        ratios
            .iter()
            .enumerate()
            .map(|(j, r)| {
                if j > 0 {
                    factor *= (nu + j as f64) * (2.0 / x);
                }
                factor * r * l0
            })
            .collect()
    }

    /// Λ_ν(x) and y_j/y₀ = J_(ν+j)(x)/J_ν(x), j = 0…count − 1, by the backward recurrence.
    fn miller_ratios(&self, x: f64, count: usize) -> (Complex64, Vec<Complex64>) {
        let nu = self.nu;
        let m_top = (((x + 6.0 * x.cbrt() + 16.0) / 2.0).ceil() as usize).max(count);
        let k_top = 2 * m_top;
        // weights (ν)_m/m! (kept, or computed upward for a far start)
        let computed;
        let weights = if m_top < WEIGHTS {
            &self.weights
        } else {
            let mut v = Vec::with_capacity(m_top + 1);
            let mut w = Complex64::new(1.0, 0.0);
            for m in 0..=m_top {
                v.push(w);
                w = w * (nu + m as f64) / (m + 1) as f64;
            }
            computed = v;
            &computed
        };
        let mut w = weights[m_top];
        let zero = Complex64::new(0.0, 0.0);
        let (mut y_next, mut y) = (zero, Complex64::new(1e-30, 0.0));
        let mut kept = vec![zero; count.max(1)];
        let mut sum = (nu + k_top as f64) * w * y;
        let mut m = m_top;
        for k in (1..=k_top).rev() {
            let y_prev = 2.0 * (nu + k as f64) / x * y - y_next;
            y_next = y;
            y = y_prev;
            if k < count {
                kept[k] = y_next;
            }
            // y now holds y_(k−1)
            if (k - 1) % 2 == 0 {
                m -= 1;
                w = weights[m];
                sum += (nu + (k - 1) as f64) * w * y;
            }
            if y.re.abs() + y.im.abs() > 1e200 {
                y *= 1e-200;
                y_next *= 1e-200;
                kept.iter_mut().for_each(|v| *v *= 1e-200);
                sum *= 1e-200;
            }
        }
        kept[0] = y;
        let inv = 1.0 / y;
        (nu * y / sum, kept.iter().map(|v| v * inv).collect())
    }

    fn asymptotic(&self, x: f64) -> Complex64 {
        let nu = self.nu;
        // Σ (±i)^k a_k/x^k for both signs, to the smallest term
        let (mut s1, mut s2) = (Complex64::new(0.0, 0.0), Complex64::new(0.0, 0.0));
        let i = Complex64::new(0.0, 1.0);
        let mut ipow = Complex64::new(1.0, 0.0);
        let mut last = f64::INFINITY;
        let mut xp = 1.0;
        for a in &self.hankel {
            let t = a * xp;
            let size = t.norm_sqr();
            if size > last {
                break;
            }
            s1 += ipow * t;
            s2 += ipow.conj() * t;
            last = size;
            if size <= 1e-34 * s1.norm_sqr() {
                break;
            }
            ipow *= i;
            xp /= x;
        }
        // e^(±iω) = e^(±ix)·e^(∓i(νπ/2 + π/4)): x's phase from sin/cos of x itself (forming
        // x − νπ/2 first would cost ε·x absolutely)
        let ex = Complex64::new(x.cos(), x.sin());
        let ph = (-i * (0.5 * PI * nu + 0.25 * PI)).exp();
        let j = (2.0 / (PI * x)).sqrt() * 0.5 * (ex * ph * s1 + (ex * ph).inv() * s2);
        self.gamma1 * (-nu * (0.5 * x).ln()).exp() * j
    }
}
