//! Rows of cos ξs, cos ξs − 1 and J₀(ξs) over the nodes of equal Gauss–Legendre panels, for
//! the holed two-plate model's transforms (module `hankel::receding::crack`): the tables it rebuilds for every
//! trial contact radius, at a few flops per entry instead of a library call.
//!
//! **What is computed.** For nodes s = m_p + δ_j (panel midpoints m_p = a + (p + ½)h, offsets
//! δ_j = ½h·x_j of the 20-point rule, the same floating-point nodes as
//! `system::panels`) and one ξ: cos ξs and sin ξs by the addition theorem from
//! the per-panel and per-offset values (with more than 8 panels, the per-panel values of every
//! 8th panel m_a from `sin_cos` and of the 7 after it by one rotation each, by ξjh, j = 1 … 7:
//! no chain of rotations, so no accumulated error); cos ξs − 1 = A + B + AB − sin ξm_p sin ξδ_j
//! with A = cos ξm_p − 1, B = cos ξδ_j − 1, each −sin²/(1 + cos) from the same sine and cosine
//! where the cosine is positive, else directly (no cancellation either way; the sum loses at most a factor
//! (m_p/s)² ≤ 16 of relative accuracy, since nodes with |s| < |m_p|/4 are computed directly);
//! J₀(x) for x ≥ 25 from Hankel's asymptotic expansion
//! (Abramowitz & Stegun 9.2.5, 9.2.9–10):
//!
//! J₀(x) = √(2/(πx)) [P(x) cos(x − π/4) − Q(x) sin(x − π/4)],
//! P = Σ_k (−1)^k a_{2k}/x^{2k}, Q = −Σ_k (−1)^k a_{2k+1}/x^{2k+1} (Q ≈ −1/(8x)),
//! a_k = 1²·3²·…·(2k−1)²/(k!·8^k),
//!
//! summed to k = 18 by Horner's rule (at x = 25 the first term dropped is 1.5e-17; the smallest,
//! near k = 2x, is ~e^(−50)); in [`PanelGrid::j0_row`] a panel whose nodes all lie at x ≥ 25
//! sums only the terms its smallest x needs for the same 1.5e-17 (k ≤ 14 from x = 33, 11 from
//! 50, 9 from 78, 7 from 160: a_{k+1}/x^(k+1) < 1.5e-17 there), with 1/x and √(2/(πx)) as
//! products of the row's 1/(8ξ), √(2/(πξ)) and the node's 1/s, 1/√s (a few ulp of J₀'s
//! amplitude),
//! with cos(x − π/4) = (cos x + sin x)/√2, sin(x − π/4) = (sin x − cos x)/√2 from the addition
//! theorem; from 2 to 25 (where [`libm::j0`] calls sin and cos), from a table built once: on each unit interval [k, k + 1) the
//! interpolant of degree 12 at 13 Chebyshev points of [`libm::j0`], summed by Clenshaw's
//! recurrence (its error ≤ h¹³/(2¹²·13!)·max|J₀⁽¹³⁾| ≤ 5e-18 for h = ½, |J₀⁽ⁿ⁾| ≤ 1, below
//! the rounding of libm's values, which the interpolation carries with a Lebesgue constant
//! under 2.5); below 2, [`libm::j0`].
//!
//! # Accuracy
//!
//! `tests/numerics/panel_grid.rs`: every row against the library functions evaluated at the
//! same nodes (cos, `libm::j0`), within the rounding of the argument ξs (a few ulp times x).
//!
//! # Cost
//!
//! One sin/cos pair per offset and per panel (per 8 panels and 7 more per row beyond 8 panels),
//! a few multiplications per entry, and for J₀ the
//! 18 terms of the series by Horner's rule (about 3× faster than summing term by term to a
//! threshold: the J₀ rows of the holed route fell from 45 to 15 ms per radius); from 2 to 25
//! the table's 12 steps of Clenshaw's recurrence instead of libm's sin, cos and rational
//! approximations (libm's J₀ was 19 % of the holed route's CPU at the knobs for 1e-3, under 2 %
//! after; Table 1 at those knobs 1.82–1.90 s instead of 2.16–2.76 s for all twelve rows, by
//! turns at load 8, R_o unchanged to the 10 digits printed). The fewer terms per panel at
//! larger x and the reciprocals per node: [`PanelGrid::j0_row`]'s own share of
//! the CPU of `two --method hankel --a 0.1 --b 0.13 --d 0.1 --tol 1e-6` (one thread, `perf
//! record`) from 20.7 % to 8.9 %, R_o moved by 5e-17 of R_o; [`dot`], the
//! rows' products with a vector, in four partial sums. The holed route's timing: example 19.
//!
//! ```
//! use boltzone::numerics::panel_grid::PanelGrid;
//! let grid = PanelGrid::new(1.0, 3.0, 0.5);
//! let mut row = vec![0.0; grid.len()];
//! grid.j0_row(40.0, &mut row);
//! let s = grid.nodes()[7];
//! assert!((row[7] - libm::j0(40.0 * s)).abs() < 1e-14);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::numerics::quadrature::gauss_legendre;
use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// Where the asymptotic expansion of J₀ takes over from [`libm::j0`].
const ASYMPTOTIC_FROM: f64 = 25.0;

