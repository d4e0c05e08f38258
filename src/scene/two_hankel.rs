//! The two-plate model by the semi-analytic route with the hole
//! ([`crate::hankel::receding::holed`]) for a scene: where it applies (two equal plates with a
//! hole, infinite or with a rim C beyond B + D, pressed by a pressure; R_o and the interface
//! pressure only), what keeps
//! a scene from it (the first blocking key), and its answer in the scene's units.
//!
//! `method = "hankel"` asks for it; `method = "auto"` takes it, as `boltzone two --method auto`
//! does, where it applies and the tolerance is below [`AUTO_BELOW`] (above it the finite
//! elements reach the tolerance faster). Equal plates are symmetric about the interface, which
//! therefore carries no shear: welded, frictionless and frictional interfaces are one problem,
//! the plate on a frictionless rigid plane that the route solves.
//!
//! ```
//! use boltzone::scene::{two_hankel, Scene};
//! let scene = Scene::parse(
//!     "model = \"two-plate\"\nmethod = \"hankel\"\n[hole]\nradius = 0.1\n\
//!      [load]\nouter_radius = 0.31\npressure = 1.0\n[[plates]]\nthickness = 0.1\n\
//!      material = { E = 3e7, nu = 0.3 }\n",
//! )?;
//! assert!(two_hankel::blocker(&scene).is_none());
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! # Accuracy
//!
//! That of [`crate::hankel::receding::holed`] (its estimate is the scene's `r_o_error`;
//! `converged` when it is within `tolerance`); `tests/scene/two_hankel.rs` checks that the
//! scene equals the library call bit for bit, agrees with the finite elements within both
//! error bars, and that every blocking key is named with its line.
//!
//! # Cost
//!
//! One semi-analytic solve, 0.10–0.15 s of CPU per Table 1 geometry at a tolerance of 1e-3,
//! 0.43–0.78 s at 1e-6 (example 19); the curve adds one evaluation per point.

use super::error::SceneError;
use super::file::{Model, Scene};
use super::solution::{InterfaceCurve, Solution};
use crate::hankel::receding::holed::{two_plate_hole_pressure, HoledParams};
use crate::hankel::receding::{MAX_B_OVER_D, MAX_B_OVER_D_RIM, MIN_A_OVER_D};
use crate::joint::Joint;

/// `method = "auto"` takes this route only below this tolerance (its reasons where it is
/// defined, beside the route's other limits).
pub use crate::hankel::receding::AUTO_BELOW;

/// Points of the interface curve (plus one), denser toward R_o where q ~ √(R_o − r).
const CURVE_POINTS: usize = 100;

/// The first scene key that keeps a two-plate scene from this route, with the reason; None
/// when the route applies.
pub fn blocker(scene: &Scene) -> Option<(&'static str, &'static str)> {
    let equal = match scene.plates.as_slice() {
        [_] => true,
        [up, lo] => up.thickness == lo.thickness && scene.material_of(0) == scene.material_of(1),
        _ => false,
    };
    let o = &scene.outputs;
    [
        (
            scene.model != Model::TwoPlate,
            "model",
            "the route is the two-plate model's",
        ),
        (!equal, "plates", "the route needs two equal plates"),
        (
            scene.hole.radius <= 0.0,
            "hole.radius",
            "the route needs a hole (without one the receding-contact solution applies)",
        ),
        (
            scene.joint.outer_radius.is_some_and(|c| {
                c <= scene.load.outer_radius + scene.plates.first().map_or(0.0, |p| p.thickness)
            }),
            "joint.outer_radius",
            "the route's finite rim needs C beyond B by more than D (or omit outer_radius)",
        ),
        (
            scene
                .plates
                .first()
                .is_some_and(|p| scene.load.outer_radius > MAX_B_OVER_D * p.thickness),
            "load.outer_radius",
            "the route takes loads up to 16 plate thicknesses wide (its cost grows like (B/D)²: \
             4.7 s and 0.6 GB at 16)",
        ),
        (
            scene.hole.radius > 0.0
                && scene
                    .plates
                    .first()
                    .is_some_and(|p| scene.hole.radius < MIN_A_OVER_D * p.thickness),
            "hole.radius",
            "the route takes holes of at least 0.04 plate thicknesses (smaller ones left \
             residual tractions of 1e1-1e4 P on the hole)",
        ),
        (
            scene.joint.outer_radius.is_some()
                && scene
                    .plates
                    .first()
                    .is_some_and(|p| scene.load.outer_radius > MAX_B_OVER_D_RIM * p.thickness),
            "load.outer_radius",
            "with a finite joint.outer_radius the route takes loads up to 8 plate thicknesses \
             wide (the rim's cost grows like (B/D)²: 10.5 s at 8)",
        ),
        (
            scene.load.nut_displacement.is_some(),
            "load.nut_displacement",
            "the route loads the plates by a pressure",
        ),
        (
            scene.temperature.is_some(),
            "temperature",
            "thermal strains are in the finite-element model only",
        ),
        (
            o.field.is_some(),
            "outputs.field",
            "the field comes from the finite elements",
        ),
        (
            o.conductance,
            "outputs.conductance",
            "the conductance integrates the finite elements' interface pressure",
        ),
    ]
    .into_iter()
    .find_map(|(blocks, key, reason)| blocks.then_some((key, reason)))
}

/// Whether `method = "auto"` takes this route for `scene`.
pub fn auto_takes(scene: &Scene) -> bool {
    scene.tolerance < AUTO_BELOW && blocker(scene).is_none()
}

/// Solves `joint` (SI) by the route and fills `out`'s R_o, error, `converged` and, when asked,
/// the interface curve (scene units: lengths divided by `length`, pressures by `stress`).
pub fn solve(
    scene: &Scene,
    joint: &Joint,
    (length, stress): (f64, f64),
    out: &mut Solution,
) -> Result<(), SceneError> {
    let plate = joint
        .single_plate_substitute()
        .ok_or_else(|| SceneError::Invalid {
            key: "plates".into(),
            line: 1,
            reason: "the Hankel route needs two equal plates".into(),
        })?;
    let at: Vec<f64> = if scene.outputs.interface_pressure.is_some() {
        (0..=CURVE_POINTS)
            .map(|k| 1.0 - (1.0 - k as f64 / CURVE_POINTS as f64).powi(2))
            .collect()
    } else {
        Vec::new()
    };
    let (h, curve) =
        two_plate_hole_pressure(&plate, &HoledParams::for_tolerance(scene.tolerance), &at)?;
    out.r_o = h.r_o / length;
    out.r_o_error = h.info.r_o_error / length;
    out.converged = h.info.r_o_error <= scene.tolerance * h.r_o;
    out.full_contact = Some(false);
    if !at.is_empty() {
        out.interface = Some(InterfaceCurve {
            radius: curve.iter().map(|&(r, _)| r / length).collect(),
            pressure: curve.iter().map(|&(_, q)| q / stress).collect(),
            gap: vec![0.0; curve.len()],
        });
    }
    Ok(())
}
