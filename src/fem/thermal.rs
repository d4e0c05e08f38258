//! Thermal strains on a mesh (report Appendix C, in the modern solver): a temperature per node,
//! E(T), ν(T), α(T) per material, the thermal load vector and the stresses σ = D (ε − ε_th).
//!
//! **What is computed.** With a stress-free reference temperature T_ref, the thermal strain of
//! an isotropic material is ε_th = α(T)(T − T_ref)(1, 1, 1, 0) in (ε_r, ε_z, ε_θ, γ_rz) (Appendix
//! C's α(T)·(T − T_ref), α the secant coefficient of its table). The equilibrium equations become
//! K u = f + f_th with f_th = ∑ₑ ∫ Bᵀ D ε_th dV ([`ElementKind::thermal_forces`](super::ElementKind::thermal_forces)) and the stresses
//! σ = D (B u − ε_th). Tension positive, compression negative; forces whole-ring; units the
//! caller's (α per degree of the temperatures').
//!
//! **Method.** A material's properties are a table of rows (T, E, ν, α) interpolated linearly in
//! T as the 1970 listing does ([`interpolate`]; one row: constants); a temperature outside a
//! table is an error. Each element takes E and ν at its temperature, the mean of its nodes (the
//! listing's rule), so a mesh with a temperature field has one material per element
//! ([`Thermal::apply`]); the thermal strain is taken per Gauss point
//! ([`super::element::thermal`]; the report's element per element, as the listing).
//!
//! # Accuracy
//!
//! `tests/fem/thermal.rs`: a free body under a uniform temperature has zero
//! stress and u = α ΔT r on every element (to round-off); under a temperature linear through the
//! thickness the free plate bends to the curvature α ΔT/D (Q9 exact, Q4 and the report's
//! element at their observed order); a body held axially and radially has
//! σ = −E α ΔT/(1 − ν) in the held directions; the Appendix C deck runner gives the same
//! answer on the same mesh to 1e-10. The nodal stresses ([`Thermal::nodal_stresses`], the
//! VTU's): `tests/io/thermal_vtu.rs` (a free body under a uniform ΔT, by superposition, shows no
//! stress to 2.3e-12 of the bolt-load stresses).
//!
//! # Cost
//!
//! One pass over the elements (as an assembly);
//! the two-plate model with a temperature: example 20.
//!
//! ```
//! use boltzone::fem::thermal::{Thermal, ThermalMaterial};
//! use boltzone::fem::*;
//! use boltzone::Material;
//! // A free ring heated by 100 degrees expands by α ΔT r and stays stress-free.
//! let r = Spacing::uniform(1.0, 2.0, 2)?;
//! let z = Spacing::uniform(0.0, 0.5, 1)?;
//! let mut mesh = Mesh::structured(ElementKind::Q9, &r, &[PlateSpec { z, material: 0 }])?;
//! let steel = ThermalMaterial::constant(Material::new(30e6, 0.3)?, 6e-6)?;
//! let th = Thermal::new(&mesh, vec![steel], vec![100.0; mesh.n_nodes()], 0.0)?;
//! let mats = th.apply(&mut mesh)?;
//! let mut s = Supports::new(mesh.n_nodes());
//! s.roller_z(mesh.bottom(0)[0]);
//! let dofs = DofMap::new(&s);
//! let k = assemble(&mesh, &mats, &dofs, &Pattern::new(&mesh, &dofs))?;
//! let f = dofs.gather(th.loads(&mesh, &mats)?.forces());
//! let u = dofs.expand(&Factorization::new(&k.matrix, &SolveParams::default())?.solve(&f));
//! let n = mesh.outer(0)[0];
//! assert!((u[n][0] - 6e-4 * 2.0).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::element::{thermal::ElementThermal, ElementKind, ElementPoint, Stress};
use super::error::FemError;
use super::loads::Loads;
use super::mesh::Mesh;
use super::recover::{element_u, material, nodal_mean};
use crate::error::InputError;
use crate::material::Material;

/// A material's elastic constants and expansion coefficient against temperature: rows
/// (T, E, ν, α), T increasing, interpolated linearly (Appendix C).
#[derive(Debug, Clone, PartialEq)]
pub struct ThermalMaterial {
    rows: Vec<[f64; 4]>,
}

