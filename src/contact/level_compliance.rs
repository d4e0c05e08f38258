//! The member compliance of one solved mesh level of the two-plate model (report Chapter II.B):
//! δ_P = ∫ p (w_head − w_nut) dA / F² by work for a prescribed face pressure — the consistent
//! load vector of both bearing faces (the head's and the nut's own, [`Joint::nut_load`]) dotted with the level's displacements, doubled for the
//! symmetric one-plate model (the mirror face does the same work) — or, for a rigid head, the
//! rigid displacement over the reaction under it, 2δ/F. The study over the levels and its
//! error estimate are module [`super::compliance`]'s.
//!
//! # Accuracy
//!
//! Exact for the level's discrete solution (one dot product); the levels' convergence is
//! `tests/joint/compliance.rs`'s.
//!
//! # Cost
//!
//! One load vector (or one product K·u for the rigid head) per level.

use super::error::ContactError;
use super::level::{LevelSolution, MeshedJoint};
use super::params::{Loading, TwoPlateParams};
use crate::fem::{internal_forces, Loads};
use crate::joint::Joint;

/// δ_P of one solved level (module docs), in the level's units.
pub(super) fn level_compliance(
    joint: &Joint,
    params: &TwoPlateParams,
    model: &MeshedJoint,
    sol: &LevelSolution,
) -> Result<f64, ContactError> {
    let mesh = &model.mesh;
    let top = mesh.top(model.upper);
    let bottom = model.lower.map(|l| mesh.bottom(l));
    match params.loading {
        Loading::Pressure => {
            let mut loads = Loads::new(mesh.n_nodes());
            loads.add_face_pressure(mesh, &top, 1.0, joint.load())?;
            if let Some(b) = &bottom {
                loads.add_face_pressure(mesh, b, -1.0, joint.nut_load())?;
            }
            let work: f64 = loads
                .forces()
                .iter()
                .zip(&sol.u)
                .map(|(f, u)| f[0] * u[0] + f[1] * u[1])
                .sum();
            // the symmetric model holds one plate: the mirror face does the same work
            let mirror = if bottom.is_some() { 1.0 } else { 2.0 };
            let f = joint.load().total_force();
            Ok(mirror * work / (f * f))
        }
        Loading::NutDisplacement(delta) => {
            let ku = internal_forces(mesh, &model.materials, &sol.u)?;
            let b = joint.load().outer();
            let force: f64 = top
                .iter()
                .filter(|&&n| mesh.nodes()[n][0] <= b * (1.0 + 1e-12))
                .map(|&n| -ku[n][1])
                .sum();
            Ok(2.0 * delta / force)
        }
    }
}
