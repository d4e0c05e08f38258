//! A scene's joint in the units the routes solve it in (module [`super::units`]): the plates'
//! materials (named in the library, module [`super::materials`], or given as `{ E, nu }` in the
//! scene's stress unit) and the joint, converted from the scene's units by [`Solved`]'s factors.
//!
//! **Which units.** A scene is solved in its own units, as `boltzone two` and `table1` solve in
//! their `--units`: the same joint from every front end is then the same floating-point input
//! and gives the same answer bit for bit (a library material's SI modulus is divided by the
//! stress unit once, as `two --material` does). A scene with `[temperature]` is solved in SI
//! (m, Pa, N): its conductivities and heat flows are SI quantities.
//!
//! # Accuracy
//!
//! Unit conversions only; `tests/scene/joint_units.rs` finds the same R_o from a joint given in
//! each system of units, and `tests/compare/one_question.rs` the same bits from `two` and a
//! scene in each system.
//!
//! # Cost
//!
//! Negligible.
//!
//! ```
//! use boltzone::scene::{si, UnitSystem};
//! let text = "units = \"mm-MPa-N\"\n[hole]\nradius = 2.5\n[load]\nouter_radius = 7.9\n\
//!             pressure = 10.0\n[[plates]]\nthickness = 2.5\nmaterial = \"steel-304\"\n";
//! let scene = boltzone::scene::Scene::parse(text)?;
//! let solved = si::solved(&scene);
//! assert_eq!((solved.units, solved.length, solved.stress), (UnitSystem::MmMpaN, 1.0, 1.0));
//! let (joint, nut) = si::joint_solved(&scene)?;
//! assert!(joint.hole_radius() == 2.5 && nut.is_none());
//! let (joint, _) = si::joint_si(&scene)?;
//! assert!((joint.hole_radius() - 2.5e-3).abs() < 1e-15);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use super::error::SceneError;
use super::file::{MaterialSpec, ProfileKind, Scene};
use super::materials;
use super::units::UnitSystem;
use crate::joint::{Joint, OuterRadius, Plate};
use crate::load::{FaceLoad, Peak};
use crate::material::Material;
use std::f64::consts::PI;

/// The units a scene is solved in and the factors from the scene's units to them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Solved {
    /// The unit system the routes solve in.
    pub units: UnitSystem,
    /// One length unit of the scene in the solving units (exactly 1 in its own).
    pub length: f64,
    /// One stress unit of the scene in the solving units.
    pub stress: f64,
    /// One force unit of the scene in the solving units.
    pub force: f64,
}

impl Solved {
    /// From the scene's `units` to `solving`.
    pub fn between(units: UnitSystem, solving: UnitSystem) -> Self {
        Self {
            units: solving,
            length: units.length() / solving.length(),
            stress: units.stress() / solving.stress(),
            force: units.force() / solving.force(),
        }
    }
}

/// The units `scene` is solved in: its own, or SI with `[temperature]` (module doc).
pub fn solved(scene: &Scene) -> Solved {
    let solving = match scene.temperature {
        Some(_) => UnitSystem::MPaN,
        None => scene.units,
    };
    Solved::between(scene.units, solving)
}

/// The material of plate `i` in the stresses of `solving`.
pub fn material_in(scene: &Scene, i: usize, solving: UnitSystem) -> Result<Material, SceneError> {
    match scene.material_of(i) {
        MaterialSpec::Name(n) => {
            let m = materials::lookup(&n).ok_or_else(|| SceneError::Invalid {
                key: format!("plates[{i}].material"),
                line: 1,
                reason: format!("\"{n}\": not in the library ({})", materials::names()),
            })?;
            Ok(Material::new(
                m.youngs_modulus / solving.stress(),
                m.poisson_ratio,
            )?)
        }
        MaterialSpec::Constants(c) => {
            let stress = Solved::between(scene.units, solving).stress;
            Ok(Material::new(c.e * stress, c.nu)?)
        }
    }
}

/// The material of plate `i` in SI units.
pub fn material(scene: &Scene, i: usize) -> Result<Material, SceneError> {
    material_in(scene, i, UnitSystem::MPaN)
}

/// The joint of `scene` in the units it is solved in ([`solved`]), and the nut displacement
/// in those units if one is given.
pub fn joint_solved(scene: &Scene) -> Result<(Joint, Option<f64>), SceneError> {
    joint_in(scene, solved(scene))
}

/// The joint of `scene` in SI units (m, Pa), and the nut displacement (m) if one is given.
pub fn joint_si(scene: &Scene) -> Result<(Joint, Option<f64>), SceneError> {
    joint_in(scene, Solved::between(scene.units, UnitSystem::MPaN))
}

/// The joint of `scene` in `to`'s units, and the nut displacement if one is given. Plates top
/// to bottom; one `[[plates]]` entry stands for two equal plates.
fn joint_in(scene: &Scene, to: Solved) -> Result<(Joint, Option<f64>), SceneError> {
    let (l, s) = (to.length, to.stress);
    let a = scene.hole.radius * l;
    let b = scene.load.outer_radius * l;
    let p = match (scene.load.force, scene.load.pressure) {
        (Some(f), _) => f * to.force / (PI * (b * b - a * a)),
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
        Plate::new(top.thickness * l, material_in(scene, 0, to.units)?)?,
        Plate::new(bottom.thickness * l, material_in(scene, last, to.units)?)?,
        load,
    )?;
    // the nut's own face: the head's profile and force over A..B₂
    let joint = match scene.load.nut_outer_radius {
        Some(b2) => joint.with_nut_outer_radius(b2 * l)?,
        None => joint,
    };
    Ok((joint, scene.load.nut_displacement.map(|d| d * l)))
}
