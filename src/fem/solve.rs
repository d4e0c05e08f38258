//! Sparse Cholesky K = L Lᵀ with faer (fill-reducing AMD, a caller's ordering, or none for
//! equations already numbered in a fill-reducing order ([`Factorization::natural`]), always the
//! supernodal variant: faer's own flop-ratio rule picks the simplicial one for 1k–10k equations,
//! where the supernodal one measured 2.6× faster, and the 20 × 20 design map 39 % cheaper): the symbolic analysis is done once per [`super::Pattern`], the numeric
//! factorization again only when values change ([`Factorization::refactor`]), and one
//! factorization serves any number of right-hand sides ([`Factorization::solve_many`]), e.g. the
//! unit loads of an interface flexibility matrix.
//!
//! # Accuracy
//!
//! Relative residuals ‖Kx − b‖/‖b‖ below 1e-10 (example 08 checks every size it runs and fails
//! otherwise; the test suite runs 2·10³ and 8·10³ equations); parallel and sequential
//! factorizations agree, flexibilities are symmetric (`tests/fem/system.rs`).
//!
//! # Cost
//!
//! `cargo bench --bench fem`, example 08.
//!
//! ```
//! use boltzone::fem::*;
//! use boltzone::Material;
//! let r = Spacing::uniform(1.0, 2.0, 4)?;
//! let z = Spacing::uniform(0.0, 0.5, 2)?;
//! let mesh = Mesh::structured(ElementKind::Q4, &r, &[PlateSpec { z, material: 0 }])?;
//! let mut s = Supports::new(mesh.n_nodes());
//! for n in mesh.bottom(0) { s.roller_z(n); }
//! let dofs = DofMap::new(&s);
//! let k = assemble(&mesh, &[Material::unit(0.3)?], &dofs, &Pattern::new(&mesh, &dofs))?;
//! let f = Factorization::new(&k.matrix, &SolveParams::default())?;
//! let b = vec![1.0; dofs.n_equations()];
//! let x = f.solve(&b);
//! assert!(x.iter().all(|v| v.is_finite()));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::FemError;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::llt::factor::LltRegularization;
use faer::perm::PermRef;
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, CholeskySymbolicParams, LltRef, SymbolicCholesky,
    SymmetricOrdering,
};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::{SparseColMat, SymbolicSparseColMat, SymbolicSparseColMatRef};
use faer::{Conj, Mat, MatRef, Par, Side};
use std::sync::Arc;
use std::time::Instant;

/// Parameters of the sparse solve.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SolveParams {
    /// Use faer's multi-threaded kernels (default false: on a busy 2-core machine sequential is
    /// faster, and callers running several solves in parallel want it off).
    pub parallel: bool,
}

/// A numeric L Lᵀ factorization with its shareable symbolic analysis.
#[derive(Debug, Clone)]
pub struct Factorization {
    symbolic: Arc<SymbolicCholesky<usize>>,
    values: Vec<f64>,
    par: Par,
    seconds: [f64; 2],
}

impl Factorization {
    /// Symbolic and numeric factorization of the lower triangle `k` (AMD ordering).
    pub fn new(k: &SparseColMat<usize, f64>, params: &SolveParams) -> Result<Self, FemError> {
        Self::with_ordering(k, None, params)
    }

    /// As [`Factorization::new`] with a caller's elimination order (`order[k]` = the equation
    /// eliminated k-th, e.g. [`super::nested_dissection`]); None: AMD.
    pub fn with_ordering(
        k: &SparseColMat<usize, f64>,
        order: Option<&[usize]>,
        params: &SolveParams,
    ) -> Result<Self, FemError> {
        let t0 = Instant::now();
        let inverse: Vec<usize>;
        let ord = match order {
            None => SymmetricOrdering::Amd,
            Some(fwd) => {
                let n = k.nrows();
                let mut inv = vec![usize::MAX; n];
                for (new, &old) in fwd.iter().enumerate() {
                    if old < n && new < n {
                        inv[old] = new;
                    }
                }
                if fwd.len() != n || inv.contains(&usize::MAX) {
                    return Err(FemError::Solver(format!(
                        "the ordering is not a permutation of 0..{n}"
                    )));
                }
                inverse = inv;
                SymmetricOrdering::Custom(PermRef::new_checked(fwd, &inverse, n))
            }
        };
        Self::ordered(k, k.symbolic(), Side::Lower, ord, t0, params)
    }

