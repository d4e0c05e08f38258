//! Biquadratic Lagrange quadrilateral Q9: N_a(ξ, η) = ℓ_i(ξ) ℓ_j(η) with the 1D quadratic
//! Lagrange polynomials ℓ₋₁(t) = t(t − 1)/2, ℓ₀(t) = 1 − t², ℓ₁(t) = t(t + 1)/2. Node order:
//! corners counterclockwise (−1,−1), (1,−1), (1,1), (−1,1); mid-sides bottom (0,−1), right (1,0),
//! top (0,1), left (−1,0); centre (0,0). 3×3 Gauss (exact to degree 5 per direction).
//!
//! Convergence: displacement error O(h³) in L2, stress O(h²).
//!
//! # Accuracy
//!
//! Partition of unity in the doc example; the rates O(h³)/O(h²) are measured in `tests/fem/lame.rs`
//! (`observed_orders_are_two_for_linear_and_three_for_quadratic`).
//!
//! # Cost
//!
//! 9 shape functions per point; see `cargo bench --bench fem`.
//!
//! ```
//! let (n, _) = boltzone::fem::element::q9::shape([0.3, 0.7]);
//! assert!((n.iter().sum::<f64>() - 1.0).abs() < 1e-15);
//! ```

use super::iso::Parent;

/// Parent coordinates of the nine nodes.
pub const NODES: [[f64; 2]; 9] = [
    [-1.0, -1.0],
    [1.0, -1.0],
    [1.0, 1.0],
    [-1.0, 1.0],
    [0.0, -1.0],
    [1.0, 0.0],
    [0.0, 1.0],
    [-1.0, 0.0],
    [0.0, 0.0],
];

/// 1D quadratic Lagrange polynomial through −1, 0, 1 that is 1 at `node` and its derivative.
fn lagrange(node: f64, t: f64) -> (f64, f64) {
    if node < -0.5 {
        (0.5 * t * (t - 1.0), t - 0.5)
    } else if node > 0.5 {
        (0.5 * t * (t + 1.0), t + 0.5)
    } else {
        (1.0 - t * t, -2.0 * t)
    }
}

/// Shape functions and their (ξ, η) derivatives at parent point `p`.
pub fn shape(p: [f64; 2]) -> ([f64; 9], [[f64; 2]; 9]) {
    let mut n = [0.0; 9];
    let mut dn = [[0.0; 2]; 9];
    for (a, c) in NODES.iter().enumerate() {
        let (lx, dlx) = lagrange(c[0], p[0]);
        let (ly, dly) = lagrange(c[1], p[1]);
        n[a] = lx * ly;
        dn[a] = [dlx * ly, lx * dly];
    }
    (n, dn)
}

pub(crate) struct Q9;

impl Parent for Q9 {
    fn eval(&self, p: [f64; 2], n: &mut [f64], dn: &mut [[f64; 2]]) {
        let (sn, sdn) = shape(p);
        n.copy_from_slice(&sn);
        dn.copy_from_slice(&sdn);
    }
    fn rule(&self) -> &'static [(f64, f64)] {
        &super::GAUSS3
    }
}
