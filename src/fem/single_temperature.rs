//! The single plate's temperature: a field mirror-symmetric about the midplane
//! ([`PlateTemperature`] by radius and depth), the stress-free temperature and the E(T), ν(T),
//! α(T) table, and what it does to a half-plate mesh (element materials at their temperature,
//! thermal forces). Apart from the solve ([`super::single_thermal`]) so that the single plate's
//! levels ([`super::single`]) can take it without importing the solve that drives them.
//!
//! ```
//! use boltzone::fem::single_temperature::SingleTemperature;
//! use boltzone::fem::plate_temperature::PlateTemperature;
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! let load = FaceLoad::uniform(0.1, 0.31, 1.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Infinite, 0.1, Material::new(3e7, 0.3)?, load)?;
//! let t = SingleTemperature::constant(&plate, 70.0, PlateTemperature::Uniform(170.0), 13e-6)?;
//! assert_eq!(t.reference, 70.0);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Accuracy
//!
//! `tests/fem/single_thermal.rs` (uniform ΔT: displacements αΔT(r, z), zero stress; linear
//! through each half: the held plate's exact stress).
//!
//! # Cost
//!
//! One pass over the nodes and elements.

use super::error::FemError;
pub use super::plate_temperature::PlateTemperature;
use super::thermal::{Thermal, ThermalMaterial};
use super::{Loads, Mesh};
use crate::error::InputError;
use crate::joint::SinglePlate;
use crate::material::Material;

/// The single plate's temperature (mirror-symmetric about the midplane) and thermal table.
#[derive(Debug, Clone, PartialEq)]
pub struct SingleTemperature {
    /// Stress-free temperature T_ref.
    pub reference: f64,
    /// Temperature by radius and depth s below the midplane.
    pub plate: PlateTemperature,
    /// E(T), ν(T), α(T) (used in place of the plate's material).
    pub material: ThermalMaterial,
}

impl SingleTemperature {
    /// The plate's own E and ν with a constant expansion coefficient `alpha`.
    pub fn constant(
        plate: &SinglePlate,
        reference: f64,
        temperature: PlateTemperature,
        alpha: f64,
    ) -> Result<Self, InputError> {
        crate::error::finite("reference temperature", reference)?;
        Ok(Self {
            reference,
            plate: temperature,
            material: ThermalMaterial::constant(plate.material(), alpha)?,
        })
    }

    /// The nodal temperatures of the half plate `mesh` (0 ≤ z ≤ `d`) as a [`Thermal`] field.
    pub fn field(&self, mesh: &Mesh, d: f64) -> Result<Thermal, FemError> {
        let t = mesh
            .nodes()
            .iter()
            .map(|x| self.plate.at(x[0], x[1], d))
            .collect();
        Thermal::new(mesh, vec![self.material.clone()], t, self.reference)
    }

    /// Gives each element of the half plate `mesh` its material at its temperature, adds the
    /// thermal forces to `loads`, and returns the element materials and the field (faces
    /// loaded by a pressure: a rigid-nut displacement has no stress scale, refused by the
    /// caller).
    pub(crate) fn apply(
        &self,
        mesh: &mut Mesh,
        d: f64,
        loads: &mut Loads,
    ) -> Result<(Vec<Material>, Thermal), FemError> {
        let th = self.field(mesh, d)?;
        let materials = th.apply(mesh)?;
        th.add_loads(mesh, &materials, loads)?;
        Ok((materials, th))
    }
}