/// The row (T, E, ν, α) of `table` at temperature `t`, linear between rows (a one-row table:
/// that row at every temperature); None outside the table or for an empty table.
pub fn interpolate(table: &[[f64; 4]], t: f64) -> Option<[f64; 4]> {
    let (first, last) = (table.first()?, table.last()?);
    if table.len() == 1 {
        return Some(*first);
    }
    if !(t >= first[0] && t <= last[0]) {
        return None;
    }
    let k = table.iter().position(|r| r[0] >= t)?.max(1);
    let (a, b) = (table[k - 1], table[k]);
    let s = (t - a[0]) / (b[0] - a[0]);
    Some([0, 1, 2, 3].map(|i| a[i] + s * (b[i] - a[i])))
}

impl ThermalMaterial {
    /// Constant E, ν (from `m`) and α at every temperature.
    pub fn constant(m: Material, alpha: f64) -> Result<Self, InputError> {
        Self::table(vec![[0.0, m.youngs_modulus(), m.poisson_ratio(), alpha]])
    }

    /// A table of rows (T, E, ν, α): T strictly increasing, every E and ν a valid material,
    /// every α finite.
    pub fn table(rows: Vec<[f64; 4]>) -> Result<Self, InputError> {
        if rows.is_empty() {
            return Err(InputError::Parameter {
                field: "temperature table rows",
                value: 0.0,
                reason: "need at least one row (T, E, nu, alpha)",
            });
        }
        for (k, row) in rows.iter().enumerate() {
            crate::error::finite("table temperature T", row[0])?;
            crate::error::finite("expansion coefficient alpha", row[3])?;
            Material::new(row[1], row[2])?;
            if k > 0 && row[0] <= rows[k - 1][0] {
                return Err(InputError::Parameter {
                    field: "table temperature T",
                    value: row[0],
                    reason: "table temperatures must increase row by row",
                });
            }
        }
        Ok(Self { rows })
    }

    /// The rows (T, E, ν, α).
    pub fn rows(&self) -> &[[f64; 4]] {
        &self.rows
    }

    /// E, ν (as a [`Material`]) and α at temperature `t`.
    pub fn at(&self, t: f64) -> Result<(Material, f64), InputError> {
        let row = interpolate(&self.rows, t).ok_or(InputError::Parameter {
            field: "temperature",
            value: t,
            reason: "outside the material's temperature table",
        })?;
        Ok((Material::new(row[1], row[2])?, row[3]))
    }

    /// The thermal strain α(T)(T − T_ref).
    pub fn strain(&self, t: f64, reference: f64) -> Result<f64, InputError> {
        Ok(self.at(t)?.1 * (t - reference))
    }
}

/// A temperature field on a mesh with its materials' tables (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct Thermal {
    reference: f64,
    temperature: Vec<f64>,
    tables: Vec<ThermalMaterial>,
    /// Table of each element (the mesh's material index when the field was made).
    table_of: Vec<usize>,
}

impl Thermal {
    /// A field of nodal `temperature`s on `mesh` with stress-free temperature `reference`;
    /// `tables[m]` is the mesh's material m. Every temperature must be finite and inside the
    /// tables of the elements that touch its node.
    pub fn new(
        mesh: &Mesh,
        tables: Vec<ThermalMaterial>,
        temperature: Vec<f64>,
        reference: f64,
    ) -> Result<Self, FemError> {
        crate::error::finite("reference temperature", reference)?;
        if temperature.len() != mesh.n_nodes() {
            return Err(InputError::Parameter {
                field: "number of nodal temperatures",
                value: temperature.len() as f64,
                reason: "must equal the number of mesh nodes",
            }
            .into());
        }
        let table_of: Vec<usize> = (0..mesh.n_elements())
            .map(|e| mesh.element_material(e))
            .collect();
        for (e, &m) in table_of.iter().enumerate() {
            let table = tables.get(m).ok_or(FemError::MissingMaterial {
                element: e,
                material: m,
                available: tables.len(),
            })?;
            for &n in mesh.element_nodes(e) {
                crate::error::finite("nodal temperature", temperature[n])?;
                table.at(temperature[n])?;
            }
        }
        Ok(Self {
            reference,
            temperature,
            tables,
            table_of,
        })
    }

    /// The stress-free temperature.
    pub fn reference(&self) -> f64 {
        self.reference
    }

    /// Temperature per node.
    pub fn temperature(&self) -> &[f64] {
        &self.temperature
    }

    fn element_temperatures(&self, mesh: &Mesh, e: usize) -> Vec<f64> {
        mesh.element_nodes(e)
            .iter()
            .map(|&n| self.temperature[n])
            .collect()
    }

