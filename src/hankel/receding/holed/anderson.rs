//! Anderson acceleration of a fixed-point iteration x ← G(x) in ℝⁿ: the holed two-plate
//! model's iteration l ← s₀ + σ_z^Z of the hole correction's amplitudes (module `crack`).
//!
//! **Method** (Anderson 1965; Walker & Ni, SIAM J. Numer. Anal. 49 (2011) 1715, "type II"):
//! with the residual f_k = G(x_k) − x_k and the differences ΔF, ΔG of the last m residuals and
//! images, γ minimises ‖f_k − ΔF γ‖₂ (SVD, singular values below 1e-12 of the largest
//! dropped) and x_{k+1} = G(x_k) − ΔG γ. On an affine contraction G it is GMRES in disguise:
//! the error falls faster than the plain iteration's ρᵏ.
//!
//! # Accuracy
//!
//! The accelerated iteration stops on the same test as the plain one (the edge value's change);
//! R_o with and without it agree to the iteration tolerance:
//! `tests/hankel/two_plate_hole_fast.rs` (`anderson_changes_nothing_but_the_count`).
//!
//! # Cost
//!
//! An m-column least-squares problem per step (n ≲ 50, m = 3): microseconds, against the
//! milliseconds of one step of the crack iteration. Timed through example 19.

use crate::hankel::hole::fit::Fit;
use nalgebra::{DMatrix, DVector};

/// The history of an accelerated iteration.
pub(super) struct Anderson {
    depth: usize,
    last: Option<(Vec<f64>, Vec<f64>)>,
    d_f: Vec<Vec<f64>>,
    d_g: Vec<Vec<f64>>,
}

impl Anderson {
    /// Keeps the last `depth` differences.
    pub(super) fn new(depth: usize) -> Self {
        Self {
            depth,
            last: None,
            d_f: Vec::new(),
            d_g: Vec::new(),
        }
    }

    /// The next iterate from the current one `x` and its image `g` = G(x).
    pub(super) fn next(&mut self, x: &[f64], g: Vec<f64>) -> Vec<f64> {
        let f: Vec<f64> = g.iter().zip(x).map(|(g, x)| g - x).collect();
        if let Some((f0, g0)) = self.last.take() {
            if f0.len() == f.len() {
                self.d_f
                    .push(f.iter().zip(&f0).map(|(a, b)| a - b).collect());
                self.d_g
                    .push(g.iter().zip(&g0).map(|(a, b)| a - b).collect());
                if self.d_f.len() > self.depth {
                    self.d_f.remove(0);
                    self.d_g.remove(0);
                }
            }
        }
        self.last = Some((f.clone(), g.clone()));
        let m = self.d_f.len();
        if m == 0 {
            return g;
        }
        let n = f.len();
        let a = DMatrix::from_fn(n, m, |i, j| self.d_f[j][i]);
        let svd = a.svd(true, true);
        let cut = 1e-12 * svd.singular_values.max();
        let gamma = match svd.solve(&DVector::from_column_slice(&f), cut) {
            Ok(v) if v.iter().all(|x| x.is_finite()) => v,
            _ => return g,
        };
        let mut out = g;
        for (j, gj) in gamma.iter().enumerate() {
            for (o, d) in out.iter_mut().zip(&self.d_g[j]) {
                *o -= gj * d;
            }
        }
        out
    }
}

/// A correction's amplitudes as one real vector: Re c_k, Im c_k, then the extra columns'.
pub(super) fn pack(f: &Fit) -> Vec<f64> {
    f.modes
        .iter()
        .map(|c| c.re)
        .chain(f.modes.iter().map(|c| c.im))
        .chain(f.extra.iter().copied())
        .collect()
}

/// `f` with the amplitudes of `x` (the layout of [`pack`]).
pub(super) fn unpack(f: Fit, x: &[f64]) -> Fit {
    let n = f.modes.len();
    Fit {
        modes: (0..n)
            .map(|k| num_complex::Complex64::new(x[k], x[n + k]))
            .collect(),
        extra: x[2 * n..].to_vec(),
        ..f
    }
}
