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
//! The mesh, elements, supports, assembly and factorization are those of [`crate::fem`]; ties
//! between plates go through [`super::tie`].
//!
//! # Accuracy
//!
//! Equilibrium (the contact forces carry the load to 1e-10) and complementarity (p ≥ 0, g ≥ 0, p·g
//! = 0) on every level: `tests/contact/two_plate.rs` (`equilibrium_and_complementarity_symmetric`);
//! the flexibility from many right-hand sides equals single solves: `tests/fem/system.rs`
//! (`flexibility_by_many_right_hand_sides_is_symmetric_and_matches_single_solves`).
//!
//! # Cost
//!
//! One sparse factorization per level and one solve with 1 + (window size) right-hand sides; `cargo
//! bench --bench contact` and example 12 (the report's own mesh).
//!
//! ```
//! use boltzone::contact::level::{solve_level, LevelSetup, MeshedJoint};
//! use boltzone::contact::LcpParams;
//! use boltzone::fem::{ElementKind, Loads, Mesh, PlateSpec, Spacing, Supports};
//! use boltzone::{FaceLoad, Material};
//! // One plate on a rigid plane, pressed on 0.1 ≤ r ≤ 0.2; the node at r = 0.15 holds it down.
//! let r = Spacing::uniform(0.1, 1.0, 18)?;
//! let z = Spacing::uniform(0.0, 0.1, 2)?;
//! let mesh = Mesh::structured(ElementKind::Q9, &r, &[PlateSpec { z, material: 0 }])?;
//! let load = FaceLoad::uniform(0.1, 0.2, 1.0)?;
//! let mut loads = Loads::new(mesh.n_nodes());
//! loads.add_face_pressure(&mesh, &mesh.top(0), 1.0, &load)?;
//! let model = MeshedJoint { mesh, materials: vec![Material::unit(0.3)?], upper: 0, lower: None,
//!                          exterior: None };
//! let window: Vec<usize> = (0..37).filter(|&i| i != 2).collect();
//! let setup = LevelSetup { tied: &[2], window: &window, welded: false, fix_rigid: true,
//!                          lcp: LcpParams::default(), nut: (0.1, 0.2) };
//! let s = solve_level(&model, &setup, &Supports::new(model.mesh.n_nodes()), &loads)?;
//! let total: f64 = s.force.iter().sum();
//! assert!((total - load.total_force()).abs() < 1e-10 * total);
//! assert!(s.closed[0] && !s.closed[36]); // in contact at the hole, open at the rim
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::edge_fit::EdgeSystem;
use super::error::ContactError;
use super::friction_level;
use super::lcp::{solve_lcp, Lcp};
pub use super::level_types::{LevelSetup, LevelSolution, MeshedJoint};
use super::tie::Ties;
use crate::fem::exterior::add_exterior;
use crate::fem::{
    assemble, node_dissection, Component, DofMap, Factorization, Loads, Mesh, Pattern, SolveParams,
    Supports,
};
use crate::load::FaceLoad;
use faer::Mat;
use nalgebra::{DMatrix, DVector};
use std::time::Instant;

/// Bytes of right-hand sides solved at once for the flexibility matrix (256 MiB).
const FLEX_BLOCK_BYTES: usize = 256 << 20;

/// Ties, numbers, assembles, factors and solves the level (module docs). `supports` adds the
/// edge supports and prescribed nut displacements; `loads` are the external nodal forces.
pub fn solve_level(
    model: &MeshedJoint,
    setup: &LevelSetup<'_>,
    supports: &Supports,
    loads: &Loads,
) -> Result<LevelSolution, ContactError> {
    solve_level_mu(model, setup, None, supports, loads)
}

