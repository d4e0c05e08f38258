//! Least-squares collocation of the hole traction: the amplitudes of the Lamé field and of N
//! Papkovich–Fadle modes ([`super::eigen`]) that cancel σ_r and τ_rz of the (extended-load) slab
//! on the hole r = A.
//!
//! **Points.** σ_r is even and τ_rz odd in z, and so is every mode: only 0 ≤ z ≤ D is fitted.
//! Collocation heights z_j = D cos(πj/(2M)), j = 0…M, M = 2N (Chebyshev–Lobatto points of
//! [−D, D] on its upper half, clustered at the corner z = D where the modes' traction varies
//! fastest); check heights at the midpoints θ = π(j + ½)/(2M) — exactly the new points of the
//! grid for 2N modes, so an adaptive doubling of N reuses every slab evaluation.
//!
//! **System.** Unknowns: the Lamé amplitude c₀ and (α_k, β_k) with mode k entering as
//! α_k Re F_k + β_k Im F_k; equations: σ_r and τ_rz at every z_j, 2(M + 1) rows for 2N + 1
//! unknowns (twofold oversampling). Columns are scaled to unit norm and the system is solved by
//! the SVD (singular values below 1e-14 of the largest dropped); the condition number of the
//! scaled matrix is reported.
//!
//! **Residual.** The residual traction σ_r, τ_rz of slab + correction on the union of collocation
//! and check heights, max and RMS (trapezoid in θ, the Chebyshev measure), divided by P.
//!
//! ```
//! use boltzone::hankel::hole::fit::heights;
//! let z = heights(0.1, 4);
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

/// Fitted amplitudes and the quality of the fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// Lamé amplitude c₀ (σ_r(A) = −c₀).
    pub lame: f64,
    /// Complex amplitudes c_k: mode k contributes Re(c_k F_k).
    pub modes: Vec<Complex64>,
    /// Condition number of the column-scaled collocation matrix.
    pub condition: f64,
    /// Singular values dropped as below 1e-14 of the largest.
    pub dropped: usize,
}

/// The least-squares amplitudes cancelling `data` with `modes` (plus the Lamé field).
pub fn fit(modes: &[Mode], data: &[HoleData]) -> Fit {
    let n = 1 + 2 * modes.len();
    let rows = 2 * data.len();
    let mut a = DMatrix::<f64>::zeros(rows, n);
    let mut b = DVector::<f64>::zeros(rows);
    for (i, p) in data.iter().enumerate() {
        a[(2 * i, 0)] = -1.0; // Lamé σ_r(A) = −1, τ = 0
        b[2 * i] = -p.sigma_r;
        b[2 * i + 1] = -p.tau_rz;
        for (k, m) in modes.iter().enumerate() {
            let (sr, tau) = m.hole_traction(p.z);
            a[(2 * i, 1 + 2 * k)] = sr.re;
            a[(2 * i, 2 + 2 * k)] = sr.im;
            a[(2 * i + 1, 1 + 2 * k)] = tau.re;
            a[(2 * i + 1, 2 + 2 * k)] = tau.im;
        }
    }
    let scale: Vec<f64> = (0..n)
        .map(|j| {
            let s = a.column(j).norm();
            if s > 0.0 {
                1.0 / s
            } else {
                1.0
            }
        })
        .collect();
    for (j, s) in scale.iter().enumerate() {
        a.column_mut(j).scale_mut(*s);
    }
    let svd = a.svd(true, true);
    let smax = svd.singular_values.max();
    let cut = 1e-14 * smax;
    let kept: Vec<f64> = svd
        .singular_values
        .iter()
        .copied()
        .filter(|&s| s > cut)
        .collect();
    let dropped = n - kept.len();
    let smin = kept.iter().copied().fold(f64::INFINITY, f64::min);
    let x = svd.solve(&b, cut).unwrap_or_else(|_| DVector::zeros(n));
    let c: Vec<f64> = (0..n).map(|j| x[j] * scale[j]).collect();
    Fit {
        lame: c[0],
        modes: (0..modes.len())
            .map(|k| Complex64::new(c[1 + 2 * k], -c[2 + 2 * k]))
            .collect(),
        condition: smax / smin,
        dropped,
    }
}

impl Fit {
    /// The correction's traction (σ_r, τ_rz) on the hole at height z.
    pub fn hole_traction(&self, modes: &[Mode], z: f64) -> (f64, f64) {
        modes
            .iter()
            .zip(&self.modes)
            .fold((-self.lame, 0.0), |(sr, tau), (m, c)| {
                let (ms, mt) = m.hole_traction(z);
                (sr + (c * ms).re, tau + (c * mt).re)
            })
    }

    /// Max and RMS of the residual traction |(σ_r, τ_rz)| of slab + correction over `data`
    /// (heights on a θ-grid from the face to the midplane, as [`heights`] gives them), absolute.
    pub fn residual(&self, modes: &[Mode], data: &[HoleData]) -> (f64, f64) {
        let mut max = 0.0f64;
        let mut sum = 0.0;
        let last = data.len() - 1;
        for (i, p) in data.iter().enumerate() {
            let (sr, tau) = self.hole_traction(modes, p.z);
            let r = (p.sigma_r + sr).hypot(p.tau_rz + tau);
            max = max.max(r);
            let w = if i == 0 || i == last { 0.5 } else { 1.0 };
            sum += w * r * r;
        }
        (max, (sum / last as f64).sqrt())
    }
}
