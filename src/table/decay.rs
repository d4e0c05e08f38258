//! The decay of a self-equilibrated disturbance (the hole, its corner, the inner load edge)
//! along the contact zone, and its fit: Δ(x) ≈ D·Re[K e^(−λx)], x = distance/D, with
//! λ = [`DECAY_RATE`] + i·[`DECAY_WAVENUMBER`] the first root of sin 2λ + 2λ = 0 (the first
//! symmetric Papkovich–Fadle mode of the free plate 2D thick that the contact zone is, reflected
//! in the frictionless interface; DESIGN.md, "Why the hole is felt only near it").
//!
//! **Under a uniform load the hole is felt by a round trip.** The uniform state σ_z = −p,
//! σ_r = σ_θ = τ_rz = 0 satisfies every condition of the hole (and of its corner with the
//! loaded face) exactly, so the hole disturbs nothing until the load edge's own tail,
//! ∝ e^(−λ(R_o − A)/D), reaches it; its reflection travels back: Δ ∝ e^(−2αx)·(a + Re b e^(−2iβx)),
//! rate [`HANDOVER_RATE`] = 2α, dips of |Δ|e^(2αx) every π/β ≈ 2.79 D, and no sign change
//! while |b| < |a|. Example 24 measures that (docs/tables.md): no sign change on either model,
//! one-mode fits of the rate 3.9–4.1 (single plate) and 4.2–5.2 (two plates, where the second
//! mode, rate 5.36, mixes in) against 4.212.
//!
//! **Method.** [`fit_decay`] fits Δ = e^(−αx)(c₁ cos βx + c₂ sin βx) by Gauss–Newton with a
//! Levenberg damping on (α, β, c₁, c₂), each residual weighted by e^(α₀x) (α₀ the rate expected) so
//! that every point counts relative to the envelope; one-sigma uncertainties from
//! s²(JᵀJ)⁻¹ with s² the weighted residual sum over n − 4. [`sign_changes`] interpolates the
//! zeros of Δ linearly between neighbours.
//!
//! # Accuracy
//!
//! The fit recovers (α, β) of exact modal data to 1e-10 (unit test below); on the measured Δ
//! of both models the ignored study `tests/table/decay.rs` asserts the fitted rate at least
//! [`HANDOVER_RATE`] − 3σ and the handover bounds of `table::far` (example 24 prints the survey).
//!
//! # Cost
//!
//! A few Gauss–Newton steps on a 4 × 4 system: microseconds.
//!
//! ```
//! use boltzone::table::decay::{fit_decay, DecayPoint, DECAY_RATE, DECAY_WAVENUMBER};
//! let pts: Vec<DecayPoint> = (0..20)
//!     .map(|k| {
//!         let x = 1.0 + 0.4 * k as f64;
//!         let delta = 0.3 * (-DECAY_RATE * x).exp() * (DECAY_WAVENUMBER * x + 0.7).cos();
//!         DecayPoint { x, delta, error: 0.0 }
//!     })
//!     .collect();
//! let f = fit_decay(&pts, 1.0, DECAY_RATE).unwrap();
//! assert!((f.alpha - DECAY_RATE).abs() < 1e-8 && (f.k_abs - 0.3).abs() < 1e-8);
//! ```

use nalgebra::{Matrix4, Vector4};

/// Re λ of the first root λ of sin 2λ + 2λ = 0 (unit thickness D): the decay rate per D.
pub const DECAY_RATE: f64 = 2.106196;
/// Im λ of that root: the wavenumber per D (Δ changes sign every π/1.125364 ≈ 2.79 D).
pub const DECAY_WAVENUMBER: f64 = 1.125364;

/// The decay rate of the hole's effect on R_o under a uniform load: the round trip, 2α.
pub const HANDOVER_RATE: f64 = 2.0 * DECAY_RATE;

/// One measured difference: x = (R_o − A)/D, Δ/D and its estimated error (both runs').
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DecayPoint {
    /// (R_o − A)/D.
    pub x: f64,
    /// (R_o(holed) − R_o(no hole))/D.
    pub delta: f64,
    /// Estimated absolute error of `delta` (the two runs' estimates added), in D.
    pub error: f64,
}

impl DecayPoint {
    /// Whether |Δ| stands above 3 times its estimated error (fit and bound use only these).
    pub fn resolved(&self) -> bool {
        self.delta.abs() > 3.0 * self.error
    }
}

/// The fitted decay law Δ = e^(−αx)(c₁ cos βx + c₂ sin βx).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DecayFit {
    /// Fitted rate α (per D).
    pub alpha: f64,
    /// Its one-sigma uncertainty.
    pub alpha_sigma: f64,
    /// Fitted wavenumber β (per D).
    pub beta: f64,
    /// Its one-sigma uncertainty.
    pub beta_sigma: f64,
    /// |K| = √(c₁² + c₂²), in D.
    pub k_abs: f64,
    /// Points fitted.
    pub points: usize,
    /// Root-mean-square weighted residual relative to |K| (the misfit of the one-mode law).
    pub rms: f64,
}

