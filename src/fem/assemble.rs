//! Assembly of the global stiffness K = ∑ₑ kₑ (report eq. A.12) over the free components, as the
//! lower triangle of a sparse symmetric matrix, and of the prescribed-displacement load
//! Q* = −K_ab u_b (eq. A.20).
//!
//! The sparsity pattern ([`Pattern`]) depends only on the mesh and on which components are
//! free; it is built once from the mesh's node adjacency (faer's `SymbolicSparseColMat`, rows
//! sorted in each column, entries located by binary search) and every later assembly with other
//! materials or prescribed values only fills values. Skew
//! nodes enter through kₑ' = Tᵀ kₑ T with T the node's rotation (s, n) → (r, z).
//!
//! # Accuracy
//!
//! Exact to rounding: the patch tests of `tests/fem/elements.rs` (`displacement_patch_test`,
//! `traction_patch_test_with_skew_rollers`) and the reused pattern of `tests/fem/system.rs`
//! (`refactor_reuses_the_pattern`).
//!
//! # Cost
//!
//! Linear in the elements; example 08 times the pattern and the assembly up to 10⁶ equations,
//! `cargo bench --bench fem`.
//!
//! ```
//! use boltzone::fem::*;
//! use boltzone::Material;
//! let r = Spacing::uniform(1.0, 2.0, 2)?;
//! let z = Spacing::uniform(0.0, 1.0, 1)?;
//! let mesh = Mesh::structured(ElementKind::Q4, &r, &[PlateSpec { z, material: 0 }])?;
//! let mut s = Supports::new(mesh.n_nodes());
//! for n in mesh.bottom(0) { s.roller_z(n); }
//! let dofs = DofMap::new(&s);
//! let pattern = Pattern::new(&mesh, &dofs);
//! let k = assemble(&mesh, &[Material::unit(0.3)?], &dofs, &pattern)?;
//! assert_eq!(k.matrix.nrows(), dofs.n_equations());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::dofs::{Component, DofMap};
use super::error::FemError;
use super::mesh::Mesh;
use super::recover::material;
use crate::material::Material;
use faer::sparse::{SparseColMat, SymbolicSparseColMat};

/// The fixed sparsity pattern of the lower triangle (columns sorted), built from the node
/// adjacency of the mesh.
#[derive(Debug, Clone)]
pub struct Pattern {
    symbolic: SymbolicSparseColMat<usize>,
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
    /// The pattern of K for `mesh` with the free components of `dofs`: column j holds every
    /// equation i ≥ j of a node that shares an element with j's node.
    pub fn new(mesh: &Mesh, dofs: &DofMap) -> Self {
        // neighbours q ≥ p of every node p (sorted, unique)
        let mut adj: Vec<Vec<u32>> = vec![Vec::new(); mesh.n_nodes()];
        for e in 0..mesh.n_elements() {
            let nodes = mesh.element_nodes(e);
            for &p in nodes {
                adj[p].extend(nodes.iter().filter(|&&q| q >= p).map(|&q| q as u32));
            }
        }
        let n = dofs.n_equations();
        let mut col_ptr = Vec::with_capacity(n + 1);
        col_ptr.push(0);
        let mut row_idx = Vec::new();
        let mut col = Vec::new();
        for (p, list) in adj.iter_mut().enumerate() {
            list.sort_unstable();
            list.dedup();
            for c in [Component::R, Component::Z] {
                let Some(j) = dofs.equation(p, c) else {
                    continue;
                };
                col.clear();
                for &q in list.iter() {
                    for cq in [Component::R, Component::Z] {
                        if let Some(i) = dofs.equation(q as usize, cq) {
                            if i >= j {
                                col.push(i);
                            }
                        }
                    }
                }
                col.sort_unstable();
                row_idx.extend_from_slice(&col);
                col_ptr.push(row_idx.len());
            }
            *list = Vec::new();
        }
        Self {
            symbolic: SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx),
        }
    }

    /// The symbolic lower-triangular structure.
    pub fn symbolic(&self) -> &SymbolicSparseColMat<usize> {
        &self.symbolic
    }

    /// Position of entry (i, j), i ≥ j, in the value array.
    pub(crate) fn position(&self, i: usize, j: usize) -> Option<usize> {
        let range = self.symbolic.col_range(j);
        let rows = &self.symbolic.row_idx()[range.clone()];
        rows.binary_search(&i).ok().map(|k| range.start + k)
    }
}

/// Element stiffness in the nodes' frames (Tᵀ k T for skew nodes).
pub(crate) fn element_matrix(
    mesh: &Mesh,
    materials: &[Material],
    dofs: &DofMap,
    e: usize,
) -> Result<Vec<f64>, FemError> {
    let m = material(mesh, materials, e)?;
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
    if pattern.symbolic.nrows() != dofs.n_equations() {
        return Err(FemError::PatternSize {
            pattern: pattern.symbolic.nrows(),
            equations: dofs.n_equations(),
        });
    }
    let mut values = vec![0.0; pattern.symbolic.row_idx().len()];
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
                    Some(b) if a >= b => {
                        let pos = pattern
                            .position(a, b)
                            .ok_or(FemError::PatternMismatch { row: a, col: b })?;
                        values[pos] += k[i * nd + j];
                    }
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
    let matrix = SparseColMat::new(pattern.symbolic.clone(), values);
    Ok(Stiffness {
        matrix,
        prescribed_load: load,
    })
}
