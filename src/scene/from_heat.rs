//! The scene's `[temperature] from_heat = true`: the plates' temperatures from the joint's own
//! heat flow ([`crate::heat::coupled`]) — the loaded faces held at `faces`, the
//! interface conductance h_c(p(r)) of the `[heat]` table, iterated with the contact solve to a
//! fixed point of R_o.
//!
//! ```toml
//! [temperature]
//! reference = 20.0          # stress-free temperature
//! from_heat = true
//! faces = [120.0, 20.0]     # upper loaded face (under the head), lower loaded face
//! alpha = [23e-6]           # or table = [[T, E, nu, alpha], ...]
//! [heat]                    # required: k, roughness, slope, hardness (super::heat)
//! ```
//!
//! Two-plate scenes only; no `plates` or `gradient` beside it. `[outputs] field` writes the last
//! pass's finest level with its thermal stresses and nodal `temperature` (that pass solved once
//! more, keeping the level: the same inputs give the same R_o). Temperatures are in the degree of the scene's conductivity unit
//! (°F in in-psi-lbf, K or °C otherwise). The answer adds `heat_passes` (thermal passes run) and
//! `heat_flow` with `heat_flow_unit` (W; Btu/hr in in-psi-lbf); a fixed point not reached within
//! [`MAX_PASSES`] passes leaves the answer flagged not converged (the command exits 3). Each error
//! names the key, the value and the line.
//!
//! # Accuracy
//!
//! Those of [`crate::heat::coupled`]; `tests/scene/from_heat.rs` checks that the example
//! scene `examples/scenes/from_heat.toml` equals the library call bit for bit and that bad tables
//! exit 2 naming the key and the line.
//!
//! # Cost
//!
//! `heat_passes` + 1 contact solves: the example scene (3 passes) took 0.22 s in
//! `boltzone solve examples/scenes/from_heat.toml --explain` (optimised build, load average 3.8).
//!
//! ```
//! let text = "[hole]\nradius = 0.1\n[load]\nouter_radius = 0.31\npressure = 1000.0\n\
//!     [[plates]]\nthickness = 0.1\nmaterial = { E = 1e7, nu = 0.33 }\n[joint]\nouter_radius = 1.0\n\
//!     [temperature]\nreference = 70.0\nfrom_heat = true\nfaces = [170.0, 70.0]\nalpha = [13e-6]\n";
//! let e = boltzone::scene::Scene::parse(text).unwrap_err().to_string();
//! assert!(e.contains("temperature.from_heat"), "{e}"); // no [heat] table
//! ```

use super::error::SceneError;
use super::file::{Model, Scene};
use super::solution::Solution;
use super::temperature_keys::fail;
use super::temperature_spec::TemperatureSpec;
use super::temperature_table::materials;
use super::units::UnitSystem;
use crate::contact::two_plate::TwoPlateParams;
use crate::heat::coupled::{solve_from_heat, HeatCoupledSolution, HeatCoupling};
use crate::joint::Joint;

/// Most thermal passes before the answer is flagged not converged.
pub const MAX_PASSES: usize = 20;

/// Elements through each plate in the conduction mesh.
pub const AXIAL_ELEMENTS: usize = 8;

/// Checks `from_heat` and `faces` (`text` for the lines); true when the temperatures come from
/// the heat flow (then `plates` and `gradient` are absent).
pub(super) fn check(scene: &Scene, t: &TemperatureSpec, text: &str) -> Result<bool, SceneError> {
    let Some(faces) = t.faces else {
        return match t.from_heat {
            true => Err(fail(
                text,
                "from_heat",
                true,
                "give faces = [upper, lower] (the loaded faces' temperatures)",
            )),
            false => Ok(false),
        };
    };
    if !t.from_heat {
        return Err(fail(
            text,
            "faces",
            format!("{faces:?}"),
            "faces need from_heat = true",
        ));
    }
    for (key, given) in [
        ("plates", t.plates.is_some()),
        ("gradient", t.gradient.is_some()),
    ] {
        if given {
            return Err(fail(
                text,
                key,
                "given",
                "from_heat = true sets the temperatures: drop plates and gradient",
            ));
        }
    }
    for v in faces {
        if !v.is_finite() {
            return Err(fail(text, "faces", v, "must be a finite number"));
        }
    }
    let refuse = |reason| Err(fail(text, "from_heat", true, reason));
    if scene.model != Model::TwoPlate {
        return refuse("needs model = \"two-plate\"");
    }
    if scene.heat.is_none() {
        return refuse("needs a [heat] table (the interface conductance h_c(p))");
    }
    Ok(true)
}

/// The heat side of a checked scene with `from_heat` in SI units (`joint` the scene's in SI).
pub fn coupling(
    scene: &Scene,
    joint: &Joint,
    t: &TemperatureSpec,
) -> Result<HeatCoupling, SceneError> {
    let no_heat = || fail("", "from_heat", true, "needs a [heat] table");
    let heat = scene.heat.as_ref().ok_or_else(no_heat)?;
    let faces = t
        .faces
        .ok_or_else(|| fail("", "faces", "absent", "give faces"))?;
    let own = [joint.upper().material(), joint.lower().material()];
    let units = scene.units;
    Ok(HeatCoupling {
        contact: heat.contact(units, own)?,
        conductivity: heat.conductivity.map(|k| k * units.conductivity()),
        faces,
        reference: t.reference,
        materials: materials(t, units.stress(), own)?,
        axial: AXIAL_ELEMENTS,
        tolerance: scene.tolerance,
        max_passes: MAX_PASSES,
    })
}

/// The unit of `heat_flow`.
pub fn heat_flow_unit(units: UnitSystem) -> &'static str {
    match units {
        UnitSystem::InPsiLbf => "Btu/hr",
        UnitSystem::MmMpaN | UnitSystem::MPaN => "W",
    }
}

/// Solves the scene's joint with `from_heat` and records the passes and the heat flow in `out`.
pub(super) fn solve(
    scene: &Scene,
    joint: &Joint,
    params: &TwoPlateParams,
    t: &TemperatureSpec,
    out: &mut Solution,
) -> Result<HeatCoupledSolution, SceneError> {
    let mut s = solve_from_heat(joint, params, &coupling(scene, joint, t)?)?;
    if scene.outputs.field.is_some() {
        // the last pass again, keeping its finest level (the same inputs: the same solution)
        let units = (scene.units.length(), scene.units.stress());
        let converged = s.solution.converged;
        s.solution = super::field::two_plate_thermal_grid(
            joint,
            params,
            &s.temperature,
            units,
            &mut out.field,
        )?;
        s.solution.converged &= converged;
    }
    out.heat_passes = Some(s.passes);
    out.heat_flow = Some(s.heat_flow / scene.units.conductance());
    out.heat_flow_unit = Some(heat_flow_unit(scene.units));
    Ok(s)
}