/// Nodes and weights of equal 20-point Gauss–Legendre panels on [a, b], with the split
/// s = m_p + δ_j that the rows use.
#[derive(Debug, Clone)]
pub struct PanelGrid {
    /// The panels' width h and midpoints m_p.
    width: f64,
    mids: Vec<f64>,
    offsets: Vec<f64>,
    nodes: Vec<f64>,
    weights: Vec<f64>,
    /// 1/s and 1/√s at every node (0 where s ≤ 0): J₀'s asymptotic expansion at x = ξs
    /// takes 1/x and √(2/(πx)) as products with the row's 1/ξ and √(2/(πξ)).
    inv: Vec<(f64, f64)>,
}

/// −2 sin²(x/2) = cos x − 1 without cancellation at small x.
fn cos_m1(x: f64) -> f64 {
    let s = (0.5 * x).sin();
    -2.0 * s * s
}

/// cos x − 1 from sin x and cos x: −sin²x/(1 + cos x) without cancellation where cos x > 0,
/// and directly where cos x ≤ 0 (then |cos x − 1| ≥ 1).
fn m1_of(s: f64, c: f64) -> f64 {
    if c > 0.0 {
        -s * s / (1.0 + c)
    } else {
        c - 1.0
    }
}

/// (cos x, cos x − 1) from one `sin_cos` ([`m1_of`]).
pub(crate) fn cos_and_m1(x: f64) -> (f64, f64) {
    let (s, c) = x.sin_cos();
    (c, m1_of(s, c))
}

/// Panels per anchor of [`PanelGrid::mid_trig`]: every 8th midpoint from `sin_cos`, the 7 after
/// it by one rotation each.
const ANCHOR_EVERY: usize = 8;

/// J₀(x) − 1 without cancellation at small x.
pub(crate) fn j0_m1(x: f64) -> f64 {
    if x < 0.1 {
        let y = 0.25 * x * x;
        // −y + y²/4 − y³/36 + y⁴/576: the next term is < 1e-17 at x < 0.1
        -y * (1.0 - y / 4.0 * (1.0 - y / 9.0 * (1.0 - y / 16.0)))
    } else {
        libm::j0(x) - 1.0
    }
}

impl PanelGrid {
    /// Panels no wider than `width` on [`a`, `b`] (at least one).
    pub fn new(a: f64, b: f64, width: f64) -> Self {
        let k = ((b - a) / width).ceil().max(1.0) as usize;
        Self::equal(a, (b - a) / k as f64, k)
    }

