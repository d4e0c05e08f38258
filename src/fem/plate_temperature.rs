//! A plate's temperature as the thermal models read it: uniform, linear through the thickness,
//! or a field T(r, s) on a grid ([`TemperatureGrid`], e.g. from
//! [`crate::heat::conduction::solve_conduction`]), with s the depth below the plate's contact
//! face (the interface of a joint, the midplane of the single-plate substitute). Used by the
//! single plate with temperatures ([`super::single_thermal`]) and by the two-plate model
//! (`boltzone::contact::thermal`, which re-exports these types). Temperatures in any degree.
//!
//! # Accuracy
//!
//! Evaluation only (bilinear on the grid, exact on a linear field):
//! `tests/contact/thermal.rs` (`a_conduction_field_equals_the_linear_description_it_reproduces`)
//! and `tests/fem/single_thermal.rs`.
//!
//! # Cost
//!
//! One binary search per coordinate and evaluation.
//!
//! ```
//! use boltzone::fem::plate_temperature::PlateTemperature;
//! let t = PlateTemperature::Linear { interface: 80.0, outer: 60.0 };
//! assert_eq!(t.at(0.5, 0.05, 0.1), 70.0);
//! ```

use super::mesh::Mesh;
use crate::error::InputError;

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
