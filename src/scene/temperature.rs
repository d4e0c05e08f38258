//! The scene's `[temperature]` table: the plates' temperatures for the two-plate model with
//! thermal strains ([`crate::contact::thermal`]) and for the single-plate substitute
//! ([`crate::fem::single_thermal`], finite elements).
//!
//! **What is computed.** Nothing here: the keys become a [`JointTemperature`] — the stress-free
//! temperature, each plate's temperature (uniform, or linear through its thickness from the
//! contact face to the loaded face) and each plate's expansion coefficient α, with E and ν the
//! plates' own. Temperatures are in any degree (only differences and the α that goes with them
//! matter): α is per degree of the same scale, whatever the scene's `units`.
//!
//! ```toml
//! [temperature]
//! reference = 70.0                      # stress-free temperature
//! plates = [170.0, 20.0]                # uniform, upper (under the head) then lower; or
//! # gradient = [[75.0, 80.0], [72.0, 67.0]]  # per plate: [contact face, loaded face]
//! alpha = [13e-6]                       # per degree; one value for both plates
//! ```
//!
//! Or `from_heat = true` with `faces = [upper, lower]`: the temperatures of the joint's own heat
//! flow ([`super::from_heat`], two-plate, needs `[heat]`).
//! Exactly one of `plates` and `gradient` otherwise; one entry stands for both plates. The two-plate and
//! the single-plate models take temperatures; the single-plate substitute mirrors one plate
//! about the midplane, so it takes one entry of each key (or two equal ones), a face pressure
//! (no nut displacement) and the FE route (`auto` picks it). With `[outputs] field` (single
//! plate or two-plate) the VTU's stresses are σ = D (ε − ε_th) and it carries the nodal `temperature`.
//! Each error names the key, the value and the line.
//!
//! # Accuracy
//!
//! Those of [`crate::contact::thermal`] (`tests/contact/thermal.rs`); the table itself:
//! `tests/scene/temperature.rs` (`scene_gradient_equals_the_library_call`: the scene equals the
//! library call; `bad_temperature_tables_name_key_and_line`), `tests/scene/thermal_single.rs`
//! (the single-plate example scene equals the library call bit for bit; what the substitute
//! cannot take is refused), `tests/io/thermal_vtu.rs` (the VTU read by meshio).
//!
//! # Cost
//!
//! Parsing and checks only; the thermal joint is timed by example 20.
//!
//! ```
//! let scene = boltzone::scene::Scene::parse(
//!     "[hole]\nradius = 0.1\n[load]\nouter_radius = 0.31\npressure = 1000.0\n\
//!      [[plates]]\nthickness = 0.1\nmaterial = { E = 1e7, nu = 0.33 }\n\
//!      [joint]\nouter_radius = 1.0\n\
//!      [temperature]\nreference = 70.0\nplates = [170.0]\nalpha = [13e-6]\n",
//! )?;
//! assert!(scene.temperature.is_some());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::SceneError;
use super::file::{Method, Model, Scene};
pub use super::temperature_spec::TemperatureSpec;
use super::temperature_table::materials;
use crate::contact::thermal::{JointTemperature, PlateTemperature};
use crate::contact::two_plate::{TwoPlateParams, TwoPlateSolution};
use crate::fem::single::{HalfPlate, SingleParams, SingleSolution};
use crate::fem::single_thermal::{self, SingleTemperature};
use crate::io::vtu::Grid;
use crate::joint::{Joint, SinglePlate};

use super::temperature_keys::{fail, pair};

/// Checks the scene's `[temperature]` table (if any) against `text` for the lines.
pub fn check(scene: &Scene, text: &str) -> Result<(), SceneError> {
    let Some(t) = &scene.temperature else {
        return Ok(());
    };
    match scene.model {
        Model::Slab => {
            return Err(fail(
                text,
                "reference",
                t.reference,
                "temperatures need model = \"two-plate\" or \"single-plate\"",
            ))
        }
        Model::SinglePlate => check_single(scene, t, text)?,
        Model::TwoPlate => {}
    }
    let from_heat = super::from_heat::check(scene, t, text)?;
    if !t.reference.is_finite() {
        return Err(fail(
            text,
            "reference",
            t.reference,
            "must be a finite number",
        ));
    }
    match (&t.plates, &t.gradient) {
        _ if from_heat => {}
        (Some(p), None) => {
            for v in pair(text, "plates", p)? {
                if !v.is_finite() {
                    return Err(fail(text, "plates", v, "must be a finite number"));
                }
            }
        }
        (None, Some(g)) => {
            for v in pair(text, "gradient", g)?.iter().flatten() {
                if !v.is_finite() {
                    return Err(fail(text, "gradient", v, "must be a finite number"));
                }
            }
        }
        (Some(p), Some(_)) => {
            return Err(fail(
                text,
                "gradient",
                format!("{p:?}"),
                "give plates or gradient, not both",
            ))
        }
        (None, None) => {
            return Err(fail(
                text,
                "reference",
                t.reference,
                "give plates = [...] or gradient = [[...]]",
            ))
        }
    }
    super::temperature_table::check(t, text)
}

