//! A scene's joint in SI units (m, Pa): the plates' materials (named in the library, module
//! [`super::materials`], or given as `{ E, nu }` in the scene's stress unit) and the joint the
//! routes solve, converted from the scene's units (module [`super::units`]).
//!
//! # Accuracy
//!
//! Unit conversions only; `tests/scene/joint_units.rs` finds the same R_o from a joint given in
//! each system of units.
//!
//! # Cost
//!
//! Negligible.
//!
//! ```
//! let text = "units = \"mm-MPa-N\"\n[hole]\nradius = 2.5\n[load]\nouter_radius = 7.9\n\
//!             pressure = 10.0\n[[plates]]\nthickness = 2.5\nmaterial = \"steel-304\"\n";
//! let scene = boltzone::scene::Scene::parse(text)?;
//! let (joint, nut) = boltzone::scene::si::joint_si(&scene)?;
//! assert!((joint.hole_radius() - 2.5e-3).abs() < 1e-15 && nut.is_none());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::SceneError;
use super::file::{MaterialSpec, ProfileKind, Scene};
use super::materials;
use crate::joint::{Joint, OuterRadius, Plate};
use crate::load::{FaceLoad, Peak};
use crate::material::Material;
use std::f64::consts::PI;

/// The material of plate `i` in SI units.
pub fn material(scene: &Scene, i: usize) -> Result<Material, SceneError> {
    match scene.material_of(i) {
        MaterialSpec::Name(n) => {
            let m = materials::lookup(&n).ok_or_else(|| SceneError::Invalid {
                key: format!("plates[{i}].material"),
                line: 1,
                reason: format!("\"{n}\": not in the library ({})", materials::names()),
            })?;
            Ok(Material::new(m.youngs_modulus, m.poisson_ratio)?)
        }
        MaterialSpec::Constants(c) => Ok(Material::new(c.e * scene.units.stress(), c.nu)?),
    }
}

/// The joint of `scene` in SI units (m, Pa), and the nut displacement (m) if one is given.
/// Plates top to bottom; one `[[plates]]` entry stands for two equal plates.
pub fn joint_si(scene: &Scene) -> Result<(Joint, Option<f64>), SceneError> {
    let u = scene.units;
    let (l, s) = (u.length(), u.stress());
    let a = scene.hole.radius * l;
    let b = scene.load.outer_radius * l;
    let p = match (scene.load.force, scene.load.pressure) {
        (Some(f), _) => f * u.force() / (PI * (b * b - a * a)),
        (None, Some(p)) => p * s,
        // a prescribed displacement: the pressure only marks A..B
        (None, None) => s,
    };
    let load = match scene.load.profile {
        ProfileKind::Uniform => FaceLoad::uniform(a, b, p)?,
        ProfileKind::PeakA => FaceLoad::triangular(a, b, p, Peak::AtA)?,
        ProfileKind::PeakB => FaceLoad::triangular(a, b, p, Peak::AtB)?,
    };
    let last = scene.plates.len().saturating_sub(1);
    let (Some(top), Some(bottom)) = (scene.plates.first(), scene.plates.get(last)) else {
        return Err(SceneError::Invalid {
            key: "plates".into(),
            line: 1,
            reason: "no [[plates]] entry".into(),
        });
    };
    let joint = Joint::new(
        a,
        scene
            .joint
            .outer_radius
            .map_or(OuterRadius::Infinite, |c| OuterRadius::Finite(c * l)),
        Plate::new(top.thickness * l, material(scene, 0)?)?,
        Plate::new(bottom.thickness * l, material(scene, last)?)?,
        load,
    )?;
    // the nut's own face: the head's profile and force over A..B₂
    let joint = match scene.load.nut_outer_radius {
        Some(b2) => joint.with_nut_outer_radius(b2 * l)?,
        None => joint,
    };
    Ok((joint, scene.load.nut_displacement.map(|d| d * l)))
}
