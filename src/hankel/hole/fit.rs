//! Least-squares collocation of the hole traction: the amplitudes of the Lamé field, of N
//! Papkovich–Fadle modes ([`super::eigen`]) and of extra given columns (the corner enrichment)
//! that cancel σ_r and τ_rz of the (extended-load) slab on the hole r = A.
//!
//! **Points.** σ_r is even and τ_rz odd in z, and so is every mode: only 0 ≤ z ≤ D is fitted.
//! Collocation heights z_j = D cos(πj/(2M)), j = 0…M (Chebyshev–Lobatto points of [−D, D] on
//! its upper half, clustered at the corner z = D where the modes' traction varies fastest),
//! M = 2N, or 4N with the corner enrichment; check heights at the midpoints
//! θ = π(j + ½)/(2M) — exactly the new points of the grid for 2N modes, so an adaptive doubling
//! of N reuses every slab evaluation.
//!
//! **System.** Unknowns: the Lamé amplitude c₀, (α_k, β_k) with mode k entering as
//! α_k Re F_k + β_k Im F_k, and any extra real columns given on the boundaries (the corner
//! enrichment of [`super::corner`], four per exponent); equations: σ_r and τ_rz at every z_j,
//! 2(M + 1) rows (at least about twice the unknowns). With a rim r = C the same heights are used
//! there too, and the unknowns add the uniform in-plane state and N modes growing outward.
//! Columns are scaled to unit norm and the system is solved by Householder QR, whose small
//! triangle's singular values give the condition number of the scaled matrix (reported; with
//! the enrichment up to ~1e9 at N = 32: the singular fields and the modes overlap away from the
//! corner; the residual is measured, not inferred); past 1e12 by the SVD instead, singular
//! values below 1e-14 of the largest dropped (QR: 2.6 ms, the SVD: 7.4 ms at
//! 258 × 129).
//!
//! **Residual.** The residual traction σ_r, τ_rz of slab + correction (extra columns included)
//! on the union of collocation and check heights, max and RMS (trapezoid in θ, the Chebyshev
//! measure), divided by P.
//!
//! # Accuracy
//!
//! The residual falls at the corner exponent's rate with modes alone and much faster with the
//! enrichment; the fitted correction is homogeneous; the hole is free and the faces loaded between
//! the fitted heights (`tests/hankel/hole_correction.rs`).
//!
//! # Cost
//!
//! A Householder QR of (2N + 4·corner terms) columns per N (`cargo bench --bench hole`, fit at N =
//! 16).
//!
//! ```
//! use boltzone::hankel::hole::fit::heights;
//! let z = heights(0.1, 8);
//! assert_eq!(z.len(), 9);
//! assert!((z[0] - 0.1).abs() < 1e-17 && z[8].abs() < 1e-17);
//! ```

use super::eigen::Mode;
use nalgebra::{DMatrix, DVector};
use num_complex::Complex64;
use std::f64::consts::FRAC_PI_2;

/// Heights D cos(πj/(2m)), j = 0…m: from the face z = D down to the midplane.
pub fn heights(d: f64, m: usize) -> Vec<f64> {
    (0..=m)
        .map(|j| {
            let z = d * (FRAC_PI_2 * j as f64 / m as f64).cos();
            if j == m {
                0.0
            } else {
                z
            }
        })
        .collect()
}

/// Slab traction (σ_r, τ_rz) on the hole at one height.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HoleData {
    /// Height z.
    pub z: f64,
    /// σ_r(A, z) of the slab.
    pub sigma_r: f64,
    /// τ_rz(A, z) of the slab.
    pub tau_rz: f64,
}

