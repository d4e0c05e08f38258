//! One mesh level of the two-plate contact problem: mesh, factor once, Schur complement on the
//! candidate interface points, LCP, recovery of p(r) and g(r).
//!
//! Interface points are split three ways. *Tied* points are closed for good: on a rigid plane
//! their w is held at 0, between two plates the pair shares its w (and, welded, its u). At least
//! one tied point removes the rigid axial motion (the "reference"); on finer levels every point
//! well inside the previous level's contact zone is tied, so that only the few points near a
//! contact boundary remain unknown. *Window* points are the LCP unknowns. Points beyond the
//! window are taken open. After the solve the assumptions are checked — tied points must press
//! (p ≥ 0), points beyond the window must not penetrate (g ≥ 0) — and the caller widens the
//! window or unties points when they fail.
//!
//! With K the reduced stiffness, f the load and Bⱼ the unit pair force of window point j
//! (+1 on the upper plate's w, −1 on the lower plate's), one multi-right-hand-side solve gives
//! X = K⁻¹[f | B], the gaps under the load g⁰ = Bᵀ X₀ and the flexibility F = Bᵀ X_B; the contact
//! forces λ solve the LCP of [`super::lcp`] and the displacements are X₀ + X_B λ.
//! Contact forces are read back as the upper plate's internal nodal forces on its interface
//! nodes, pressures as force / tributary area ∫N_i 2πr dr. Forces are totals (2π included), z up.

use super::lcp::{solve_lcp, Lcp, LcpInfo, LcpParams};
use super::stack::{Dof, Solver, Stack};
use super::ContactError;
use faer::Mat;
use nalgebra::{DMatrix, DVector};
use std::time::{Duration, Instant};

/// What the level needs to know besides the mesh.
#[derive(Debug, Clone)]
pub struct LevelSetup<'a> {
    /// Radial lines of tied interface points (non-empty).
    pub tied: &'a [usize],
    /// Radial lines of the LCP unknowns.
    pub window: &'a [usize],
    /// Whether to tie u as well as w for tied points and solve the welded LCP (two plates).
    pub welded: bool,
    /// Whether an axial support is still needed to remove the stack's rigid motion.
    pub fix_rigid: bool,
    /// LCP knobs.
    pub lcp: LcpParams,
    /// Loaded annulus (A, B) of the upper plate's top face, for the deflection under the nut.
    pub nut: (f64, f64),
}

/// The state of the interface after one level.
#[derive(Debug, Clone)]
pub struct LevelSolution {
    /// Interface node radii.
    pub radius: Vec<f64>,
    /// Contact force on the upper plate at each interface node (total, axial, > 0 compression).
    pub force: Vec<f64>,
    /// Interface pressure: force / tributary area.
    pub pressure: Vec<f64>,
    /// Gap w_upper − w_lower (rigid plane: w_upper).
    pub gap: Vec<f64>,
    /// Whether each interface node is closed (tied or active).
    pub closed: Vec<bool>,
    /// Full nodal displacements (u, w interleaved).
    pub displacement: Vec<f64>,
    /// Mean axial displacement of the upper plate's top face over the loaded annulus, weighted
    /// by area (the deflection under the nut; negative = toward the interface).
    pub nut_deflection: f64,
    /// The LCP record.
    pub lcp: LcpInfo,
    /// Reduced unknowns.
    pub dofs: usize,
    /// Assembly + factorization + the load solve.
    pub time_linear: Duration,
    /// Flexibility solves + LCP + recovery.
    pub time_contact: Duration,
}

