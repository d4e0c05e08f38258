//! The single-plate model with thermal strains: Fernlund's substitute plate 2D thick
//! ([`super::single`]) whose temperature is mirror-symmetric about the midplane, as in a
//! symmetric joint whose two plates carry the same temperature field.
//!
//! **What is computed.** R_o (the first radius beyond B where the midplane σ_z turns tensile)
//! of the plate under its face load and the thermal strains ε_th = α(T)(T − T_ref)(1, 1, 1, 0)
//! (report Appendix C in the modern solver), E(T), ν(T), α(T) from a table read linearly
//! ([`super::thermal::ThermalMaterial`]). The temperature is a [`PlateTemperature`] in terms of
//! the depth s below the midplane (s = 0 the midplane, the joint's interface; s = D the loaded
//! face): uniform, linear through the half thickness, or a field T(r, s). Compression negative;
//! units the plate's, α per degree of the temperatures.
//!
//! **Method.** The half plate 0 ≤ z ≤ D of [`super::single`] on its midplane rollers, on the
//! same refinement levels: each node gets T(r, z), each element E and ν at its temperature
//! ([`super::thermal::Thermal`]), the thermal forces join the face load, and the midplane σ_z
//! comes from the roller reactions K u − f (thermal forces included). The mirror symmetry is
//! what keeps the roller exact: a temperature odd about the midplane bends the plate and is not
//! a single-plate substitute. A rigid nut (a prescribed displacement of unit-modulus scale) is
//! refused with temperatures: their stresses would not be on the same scale.
//!
//! Exact statements: a uniform temperature (α constant) makes the free plate expand without
//! stress, u = α ΔT r, w = α ΔT z, so R_o is the isothermal one; a temperature linear in s is
//! odd-free only through |z|, so the substitute plate is held flat by the midplane (the plate
//! on rollers cannot take the curvature α ΔT/D a free half plate would take): away from the
//! hole, the load and the rim the thermal part of the stress is
//! σ_r = σ_θ = E α (T̄ − T(z))/(1 − ν), σ_z = τ_rz = 0 (T̄ the mean over the thickness), the
//! disturbances decaying like e^(−2.1 x/D) (the first Papkovich–Fadle root of a strip 2D thick).
//!
//! # Accuracy
//!
//! `tests/fem/single_thermal.rs`: uniform ΔT leaves R_o unchanged to rounding and adds
//! exactly α ΔT (r, z) to the displacements with no stress; the thermal part of the stress
//! under a mirrored linear gradient matches E α (T̄ − T)/(1 − ν) in the interior within the
//! e^(−2.1 x/D) decay of the edge disturbances; the thermal midplane reactions carry no net force.
//!
//! # Cost
//!
//! The isothermal levels' ([`super::single`]) plus one pass over the elements per level for
//! the materials and thermal forces; `tests/fem/single_thermal.rs` prints the times.
//!
//! ```
//! use boltzone::fem::single::SingleParams;
//! use boltzone::fem::single_thermal::{solve_with_temperature, SingleTemperature};
//! use boltzone::fem::plate_temperature::PlateTemperature;
//! use boltzone::{FaceLoad, Material, OuterRadius, SinglePlate};
//! let load = FaceLoad::uniform(0.1, 0.22, 1000.0)?;
//! let plate = SinglePlate::new(0.1, OuterRadius::Finite(1.54), 0.1,
//!                              Material::new(1e7, 0.3)?, load)?;
//! let params = SingleParams { levels: 3, tolerance: 1e-2, ..SingleParams::default() };
//! let hot = SingleTemperature::constant(&plate, 70.0, PlateTemperature::Uniform(170.0), 13e-6)?;
//! let s = solve_with_temperature(&plate, &params, &hot)?;
//! let iso = boltzone::fem::single::solve(&plate, &params)?;
//! assert!((s.r_o - iso.r_o).abs() < 1e-9 * iso.r_o); // free expansion: R_o unchanged
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::FemError;
pub use super::plate_temperature::PlateTemperature;
use super::single::{check_tolerance, study, HalfPlate, SingleParams, SingleSolution};
pub use super::single_temperature::SingleTemperature;
use crate::joint::SinglePlate;

/// R_o of `plate` with the temperatures `t`, refined as [`super::single::solve`] refines.
pub fn solve_with_temperature(
    plate: &SinglePlate,
    params: &SingleParams,
    t: &SingleTemperature,
) -> Result<SingleSolution, FemError> {
    check_tolerance(params.tolerance)?;
    Ok(study(plate, params, Some(params.tolerance), false, Some(t))?.0)
}

/// As [`solve_with_temperature`], keeping the finest level's half plate (with its
/// [`Thermal`](super::thermal::Thermal) field) for a field or curve output.
pub fn solve_with_temperature_field(
    plate: &SinglePlate,
    params: &SingleParams,
    t: &SingleTemperature,
) -> Result<(SingleSolution, HalfPlate), FemError> {
    check_tolerance(params.tolerance)?;
    let (s, h) = study(plate, params, Some(params.tolerance), true, Some(t))?;
    let h = h.ok_or(FemError::Solver("no refinement level was solved".into()))?;
    Ok((s, h))
}
