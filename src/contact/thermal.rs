//! The two-plate model with a temperature field: each plate's temperature (uniform, linear
//! through its thickness, or a field T(r, z) such as [`crate::heat::conduction`]'s), its
//! E(T), ν(T), α(T) table and the stress-free temperature; the contact problem of
//! [`super::two_plate`] solved with the thermal strains of [`crate::fem::thermal`].
//!
//! **What is computed.** R_o, the interface pressure p(r) and the gap g(r) of the joint under
//! its bolt load and the thermal strains ε_th = α(T)(T − T_ref)(1, 1, 1, 0) (report Appendix C
//! in the modern solver; Chapter V: "for large heat fluxes where thermal strains may have an
//! influence on the radii of separation"). Temperatures are given plate by plate in terms of the
//! depth s below the interface (s = 0 on the contact face, s = D on the loaded face).
//! p > 0 compression, g > 0 open; units: the joint's, α per degree of the temperatures.
//!
//! **Method.** Both plates are meshed (a temperature field breaks the mirror symmetry the
//! one-plate model relies on). On every mesh level each node gets its plate's temperature, each
//! element E and ν at its temperature, and the thermal forces join the bolt load
//! ([`crate::fem::thermal::Thermal`]); the contact forces are K u − f on the interface. The
//! solver's units (thinner plate, stiffer modulus, bearing pressure 1) scale the thermal strain
//! by E/P: what matters is E α ΔT against the bearing pressure. Unlike the isothermal joint,
//! R_o then depends on the load's magnitude.
//!
//! # Accuracy
//!
//! `tests/contact/thermal.rs`: a uniform temperature (any, the same α) leaves R_o
//! and p(r) of the frictionless joint unchanged to rounding (the plates expand freely), ΔT = 0
//! reproduces the isothermal solution bit for bit; the same gradient through both plates changes
//! nothing; a field from [`crate::heat::conduction`] gives the joint of the linear temperatures
//! it reproduces; mirrored gradients move R_o the way the rims bend. The level study's error
//! estimate is the isothermal one's (it does not include the temperatures' own error).
//! The field ([`solve_field_with_temperature`]: the finest level with its temperature field,
//! stresses σ = D (ε − ε_th)): `tests/io/thermal_vtu.rs` reads its VTU with meshio — a uniform
//! ΔT adds exactly the free expansion α ΔT (r, z) and no stress.
//!
//! # Cost
//!
//! Two plates meshed (about twice the symmetric model); example 20.
//!
//! ```
//! use boltzone::contact::thermal::{solve_with_temperature, JointTemperature, PlateTemperature};
//! use boltzone::contact::two_plate::TwoPlateParams;
//! use boltzone::{Joint, Material, OuterRadius};
//! let joint = Joint::symmetric(0.1, 0.31, 0.1, Material::new(10e6, 0.3)?)?
//!     .with_outer_radius(OuterRadius::Finite(1.0))?;
//! let hot = PlateTemperature::Uniform(170.0);
//! let t = JointTemperature::constant(&joint, 70.0, [hot.clone(), hot], [12e-6; 2])?;
//! let params = TwoPlateParams { tolerance: 1e-2, ..Default::default() };
//! let s = solve_with_temperature(&joint, &params, &t)?;
//! assert!(s.r_o > 0.31 && s.r_o < 0.6, "R_o = {}", s.r_o);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::ContactError;
use super::field::TwoPlateField;
pub use super::temperature::{thermal_field, JointTemperature, PlateTemperature, TemperatureGrid};
use super::two_plate::{solve_keeping_with, TwoPlateParams, TwoPlateSolution};
use crate::fem::thermal::Thermal;
use crate::joint::Joint;

/// Solves the two-plate joint with the temperature field `t` (module docs); the isothermal
/// model is [`super::two_plate::solve`].
pub fn solve_with_temperature(
    joint: &Joint,
    params: &TwoPlateParams,
    t: &JointTemperature,
) -> Result<TwoPlateSolution, ContactError> {
    solve_keeping_with(joint, params, Some(t)).map(|(s, _)| s)
}

/// As [`solve_with_temperature`], keeping the finest level's field in the joint's units and its
/// temperature field ([`thermal_field`]) for a VTU with the thermal stresses.
pub fn solve_field_with_temperature(
    joint: &Joint,
    params: &TwoPlateParams,
    t: &JointTemperature,
) -> Result<(TwoPlateSolution, TwoPlateField, Thermal), ContactError> {
    let (s, f) = solve_keeping_with(joint, params, Some(t))?;
    let f = f.rescaled()?;
    let th = thermal_field(t, &f)?;
    Ok((s, f, th))
}
