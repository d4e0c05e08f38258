//! What every element kind shares: the stress and quadrature-point types, the isotropic
//! elasticity matrix D (report eqs. 2.3, A.5), the products Bᵀ D B and D ε, strains from B, and
//! the Gauss–Legendre rules. Sign convention and units as in the [folder's docs](super).
//!
//! # Accuracy
//!
//! D and the Gauss rules are exact to rounding: `tests/fem/elements.rs` (patch tests, which
//! fail on any error in D, B or the rules) and `tests/fem/lame.rs`.
//!
//! # Cost
//!
//! O(n²) per point for an element of n dofs (`cargo bench --bench fem`).
//!
//! ```
//! use boltzone::fem::element::elasticity;
//! use boltzone::Material;
//! let d = elasticity(&Material::new(1.0, 0.25)?);
//! assert!((d[3][3] - 0.4).abs() < 1e-15); // μ = E / 2(1 + ν)
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::material::Material;
use serde::Serialize;

/// Stresses (σ_r, σ_z, σ_θ, τ_rz), tension positive.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Stress {
    /// Radial normal stress σ_r.
    pub r: f64,
    /// Axial normal stress σ_z.
    pub z: f64,
    /// Hoop stress σ_θ.
    pub theta: f64,
    /// Shear stress τ_rz.
    pub rz: f64,
}

impl Stress {
    pub(super) fn from_array(s: [f64; 4]) -> Self {
        Self {
            r: s[0],
            z: s[1],
            theta: s[2],
            rz: s[3],
        }
    }

    /// The components as (σ_r, σ_z, σ_θ, τ_rz).
    pub fn to_array(self) -> [f64; 4] {
        [self.r, self.z, self.theta, self.rz]
    }
}

/// A point of an element with its volume weight (2πr·det J·w) and what lives there.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ElementPoint {
    /// Radius.
    pub r: f64,
    /// Axial coordinate.
    pub z: f64,
    /// Volume weight of the point in ∫ · dV (zero where only a value is reported).
    pub weight: f64,
    /// Displacement (u_r, u_z) at the point.
    pub displacement: [f64; 2],
    /// Stress at the point.
    pub stress: Stress,
}

/// The isotropic elasticity matrix D for (ε_r, ε_z, ε_θ, γ_rz).
pub fn elasticity(m: &Material) -> [[f64; 4]; 4] {
    let (l, mu) = m.lame();
    let c = l + 2.0 * mu;
    [
        [c, l, l, 0.0],
        [l, c, l, 0.0],
        [l, l, c, 0.0],
        [0.0, 0.0, 0.0, mu],
    ]
}

/// σ = D ε.
pub(crate) fn apply_d(d: &[[f64; 4]; 4], e: &[f64; 4]) -> [f64; 4] {
    let mut s = [0.0; 4];
    for (i, si) in s.iter_mut().enumerate() {
        *si = (0..4).map(|j| d[i][j] * e[j]).sum();
    }
    s
}

/// Adds w·Bᵀ D B to the upper triangle (i ≤ j) of the (nd × nd, row-major) matrix `k`, B given
/// by columns (4 strains per dof); call [`mirror_upper`] once after the last point.
pub(crate) fn add_btdb(k: &mut [f64], b: &[[f64; 4]], d: &[[f64; 4]; 4], w: f64) {
    let nd = b.len();
    for j in 0..nd {
        let db = apply_d(d, &b[j]);
        for i in 0..=j {
            let bi = &b[i];
            k[i * nd + j] += w * (bi[0] * db[0] + bi[1] * db[1] + bi[2] * db[2] + bi[3] * db[3]);
        }
    }
}

