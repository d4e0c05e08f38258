//! Assembly of the global stiffness K = ∑ₑ kₑ (report eq. A.12) over the free components, as the
//! lower triangle of a sparse symmetric matrix, and of the prescribed-displacement load
//! Q* = −K_ab u_b (eq. A.20).
//!
//! The sparsity pattern ([`Pattern`]) depends only on the mesh and on which components are
//! free; it is built once from the mesh's node adjacency (faer's `SymbolicSparseColMat`, rows
//! sorted in each column) and every later assembly with other materials or prescribed values
//! only fills values. With the pattern come the value-array positions of every element's
//! entries, found while each column is built (a table of the column's rows indexed by
//! equation), so that assembly adds each kₑ entry at a stored position; an assembly with
//! other free components than the pattern's finds them by binary search. Skew
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
/// adjacency of the mesh, with every element's value positions.
#[derive(Debug, Clone)]
pub struct Pattern {
    symbolic: SymbolicSparseColMat<usize>,
    /// Local dofs per element (2 × nodes).
    nd: usize,
    /// The equation of each element's local dofs when the pattern was built (u32::MAX: none).
    equations: Vec<u32>,
    /// Per element, the position of the entry of local dofs (i, j), i ≤ j, at j(j + 1)/2 + i
    /// (u32::MAX where a dof has no equation); empty when the values outgrow u32.
    positions: Vec<u32>,
}

/// No equation / no position in the element tables.
const NONE: u32 = u32::MAX;

/// Index of local entry (i, j), i ≤ j, in an element's packed triangle.
fn packed(i: usize, j: usize) -> usize {
    j * (j + 1) / 2 + i
}

/// An assembled system: K (lower triangle stored) and the load of the prescribed components.
#[derive(Debug, Clone)]
pub struct Stiffness {
    /// Lower triangle of K over the free components.
    pub matrix: SparseColMat<usize, f64>,
    /// −K_ab u_b: add to every right-hand side (zero when all prescribed values are zero).
    pub prescribed_load: Vec<f64>,
}

/// Most local dofs of an element (Q9's 18).
const MAX_DOFS: usize = 18;

/// Equation numbers (or None) of an element's local dofs, in local order, into `out`.
fn element_equations(mesh: &Mesh, dofs: &DofMap, e: usize, out: &mut [Option<usize>]) {
    for (k, &n) in mesh.element_nodes(e).iter().enumerate() {
        out[2 * k] = dofs.equation(n, Component::R);
        out[2 * k + 1] = dofs.equation(n, Component::Z);
    }
}

