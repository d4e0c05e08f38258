//! Nested-dissection ordering of a structured mesh's equations (George 1973), an alternative to
//! faer's default approximate minimum degree (AMD) for the sparse Cholesky.
//!
//! The node grid (columns in r × rows in z over all plates) is split recursively by a grid line
//! that is an element boundary (so it separates the two halves: no element couples across it),
//! chosen across the longer side nearest the middle; each half is ordered first, the separator
//! last. Blocks of ≤ 64 nodes keep the mesh's own order. On an n × n grid this gives
//! O(n² log n) fill and O(n³) work (Hoffman, Martin & Rose 1973 show this is optimal order).
//! Every free component of a node is numbered with it, so 2 × 2 node blocks stay together.
//!
//! # Accuracy
//!
//! A permutation (doc example); the solution does not depend on the ordering: `tests/fem/system.rs`
//! (`parallel_and_sequential_factorizations_agree`).
//!
//! # Cost
//!
//! O(N log N) for N nodes; its effect on the factorization is timed by example 08.
//!
//! ```
//! use boltzone::fem::*;
//! let r = Spacing::uniform(0.0, 1.0, 20)?;
//! let z = Spacing::uniform(0.0, 1.0, 20)?;
//! let mesh = Mesh::structured(ElementKind::Q4, &r, &[PlateSpec { z, material: 0 }])?;
//! let dofs = DofMap::new(&Supports::new(mesh.n_nodes()));
//! let p = nested_dissection(&mesh, &dofs);
//! let mut seen = p.clone();
//! seen.sort();
//! assert!(seen.iter().enumerate().all(|(i, &v)| i == v)); // a permutation
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::dofs::{Component, DofMap};
use super::mesh::Mesh;

struct Grid<'a> {
    rows: usize,
    order: usize,
    row_ok: Vec<bool>,
    out: &'a mut Vec<usize>,
}

impl Grid<'_> {
    fn push_block(&mut self, i0: usize, i1: usize, j0: usize, j1: usize) {
        for i in i0..=i1 {
            for j in j0..=j1 {
                self.out.push(i * self.rows + j);
            }
        }
    }

    fn split_col(&self, i0: usize, i1: usize) -> Option<usize> {
        let mid = (i0 + i1) / 2;
        (0..=(i1 - i0) / 2)
            .flat_map(|d| [mid.wrapping_sub(d), mid + d])
            .find(|&i| i > i0 && i < i1 && i % self.order == 0)
    }

    fn split_row(&self, j0: usize, j1: usize) -> Option<usize> {
        let mid = (j0 + j1) / 2;
        (0..=(j1 - j0) / 2)
            .flat_map(|d| [mid.wrapping_sub(d), mid + d])
            .find(|&j| j > j0 && j < j1 && self.row_ok[j])
    }

    fn dissect(&mut self, i0: usize, i1: usize, j0: usize, j1: usize) {
        let (ni, nj) = (i1 - i0 + 1, j1 - j0 + 1);
        if ni * nj <= 64 {
            return self.push_block(i0, i1, j0, j1);
        }
        let by_col = if ni >= nj {
            self.split_col(i0, i1)
                .map(|i| (true, i))
                .or(self.split_row(j0, j1).map(|j| (false, j)))
        } else {
            self.split_row(j0, j1)
                .map(|j| (false, j))
                .or(self.split_col(i0, i1).map(|i| (true, i)))
        };
        match by_col {
            None => self.push_block(i0, i1, j0, j1),
            Some((true, s)) => {
                self.dissect(i0, s - 1, j0, j1);
                self.dissect(s + 1, i1, j0, j1);
                self.push_block(s, s, j0, j1);
            }
            Some((false, s)) => {
                self.dissect(i0, i1, j0, s - 1);
                self.dissect(i0, i1, s + 1, j1);
                self.push_block(i0, i1, s, s);
            }
        }
    }
}

/// The equations of `dofs` in nested-dissection order: entry k is the equation eliminated k-th
/// (faer's "forward" permutation, new → old).
pub fn nested_dissection(mesh: &Mesh, dofs: &DofMap) -> Vec<usize> {
    node_dissection(mesh)
        .iter()
        .flat_map(|&n| {
            [
                dofs.equation(n, Component::R),
                dofs.equation(n, Component::Z),
            ]
        })
        .flatten()
        .collect()
}

/// The nodes of a structured mesh in nested-dissection order: numbering the equations in it
/// ([`DofMap::in_node_order`](super::DofMap::in_node_order)) makes [`nested_dissection`] the
/// identity, so the factorization needs no permutation of the matrix
/// ([`Factorization::natural`](super::Factorization::natural)).
pub fn node_dissection(mesh: &Mesh) -> Vec<usize> {
    let cols = mesh.radial_nodes().len();
    let rows = mesh.n_nodes() / cols;
    let order = mesh.kind().order();
    let mut row_ok = Vec::with_capacity(rows);
    for k in 0..mesh.n_plates() {
        row_ok.extend((0..mesh.plate_z(k).len()).map(|j| j % order == 0));
    }
    let mut nodes = Vec::with_capacity(mesh.n_nodes());
    let mut g = Grid {
        rows,
        order,
        row_ok,
        out: &mut nodes,
    };
    g.dissect(0, cols - 1, 0, rows - 1);
    nodes
}
