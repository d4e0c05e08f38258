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
//! Two coefficients are read at each trial: the edge node's force over √h (h the mean of its
//! two elements; [`EdgeFit::r_o_force`], what the study uses) and the √ coefficient a of a fit
//! g = a s^{1/2} + b s^{3/2} + c s^{5/2} to the gap's first three open nodes ([`EdgeFit::r_o`],
//! kept as a record). Both are local extractions, so both roots carry the elements' own
//! first-order error β c h (the nodal fields of the s^{3/2} edge field are not exact at the
//! scale of one element). Measured (example 22, five random infinite plates, levels down to
//! h = D/1024): the force root's error is of one sign (positive) and falls 1.93–1.99× per
//! level on every plate, the gap fit's changes sign with ν (as the gap-shape estimate of
//! [`super::separation`] does) and falls irregularly (0.3–4.9×). So the study takes the force
//! root and, with the elements at the edge the same in units of h on every level (the mesh of
//! a fitted study has four elements of exactly h on either side of the previous root, and the axial grading shrinks like √h, not h^{1/4}, so the far
//! mesh's error is second order), removes the first-order term by Richardson in h,
//! 2R_k − R_{k−1} ([`extrapolated`]). The interaction-integral extraction, whose error would
//! be a product of two FE errors, was not built (its axisymmetric terms).
//!
//! Units: those of the level (any consistent set).
//!
//! # Accuracy
//!
//! Example 22 (`examples/22_fe_edge.rs`) against the receding contact and the holed
//! semi-analytic route: the extrapolated values were +1.5e-7 … +5.0e-7 R_o at h = D/1024 and
//! +1.3e-6 … +3.5e-6 at D/512 (the gap-shape estimate at D/512: |error| 3.4e-8 … 2.4e-5 of
//! either sign); the studies with
//! `fitted_edge` are within their estimates (at most 0.49 of them) on the survey of that
//! example. `tests/contact/edge_fit.rs`: the root on quadratics, the trial edges on a
//! synthetic system with a known root, the force root's first order and the study's estimate
//! against the receding contact on two plates.
//!
//! # Cost
//!
//! One dense Cholesky of the closed window points per trial edge, four trials per level (the
//! window holds < 40 points past the first level): small beside the level's factorization.
//! The fitted study needs more levels than the gap-shape one at a tight tolerance (its
//! estimate, of the extrapolated values, falls ~2× per level): Table 1's first row at 1e-6 took
//! 11 levels (example 23).
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
    for &e in &corners[lo..=hi] {
        let closed: Vec<usize> = (0..m)
            .filter(|&q| (q < first && active[q]) || (q >= first && q <= e))
            .collect();
        let (a, f) = coefficient(sys, radius, &closed, e)?;
        let i = w[e];
        let h = 0.5 * (radius[(i + step).min(radius.len() - 1)] - radius[i.saturating_sub(step)]);
        trials.push((radius[i], a));
        forces.push((radius[i], f / h.sqrt()));
    }
    let r_o = root(&trials)?;
    Some(EdgeFit {
        r_o,
        trials,
        r_o_force: root(&forces),
    })
}

/// The √ coefficient a of the gap beyond the edge at window position `e` with `closed` held.
fn coefficient(sys: &EdgeSystem, radius: &[f64], closed: &[usize], e: usize) -> Option<(f64, f64)> {
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
    Some((c[0], edge_force))
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
