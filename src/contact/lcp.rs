//! The contact problem on the interface: a small dense linear complementarity problem (LCP).
//!
//! Once the plate (or the stack) is factorized, everything the contact iteration needs is the
//! interface flexibility F: entry F_ij is the gap change at interface point i per unit contact
//! force at point j (a Schur complement of the stiffness, computed once by a multi-right-hand-side
//! solve). With g⁰ the gap under the applied load alone (negative = penetration), the gaps and
//! the contact forces λ satisfy
//!
//! g = g⁰ + F λ,  g ≥ 0,  λ ≥ 0,  gᵢ λᵢ = 0  (Signorini conditions, report eq. 2.7 discretized).
//!
//! Sign convention: λ > 0 presses the bodies apart (compression in the contact), g > 0 is an
//! open gap; units are those of the flexibility (length per force). F is symmetric positive
//! definite (Betti–Maxwell reciprocity, and the supports remove every rigid motion), so the LCP
//! has exactly one solution.
//!
//! **Welded variant** (the report's model for unequal plates, Fig. 5(c)): each interface point
//! also has a tangential unknown (index `m + i` for point `i`): where the point is in contact its
//! tangential relative displacement is tied to zero and its tangential force is free in sign;
//! where it is open both its forces vanish. The active set is still decided by the normal
//! conditions alone.
//!
//! **Method.** Primal–dual active set (semismooth Newton on the min-function
//! min(λ, g) = 0): on the current active set solve F_AA λ_A = −g⁰_A by dense Cholesky, then
//! keep the active points with λ > 0 and add the open points with g < 0; stop when the set no
//! longer changes. Block pivoting usually converges in a handful of steps; should an active set
//! repeat (a cycle), the iteration switches to Murty's least-index single pivoting, which is
//! finite for any P-matrix (and an SPD matrix is one). The welded problem is not an LCP of that
//! kind and need not have a solution (plates of different materials welded together have no
//! sign-consistent contact edge): a repeated set under Murty's rule ends the pivoting, and the
//! welded problem then falls back to the report's own rule, the longest contact zone from the
//! inside out without tension ([`LcpInfo::prefix`]). Both are bounded by
//! [`LcpParams::max_iterations`]; beyond it the solver returns [`ContactError::NotConverged`].
//!
//! # Accuracy
//!
//! Against brute-force enumeration of active sets on random problems, the KKT conditions and
//! projected Gauss–Seidel (`tests/contact/lcp.rs`).
//!
//! # Cost
//!
//! A few dense solves of the window's size per level; its share of a two-plate run is printed by
//! `cargo bench --bench contact`.
//!
//! ```
//! use boltzone::contact::{solve_lcp, Lcp, LcpParams};
//! use nalgebra::{DMatrix, DVector};
//! // Two springs of flexibility 1 on a rigid plane, one pushed in by 1, the other lifted by 1.
//! let lcp = Lcp::frictionless(DMatrix::identity(2, 2), DVector::from_vec(vec![-1.0, 1.0]));
//! let s = solve_lcp(&lcp, &LcpParams::default())?;
//! assert!((s.force[0] - 1.0).abs() < 1e-15 && s.force[1] == 0.0);
//! assert!(s.active == vec![true, false]);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::ContactError;
use crate::error::InputError;
use nalgebra::{DMatrix, DVector};
use std::collections::HashSet;
use std::time::{Duration, Instant};

/// An interface LCP: flexibility, initial gaps, and whether contact points are welded.
#[derive(Debug, Clone, PartialEq)]
pub struct Lcp {
    /// Flexibility F (symmetric positive definite): m × m, or 2m × 2m when welded
    /// (normal unknowns first, then the tangential ones in the same point order).
    pub flexibility: DMatrix<f64>,
    /// Gaps (and, welded, tangential relative displacements) under the applied load alone.
    pub gap0: DVector<f64>,
    /// Welded contact: tangential motion tied inside the contact zone.
    pub welded: bool,
}

impl Lcp {
    /// A frictionless (normal-only) problem.
    pub fn frictionless(flexibility: DMatrix<f64>, gap0: DVector<f64>) -> Self {
        Self {
            flexibility,
            gap0,
            welded: false,
        }
    }

    /// Number of interface points m.
    pub fn points(&self) -> usize {
        if self.welded {
            self.gap0.len() / 2
        } else {
            self.gap0.len()
        }
    }

    fn check(&self) -> Result<(), InputError> {
        let n = self.gap0.len();
        let bad = |reason| {
            Err(InputError::Parameter {
                field: "LCP size",
                value: n as f64,
                reason,
            })
        };
        if self.flexibility.nrows() != n || self.flexibility.ncols() != n {
            return bad("the flexibility must be square and match the gap vector");
        }
        if self.welded && n % 2 != 0 {
            return bad("a welded problem needs a normal and a tangential unknown per point");
        }
        if let Some(x) = self
            .gap0
            .iter()
            .chain(self.flexibility.iter())
            .find(|x| !x.is_finite())
        {
            return Err(InputError::NotFinite {
                field: "LCP data",
                value: *x,
            });
        }
        Ok(())
    }