/// [`add_btdb`] for B of the shape every isoparametric element without B-bar has: node a's two
/// columns are [∂N_a/∂r, 0, N_a/r, ∂N_a/∂z] (u_r) and [0, ∂N_a/∂z, 0, ∂N_a/∂r] (u_z), given
/// per node as `g[a]` = (∂N_a/∂r, ∂N_a/∂z, N_a/r). Only the nonzero products are formed, in the
/// order [`add_btdb`] forms them (its products with B's zeros add exact zeros), so the two agree
/// to the last bit (this module's test `node_gradient_product_equals_the_general_one`):
/// D·b costs 10 products instead of 16 and each entry 2–3 instead of 4.
pub(crate) fn add_btdb_nodes(k: &mut [f64], g: &[[f64; 3]], d: &[[f64; 4]; 4], w: f64) {
    let nd = 2 * g.len();
    for (b, &[dr, dz, hoop]) in g.iter().enumerate() {
        // D times node b's u_r column (dr, 0, hoop, dz) and u_z column (0, dz, 0, dr)
        let du = d.map(|di| di[0] * dr + di[2] * hoop + di[3] * dz);
        let dw = d.map(|di| di[1] * dz + di[3] * dr);
        let (ju, jw) = (2 * b, 2 * b + 1);
        for (a, &[ar, az, ah]) in g[..=b].iter().enumerate() {
            let (iu, iw) = (2 * a * nd, (2 * a + 1) * nd);
            k[iu + ju] += w * (ar * du[0] + ah * du[2] + az * du[3]);
            k[iu + jw] += w * (ar * dw[0] + ah * dw[2] + az * dw[3]);
            k[iw + jw] += w * (az * dw[1] + ar * dw[3]);
            if a < b {
                k[iw + ju] += w * (az * du[1] + ar * du[3]);
            }
        }
    }
}

/// Copies the upper triangle of the (nd × nd, row-major) `k` into the lower one.
pub(crate) fn mirror_upper(k: &mut [f64], nd: usize) {
    for i in 0..nd {
        for j in 0..i {
            k[i * nd + j] = k[j * nd + i];
        }
    }
}

/// Strain B·u from columns of B.
pub(crate) fn strain(b: &[[f64; 4]], u: &[f64]) -> [f64; 4] {
    let mut e = [0.0; 4];
    for (bj, uj) in b.iter().zip(u) {
        for c in 0..4 {
            e[c] += bj[c] * uj;
        }
    }
    e
}

/// Gauss–Legendre abscissae and weights on [−1, 1].
pub(crate) const GAUSS2: [(f64, f64); 2] = [
    (-0.577_350_269_189_625_8, 1.0),
    (0.577_350_269_189_625_8, 1.0),
];
/// Three-point Gauss–Legendre rule (exact to degree 5).
pub(crate) const GAUSS3: [(f64, f64); 3] = [
    (-0.774_596_669_241_483_4, 5.0 / 9.0),
    (0.0, 8.0 / 9.0),
    (0.774_596_669_241_483_4, 5.0 / 9.0),
];

#[cfg(test)]
mod tests {
    use super::*;

    /// The product over B's nonzeros equals the general one bit for bit (upper triangles),
    /// including a node on the axis (hoop column = ∂N/∂r) and an anisotropic-looking D.
    #[test]
    fn node_gradient_product_equals_the_general_one() {
        let g: Vec<[f64; 3]> = (0..9)
            .map(|a| {
                let t = a as f64 + 0.37;
                [t.sin() * 3.1, (1.7 * t).cos() / 7.0, (0.3 * t).tan()]
            })
            .collect();
        let b: Vec<[f64; 4]> = g
            .iter()
            .flat_map(|&[dr, dz, hoop]| [[dr, 0.0, hoop, dz], [0.0, dz, 0.0, dr]])
            .collect();
        let iso = elasticity(&Material::new(2.9e7, 0.3).unwrap());
        let mut general = iso;
        general[0][3] = 0.125e7;
        general[3][1] = -0.5e6;
        for d in [iso, general] {
            let (mut k1, mut k2) = (vec![0.0; 324], vec![0.0; 324]);
            for w in [0.31, 1.7e-3] {
                add_btdb(&mut k1, &b, &d, w);
                add_btdb_nodes(&mut k2, &g, &d, w);
            }
            for j in 0..18 {
                for i in 0..=j {
                    assert_eq!(
                        k1[i * 18 + j].to_bits(),
                        k2[i * 18 + j].to_bits(),
                        "({i}, {j})"
                    );
                }
            }
        }
    }
}
