//! The slab's traction on a cylinder r = R (the hole r = A, or a rim r = C), σ_r(R, z) and
//! τ_rz(R, z), at many heights at once.
//!
//! The same Hankel integrals as [`crate::hankel::Slab::stress`] (kernels of
//! [`crate::hankel::kernel`], partition–extrapolation of [`crate::numerics::quadrature`]):
//!
//! σ_r = −∫ ξp̄ [K_r J₀(ξR) − K_m J₁(ξR)/(ξR)] dξ,  τ_rz = −∫ ξp̄ K_τ J₁(ξR) dξ,
//!
//! but up to [`BATCH`] heights share one set of ξ-nodes, so J₀(ξR), J₁(ξR) and p̄(ξ) — the
//! Bessel calls — are computed once per node for all of them, and p̄ comes from the closed form
//! of [`crate::hankel::transform`] (O(1) per ξ for sloped loads too).
//! The kernels are split into the factors of t = ξD, computed once per node (S_t, C_t and
//! 4/Q(t) of the overflow-free form), and those of s = ξ|z| (one `expm1` and one `exp` per
//! height); and a height whose kernels have decayed below e^(−40) of their scale
//! (ξ(D − |z|) > 40: every kernel is e^(−(t−s)) times a polynomial of degree one in t − s)
//! contributes an exact zero from there on, so its partial sums freeze and Wynn's ε on them
//! returns at once. A batch runs as long as its nearest-to-face height needs, and until the
//! others freeze every panel pays Wynn's ε (window 13, twice with the whole-period check) for
//! each of them — with the Bessel calls, the two dominant costs (the ε-table is updated
//! incrementally, [`crate::numerics::quadrature::WynnWindow`]): so a batch only takes heights
//! within a factor 4 of distance to the face (see [`hole_tractions`]). The tolerance applies to
//! the largest value in the batch.
//! The face height z = D, where the kernels do not decay, is left to `Slab::stress`, which
//! integrates the half-space limit analytically there.
//!
//! # Accuracy
//!
//! The batched tractions match the slab solver's per-point integrals
//! (`tests/hankel/hole_correction.rs`, `batched_hole_tractions_match_the_slab_solver`).
//!
//! # Cost
//!
//! At A = 0.1, P = 1 and an absolute tolerance 1e-8, a height at distance ζ below the face needs
//! of order 10³–10⁴ ξ-nodes, growing roughly like ζ^(−1/2) (the integrand's tail decays only
//! like e^(−ξζ) and beats at the frequency B − A): which is why [`super::profile`] samples only
//! a few Chebyshev heights and interpolates. Timed in `cargo bench --bench hole`.
//!
//! ```
//! use boltzone::{FaceLoad, Material, hankel::{QuadParams, Slab}};
//! use boltzone::hankel::hole::traction::hole_tractions;
//! let slab = Slab::new(0.1, Material::unit(0.3)?, FaceLoad::uniform(0.0, 0.31, 1.0)?)?;
//! let q = QuadParams { rel_tol: 1e-12, abs_tol: 1e-12, ..QuadParams::default() };
//! let (t, _evaluations) = hole_tractions(&slab, 0.1, &[0.05], &q);
//! let s = slab.stress(0.1, 0.05, &q);
//! assert!((t[0].sigma_r - s.sigma_r.value).abs() < 1e-9);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::hankel::field::Slab;
use crate::hankel::transform::LoadTransform;
use crate::numerics::quadrature::{integrate_oscillatory_vec, QuadParams};

/// Heights per shared node set.
pub const BATCH: usize = 8;

/// Beyond ξ(D − |z|) = `DECAYED` a height's kernels are below e^(−40)·41 ≈ 2e-16 of their
/// scale and are dropped.
const DECAYED: f64 = 40.0;

/// The slab's hole traction at one height, with the quadrature's error estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HoleTraction {
    /// σ_r(R, z).
    pub sigma_r: f64,
    /// τ_rz(R, z).
    pub tau_rz: f64,
    /// Estimated absolute error of (σ_r, τ_rz) (the larger).
    pub error: f64,
}