    /// Unknown indices that belong to the points in `active` (normals, then tangentials).
    fn unknowns(&self, active: &[bool]) -> Vec<usize> {
        let m = self.points();
        let mut idx: Vec<usize> = (0..m).filter(|&i| active[i]).collect();
        if self.welded {
            let t: Vec<usize> = idx.iter().map(|&i| m + i).collect();
            idx.extend(t);
        }
        idx
    }
}

/// Knobs of [`solve_lcp`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LcpParams {
    /// Bound on active-set iterations (block and single pivots together). Default 500.
    pub max_iterations: usize,
    /// Relative tolerance of the sign checks: a force counts as negative below
    /// −tol·max|λ|, a gap below −tol·max|g⁰|. Default 1e-10: the restricted systems are solved
    /// by Cholesky with a backward error of a few ε·cond(F), and the FE flexibilities met here
    /// have cond(F) ≲ 10⁵, so round-off stays below 1e-10 relative.
    pub tolerance: f64,
}

impl Default for LcpParams {
    fn default() -> Self {
        Self {
            max_iterations: 500,
            tolerance: 1e-10,
        }
    }
}

impl LcpParams {
    /// The tolerance must lie in (0, 1).
    pub(crate) fn check(&self) -> Result<(), InputError> {
        if !(self.tolerance.is_finite() && self.tolerance > 0.0 && self.tolerance < 1.0) {
            return Err(InputError::Parameter {
                field: "LcpParams::tolerance",
                value: self.tolerance,
                reason: "must lie in (0, 1)",
            });
        }
        Ok(())
    }
}

/// What the iteration did.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LcpInfo {
    /// Active-set iterations (dense solves).
    pub iterations: usize,
    /// Total number of points that changed between contact and open.
    pub changes: usize,
    /// Whether the least-index (Murty) fallback was needed.
    pub murty: bool,
    /// Whether the welded problem fell back to the report's contiguous-zone rule (module docs);
    /// then `residual` tells how far the Signorini conditions are from holding.
    pub prefix: bool,
    /// Largest relative violation at the solution: max over points of the negative parts of
    /// λ/max|λ| and g/max|g⁰|, and of |λ g|/(max|λ| max|g⁰|).
    pub residual: f64,
    /// Number of points in contact.
    pub active: usize,
    /// Wall time.
    pub time: Duration,
}

/// Solution of an [`Lcp`].
#[derive(Debug, Clone, PartialEq)]
pub struct LcpSolution {
    /// Contact forces λ (welded: normal then tangential).
    pub force: DVector<f64>,
    /// Gaps g = g⁰ + F λ (welded: then tangential relative displacements).
    pub gap: DVector<f64>,
    /// Which points are in contact.
    pub active: Vec<bool>,
    /// Iteration record.
    pub info: LcpInfo,
}

/// Solves the Signorini LCP by primal–dual active sets with a Murty fallback (module docs).
/// `warm` may give an initial active set (e.g. from a coarser mesh); by default the points that
/// penetrate under the load alone start in contact.
pub fn solve_lcp(lcp: &Lcp, params: &LcpParams) -> Result<LcpSolution, ContactError> {
    solve_lcp_from(lcp, params, None)
}

/// [`solve_lcp`] started from the active set `warm` (length m) when given.
pub fn solve_lcp_from(
    lcp: &Lcp,
    params: &LcpParams,
    warm: Option<&[bool]>,
) -> Result<LcpSolution, ContactError> {
    let start = Instant::now();
    match active_set(lcp, params, warm, start) {
        Err(ContactError::NotConverged { iterations, .. }) if lcp.welded => {
            prefix_scan(lcp, params, iterations, start)
        }
        other => other,
    }
}

