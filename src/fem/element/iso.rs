//! Isoparametric machinery shared by Q4 and Q9: map a parent point (ξ, η) ∈ [−1, 1]² to (r, z),
//! form B, integrate k = ∑ w_g 2π r_g det J_g Bᵀ D B over a tensor Gauss rule.
//!
//! B-bar (Hughes 1980, mean dilatation): the volumetric part (1/3)(ε_r + ε_z + ε_θ) of each
//! normal-strain row is replaced by its element average ∫ θ dV / V, which removes volumetric
//! locking of the bilinear element.
//!
//! # Accuracy
//!
//! The patch tests of `tests/fem/elements.rs` and the observed orders of `tests/fem/lame.rs`
//! (`observed_orders_are_two_for_linear_and_three_for_quadratic`,
//! `nearly_incompressible_q4_locks_and_bbar_q9_do_not` for B-bar).
//!
//! # Cost
//!
//! O(n_g · n²) per element for n dofs and n_g Gauss points; `cargo bench --bench fem`.

use super::{add_btdb, add_btdb_nodes, apply_d, mirror_upper, strain, ElementPoint, Stress};
use std::f64::consts::PI;

/// A parent element: shape functions and their (ξ, η) derivatives, and a Gauss rule.
pub(crate) trait Parent {
    /// Shape functions N and ∂N/∂(ξ, η) at `p`, written to `n` and `dn` (one entry a node).
    fn eval(&self, p: [f64; 2], n: &mut [f64], dn: &mut [[f64; 2]]);
    /// 1D Gauss rule used in each direction.
    fn rule(&self) -> &'static [(f64, f64)];
}

/// A mapped point: position, area Jacobian, B columns and the volumetric row.
pub(crate) struct Mapped {
    pub r: f64,
    pub z: f64,
    pub det: f64,
    pub n: Vec<f64>,
    pub b: Vec<[f64; 4]>,
}

/// Most nodes of a parent element (Q9).
const MAX_NODES: usize = 9;

pub(crate) fn map(el: &dyn Parent, x: &[[f64; 2]], p: [f64; 2]) -> Mapped {
    let mut n = vec![0.0; x.len()];
    let mut g = [[0.0; 3]; MAX_NODES];
    let [r, z, det] = map_nodes(el, x, p, &mut n, &mut g[..x.len()]);
    let b = g[..x.len()]
        .iter()
        .flat_map(|&[dr, dz, hoop]| [[dr, 0.0, hoop, dz], [0.0, dz, 0.0, dr]])
        .collect();
    Mapped { r, z, det, n, b }
}

/// The mapping at `p` without allocating: N into `n`, each node's (∂N/∂r, ∂N/∂z, N/r) into
/// `g` (B's nonzeros, [`super::add_btdb_nodes`]); returns (r, z, det J).
fn map_nodes(
    el: &dyn Parent,
    x: &[[f64; 2]],
    p: [f64; 2],
    n: &mut [f64],
    g: &mut [[f64; 3]],
) -> [f64; 3] {
    let mut dn = [[0.0; 2]; MAX_NODES];
    let dn = &mut dn[..x.len()];
    el.eval(p, n, dn);
    let (mut r, mut z) = (0.0, 0.0);
    let mut j = [[0.0; 2]; 2]; // j[a][b] = ∂x_a/∂ξ_b
    for (k, xk) in x.iter().enumerate() {
        r += n[k] * xk[0];
        z += n[k] * xk[1];
        for a in 0..2 {
            for b in 0..2 {
                j[a][b] += xk[a] * dn[k][b];
            }
        }
    }
    let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    // ∂ξ/∂x = J⁻¹
    let inv = [
        [j[1][1] / det, -j[0][1] / det],
        [-j[1][0] / det, j[0][0] / det],
    ];
    for (k, (d, gk)) in dn.iter().zip(g.iter_mut()).enumerate() {
        let dr = d[0] * inv[0][0] + d[1] * inv[1][0];
        let dz = d[0] * inv[0][1] + d[1] * inv[1][1];
        // hoop strain N/r; on the axis its limit ∂N/∂r (valid because u = 0 there)
        let hoop = if r > 1e-14 * (1.0 + z.abs()) {
            n[k] / r
        } else {
            dr
        };
        *gk = [dr, dz, hoop];
    }
    [r, z, det]
}