/// The factors of the kernels K_r, K_m, K_τ ([`crate::hankel::kernel::Kernels::at`]) that depend
/// on t = ξD only: with sinh t = eᵗ S_t, cosh t = eᵗ C_t and Q(t) = 1 − e^(−4t) + 4t e^(−2t),
/// K = 4e^(s−t)/Q · (polynomial in S_t, C_t, S_s, C_s, s, t).
#[derive(Debug, Clone, Copy)]
pub struct ThicknessFactors {
    t: f64,
    st: f64,
    tct: f64,
    four_over_q: f64,
    one_minus_2nu: f64,
}

impl ThicknessFactors {
    /// The factors at t = ξD (t ≥ 0), Poisson's ratio `nu`.
    pub fn new(t: f64, nu: f64) -> Self {
        let t = t.max(1e-300);
        // e^(−2t) − 1 in full relative precision; S_t = −em/2, C_t = 1 − S_t,
        // e^(−4t) − 1 = em(2 + em), e^(−2t) = 1 + em
        let em = (-2.0 * t).exp_m1();
        let st = -0.5 * em;
        let q = -em * (2.0 + em) + 4.0 * t * (1.0 + em);
        Self {
            t,
            st,
            tct: t * (1.0 - st),
            four_over_q: 4.0 / q,
            one_minus_2nu: 1.0 - 2.0 * nu,
        }
    }

    /// (K_r, K_m, K_τ) at s = ξ|z| (clamped to [0, t]); all zero once t − s > 40.
    pub fn kernels(&self, s: f64) -> (f64, f64, f64) {
        let s = s.clamp(0.0, self.t);
        if self.t - s > DECAYED {
            return (0.0, 0.0, 0.0);
        }
        let ss = -0.5 * (-2.0 * s).exp_m1();
        let cs = 1.0 - ss;
        let f = self.four_over_q * (s - self.t).exp();
        let (st, tct) = (self.st, self.tct);
        let common = s * st * ss;
        (
            f * ((st - tct) * cs + common),
            f * ((self.one_minus_2nu * st - tct) * cs + common),
            f * (s * st * cs - tct * ss),
        )
    }
}

/// What one batch integrates: the radius, the slab's half-thickness and Poisson's ratio, the
/// load transform.
struct Batch<'a> {
    r: f64,
    d: f64,
    nu: f64,
    tr: &'a LoadTransform,
    omega: f64,
}

impl Batch<'_> {
    /// σ_r and τ_rz at the heights `z` (0 ≤ z < D, at most N/2 of them) on one node set;
    /// returns them with the node count.
    fn run<const N: usize>(&self, z: &[f64], params: &QuadParams) -> (Vec<HoleTraction>, usize) {
        let (r, d, nu, tr) = (self.r, self.d, self.nu, self.tr);
        let e = integrate_oscillatory_vec::<N, _>(
            |xi| {
                let x = xi * r;
                let (j0, j1) = (libm::j0(x), libm::j1(x));
                let j1x = if x > 0.0 { j1 / x } else { 0.5 };
                let q = xi * tr.eval(xi);
                let tf = ThicknessFactors::new(xi * d, nu);
                // unused slots stay exact zeros
                let mut v = [0.0; N];
                for (k, zk) in z.iter().enumerate() {
                    let (kr, km, ktau) = tf.kernels(xi * zk);
                    v[2 * k] = q * (km * j1x - kr * j0); // σ_r
                    v[2 * k + 1] = -q * ktau * j1; // τ_rz for z ≥ 0
                }
                v
            },
            self.omega,
            1.0 / d,
            // J₀(ξR)·p̄(ξ) is a product of oscillations (p̄ carries J₁(ξB)): the beat needs the
            // second, whole-period extrapolation in the error estimate.
            &QuadParams {
                products: true,
                ..*params
            },
        );
        let out = (0..z.len())
            .map(|k| HoleTraction {
                sigma_r: e[2 * k].value,
                tau_rz: e[2 * k + 1].value,
                error: e[2 * k].error.max(e[2 * k + 1].error),
            })
            .collect();
        (out, e[0].evaluations)
    }
}

