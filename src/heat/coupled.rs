//! The two-plate joint with the temperature field its own heat flow sets up: the contact
//! pressure p(r) gives the interface conductance h_c(p(r)), conduction through the stack gives
//! T(r, z), the thermal strains of T give a new p(r) — repeated to a fixed point (issue 12's
//! `[temperature] from_heat = true`; report Chapter V: "for large heat fluxes where thermal
//! strains may have an influence on the radii of separation").
//!
//! **What is computed.** R_o, p(r), g(r) of [`crate::contact::thermal::solve_with_temperature`] with the
//! field T(r, z) of [`crate::heat::conduction::solve_conduction`] on the two-plate stack: the
//! upper plate's loaded face held at `faces[0]`, the lower plate's at `faces[1]`, the hole and
//! rim faces insulated, the plates joined by h_c(p(r)) of [`crate::heat::correlation`] where
//! p > 0 and r ≤ R_o (zero beyond). The heat flow Q into the upper loaded face (positive from
//! the upper plate to the lower when `faces[0] > faces[1]`) is that of the last conduction solve.
//! Units: the joint in SI (m, Pa), conductivities in W/(m·K), temperatures in kelvin or °C
//! (α per the same degree), Q in W. Compression p > 0, as [`crate::contact::two_plate`].
//!
//! **Method.** Pass 0 is the isothermal joint. Each pass meshes the stack with Q4 elements on
//! the radii of the previous pass's interface nodes ([`TwoPlateSolution::radius`]) and
//! `axial` elements through each plate, solves the conduction, reads each plate's nodal T as a
//! [`TemperatureGrid`] and solves the thermal joint. The passes stop when R_o moves by no more
//! than `tolerance` × R_o ([`HeatCoupling::tolerance`]); after `max_passes` without that the
//! answer is flagged not converged.
//!
//! # Accuracy
//!
//! `tests/scene/from_heat.rs`: equal face temperatures give a field uniform to 1e-12 and, at the
//! stress-free temperature, the isothermal R_o to 1e-10; the conduction's heat in equals its heat
//! out to 1e-10 relative, and Q/ΔT tends to the interface conductance G of
//! [`crate::heat::joint::joint_conductance`] as the plates' conductivity grows (the plates'
//! resistance in series falls as 1/k: observed rate 0.99 from k × 1000 to k × 10 000; the limit is
//! the lumped interface Σ h_i ∫N_i 2πr dr, 1.3e-3 above the tributary rule of `heat::joint`);
//! a symmetric pair's field is antisymmetric about the interface to 1.4e-12 °F and leaves R_o
//! at the isothermal value (7e-12: the mirrored plates bend alike, so thermal strains move R_o
//! only through unequal plates, conductivities or α — the example scene's α ratio 2 moves it
//! 8.6 % in 3 passes); a fixed point not reached is flagged not converged.
//!
//! # Cost
//!
//! One isothermal and `passes` thermal contact solves plus as many conduction solves (one sparse
//! Cholesky each, small beside the contact solve); the scene `examples/scenes/from_heat.toml`
//! (3 passes) takes 0.22 s through `boltzone solve --explain`.
//!
//! ```
//! use boltzone::heat::coupled::{solve_from_heat, HeatCoupling};
//! use boltzone::contact::two_plate::TwoPlateParams;
//! use boltzone::fem::thermal::ThermalMaterial;
//! use boltzone::heat::correlation::{ContactConductance, Correlation, Surfaces};
//! use boltzone::heat::units::{Conductivity, Length, Pressure};
//! use boltzone::{Joint, Material, OuterRadius};
//! let al = Material::new(70e9, 0.33)?;
//! let joint = Joint::symmetric(0.005, 0.01, 0.01, al)?.with_outer_radius(OuterRadius::Finite(0.04))?;
//! let surfaces = Surfaces::new([Conductivity::from_si(170.0); 2], [Length::from_si(1e-6); 2],
//!     [0.1; 2], Pressure::from_si(1e9))?;
//! let coupling = HeatCoupling {
//!     contact: ContactConductance::new(Correlation::Cmy1969, surfaces)?,
//!     conductivity: [170.0; 2],
//!     faces: [20.0, 20.0],
//!     reference: 20.0,
//!     materials: [ThermalMaterial::constant(al, 23e-6)?, ThermalMaterial::constant(al, 23e-6)?],
//!     axial: 4,
//!     tolerance: 1e-3,
//!     max_passes: 5,
//! };
//! let params = TwoPlateParams { tolerance: 1e-2, ..Default::default() };
//! let s = solve_from_heat(&joint, &params, &coupling)?;
//! assert_eq!(s.passes, 1); // no heat flows: the first field changes nothing
//! assert!(s.heat_flow.abs() < 1e-9, "{} W", s.heat_flow); // reactions at 20 °C: rounding only
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::conduction::{solve_conduction, ConductionSolution};
use super::correlation::ContactConductance;
use crate::contact::thermal::{
    solve_with_temperature, JointTemperature, PlateTemperature, TemperatureGrid,
};
use crate::contact::two_plate::{self, TwoPlateParams, TwoPlateSolution};
use crate::contact::ContactError;
use crate::error::InputError;
use crate::fem::thermal::ThermalMaterial;
use crate::fem::{ElementKind, Mesh, PlateSpec, Spacing};
use crate::joint::Joint;