/// [`solve_level`] with Coulomb friction of coefficient `mu` when given (two plates, not
/// welded): every window point gets a tangential unknown, and so does the first tied point
/// when it is held by supports (module `friction_level`).
pub(crate) fn solve_level_mu(
    model: &MeshedJoint,
    setup: &LevelSetup<'_>,
    mu: Option<f64>,
    supports: &Supports,
    loads: &Loads,
) -> Result<LevelSolution, ContactError> {
    let t0 = Instant::now();
    let mesh = &model.mesh;
    let nr = mesh.radial_nodes().len();
    let mut sup = supports.clone();
    let mut pairs = Vec::new();
    for (k, &i) in setup.tied.iter().enumerate() {
        match model.pair(i) {
            (up, None) => sup.roller_z(up),
            (up, Some(low)) => {
                if k == 0 && setup.fix_rigid {
                    sup.roller_z(up);
                    sup.roller_z(low);
                } else {
                    pairs.push((up, low, Component::Z));
                }
                if setup.welded {
                    pairs.push((up, low, Component::R));
                }
            }
        }
    }
    // Equations numbered in the nested dissection of the structured mesh (fem's), so that the
    // factorization needs no permutation; tied unknowns keep the place of their first equation
    // (Ties numbers them so). (AMD's symbolic analysis costs more than the extra fill ND
    // leaves: measured 60 vs 115 ms on a 3045-node Q9 mesh.)
    let dofs = DofMap::in_node_order(&sup, &node_dissection(mesh))?;
    let eq_pairs: Vec<(usize, usize)> = pairs
        .iter()
        .filter_map(|&(a, b, c)| Some((dofs.equation(a, c)?, dofs.equation(b, c)?)))
        .collect();
    let ties = Ties::new(dofs.n_equations(), &eq_pairs);
    let pattern = Pattern::new(mesh, &dofs);
    let mut stiff = assemble(mesh, &model.materials, &dofs, &pattern)?;
    if let Some(rim) = model.exterior {
        for p in std::iter::once(model.upper).chain(model.lower) {
            add_exterior(&mut stiff, &pattern, mesh, &model.materials, &dofs, p, rim)?;
        }
    }
    // (K itself when nothing is tied: no copy)
    let tied = match ties.is_trivial() {
        true => None,
        false => Some(ties.matrix(&stiff.matrix)?),
    };
    let k = tied.as_ref().unwrap_or(&stiff.matrix);
    let solver = Factorization::natural(k, &SolveParams::default())?;
    let mut f = dofs.gather(loads.forces());
    for (fi, pi) in f.iter_mut().zip(&stiff.prescribed_load) {
        *fi += pi;
    }
    let x0 = solver.solve(&ties.restrict(&f));
    let time_linear = t0.elapsed();

    let t1 = Instant::now();
    let comps: &[Component] = if setup.welded || mu.is_some() {
        &[Component::Z, Component::R]
    } else {
        &[Component::Z]
    };
    let cols: Vec<Vec<(usize, f64)>> = comps
        .iter()
        .flat_map(|&c| setup.window.iter().map(move |&i| (c, i)))
        .chain(friction_level::held(setup, mu).map(|i| (Component::R, i)))
        .map(|(c, i)| pair_vector(model, &dofs, &ties, i, c))
        .collect();
    let dot = |col: &[(usize, f64)], x: &dyn Fn(usize) -> f64| {
        col.iter().map(|&(e, v)| v * x(e)).sum::<f64>()
    };
    let m = cols.len();
    let g0 = DVector::from_fn(m, |k, _| dot(&cols[k], &|e| x0[e]));
    // The flexibility's columns are solved in blocks of at most FLEX_BLOCK_BYTES of right-hand
    // sides (and as many of solutions): a fine mesh with a wide candidate window (320k unknowns
    // × 800 columns held 2.3 GB) stays bounded; below the bound it is one block, as before.
    let width = (FLEX_BLOCK_BYTES / (8 * ties.n().max(1))).clamp(1, m.max(1));
    let mut flex = DMatrix::<f64>::zeros(m, m);
    let mut whole = None; // the solutions, kept when one block holds them all
    for start in (0..m).step_by(width) {
        let block = &cols[start..(start + width).min(m)];
        let mut b = Mat::<f64>::zeros(ties.n(), block.len());
        for (k, col) in block.iter().enumerate() {
            for &(e, v) in col {
                b[(e, k)] += v;
            }
        }
        let xb = solver.solve_many_in_place(b);
        for (k, _) in block.iter().enumerate() {
            for a in 0..m {
                flex[(a, start + k)] = dot(&cols[a], &|e| xb[(e, k)]);
            }
        }
        if width >= m {
            whole = Some(xb);
        }
    }
    let flexibility = (&flex + flex.transpose()) * 0.5;
    let mut edge = None;
    let (sol, states) = match mu {
        None => {
            let lcp = Lcp {
                flexibility,
                gap0: g0,
                welded: setup.welded,
            };
            let sol = solve_lcp(&lcp, &setup.lcp)?;
            if !setup.welded {
                edge = Some(EdgeSystem {
                    window: setup.window.to_vec(),
                    flexibility: lcp.flexibility,
                    gap0: lcp.gap0,
                });
            }
            (sol, None)
        }
        Some(mu) => {
            let (s, st) = friction_level::solve(model, setup, mu, flexibility, g0, loads)?;
            (s, Some(st))
        }
    };
    let mut y = x0;
    match &whole {
        Some(xb) => {
            for (k, l) in sol.force.iter().enumerate() {
                if *l != 0.0 {
                    for (i, yi) in y.iter_mut().enumerate() {
                        *yi += xb[(i, k)] * l;
                    }
                }
            }
        }
        None => {
            // blocks: one more solve, of the contact forces' load, instead of m kept solutions
            let mut b = Mat::<f64>::zeros(ties.n(), 1);
            for (col, l) in cols.iter().zip(sol.force.iter()) {
                for &(e, v) in col {
                    b[(e, 0)] += v * l;
                }
            }
            let dy = solver.solve_many_in_place(b);
            for (i, yi) in y.iter_mut().enumerate() {
                *yi += dy[(i, 0)];
            }
        }
    }
    let u = dofs.expand(&ties.prolong(&y));
    let line = mesh.bottom(model.upper);
    let mut forces = line_forces(model, &u, &line)?;
    // Contact = K u − f: the part of K u the external forces (thermal ones) do not balance.
    for (f, &n) in forces.iter_mut().zip(&line) {
        f[0] -= loads.forces()[n][0];
        f[1] -= loads.forces()[n][1];
    }
    // A component held by a support (edge, axis) transmits that support's reaction, not contact.
    for (i, f) in forces.iter_mut().enumerate() {
        let (up, low) = model.pair(i);
        for (c, fc) in f.iter_mut().enumerate() {
            if std::iter::once(up)
                .chain(low)
                .any(|n| supports.get(n).fixed[c].is_some())
            {
                *fc = 0.0;
            }
        }
    }
    let force: Vec<f64> = forces.iter().map(|f| f[1]).collect();
    let areas = face_weights(
        mesh,
        &line,
        -1.0,
        &FaceLoad::uniform(mesh.radial_nodes()[0], mesh.radial_nodes()[nr - 1], 1.0)?,
    )?;
    let mut closed = vec![false; nr];
    for &i in setup.tied {
        closed[i] = true;
    }
    for (k, &i) in setup.window.iter().enumerate() {
        closed[i] = sol.active[k];
    }
    let gap: Vec<f64> = (0..nr)
        .map(|i| {
            let (up, low) = model.pair(i);
            u[up][1] - low.map_or(0.0, |l| u[l][1])
        })
        .collect();
    let (a, bb) = setup.nut;
    let top = mesh.top(model.upper);
    let w = face_weights(mesh, &top, 1.0, &FaceLoad::uniform(a, bb, 1.0)?)?;
    let nut_deflection =
        top.iter().zip(&w).map(|(&n, wi)| u[n][1] * wi).sum::<f64>() / w.iter().sum::<f64>();
    Ok(LevelSolution {
        radius: mesh.radial_nodes().to_vec(),
        pressure: per_area(&force, &areas),
        shear: per_area(&forces.iter().map(|f| f[0]).collect::<Vec<_>>(), &areas),
        force,
        gap,
        closed,
        nut_deflection,
        lcp: sol.info,
        dofs: ties.n(),
        time_linear,
        time_contact: t1.elapsed(),
        u,
        friction: states,
        edge,
    })
}

