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
//! ```
//! use boltzone::fem::element::ElementKind;
//! let x = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
//! let k = ElementKind::Cst4.stiffness(&x, &boltzone::Material::unit(0.25)?);
//! assert_eq!(k.len(), 64);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::{add_btdb, apply_d, mirror_upper, strain, ElementPoint, Stress};
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

fn triangles(x: &[[f64; 2]]) -> Vec<Tri> {
    let p = with_centre(x);
    (0..4)
        .map(|t| {
            let nodes = [t, (t + 1) % 4, 4];
            let v = nodes.map(|i| p[i]);
            let two_area = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1])
                - (v[2][0] - v[0][0]) * (v[1][1] - v[0][1]);
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
        })
        .collect()
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
    let inv = centre_inverse(&k);
    let mut out = vec![0.0; 64];
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

/// All ten dofs: the eight corner values and the recovered centre displacement.
fn expand(tris: &[Tri], d: &[[f64; 4]; 4], u: &[f64]) -> [f64; 10] {
    let k = full_stiffness(tris, d);
    let inv = centre_inverse(&k);
    let kcb: [f64; 2] = [0, 1].map(|a| (0..8).map(|j| k[(8 + a) * 10 + j] * u[j]).sum());
    let mut all = [0.0; 10];
    all[..8].copy_from_slice(&u[..8]);
    all[8] = -(inv[0][0] * kcb[0] + inv[0][1] * kcb[1]);
    all[9] = -(inv[1][0] * kcb[0] + inv[1][1] * kcb[1]);
    all
}

pub(crate) fn points(x: &[[f64; 2]], d: &[[f64; 4]; 4], u: &[f64]) -> Vec<ElementPoint> {
    let tris = triangles(x);
    let all = expand(&tris, d, u);
    tris.iter()
        .map(|t| {
            let ue: Vec<f64> = t
                .nodes
                .iter()
                .flat_map(|&n| [all[2 * n], all[2 * n + 1]])
                .collect();
            let disp = [(ue[0] + ue[2] + ue[4]) / 3.0, (ue[1] + ue[3] + ue[5]) / 3.0];
            ElementPoint {
                r: t.r,
                z: t.z,
                weight: 2.0 * PI * t.r * t.area,
                displacement: disp,
                stress: Stress::from_array(apply_d(d, &strain(&t.b, &ue))),
            }
        })
        .collect()
}

/// Volume-weighted mean of the four triangles' stresses at the centre node.
pub(crate) fn centre(x: &[[f64; 2]], d: &[[f64; 4]; 4], u: &[f64]) -> ElementPoint {
    let pts = points(x, d, u);
    let c = with_centre(x)[4];
    let all = expand(&triangles(x), d, u);
    let w: f64 = pts.iter().map(|p| p.weight).sum();
    let mut s = [0.0; 4];
    for p in &pts {
        for (si, pi) in s.iter_mut().zip(p.stress.to_array()) {
            *si += p.weight * pi / w;
        }
    }
    ElementPoint {
        r: c[0],
        z: c[1],
        weight: w,
        displacement: [all[8], all[9]],
        stress: Stress::from_array(s),
    }
}

/// Each corner gets the mean stress of the two triangles that contain it.
pub(crate) fn corner_stresses(x: &[[f64; 2]], d: &[[f64; 4]; 4], u: &[f64]) -> Vec<Stress> {
    let pts = points(x, d, u);
    (0..4)
        .map(|c| {
            let (a, b) = (pts[c].stress.to_array(), pts[(c + 3) % 4].stress.to_array());
            Stress::from_array([0, 1, 2, 3].map(|i| 0.5 * (a[i] + b[i])))
        })
        .collect()
}
