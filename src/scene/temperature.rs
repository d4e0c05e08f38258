//! The scene's `[temperature]` table: the plates' temperatures for the two-plate model with
//! thermal strains ([`crate::contact::thermal`]).
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
//! Exactly one of `plates` and `gradient`; one entry stands for both plates. Only the two-plate
//! model takes temperatures. Each error names the key, the value and the line.
//!
//! # Accuracy
//!
//! Those of [`crate::contact::thermal`] (`tests/contact/thermal.rs`); the table itself:
//! `tests/scene/temperature.rs` (`scene_gradient_equals_the_library_call`: the scene equals the
//! library call; `bad_temperature_tables_name_key_and_line`).
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
use super::file::{line_of, path_name, Model, Scene, Seg};
pub use super::temperature_spec::TemperatureSpec;
use crate::contact::thermal::{JointTemperature, PlateTemperature};
use crate::joint::Joint;

fn fail(text: &str, key: &str, value: impl std::fmt::Display, reason: &str) -> SceneError {
    let path = [Seg::Key("temperature".into()), Seg::Key(key.into())];
    SceneError::Invalid {
        key: path_name(&path),
        line: line_of(text, &path).unwrap_or(1),
        reason: format!("{value}: {reason}"),
    }
}

/// One or two entries → (upper, lower).
fn pair<T: Clone + std::fmt::Debug>(text: &str, key: &str, v: &[T]) -> Result<[T; 2], SceneError> {
    match v {
        [a] => Ok([a.clone(), a.clone()]),
        [a, b] => Ok([a.clone(), b.clone()]),
        _ => Err(fail(
            text,
            key,
            format!("{v:?}"),
            "give one entry (both plates) or two (upper, lower)",
        )),
    }
}

/// Checks the scene's `[temperature]` table (if any) against `text` for the lines.
pub fn check(scene: &Scene, text: &str) -> Result<(), SceneError> {
    let Some(t) = &scene.temperature else {
        return Ok(());
    };
    if scene.model != Model::TwoPlate {
        return Err(fail(
            text,
            "reference",
            t.reference,
            "temperatures need model = \"two-plate\"",
        ));
    }
    if scene.outputs.field.is_some() {
        return Err(fail(
            text,
            "reference",
            t.reference,
            "the VTU field has no thermal strains yet: drop [outputs] field or [temperature]",
        ));
    }
    if !t.reference.is_finite() {
        return Err(fail(
            text,
            "reference",
            t.reference,
            "must be a finite number",
        ));
    }
    for a in pair(text, "alpha", &t.alpha)? {
        if !a.is_finite() {
            return Err(fail(text, "alpha", a, "must be a finite number"));
        }
    }
    match (&t.plates, &t.gradient) {
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
    Ok(())
}

impl TemperatureSpec {
    /// The joint's temperatures (a checked spec; `joint` the scene's joint, any units).
    pub fn joint_temperature(&self, joint: &Joint) -> Result<JointTemperature, SceneError> {
        let plates = match (&self.plates, &self.gradient) {
            (Some(p), _) => pair("", "plates", p)?.map(PlateTemperature::Uniform),
            (None, Some(g)) => pair("", "gradient", g)?
                .map(|[interface, outer]| PlateTemperature::Linear { interface, outer }),
            (None, None) => return Err(fail("", "reference", self.reference, "no temperatures")),
        };
        let alpha = pair("", "alpha", &self.alpha)?;
        Ok(JointTemperature::constant(
            joint,
            self.reference,
            plates,
            alpha,
        )?)
    }
}