/// Gauss points of the tensor rule with their parent weights.
pub(crate) fn gauss(el: &dyn Parent) -> impl Iterator<Item = ([f64; 2], f64)> + '_ {
    let rule = el.rule();
    rule.iter()
        .flat_map(move |&(xi, wi)| rule.iter().map(move |&(eta, wj)| ([xi, eta], wi * wj)))
}

/// Element average of the volumetric row (ε_r + ε_z + ε_θ per dof).
pub(crate) fn mean_dilatation(el: &dyn Parent, x: &[[f64; 2]]) -> Vec<f64> {
    let nd = 2 * x.len();
    let (mut acc, mut vol) = (vec![0.0; nd], 0.0);
    for (p, w) in gauss(el) {
        let m = map(el, x, p);
        let dv = w * 2.0 * PI * m.r * m.det;
        vol += dv;
        for (a, bc) in acc.iter_mut().zip(&m.b) {
            *a += dv * (bc[0] + bc[1] + bc[2]);
        }
    }
    acc.iter().map(|a| a / vol).collect()
}

/// Replaces the volumetric part of the B columns by the element mean.
pub(crate) fn bbar(b: &mut [[f64; 4]], mean: &[f64]) {
    for (bc, m) in b.iter_mut().zip(mean) {
        let shift = (m - (bc[0] + bc[1] + bc[2])) / 3.0;
        for c in bc.iter_mut().take(3) {
            *c += shift;
        }
    }
}

pub(crate) fn stiffness(el: &dyn Parent, x: &[[f64; 2]], d: &[[f64; 4]; 4], bb: bool) -> Vec<f64> {
    let nd = 2 * x.len();
    let mean = if bb {
        mean_dilatation(el, x)
    } else {
        Vec::new()
    };
    let mut k = vec![0.0; nd * nd];
    let (mut n, mut g) = ([0.0; MAX_NODES], [[0.0; 3]; MAX_NODES]);
    for (p, w) in gauss(el) {
        if bb {
            let mut m = map(el, x, p);
            bbar(&mut m.b, &mean);
            add_btdb(&mut k, &m.b, d, w * 2.0 * PI * m.r * m.det);
        } else {
            // B without B-bar keeps its zeros: the product over the nonzeros only
            let [r, _, det] = map_nodes(el, x, p, &mut n[..x.len()], &mut g[..x.len()]);
            add_btdb_nodes(&mut k, &g[..x.len()], d, w * 2.0 * PI * r * det);
        }
    }
    mirror_upper(&mut k, nd);
    k
}

fn point(m: &Mapped, d: &[[f64; 4]; 4], u: &[f64], weight: f64) -> ElementPoint {
    let mut disp = [0.0; 2];
    for (k, nk) in m.n.iter().enumerate() {
        disp[0] += nk * u[2 * k];
        disp[1] += nk * u[2 * k + 1];
    }
    ElementPoint {
        r: m.r,
        z: m.z,
        weight,
        displacement: disp,
        stress: Stress::from_array(apply_d(d, &strain(&m.b, u))),
    }
}

pub(crate) fn gauss_points(
    el: &dyn Parent,
    x: &[[f64; 2]],
    d: &[[f64; 4]; 4],
    u: &[f64],
    bb: bool,
) -> Vec<ElementPoint> {
    let mean = if bb {
        mean_dilatation(el, x)
    } else {
        Vec::new()
    };
    gauss(el)
        .map(|(p, w)| {
            let mut m = map(el, x, p);
            if bb {
                bbar(&mut m.b, &mean);
            }
            point(&m, d, u, w * 2.0 * PI * m.r * m.det)
        })
        .collect()
}

pub(crate) fn at_parent(
    el: &dyn Parent,
    x: &[[f64; 2]],
    d: &[[f64; 4]; 4],
    u: &[f64],
    p: [f64; 2],
    bb: bool,
) -> ElementPoint {
    let mut m = map(el, x, p);
    if bb {
        bbar(&mut m.b, &mean_dilatation(el, x));
    }
    point(&m, d, u, 0.0)
}