/// Fits the one-mode law to the resolved points with x ≥ `x_min`, starting from and weighting
/// by the rate `rate0` (None below 6 points or when the normal equations are singular).
pub fn fit_decay(points: &[DecayPoint], x_min: f64, rate0: f64) -> Option<DecayFit> {
    let pts: Vec<&DecayPoint> = points
        .iter()
        .filter(|p| p.x >= x_min && p.resolved())
        .collect();
    if pts.len() < 6 {
        return None;
    }
    let weight = |x: f64| (rate0 * x).exp();
    let model = |q: &Vector4<f64>, x: f64| {
        (-q[0] * x).exp() * (q[2] * (q[1] * x).cos() + q[3] * (q[1] * x).sin())
    };
    let jacobian_row = |q: &Vector4<f64>, x: f64| {
        let e = (-q[0] * x).exp();
        let (s, c) = (q[1] * x).sin_cos();
        let m = e * (q[2] * c + q[3] * s);
        Vector4::new(-x * m, e * x * (q[3] * c - q[2] * s), e * c, e * s)
    };
    let normal = |q: &Vector4<f64>| {
        let (mut jtj, mut jtr, mut rss) = (Matrix4::zeros(), Vector4::zeros(), 0.0);
        for p in &pts {
            let w = weight(p.x);
            let r = w * (p.delta - model(q, p.x));
            let j = w * jacobian_row(q, p.x);
            jtj += j * j.transpose();
            jtr += j * r;
            rss += r * r;
        }
        (jtj, jtr, rss)
    };
    // start: the theoretical (α, β) and c by linear least squares at them
    let mut q = Vector4::new(rate0, DECAY_WAVENUMBER, 0.0, 0.0);
    let (jtj, jtr, _) = normal(&q);
    let lin = jtj.fixed_view::<2, 2>(2, 2).into_owned();
    let c = lin.try_inverse()? * jtr.fixed_rows::<2>(2).into_owned();
    q[2] = c[0];
    q[3] = c[1];
    let mut damping = 1e-6;
    let (_, _, mut rss) = normal(&q);
    for _ in 0..200 {
        let (jtj, jtr, _) = normal(&q);
        let mut a = jtj;
        for k in 0..4 {
            a[(k, k)] *= 1.0 + damping;
        }
        let step = a.try_inverse()? * jtr;
        let trial = q + step;
        let (_, _, trial_rss) = normal(&trial);
        if trial_rss <= rss {
            let small = step.norm() <= 1e-13 * (1.0 + q.norm());
            q = trial;
            rss = trial_rss;
            damping = (damping * 0.3).max(1e-12);
            if small {
                break;
            }
        } else {
            damping *= 10.0;
            if damping > 1e12 {
                break;
            }
        }
    }
    let (jtj, _, rss) = normal(&q);
    let dof = (pts.len() - 4) as f64;
    let cov = jtj.try_inverse()? * (rss / dof);
    let k_abs = q[2].hypot(q[3]);
    Some(DecayFit {
        alpha: q[0],
        alpha_sigma: cov[(0, 0)].max(0.0).sqrt(),
        beta: q[1],
        beta_sigma: cov[(1, 1)].max(0.0).sqrt(),
        k_abs,
        points: pts.len(),
        rms: (rss / pts.len() as f64).sqrt() / k_abs,
    })
}

/// The x where Δ changes sign between neighbouring resolved points (linear interpolation),
/// in increasing x.
pub fn sign_changes(points: &[DecayPoint]) -> Vec<f64> {
    let mut pts: Vec<&DecayPoint> = points.iter().filter(|p| p.resolved()).collect();
    pts.sort_by(|a, b| a.x.total_cmp(&b.x));
    pts.windows(2)
        .filter(|w| w[0].delta * w[1].delta < 0.0)
        .map(|w| w[0].x + (w[1].x - w[0].x) * w[0].delta / (w[0].delta - w[1].delta))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_root_solves_sin_2z_plus_2z() {
        // |sin 2λ + 2λ| at the rounded root: the derivative 2cos 2λ + 2 is O(10), so a root
        // rounded to 1e-6 leaves a residual of order 1e-5
        let z = num_complex::Complex64::new(DECAY_RATE, DECAY_WAVENUMBER);
        assert!(((2.0 * z).sin() + 2.0 * z).norm() < 2e-5);
    }

    #[test]
    fn the_fit_recovers_a_mode_of_another_rate_with_noise_free_data() {
        let pts: Vec<DecayPoint> = (0..25)
            .map(|k| {
                let x = 0.5 + 0.3 * k as f64;
                DecayPoint {
                    x,
                    delta: -0.02 * (-1.9 * x).exp() * (1.3 * x - 0.4).cos(),
                    error: 0.0,
                }
            })
            .collect();
        let f = fit_decay(&pts, 0.0, 2.0).unwrap();
        // exact data: the fit is limited by round-off in the weighted normal equations
        assert!((f.alpha - 1.9).abs() < 1e-9, "{f:?}");
        assert!((f.beta - 1.3).abs() < 1e-9, "{f:?}");
        let zeros = sign_changes(&pts);
        // zeros of cos(1.3x − 0.4): (0.4 + π/2 + kπ)/1.3; linear interpolation over 0.3 of a
        // curve that bends by e^(−1.9x) leaves errors of order 0.3²·1.9/8 of the spacing
        for (k, z) in zeros.iter().enumerate() {
            let exact = (0.4 + std::f64::consts::FRAC_PI_2 + k as f64 * std::f64::consts::PI) / 1.3;
            assert!((z - exact).abs() < 0.05, "{z} {exact}");
        }
    }
}