/// The slab's traction on one cylinder (the hole r = A, or a rim r = C) at the fitted heights.
#[derive(Debug, Clone, Copy)]
pub struct Boundary<'a> {
    /// Radius of the cylinder.
    pub r: f64,
    /// Slab traction at heights from the face down to the midplane.
    pub data: &'a [HoleData],
    /// Extra real columns (the corner enrichment, [`super::corner`]) at the same heights: for
    /// height i, `extra[2Mi..2Mi + M]` their σ_r and `extra[2Mi + M..2M(i + 1)]` their τ_rz,
    /// M = [`Fit::extra`]`.len()` (empty when there are none).
    pub extra: &'a [f64],
}

/// Fitted amplitudes and the quality of the fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// Hole radius A of the Lamé field.
    pub a: f64,
    /// Lamé amplitude c₀ (σ_r = −c₀ (A/r)²).
    pub lame: f64,
    /// Amplitude of the uniform state σ_r = σ_θ (0 without a rim).
    pub uniform: f64,
    /// Complex amplitudes c_k: mode k contributes Re(c_k F_k).
    pub modes: Vec<Complex64>,
    /// Amplitudes of the extra real columns of [`Boundary::extra`].
    pub extra: Vec<f64>,
    /// Condition number of the column-scaled collocation matrix.
    pub condition: f64,
    /// Singular values dropped as below 1e-14 of the largest.
    pub dropped: usize,
}

/// The least-squares amplitudes cancelling the slab's traction on every boundary with `modes`,
/// the Lamé field of the hole radius `a`, (if `uniform`) the uniform in-plane state, and
/// `columns` extra real fields given on the boundaries ([`Boundary::extra`]).
pub fn fit(modes: &[Mode], a: f64, uniform: bool, columns: usize, boundaries: &[Boundary]) -> Fit {
    let extra = 1 + usize::from(uniform);
    let first_extra = extra + 2 * modes.len();
    let n = first_extra + columns;
    let rows = 2 * boundaries.iter().map(|b| b.data.len()).sum::<usize>();
    let mut m = DMatrix::<f64>::zeros(rows, n);
    let mut rhs = DVector::<f64>::zeros(rows);
    let mut i = 0;
    for bd in boundaries {
        let radial: Vec<_> = modes.iter().map(|md| md.radial(bd.r)).collect();
        for (h, p) in bd.data.iter().enumerate() {
            m[(i, 0)] = -(a / bd.r) * (a / bd.r); // Lamé σ_r, τ = 0
            for c in 0..columns {
                m[(i, first_extra + c)] = bd.extra[2 * columns * h + c];
                m[(i + 1, first_extra + c)] = bd.extra[2 * columns * h + columns + c];
            }
            if uniform {
                m[(i, 1)] = 1.0;
            }
            rhs[i] = -p.sigma_r;
            rhs[i + 1] = -p.tau_rz;
            for (k, (md, rad)) in modes.iter().zip(&radial).enumerate() {
                let (sr, tau) = md.traction_at(*rad, bd.r, p.z);
                m[(i, extra + 2 * k)] = sr.re;
                m[(i, extra + 2 * k + 1)] = sr.im;
                m[(i + 1, extra + 2 * k)] = tau.re;
                m[(i + 1, extra + 2 * k + 1)] = tau.im;
            }
            i += 2;
        }
    }
    let scale: Vec<f64> = (0..n)
        .map(|j| {
            let s = m.column(j).norm();
            if s > 0.0 {
                1.0 / s
            } else {
                1.0
            }
        })
        .collect();
    for (j, s) in scale.iter().enumerate() {
        m.column_mut(j).scale_mut(*s);
    }
    // Householder QR (backward stable: the residual is near-optimal while the scaled matrix
    // is far from rank-deficient); the singular values of the small triangle R — those of the
    // scaled matrix — give the condition number. Past 1e12 the SVD's truncated solve instead.
    let (rows_m, _) = m.shape();
    let (x, smax, smin, kept) = if rows_m >= n {
        let qr = m.clone().qr();
        let r = qr.r();
        let sv = r.singular_values();
        let (smax, smin) = (sv.max(), sv.min());
        let solved = (smin > 1e-12 * smax)
            .then(|| {
                let mut qtb = rhs.clone();
                qr.q_tr_mul(&mut qtb);
                let qtb = qtb.rows(0, n).into_owned();
                r.solve_upper_triangular(&qtb)
            })
            .flatten();
        match solved {
            Some(x) => (x, smax, smin, n),
            None => svd_solve(m, &rhs),
        }
    } else {
        svd_solve(m, &rhs)
    };
    let c: Vec<f64> = (0..n).map(|j| x[j] * scale[j]).collect();
    Fit {
        a,
        lame: c[0],
        uniform: if uniform { c[1] } else { 0.0 },
        modes: (0..modes.len())
            .map(|k| Complex64::new(c[extra + 2 * k], -c[extra + 2 * k + 1]))
            .collect(),
        extra: c[first_extra..].to_vec(),
        condition: smax / smin,
        dropped: n - kept,
    }
}