/// Applies the ties of `setup`, numbers, factors and solves the level (module docs).
/// `supports` prescribes the loads' displacements and edge supports before numbering, and
/// `loads` adds face loads to the reduced right-hand side.
pub fn solve_level(
    mut stack: Stack,
    setup: &LevelSetup<'_>,
    supports: impl Fn(&mut Stack),
    loads: impl Fn(&Stack, &mut [f64]),
) -> Result<LevelSolution, ContactError> {
    let t0 = Instant::now();
    let nr = stack.radii().len();
    supports(&mut stack);
    for (k, &i) in setup.tied.iter().enumerate() {
        let (up, low) = stack.interface_pair(i);
        match low {
            None => stack.fix(up, 1, 0.0),
            Some(low) => {
                if k == 0 && setup.fix_rigid {
                    stack.fix(up, 1, 0.0);
                }
                stack.tie(up, low, 1);
                if setup.welded {
                    stack.tie(up, low, 0);
                }
            }
        }
    }
    let n = stack.number();
    let (solver, mut f) = stack.factorize(n)?;
    loads(&stack, &mut f);
    let mut x0 = Mat::from_fn(n, 1, |i, _| f[i]);
    solver.solve_in_place(&mut x0);
    let time_linear = t0.elapsed();

    let t1 = Instant::now();
    let comps: &[usize] = if setup.welded { &[1, 0] } else { &[1] };
    let cols: Vec<Vec<(usize, f64)>> = comps
        .iter()
        .flat_map(|&c| setup.window.iter().map(move |&i| (c, i)))
        .map(|(c, i)| pair_vector(&stack, i, c))
        .collect();
    let (g0, flex, xb) = flexibility(&solver, &x0, &cols);
    let lcp = Lcp {
        flexibility: flex,
        gap0: g0,
        welded: setup.welded,
    };
    let sol = solve_lcp(&lcp, &setup.lcp)?;
    let mut y: Vec<f64> = (0..n).map(|i| x0[(i, 0)]).collect();
    for (k, l) in sol.force.iter().enumerate() {
        if *l != 0.0 {
            for (i, yi) in y.iter_mut().enumerate() {
                *yi += xb[(i, k)] * l;
            }
        }
    }
    let x = stack.expand(&y);
    let forces = stack.interface_forces(&x);
    let area = stack.edge_weights(|_| 1.0, &[]);
    let mut areas = vec![0.0; nr];
    for (i, a) in area {
        areas[i] = a;
    }
    let mut closed = vec![false; nr];
    for &i in setup.tied {
        closed[i] = true;
    }
    for (k, &i) in setup.window.iter().enumerate() {
        closed[i] = sol.active[k];
    }
    let gap: Vec<f64> = (0..nr)
        .map(|i| {
            let (up, low) = stack.interface_pair(i);
            x[2 * up + 1] - low.map_or(0.0, |l| x[2 * l + 1])
        })
        .collect();
    let force: Vec<f64> = forces.iter().map(|f| f[1]).collect();
    let (a, b) = setup.nut;
    let top = stack.z_lines(0).len() - 1;
    let (mut ws, mut aw) = (0.0, 0.0);
    for (i, wgt) in stack.edge_weights(|r| if r >= a && r <= b { 1.0 } else { 0.0 }, &[a, b]) {
        ws += wgt * x[2 * stack.node(0, i, top) + 1];
        aw += wgt;
    }
    Ok(LevelSolution {
        nut_deflection: ws / aw,
        radius: stack.radii().to_vec(),
        pressure: force.iter().zip(&areas).map(|(f, a)| f / a).collect(),
        force,
        gap,
        closed,
        displacement: x,
        lcp: sol.info,
        dofs: n,
        time_linear,
        time_contact: t1.elapsed(),
    })
}

/// The reduced unit pair force of component `c` at radial line `i`: +1 on the upper node,
/// −1 on the lower one (free unknowns only).
fn pair_vector(stack: &Stack, i: usize, c: usize) -> Vec<(usize, f64)> {
    let (up, low) = stack.interface_pair(i);
    let mut v = Vec::new();
    if let Dof::Free(e) = stack.dof(up, c) {
        v.push((e, 1.0));
    }
    if let Some(Dof::Free(e)) = low.map(|l| stack.dof(l, c)) {
        v.push((e, -1.0));
    }
    v
}

/// g⁰ = Bᵀx₀, F = BᵀK⁻¹B (symmetrized), and X_B = K⁻¹B, by one multi-column solve.
fn flexibility(
    solver: &Solver,
    x0: &Mat<f64>,
    cols: &[Vec<(usize, f64)>],
) -> (DVector<f64>, DMatrix<f64>, Mat<f64>) {
    let m = cols.len();
    let mut xb = Mat::<f64>::zeros(solver.size(), m);
    for (k, col) in cols.iter().enumerate() {
        for &(e, v) in col {
            xb[(e, k)] = v;
        }
    }
    solver.solve_in_place(&mut xb);
    let dot = |col: &[(usize, f64)], x: &dyn Fn(usize) -> f64| {
        col.iter().map(|&(e, v)| v * x(e)).sum::<f64>()
    };
    let g0 = DVector::from_fn(m, |k, _| dot(&cols[k], &|e| x0[(e, 0)]));
    let f = DMatrix::from_fn(m, m, |a, b| dot(&cols[a], &|e| xb[(e, b)]));
    let f = (&f + f.transpose()) * 0.5;
    (g0, f, xb)
}
