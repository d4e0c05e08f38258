//! Bilinear quadrilateral Q4: N_a(ξ, η) = (1 + ξ_a ξ)(1 + η_a η)/4 at corners
//! (ξ_a, η_a) = (−1, −1), (1, −1), (1, 1), (−1, 1) (counterclockwise in (r, z)); 2×2 Gauss
//! (points ±1/√3, weights 1), which integrates the axisymmetric patch-test integrand exactly.
//! [`super::ElementKind::Q4Bbar`] uses the same shape functions with the B-bar volumetric strain.
//!
//! Convergence: displacement error O(h²) in L2, stress O(h).
//!
//! # Accuracy
//!
//! Partition of unity in the doc example; the rates O(h²)/O(h) are measured in `tests/fem/lame.rs`
//! (`observed_orders_are_two_for_linear_and_three_for_quadratic`).
//!
//! # Cost
//!
//! 4 shape functions per point; see `cargo bench --bench fem`.
//!
//! ```
//! let (n, _) = boltzone::fem::element::q4::shape([0.2, -0.4]);
//! assert!((n.iter().sum::<f64>() - 1.0).abs() < 1e-15);
//! ```

use super::iso::Parent;

/// Parent coordinates of the corners, counterclockwise.
pub const CORNERS: [[f64; 2]; 4] = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];

/// Shape functions and their (ξ, η) derivatives at parent point `p`.
pub fn shape(p: [f64; 2]) -> ([f64; 4], [[f64; 2]; 4]) {
    let mut n = [0.0; 4];
    let mut dn = [[0.0; 2]; 4];
    for (a, c) in CORNERS.iter().enumerate() {
        let (fx, fy) = (1.0 + c[0] * p[0], 1.0 + c[1] * p[1]);
        n[a] = 0.25 * fx * fy;
        dn[a] = [0.25 * c[0] * fy, 0.25 * c[1] * fx];
    }
    (n, dn)
}

pub(crate) struct Q4;

impl Parent for Q4 {
    fn eval(&self, p: [f64; 2], n: &mut [f64], dn: &mut [[f64; 2]]) {
        let (sn, sdn) = shape(p);
        n.copy_from_slice(&sn);
        dn.copy_from_slice(&sdn);
    }
    fn rule(&self) -> &'static [(f64, f64)] {
        &super::GAUSS2
    }
}
