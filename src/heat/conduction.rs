//! Steady axisymmetric heat conduction on the finite-element meshes of [`crate::fem`]: a scalar
//! temperature T(r, z) in a stack of plates joined by an interface conductance h(r).
//!
//! Weak form of ∇·(k∇T) = 0 with dV = 2πr dr dz: K T = f with
//! K_ab = ∫ k ∇N_a·∇N_b 2πr dr dz over each plate (k per material), plus, between the top of
//! plate p and the bottom of plate p + 1 (coincident, distinct nodes), the interface conductance
//! lumped at the nodes: g_i = h(r_i) ∫ N_i 2πr dr joining node i of one plate to its partner.
//! Faces without a condition are insulated; fixed temperatures are eliminated. The heat flow
//! at a fixed node is its reaction (K T)_i, positive into the body. Units: any consistent set
//! (SI: W/(m·K), W/(m²·K), m, K give W).
//!
//! Method: Q4 (2 × 2 Gauss) or Q9 (3 × 3) shape functions of [`crate::fem::element`], assembled
//! sparse and factored by [`crate::fem::Factorization`].
//!
//! # Accuracy
//!
//! `tests/heat/conduction.rs`: two plates with a uniform h against the one-dimensional series
//! resistance D₁/k₁ + 1/h + D₂/k₂ (exact: T is linear in z); radial flow through an annulus against
//! 2πkD/ln(b/a): the heat flow's error falls at the square of the energy norm's rate, measured 1.99
//! (Q4, predicted 2) and 3.95 (Q9, predicted 4) from 32 to 64 elements (Q9 error 2.3e-7 at 64).
//!
//! # Cost
//!
//! One sparse Cholesky of the mesh's nodes.
//!
//! ```
//! use boltzone::fem::{ElementKind, Mesh, PlateSpec, Spacing};
//! use boltzone::heat::conduction::solve_conduction;
//! let r = Spacing::uniform(1.0, 2.0, 4)?;
//! let plate = PlateSpec { z: Spacing::uniform(0.0, 1.0, 2)?, material: 0 };
//! let mesh = Mesh::structured(ElementKind::Q4, &r, &[plate])?;
//! let fixed: Vec<(usize, f64)> = mesh.bottom(0).into_iter().map(|n| (n, 0.0))
//!     .chain(mesh.top(0).into_iter().map(|n| (n, 1.0))).collect();
//! let s = solve_conduction(&mesh, &[2.0], &|_| 0.0, &fixed)?;
//! // k ΔT / D over the annulus' area π(2² − 1²).
//! let q: f64 = mesh.top(0).iter().map(|&n| s.flow[n]).sum();
//! assert!((q - 2.0 * std::f64::consts::PI * 3.0).abs() < 1e-10);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::error::{finite, non_negative, positive, InputError};
use crate::fem::element::{q4, q9, ElementKind, GAUSS2, GAUSS3};
use crate::fem::{Factorization, Mesh, SolveParams};
use faer::sparse::{SparseColMat, Triplet};
use std::f64::consts::PI;
use std::time::Instant;

/// Temperatures and heat flows of [`solve_conduction`].
#[derive(Debug, Clone, PartialEq)]
pub struct ConductionSolution {
    /// Temperature per mesh node.
    pub temperature: Vec<f64>,
    /// Heat flow into the body at each fixed node (0 at free nodes).
    pub flow: Vec<f64>,
    /// Seconds to assemble and solve.
    pub seconds: f64,
}

/// Shape functions and their parent derivatives of a Q4 or Q9 element.
fn shape(kind: ElementKind, p: [f64; 2]) -> (Vec<f64>, Vec<[f64; 2]>) {
    match kind {
        ElementKind::Q9 => {
            let (n, d) = q9::shape(p);
            (n.to_vec(), d.to_vec())
        }
        _ => {
            let (n, d) = q4::shape(p);
            (n.to_vec(), d.to_vec())
        }
    }
}

/// ∫ k ∇N_a·∇N_b 2πr dA of one element, row-major.
fn element_matrix(kind: ElementKind, x: &[[f64; 2]], k: f64) -> Vec<f64> {
    let nn = x.len();
    let mut m = vec![0.0; nn * nn];
    let rule: &[(f64, f64)] = if kind == ElementKind::Q9 {
        &GAUSS3
    } else {
        &GAUSS2
    };
    for &(xi, wi) in rule {
        for &(eta, wj) in rule {
            let (n, dn) = shape(kind, [xi, eta]);
            // Jacobian columns: ∂(r, z)/∂ξ and ∂(r, z)/∂η.
            let (mut r, mut jac) = (0.0, [[0.0; 2]; 2]);
            for (a, xa) in x.iter().enumerate() {
                r += n[a] * xa[0];
                for (c, jc) in jac.iter_mut().enumerate() {
                    jc[0] += xa[c] * dn[a][0];
                    jc[1] += xa[c] * dn[a][1];
                }
            }
            let det = jac[0][0] * jac[1][1] - jac[0][1] * jac[1][0];
            let grad: Vec<[f64; 2]> = dn
                .iter()
                .map(|d| {
                    [
                        (d[0] * jac[1][1] - d[1] * jac[1][0]) / det,
                        (d[1] * jac[0][0] - d[0] * jac[0][1]) / det,
                    ]
                })
                .collect();
            let w = k * 2.0 * PI * r * det.abs() * wi * wj;
            for a in 0..nn {
                for b in 0..nn {
                    m[a * nn + b] += w * (grad[a][0] * grad[b][0] + grad[a][1] * grad[b][1]);
                }
            }
        }
    }
    m
}

