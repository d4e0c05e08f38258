//! Ji₀(x) = ∫₀^x J₀(t) dt, the integral of the Bessel function J₀ (DLMF 10.22.1), needed by the
//! Hankel transform of a linearly sloped face load (`hankel::transform`).
//!
//! Method: power series for x ≤ 2, a table of piecewise Chebyshev interpolants for 2 < x < 40,
//! Hankel's asymptotic expansion for x ≥ 40 (see [`integral_j0`]).
//!
//! # Accuracy
//!
//! ~20ε absolute; checked against mpmath (Struve form) in `tests/numerics/` (module `bessel_j`).
//!
//! # Cost
//!
//! O(1) per call after the table is built once (20 panels).
//!
//! ```
//! use boltzone::numerics::integral_j0::integral_j0;
//! // Ji₀(x) → 1 as x → ∞, and Ji₀(x) ≈ x for small x
//! assert!((integral_j0(1e-8) - 1e-8).abs() < 1e-22);
//! assert!((integral_j0(1e4) - 1.0).abs() < 1e-2);
//! ```

use crate::numerics::quadrature::{gauss_legendre, panel};

const TABLE_END: f64 = 40.0;
const TABLE_PANEL: f64 = 2.0;
const TABLE_POINTS: usize = 24;

/// Ji₀ on panels of width 2 covering [0, 40]: values at 24 Chebyshev points (second kind) of
/// each panel, each by 20-point Gauss–Legendre from the panel's left end (interpolation error
/// ~1e-25, so rounding dominates: ~20ε accumulated over the panels).
struct Ji0Table {
    t: [f64; TABLE_POINTS],
    w: [f64; TABLE_POINTS],
    f: Vec<[f64; TABLE_POINTS]>,
}

fn ji0_tables() -> &'static Ji0Table {
    static TABLE: std::sync::OnceLock<Ji0Table> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let n = TABLE_POINTS - 1;
        let t: [f64; TABLE_POINTS] =
            std::array::from_fn(|j| (std::f64::consts::PI * j as f64 / n as f64).cos());
        // barycentric weights of Chebyshev points of the second kind
        let w: [f64; TABLE_POINTS] = std::array::from_fn(|j| {
            let s = if j % 2 == 0 { 1.0 } else { -1.0 };
            if j == 0 || j == n {
                0.5 * s
            } else {
                s
            }
        });
        let rule = gauss_legendre(20);
        let mut j0 = |t: f64| libm::j0(t);
        let mut f = Vec::new();
        let mut start = 0.0; // Ji₀ at the panel's left end
        for p in 0..(TABLE_END / TABLE_PANEL) as usize {
            let a = p as f64 * TABLE_PANEL;
            let vals = std::array::from_fn(|j| {
                start + panel(&rule, a, a + 0.5 * TABLE_PANEL * (1.0 - t[j]), &mut j0).0
            });
            start += panel(&rule, a, a + TABLE_PANEL, &mut j0).0;
            f.push(vals);
        }
        Ji0Table { t, w, f }
    })
}

/// Ji₀(x) for 0 ≤ x < 40 by barycentric interpolation in the table's panel.
fn ji0_table(x: f64) -> f64 {
    let tab = ji0_tables();
    let p = ((x / TABLE_PANEL) as usize).min(tab.f.len() - 1);
    let s = 1.0 - 2.0 * (x - p as f64 * TABLE_PANEL) / TABLE_PANEL; // t₀ = 1 at the left end
    let (mut num, mut den) = (0.0, 0.0);
    for j in 0..TABLE_POINTS {
        let d = s - tab.t[j];
        if d == 0.0 {
            return tab.f[p][j];
        }
        let c = tab.w[j] / d;
        num += c * tab.f[p][j];
        den += c;
    }
    num / den
}

/// Ji₀(x) = ∫₀^x J₀(t) dt for x ≥ 0: power series for x ≤ 2, a table of piecewise Chebyshev
/// interpolants for 2 < x < 40 (`ji0_table`), and for x ≥ 40 the asymptotic expansion
/// Ji₀ = 1 − Re F, F(x) = ∫ₓ^∞ H₀⁽¹⁾ = √(2/π) e^(i(x−π/4)) x^(−1/2) Σ b_k x^(−k), where
/// b₀ = i, b_k = i^(k+1) a_k − i(k − ½) b_(k−1) follows from F′ = −H₀⁽¹⁾ with Hankel's
/// a_k = a_(k−1)·(−(2k−1)²)/(8k) (DLMF 10.17.1); summed to its smallest term (≈ e^(−x) < 5e-18).
/// Checked against mpmath (Struve form) in `tests/numerics/` (module `bessel_j`).
pub fn integral_j0(x: f64) -> f64 {
    let x = x.abs();
    if x <= 2.0 {
        // Σ (−1)^k x^(2k+1) / ((k!)² 4^k (2k+1)): terms fall from the first, no cancellation
        let (mut term, mut sum) = (x, x);
        for k in 1..40 {
            let kf = k as f64;
            term *= -x * x / (4.0 * kf * kf);
            let t = term / (2.0 * kf + 1.0);
            sum += t;
            if t.abs() < 1e-18 * sum.abs() {
                break;
            }
        }
        return sum;
    }
    if x < TABLE_END {
        return ji0_table(x);
    }
    // complex b_k as (re, im); i·(re, im) = (−im, re)
    let (mut b_re, mut b_im) = (0.0, 1.0);
    let (mut s_re, mut s_im) = (0.0, 1.0);
    let mut a = 1.0;
    let mut last = f64::INFINITY;
    let mut xk = 1.0;
    for k in 1..60 {
        let kf = k as f64;
        a *= -(2.0 * kf - 1.0) * (2.0 * kf - 1.0) / (8.0 * kf);
        // i^(k+1) a_k
        let (ik_re, ik_im) = match (k + 1) % 4 {
            0 => (a, 0.0),
            1 => (0.0, a),
            2 => (-a, 0.0),
            _ => (0.0, -a),
        };
        // − i (k − ½) b_(k−1) = (k − ½)(b_im, −b_re)
        let c = kf - 0.5;
        let (nb_re, nb_im) = (ik_re + c * b_im, ik_im - c * b_re);
        xk /= x;
        let size = (nb_re.hypot(nb_im)) * xk;
        if size > last {
            break;
        }
        last = size;
        (b_re, b_im) = (nb_re, nb_im);
        s_re += b_re * xk;
        s_im += b_im * xk;
        if size < 1e-18 {
            break;
        }
    }
    // sin, cos of x − π/4 from those of x (x − π/4 itself would round by ulp(x))
    let (sx, cx) = x.sin_cos();
    let (sn, cs) = (
        (sx - cx) * std::f64::consts::FRAC_1_SQRT_2,
        (cx + sx) * std::f64::consts::FRAC_1_SQRT_2,
    );
    // Re[e^(iφ)(s_re + i s_im)] = cos φ s_re − sin φ s_im
    1.0 - (2.0 / (std::f64::consts::PI * x)).sqrt() * (cs * s_re - sn * s_im)
}
