//! The report's quadrilateral (Appendix A; Wilson's program, Appendix B): four constant-strain
//! triangles around a centre node placed at the mean of the four corners, the centre's two
//! degrees of freedom condensed out (the listing's "ten equilibrium equations" per element,
//! reduced to eight by Gaussian elimination of equations 10 and 9).
//!
//! In each triangle (i, j, k) the displacement is linear, eq. (A.21):
//! u = α₁ + α₂ r + α₃ z, w = α₄ + α₅ r + α₆ z, i.e. N_i = (a_i + b_i r + c_i z)/(2Δ) with
//! b_i = z_j − z_k, c_i = r_k − r_j. The strains are constant except the hoop strain u/r, which,
//! like the stiffness integral, is evaluated at the triangle's centroid r̄:
//! k_t = 2π r̄ Δ Bᵀ(r̄) D B(r̄) (one-point rule, exact for the patch test).
//!
//! Condensation: with b the eight corner dofs and c the two centre dofs,
//! k* = k_bb − k_bc k_cc⁻¹ k_cb and, after the solve, u_c = −k_cc⁻¹ k_cb u_b.
//!
//! The listing's triangle I, J, K, K (last two corners equal) is one constant-strain triangle,
//! no centre. A uniform thermal strain ε_th = α ΔT (Appendix C) enters as the condensed forces
//! [`thermal_load`] and leaves the stresses as σ = D (ε − ε_th); [`listing_centre`] is the centre
//! stress as the listing's STRESS routine forms it (tested through decks in `tests/io/exact.rs`).
//!
//! # Accuracy
//!
//! Symmetric stiffness with one rigid-body mode and the patch tests to round-off:
//! `tests/fem/elements.rs`; convergence on the Lamé cylinder through decks: `tests/io/exact.rs`
//! (`lame_cylinder_converges_at_second_order`); the thermal load: `tests/io/exact.rs`
//! (`free_body_at_uniform_temperature_expands_without_stress`).
//!
//! # Cost
//!
//! Four triangles and a 10×10 condensation per element; `cargo bench --bench fem`.
//!
//! ```
//! use boltzone::fem::element::ElementKind;
//! let x = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
//! let k = ElementKind::Cst4.stiffness(&x, &boltzone::Material::unit(0.25)?);
//! assert_eq!(k.len(), 64);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::{add_btdb, apply_d, elasticity, mirror_upper, strain, ElementPoint, Stress};
use crate::material::Material;
use std::f64::consts::PI;

/// One triangle: its three local dof-node indices (4 = centre), centroid, area, B columns.
struct Tri {
    nodes: [usize; 3],
    r: f64,
    z: f64,
    area: f64,
    b: Vec<[f64; 4]>,
}

fn with_centre(x: &[[f64; 2]]) -> [[f64; 2]; 5] {
    let c = [
        x.iter().map(|p| p[0]).sum::<f64>() / 4.0,
        x.iter().map(|p| p[1]).sum::<f64>() / 4.0,
    ];
    [x[0], x[1], x[2], x[3], c]
}

/// True when the quadrilateral is the listing's triangle I, J, K, K (last two corners equal).
fn is_triangle(x: &[[f64; 2]]) -> bool {
    x[2] == x[3]
}

fn triangle(p: &[[f64; 2]; 5], nodes: [usize; 3]) -> Tri {
    let v = nodes.map(|i| p[i]);
    let two_area =
        (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[2][0] - v[0][0]) * (v[1][1] - v[0][1]);
    let r = (v[0][0] + v[1][0] + v[2][0]) / 3.0;
    let z = (v[0][1] + v[1][1] + v[2][1]) / 3.0;
    let mut b = Vec::with_capacity(6);
    for i in 0..3 {
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let bi = (v[j][1] - v[k][1]) / two_area;
        let ci = (v[k][0] - v[j][0]) / two_area;
        // N_i at the centroid is 1/3
        b.push([bi, 0.0, 1.0 / (3.0 * r), ci]);
        b.push([0.0, ci, 0.0, bi]);
    }
    Tri {
        nodes,
        r,
        z,
        area: 0.5 * two_area,
        b,
    }
}

/// The four triangles around the centre, or the one triangle of I, J, K, K.
fn triangles(x: &[[f64; 2]]) -> Vec<Tri> {
    let p = with_centre(x);
    if is_triangle(x) {
        return vec![triangle(&p, [0, 1, 2])];
    }
    (0..4).map(|t| triangle(&p, [t, (t + 1) % 4, 4])).collect()
}

