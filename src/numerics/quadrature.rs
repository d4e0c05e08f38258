//! Semi-infinite oscillatory integrals ∫₀^∞ f(ξ) dξ by partition–extrapolation.
//!
//! The integrands of the slab solution are products of Bessel functions J_n(ξr), J₁(ξB), …
//! and a smooth kernel that may decay slowly (on a face, like ξ^(−3/2)) or exponentially
//! (inside the slab, like e^(−ξ·distance to the face)). Double-exponential rules fail silently on
//! them (CRATES.md), so this module uses the classical partition–extrapolation method
//! (Longman 1956; Lucas & Stone 1995, *J. Comput. Appl. Math.* 64, 217–231):
//!
//! 1. the half-line is cut into panels of equal width h = π/ω, the half-period of the fastest
//!    oscillation ω of the integrand (for J₀(ξr)·J₁(ξB), ω = r + B);
//! 2. each panel is integrated by an n-point Gauss–Legendre rule (nodes from `gauss-quad`,
//!    computed once per order and cached). With h a half-period, the n = 10 rule's error on
//!    a trigonometric integrand is ≈ (π/2)^(2n)(n!)⁴/((2n)!³(2n+1)) ≈ 5e-27 of its amplitude;
//! 3. Wynn's ε algorithm (Wynn 1956) accelerates the partial sums S_k = ∫₀^{kh}; it is applied to
//!    a sliding window of the last [`QuadParams::window`] sums, and the estimate is accepted
//!    when two successive extrapolations agree within the tolerance.
//!
//! The error estimate is the largest distance between the latest extrapolated value and the four
//! before it, plus the last change, plus (for products of oscillations, [`QuadParams::products`])
//! the distance to an extrapolation of whole-period sums, plus a rounding floor 50·ε·Σ|w f| (the
//! sum of absolute values of the terms, QUADPACK's `resabs`).
//!
//! # Accuracy
//!
//! The estimate is never below the actual error on closed-form Hankel pairs
//! (`tests/numerics/quadrature.rs`: e^(−aξ)J₀, e^(−aξ)J₁ from fast to no decay, the
//! Weber–Schafheitlin step) and on the slab's fields (`tests/hankel/slab.rs`,
//! `field_error_estimates_cover_the_actual_error`).
//!
//! # Cost
//!
//! One n-point rule per half-period panel and O(window) per Wynn update; panels ∝ (decay
//! length)⁻¹·ω: `cargo bench --bench hankel`.
//!
//! ```
//! use boltzone::numerics::quadrature::{integrate_oscillatory, QuadParams};
//! // ∫₀^∞ e^(−ξ/10) J₀(2ξ) dξ = 1/√(0.01 + 4)
//! let est = integrate_oscillatory(|x| (-0.1 * x).exp() * libm::j0(2.0 * x), 2.0, 10.0, &QuadParams::default());
//! assert!((est.value - 1.0 / (0.01f64 + 4.0).sqrt()).abs() <= est.error);
//! assert!(est.error < 1e-11);
//! ```

use std::num::NonZeroUsize;
use std::sync::OnceLock;

/// Knobs of the partition–extrapolation quadrature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadParams {
    /// Relative tolerance on the value (default 1e-12).
    pub rel_tol: f64,
    /// Absolute tolerance (default 0: relative only).
    pub abs_tol: f64,
    /// Largest number of panels before giving up and returning the best estimate with its
    /// (then large) error (default 20 000).
    pub max_panels: usize,
    /// Gauss–Legendre points per panel (default 10; 10 or 20 are cached).
    pub order: usize,
    /// Number of the latest partial sums Wynn's ε algorithm works on (default 13, odd).
    pub window: usize,
    /// The integrand is a product of two oscillations (e.g. J₀(ξr)·J₁(ξB)) whose beat the
    /// half-period sums do not resolve: the error estimate then also includes the distance to
    /// a second extrapolation from whole-period sums (default false; pessimistic but honest).
    pub products: bool,
    /// The integrand may have a non-oscillating algebraic tail (e.g. J₀(ξr)·J₁(ξB) at r = B,
    /// where the beat frequency r − B vanishes): Wynn's ε does not accelerate such tails
    /// reliably, so the distance between the extrapolation and the plain partial sum joins
    /// the error estimate (default false).
    pub algebraic_tail: bool,
}

impl Default for QuadParams {
    fn default() -> Self {
        Self {
            rel_tol: 1e-12,
            abs_tol: 0.0,
            max_panels: 20_000,
            order: 10,
            window: 13,
            products: false,
            algebraic_tail: false,
        }
    }
}