/// The heat side of [`solve_from_heat`] (module docs; SI units).
#[derive(Debug, Clone)]
pub struct HeatCoupling {
    /// h_c(p) of the interface.
    pub contact: ContactConductance,
    /// Conductivities of the upper and the lower plate, W/(m·K).
    pub conductivity: [f64; 2],
    /// Temperatures of the upper and the lower loaded face.
    pub faces: [f64; 2],
    /// Stress-free temperature T_ref.
    pub reference: f64,
    /// E(T), ν(T), α(T) of the upper and the lower plate.
    pub materials: [ThermalMaterial; 2],
    /// Elements through each plate's thickness in the conduction mesh (≥ 1).
    pub axial: usize,
    /// Stop when R_o changes by at most this fraction of R_o between passes.
    pub tolerance: f64,
    /// Most thermal passes.
    pub max_passes: usize,
}

/// The conduction through a solved joint ([`conduct`]).
#[derive(Debug, Clone)]
pub struct Conduction {
    /// The stack's mesh: plate 0 the lower (z ≤ 0), plate 1 the upper (z ≥ 0).
    pub mesh: Mesh,
    /// Nodal temperatures and reactions.
    pub solution: ConductionSolution,
    /// Heat flow into the upper loaded face, W.
    pub heat_in: f64,
    /// Heat flow out of the lower loaded face, W.
    pub heat_out: f64,
}

impl Conduction {
    /// Each plate's temperature by depth below the interface (upper, lower).
    pub fn plates(&self) -> Result<[PlateTemperature; 2], InputError> {
        let t = &self.solution.temperature;
        Ok([
            PlateTemperature::Field(TemperatureGrid::from_mesh(&self.mesh, 1, t, false)?),
            PlateTemperature::Field(TemperatureGrid::from_mesh(&self.mesh, 0, t, true)?),
        ])
    }
}

/// The answer of [`solve_from_heat`].
#[derive(Debug, Clone)]
pub struct HeatCoupledSolution {
    /// The last thermal contact solution; its `converged` also requires the fixed point.
    pub solution: TwoPlateSolution,
    /// The temperatures of the last pass.
    pub temperature: JointTemperature,
    /// Thermal passes run (each one conduction and one contact solve).
    pub passes: usize,
    /// |ΔR_o| / R_o of the last pass.
    pub r_o_change: f64,
    /// Heat flow through the joint in the last pass, W (into the upper loaded face).
    pub heat_flow: f64,
}

/// Steady conduction through `joint` with the interface conductance h_c(p(r)) of the solved
/// `contact` (module docs).
pub fn conduct(
    joint: &Joint,
    contact: &TwoPlateSolution,
    heat: &HeatCoupling,
) -> Result<Conduction, ContactError> {
    let axial = heat.axial.max(1);
    let radial = Spacing::from_points(contact.radius.clone())?;
    let plate = |z0: f64, z1: f64, material| -> Result<PlateSpec, InputError> {
        Ok(PlateSpec {
            z: Spacing::uniform(z0, z1, axial)?,
            material,
        })
    };
    let plates = [
        plate(-joint.lower().thickness(), 0.0, 1)?,
        plate(0.0, joint.upper().thickness(), 0)?,
    ];
    let mesh = Mesh::structured(ElementKind::Q4, &radial, &plates)?;
    let r_o = contact.r_o;
    let h = |r: f64| {
        let p = contact.pressure_at(r);
        if r <= r_o && p > 0.0 {
            heat.contact.coefficient_si(p)
        } else {
            0.0
        }
    };
    let (top, bottom) = (mesh.top(1), mesh.bottom(0));
    let fixed: Vec<(usize, f64)> = top
        .iter()
        .map(|&n| (n, heat.faces[0]))
        .chain(bottom.iter().map(|&n| (n, heat.faces[1])))
        .collect();
    let solution = solve_conduction(&mesh, &heat.conductivity, &h, &fixed)?;
    let heat_in = top.iter().map(|&n| solution.flow[n]).sum();
    let heat_out = -bottom.iter().map(|&n| solution.flow[n]).sum::<f64>();
    Ok(Conduction {
        mesh,
        solution,
        heat_in,
        heat_out,
    })
}

/// Solves the joint with the temperature field of its own heat flow, to a fixed point (module
/// docs).
pub fn solve_from_heat(
    joint: &Joint,
    params: &TwoPlateParams,
    heat: &HeatCoupling,
) -> Result<HeatCoupledSolution, ContactError> {
    crate::error::positive("from_heat tolerance", heat.tolerance)?;
    let mut sol = two_plate::solve(joint, params)?;
    let mut passes = 0;
    loop {
        let c = conduct(joint, &sol, heat)?;
        let temperature = JointTemperature {
            reference: heat.reference,
            plates: c.plates()?,
            materials: heat.materials.clone(),
        };
        let next = solve_with_temperature(joint, params, &temperature)?;
        passes += 1;
        let r_o_change = (next.r_o - sol.r_o).abs() / next.r_o;
        sol = next;
        let fixed = r_o_change <= heat.tolerance;
        if fixed || passes >= heat.max_passes.max(1) {
            sol.converged &= fixed;
            return Ok(HeatCoupledSolution {
                solution: sol,
                temperature,
                passes,
                r_o_change,
                heat_flow: c.heat_in,
            });
        }
    }
}