/// The 10 × 10 stiffness before condensation.
fn full_stiffness(tris: &[Tri], d: &[[f64; 4]; 4]) -> Vec<f64> {
    let mut k = vec![0.0; 100];
    for t in tris {
        let mut kt = vec![0.0; 36];
        add_btdb(&mut kt, &t.b, d, 2.0 * PI * t.r * t.area);
        mirror_upper(&mut kt, 6);
        let dofs: Vec<usize> = t.nodes.iter().flat_map(|&n| [2 * n, 2 * n + 1]).collect();
        for (a, &ga) in dofs.iter().enumerate() {
            for (b, &gb) in dofs.iter().enumerate() {
                k[ga * 10 + gb] += kt[a * 6 + b];
            }
        }
    }
    k
}

/// k_cc⁻¹ (2 × 2) of the centre dofs.
fn centre_inverse(k: &[f64]) -> [[f64; 2]; 2] {
    let (a, b, c, e) = (k[88], k[89], k[98], k[99]);
    let det = a * e - b * c;
    [[e / det, -b / det], [-c / det, a / det]]
}

pub(crate) fn stiffness(x: &[[f64; 2]], d: &[[f64; 4]; 4]) -> Vec<f64> {
    let k = full_stiffness(&triangles(x), d);
    let mut out = vec![0.0; 64];
    if is_triangle(x) {
        // no centre node: the corner block (node L = K carries zero rows and columns)
        for i in 0..8 {
            out[i * 8..i * 8 + 8].copy_from_slice(&k[i * 10..i * 10 + 8]);
        }
        return out;
    }
    let inv = centre_inverse(&k);
    for i in 0..8 {
        for j in 0..8 {
            let mut s = k[i * 10 + j];
            for a in 0..2 {
                for b in 0..2 {
                    s -= k[i * 10 + 8 + a] * inv[a][b] * k[(8 + b) * 10 + j];
                }
            }
            out[i * 8 + j] = s;
        }
    }
    out
}

/// The thermal strain (ε_r, ε_z, ε_θ, γ_rz) = e·(1, 1, 1, 0) of an isotropic expansion e.
fn thermal_strain(e: f64) -> [f64; 4] {
    [e, e, e, 0.0]
}

/// The 10 thermal forces ∑ₜ wₜ Bₜᵀ D ε_th of the uncondensed element.
fn full_thermal(tris: &[Tri], d: &[[f64; 4]; 4], eth: f64) -> [f64; 10] {
    let s = apply_d(d, &thermal_strain(eth));
    let mut f = [0.0; 10];
    for t in tris {
        let w = 2.0 * PI * t.r * t.area;
        for (a, col) in t.b.iter().enumerate() {
            let dof = 2 * t.nodes[a / 2] + a % 2;
            f[dof] += w * (0..4).map(|c| col[c] * s[c]).sum::<f64>();
        }
    }
    f
}

/// All ten dofs: the eight corner values and the recovered centre displacement
/// u_c = k_cc⁻¹ (f_c − k_cb u_b), f_c the centre's thermal force (zero for a triangle, which has
/// no centre: its centroid displacement is stored instead).
fn expand(tris: &[Tri], d: &[[f64; 4]; 4], u: &[f64], eth: f64) -> [f64; 10] {
    let mut all = [0.0; 10];
    all[..8].copy_from_slice(&u[..8]);
    if tris.len() == 1 {
        all[8] = (u[0] + u[2] + u[4]) / 3.0;
        all[9] = (u[1] + u[3] + u[5]) / 3.0;
        return all;
    }
    let k = full_stiffness(tris, d);
    let inv = centre_inverse(&k);
    let f = full_thermal(tris, d, eth);
    let rhs: [f64; 2] =
        [0, 1].map(|a| f[8 + a] - (0..8).map(|j| k[(8 + a) * 10 + j] * u[j]).sum::<f64>());
    all[8] = inv[0][0] * rhs[0] + inv[0][1] * rhs[1];
    all[9] = inv[1][0] * rhs[0] + inv[1][1] * rhs[1];
    all
}

/// Stress σ = D (B u − ε_th) of triangle `t` from all ten dofs.
fn triangle_stress(t: &Tri, d: &[[f64; 4]; 4], all: &[f64; 10], eth: f64) -> ([f64; 4], [f64; 6]) {
    let mut ue = [0.0; 6];
    for (k, &n) in t.nodes.iter().enumerate() {
        ue[2 * k] = all[2 * n];
        ue[2 * k + 1] = all[2 * n + 1];
    }
    let mut e = strain(&t.b, &ue);
    for (ei, ti) in e.iter_mut().zip(thermal_strain(eth)) {
        *ei -= ti;
    }
    (apply_d(d, &e), ue)
}