/// σ_r and τ_rz of `slab` at (r, z) for every z in `heights` (|z| ≤ D), and the number of
/// ξ-nodes spent (one per shared node).
///
/// Interior heights are batched in the order given: a batch closes when it holds [`BATCH`]
/// heights or when the next one lies more than 4× closer to the face than its first (its
/// integral would run ~2× longer, and every panel costs Wynn's ε for every member), so the
/// few heights next to the face, whose integrals are the long ones, run in batches of 1–4.
pub fn hole_tractions(
    slab: &Slab,
    r: f64,
    heights: &[f64],
    params: &QuadParams,
) -> (Vec<HoleTraction>, usize) {
    let d = slab.half_thickness();
    // The closed-form transform: O(1) per ξ even for sloped pieces (the slab's own is O(ξ)).
    let tr = LoadTransform::new(slab.load());
    let batch = Batch {
        r,
        d,
        nu: slab.material().poisson_ratio(),
        tr: &tr,
        omega: r + slab.transform().outer(),
    };
    let mut evaluations = 0;
    let interior: Vec<(usize, f64)> = heights
        .iter()
        .enumerate()
        .filter(|(_, z)| z.abs() < d)
        .map(|(i, z)| (i, z.abs()))
        .collect();
    let mut values = vec![None; heights.len()];
    let mut start = 0;
    while start < interior.len() {
        let gap = d - interior[start].1;
        let mut end = start + 1;
        while end < interior.len()
            && end - start < BATCH
            && 4.0 * (d - interior[end].1) >= gap
            && (d - interior[end].1) <= 4.0 * gap
        {
            end += 1;
        }
        let z: Vec<f64> = interior[start..end].iter().map(|c| c.1).collect();
        let (t, n) = match z.len() {
            1 => batch.run::<2>(&z, params),
            2 => batch.run::<4>(&z, params),
            3 | 4 => batch.run::<8>(&z, params),
            _ => batch.run::<{ 2 * BATCH }>(&z, params),
        };
        evaluations += n;
        for ((i, _), mut v) in interior[start..end].iter().zip(t) {
            if heights[*i] < 0.0 {
                v.tau_rz = -v.tau_rz;
            }
            values[*i] = Some(v);
        }
        start = end;
    }
    let out = heights
        .iter()
        .zip(values)
        .map(|(z, v)| {
            v.unwrap_or_else(|| {
                let s = slab.stress(r, *z, params);
                evaluations += s.sigma_r.evaluations;
                HoleTraction {
                    sigma_r: s.sigma_r.value,
                    tau_rz: s.tau_rz.value,
                    error: s.sigma_r.error.max(s.tau_rz.error),
                }
            })
        })
        .collect();
    (out, evaluations)
}

#[cfg(test)]
mod tests {
    use super::ThicknessFactors;
    use crate::hankel::kernel::Kernels;

    #[test]
    fn split_kernels_equal_the_slab_kernels() {
        // The same algebra rearranged (t-factors hoisted, C = 1 − S, e^(−4t) − 1 from
        // e^(−2t) − 1): agreement to a few ε of the kernels' scale, from t → 0 to the
        // far tail, and exact zeros only where the kernels are below 2e-16 of their scale.
        for nu in [0.0, 0.3, 0.499] {
            for t in [1e-9, 1e-3, 0.1, 0.7, 2.0, 9.0, 35.0, 80.0, 400.0] {
                let tf = ThicknessFactors::new(t, nu);
                for frac in [0.0, 0.1, 0.5, 0.9, 0.99, 0.999, 1.0] {
                    let s = frac * t;
                    let k = Kernels::at(t, s, nu);
                    let (kr, km, ktau) = tf.kernels(s);
                    let scale = 1.0 + t;
                    for (a, b) in [(kr, k.r), (km, k.m), (ktau, k.tau)] {
                        let tol = if t - s > 40.0 {
                            2e-16 * scale
                        } else {
                            8.0 * f64::EPSILON * scale
                        };
                        assert!((a - b).abs() <= tol, "ν {nu} t {t} s {s}: {a} vs {b}");
                    }
                }
            }
        }
    }
}