    /// `k` panels of width `h` from `a`.
    pub fn equal(a: f64, h: f64, k: usize) -> Self {
        let rule = gauss_legendre(20);
        let mids: Vec<f64> = (0..k).map(|j| a + (j as f64 + 0.5) * h).collect();
        let offsets: Vec<f64> = rule.iter().map(|&(x, _)| 0.5 * h * x).collect();
        let nodes: Vec<f64> = mids
            .iter()
            .flat_map(|m| offsets.iter().map(move |o| m + o))
            .collect();
        let weights = mids
            .iter()
            .flat_map(|_| rule.iter().map(|&(_, w)| 0.5 * h * w))
            .collect::<Vec<f64>>();
        let inv = nodes
            .iter()
            .map(|&s: &f64| match s > 0.0 {
                true => (1.0 / s, 1.0 / s.sqrt()),
                false => (0.0, 0.0),
            })
            .collect();
        Self {
            width: h,
            mids,
            offsets,
            nodes,
            weights,
            inv,
        }
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Whether there are no nodes (never: at least one panel).
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The nodes s, panel by panel.
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    /// The quadrature weights.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// The rule as (node, weight) pairs.
    pub fn pairs(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        self.nodes.iter().copied().zip(self.weights.iter().copied())
    }

    /// Calls `f(index, cos ξs, sin ξs, cos ξs − 1)` for every node.
    fn for_each(&self, xi: f64, mut f: impl FnMut(usize, f64, f64, f64)) {
        let offs: Vec<(f64, f64, f64)> = self
            .offsets
            .iter()
            .map(|&o| {
                let (s, c) = (xi * o).sin_cos();
                (c, s, m1_of(s, c))
            })
            .collect();
        for (p, (&m, (sm, cm))) in self.mids.iter().zip(self.mid_trig(xi)).enumerate() {
            let am = m1_of(sm, cm);
            for (j, &(co, so, bo)) in offs.iter().enumerate() {
                let c = cm * co - sm * so;
                let s = sm * co + cm * so;
                let i = 20 * p + j;
                // A + B + AB − sin·sin cancels like (m/s)² where the node s is much nearer zero
                // than its panel's midpoint m (first panels from 0): there, directly
                let m1 = if 4.0 * self.nodes[i].abs() < m.abs() {
                    cos_m1(xi * self.nodes[i])
                } else {
                    am + bo + am * bo - sm * so
                };
                f(i, c, s, m1);
            }
        }
    }

    /// (sin ξm_p, cos ξm_p) at every panel midpoint: with more than [`ANCHOR_EVERY`] panels,
    /// every 8th (the anchor m_a) from `sin_cos` and the 7 after it by the addition theorem
    /// with ξjh (j = 1 … 7, one `sin_cos` each per row) — one rotation from an anchor, so the
    /// error does not accumulate: a few ulp, as the rounding of ξm_p itself.
    fn mid_trig(&self, xi: f64) -> Vec<(f64, f64)> {
        if self.mids.len() <= ANCHOR_EVERY {
            return self.mids.iter().map(|&m| (xi * m).sin_cos()).collect();
        }
        let steps: [(f64, f64); ANCHOR_EVERY] =
            std::array::from_fn(|j| (xi * (j as f64 * self.width)).sin_cos());
        let mut out = Vec::with_capacity(self.mids.len());
        for chunk in self.mids.chunks(ANCHOR_EVERY) {
            let (sa, ca) = (xi * chunk[0]).sin_cos();
            out.push((sa, ca));
            for &(sj, cj) in &steps[1..chunk.len()] {
                out.push((sa * cj + ca * sj, ca * cj - sa * sj));
            }
        }
        out
    }

    /// `cos` ← cos ξs and `cos_m1` ← cos ξs − 1 at every node.
    pub fn cos_rows(&self, xi: f64, cos: &mut [f64], cos_m1: &mut [f64]) {
        self.for_each(xi, |i, c, _, m1| {
            cos[i] = c;
            cos_m1[i] = m1;
        });
    }

    /// `out` ← cos ξs − 1 at every node.
    pub fn cos_m1_row(&self, xi: f64, out: &mut [f64]) {
        self.for_each(xi, |i, _, _, m1| out[i] = m1);
    }

    /// `out` ← J₀(ξs) at every node (ξ ≥ 0). A panel whose nodes all lie at x = ξs ≥ 25
    /// takes the asymptotic expansion with the fewest terms its smallest x allows (module
    /// docs), the others each node's branch.
    pub fn j0_row(&self, xi: f64, out: &mut [f64]) {
        self.j0_panels(xi, |p, values| {
            out[20 * p..20 * (p + 1)].copy_from_slice(values)
        });
    }

    /// Σ_i w_i J₀(ξs_i) over the nodes (ξ ≥ 0): [`Self::j0_row`]'s values summed panel by panel,
    /// without a row of the grid's size (the slab's midplane rule, one per radius).
    pub fn j0_dot(&self, xi: f64, w: &[f64]) -> f64 {
        let mut sum = 0.0;
        self.j0_panels(xi, |p, values| sum += dot(&w[20 * p..20 * (p + 1)], values));
        sum
    }

    /// J₀(ξs) at each panel's 20 nodes, handed to `each` with the panel's index (module docs).
    fn j0_panels(&self, xi: f64, mut each: impl FnMut(usize, &[f64; 20])) {
        let offs: Vec<(f64, f64)> = self
            .offsets
            .iter()
            .map(|&o| {
                let (s, c) = (xi * o).sin_cos();
                (c, s)
            })
            .collect();
        let reach = self.offsets.iter().fold(0.0f64, |r, o| r.max(o.abs()));
        let scale = (1.0 / (8.0 * xi), (2.0 / (PI * xi)).sqrt());
        for (p, (&m, (sm, cm))) in self.mids.iter().zip(self.mid_trig(xi)).enumerate() {
            let at = 20 * p..20 * (p + 1);
            let (nodes, inv) = (&self.nodes[at.clone()], &self.inv[at]);
            let mut out = [0.0; 20];
            // cos ξs and sin ξs by the addition theorem, as in `for_each`
            let mut trig = [(0.0, 0.0); 20];
            for (t, &(co, so)) in trig.iter_mut().zip(&offs) {
                *t = (cm * co - sm * so, sm * co + cm * so);
            }
            let panel = Panel {
                trig: &trig,
                inv,
                scale,
            };
            match asymptotic_terms(xi * (m - reach)) {
                Some(18) => panel.asymptotic::<10, 9>(&mut out),
                Some(14) => panel.asymptotic::<8, 7>(&mut out),
                Some(11) => panel.asymptotic::<6, 6>(&mut out),
                Some(9) => panel.asymptotic::<5, 5>(&mut out),
                Some(_) => panel.asymptotic::<4, 4>(&mut out),
                None => {
                    for ((o, &s), &(c, sn)) in out.iter_mut().zip(nodes).zip(&trig) {
                        let x = xi * s;
                        *o = if x < TABLE_FROM {
                            libm::j0(x)
                        } else if x < ASYMPTOTIC_FROM {
                            j0_table(x)
                        } else {
                            j0_asymptotic(x, c, sn)
                        };
                    }
                }
            }
            each(p, &out);
        }
    }
}

/// One panel of a J₀ row: (cos ξs, sin ξs) and (1/s, 1/√s) at its 20 nodes, and the row's
/// (1/(8ξ), √(2/(πξ))).
struct Panel<'a> {
    trig: &'a [(f64, f64); 20],
    inv: &'a [(f64, f64)],
    scale: (f64, f64),
}