/// The least-squares solution by the SVD, singular values below 1e-14 of the largest dropped:
/// (x, largest, smallest kept, number kept).
fn svd_solve(m: DMatrix<f64>, rhs: &DVector<f64>) -> (DVector<f64>, f64, f64, usize) {
    let n = m.ncols();
    let svd = m.svd(true, true);
    let smax = svd.singular_values.max();
    let cut = 1e-14 * smax;
    let kept = svd.singular_values.iter().filter(|&&s| s > cut).count();
    let smin = svd
        .singular_values
        .iter()
        .copied()
        .filter(|&s| s > cut)
        .fold(f64::INFINITY, f64::min);
    let x = svd.solve(rhs, cut).unwrap_or_else(|_| DVector::zeros(n));
    (x, smax, smin, kept)
}

impl Fit {
    /// The Lamé and mode part of the correction's traction (σ_r, τ_rz) on the cylinder of
    /// radius r at height z (without the extra columns, which are known only where given).
    pub fn traction(&self, modes: &[Mode], r: f64, z: f64) -> (f64, f64) {
        let radial: Vec<_> = modes.iter().map(|m| m.radial(r)).collect();
        self.traction_at(modes, &radial, r, z)
    }

    /// [`Self::traction`] with every mode's radial factors at r given.
    fn traction_at(
        &self,
        modes: &[Mode],
        radial: &[(Complex64, Complex64)],
        r: f64,
        z: f64,
    ) -> (f64, f64) {
        let q = (self.a / r) * (self.a / r);
        modes.iter().zip(radial).zip(&self.modes).fold(
            (-self.lame * q + self.uniform, 0.0),
            |(sr, tau), ((m, rad), c)| {
                let (ms, mt) = m.traction_at(*rad, r, z);
                (sr + (c * ms).re, tau + (c * mt).re)
            },
        )
    }

    /// Max and RMS of the residual traction |(σ_r, τ_rz)| of slab + correction on `boundary`
    /// (heights on a θ-grid from the face to the midplane, as [`heights`] gives them), absolute.
    pub fn residual(&self, modes: &[Mode], boundary: &Boundary) -> (f64, f64) {
        let mut max = 0.0f64;
        let mut sum = 0.0;
        let data = boundary.data;
        let last = data.len() - 1;
        let radial: Vec<_> = modes.iter().map(|m| m.radial(boundary.r)).collect();
        let m = self.extra.len();
        for (i, p) in data.iter().enumerate() {
            let (mut sr, mut tau) = self.traction_at(modes, &radial, boundary.r, p.z);
            for (c, x) in self.extra.iter().enumerate() {
                sr += x * boundary.extra[2 * m * i + c];
                tau += x * boundary.extra[2 * m * i + m + c];
            }
            let r = (p.sigma_r + sr).hypot(p.tau_rz + tau);
            max = max.max(r);
            let w = if i == 0 || i == last { 0.5 } else { 1.0 };
            sum += w * r * r;
        }
        (max, (sum / last as f64).sqrt())
    }
}