impl Pattern {
    /// The pattern of K for `mesh` with the free components of `dofs`: column j holds every
    /// equation i ≥ j of a node that shares an element with j's node. Any numbering of the
    /// equations ([`DofMap::new`], [`DofMap::in_node_order`]).
    pub fn new(mesh: &Mesh, dofs: &DofMap) -> Self {
        let n = dofs.n_equations();
        let nd = 2 * mesh.kind().nodes();
        let n_el = mesh.n_elements();
        let mut equations = vec![NONE; n_el * nd];
        let mut eqs = [None; MAX_DOFS];
        for e in 0..n_el {
            element_equations(mesh, dofs, e, &mut eqs[..nd]);
            for (t, q) in equations[e * nd..(e + 1) * nd].iter_mut().zip(&eqs) {
                *t = q.map_or(NONE, |q| q as u32);
            }
        }
        // the elements of every node (ascending), to place their entries column by column
        let mut first = vec![0usize; mesh.n_nodes() + 1];
        for e in 0..n_el {
            for &p in mesh.element_nodes(e) {
                first[p + 1] += 1;
            }
        }
        for p in 0..mesh.n_nodes() {
            first[p + 1] += first[p];
        }
        let mut incident = vec![0usize; first[mesh.n_nodes()]];
        let mut fill = first.clone();
        for e in 0..n_el {
            for &p in mesh.element_nodes(e) {
                incident[fill[p]] = e;
                fill[p] += 1;
            }
        }
        // the node and component of every equation
        let mut owner = vec![(0usize, 0usize); n];
        for p in 0..mesh.n_nodes() {
            for c in [Component::R, Component::Z] {
                if let Some(j) = dofs.equation(p, c) {
                    owner[j] = (p, c as usize);
                }
            }
        }
        let packed_len = nd * (nd + 1) / 2;
        let mut positions = vec![NONE; n_el * packed_len];
        let mut at = vec![NONE; n]; // position of each row of the current column
        let mut col_ptr = Vec::with_capacity(n + 1);
        col_ptr.push(0);
        let mut row_idx = Vec::new();
        // the equations of the elements of the current node, sorted and unique
        let (mut near, mut near_of): (Vec<u32>, usize) = (Vec::new(), usize::MAX);
        let mut seen = vec![usize::MAX; n]; // the node whose list last took each equation
        for (j, &(p, c)) in owner.iter().enumerate() {
            let elements = &incident[first[p]..first[p + 1]];
            if near_of != p {
                near.clear();
                for &e in elements {
                    for &i in &equations[e * nd..(e + 1) * nd] {
                        if i != NONE && seen[i as usize] != p {
                            seen[i as usize] = p;
                            near.push(i);
                        }
                    }
                }
                near.sort_unstable();
                near_of = p;
            }
            let start = row_idx.len();
            let col = &near[near.partition_point(|&i| (i as usize) < j)..];
            row_idx.extend(col.iter().map(|&i| i as usize));
            col_ptr.push(row_idx.len());
            if row_idx.len() >= NONE as usize {
                continue; // positions beyond u32: assembly searches (see `positions`)
            }
            for (k, &i) in col.iter().enumerate() {
                at[i as usize] = (start + k) as u32;
            }
            // every element of p: its entries (i, j) of this column, i ≥ j, at every place of p
            // in the element (a card deck's degenerate quadrilateral names one node twice, and
            // `elements` lists it once per place, consecutively: it is visited once)
            for (k, &e) in elements.iter().enumerate() {
                if k > 0 && elements[k - 1] == e {
                    continue;
                }
                let places = mesh.element_nodes(e).iter().enumerate();
                for lj in places.filter(|(_, &q)| q == p).map(|(a, _)| 2 * a + c) {
                    for (li, &i) in equations[e * nd..(e + 1) * nd].iter().enumerate() {
                        if i != NONE && i as usize >= j {
                            positions[e * packed_len + packed(li.min(lj), li.max(lj))] =
                                at[i as usize];
                        }
                    }
                }
            }
        }
        if row_idx.len() >= NONE as usize {
            positions = Vec::new();
        }
        Self {
            symbolic: SymbolicSparseColMat::new_checked(n, n, col_ptr, None, row_idx),
            nd,
            equations,
            positions,
        }
    }

    /// The stored positions of element `e`'s entries when its local dofs have the equations
    /// `eqs` the pattern was built with (else None: the caller searches).
    fn element_positions(&self, e: usize, eqs: &[Option<usize>]) -> Option<&[u32]> {
        let len = self.nd * (self.nd + 1) / 2;
        let stored = self.equations.get(e * self.nd..(e + 1) * self.nd)?;
        let same = eqs.len() == self.nd
            && eqs
                .iter()
                .zip(stored)
                .all(|(q, &t)| q.map_or(NONE, |q| q as u32) == t);
        if same {
            self.positions.get(e * len..(e + 1) * len)
        } else {
            None
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
    let mut buf = [None; MAX_DOFS];
    for e in 0..mesh.n_elements() {
        let k = element_matrix(mesh, materials, dofs, e)?;
        let nodes = mesh.element_nodes(e);
        let nd = 2 * nodes.len();
        let eqs = &mut buf[..nd];
        element_equations(mesh, dofs, e, eqs);
        let stored = pattern.element_positions(e, eqs);
        for (i, a) in eqs.iter().enumerate() {
            let Some(a) = *a else { continue };
            for (j, b) in eqs.iter().enumerate() {
                match *b {
                    Some(b) if a >= b => {
                        let pos = match stored.map(|t| t[packed(i.min(j), i.max(j))]) {
                            Some(t) if t != NONE => t as usize,
                            _ => pattern
                                .position(a, b)
                                .ok_or(FemError::PatternMismatch { row: a, col: b })?,
                        };
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
