//! Results from a displacement solution: stresses (at Gauss points, element centres as the 1970
//! program printed them, and nodes by averaging), nodal forces K u, reactions, and the traction
//! along a supported line.
//!
//! Reactions: R = K u − f (report eq. A.17's Q_b), in the global (r, z) frame, whole-ring forces;
//! at a free node R vanishes to round-off. The support exerts R on the body.
//!
//! Line traction: along a line of nodes (a symmetry plane or an interface), the nodal forces R_i
//! are the consistent forces of a traction t(r): R_i = ∫ N_i t 2πr dr. Solving the line's
//! "mass" system M t = R with M_ij = ∫ N_i N_j 2πr dr recovers the nodal traction values, which
//! converge faster than the nodal-averaged σ_z (a variationally consistent flux). On a plane with
//! outward normal −z (the midplane under the upper half of a plate) σ_z = −t_z.
//!
//! # Accuracy
//!
//! Uniform stress recovered to round-off in the patch tests of `tests/fem/elements.rs`; exact
//! reactions under a flat punch in `tests/fem/system.rs`; the line traction carries the applied
//! force in `tests/fem/single.rs` (`midplane_traction_carries_the_applied_force`).
//!
//! # Cost
//!
//! Linear in the elements (the line traction: one banded solve per line).
//!
//! ```
//! use boltzone::fem::*;
//! use boltzone::{FaceLoad, Material};
//! let r = Spacing::uniform(0.0, 1.0, 4)?;
//! let z = Spacing::uniform(0.0, 0.5, 2)?;
//! let mesh = Mesh::structured(ElementKind::Q9, &r, &[PlateSpec { z, material: 0 }])?;
//! let mut s = Supports::new(mesh.n_nodes());
//! for n in mesh.bottom(0) { s.roller_z(n); }
//! for n in mesh.inner(0) { s.roller_r(n); } // the axis
//! let mut loads = Loads::new(mesh.n_nodes());
//! loads.add_face_pressure(&mesh, &mesh.top(0), 1.0, &FaceLoad::uniform(0.0, 1.0, 3.0)?)?;
//! let mat = [Material::unit(0.3)?];
//! let dofs = DofMap::new(&s);
//! let k = assemble(&mesh, &mat, &dofs, &Pattern::new(&mesh, &dofs))?;
//! let x = Factorization::new(&k.matrix, &SolveParams::default())?.solve(&dofs.gather(loads.forces()));
//! let u = dofs.expand(&x);
//! let reac = reactions(&mesh, &mat, &u, &loads)?;
//! let line = mesh.bottom(0);
//! let rz: Vec<f64> = line.iter().map(|&n| reac[n][1]).collect();
//! let t = line_traction(&mesh, &line, &rz)?;
//! assert!(t.iter().all(|tz| (tz - 3.0).abs() < 1e-10)); // σ_z = −t_z = −3 everywhere
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::element::{ElementPoint, Stress};
use super::error::FemError;
use super::loads::{edge_integrals, edges, Loads};
use super::mesh::Mesh;
use super::solve::{Factorization, SolveParams};
use crate::material::Material;
use faer::sparse::{SparseColMat, Triplet};

pub(crate) fn material<'a>(
    mesh: &Mesh,
    materials: &'a [Material],
    e: usize,
) -> Result<&'a Material, FemError> {
    let mi = mesh.element_material(e);
    materials.get(mi).ok_or(FemError::MissingMaterial {
        element: e,
        material: mi,
        available: materials.len(),
    })
}

pub(crate) fn element_u(mesh: &Mesh, u: &[[f64; 2]], e: usize) -> Vec<f64> {
    mesh.element_nodes(e).iter().flat_map(|&n| u[n]).collect()
}

/// K u as nodal forces in the global frame.
pub fn internal_forces(
    mesh: &Mesh,
    materials: &[Material],
    u: &[[f64; 2]],
) -> Result<Vec<[f64; 2]>, FemError> {
    let mut f = vec![[0.0; 2]; mesh.n_nodes()];
    for e in 0..mesh.n_elements() {
        let k = mesh
            .kind()
            .stiffness(&mesh.element_coords(e), material(mesh, materials, e)?);
        let ue = element_u(mesh, u, e);
        let nd = ue.len();
        for (a, &n) in mesh.element_nodes(e).iter().enumerate() {
            for (c, fc) in f[n].iter_mut().enumerate() {
                let row = 2 * a + c;
                *fc += (0..nd).map(|j| k[row * nd + j] * ue[j]).sum::<f64>();
            }
        }
    }
    Ok(f)
}

/// Reactions R = K u − f at every node (global frame); nonzero only where supported.
pub fn reactions(
    mesh: &Mesh,
    materials: &[Material],
    u: &[[f64; 2]],
    loads: &Loads,
) -> Result<Vec<[f64; 2]>, FemError> {
    let mut r = internal_forces(mesh, materials, u)?;
    for (ri, fi) in r.iter_mut().zip(loads.forces()) {
        ri[0] -= fi[0];
        ri[1] -= fi[1];
    }
    Ok(r)
}

