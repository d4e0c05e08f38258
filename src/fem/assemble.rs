//! Assembly of the global stiffness K = ∑ₑ kₑ (report eq. A.12) over the free components, as the
//! lower triangle of a sparse symmetric matrix, and of the prescribed-displacement load
//! Q* = −K_ab u_b (eq. A.20).
//!
//! The sparsity pattern ([`Pattern`]) depends only on the mesh and on which components are
//! free; it is built once (faer's `SymbolicSparseColMat` with the order of the assembled values)
//! and every later assembly with other materials or prescribed values only fills values. Skew
//! nodes enter through kₑ' = Tᵀ kₑ T with T the node's rotation (s, n) → (r, z).
//!
//! ```
//! use boltzone::fem::*;
//! use boltzone::Material;
//! let r = Spacing::uniform(1.0, 2.0, 2).unwrap();
//! let z = Spacing::uniform(0.0, 1.0, 1).unwrap();
//! let mesh = Mesh::structured(ElementKind::Q4, &r, &[PlateSpec { z, material: 0 }]).unwrap();
//! let mut s = Supports::new(mesh.n_nodes());
//! for n in mesh.bottom(0) { s.roller_z(n); }
//! let dofs = DofMap::new(&s);
//! let pattern = Pattern::new(&mesh, &dofs);
//! let k = assemble(&mesh, &[Material::unit(0.3).unwrap()], &dofs, &pattern).unwrap();
//! assert_eq!(k.matrix.nrows(), dofs.n_equations());
//! ```

use super::dofs::{Component, DofMap};
use super::mesh::Mesh;
use super::FemError;
use crate::material::Material;
use faer::sparse::{Argsort, Pair, SparseColMat, SymbolicSparseColMat};

/// The fixed sparsity pattern of the lower triangle and the order of assembled values.
#[derive(Debug, Clone)]
pub struct Pattern {
    symbolic: SymbolicSparseColMat<usize>,
    argsort: Argsort<usize>,
    n_values: usize,
}

/// An assembled system: K (lower triangle stored) and the load of the prescribed components.
#[derive(Debug, Clone)]
pub struct Stiffness {
    /// Lower triangle of K over the free components.
    pub matrix: SparseColMat<usize, f64>,
    /// −K_ab u_b: add to every right-hand side (zero when all prescribed values are zero).
    pub prescribed_load: Vec<f64>,
}

/// Equation numbers (or None) of an element's local dofs, in local order.
fn element_equations(mesh: &Mesh, dofs: &DofMap, e: usize) -> Vec<Option<usize>> {
    mesh.element_nodes(e)
        .iter()
        .flat_map(|&n| {
            [
                dofs.equation(n, Component::R),
                dofs.equation(n, Component::Z),
            ]
        })
        .collect()
}

impl Pattern {
    /// The pattern of K for `mesh` with the free components of `dofs`.
    pub fn new(mesh: &Mesh, dofs: &DofMap) -> Self {
        let mut idx = Vec::new();
        for e in 0..mesh.n_elements() {
            let eqs = element_equations(mesh, dofs, e);
            for &a in eqs.iter().flatten() {
                for &b in eqs.iter().flatten() {
                    if a >= b {
                        idx.push(Pair::new(a, b));
                    }
                }
            }
        }
        let n = dofs.n_equations();
        let (symbolic, argsort) = SymbolicSparseColMat::try_new_from_indices(n, n, &idx)
            .expect("indices are in range by construction");
        Self {
            symbolic,
            argsort,
            n_values: idx.len(),
        }
    }

    /// The symbolic lower-triangular structure.
    pub fn symbolic(&self) -> &SymbolicSparseColMat<usize> {
        &self.symbolic
    }
}

/// Element stiffness in the nodes' frames (Tᵀ k T for skew nodes).
pub(crate) fn element_matrix(
    mesh: &Mesh,
    materials: &[Material],
    dofs: &DofMap,
    e: usize,
) -> Result<Vec<f64>, FemError> {
    let mi = mesh.element_material(e);
    let m = materials.get(mi).ok_or(FemError::MissingMaterial {
        element: e,
        material: mi,
        available: materials.len(),
    })?;
    let mut k = mesh.kind().stiffness(&mesh.element_coords(e), m);
    let nodes = mesh.element_nodes(e);
    let nd = 2 * nodes.len();
    for (a, &n) in nodes.iter().enumerate() {
        if let Some((c, s)) = dofs.frame(n) {
            // columns: K T, then rows: Tᵀ K (T = [[c, −s], [s, c]] on this node's block)
            let (i, j) = (2 * a, 2 * a + 1);
            for row in 0..nd {
                let (x, y) = (k[row * nd + i], k[row * nd + j]);
                k[row * nd + i] = c * x + s * y;
                k[row * nd + j] = -s * x + c * y;
            }
            for col in 0..nd {
                let (x, y) = (k[i * nd + col], k[j * nd + col]);
                k[i * nd + col] = c * x + s * y;
                k[j * nd + col] = -s * x + c * y;
            }
        }
    }
    Ok(k)
}

/// Assembles K over the free components and −K_ab u_b.
pub fn assemble(
    mesh: &Mesh,
    materials: &[Material],
    dofs: &DofMap,
    pattern: &Pattern,
) -> Result<Stiffness, FemError> {
    let mut values = Vec::with_capacity(pattern.n_values);
    let mut load = vec![0.0; dofs.n_equations()];
    for e in 0..mesh.n_elements() {
        let k = element_matrix(mesh, materials, dofs, e)?;
        let eqs = element_equations(mesh, dofs, e);
        let nodes = mesh.element_nodes(e);
        let nd = eqs.len();
        for (i, a) in eqs.iter().enumerate() {
            let Some(a) = *a else { continue };
            for (j, b) in eqs.iter().enumerate() {
                match *b {
                    Some(b) if a >= b => values.push(k[i * nd + j]),
                    Some(_) => {}
                    None => {
                        let c = if j % 2 == 0 {
                            Component::R
                        } else {
                            Component::Z
                        };
                        let v = dofs.prescribed(nodes[j / 2], c).unwrap_or(0.0);
                        load[a] -= k[i * nd + j] * v;
                    }
                }
            }
        }
    }
    if values.len() != pattern.n_values {
        return Err(FemError::PatternMismatch {
            expected: pattern.n_values,
            found: values.len(),
        });
    }
    let matrix =
        SparseColMat::new_from_argsort(pattern.symbolic.clone(), &pattern.argsort, &values)
            .map_err(|e| FemError::Solver(format!("{e:?}")))?;
    Ok(Stiffness {
        matrix,
        prescribed_load: load,
    })
}