    /// As [`Factorization::new`] in the equations' own order (no permutation of the matrix at
    /// either step): for equations already numbered in a fill-reducing order, e.g. a
    /// [`super::DofMap::in_node_order`] of [`super::node_dissection`], where it computes what
    /// [`Factorization::with_ordering`] with [`super::nested_dissection`] computes on the
    /// mesh's own numbering (`tests/fem/system.rs`,
    /// `natural_order_in_dissection_numbering_equals_the_permuted_factorization`: the same
    /// displacements to the last bit).
    ///
    /// ```
    /// use boltzone::fem::*;
    /// use boltzone::Material;
    /// let r = Spacing::uniform(1.0, 2.0, 8)?;
    /// let z = Spacing::uniform(0.0, 0.5, 4)?;
    /// let mesh = Mesh::structured(ElementKind::Q9, &r, &[PlateSpec { z, material: 0 }])?;
    /// let mut s = Supports::new(mesh.n_nodes());
    /// for n in mesh.bottom(0) { s.roller_z(n); }
    /// let dofs = DofMap::in_node_order(&s, &node_dissection(&mesh))?;
    /// let k = assemble(&mesh, &[Material::unit(0.3)?], &dofs, &Pattern::new(&mesh, &dofs))?;
    /// let x = Factorization::natural(&k.matrix, &SolveParams::default())?.solve(&vec![1.0; dofs.n_equations()]);
    /// assert!(x.iter().all(|v| v.is_finite()));
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn natural(k: &SparseColMat<usize, f64>, params: &SolveParams) -> Result<Self, FemError> {
        // faer 0.24 reads the pattern as the upper triangle whatever the side when it does not
        // permute: give it the transpose (the numeric step reads the lower one as it is)
        let t0 = Instant::now();
        let upper = transpose(k.symbolic());
        Self::ordered(
            k,
            upper.as_ref(),
            Side::Upper,
            SymmetricOrdering::Identity,
            t0,
            params,
        )
    }

    fn ordered(
        k: &SparseColMat<usize, f64>,
        pattern: SymbolicSparseColMatRef<'_, usize>,
        side: Side,
        ord: SymmetricOrdering<'_, usize>,
        t0: Instant,
        params: &SolveParams,
    ) -> Result<Self, FemError> {
        let supernodal = CholeskySymbolicParams {
            supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SUPERNODAL,
            ..Default::default()
        };
        let symbolic = factorize_symbolic_cholesky(pattern, side, ord, supernodal)
            .map_err(|e| FemError::Solver(format!("symbolic Cholesky: {e:?}")))?;
        let par = if params.parallel {
            Par::rayon(0)
        } else {
            Par::Seq
        };
        let mut f = Self {
            symbolic: Arc::new(symbolic),
            values: Vec::new(),
            par,
            seconds: [t0.elapsed().as_secs_f64(), 0.0],
        };
        f.refactor(k)?;
        Ok(f)
    }

    /// Numeric factorization of new values with the same pattern (the symbolic step is reused).
    pub fn refactor(&mut self, k: &SparseColMat<usize, f64>) -> Result<(), FemError> {
        let t0 = Instant::now();
        let sym = &*self.symbolic;
        // (faer zeroes the values before it factors: only the length is set here)
        self.values.resize(sym.len_val(), 0.0);
        let mut mem =
            MemBuffer::new(sym.factorize_numeric_llt_scratch::<f64>(self.par, Default::default()));
        sym.factorize_numeric_llt(
            &mut self.values,
            k.as_ref(),
            Side::Lower,
            LltRegularization::default(),
            self.par,
            MemStack::new(&mut mem),
            Default::default(),
        )
        .map_err(|e| FemError::NotPositiveDefinite(format!("{e:?}")))?;
        self.seconds[1] = t0.elapsed().as_secs_f64();
        Ok(())
    }

    /// Number of equations.
    pub fn n(&self) -> usize {
        self.symbolic.nrows()
    }

    /// Wall-clock seconds of the symbolic analysis and of the last numeric factorization.
    pub fn seconds(&self) -> [f64; 2] {
        self.seconds
    }

    /// Stored entries of L (a measure of fill and memory: 8 bytes each).
    pub fn factor_entries(&self) -> usize {
        self.values.len()
    }

    /// Solves K x = b.
    pub fn solve(&self, b: &[f64]) -> Vec<f64> {
        let x = self.solve_many(MatRef::from_column_major_slice(b, b.len(), 1));
        x.col(0).iter().copied().collect()
    }

    /// Solves K X = B for every column of B at once.
    pub fn solve_many(&self, b: MatRef<'_, f64>) -> Mat<f64> {
        self.solve_many_in_place(b.to_owned())
    }

    /// [`Factorization::solve_many`] overwriting B (no copy of it).
    pub fn solve_many_in_place(&self, mut x: Mat<f64>) -> Mat<f64> {
        let sym = &*self.symbolic;
        let mut mem = MemBuffer::new(sym.solve_in_place_scratch::<f64>(x.ncols(), self.par));
        LltRef::new(sym, &self.values).solve_in_place_with_conj(
            Conj::No,
            x.as_mut(),
            self.par,
            MemStack::new(&mut mem),
        );
        x
    }
}

/// The transposed pattern (the upper triangle of a symmetric matrix from its lower one), rows
/// sorted in each column.
fn transpose(k: SymbolicSparseColMatRef<'_, usize>) -> SymbolicSparseColMat<usize> {
    let n = k.nrows();
    let mut col_ptr = vec![0usize; n + 1];
    for j in 0..k.ncols() {
        for i in k.row_idx_of_col(j) {
            col_ptr[i + 1] += 1;
        }
    }
    for i in 0..n {
        col_ptr[i + 1] += col_ptr[i];
    }
    let mut next = col_ptr.clone();
    let mut row_idx = vec![0usize; col_ptr[n]];
    for j in 0..k.ncols() {
        for i in k.row_idx_of_col(j) {
            row_idx[next[i]] = j;
            next[i] += 1;
        }
    }
    SymbolicSparseColMat::new_checked(k.ncols(), n, col_ptr, None, row_idx)
}
