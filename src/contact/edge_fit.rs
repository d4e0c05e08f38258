//! R_o as the root of the contact edge's singular coefficient, on one mesh level, and the
//! study's first-order extrapolation of those roots (issue 36).
//!
//! Hold the plates closed exactly on the interface nodes up to a trial edge ρ (a corner node)
//! and open beyond. The exact solution of that bilateral problem has, at ρ, a pressure
//! p ≈ K(ρ)/√(ρ − r) + c √(ρ − r) and a gap g ≈ −κK(ρ)√(r − ρ) + c′(r − ρ)^{3/2} (for equal
//! plates the open interface is a crack in the mirrored plate and ρ its tip: K is the mode-I
//! stress intensity). K(ρ) > 0 for an edge short of the true one (the plates would overlap
//! beyond it), < 0 beyond it (they would pull), and zero exactly at the smooth receding
//! separation R_o (Signorini: p ≥ 0, g ≥ 0 on both sides). K is smooth in ρ.
//!
//! The level's interface Schur complement g = g⁰ + Fλ on the LCP window ([`super::level`])
//! gives the bilateral solution for any trial edge at a node without a new factorization: the
//! forces λ_J = −F_JJ⁻¹ g⁰_J of the closed set J and the gaps g⁰ + F λ beyond. Trial edges are
//! the corner nodes near the LCP's edge (two at or before it, two after), so that each trial
//! meets the same elements (an edge inside a quadratic element would not); R_o is the root of
//! the quadratic through the coefficient at the three trials nearest the sign change
//! ([`root`]), so no mesh is moved and no matrix refactored.
//!
//! Three coefficients are read at each trial: the edge node's force over √h (h the mean of
//! its two elements; [`EdgeFit::r_o_force`], what the study uses); K of a least-squares fit
//! p = K s^{-1/2} + c s^{1/2} + d s^{3/2} (s = ρ − r) to the reactions of the last five closed
//! nodes, each reaction being the consistent force ∫ p N_i 2πr dr of its closed elements
//! ([`EdgeFit::r_o_reaction`], a record); and the √ coefficient a of a fit
//! g = a s^{1/2} + b s^{3/2} + c s^{5/2} to the gap's first three open nodes ([`EdgeFit::r_o`],
//! a record).
//!
//! # Why each root is first order in h
//!
//! At the true edge K = 0 and the field is the next term of the crack-tip expansion: p ∝
//! √(R_o − r), displacements ∝ ϱ^{3/2} in the distance ϱ from the edge. On a mesh that is the
//! same in units of h near the edge (four elements of exactly h either side of the previous
//! root), the elements' error of that field is, by scaling, c h^{3/2} times a fixed pattern in
//! the nodal forces — the same size as the regular term's own share c h^{3/2} of a node's
//! force, which the edge force carries and the reaction fit removes. Any extraction from the
//! nodes within a few h of the edge therefore reads K with an error ∝ c h, and its root an
//! error β h with β set by the extraction and the local mesh pattern. Measured (example 22,
//! `survey`): the force root +, ratios 1.93–1.99 per level; the reaction fit −, half the size,
//! ratios 2.0–2.16; fits of three to seven nodes with two to four terms move β, none removes
//! it. Only an extraction whose weight is smooth on a scale fixed in D (an interaction or
//! reciprocal-work integral: Babuška & Miller, IJNME 20 (1984) 1111; Stern, Becker & Dunham,
//! Int. J. Fract. 12 (1976) 359) or an enrichment with the ϱ^{3/2} field would lift the order;
//! neither is built (the axisymmetric domain terms).
//!
//! So the study takes the force root and, with the mesh at the edge the same in units of h
//! on every level, removes β h by Richardson in h, 2R_k − R_{k−1} ([`extrapolated`]). The
//! two roots' Richardson values agree to 5e-7 … 2e-6 of R_o at h = D/128 (six plates) while
//! their raw errors are ~1e-4: what remains belongs to the field, not to the extraction — the graded mesh
//! away from the edge (its growth ratio shrinks like √h below D/64, so that part falls roughly
//! first order, irregularly: +1.5e-7 … +8.0e-7 R_o at h = D/1024 on 39 plates), then a
//! residual of +2e-7 … +5.4e-7 at D/1024 … D/2048 whatever the grading (finer, fixed or
//! shrunk like h) or the largest element (10× smaller). With the first elements across the
//! plates from the interface also exactly h on every level, that residual is within 3.3e-7 of
//! R_o at D/512 … D/2048 (example 28). The study adds a floor of 5e-7 R_o for it
//! (`two_plate::FITTED_FLOOR`).
//!
//! Units: those of the level (any consistent set).
//!
//! # Accuracy
//!
//! Example 22 against the receding contact (no hole) and the holed semi-analytic route:
//! extrapolated values +1.5e-7 … +5.0e-7 R_o at h = D/1024, +1.3e-6 … +3.5e-6 at D/512
//! (the gap-shape estimate of [`super::separation`] at D/512: |error| 3.4e-8 … 2.4e-5 of
//! either sign); studies at 1e-4 and 1e-5 within their estimates (`check`; counts in
//! docs/fem.md). `tests/contact/edge_fit.rs`: the root on quadratics, the trial edges on a
//! synthetic system with a known root, both roots' first order, their shared Richardson
//! limit and the study's estimate against the receding contact on two plates.
//!
//! # Cost
//!
//! One dense Cholesky of the closed window points per trial edge, four trials per level (the
//! window holds < 40 points past the first level), and a 5 × 3 least-squares fit: small
//! beside the level's factorization. The fitted study needs more levels than the gap-shape
//! one at a tight tolerance (its estimate falls ~2× per level): 8–9 levels at 1e-5 on
//! infinite plates (1–3 s); Table 1's rows at 2e-6, 10–11 levels and 3–10 s (example 23).
//!
//! ```
//! use boltzone::contact::edge_fit::root;
//! // a coefficient falling through zero at 0.345 between corner trials 0.01 apart
//! let t: Vec<(f64, f64)> = (0..4).map(|i| 0.33 + 0.01 * i as f64).map(|x| (x, 0.345 - x)).collect();
//! assert!((root(&t).unwrap() - 0.345).abs() < 1e-15);
//! ```

