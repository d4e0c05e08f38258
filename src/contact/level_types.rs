//! The types one mesh level of the two-plate contact problem ([`super::level`]) reads and
//! returns: the meshed joint, what the level needs besides the mesh, and the interface state
//! after the solve. They live apart from the solver so that the friction step
//! ([`super::friction_level`]) reads them without importing the solver that calls it. Public
//! paths stay `boltzone::contact::level::{MeshedJoint, LevelSetup, LevelSolution}`.
//!
//! # Accuracy
//!
//! Types only: the level that fills them is measured by `tests/contact/two_plate.rs`
//! (`equilibrium_and_complementarity_symmetric`).
//!
//! # Cost
//!
//! None of their own; the level: `cargo bench --bench contact`.

use super::friction::PointState;
use super::lcp::{LcpInfo, LcpParams};
use crate::fem::Mesh;
use crate::material::Material;
use std::time::Duration;

/// The meshed joint: a fem mesh of one plate (on a rigid plane) or two plates, and which is which.
#[derive(Debug, Clone)]
pub struct MeshedJoint {
    /// The mesh (plates stacked bottom to top).
    pub mesh: Mesh,
    /// Materials, indexed by the plates' material indices.
    pub materials: Vec<Material>,
    /// Plate index of the upper plate (its bottom face is the interface).
    pub upper: usize,
    /// Plate index of the lower plate, None for a rigid plane.
    pub lower: Option<usize>,
    /// The plates' rim beyond the mesh's outer face when that face is a cut
    /// (`f64::INFINITY`: infinite plates), None when the plates are meshed whole: the cut face
    /// then carries the exact exterior ([`crate::fem::exterior`]).
    pub exterior: Option<f64>,
}

impl MeshedJoint {
    /// Interface node of the upper plate at radial line `i` and its partner below (if any).
    pub fn pair(&self, i: usize) -> (usize, Option<usize>) {
        let low = self.lower.map(|l| self.mesh.top(l)[i]);
        (self.mesh.bottom(self.upper)[i], low)
    }
}

/// What the level needs to know besides the mesh.
#[derive(Debug, Clone)]
pub struct LevelSetup<'a> {
    /// Radial lines of tied interface points (non-empty unless supports hold the stack).
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
    /// Contact force on the upper plate at each interface node (total, axial, > 0 compression;
    /// 0 at nodes held by an edge support, whose reaction is the support's).
    pub force: Vec<f64>,
    /// Interface pressure: force / tributary area.
    pub pressure: Vec<f64>,
    /// Interface shear stress on the upper plate (radial force / tributary area; outward > 0):
    /// zero for frictionless contact, the welded or frictional model's shear otherwise.
    pub shear: Vec<f64>,
    /// Gap w_upper − w_lower (rigid plane: w_upper).
    pub gap: Vec<f64>,
    /// Whether each interface node is closed (tied or active).
    pub closed: Vec<bool>,
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
    /// Nodal displacements (u, w) of the whole mesh.
    pub u: Vec<[f64; 2]>,
    /// With friction ([`super::friction`]): the state of each interface node.
    pub friction: Option<Vec<PointState>>,
    /// The window's Schur complement for the fitted edge ([`super::edge_fit`]; frictionless
    /// or symmetric contact only, None otherwise).
    pub edge: Option<super::edge_fit::EdgeSystem>,
}