/// The unit pair force of component `c` at radial line `i` in tied unknowns: +1 on the upper
/// node, −1 on the lower one (free equations only).
fn pair_vector(
    model: &MeshedJoint,
    dofs: &DofMap,
    ties: &Ties,
    i: usize,
    c: Component,
) -> Vec<(usize, f64)> {
    let (up, low) = model.pair(i);
    let mut v = Vec::new();
    if let Some(e) = dofs.equation(up, c) {
        v.push((ties.of(e), 1.0));
    }
    if let Some(e) = low.and_then(|l| dofs.equation(l, c)) {
        v.push((ties.of(e), -1.0));
    }
    v
}

/// Nodal forces over their tributary areas. A node with no area (the axis node of a solid plate:
/// with quadratic elements ∫N₀ 2πr dr = 0 there) takes its neighbour's value: force / 0 put
/// 2e9 psi at the axis of `two --a 0 … --curve` for a mean pressure of 1.
fn per_area(force: &[f64], areas: &[f64]) -> Vec<f64> {
    let scale = areas.iter().fold(0.0f64, |m, a| m.max(a.abs()));
    let mut v: Vec<f64> = force.iter().zip(areas).map(|(f, a)| f / a).collect();
    for i in 0..v.len() {
        if areas[i].abs() <= 1e-12 * scale {
            let next = if i + 1 < v.len() {
                i + 1
            } else {
                i.saturating_sub(1)
            };
            v[i] = if areas[next].abs() > 1e-12 * scale {
                v[next]
            } else {
                0.0
            };
        }
    }
    v
}