use nalgebra::{DMatrix, DVector};

/// The interface Schur complement of one level: gaps g = g⁰ + F λ of the window points
/// (normal components only: frictionless or symmetric contact).
#[derive(Debug, Clone, PartialEq)]
pub struct EdgeSystem {
    /// Radial line of each window point, increasing.
    pub window: Vec<usize>,
    /// Flexibility F (window × window).
    pub flexibility: DMatrix<f64>,
    /// Gaps under the load alone, g⁰.
    pub gap0: DVector<f64>,
}

/// The fitted edge of one level.
#[derive(Debug, Clone, PartialEq)]
pub struct EdgeFit {
    /// The root of the edge coefficient: R_o on this level.
    pub r_o: f64,
    /// (trial edge ρ, gap coefficient a(ρ)) at the corner edges used.
    pub trials: Vec<(f64, f64)>,
    /// The root of the edge node's force over √h (h the mean of its two elements).
    pub r_o_force: Option<f64>,
    /// The root of K, the s^{-1/2} coefficient fitted to the reactions of the last closed
    /// nodes (module docs).
    pub r_o_reaction: Option<f64>,
}

/// How many window points beyond a trial edge the gap fit reads.
const FIT_POINTS: usize = 3;

/// The fitted edge (module docs). `radius` are the interface node radii, `active` the LCP's
/// closed state of each window point, `step` the radial lines per element (2 for quadratic
/// elements, 1 for linear). None when the window does not hold the edge's neighbourhood.
pub fn fit(sys: &EdgeSystem, radius: &[f64], active: &[bool], step: usize) -> Option<EdgeFit> {
    let w = &sys.window;
    let m = w.len();
    let k = (0..m).rev().find(|&q| active[q])?;
    // Window positions of corner nodes around the LCP's edge: two at or before it, two after.
    let corners: Vec<usize> = (0..m)
        .filter(|&q| w[q] % step == 0 && q + FIT_POINTS < m)
        .filter(|&q| (0..=FIT_POINTS).all(|i| w[q + i] == w[q] + i))
        .collect();
    let at = corners.iter().rposition(|&q| q <= k)?;
    let lo = at.checked_sub(1)?;
    let hi = (at + 2).min(corners.len() - 1);
    let first = corners[lo.saturating_sub(1)];
    let mut trials = Vec::new();
    let mut forces = Vec::new();
    let mut ks = Vec::new();
    for &e in &corners[lo..=hi] {
        let closed: Vec<usize> = (0..m)
            .filter(|&q| (q < first && active[q]) || (q >= first && q <= e))
            .collect();
        let (a, f, lambda) = coefficient(sys, radius, &closed, e)?;
        let i = w[e];
        if let Some(k) = reaction_k(sys, radius, &closed, &lambda, e, step) {
            ks.push((radius[i], k));
        }
        let h = 0.5 * (radius[(i + step).min(radius.len() - 1)] - radius[i.saturating_sub(step)]);
        trials.push((radius[i], a));
        forces.push((radius[i], f / h.sqrt()));
    }
    let r_o = root(&trials)?;
    Some(EdgeFit {
        r_o,
        trials,
        r_o_force: root(&forces),
        r_o_reaction: (ks.len() == hi + 1 - lo).then(|| root(&ks)).flatten(),
    })
}

