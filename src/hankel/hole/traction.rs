//! The slab's traction on the hole cylinder, σ_r(A, z) and τ_rz(A, z), at many heights at once.
//!
//! The same Hankel integrals as [`crate::hankel::Slab::stress`] (kernels of
//! [`crate::hankel::kernel`], partition–extrapolation of [`crate::hankel::quadrature`]):
//!
//! σ_r = −∫ ξp̄ [K_r J₀(ξA) − K_m J₁(ξA)/(ξA)] dξ,  τ_rz = −∫ ξp̄ K_τ J₁(ξA) dξ,
//!
//! but [`BATCH`] heights share one set of ξ-nodes, so J₀(ξA), J₁(ξA) and p̄(ξ) — most of an
//! integrand's cost — are computed once per node for all of them, and p̄ comes from the
//! closed form of [`crate::hankel::transform`] (O(1) per ξ for sloped loads too). Heights are batched in the
//! order given (the θ-grid of [`super::fit`] puts neighbours together, whose integrands decay at
//! similar rates e^(−ξ(D−z))), and the tolerance applies to the largest value in the batch.
//! The face height z = D, where the kernels do not decay, is left to `Slab::stress`, which
//! integrates the half-space limit analytically there.
//!
//! ```
//! use boltzone::{FaceLoad, Material, hankel::{QuadParams, Slab}};
//! use boltzone::hankel::hole::traction::hole_tractions;
//! let slab = Slab::new(0.1, Material::unit(0.3).unwrap(), FaceLoad::uniform(0.0, 0.31, 1.0).unwrap()).unwrap();
//! let q = QuadParams { rel_tol: 1e-12, abs_tol: 1e-12, ..QuadParams::default() };
//! let (t, _evaluations) = hole_tractions(&slab, 0.1, &[0.05], &q);
//! let s = slab.stress(0.1, 0.05, &q);
//! assert!((t[0].sigma_r - s.sigma_r.value).abs() < 1e-9);
//! ```

use crate::hankel::field::Slab;
use crate::hankel::kernel::Kernels;
use crate::hankel::quadrature::{integrate_oscillatory_vec, QuadParams};
use crate::hankel::transform::LoadTransform;

/// Heights per shared node set.
pub const BATCH: usize = 4;

/// The slab's hole traction at one height, with the quadrature's error estimate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HoleTraction {
    /// σ_r(A, z).
    pub sigma_r: f64,
    /// τ_rz(A, z).
    pub tau_rz: f64,
    /// Estimated absolute error of (σ_r, τ_rz) (the larger).
    pub error: f64,
}

/// σ_r and τ_rz of `slab` at (a, z) for every z in `heights` (|z| ≤ D), and the number of
/// integrand evaluations spent (one per shared node).
pub fn hole_tractions(
    slab: &Slab,
    a: f64,
    heights: &[f64],
    params: &QuadParams,
) -> (Vec<HoleTraction>, usize) {
    let d = slab.half_thickness();
    let nu = slab.material().poisson_ratio();
    // The closed-form transform: O(1) per ξ even for sloped pieces (the slab's own is O(ξ)).
    let tr = LoadTransform::new(slab.load());
    let omega = a + slab.transform().outer();
    let mut out = Vec::with_capacity(heights.len());
    let mut evaluations = 0;
    let interior: Vec<(usize, f64)> = heights
        .iter()
        .enumerate()
        .filter(|(_, z)| z.abs() < d)
        .map(|(i, z)| (i, z.abs()))
        .collect();
    let mut values = vec![None; heights.len()];
    for chunk in interior.chunks(BATCH) {
        // pad a short chunk with its last height (computed twice, used once)
        let z: [f64; BATCH] = std::array::from_fn(|k| chunk[k.min(chunk.len() - 1)].1);
        let e = integrate_oscillatory_vec::<{ 2 * BATCH }, _>(
            |xi| {
                let x = xi * a;
                let (j0, j1) = (libm::j0(x), libm::j1(x));
                let j1x = if x > 0.0 { j1 / x } else { 0.5 };
                let q = xi * tr.eval(xi);
                let mut v = [0.0; 2 * BATCH];
                for (k, zk) in z.iter().enumerate() {
                    let kn = Kernels::at(xi * d, xi * zk, nu);
                    v[2 * k] = q * (kn.m * j1x - kn.r * j0); // σ_r
                    v[2 * k + 1] = -q * kn.tau * j1; // τ_rz for z ≥ 0
                }
                v
            },
            omega,
            1.0 / d,
            // J₀(ξA)·p̄(ξ) is a product of oscillations (p̄ carries J₁(ξB)): the beat needs the
            // second, whole-period extrapolation in the error estimate.
            &QuadParams {
                products: true,
                ..*params
            },
        );
        evaluations += e[0].evaluations;
        for (k, (i, _)) in chunk.iter().enumerate() {
            let sign = if heights[*i] < 0.0 { -1.0 } else { 1.0 };
            let (sr, tau) = (e[2 * k], e[2 * k + 1]);
            values[*i] = Some(HoleTraction {
                sigma_r: sr.value,
                tau_rz: sign * tau.value,
                error: sr.error.max(tau.error),
            });
        }
    }
    for (i, z) in heights.iter().enumerate() {
        match values[i] {
            Some(v) => out.push(v),
            None => {
                let s = slab.stress(a, *z, params);
                evaluations += s.sigma_r.evaluations;
                out.push(HoleTraction {
                    sigma_r: s.sigma_r.value,
                    tau_rz: s.tau_rz.value,
                    error: s.sigma_r.error.max(s.tau_rz.error),
                });
            }
        }
    }
    (out, evaluations)
}
