//! The temperatures of a joint's two plates ([`JointTemperature`]: uniform, linear through the
//! thickness, or a field T(r, s) on a grid, with each plate's E(T), ν(T), α(T) table), and their
//! scaling into the contact solver's units. The solver with temperatures is
//! [`super::thermal`]; these types live apart from it so that the mesh levels
//! ([`super::refine`], [`super::two_plate`]) read them without importing the solver that calls
//! them. A plate's own temperature ([`PlateTemperature`], [`TemperatureGrid`]) lives in
//! [`crate::fem::plate_temperature`], shared with the single plate; public paths stay
//! `boltzone::contact::thermal::{JointTemperature, PlateTemperature, TemperatureGrid}`.
//!
//! # Accuracy
//!
//! `tests/contact/thermal.rs`: a uniform temperature leaves the frictionless joint unchanged
//! (`uniform_temperatures_leave_a_frictionless_joint_unchanged`), a conduction field on a grid
//! gives the joint of the linear temperatures it reproduces
//! (`a_conduction_field_equals_the_linear_description_it_reproduces`).
//!
//! # Cost
//!
//! One pass over the mesh nodes per level; the thermal joint is timed by example 20.

use super::error::ContactError;
use super::level_types::MeshedJoint;
use crate::error::InputError;
pub use crate::fem::plate_temperature::{PlateTemperature, TemperatureGrid};
use crate::fem::thermal::{Thermal, ThermalMaterial};
use crate::fem::Loads;
use crate::joint::Joint;

/// The temperatures and thermal tables of a joint's two plates.
#[derive(Debug, Clone, PartialEq)]
pub struct JointTemperature {
    /// Stress-free temperature T_ref.
    pub reference: f64,
    /// Temperatures of the upper and the lower plate.
    pub plates: [PlateTemperature; 2],
    /// E(T), ν(T), α(T) of the upper and the lower plate (used in place of the joint's
    /// materials, which then only set the solver's units).
    pub materials: [ThermalMaterial; 2],
}

impl JointTemperature {
    /// The joint's own E and ν with constant expansion coefficients `alpha` (upper, lower).
    pub fn constant(
        joint: &Joint,
        reference: f64,
        plates: [PlateTemperature; 2],
        alpha: [f64; 2],
    ) -> Result<Self, InputError> {
        Ok(Self {
            reference,
            plates,
            materials: [
                ThermalMaterial::constant(joint.upper().material(), alpha[0])?,
                ThermalMaterial::constant(joint.lower().material(), alpha[1])?,
            ],
        })
    }
}

/// A [`JointTemperature`] in the solver's units: lengths / `length`, moduli / `modulus`,
/// α · `modulus` / `stress` (so that E α ΔT / P is kept).
#[derive(Debug, Clone)]
pub(crate) struct ScaledTemperature<'a> {
    field: &'a JointTemperature,
    tables: [ThermalMaterial; 2],
    length: f64,
}

impl<'a> ScaledTemperature<'a> {
    pub(crate) fn new(
        field: &'a JointTemperature,
        length: f64,
        modulus: f64,
        stress: f64,
    ) -> Result<Self, InputError> {
        let scale = |m: &ThermalMaterial| {
            let rows = m.rows().iter();
            ThermalMaterial::table(
                rows.map(|r| [r[0], r[1] / modulus, r[2], r[3] * modulus / stress])
                    .collect(),
            )
        };
        Ok(Self {
            field,
            tables: [scale(&field.materials[0])?, scale(&field.materials[1])?],
            length,
        })
    }

    /// Sets the model's materials (one per element, at its temperature) and returns the
    /// thermal forces. The model is one of `refine::mesh`: plate p has material p, the upper
    /// plate lies above z = 0 and the lower one below.
    pub(crate) fn apply(&self, model: &mut MeshedJoint) -> Result<Loads, ContactError> {
        let mesh = &model.mesh;
        let mut temperature = vec![0.0; mesh.n_nodes()];
        let plates = [(model.upper, 0usize)]
            .into_iter()
            .chain(model.lower.map(|l| (l, 1usize)));
        let mut tables = vec![self.tables[0].clone(); mesh.n_plates()];
        for (p, k) in plates {
            let z = mesh.plate_z(p);
            let d = (z[z.len() - 1] - z[0]) * self.length;
            tables[p] = self.tables[k].clone();
            for (j, &zj) in z.iter().enumerate() {
                for (i, &r) in mesh.radial_nodes().iter().enumerate() {
                    let t = self.field.plates[k].at(r * self.length, zj.abs() * self.length, d);
                    temperature[mesh.node_at(p, i, j)] = t;
                }
            }
        }
        let th = Thermal::new(mesh, tables, temperature, self.field.reference)?;
        model.materials = th.apply(&mut model.mesh)?;
        Ok(th.loads(&model.mesh, &model.materials)?)
    }
}

/// The temperature field of `t` on the finest level's mesh of a two-plate field in the joint's
/// units ([`super::field::TwoPlateField`], both plates meshed): each element's table is its
/// plate's (the upper plate above z = 0, the lower below), each node's temperature its plate's
/// at (r, |z|). Its stresses σ = D (ε − ε_th) are those the contact solve balanced.
pub fn thermal_field(
    t: &JointTemperature,
    field: &super::field::TwoPlateField,
) -> Result<Thermal, ContactError> {
    let mesh = &field.model.mesh;
    let z = |n: usize| mesh.nodes()[n][1];
    let (top, bottom) = mesh
        .nodes()
        .iter()
        .fold((0.0f64, 0.0f64), |(t, b), x| (t.max(x[1]), b.min(x[1])));
    let thickness = [top, -bottom];
    let mut temperature = vec![t.reference; mesh.n_nodes()];
    let mut tables = Vec::with_capacity(mesh.n_elements());
    for e in 0..mesh.n_elements() {
        let nodes = mesh.element_nodes(e);
        let zc = nodes.iter().map(|&n| z(n)).sum::<f64>() / nodes.len() as f64;
        let k = usize::from(zc < 0.0);
        for &n in nodes {
            let r = mesh.nodes()[n][0];
            temperature[n] = t.plates[k].at(r, z(n).abs(), thickness[k]);
        }
        tables.push((mesh.element_material(e), t.materials[k].clone()));
    }
    // the mesh's material index of each element → its table
    let count = tables.iter().map(|(m, _)| m + 1).max().unwrap_or(0);
    let mut by_index = vec![t.materials[0].clone(); count];
    for (m, table) in tables {
        by_index[m] = table;
    }
    Ok(Thermal::new(mesh, by_index, temperature, t.reference)?)
}