fn active_set(
    lcp: &Lcp,
    params: &LcpParams,
    warm: Option<&[bool]>,
    start: Instant,
) -> Result<LcpSolution, ContactError> {
    lcp.check()?;
    params.check()?;
    let m = lcp.points();
    let mut active: Vec<bool> = match warm {
        Some(w) if w.len() == m => w.to_vec(),
        _ => (0..m).map(|i| lcp.gap0[i] < 0.0).collect(),
    };
    let g_scale = lcp.gap0.amax().max(f64::MIN_POSITIVE);
    let mut seen: HashSet<Vec<bool>> = HashSet::new();
    let mut info = LcpInfo::default();
    for it in 1..=params.max_iterations {
        info.iterations = it;
        let (force, gap) = solve_on(lcp, &active)?;
        let l_scale = force.amax().max(f64::MIN_POSITIVE);
        let tol_l = params.tolerance * l_scale;
        let tol_g = params.tolerance * g_scale;
        let violated: Vec<usize> = (0..m)
            .filter(|&i| {
                if active[i] {
                    force[i] < -tol_l
                } else {
                    gap[i] < -tol_g
                }
            })
            .collect();
        if violated.is_empty() {
            info.residual = residual(lcp, &force, &gap, g_scale);
            info.active = active.iter().filter(|&&a| a).count();
            info.time = start.elapsed();
            return Ok(LcpSolution {
                force,
                gap,
                active,
                info,
            });
        }
        seen.insert(active.clone());
        let mut next = active.clone();
        for &i in &violated {
            next[i] = !next[i];
        }
        if info.murty || seen.contains(&next) {
            // A block pivot would revisit a set: pivot the least violated index only.
            if !info.murty {
                info.murty = true;
                seen.clear();
                seen.insert(active.clone());
            }
            next = active.clone();
            next[violated[0]] = !next[violated[0]];
            info.changes += 1;
            if seen.contains(&next) {
                // Murty's rule cannot cycle on a P-matrix LCP; a cycle means the (welded) problem
                // has no solution on this path: give up now rather than at the bound.
                return Err(ContactError::NotConverged {
                    iterations: it,
                    violations: violated.len(),
                });
            }
        } else {
            info.changes += violated.len();
        }
        active = next;
        if it == params.max_iterations {
            return Err(ContactError::NotConverged {
                iterations: it,
                violations: violated.len(),
            });
        }
    }
    Err(ContactError::NotConverged {
        iterations: params.max_iterations,
        violations: m,
    })
}

/// The report's rule for the welded model when pivoting finds no solution (dissimilar
/// materials welded together have no sign-consistent contact edge): the contact zone is the
/// longest run of points from the inside out (points are ordered by radius) whose normal forces
/// are all compressive; among those runs the first, scanning from the longest, whose open points
/// do not penetrate is taken if there is one.
fn prefix_scan(
    lcp: &Lcp,
    params: &LcpParams,
    iterations: usize,
    start: Instant,
) -> Result<LcpSolution, ContactError> {
    let m = lcp.points();
    let g_scale = lcp.gap0.amax().max(f64::MIN_POSITIVE);
    let mut info = LcpInfo {
        iterations,
        prefix: true,
        murty: true,
        ..Default::default()
    };
    let mut best: Option<(Vec<bool>, DVector<f64>, DVector<f64>)> = None;
    for k in (0..=m).rev() {
        info.iterations += 1;
        let active: Vec<bool> = (0..m).map(|i| i < k).collect();
        let (force, gap) = solve_on(lcp, &active)?;
        let tol_l = params.tolerance * force.amax().max(f64::MIN_POSITIVE);
        if (0..k).any(|i| force[i] < -tol_l) {
            continue;
        }
        let tight = (k..m).all(|i| gap[i] >= -params.tolerance * g_scale);
        if tight || best.is_none() {
            best = Some((active, force, gap));
        }
        if tight {
            break;
        }
    }
    let (active, force, gap) = best.ok_or(ContactError::NotConverged {
        iterations: info.iterations,
        violations: m,
    })?;
    info.residual = residual(lcp, &force, &gap, g_scale);
    info.active = active.iter().filter(|&&a| a).count();
    info.time = start.elapsed();
    Ok(LcpSolution {
        force,
        gap,
        active,
        info,
    })
}

/// Forces and gaps with the points in `active` closed (g = 0, tangential tie if welded) and the
/// others free (λ = 0).
fn solve_on(lcp: &Lcp, active: &[bool]) -> Result<(DVector<f64>, DVector<f64>), ContactError> {
    let n = lcp.gap0.len();
    let idx = lcp.unknowns(active);
    let mut force = DVector::zeros(n);
    if !idx.is_empty() {
        let faa = lcp.flexibility.select_rows(&idx).select_columns(&idx);
        let rhs = -DVector::from_iterator(idx.len(), idx.iter().map(|&i| lcp.gap0[i]));
        let chol = faa
            .cholesky()
            .ok_or(ContactError::NotPositiveDefinite { size: idx.len() })?;
        let x = chol.solve(&rhs);
        for (k, &i) in idx.iter().enumerate() {
            force[i] = x[k];
        }
    }
    let gap = &lcp.gap0 + &lcp.flexibility * &force;
    Ok((force, gap))
}

/// The relative KKT residual of [`LcpInfo::residual`] (normal unknowns only).
pub fn residual(lcp: &Lcp, force: &DVector<f64>, gap: &DVector<f64>, g_scale: f64) -> f64 {
    let m = lcp.points();
    let l_scale = force.rows(0, m).amax().max(f64::MIN_POSITIVE);
    (0..m)
        .map(|i| {
            let l = force[i] / l_scale;
            let g = gap[i] / g_scale;
            (-l).max(0.0).max((-g).max(0.0)).max((l * g).abs())
        })
        .fold(0.0, f64::max)
}
