//! External nodal forces (report eqs. A.14–A.15): consistent forces of face pressures,
//! f_i = ∫ N_i(s) t(s) 2πr ds over the loaded edges, and point (ring) forces.
//!
//! Face loads come from [`FaceLoad`] (piecewise linear on knots, zero outside [A, B], jumps at A
//! and B allowed). Each element edge is split at the load's knots and integrated piece by piece
//! with 3-point Gauss–Legendre, exact for N_i (degree ≤ 2) × p (degree 1) × r (degree 1) even when
//! the mesh lines are not snapped to the knots; snapping (see [`super::Spacing::graded`]) is
//! still better, because the solution's kink then falls on an element edge.
//!
//! Sign: a pressure p > 0 pushes on the face: traction t = −p n with n the outward normal. On a
//! top face (n = +z) the force is downward, on a bottom face upward. Forces are whole-ring
//! forces, so the sum of a face load's nodal forces is ∓F = ∓2π∫p r dr.
//!
//! # Accuracy
//!
//! Exact for piecewise-linear loads (3-point Gauss on each piece): the doc example's total force to
//! 1e-13, the traction patch test of `tests/fem/elements.rs`, and the midplane traction of
//! `tests/fem/single.rs` (`midplane_traction_carries_the_applied_force`).
//!
//! # Cost
//!
//! Linear in the loaded edges.
//!
//! ```
//! use boltzone::fem::*;
//! use boltzone::FaceLoad;
//! let r = Spacing::uniform(0.1, 1.0, 7)?;
//! let z = Spacing::uniform(0.0, 0.1, 1)?;
//! let mesh = Mesh::structured(ElementKind::Q9, &r, &[PlateSpec { z, material: 0 }])?;
//! let p = FaceLoad::uniform(0.1, 0.31, 2.0)?;
//! let mut loads = Loads::new(mesh.n_nodes());
//! loads.add_face_pressure(&mesh, &mesh.top(0), 1.0, &p)?;
//! let fz: f64 = loads.forces().iter().map(|f| f[1]).sum();
//! assert!((fz + p.total_force()).abs() < 1e-13 * p.total_force());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::element::GAUSS3;
use super::mesh::Mesh;
use crate::error::InputError;
use crate::load::FaceLoad;
use std::f64::consts::PI;

/// Nodal forces (f_r, f_z) of every node, global frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Loads {
    forces: Vec<[f64; 2]>,
}

/// 1D Lagrange shape functions of an edge with `n` = 2 or 3 equally spaced nodes, at s ∈ [0, 1].
pub(crate) fn edge_shape(n: usize, s: f64) -> [f64; 3] {
    if n == 2 {
        [1.0 - s, s, 0.0]
    } else {
        [
            2.0 * (s - 0.5) * (s - 1.0),
            -4.0 * s * (s - 1.0),
            2.0 * s * (s - 0.5),
        ]
    }
}

/// The element edges along a line of nodes (pairs, or triples for quadratic elements).
pub(crate) fn edges(line: &[usize], order: usize) -> impl Iterator<Item = &[usize]> {
    line.windows(order + 1).step_by(order)
}

/// ∫ N_i(t) g(t) 2πr(t) dt over each edge of `line` (coordinate t = r if `radial`, else z),
/// splitting at `breaks`; returns (node, value) contributions.
pub(crate) fn edge_integrals(
    mesh: &Mesh,
    line: &[usize],
    radial: bool,
    breaks: &[f64],
    g: &dyn Fn(f64) -> f64,
) -> Vec<(usize, f64)> {
    let x = mesh.nodes();
    let c = if radial { 0 } else { 1 };
    let mut out = Vec::new();
    for e in edges(line, mesh.kind().order()) {
        let (ta, tb) = (x[e[0]][c], x[e[e.len() - 1]][c]);
        let mut cuts = vec![ta];
        cuts.extend(breaks.iter().copied().filter(|&k| k > ta && k < tb));
        cuts.push(tb);
        let mut f = [0.0; 3];
        for w in cuts.windows(2) {
            let (a, b) = (w[0], w[1]);
            for &(xi, wt) in &GAUSS3 {
                let t = 0.5 * (a + b) + 0.5 * (b - a) * xi;
                // evaluate g inside the piece (avoids picking the wrong side of a jump)
                let r = if radial { t } else { x[e[0]][0] };
                let val = g(t) * 2.0 * PI * r * 0.5 * (b - a) * wt;
                let n = edge_shape(e.len(), (t - ta) / (tb - ta));
                for (fi, ni) in f.iter_mut().zip(n) {
                    *fi += ni * val;
                }
            }
        }
        for (k, &node) in e.iter().enumerate() {
            out.push((node, f[k]));
        }
    }
    out
}

impl Loads {
    /// No forces on `n_nodes` nodes.
    pub fn new(n_nodes: usize) -> Self {
        Self {
            forces: vec![[0.0; 2]; n_nodes],
        }
    }

    /// Adds a ring force (f_r, f_z) at `node`.
    pub fn add_point(&mut self, node: usize, f: [f64; 2]) {
        self.forces[node][0] += f[0];
        self.forces[node][1] += f[1];
    }

    /// Pressure `load` on a horizontal face whose nodes `line` are sorted by r;
    /// `outward_z` = +1 for a top face, −1 for a bottom face.
    pub fn add_face_pressure(
        &mut self,
        mesh: &Mesh,
        line: &[usize],
        outward_z: f64,
        load: &FaceLoad,
    ) -> Result<(), InputError> {
        check_normal(outward_z)?;
        let p = |r: f64| load.pressure_at(r);
        for (n, f) in edge_integrals(mesh, line, true, load.knots(), &p) {
            self.forces[n][1] -= outward_z * f;
        }
        Ok(())
    }

    /// Uniform pressure `p` on a vertical face (nodes `line` sorted by z, e.g. the hole or the
    /// rim); `outward_r` = −1 on a hole surface, +1 on an outer rim.
    pub fn add_side_pressure(
        &mut self,
        mesh: &Mesh,
        line: &[usize],
        outward_r: f64,
        p: f64,
    ) -> Result<(), InputError> {
        check_normal(outward_r)?;
        for (n, f) in edge_integrals(mesh, line, false, &[], &|_| p) {
            self.forces[n][0] -= outward_r * f;
        }
        Ok(())
    }

    /// The nodal forces, global frame.
    pub fn forces(&self) -> &[[f64; 2]] {
        &self.forces
    }
}

fn check_normal(s: f64) -> Result<(), InputError> {
    if s == 1.0 || s == -1.0 {
        Ok(())
    } else {
        Err(InputError::Parameter {
            field: "outward normal sign",
            value: s,
            reason: "must be +1 or -1",
        })
    }
}