/// A value with its error estimate and the number of integrand evaluations spent.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Estimate {
    /// The estimate.
    pub value: f64,
    /// Estimated absolute error (an upper estimate, not a guaranteed bound).
    pub error: f64,
    /// Integrand evaluations.
    pub evaluations: usize,
}

impl Estimate {
    /// `self + other` with errors and evaluations added.
    pub fn plus(self, other: Estimate) -> Estimate {
        Estimate {
            value: self.value + other.value,
            error: self.error + other.error,
            evaluations: self.evaluations + other.evaluations,
        }
    }

    /// `factor · self` (the error scales with |factor|).
    pub fn scale(self, factor: f64) -> Estimate {
        Estimate {
            value: factor * self.value,
            error: factor.abs() * self.error,
            evaluations: self.evaluations,
        }
    }
}

/// Gauss–Legendre nodes and weights on [−1, 1], computed once per order and cached
/// (orders 10 and 20 are cached; others are computed on each call).
pub fn gauss_legendre(order: usize) -> std::borrow::Cow<'static, [(f64, f64)]> {
    static G10: OnceLock<Vec<(f64, f64)>> = OnceLock::new();
    static G20: OnceLock<Vec<(f64, f64)>> = OnceLock::new();
    let make = |n: usize| -> Vec<(f64, f64)> {
        let n = NonZeroUsize::new(n.max(1)).expect("n ≥ 1");
        gauss_quad::GaussLegendre::new(n)
            .as_node_weight_pairs()
            .to_vec()
    };
    match order {
        10 => std::borrow::Cow::Borrowed(G10.get_or_init(|| make(10))),
        20 => std::borrow::Cow::Borrowed(G20.get_or_init(|| make(20))),
        n => std::borrow::Cow::Owned(make(n)),
    }
}

/// ∫ₐᵇ f by the cached rule `rule`; returns (value, Σ w|f|).
pub fn panel<F: FnMut(f64) -> f64>(rule: &[(f64, f64)], a: f64, b: f64, f: &mut F) -> (f64, f64) {
    let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
    let (mut s, mut sa) = (0.0, 0.0);
    for &(x, w) in rule {
        let v = w * f(c + h * x);
        s += v;
        sa += v.abs();
    }
    (h * s, h.abs() * sa)
}

/// Wynn's ε algorithm on `s`: the highest even-column entry computable from the sequence.
/// A vanishing difference means the sequence has converged: its last value is returned.
/// Works in two buffers on the stack for up to 64 terms (it runs once per panel and component
/// in [`integrate_oscillatory_vec`], so it must not allocate).
pub fn wynn_epsilon(s: &[f64]) -> f64 {
    const STACK: usize = 64;
    let n = s.len();
    if n < 3 {
        return *s.last().unwrap_or(&0.0);
    }
    if n > STACK {
        let (mut prev, mut cur) = (vec![0.0; n + 1], s.to_vec());
        cur.push(0.0);
        return wynn_in_place(s, &mut prev, &mut cur);
    }
    let (mut prev, mut cur) = ([0.0; STACK + 1], [0.0; STACK + 1]);
    cur[..n].copy_from_slice(s);
    wynn_in_place(s, &mut prev[..=n], &mut cur[..=n])
}

/// The ε table column by column: `cur` holds column k (its first `len` entries), `prev` column
/// k − 1; column k + 1 is written over `prev` (entry i needs only prev[i + 1] and cur[i..=i+1],
/// so increasing i never reads an overwritten entry), then the buffers swap roles.
fn wynn_in_place(s: &[f64], prev: &mut [f64], cur: &mut [f64]) -> f64 {
    let (mut prev, mut cur) = (prev, cur);
    let mut len = s.len();
    let mut best = s[len - 1];
    let mut k = 0;
    while len > 1 {
        for i in 0..len - 1 {
            let d = cur[i + 1] - cur[i];
            if d == 0.0 || !d.is_finite() {
                return if k % 2 == 0 { cur[len - 1] } else { best };
            }
            prev[i] = prev[i + 1] + 1.0 / d;
        }
        std::mem::swap(&mut prev, &mut cur);
        len -= 1;
        k += 1;
        if k % 2 == 0 {
            if !cur[len - 1].is_finite() {
                return best;
            }
            best = cur[len - 1];
        }
    }
    best
}

/// Wynn's ε on the last `window` terms of a growing sequence, updated in O(window) per term:
/// it keeps the newest entry of each column of the ε-table, ε_(k+1)^(n) = ε_(k−1)^(n+1) +
/// 1/(ε_k^(n+1) − ε_k^(n)) (the newest entries of a column use only the newest terms, so they
/// are the entries of the window's own table), and where a difference vanished or was not
/// finite. [`Self::push`] returns bit for bit what [`wynn_epsilon`] returns on the window's
/// terms (the same operations on the same operands, the same early exits; checked in the
/// tests), at a cost of `window` divisions instead of window²/2.
#[derive(Debug, Clone)]
pub struct WynnWindow {
    window: usize,
    /// Terms pushed so far.
    count: usize,
    /// Newest entry of each column k < window.
    last: Vec<f64>,
    /// Per column k: the first term index n of the newest pair (ε_k^(n), ε_k^(n+1)) whose
    /// difference vanished or was not finite.
    broken: Vec<Option<usize>>,
}