/// ∫ N_i 2πr dr along a horizontal line of nodes sorted by r (edges of 2 or 3 nodes).
fn line_weights(mesh: &Mesh, line: &[usize]) -> Vec<f64> {
    let order = if mesh.kind() == ElementKind::Q9 { 2 } else { 1 };
    let x = mesh.nodes();
    let mut w = vec![0.0; line.len()];
    for start in (0..line.len().saturating_sub(1)).step_by(order) {
        let (r0, r1) = (x[line[start]][0], x[line[start + order]][0]);
        for &(t, wt) in &GAUSS3 {
            let r = 0.5 * (r0 + r1) + 0.5 * (r1 - r0) * t;
            let n: Vec<f64> = if order == 1 {
                vec![0.5 * (1.0 - t), 0.5 * (1.0 + t)]
            } else {
                vec![0.5 * t * (t - 1.0), 1.0 - t * t, 0.5 * t * (t + 1.0)]
            };
            for (a, na) in n.iter().enumerate() {
                w[start + a] += na * 2.0 * PI * r * 0.5 * (r1 - r0) * wt;
            }
        }
    }
    w
}

/// Solves K T = f (module docs): `conductivity[m]` of material m, `interface_h(r)` between
/// consecutive plates (≥ 0), `fixed` (node, temperature) pairs (at least one).
pub fn solve_conduction(
    mesh: &Mesh,
    conductivity: &[f64],
    interface_h: &dyn Fn(f64) -> f64,
    fixed: &[(usize, f64)],
) -> Result<ConductionSolution, InputError> {
    let start = Instant::now();
    let n = mesh.n_nodes();
    if mesh.kind() == ElementKind::Cst4 {
        return Err(InputError::Parameter {
            field: "element kind",
            value: 0.0,
            reason: "conduction takes Q4, Q4Bbar or Q9 meshes",
        });
    }
    for &k in conductivity {
        positive("conductivity k", k)?;
    }
    // Equation numbers: free nodes only.
    let mut value = vec![None; n];
    for &(node, t) in fixed {
        if node >= n {
            return Err(InputError::Parameter {
                field: "fixed node",
                value: node as f64,
                reason: "is not a node of the mesh",
            });
        }
        value[node] = Some(finite("fixed temperature", t)?);
    }
    if fixed.is_empty() {
        return Err(InputError::Parameter {
            field: "fixed temperatures",
            value: 0.0,
            reason: "at least one node needs a temperature",
        });
    }
    let mut eq = vec![usize::MAX; n];
    let mut m = 0;
    for i in 0..n {
        if value[i].is_none() {
            eq[i] = m;
            m += 1;
        }
    }
    // All couplings (a, b, g) of the full matrix, element and interface.
    let mut full: Vec<(usize, usize, f64)> = Vec::new();
    for e in 0..mesh.n_elements() {
        let mat = mesh.element_material(e);
        let k = *conductivity.get(mat).ok_or(InputError::Parameter {
            field: "material index",
            value: mat as f64,
            reason: "has no conductivity",
        })?;
        let nodes = mesh.element_nodes(e);
        let km = element_matrix(mesh.kind(), &mesh.element_coords(e), k);
        let nn = nodes.len();
        for a in 0..nn {
            for b in 0..nn {
                full.push((nodes[a], nodes[b], km[a * nn + b]));
            }
        }
    }
    for p in 0..mesh.n_plates().saturating_sub(1) {
        let (lo, up) = (mesh.top(p), mesh.bottom(p + 1));
        let w = line_weights(mesh, &lo);
        for ((&i, &j), wi) in lo.iter().zip(&up).zip(&w) {
            let g = wi * non_negative("interface conductance h", interface_h(mesh.nodes()[i][0]))?;
            full.extend([(i, i, g), (j, j, g), (i, j, -g), (j, i, -g)]);
        }
    }
    let mut trip = Vec::new();
    let mut rhs = vec![0.0; m];
    for &(a, b, g) in &full {
        match (value[a], value[b]) {
            (None, None) if eq[a] >= eq[b] => trip.push(Triplet::new(eq[a], eq[b], g)),
            (None, Some(tb)) => rhs[eq[a]] -= g * tb,
            _ => {}
        }
    }
    let mut temperature: Vec<f64> = value.iter().map(|v| v.unwrap_or(0.0)).collect();
    if m > 0 {
        let kff = SparseColMat::<usize, f64>::try_new_from_triplets(m, m, &trip).map_err(|_| {
            InputError::Parameter {
                field: "conduction matrix",
                value: m as f64,
                reason: "could not be assembled",
            }
        })?;
        let f = Factorization::new(&kff, &SolveParams::default()).map_err(|_| {
            InputError::Parameter {
                field: "conduction matrix",
                value: m as f64,
                reason: "is singular: a plate without a fixed temperature or interface",
            }
        })?;
        let t = f.solve(&rhs);
        for i in 0..n {
            if eq[i] != usize::MAX {
                temperature[i] = t[eq[i]];
            }
        }
    }
    let mut flow = vec![0.0; n];
    for &(a, b, g) in &full {
        if value[a].is_some() {
            flow[a] += g * temperature[b];
        }
    }
    Ok(ConductionSolution {
        temperature,
        flow,
        seconds: start.elapsed().as_secs_f64(),
    })
}