/// The single-plate substitute's own rules: finite elements, a face pressure, and the same
/// temperatures and α in both plates (the mirror symmetry of the substitute).
fn check_single(scene: &Scene, t: &TemperatureSpec, text: &str) -> Result<(), SceneError> {
    if scene.method == Method::Hankel {
        return Err(fail(
            text,
            "reference",
            t.reference,
            "the Hankel route has no thermal strains: method = \"fem\" or \"auto\"",
        ));
    }
    if let Some(d) = scene.load.nut_displacement {
        return Err(fail(
            text,
            "reference",
            d,
            "a single plate with temperatures is loaded by a pressure or force, not a nut displacement",
        ));
    }
    let same = |key: &str, two: bool| {
        if two {
            Err(fail(
                text,
                key,
                "two different entries",
                "the single-plate substitute mirrors one plate: give one entry (both plates)",
            ))
        } else {
            Ok(())
        }
    };
    let differ = |v: Option<[f64; 2]>| v.is_some_and(|[a, b]| a != b);
    same("alpha", differ(pair(text, "alpha", &t.alpha).ok()))?;
    if let Some(p) = &t.plates {
        same("plates", differ(pair(text, "plates", p).ok()))?;
    }
    if let Some(g) = &t.gradient {
        let g = pair(text, "gradient", g).ok();
        same("gradient", g.is_some_and(|[a, b]| a != b))?;
    }
    Ok(())
}

impl TemperatureSpec {
    /// The single plate's temperatures (a checked spec of a single-plate scene; `plate` the
    /// substitute): the upper plate's entry, by depth below the midplane.
    /// `stress` is the scene's stress unit in the plate's units (for a `table`'s E).
    pub fn single_temperature(
        &self,
        plate: &SinglePlate,
        stress: f64,
    ) -> Result<SingleTemperature, SceneError> {
        let [upper, _] = self.joint_temperature_plates()?;
        let [material, _] = materials(self, stress, [plate.material(); 2])?;
        Ok(SingleTemperature {
            reference: self.reference,
            plate: upper,
            material,
        })
    }

    fn joint_temperature_plates(&self) -> Result<[PlateTemperature; 2], SceneError> {
        Ok(match (&self.plates, &self.gradient) {
            (Some(p), _) => pair("", "plates", p)?.map(PlateTemperature::Uniform),
            (None, Some(g)) => pair("", "gradient", g)?
                .map(|[interface, outer]| PlateTemperature::Linear { interface, outer }),
            (None, None) => return Err(fail("", "reference", self.reference, "no temperatures")),
        })
    }

    /// The joint's temperatures (a checked spec; `joint` the scene's joint, `stress` the
    /// scene's stress unit in the joint's units, for a `table`'s E).
    pub fn joint_temperature(
        &self,
        joint: &Joint,
        stress: f64,
    ) -> Result<JointTemperature, SceneError> {
        let own = [joint.upper().material(), joint.lower().material()];
        Ok(JointTemperature {
            reference: self.reference,
            plates: self.joint_temperature_plates()?,
            materials: materials(self, stress, own)?,
        })
    }
}

/// The single plate with the scene's temperatures (`stress` the scene's stress unit in the
/// plate's units), keeping the finest level when `keep`.
pub fn solve_single(
    plate: &SinglePlate,
    params: &SingleParams,
    t: &TemperatureSpec,
    stress: f64,
    keep: bool,
) -> Result<(SingleSolution, Option<HalfPlate>), SceneError> {
    let t = t.single_temperature(plate, stress)?;
    Ok(if keep {
        let (s, h) = single_thermal::solve_with_temperature_field(plate, params, &t)?;
        (s, Some(h))
    } else {
        (
            single_thermal::solve_with_temperature(plate, params, &t)?,
            None,
        )
    })
}

/// The two-plate joint with the scene's temperatures, its finest level's field (thermal
/// stresses, nodal temperature) written to `field` in the scene's units `(length, stress)`.
pub fn two_plate_field(
    joint: &Joint,
    params: &TwoPlateParams,
    t: &TemperatureSpec,
    (length, stress): (f64, f64),
    field: &mut Option<Grid>,
) -> Result<TwoPlateSolution, SceneError> {
    let jt = t.joint_temperature(joint, stress)?;
    super::field::two_plate_thermal_grid(joint, params, &jt, (length, stress), field)
}
