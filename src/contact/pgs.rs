//! Projected Gauss–Seidel: a second, independent method for the frictionless contact LCP.
//!
//! For g = g⁰ + F λ ≥ 0, λ ≥ 0, gᵀλ = 0 with F symmetric positive definite, sweep
//! λᵢ ← max(0, λᵢ − gᵢ(λ)/Fᵢᵢ) over the points in order. Each update minimises the convex
//! quadratic ½λᵀFλ + g⁰ᵀλ over λᵢ ≥ 0 exactly (the LCP is that problem's optimality condition),
//! so the iteration converges for any SPD F (Cryer 1971), linearly and often slowly. It shares
//! no code with the active-set solver [`super::solve_lcp`] and serves to check it; it is not
//! meant for production use. Units and signs as in [`super::lcp`].
//!
//! # Accuracy
//!
//! Agrees with the active-set solver (`tests/contact/lcp.rs`,
//! `kkt_conditions_hold_and_pgs_agrees`).
//!
//! # Cost
//!
//! Linear convergence: many sweeps.
//!
//! ```
//! use boltzone::contact::projected_gauss_seidel;
//! use nalgebra::{DMatrix, DVector};
//! let f = DMatrix::from_row_slice(2, 2, &[2.0, 1.0, 1.0, 2.0]);
//! let (l, sweeps) = projected_gauss_seidel(&f, &DVector::from_vec(vec![-3.0, 1.0]), 1e-14, 10_000);
//! assert!((l[0] - 1.5).abs() < 1e-12 && l[1] == 0.0 && sweeps < 10_000);
//! ```

use nalgebra::{DMatrix, DVector};

/// Runs projected Gauss–Seidel sweeps until the largest change of a force in one sweep falls
/// below `tol` × the largest force, or `max_sweeps` are done. Returns the forces and the sweeps.
pub fn projected_gauss_seidel(
    f: &DMatrix<f64>,
    gap0: &DVector<f64>,
    tol: f64,
    max_sweeps: usize,
) -> (DVector<f64>, usize) {
    let m = gap0.len();
    let mut l = DVector::zeros(m);
    for sweep in 1..=max_sweeps {
        let mut change: f64 = 0.0;
        for i in 0..m {
            let gi = gap0[i] + f.row(i).dot(&l.transpose());
            let new = (l[i] - gi / f[(i, i)]).max(0.0);
            change = change.max((new - l[i]).abs());
            l[i] = new;
        }
        if change <= tol * l.amax() {
            return (l, sweep);
        }
    }
    (l, max_sweeps)
}