    /// Calls `f` with element `e`'s nodal temperatures and strain function.
    fn with_element<T>(&self, mesh: &Mesh, e: usize, f: impl FnOnce(&ElementThermal) -> T) -> T {
        let table = &self.tables[self.table_of[e]];
        let t = self.element_temperatures(mesh, e);
        let alpha = |t: f64| table.at(t).map_or(f64::NAN, |r| r.1);
        f(&ElementThermal {
            temperature: &t,
            reference: self.reference,
            alpha: &alpha,
        })
    }

    /// E and ν of every element at its temperature (the mean of its nodes), indexed by element.
    pub fn materials(&self, mesh: &Mesh) -> Result<Vec<Material>, FemError> {
        (0..mesh.n_elements())
            .map(|e| {
                let t = self.with_element(mesh, e, |th| th.mean());
                Ok(self.tables[self.table_of[e]].at(t)?.0)
            })
            .collect()
    }

    /// Gives every element of `mesh` its own material and returns them ([`Thermal::materials`]),
    /// ready for [`crate::fem::assemble()`](fn@crate::fem::assemble).
    pub fn apply(&self, mesh: &mut Mesh) -> Result<Vec<Material>, FemError> {
        let m = self.materials(mesh)?;
        mesh.set_element_materials((0..m.len()).collect())?;
        Ok(m)
    }

    /// The thermal nodal forces f_th (global frame, whole-ring) for element materials
    /// `materials` (as [`Thermal::apply`] returns them).
    pub fn loads(&self, mesh: &Mesh, materials: &[Material]) -> Result<Loads, FemError> {
        let mut loads = Loads::new(mesh.n_nodes());
        self.add_loads(mesh, materials, &mut loads)?;
        Ok(loads)
    }

    /// Adds the thermal nodal forces to `loads`.
    pub fn add_loads(
        &self,
        mesh: &Mesh,
        materials: &[Material],
        loads: &mut Loads,
    ) -> Result<(), FemError> {
        for e in 0..mesh.n_elements() {
            let m = material(mesh, materials, e)?;
            let x = mesh.element_coords(e);
            let f = self.with_element(mesh, e, |th| mesh.kind().thermal_forces(&x, m, th));
            for (a, &n) in mesh.element_nodes(e).iter().enumerate() {
                loads.add_point(n, [f[2 * a], f[2 * a + 1]]);
            }
        }
        Ok(())
    }

    /// Displacements and stresses σ = D (B u − ε_th) at every element's quadrature points.
    pub fn gauss_stresses(
        &self,
        mesh: &Mesh,
        materials: &[Material],
        u: &[[f64; 2]],
    ) -> Result<Vec<ElementPoint>, FemError> {
        let per = self.each_element(mesh, materials, u, |k, x, m, ue, th| {
            k.thermal_quadrature_points(x, m, ue, th)
        })?;
        Ok(per.into_iter().flatten().collect())
    }

    /// Nodal stresses σ = D (B u − ε_th), each element's value at the node (its own
    /// temperature there; the report's element: its mean strain) averaged over the elements
    /// sharing it, as [`super::recover::nodal_stresses`] averages.
    pub fn nodal_stresses(
        &self,
        mesh: &Mesh,
        materials: &[Material],
        u: &[[f64; 2]],
    ) -> Result<Vec<Stress>, FemError> {
        let per = self.each_element(mesh, materials, u, |k, x, m, ue, th| {
            k.thermal_nodal_stresses(x, m, ue, th)
        })?;
        nodal_mean(mesh, |e| Ok(per[e].clone()))
    }

    /// Stress σ = D (B u − ε_th) at each element's centre.
    pub fn centre_stresses(
        &self,
        mesh: &Mesh,
        materials: &[Material],
        u: &[[f64; 2]],
    ) -> Result<Vec<ElementPoint>, FemError> {
        self.each_element(mesh, materials, u, |k, x, m, ue, th| {
            k.thermal_centre_stress(x, m, ue, th)
        })
    }

    /// `f(kind, coordinates, material, element displacements, thermal state)` of every element.
    fn each_element<T>(
        &self,
        mesh: &Mesh,
        materials: &[Material],
        u: &[[f64; 2]],
        f: impl Fn(ElementKind, &[[f64; 2]], &Material, &[f64], &ElementThermal) -> T,
    ) -> Result<Vec<T>, FemError> {
        (0..mesh.n_elements())
            .map(|e| {
                let m = material(mesh, materials, e)?;
                let (x, ue) = (mesh.element_coords(e), element_u(mesh, u, e));
                Ok(self.with_element(mesh, e, |th| f(mesh.kind(), &x, m, &ue, th)))
            })
            .collect()
    }
}