/// Displacements and stresses at every element's quadrature points, element by element.
pub fn gauss_stresses(
    mesh: &Mesh,
    materials: &[Material],
    u: &[[f64; 2]],
) -> Result<Vec<ElementPoint>, FemError> {
    let mut out = Vec::new();
    for e in 0..mesh.n_elements() {
        let m = material(mesh, materials, e)?;
        out.extend(mesh.kind().quadrature_points(
            &mesh.element_coords(e),
            m,
            &element_u(mesh, u, e),
        ));
    }
    Ok(out)
}

/// Stress at each element's centre (one point per element; the report's printed output).
pub fn centre_stresses(
    mesh: &Mesh,
    materials: &[Material],
    u: &[[f64; 2]],
) -> Result<Vec<ElementPoint>, FemError> {
    (0..mesh.n_elements())
        .map(|e| {
            let m = material(mesh, materials, e)?;
            Ok(mesh
                .kind()
                .centre_stress(&mesh.element_coords(e), m, &element_u(mesh, u, e)))
        })
        .collect()
}

/// Nodal stresses: the mean over the elements sharing a node of each element's stress there.
/// (Across a material interface this averages two different stress states: use per-plate
/// meshes' own values there.)
pub fn nodal_stresses(
    mesh: &Mesh,
    materials: &[Material],
    u: &[[f64; 2]],
) -> Result<Vec<Stress>, FemError> {
    nodal_mean(mesh, |e| {
        let m = material(mesh, materials, e)?;
        Ok(mesh
            .kind()
            .nodal_stresses(&mesh.element_coords(e), m, &element_u(mesh, u, e)))
    })
}

/// The mean over the elements sharing each node of `at_nodes(e)`, element e's stresses at its
/// nodes (in its node order): the averaging of [`nodal_stresses`], for any recovery.
pub fn nodal_mean(
    mesh: &Mesh,
    at_nodes: impl Fn(usize) -> Result<Vec<Stress>, FemError>,
) -> Result<Vec<Stress>, FemError> {
    let mut acc = vec![([0.0; 4], 0usize); mesh.n_nodes()];
    for e in 0..mesh.n_elements() {
        for (&n, se) in mesh.element_nodes(e).iter().zip(at_nodes(e)?) {
            for (a, b) in acc[n].0.iter_mut().zip(se.to_array()) {
                *a += b;
            }
            acc[n].1 += 1;
        }
    }
    Ok(acc
        .into_iter()
        .map(|(s, c)| {
            let c = c.max(1) as f64;
            Stress {
                r: s[0] / c,
                z: s[1] / c,
                theta: s[2] / c,
                rz: s[3] / c,
            }
        })
        .collect())
}

/// Nodal traction values t_i along a horizontal `line` (sorted by r) whose consistent nodal
/// forces are `forces` (one per line node): solves M t = forces, M_ij = ∫ N_i N_j 2πr dr.
pub fn line_traction(mesh: &Mesh, line: &[usize], forces: &[f64]) -> Result<Vec<f64>, FemError> {
    if forces.len() != line.len() {
        return Err(FemError::Input(crate::error::InputError::Parameter {
            field: "number of line forces",
            value: forces.len() as f64,
            reason: "must equal the number of line nodes",
        }));
    }
    let pos: std::collections::HashMap<usize, usize> =
        line.iter().enumerate().map(|(i, &n)| (n, i)).collect();
    let mut trip = Vec::new();
    let order = mesh.kind().order();
    for e in edges(line, order) {
        // M_ij = ∫ N_i (N_j 2πr) dr: integrate each N_j with the edge machinery
        for (j, &nj) in e.iter().enumerate() {
            let (x0, x1) = (mesh.nodes()[e[0]][0], mesh.nodes()[e[e.len() - 1]][0]);
            let nfun = move |r: f64| {
                let s = (r - x0) / (x1 - x0);
                match (e.len(), j) {
                    (2, 0) => 1.0 - s,
                    (2, _) => s,
                    (_, 0) => 2.0 * (s - 0.5) * (s - 1.0),
                    (_, 1) => -4.0 * s * (s - 1.0),
                    _ => 2.0 * s * (s - 0.5),
                }
            };
            for (ni, v) in edge_integrals_single(mesh, e, &nfun) {
                let (a, b) = (pos[&ni], pos[&nj]);
                if a >= b {
                    trip.push(Triplet::new(a, b, v));
                }
            }
        }
    }
    let n = line.len();
    let m = SparseColMat::try_new_from_triplets(n, n, &trip)
        .map_err(|e| FemError::Solver(format!("{e:?}")))?;
    Ok(Factorization::new(&m, &SolveParams::default())?.solve(forces))
}

/// ∫ N_i g 2πr dr over one edge.
fn edge_integrals_single(mesh: &Mesh, e: &[usize], g: &dyn Fn(f64) -> f64) -> Vec<(usize, f64)> {
    edge_integrals(mesh, e, true, &[], g)
}