/// The √ coefficient a of the gap beyond the edge at window position `e` with `closed` held.
fn coefficient(
    sys: &EdgeSystem,
    radius: &[f64],
    closed: &[usize],
    e: usize,
) -> Option<(f64, f64, DVector<f64>)> {
    let n = closed.len();
    let f = &sys.flexibility;
    let fjj = DMatrix::from_fn(n, n, |i, j| f[(closed[i], closed[j])]);
    let rhs = DVector::from_fn(n, |i, _| -sys.gap0[closed[i]]);
    let lambda = fjj.cholesky()?.solve(&rhs);
    let gap = |q: usize| {
        sys.gap0[q]
            + closed
                .iter()
                .zip(lambda.iter())
                .map(|(&j, l)| f[(q, j)] * l)
                .sum::<f64>()
    };
    let rho = radius[sys.window[e]];
    let mut a = DMatrix::<f64>::zeros(FIT_POINTS, FIT_POINTS);
    let mut b = DVector::<f64>::zeros(FIT_POINTS);
    for i in 0..FIT_POINTS {
        let q = e + 1 + i;
        let s = radius[sys.window[q]] - rho;
        for j in 0..FIT_POINTS {
            a[(i, j)] = s.powf(0.5 + j as f64);
        }
        b[i] = gap(q);
    }
    let c = a.lu().solve(&b)?;
    let edge_force = lambda[closed.iter().position(|&q| q == e)?];
    Some((c[0], edge_force, lambda))
}

/// Closed nodes whose reactions [`reaction_k`] fits (least squares).
const REACTION_POINTS: usize = 5;
/// Terms of that fit: s^{-1/2}, s^{1/2}, s^{3/2}.
const REACTION_TERMS: usize = 3;

/// K of p = K s^{-1/2} + c s^{1/2} + d s^{3/2} (s = ρ − r) fitted to the reactions λ of the
/// last closed nodes up to the trial edge at window position `e`: each reaction is the
/// consistent force ∫ p N_i 2πr dr over the closed elements at node i (N_i the element's
/// interface trace: quadratic for `step` 2, linear for 1).
fn reaction_k(
    sys: &EdgeSystem,
    radius: &[f64],
    closed: &[usize],
    lambda: &DVector<f64>,
    e: usize,
    step: usize,
) -> Option<f64> {
    let w = &sys.window;
    let (m, terms) = (REACTION_POINTS, REACTION_TERMS);
    let ie = w[e];
    let rho = radius[ie];
    let pos = closed.iter().position(|&q| q == e)?;
    if pos + 1 < m || e + 1 < m || ie < m + step {
        return None;
    }
    // the last m closed nodes: window positions e−m+1..=e on consecutive lines
    for j in 0..m {
        let q = e - j;
        if w[q] != ie - j || closed.get(pos - j) != Some(&q) {
            return None;
        }
    }
    let gl = crate::numerics::quadrature::gauss_legendre(10);
    let mut a = DMatrix::<f64>::zeros(m, terms);
    let mut b = DVector::<f64>::zeros(m);
    for j in 0..m {
        let i = ie - j;
        b[j] = lambda[pos - j];
        // the closed elements holding line i: [first, first + step] with first ≤ i
        let starts: Vec<usize> = if i % step == 0 {
            [i.checked_sub(step), (i < ie).then_some(i)]
                .into_iter()
                .flatten()
                .collect()
        } else {
            vec![i - i % step]
        };
        for s0 in starts {
            let nodes: Vec<f64> = (0..=step).map(|l| radius[s0 + l]).collect();
            let me = i - s0;
            // ∫ s^{k−1/2} N(r) 2πr dr over [r0, r1] with s = t²: ∫ 2 t^{2k} N 2πr dt
            let (t0, t1) = ((rho - nodes[step]).max(0.0).sqrt(), (rho - nodes[0]).sqrt());
            for &(x, wt) in gl.iter() {
                let t = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * x;
                let r = rho - t * t;
                let mut n = 1.0;
                for (l, &rl) in nodes.iter().enumerate() {
                    if l != me {
                        n *= (r - rl) / (nodes[me] - rl);
                    }
                }
                let base = 0.5 * (t1 - t0) * wt * 2.0 * n * 2.0 * std::f64::consts::PI * r;
                for k in 0..terms {
                    a[(j, k)] += base * t.powi(2 * k as i32);
                }
            }
        }
    }
    // columns scaled to unit size, least squares by QR
    let h = radius[ie] - radius[ie - step];
    for k in 0..terms {
        let sc = h.powf(k as f64 - 0.5);
        for j in 0..m {
            a[(j, k)] /= sc;
        }
    }
    let c = if m == terms {
        a.lu().solve(&b)?
    } else {
        let qr = a.qr();
        let qtb = qr.q().transpose() * &b;
        qr.r().solve_upper_triangular(&qtb)?
    };
    Some(c[0] * h.sqrt())
}