/// ∫ q N_i 2πr dr along a face `line` (as positive weights), from the fem consistent loads.
fn face_weights(
    mesh: &Mesh,
    line: &[usize],
    outward_z: f64,
    q: &FaceLoad,
) -> Result<Vec<f64>, ContactError> {
    let mut l = Loads::new(mesh.n_nodes());
    l.add_face_pressure(mesh, line, outward_z, q)?;
    Ok(line
        .iter()
        .map(|&n| -outward_z * l.forces()[n][1])
        .collect())
}

/// Internal forces K u (radial, axial) of the upper plate at its interface nodes `line` (only
/// the elements touching the line are visited): the contact forces on the upper plate.
fn line_forces(
    model: &MeshedJoint,
    u: &[[f64; 2]],
    line: &[usize],
) -> Result<Vec<[f64; 2]>, ContactError> {
    let mesh = &model.mesh;
    let mut pos = vec![usize::MAX; mesh.n_nodes()];
    for (k, &n) in line.iter().enumerate() {
        pos[n] = k;
    }
    let mut f = vec![[0.0; 2]; line.len()];
    for e in 0..mesh.n_elements() {
        let nodes = mesh.element_nodes(e);
        if nodes.iter().all(|&n| pos[n] == usize::MAX) {
            continue;
        }
        let mat = model.materials[mesh.element_material(e)];
        let k = mesh.kind().stiffness(&mesh.element_coords(e), &mat);
        let ue: Vec<f64> = nodes.iter().flat_map(|&n| u[n]).collect();
        let nd = ue.len();
        for (a, &n) in nodes.iter().enumerate() {
            if pos[n] != usize::MAX {
                for (c, fc) in f[pos[n]].iter_mut().enumerate() {
                    let row = 2 * a + c;
                    *fc += (0..nd).map(|j| k[row * nd + j] * ue[j]).sum::<f64>();
                }
            }
        }
    }
    Ok(f)
}
