//! Axisymmetric Lagrange rectangles (Q4 bilinear, Q9 biquadratic) for linear elasticity in (r, z).
//!
//! Displacements (u, w) = Σ_a N_a(ξ, η)(u_a, w_a), N_a = L_i(ξ) L_j(η) with the 1D Lagrange
//! polynomials on {−1, 1} (order 1) or {−1, 0, 1} (order 2); the element is the rectangle
//! [r₀, r₁] × [z₀, z₁] mapped affinely, so ∂/∂r = (2/h_r) ∂/∂ξ and ∂/∂z = (2/h_z) ∂/∂η. Strains
//! (report eq. 2.5) ε = (ε_r, ε_θ, ε_z, γ_rz) = (∂u/∂r, u/r, ∂w/∂z, ∂u/∂z + ∂w/∂r), stresses
//! σ = D ε with Lamé's λ, μ (eq. 2.2), and the stiffness K_e = ∫ Bᵀ D B 2πr dr dz by
//! (order + 1)² Gauss–Legendre points (the standard full rule; the Gauss points avoid r = 0).
//! Forces are totals around the circumference (the 2π is included). Local node order: radial
//! index fastest, then axial; dofs (u, w) per node.
//!
//! (A stand-in for the FE module's elements while `fem` is being built; the FE module may absorb
//! it.)
//!
//! ```
//! use boltzone::contact::axisym::element_stiffness;
//! // A rigid axial translation (u = 0, w = 1) produces no force.
//! let k = element_stiffness(1, [0.1, 0.2], [0.0, 0.1], 1.15, 0.77);
//! let n = k.nrows();
//! let x = nalgebra::DVector::from_fn(n, |i, _| if i % 2 == 1 { 1.0 } else { 0.0 });
//! assert!((k * x).amax() < 1e-12);
//! ```

use nalgebra::DMatrix;
use std::f64::consts::PI;

/// Gauss–Legendre points and weights on [−1, 1] for 1 ≤ n ≤ 3 (exact for degree 2n − 1).
pub fn gauss(n: usize) -> (&'static [f64], &'static [f64]) {
    const P2: [f64; 2] = [-0.577_350_269_189_625_8, 0.577_350_269_189_625_8];
    const W2: [f64; 2] = [1.0, 1.0];
    const P3: [f64; 3] = [-0.774_596_669_241_483_4, 0.0, 0.774_596_669_241_483_4];
    const W3: [f64; 3] = [5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0];
    match n {
        1 => (&[0.0], &[2.0]),
        2 => (&P2, &W2),
        _ => (&P3, &W3),
    }
}

/// 1D Lagrange basis values and derivatives at ξ for order 1 or 2.
pub fn lagrange(order: usize, xi: f64) -> ([f64; 3], [f64; 3]) {
    if order == 1 {
        ([(1.0 - xi) / 2.0, (1.0 + xi) / 2.0, 0.0], [-0.5, 0.5, 0.0])
    } else {
        (
            [xi * (xi - 1.0) / 2.0, 1.0 - xi * xi, xi * (xi + 1.0) / 2.0],
            [xi - 0.5, -2.0 * xi, xi + 0.5],
        )
    }
}

/// Stiffness of the rectangle `r` × `z` of the given order with Lamé constants λ, μ:
/// a 2(order+1)² square matrix in the local node order of the module docs.
pub fn element_stiffness(
    order: usize,
    r: [f64; 2],
    z: [f64; 2],
    lambda: f64,
    mu: f64,
) -> DMatrix<f64> {
    let k = order + 1;
    let n = k * k;
    let (hr, hz) = (r[1] - r[0], z[1] - z[0]);
    let (pts, wts) = gauss(k);
    let d = [
        [lambda + 2.0 * mu, lambda, lambda, 0.0],
        [lambda, lambda + 2.0 * mu, lambda, 0.0],
        [lambda, lambda, lambda + 2.0 * mu, 0.0],
        [0.0, 0.0, 0.0, mu],
    ];
    let mut ke = DMatrix::zeros(2 * n, 2 * n);
    let mut b = vec![[[0.0; 2]; 4]; n];
    for (gi, &xi) in pts.iter().enumerate() {
        let (lx, dlx) = lagrange(order, xi);
        let rr = r[0] + (xi + 1.0) * hr / 2.0;
        for (gj, &eta) in pts.iter().enumerate() {
            let (ly, dly) = lagrange(order, eta);
            let weight = wts[gi] * wts[gj] * hr * hz / 4.0 * 2.0 * PI * rr;
            for jb in 0..k {
                for ia in 0..k {
                    let a = jb * k + ia;
                    let nn = lx[ia] * ly[jb];
                    let dr = dlx[ia] * ly[jb] * 2.0 / hr;
                    let dz = lx[ia] * dly[jb] * 2.0 / hz;
                    b[a] = [[dr, 0.0], [nn / rr, 0.0], [0.0, dz], [dz, dr]];
                }
            }
            for a in 0..n {
                for ca in 0..2 {
                    // (D B)_{:, a, ca}
                    let mut db = [0.0; 4];
                    for (s, dbs) in db.iter_mut().enumerate() {
                        *dbs = (0..4).map(|t| d[s][t] * b[a][t][ca]).sum();
                    }
                    for bb in 0..n {
                        for cb in 0..2 {
                            let v: f64 = (0..4).map(|s| b[bb][s][cb] * db[s]).sum();
                            ke[(2 * bb + cb, 2 * a + ca)] += weight * v;
                        }
                    }
                }
            }
        }
    }
    ke
}