impl WynnWindow {
    /// An empty sequence with Wynn's ε on its last `window` (≥ 1) terms.
    pub fn new(window: usize) -> Self {
        let window = window.max(1);
        Self {
            window,
            count: 0,
            last: vec![0.0; window],
            broken: vec![None; window],
        }
    }

    /// Appends term `s` and returns the extrapolation of the last `window` terms.
    pub fn push(&mut self, s: f64) -> f64 {
        let m = self.count;
        self.count += 1;
        let n = self.count.min(self.window);
        // new newest entries, column by column: ε_(k+1) from the old ε_(k−1), ε_k and the new ε_k
        let (mut old_km1, mut new_k) = (0.0, s);
        for k in 0..n {
            let old_k = self.last[k];
            self.last[k] = new_k;
            if k + 1 < n {
                let d = new_k - old_k;
                if d == 0.0 || !d.is_finite() {
                    self.broken[k] = Some(m - k - 1);
                }
                let next = old_km1 + 1.0 / d;
                old_km1 = old_k;
                new_k = next;
            }
        }
        if n < 3 {
            return s;
        }
        // the value wynn_epsilon gives on the window's n terms (first index m + 1 − n)
        let first = m + 1 - n;
        let mut best = self.last[0];
        for k in 0..n - 1 {
            if self.broken[k].is_some_and(|b| b >= first) {
                return best;
            }
            if (k + 1) % 2 == 0 {
                if !self.last[k + 1].is_finite() {
                    return best;
                }
                best = self.last[k + 1];
            }
        }
        best
    }
}

/// ∫₀^∞ f(ξ) dξ for an integrand oscillating with angular frequency at most `omega` (> 0)
/// whose non-oscillating factor varies on the ξ-scale `smooth` (use `f64::INFINITY` when it
/// varies slower than the oscillation): see [`integrate_oscillatory_vec`].
pub fn integrate_oscillatory<F: FnMut(f64) -> f64>(
    mut f: F,
    omega: f64,
    smooth: f64,
    params: &QuadParams,
) -> Estimate {
    let [e] = integrate_oscillatory_vec(|x| [f(x)], omega, smooth, params);
    e
}