impl Panel<'_> {
    /// `out` ← J₀ at the panel's nodes from the asymptotic expansion with the first `P`
    /// coefficients of P and `Q` of Q (the terms a_k/x^k up to k = 2P − 2 and 2Q − 1).
    fn asymptotic<const P: usize, const Q: usize>(&self, out: &mut [f64]) {
        let (p_c, q_c) = coefficients();
        let p_c: [f64; P] = std::array::from_fn(|k| p_c[k]);
        let q_c: [f64; Q] = std::array::from_fn(|k| q_c[k]);
        let (y_scale, amp_scale) = self.scale;
        for ((o, &(c, s)), &(inv, inv_sqrt)) in out.iter_mut().zip(self.trig).zip(self.inv) {
            let y = y_scale * inv;
            let y2 = y * y;
            let p = p_c.iter().rev().fold(0.0, |acc, &v| acc * y2 + v);
            let q = y * q_c.iter().rev().fold(0.0, |acc, &v| acc * y2 + v);
            let (cos_w, sin_w) = ((c + s) * FRAC_1_SQRT_2, (s - c) * FRAC_1_SQRT_2);
            *o = amp_scale * inv_sqrt * (p * cos_w - q * sin_w);
        }
    }
}

/// The largest index k of the terms a_k/x^k of J₀'s expansion kept at every x ≥ `x_min`: the
/// first term dropped is below 1.5e-17 (as at x = 25 with k ≤ 18): 18 from x = 25, 14 from 33,
/// 11 from 50, 9 from 78, 7 from 160; None below 25.
fn asymptotic_terms(x_min: f64) -> Option<usize> {
    const FROM: [(f64, usize); 5] = [(160.0, 7), (78.0, 9), (50.0, 11), (33.0, 14), (25.0, 18)];
    FROM.iter().find(|f| x_min >= f.0).map(|f| f.1)
}