/// The root of the coefficient sampled at `t` (ρ, value), ρ increasing: the quadratic through
/// the sign change's two trials and the neighbour on the side nearer the root (linear with two
/// trials). None without a sign change.
pub fn root(t: &[(f64, f64)]) -> Option<f64> {
    let i = t
        .windows(2)
        .position(|p| (p[0].1 > 0.0) != (p[1].1 > 0.0))?;
    let (x0, y0) = t[i];
    let (x1, y1) = t[i + 1];
    let lin = x0 - y0 * (x1 - x0) / (y1 - y0);
    let third = if i + 2 < t.len() && (i == 0 || lin - x0 > x1 - lin) {
        Some(i + 2)
    } else {
        i.checked_sub(1).or((i + 2 < t.len()).then_some(i + 2))
    };
    let Some(j) = third else {
        return Some(lin);
    };
    // Newton form through (x0, y0), (x1, y1), (x2, y2): q(x0 + u) = y0 + d1 u + d2 u (u − (x1 − x0))
    let (x2, y2) = t[j];
    let d1 = (y1 - y0) / (x1 - x0);
    let d2 = ((y2 - y1) / (x2 - x1) - d1) / (x2 - x0);
    let (qa, qb, qc) = (d2, d1 - d2 * (x1 - x0), y0);
    let disc = qb * qb - 4.0 * qa * qc;
    if qa == 0.0 || disc < 0.0 {
        return Some(lin);
    }
    // both roots, stably; the one nearer the linear root
    let big = -0.5 * (qb + qb.signum() * disc.sqrt());
    let roots = [big / qa, if big != 0.0 { qc / big } else { 0.0 }];
    let u = roots
        .into_iter()
        .filter(|u| u.is_finite())
        .min_by(|a, b| (x0 + a - lin).abs().total_cmp(&(x0 + b - lin).abs()))?;
    let x = x0 + u;
    // (a root outside the bracketing pair: the curvature is not resolved, keep the line)
    Some(if x >= x0 && x <= x1 { x } else { lin })
}

/// The study's R_o from the levels' fitted edges: the first level's, then the first-order
/// Richardson values 2R_k − R_{k−1} (each level halves h; module docs).
///
/// ```
/// use boltzone::contact::edge_fit::extrapolated;
/// // R_k = 1 + 0.3 h_k, h halved per level: every extrapolated value after the first is 1
/// let raw: Vec<f64> = (0..4).map(|k| 1.0 + 0.3 * 0.5f64.powi(k)).collect();
/// assert!(extrapolated(&raw)[1..].iter().all(|r| (r - 1.0).abs() < 1e-15));
/// ```
pub fn extrapolated(raw: &[f64]) -> Vec<f64> {
    raw.iter()
        .enumerate()
        .map(|(k, &r)| if k == 0 { r } else { 2.0 * r - raw[k - 1] })
        .collect()
}