/// The four triangles' centroid points; `eth` the element's uniform thermal strain (0 without).
pub(crate) fn points(x: &[[f64; 2]], d: &[[f64; 4]; 4], u: &[f64], eth: f64) -> Vec<ElementPoint> {
    let tris = triangles(x);
    let all = expand(&tris, d, u, eth);
    tris.iter()
        .map(|t| {
            let (s, ue) = triangle_stress(t, d, &all, eth);
            ElementPoint {
                r: t.r,
                z: t.z,
                weight: 2.0 * PI * t.r * t.area,
                displacement: [(ue[0] + ue[2] + ue[4]) / 3.0, (ue[1] + ue[3] + ue[5]) / 3.0],
                stress: Stress::from_array(s),
            }
        })
        .collect()
}

/// Volume-weighted mean of the four triangles' stresses at the centre node.
pub(crate) fn centre(x: &[[f64; 2]], d: &[[f64; 4]; 4], u: &[f64], eth: f64) -> ElementPoint {
    let tris = triangles(x);
    let pts = points(x, d, u, eth);
    let all = expand(&tris, d, u, eth);
    let w: f64 = pts.iter().map(|p| p.weight).sum();
    let mut s = [0.0; 4];
    for p in &pts {
        for (si, pi) in s.iter_mut().zip(p.stress.to_array()) {
            *si += p.weight * pi / w;
        }
    }
    let c = if tris.len() == 1 {
        [tris[0].r, tris[0].z]
    } else {
        with_centre(x)[4]
    };
    ElementPoint {
        r: c[0],
        z: c[1],
        weight: w,
        displacement: [all[8], all[9]],
        stress: Stress::from_array(s),
    }
}

/// Each corner gets the mean stress of the two triangles that contain it (a triangle element:
/// its one stress).
pub(crate) fn corner_stresses(
    x: &[[f64; 2]],
    d: &[[f64; 4]; 4],
    u: &[f64],
    eth: f64,
) -> Vec<Stress> {
    let pts = points(x, d, u, eth);
    if pts.len() == 1 {
        return vec![pts[0].stress; 4];
    }
    (0..4)
        .map(|c| {
            let (a, b) = (pts[c].stress.to_array(), pts[(c + 3) % 4].stress.to_array());
            Stress::from_array([0, 1, 2, 3].map(|i| 0.5 * (a[i] + b[i])))
        })
        .collect()
}

/// Condensed nodal forces (8, whole-ring, dofs u₀, w₀, …) of a uniform isotropic thermal strain
/// `eth` = α ΔT (Appendix C): f* = f_b − k_bc k_cc⁻¹ f_c with f = ∑ₜ wₜ Bₜᵀ D ε_th. Add them to
/// the load vector; the element's stresses are then D (ε − ε_th) ([`listing_centre`]).
pub fn thermal_load(x: &[[f64; 2]], m: &Material, eth: f64) -> Vec<f64> {
    let d = elasticity(m);
    let tris = triangles(x);
    let f = full_thermal(&tris, &d, eth);
    if tris.len() == 1 {
        return f[..8].to_vec();
    }
    let k = full_stiffness(&tris, &d);
    let inv = centre_inverse(&k);
    (0..8)
        .map(|i| {
            let mut s = f[i];
            for a in 0..2 {
                for b in 0..2 {
                    s -= k[i * 10 + 8 + a] * inv[a][b] * f[8 + b];
                }
            }
            s
        })
        .collect()
}

/// The stress at the element's centre as the 1970 listing's STRESS routine computes it: the
/// four triangles' linear displacement fields averaged (their generalized coordinates, the
/// listing's HH/4), so ε_r, ε_z and γ_rz are the plain means of the triangles' constant strains
/// and ε_θ = u_c/r_c with u_c the condensed centre displacement (every triangle interpolates it
/// exactly); σ = D (ε − ε_th). A triangle element reports its own strain at its centroid. `u`
/// holds the corner displacements (u₀, w₀, …), `eth` the thermal strain α ΔT (0 without).
pub fn listing_centre(x: &[[f64; 2]], m: &Material, u: &[f64], eth: f64) -> ElementPoint {
    let d = elasticity(m);
    let tris = triangles(x);
    let all = expand(&tris, &d, u, eth);
    let n = tris.len() as f64;
    let mut e = [0.0; 4];
    for t in &tris {
        let (_, ue) = triangle_stress(t, &d, &all, eth);
        for (ei, si) in e.iter_mut().zip(strain(&t.b, &ue)) {
            *ei += si / n;
        }
    }
    let c = if tris.len() == 1 {
        [tris[0].r, tris[0].z]
    } else {
        with_centre(x)[4]
    };
    if tris.len() > 1 {
        e[2] = all[8] / c[0];
    }
    for (ei, ti) in e.iter_mut().zip(thermal_strain(eth)) {
        *ei -= ti;
    }
    ElementPoint {
        r: c[0],
        z: c[1],
        weight: tris.iter().map(|t| 2.0 * PI * t.r * t.area).sum(),
        displacement: [all[8], all[9]],
        stress: Stress::from_array(apply_d(&d, &e)),
    }
}