/// Σ x_i y_i over the common length, in four interleaved partial sums (which the compiler
/// keeps in vector registers; the plain left-to-right sum is one dependent chain): the
/// products with the tables' rows, the holed route's inner loop.
pub fn dot(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len().min(y.len());
    let (x, y) = (&x[..n], &y[..n]);
    let mut acc = [0.0; 4];
    let (xc, yc) = (x.chunks_exact(4), y.chunks_exact(4));
    let tail: f64 = xc
        .remainder()
        .iter()
        .zip(yc.remainder())
        .map(|(a, b)| a * b)
        .sum();
    for (a, b) in xc.zip(yc) {
        for k in 0..4 {
            acc[k] += a[k] * b[k];
        }
    }
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}

/// Where the table of J₀ takes over from [`libm::j0`] (whose rational approximation below 2
/// is fast and, near J₀ = 1, a few ulp more accurate than the table).
const TABLE_FROM: f64 = 2.0;

/// Chebyshev points (and coefficients) per unit interval of the table of J₀ on [0, 25).
const CHEB: usize = 13;

/// J₀ on [k, k + 1) for k = 0 … 24: the coefficients of its interpolant of degree 12 in
/// Chebyshev polynomials of 2(x − k) − 1, from [`libm::j0`] at the 13 Chebyshev points.
static J0_TABLE: std::sync::OnceLock<Vec<[f64; CHEB]>> = std::sync::OnceLock::new();

/// J₀(x) for 0 ≤ x < 25 from [`J0_TABLE`] by Clenshaw's recurrence (module docs).
fn j0_table(x: f64) -> f64 {
    let table = J0_TABLE.get_or_init(|| {
        let n = CHEB as f64;
        let theta = |j: usize| PI * (j as f64 + 0.5) / n;
        (0..ASYMPTOTIC_FROM as usize)
            .map(|k| {
                let f: Vec<f64> = (0..CHEB)
                    .map(|j| libm::j0(k as f64 + 0.5 + 0.5 * theta(j).cos()))
                    .collect();
                let mut c = [0.0; CHEB];
                for (m, cm) in c.iter_mut().enumerate() {
                    let sum: f64 = f
                        .iter()
                        .enumerate()
                        .map(|(j, v)| v * (m as f64 * theta(j)).cos())
                        .sum();
                    *cm = sum * if m == 0 { 1.0 } else { 2.0 } / n;
                }
                c
            })
            .collect()
    });
    let k = (x.max(0.0) as usize).min(table.len() - 1);
    let t = 2.0 * (x - k as f64) - 1.0;
    let c = &table[k];
    let (mut b1, mut b2) = (0.0, 0.0);
    for &cm in c[1..].iter().rev() {
        let b0 = 2.0 * t * b1 - b2 + cm;
        b2 = b1;
        b1 = b0;
    }
    t * b1 - b2 + c[0]
}

/// Terms of the asymptotic series kept: a_k/x^k for k ≤ 18 (at x = 25 the first dropped, k = 19,
/// is 1.5e-17 and the rest smaller; at larger x they fall faster).
const TERMS: usize = 18;

/// The signed coefficients of P and Q in powers of y = 1/(8x): P = Σ_j p_j (y²)^j,
/// Q = y Σ_j q_j (y²)^j, from b_k = Π_{i<k} (2i + 1)²/(i + 1) (so that a_k/x^k = b_k y^k) with
/// the sign (−1)^⌈k/2⌉.
static COEFFICIENTS: std::sync::OnceLock<(Vec<f64>, Vec<f64>)> = std::sync::OnceLock::new();

/// J₀(x) for x ≥ 25 from cos x and sin x (module docs): P and Q by Horner's rule.
fn j0_asymptotic(x: f64, cos: f64, sin: f64) -> f64 {
    let (p_c, q_c) = coefficients();
    let y = 1.0 / (8.0 * x);
    let y2 = y * y;
    let horner = |c: &[f64]| c.iter().rev().fold(0.0, |acc, &v| acc * y2 + v);
    let (p, q) = (horner(p_c), y * horner(q_c));
    let cos_w = (cos + sin) * FRAC_1_SQRT_2;
    let sin_w = (sin - cos) * FRAC_1_SQRT_2;
    (2.0 / (PI * x)).sqrt() * (p * cos_w - q * sin_w)
}