/// N integrals with the same oscillation sharing every integrand evaluation (the fields of one
/// point). The tolerance applies to the largest of the N values; all N must meet it.
///
/// `smooth` is the ξ-length over which the non-oscillating factor varies (1/D for the slab
/// kernels): each half-period panel is split into sub-panels no longer than it, so the
/// partial sums stay at half-period break points (what the extrapolation needs) while the
/// Gauss rule resolves the kernel; beyond ξ = 64·smooth one rule per half-period is used
/// (there the slab kernels are e^(−ξ(D−|z|)) times a polynomial, up to e^(−64)).
pub fn integrate_oscillatory_vec<const N: usize, F: FnMut(f64) -> [f64; N]>(
    mut f: F,
    omega: f64,
    smooth: f64,
    params: &QuadParams,
) -> [Estimate; N] {
    let h = std::f64::consts::PI / omega.max(f64::MIN_POSITIVE);
    // below ξ = 64·smooth, sub-panels of width `smooth`; beyond, the kernel has decayed or
    // varies only through e^(−ξ·distance) and one Gauss rule per half-period suffices
    let cut = if smooth.is_finite() && smooth > 0.0 {
        64.0 * smooth
    } else {
        0.0
    };
    let mut evaluations = 0;
    let rule = gauss_legendre(params.order);
    let window = params.window.max(3);
    let max_panels = params.max_panels.max(5);
    // Wynn's ε on the last `window` half-period sums, and (products) on the last `window`
    // whole-period sums ending at the newest — the sums of one parity, alternately
    let mut tables: [WynnWindow; N] = std::array::from_fn(|_| WynnWindow::new(window));
    let mut whole: [[WynnWindow; 2]; N] =
        std::array::from_fn(|_| std::array::from_fn(|_| WynnWindow::new(window)));
    let mut second_value = [0.0; N];
    let mut extrapolated: [Vec<f64>; N] = std::array::from_fn(|_| Vec::with_capacity(64));
    let mut total = [0.0; N];
    let mut total_abs = [0.0; N];
    let mut k = 0;
    loop {
        let (mut x0, end) = (k as f64 * h, (k + 1) as f64 * h);
        while x0 < end {
            let x1 = if x0 < cut {
                (x0 + smooth).min(end)
            } else {
                end
            };
            let (c, hw) = (0.5 * (x0 + x1), 0.5 * (x1 - x0));
            x0 = x1;
            evaluations += rule.len();
            for &(x, w) in rule.iter() {
                let v = f(c + hw * x);
                for j in 0..N {
                    total[j] += hw * w * v[j];
                    total_abs[j] += (hw * w * v[j]).abs();
                }
            }
        }
        k += 1;
        for j in 0..N {
            extrapolated[j].push(tables[j].push(total[j]));
            if params.products {
                second_value[j] = whole[j][k % 2].push(total[j]);
            }
        }
        if k < 6 {
            continue;
        }
        let mut out = [Estimate::default(); N];
        let mut scale: f64 = params.abs_tol;
        let mut finite = true;
        for j in 0..N {
            let e = &extrapolated[j];
            let m = e.len();
            let floor = 50.0 * f64::EPSILON * total_abs[j];
            // a second extrapolation from every other partial sum (whole periods): it differs
            // from the first when the integrand beats with a slower frequency (products of
            // Bessel functions), where the half-period sums are not a clean alternation
            let second = if params.products {
                second_value[j]
            } else {
                e[m - 1]
            };
            // spread of the last five extrapolations: a sequence that only seems to settle
            // (several incommensurate frequencies, slow decay) keeps a wide spread
            let spread = (m.saturating_sub(5)..m - 1)
                .map(|i| (e[m - 1] - e[i]).abs())
                .fold(0.0, f64::max);
            let gap = if params.algebraic_tail {
                (e[m - 1] - total[j]).abs()
            } else {
                0.0
            };
            let err =
                spread + (e[m - 1] - e[m - 2]).abs() + (e[m - 1] - second).abs() + gap + floor;
            finite &= e[m - 1].is_finite() && err.is_finite();
            scale = scale.max(params.rel_tol * e[m - 1].abs()).max(2.0 * floor);
            out[j] = Estimate {
                value: e[m - 1],
                error: err,
                evaluations,
            };
        }
        let done = out.iter().all(|e| e.error <= scale);
        if !finite {
            for j in 0..N {
                out[j] = Estimate {
                    value: total[j],
                    error: f64::INFINITY,
                    evaluations,
                };
            }
            return out;
        }
        if done {
            return out;
        }
        if k >= max_panels {
            // not converged: the extrapolation is unconfirmed, so its distance from the plain
            // partial sum joins the error
            for j in 0..N {
                out[j].error += (out[j].value - total[j]).abs();
            }
            return out;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{wynn_epsilon, WynnWindow};

    /// The incremental table against the from-scratch ε on every window, bit for bit: partial
    /// sums of alternating series (the use), random sequences, and sequences with repeated
    /// terms, zero differences, huge and non-finite terms (the early exits).
    #[test]
    fn wynn_window_equals_wynn_epsilon_on_every_window() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut uniform = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut sequences: Vec<Vec<f64>> = Vec::new();
        // partial sums of Σ (−1)^k/(k + 1)^p and of e^(−ak)cos(k)
        for p in [0.5, 1.0, 2.0] {
            let mut s = 0.0;
            sequences.push(
                (0..60)
                    .map(|k| {
                        s += (-1f64).powi(k) / (k as f64 + 1.0).powf(p);
                        s
                    })
                    .collect(),
            );
        }
        let mut s = 0.0;
        sequences.push(
            (0..60)
                .map(|k| {
                    s += (-0.05 * k as f64).exp() * (k as f64).cos();
                    s
                })
                .collect(),
        );
        for _ in 0..40 {
            let seq: Vec<f64> = (0..50)
                .map(|_| {
                    let u = uniform();
                    match (uniform() * 20.0) as usize {
                        0 => 1.0,       // repeats: zero differences
                        1 => 1e300 * u, // overflow of the table
                        2 => f64::NAN,
                        3 => f64::INFINITY,
                        _ => u,
                    }
                })
                .collect();
            sequences.push(seq);
        }
        sequences.push(vec![2.0; 30]);
        for seq in &sequences {
            for window in [1, 2, 3, 4, 7, 13, 14] {
                let mut table = WynnWindow::new(window);
                for end in 1..=seq.len() {
                    let fast = table.push(seq[end - 1]);
                    let slow = wynn_epsilon(&seq[end.saturating_sub(window)..end]);
                    assert!(
                        fast.to_bits() == slow.to_bits() || (fast.is_nan() && slow.is_nan()),
                        "window {window}, {end} terms: {fast:e} vs {slow:e}"
                    );
                }
            }
        }
    }
}
