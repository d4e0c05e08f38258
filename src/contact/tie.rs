//! Tied degrees of freedom on top of the FE dof map: two nodes sharing one unknown.
//!
//! A closed contact pair between two deformable plates shares its axial displacement (and, in
//! the welded model, its radial one). With T the 0/1 matrix that maps the tied unknowns to the
//! FE equations (one 1 per row), the tied system is Tᵀ K T y = Tᵀ f and x = T y: Tᵀ K T is K
//! with rows and columns of tied equations summed, Tᵀ f sums their loads. On the lower triangle
//! that [`crate::fem::assemble()`] returns, an off-diagonal entry whose two equations are tied to
//! the same unknown lands on the diagonal twice (as K_ij and K_ji). Units and signs: those of K.
//!
//! (A thin layer the FE dof map could absorb as a `tie` support.)
//!
//! # Accuracy
//!
//! Exact (sums of entries): the doc example below; the two-plate mesh with tied interfaces
//! reproduces the symmetric model in `tests/contact/two_plate.rs`
//! (`two_plate_mesh_reproduces_the_symmetric_model`).
//!
//! # Cost
//!
//! Linear in the matrix's entries; part of each level's cost in `cargo bench --bench contact`.
//!
//! ```
//! use boltzone::contact::tie::Ties;
//! use faer::sparse::{SparseColMat, Triplet};
//! // Two unit springs to ground, tied together: one unknown of stiffness 2.
//! let k = SparseColMat::<usize, f64>::try_new_from_triplets(
//!     2, 2, &[Triplet::new(0, 0, 1.0), Triplet::new(1, 1, 1.0)])?;
//! let t = Ties::new(2, &[(0, 1)]);
//! let kt = t.matrix(&k)?;
//! assert_eq!(kt.nrows(), 1);
//! assert_eq!(t.restrict(&[1.0, 2.0]), vec![3.0]);
//! assert_eq!(t.prolong(&[5.0]), vec![5.0, 5.0]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use crate::fem::FemError;
use faer::sparse::{SparseColMat, Triplet};

/// A map from FE equations to tied unknowns.
#[derive(Debug, Clone, PartialEq)]
pub struct Ties {
    map: Vec<usize>,
    n: usize,
    trivial: bool,
}

impl Ties {
    /// Ties equation `b` to equation `a` for every pair (a, b) of `pairs` among `n_eq` equations.
    /// Chains are followed (tying c to b after b to a ties all three).
    pub fn new(n_eq: usize, pairs: &[(usize, usize)]) -> Self {
        let mut parent: Vec<usize> = (0..n_eq).collect();
        let root = |p: &Vec<usize>, mut i: usize| {
            while p[i] != i {
                i = p[i];
            }
            i
        };
        for &(a, b) in pairs {
            let (ra, rb) = (root(&parent, a), root(&parent, b));
            if ra != rb {
                parent[ra.max(rb)] = ra.min(rb);
            }
        }
        let mut index = vec![usize::MAX; n_eq];
        let mut n = 0;
        for (i, slot) in index.iter_mut().enumerate() {
            if root(&parent, i) == i {
                *slot = n;
                n += 1;
            }
        }
        let map = (0..n_eq).map(|i| index[root(&parent, i)]).collect();
        Self {
            map,
            n,
            trivial: n == n_eq,
        }
    }

    /// True when no two equations are tied (Tᵀ K T = K: callers may use K as it is).
    pub fn is_trivial(&self) -> bool {
        self.trivial
    }

    /// Number of tied unknowns.
    pub fn n(&self) -> usize {
        self.n
    }

    /// The tied unknown of FE equation `e`.
    pub fn of(&self, e: usize) -> usize {
        self.map[e]
    }

    /// Tᵀ K T from the lower triangle `k` (returned as a lower triangle).
    pub fn matrix(
        &self,
        k: &SparseColMat<usize, f64>,
    ) -> Result<SparseColMat<usize, f64>, FemError> {
        if self.trivial {
            return Ok(k.clone());
        }
        let mut trip = Vec::with_capacity(k.compute_nnz());
        for j in 0..k.ncols() {
            for (i, &v) in k.row_idx_of_col(j).zip(k.val_of_col(j)) {
                let (a, b) = (self.map[i], self.map[j]);
                if a == b && i != j {
                    trip.push(Triplet::new(a, a, 2.0 * v));
                } else {
                    trip.push(Triplet::new(a.max(b), a.min(b), v));
                }
            }
        }
        SparseColMat::try_new_from_triplets(self.n, self.n, &trip)
            .map_err(|e| FemError::Solver(format!("tied matrix: {e:?}")))
    }

    /// Tᵀ f.
    pub fn restrict(&self, f: &[f64]) -> Vec<f64> {
        let mut out = vec![0.0; self.n];
        for (i, v) in f.iter().enumerate() {
            out[self.map[i]] += v;
        }
        out
    }

    /// T y.
    pub fn prolong(&self, y: &[f64]) -> Vec<f64> {
        self.map.iter().map(|&i| y[i]).collect()
    }
}
