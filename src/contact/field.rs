//! The finest level's field of a two-plate solution, for output: the mesh of the plates (one
//! plate on a rigid frictionless plane for a symmetric joint, both plates otherwise), their
//! materials and the nodal displacements, in the joint's own units (lengths as the joint's,
//! stresses as its bearing pressure or moduli). Returned by
//! [`super::two_plate::solve_field`]; written as VTU by the `two --field` command
//! ([`crate::io::vtu`]).
//!
//! Method: the solver works in units where the thinner plate, the stiffer modulus and the
//! largest bearing pressure are 1; the kept mesh is scaled back by the same factors as R_o and
//! the interface curves (coordinates × length, displacements × length·stress/modulus, moduli ×
//! modulus), so that the stresses recovered from it are in the joint's units.
//!
//! # Accuracy
//!
//! The field is the finest level's; `tests/io/vtu.rs` checks the written file against the interface
//! curves of the same solution (gap from the displacements) and the bolt force.
//!
//! # Cost
//!
//! The finest level's model (mesh, materials) and displacements are kept instead of dropped, and
//! rescaled once (linear in the nodes); nothing is solved again.
//!
//! ```
//! use boltzone::contact::two_plate::{solve_field, TwoPlateParams};
//! use boltzone::{FaceLoad, Joint, Material, OuterRadius, Plate};
//! let m = Material::new(28e6, 0.3)?;
//! let joint = Joint::new(0.1, OuterRadius::Finite(1.0), Plate::new(0.1, m)?,
//!     Plate::new(0.1, m)?, FaceLoad::uniform(0.1, 0.31, 1e3)?)?;
//! let params = TwoPlateParams { tolerance: 1e-2, ..Default::default() };
//! let (s, field) = solve_field(&joint, &params)?;
//! assert_eq!(field.u.len(), field.model.mesh.n_nodes());
//! assert_eq!(field.closed.len(), s.radius.len());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::ContactError;
use super::level::MeshedJoint;
use crate::material::Material;

/// The finest level's field in the joint's units (module docs).
#[derive(Debug, Clone)]
pub struct TwoPlateField {
    /// Mesh, materials and which plate is upper/lower (lower None: a rigid plane at z = 0).
    pub model: MeshedJoint,
    /// Nodal displacements (u, w).
    pub u: Vec<[f64; 2]>,
    /// Whether each interface node (in radial order) is closed.
    pub closed: Vec<bool>,
}

/// The field in the solver's units and the factors back to the joint's.
#[derive(Debug, Clone)]
pub(crate) struct UnitField {
    pub model: MeshedJoint,
    pub u: Vec<[f64; 2]>,
    pub closed: Vec<bool>,
    pub length: f64,
    pub displacement: f64,
    pub modulus: f64,
}

impl UnitField {
    /// The field in the joint's units.
    pub fn rescaled(self) -> Result<TwoPlateField, ContactError> {
        let Self {
            mut model,
            u,
            closed,
            length,
            displacement,
            modulus,
        } = self;
        model
            .mesh
            .transform_nodes(|p| [p[0] * length, p[1] * length]);
        model.materials = model
            .materials
            .iter()
            .map(|m| Material::new(m.youngs_modulus() * modulus, m.poisson_ratio()))
            .collect::<Result<_, _>>()?;
        Ok(TwoPlateField {
            model,
            u: u.iter()
                .map(|x| [x[0] * displacement, x[1] * displacement])
                .collect(),
            closed,
        })
    }
}