/// The coefficients of P and Q ([`COEFFICIENTS`]).
fn coefficients() -> &'static (Vec<f64>, Vec<f64>) {
    COEFFICIENTS.get_or_init(|| {
        let mut b = vec![1.0];
        for i in 0..TERMS {
            let i = i as f64;
            let next = b[b.len() - 1] * (2.0 * i + 1.0) * (2.0 * i + 1.0) / (i + 1.0);
            b.push(next);
        }
        let sign = |k: usize| if k.div_ceil(2) % 2 == 1 { -1.0 } else { 1.0 };
        let p = (0..=TERMS).step_by(2).map(|k| sign(k) * b[k]).collect();
        let q = (1..=TERMS).step_by(2).map(|k| sign(k) * b[k]).collect();
        (p, q)
    })
}

/// Barycentric interpolation on Gauss–Legendre panels of equal width from `start`.
pub(crate) struct PanelInterp {
    start: f64,
    /// The panels' width.
    pub(crate) width: f64,
    panels: usize,
    nodes: Vec<f64>,
    weights: Vec<f64>,
}

impl PanelInterp {
    pub(crate) fn new(start: f64, end: f64, width: f64) -> Self {
        let panels = ((end - start) / width).ceil().max(1.0) as usize;
        let nodes: Vec<f64> = gauss_legendre(20).iter().map(|&(x, _)| x).collect();
        let weights = (0..nodes.len())
            .map(|j| {
                1.0 / (0..nodes.len())
                    .filter(|&k| k != j)
                    .map(|k| nodes[j] - nodes[k])
                    .product::<f64>()
            })
            .collect();
        Self {
            start,
            width: (end - start) / panels as f64,
            panels,
            nodes,
            weights,
        }
    }

    /// `panels` panels of width `width` from `start` (exactly that width, unlike [`Self::new`]).
    pub(crate) fn equal(start: f64, width: f64, panels: usize) -> Self {
        let mut out = Self::new(start, start + width, width);
        out.panels = panels.max(1);
        out.width = width;
        out
    }

    /// The nodes and weights of every panel, in order.
    pub(crate) fn grid(&self) -> PanelGrid {
        PanelGrid::equal(self.start, self.width, self.panels)
    }

    /// The interpolant of `values` (one per node of [`Self::grid`]) at `s` (0 beyond the end).
    pub(crate) fn eval(&self, values: &[f64], s: f64) -> f64 {
        self.weights_at(s).map_or(0.0, |(k, w)| {
            w.iter()
                .zip(&values[20 * k..20 * (k + 1)])
                .map(|(w, v)| w * v)
                .sum()
        })
    }

    /// The interpolation weights at `s`: its panel k and the weights of that panel's 20 values
    /// (barycentric formula); None beyond the grid.
    pub(crate) fn weights_at(&self, s: f64) -> Option<(usize, [f64; 20])> {
        let u = (s - self.start) / self.width;
        if !(0.0..=self.panels as f64).contains(&u) {
            return None;
        }
        let k = (u.floor() as usize).min(self.panels - 1);
        let x = 2.0 * (u - k as f64) - 1.0;
        let mut out = [0.0; 20];
        let mut den = 0.0;
        for (j, (xj, wj)) in self.nodes.iter().zip(&self.weights).enumerate() {
            let dx = x - xj;
            if dx == 0.0 {
                let mut one = [0.0; 20];
                one[j] = 1.0;
                return Some((k, one));
            }
            out[j] = wj / dx;
            den += out[j];
        }
        out.iter_mut().for_each(|w| *w /= den);
        Some((k, out))
    }

    /// The interpolant of a table with one row per node (`rows`, each of equal length) at `s`:
    /// None beyond the grid or when the table does not match it.
    pub(crate) fn rows_at(&self, rows: &[Vec<f64>], s: f64) -> Option<Vec<f64>> {
        if rows.len() != 20 * self.panels {
            return None;
        }
        let (k, w) = self.weights_at(s)?;
        let mut out = vec![0.0; rows[20 * k].len()];
        for (wj, row) in w.iter().zip(&rows[20 * k..20 * (k + 1)]) {
            for (o, v) in out.iter_mut().zip(row) {
                *o += wj * v;
            }
        }
        Some(out)
    }
}
