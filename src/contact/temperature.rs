//! The temperatures of a joint's two plates ([`JointTemperature`]: uniform, linear through the
//! thickness, or a field T(r, s) on a grid, with each plate's E(T), ν(T), α(T) table), and their
//! scaling into the contact solver's units. The solver with temperatures is
//! [`super::thermal`]; these types live apart from it so that the mesh levels
//! ([`super::refine`], [`super::two_plate`]) read them without importing the solver that calls
//! them. Public paths stay `boltzone::contact::thermal::{JointTemperature, PlateTemperature,
//! TemperatureGrid}`.
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
use super::level_types::Model;
use crate::error::InputError;
use crate::fem::thermal::{Thermal, ThermalMaterial};
use crate::fem::{Loads, Mesh};
use crate::joint::Joint;

/// A temperature field T(r, s) on a tensor grid of radii `r` and depths `s` below the interface,
/// bilinear between grid points and held at the edge values outside the grid.
#[derive(Debug, Clone, PartialEq)]
pub struct TemperatureGrid {
    r: Vec<f64>,
    s: Vec<f64>,
    /// Row-major: t[i·s.len() + j] at (r[i], s[j]).
    t: Vec<f64>,
}

impl TemperatureGrid {
    /// A grid of `r` (increasing) × `s` (increasing) with values `t[i·s.len() + j]`.
    pub fn new(r: Vec<f64>, s: Vec<f64>, t: Vec<f64>) -> Result<Self, InputError> {
        let bad = |field, value: f64, reason| InputError::Parameter {
            field,
            value,
            reason,
        };
        for (field, v) in [("grid radii r", &r), ("grid depths s", &s)] {
            if v.is_empty()
                || v.windows(2)
                    .any(|w| w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater))
            {
                return Err(bad(
                    field,
                    v.len() as f64,
                    "must be non-empty and increasing",
                ));
            }
        }
        if t.len() != r.len() * s.len() {
            return Err(bad(
                "grid temperatures",
                t.len() as f64,
                "need one per (r, s) grid point",
            ));
        }
        for &v in t.iter().chain(&r).chain(&s) {
            crate::error::finite("temperature grid value", v)?;
        }
        Ok(Self { r, s, t })
    }

    /// Plate `plate`'s nodal temperatures of a structured `mesh` (e.g. from
    /// [`crate::heat::conduction::solve_conduction`]), depth measured from the plate's top face
    /// (`interface_on_top`) or its bottom face.
    pub fn from_mesh(
        mesh: &Mesh,
        plate: usize,
        temperature: &[f64],
        interface_on_top: bool,
    ) -> Result<Self, InputError> {
        let z = mesh.plate_z(plate);
        let (z0, z1) = (z[0], z[z.len() - 1]);
        let mut rows: Vec<usize> = (0..z.len()).collect();
        if interface_on_top {
            rows.reverse();
        }
        let s = rows
            .iter()
            .map(|&j| {
                if interface_on_top {
                    z1 - z[j]
                } else {
                    z[j] - z0
                }
            })
            .collect();
        let mut t = Vec::new();
        for i in 0..mesh.radial_nodes().len() {
            for &j in &rows {
                let n = mesh.node_at(plate, i, j);
                t.push(*temperature.get(n).ok_or(InputError::Parameter {
                    field: "number of nodal temperatures",
                    value: temperature.len() as f64,
                    reason: "must cover every node of the mesh",
                })?);
            }
        }
        Self::new(mesh.radial_nodes().to_vec(), s, t)
    }

    /// T at (r, s), bilinear.
    pub fn at(&self, r: f64, s: f64) -> f64 {
        let cell = |x: &[f64], v: f64| -> (usize, f64) {
            if x.len() == 1 {
                return (0, 0.0);
            }
            let i = x.partition_point(|&a| a <= v).clamp(1, x.len() - 1) - 1;
            (i, ((v - x[i]) / (x[i + 1] - x[i])).clamp(0.0, 1.0))
        };
        let ((i, a), (j, b)) = (cell(&self.r, r), cell(&self.s, s));
        let ns = self.s.len();
        let v = |i: usize, j: usize| self.t[i.min(self.r.len() - 1) * ns + j.min(ns - 1)];
        (1.0 - a) * ((1.0 - b) * v(i, j) + b * v(i, j + 1))
            + a * ((1.0 - b) * v(i + 1, j) + b * v(i + 1, j + 1))
    }
}

/// One plate's temperature.
#[derive(Debug, Clone, PartialEq)]
pub enum PlateTemperature {
    /// The same temperature throughout.
    Uniform(f64),
    /// Linear through the thickness, from `interface` on the contact face to `outer` on the
    /// loaded face (a steady heat flow through the plate).
    Linear {
        /// Temperature on the contact face.
        interface: f64,
        /// Temperature on the loaded (outer) face.
        outer: f64,
    },
    /// A field T(r, s) (s the depth below the interface).
    Field(TemperatureGrid),
}

impl PlateTemperature {
    /// T at radius `r`, depth `s` below the interface of a plate `thickness` thick.
    pub fn at(&self, r: f64, s: f64, thickness: f64) -> f64 {
        match self {
            Self::Uniform(t) => *t,
            Self::Linear { interface, outer } => interface + (outer - interface) * s / thickness,
            Self::Field(g) => g.at(r, s),
        }
    }
}

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
    pub(crate) fn apply(&self, model: &mut Model) -> Result<Loads, ContactError> {
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
